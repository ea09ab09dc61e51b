/*
 * nearest.c: the nearest point of a mesh, by a bucket grid of triangles
 * and shells of cells searched outwards (nearest.h).
 */
#include "nearest.h"

#include <assert.h>
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/base/vec3.h"

/* Ericson, Real-Time Collision Detection, 5.1.5: the nearest point of
 * triangle abc to p by the Voronoi region of p. */
double nearest_on_triangle(const double p[3], const double a[3],
                           const double b[3], const double c[3],
                           double out[3])
{
    double ab[3], ac[3], ap[3], bp[3], cp[3];
    vec3_sub(b, a, ab);
    vec3_sub(c, a, ac);
    vec3_sub(p, a, ap);
    double d1 = vec3_dot(ab, ap), d2 = vec3_dot(ac, ap);
    double s = 0, t = 0;  /* out = a + s ab + t ac */
    if (d1 <= 0 && d2 <= 0)
        goto done;
    vec3_sub(p, b, bp);
    double d3 = vec3_dot(ab, bp), d4 = vec3_dot(ac, bp);
    if (d3 >= 0 && d4 <= d3) {
        s = 1;
        goto done;
    }
    double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) {
        s = d1 / (d1 - d3);
        goto done;
    }
    vec3_sub(p, c, cp);
    double d5 = vec3_dot(ab, cp), d6 = vec3_dot(ac, cp);
    if (d6 >= 0 && d5 <= d6) {
        t = 1;
        goto done;
    }
    double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) {
        t = d2 / (d2 - d6);
        goto done;
    }
    double va = d3 * d6 - d5 * d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
        double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        s = 1 - w;
        t = w;
        goto done;
    }
    double denom = 1 / (va + vb + vc);
    s = vb * denom;
    t = vc * denom;
done:
    for (int x = 0; x < 3; x++)
        out[x] = a[x] + s * ab[x] + t * ac[x];
    double d[3];
    vec3_sub(p, out, d);
    return vec3_dot(d, d);
}

static int clamp_cell(double value, int n)
{
    if (!(value > 0))
        return 0;
    if (value >= n - 1)
        return n - 1;
    return (int)value;
}

/* The cells a triangle's bounding box touches, as index ranges. */
static void triangle_cells(const struct nearest_index *index, uint32_t t,
                           int from[3], int to[3])
{
    const struct mesh *m = index->mesh;
    for (int x = 0; x < 3; x++) {
        double lo = DBL_MAX, hi = -DBL_MAX;
        for (int k = 0; k < 3; k++) {
            double v = m->position[3 * (size_t)m->triangle[3 * (size_t)t + k] + x];
            lo = fmin(lo, v);
            hi = fmax(hi, v);
        }
        from[x] = clamp_cell((lo - index->lo[x]) / index->cell[x], index->n[x]);
        to[x] = clamp_cell((hi - index->lo[x]) / index->cell[x], index->n[x]);
    }
}

int nearest_index_build(const struct mesh *mesh, struct nearest_index *out,
                        struct facet_error *err)
{
    memset(out, 0, sizeof *out);
    out->mesh = mesh;
    if (mesh->ntriangles == 0)
        return facet_error_set(err, FACET_EINPUT,
                               "the surface has no triangles");
    /* Cells about a triangle's size: a few triangles in each the surface
     * crosses. A flat surface's thin axis gets one cell. */
    double side = sqrt(2 * mesh->area / (double)mesh->ntriangles);
    double extent_max = 0;
    for (int x = 0; x < 3; x++)
        extent_max = fmax(extent_max, mesh->bbox_max[x] - mesh->bbox_min[x]);
    if (!(side > 0))
        side = extent_max > 0 ? extent_max : 1;
    side = fmax(side, extent_max / 1024);
    size_t cells = 1;
    for (int x = 0; x < 3; x++) {
        double extent = mesh->bbox_max[x] - mesh->bbox_min[x];
        int n = (int)ceil(extent / side);
        out->n[x] = n < 1 ? 1 : n;
        out->lo[x] = mesh->bbox_min[x];
        out->cell[x] = extent > 0 ? extent / out->n[x] : side;
        cells *= (size_t)out->n[x];
    }
    out->cell_start = calloc(cells + 1, sizeof *out->cell_start);
    if (out->cell_start == NULL)
        return facet_error_set(err, FACET_EWORK, "out of memory");
    size_t total = 0;
    for (int pass = 0; pass < 2; pass++) {
        for (uint32_t t = 0; t < mesh->ntriangles; t++) {
            int from[3], to[3];
            triangle_cells(out, t, from, to);
            for (int k = from[2]; k <= to[2]; k++)
                for (int j = from[1]; j <= to[1]; j++)
                    for (int i = from[0]; i <= to[0]; i++) {
                        size_t c = ((size_t)k * out->n[1] + j) * out->n[0] + i;
                        if (pass == 0)
                            out->cell_start[c + 1]++;
                        else
                            out->cell_triangles[out->cell_start[c]++] = t;
                    }
        }
        if (pass == 0) {
            for (size_t c = 0; c < cells; c++)
                out->cell_start[c + 1] += out->cell_start[c];
            total = out->cell_start[cells];
            if (total >= UINT32_MAX)
                return facet_error_set(err, FACET_EWORK,
                                       "the surface is too large to index");
            out->cell_triangles = malloc((total ? total : 1) *
                                         sizeof *out->cell_triangles);
            if (out->cell_triangles == NULL)
                return facet_error_set(err, FACET_EWORK, "out of memory");
        }
    }
    /* The second pass advanced each start to the next cell's: back. */
    for (size_t c = cells; c > 0; c--)
        out->cell_start[c] = out->cell_start[c - 1];
    out->cell_start[0] = 0;
    return FACET_OK;
}

/* The nearest point of triangle t to p into *hit when nearer. */
static void try_triangle(const struct nearest_index *index, uint32_t t,
                         const double p[3], struct nearest_hit *hit,
                         double *best2)
{
    const struct mesh *m = index->mesh;
    const uint32_t *v = &m->triangle[3 * (size_t)t];
    double q[3];
    double d2 = nearest_on_triangle(p, &m->position[3 * (size_t)v[0]],
                                    &m->position[3 * (size_t)v[1]],
                                    &m->position[3 * (size_t)v[2]], q);
    if (d2 < *best2) {
        *best2 = d2;
        hit->triangle = t;
        memcpy(hit->point, q, sizeof q);
    }
}

void nearest_point(const struct nearest_index *index, const double p[3],
                   struct nearest_hit *hit)
{
    assert(isfinite(p[0]) && isfinite(p[1]) && isfinite(p[2]));
    int c[3];
    for (int x = 0; x < 3; x++)
        c[x] = clamp_cell((p[x] - index->lo[x]) / index->cell[x], index->n[x]);
    double best2 = DBL_MAX;
    hit->triangle = UINT32_MAX;
    for (int ring = 0;; ring++) {
        /* Every cell of shell ring lies outside the box of the cells
         * within ring - 1 of c: once p is farther inside that box than
         * the best distance, no later shell holds a nearer point. */
        if (ring > 0 && best2 < DBL_MAX) {
            double inside = DBL_MAX;
            for (int x = 0; x < 3; x++) {
                double lo = index->lo[x] + (c[x] - (ring - 1)) * index->cell[x];
                double hi = index->lo[x] + (c[x] + ring) * index->cell[x];
                /* A side at the grid's edge has nothing beyond it. */
                if (c[x] - (ring - 1) > 0)
                    inside = fmin(inside, p[x] - lo);
                if (c[x] + ring < index->n[x])
                    inside = fmin(inside, hi - p[x]);
            }
            if (inside < 0)
                inside = 0;
            if (inside * inside >= best2)
                break;
        }
        int covered = 1;
        for (int x = 0; x < 3; x++)
            if (c[x] - ring > 0 || c[x] + ring < index->n[x] - 1)
                covered = 0;
        for (int k = c[2] - ring; k <= c[2] + ring; k++) {
            if (k < 0 || k >= index->n[2])
                continue;
            for (int j = c[1] - ring; j <= c[1] + ring; j++) {
                if (j < 0 || j >= index->n[1])
                    continue;
                int shell_kj = abs(k - c[2]) == ring || abs(j - c[1]) == ring;
                for (int i = c[0] - ring; i <= c[0] + ring; i++) {
                    if (i < 0 || i >= index->n[0])
                        continue;
                    /* Only the shell: the inside was searched before. */
                    if (!shell_kj && abs(i - c[0]) != ring)
                        i = c[0] + ring;
                    if (i >= index->n[0])
                        continue;
                    size_t cell = ((size_t)k * index->n[1] + j) * index->n[0] + i;
                    for (uint32_t e = index->cell_start[cell];
                         e < index->cell_start[cell + 1]; e++)
                        try_triangle(index, index->cell_triangles[e], p, hit,
                                     &best2);
                }
            }
        }
        if (covered)
            break;
    }
    assert(hit->triangle != UINT32_MAX);
    hit->distance = sqrt(best2);
}

void nearest_index_free(struct nearest_index *index)
{
    free(index->cell_start);
    free(index->cell_triangles);
    index->cell_start = NULL;
    index->cell_triangles = NULL;
}
