/*
 * coarse_mesh.c: facet size, panel size and the warning. See coarse_mesh.h.
 */
#include "core/surface/coarse_mesh.h"

#include <assert.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "core/base/vec3.h"
#include "core/base/units.h"




static int compare_doubles(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* The median of values[0..n), which it reorders; n > 0. */
static double median(double *values, size_t n)
{
    assert(n > 0);
    qsort(values, n, sizeof *values, compare_doubles);
    return n % 2 ? values[n / 2] : (values[n / 2 - 1] + values[n / 2]) / 2;
}

int mesh_facet_size(const struct mesh *mesh, double *size,
                    struct facet_error *err)
{
    *size = 0;
    if (mesh->ntriangles == 0)
        return FACET_OK;
    double *side = malloc(mesh->ntriangles * sizeof *side);
    if (side == NULL)
        return facet_error_set(err, FACET_EWORK,
                               "out of memory (facet size of %zu triangles)",
                               mesh->ntriangles);
    for (size_t t = 0; t < mesh->ntriangles; t++)
        side[t] = sqrt(2 * mesh->face_area[t]);
    *size = median(side, mesh->ntriangles);
    free(side);
    return FACET_OK;
}

int panels_typical_side(const struct panelization *p, double *side,
                        struct facet_error *err)
{
    *side = 0;
    if (p->npanels == 0)
        return FACET_OK;
    double *area = malloc(p->npanels * sizeof *area);
    if (area == NULL)
        return facet_error_set(err, FACET_EWORK,
                               "out of memory (side of %zu panels)",
                               p->npanels);
    size_t n = 0;
    for (size_t k = 0; k < p->npanels; k++)
        if (!p->panels[k].trimmed)
            area[n++] = p->panels[k].area;
    if (n == 0)
        for (size_t k = 0; k < p->npanels; k++)
            area[n++] = p->panels[k].area;
    *side = sqrt(median(area, n));
    free(area);
    return FACET_OK;
}

double grid_panel_side(double area, double fill, int nu, int nv)
{
    if (!(fill > 0) || fill > 1)
        fill = 1;
    return sqrt(area / (fill * (double)nu * (double)nv));
}

int coarse_mesh_warning(double facet_size, double panel_side,
                        const char *grid, char *warning, size_t size)
{
    if (!(facet_size > 0) || !(panel_side > 0) ||
        facet_size < COARSE_MESH_RATIO * panel_side)
        return 0;
    snprintf(warning, size,
             "the mesh is coarse for %s: its facets (%.3g m) are %.1f times "
             "the panels' side (%.3g m), so curvature is the smooth "
             "surface's and deviation the facets' folds; FP panels may "
             "deviate more than the threshold (refine the mesh or use "
             "fewer panels)",
             grid, facet_size, facet_size / panel_side, panel_side);
    return 1;
}

/* |normal curvature| along tangent-ish direction e at vertex v: the shape
 * operator k1 d1 d1^T + k2 d2 d2^T on e's tangent part, over its length
 * squared; 0 for an e along the normal. */
static double normal_curvature(const struct curvature *c, size_t v,
                               const double e[3])
{
    double a = vec3_dot(e, c->dir1 + 3 * v), b = vec3_dot(e, c->dir2 + 3 * v);
    double tangent = a * a + b * b;
    return tangent > 0 ? fabs(c->k1[v] * a * a + c->k2[v] * b * b) / tangent
                       : 0;
}

int mesh_facet_sag(const struct mesh *mesh, const struct curvature *curvature,
                   double *sag, struct facet_error *err)
{
    *sag = 0;
    size_t n = mesh->ntriangles;
    if (n == 0)
        return FACET_OK;
    double *each = malloc(n * sizeof *each);
    if (each == NULL)
        return facet_error_set(err, FACET_EWORK,
                               "out of memory (facet sag of %zu triangles)",
                               n);
    for (size_t t = 0; t < n; t++) {
        const uint32_t *tri = mesh->triangle + 3 * t;
        double most = 0;
        for (int k = 0; k < 3; k++) {
            size_t a = tri[k], b = tri[(k + 1) % 3];
            double e[3];
            vec3_sub(mesh->position + 3 * b, mesh->position + 3 * a, e);
            double k_n = fmax(normal_curvature(curvature, a, e),
                              normal_curvature(curvature, b, e));
            most = fmax(most, vec3_dot(e, e) * k_n / 8);
        }
        each[t] = most;
    }
    *sag = median(each, n);
    free(each);
    return FACET_OK;
}

int facet_sag_matters(double sag, double threshold)
{
    return sag > FACET_SAG_FRACTION * threshold;
}

int facet_sag_warning(double sag, double threshold, const char *what,
                      char *warning, size_t size)
{
    if (!facet_sag_matters(sag, threshold))
        return 0;
    snprintf(warning, size,
             "the facets sag %.2g mm from the surface their vertices sample, "
             "more than a quarter of %s: single-curved panels are measured "
             "against the smooth surface through the vertices, but FP "
             "deviations and joints still include the sag (refine the mesh)",
             units_mm(sag), what);
    return 1;
}
