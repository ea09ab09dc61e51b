/*
 * sp_fit.c: single-curved panels as built. See sp_fit.h.
 */
#include "core/fit/sp_fit.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/base/sym3.h"
#include "core/base/vec3.h"
#include "core/classify/classify.h"

/* Of a panel's side samples, every FIT_SIDE_STRIDE-th joins the fit (the
 * corners and side midpoints); all count in its deviation. */
#define FIT_SIDE_STRIDE 4

/* A point within this fraction of a cell of a cell line lies on it. */
#define ON_LINE 1e-9

int fit_points_build(const struct panel_prep *prep, struct fit_points *out,
                     struct facet_error *err)
{
    memset(out, 0, sizeof *out);
    const struct mesh *mesh = prep->mesh;
    const struct curvature *curvature = prep->curvature;
    out->npoints = prep->npoints;
    out->uv = prep->point_uv;
    out->vertex = malloc((prep->npoints + 1) * sizeof *out->vertex);
    out->ruling = malloc((prep->npoints + 1) * 3 * sizeof *out->ruling);
    if (out->vertex == NULL || out->ruling == NULL) {
        fit_points_free(out);
        return facet_error_set(err, FACET_EWORK,
                               "out of memory for %zu fit points",
                               prep->npoints);
    }
    for (size_t c = 0; c < 3 * mesh->ntriangles; c++)
        out->vertex[prep->corner[c]] = mesh->triangle[c];
    for (size_t p = 0; p < out->npoints; p++) {
        size_t v = out->vertex[p];
        const double *dir = fabs(curvature->k1[v]) <= fabs(curvature->k2[v])
                                ? curvature->dir1 : curvature->dir2;
        memcpy(out->ruling + 3 * p, dir + 3 * v, 3 * sizeof *dir);
    }
    return FACET_OK;
}

void fit_points_free(struct fit_points *points)
{
    free(points->vertex);
    free(points->ruling);
    memset(points, 0, sizeof *points);
}

/* The cells a point at grid coordinate x (in cells from the first line)
 * lies in along one axis of count cells: those whose closed interval
 * holds it, to ON_LINE, so that a point on a cell line belongs to both
 * sides. Returns how many (1 or 2) into cell[]. */
static int cells_along(double x, int count, int cell[2])
{
    int i = x > 0 ? (x < count ? (int)x : count - 1) : 0;
    double f = x - i;
    cell[0] = i;
    if (f <= ON_LINE && i > 0) {
        cell[1] = i - 1;
        return 2;
    }
    if (f >= 1 - ON_LINE && i < count - 1) {
        cell[1] = i + 1;
        return 2;
    }
    return 1;
}

/* The SP panels holding fit point p (the panels of the cells it lies in)
 * into out; returns how many. */
static int point_panels(const struct fit_points *points, size_t p,
                        const struct panelization *panels, double du,
                        double dv, int32_t out[4])
{
    int ci[2], cj[2];
    int ni = cells_along((points->uv[2 * p] - panels->umin) / du, panels->nu,
                         ci);
    int nj = cells_along((points->uv[2 * p + 1] - panels->vmin) / dv,
                         panels->nv, cj);
    int n = 0;
    for (int a = 0; a < ni; a++)
        for (int b = 0; b < nj; b++) {
            int32_t panel = panels->cell_panel[cj[b] * panels->nu + ci[a]];
            if (panel >= 0 && panels->panels[panel].type == TYPE_SP)
                out[n++] = panel;
        }
    return n;
}

/* Appends sample k of side s to xyz at *n when it is on the surface. */
static void add_sample(const struct cell_sides *sides, size_t s, int k,
                       double *xyz, size_t *n)
{
    size_t at = s * CELL_SIDE_SAMPLES + (size_t)k;
    if (!sides->on[at])
        return;
    memcpy(xyz + 3 * *n, sides->point + 3 * at, 3 * sizeof *xyz);
    (*n)++;
}

/* Fits the first nfit of panel's samples xyz (n) with the axis guess
 * axis, and measures the fit's deviation on all n; the first nrulings
 * samples carry the rulings ruling (nrulings x 3), for a cone. Fills
 * *b. */
static void fit_panel(const struct panel *panel, const double *xyz,
                      size_t nfit, size_t n, const double *ruling,
                      size_t nrulings, const double axis[3],
                      double threshold, struct built_panel *b)
{
    double limit = threshold + CLASSIFY_ROUNDING * panel->diameter;
    struct developable cylinder, cone;
    memset(&b->fit, 0, sizeof b->fit);
    b->best_cylinder = b->best_cone = NAN;
    int have_cylinder = developable_fit_cylinder(xyz, nfit, axis,
                                                 &cylinder) == 0;
    if (have_cylinder) {
        b->best_cylinder = developable_max_distance(&cylinder, xyz, n);
        if (b->best_cylinder <= limit) {
            b->fitted = 1;
            b->fit = cylinder;
            b->sp_deviation = b->best_cylinder;
            return;
        }
        /* From the cylinder and from where the rulings converge; the one
         * nearer the samples is kept (two least-squares cones can tie
         * where their largest distances do not). */
        struct developable start[2];
        start[0] = cylinder;
        int starts = 1 + (developable_cone_start(xyz, nfit, xyz, ruling,
                                                 nrulings, &start[1]) == 0);
        for (int k = 0; k < starts; k++) {
            if (developable_fit_cone(xyz, nfit, &start[k], &cone) != 0)
                continue;
            double deviation = developable_max_distance(&cone, xyz, n);
            if (isfinite(deviation) && !(deviation >= b->best_cone)) {
                b->best_cone = deviation;
                b->fit = cone;
            }
        }
        if (b->best_cone <= limit) {
            b->fitted = 1;
            b->sp_deviation = b->best_cone;
            return;
        }
    }
    b->type = TYPE_DP;
    b->misfit = 1;
    b->sp_deviation = fmin(b->best_cylinder, b->best_cone);
}

int built_option_fit(const struct mesh *mesh, const struct fit_points *points,
                     const struct panelization *panels,
                     const struct cell_sides *sides, double threshold,
                     struct built_option *out, struct facet_error *err)
{
    memset(out, 0, sizeof *out);
    out->npanels = panels->npanels;
    out->threshold = threshold;
    size_t np = panels->npanels;
    out->panels = calloc(np + 1, sizeof *out->panels);
    size_t *start = calloc(np + 2, sizeof *start);
    uint32_t *member = NULL, *held = NULL;
    int32_t *held_by = NULL;
    double *xyz = NULL, *ruling = NULL;
    if (out->panels == NULL || start == NULL)
        goto out_of_memory;
    double du = (panels->umax - panels->umin) / panels->nu;
    double dv = (panels->vmax - panels->vmin) / panels->nv;

    /* The fit points of each SP panel, bucketed: count, then place. The
     * count keeps the points some SP panel holds in held, and the panel of
     * those only one holds (all but the points on cell lines) in held_by
     * (-1 for the others), so that the placing looks again only at the
     * points on cell lines some SP panel holds (most of a surface is in FP
     * and DP panels, most points inside a cell). */
    held = malloc((points->npoints + 1) * sizeof *held);
    held_by = malloc((points->npoints + 1) * sizeof *held_by);
    if (held == NULL || held_by == NULL)
        goto out_of_memory;
    size_t nheld = 0;
    for (size_t p = 0; p < points->npoints; p++) {
        int32_t holder[4];
        int n = point_panels(points, p, panels, du, dv, holder);
        for (int k = 0; k < n; k++)
            start[holder[k] + 2]++;
        if (n > 0) {
            held_by[nheld] = n == 1 ? holder[0] : -1;
            held[nheld++] = (uint32_t)p;
        }
    }
    size_t largest = 0;
    for (size_t k = 0; k < np; k++) {
        largest = start[k + 2] > largest ? start[k + 2] : largest;
        start[k + 2] += start[k + 1];
    }
    member = malloc((start[np + 1] + 1) * sizeof *member);
    xyz = malloc((largest + 4 * CELL_SIDE_SAMPLES) * 3 * sizeof *xyz);
    ruling = malloc((largest + 1) * 3 * sizeof *ruling);
    if (member == NULL || xyz == NULL || ruling == NULL)
        goto out_of_memory;
    for (size_t x = 0; x < nheld; x++) {
        if (held_by[x] >= 0) {
            member[start[held_by[x] + 1]++] = held[x];
            continue;
        }
        int32_t holder[4];
        int n = point_panels(points, held[x], panels, du, dv, holder);
        for (int k = 0; k < n; k++)
            member[start[holder[k] + 1]++] = held[x];
    }

    for (size_t k = 0; k < np; k++) {
        const struct panel *panel = &panels->panels[k];
        struct built_panel *b = &out->panels[k];
        b->type = panel->type;
        b->sp_deviation = b->best_cylinder = b->best_cone = NAN;
        if (panel->type != TYPE_SP)
            continue;
        /* Mean ruling of the points inside, and the samples. */
        double outer[9] = {0};
        size_t n = 0;
        for (size_t m = start[k]; m < start[k + 1]; m++) {
            size_t p = member[m];
            const double *r = points->ruling + 3 * p;
            for (int a = 0; a < 3; a++)
                for (int c = 0; c < 3; c++)
                    outer[3 * a + c] += r[a] * r[c];
            memcpy(xyz + 3 * n, mesh->position + 3 * (size_t)points->vertex[p],
                   3 * sizeof *xyz);
            memcpy(ruling + 3 * n, r, 3 * sizeof *ruling);
            n++;
        }
        /* Every FIT_SIDE_STRIDE-th sample of the sides (corners included,
         * once) joins the fit; the others only the deviation. The first
         * two sides start at a corner, the last two end at one. */
        int i = panel->i, j = panel->j;
        size_t around[4] = {
            cell_side_v(sides, i, j), cell_side_u(sides, i + 1, j),
            cell_side_v(sides, i, j + 1), cell_side_u(sides, i, j)};
        size_t nfit = 0;
        for (int pass = 0; pass < 2; pass++) {
            for (int e = 0; e < 4; e++)
                for (int step = 0; step < CELL_SIDE_SEGMENTS; step++) {
                    int at = e < 2 ? step : step + 1;
                    if ((at % FIT_SIDE_STRIDE == 0) == (pass == 0))
                        add_sample(sides, around[e], at, xyz, &n);
                }
            if (pass == 0)
                nfit = n;
        }
        double axis[3];
        if (start[k + 1] > start[k]) {
            double value[3], vector[3][3];
            sym3_eigen(outer, value, vector);
            memcpy(axis, vector[2], sizeof axis);
        } else {
            /* No point inside: the longest extent of the samples. */
            double mean[3], value[3], vector[3][3];
            developable_principal_axes(xyz, n, mean, value, vector);
            memcpy(axis, vector[2], sizeof axis);
        }
        fit_panel(panel, xyz, nfit, n, ruling, start[k + 1] - start[k], axis,
                  threshold, b);
        if (b->fitted)
            out->sp_fitted++;
        else
            out->sp_misfits++;
    }
    free(start);
    free(member);
    free(held);
    free(held_by);
    free(xyz);
    free(ruling);
    return FACET_OK;

out_of_memory:
    free(start);
    free(member);
    free(held);
    free(held_by);
    free(xyz);
    free(ruling);
    built_option_free(out);
    return facet_error_set(err, FACET_EWORK,
                           "out of memory fitting %zu panels", np);
}

void built_option_free(struct built_option *built)
{
    free(built->panels);
    memset(built, 0, sizeof *built);
}

/* "4.2 mm", or "none" for NaN (no surface of that kind fits the
 * samples). */
static void millimetres(double metres, char *text, size_t size)
{
    if (isnan(metres))
        snprintf(text, size, "none");
    else
        snprintf(text, size, "%.1f mm", metres * 1e3);
}

void built_panel_reason(const struct built_option *built, size_t panel,
                        char *text, size_t size)
{
    const struct built_panel *b = &built->panels[panel];
    if (size > 0)
        text[0] = '\0';
    if (!b->misfit)
        return;
    char cylinder[32], cone[32];
    millimetres(b->best_cylinder, cylinder, sizeof cylinder);
    millimetres(b->best_cone, cone, sizeof cone);
    snprintf(text, size,
             "no cylinder or cone within t = %.1f mm: best cylinder %s, "
             "best cone %s", built->threshold * 1e3, cylinder, cone);
}
