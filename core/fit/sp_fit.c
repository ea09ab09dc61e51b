/*
 * sp_fit.c: single-curved panels as built. See sp_fit.h.
 */
#include "core/fit/sp_fit.h"

#include <assert.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/base/sym3.h"
#include "core/base/vec3.h"
#include "core/classify/classify.h"
#include "core/base/units.h"

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

/* The panels holding fit point p (the panels of the cells it lies in),
 * only the SP ones unless any, into out; returns how many. */
static int point_panels(const struct fit_points *points, size_t p,
                        const struct panelization *panels, double du,
                        double dv, int any, int32_t out[4])
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
            if (panel >= 0 && (any || panels->panels[panel].type == TYPE_SP))
                out[n++] = panel;
        }
    return n;
}

/* Appends sample k of side s to xyz at *n when it is on the surface: on
 * the smooth surface through the vertices when smooth, else on the
 * facets. */
static void add_sample(const struct cell_sides *sides, size_t s, int k,
                       int smooth, double *xyz, size_t *n)
{
    size_t at = s * CELL_SIDE_SAMPLES + (size_t)k;
    if (!sides->on[at])
        return;
    const double *x = smooth ? sides->smooth : sides->point;
    memcpy(xyz + 3 * *n, x + 3 * at, 3 * sizeof *xyz);
    (*n)++;
}

/* The fit points of panels, bucketed: those of panel k are member[start[k]
 * .. start[k + 1]), in the order of the points; only the SP panels' unless
 * any. largest: the most of one panel. */
struct buckets {
    size_t *start;             /* npanels + 2 */
    uint32_t *member;
    size_t largest;
};

static void buckets_free(struct buckets *b)
{
    free(b->start);
    free(b->member);
    memset(b, 0, sizeof *b);
}

/* Fills *out (release with buckets_free); returns 0, or -1 when out of
 * memory. */
static int buckets_build(const struct fit_points *points,
                         const struct panelization *panels, int any,
                         struct buckets *out)
{
    memset(out, 0, sizeof *out);
    size_t np = panels->npanels;
    double du = (panels->umax - panels->umin) / panels->nu;
    double dv = (panels->vmax - panels->vmin) / panels->nv;
    out->start = calloc(np + 2, sizeof *out->start);
    /* Count, then place. The count keeps the points some panel holds in
     * held, and the panel of those only one holds (all but the points on
     * cell lines) in held_by (-1 for the others), so that the placing looks
     * again only at the points on cell lines (most of a surface is in FP
     * and DP panels, most points inside a cell). */
    uint32_t *held = malloc((points->npoints + 1) * sizeof *held);
    int32_t *held_by = malloc((points->npoints + 1) * sizeof *held_by);
    if (out->start == NULL || held == NULL || held_by == NULL)
        goto out_of_memory;
    size_t *start = out->start;
    size_t nheld = 0;
    for (size_t p = 0; p < points->npoints; p++) {
        int32_t holder[4];
        int n = point_panels(points, p, panels, du, dv, any, holder);
        for (int k = 0; k < n; k++)
            start[holder[k] + 2]++;
        if (n > 0) {
            held_by[nheld] = n == 1 ? holder[0] : -1;
            held[nheld++] = (uint32_t)p;
        }
    }
    for (size_t k = 0; k < np; k++) {
        out->largest = start[k + 2] > out->largest ? start[k + 2]
                                                   : out->largest;
        start[k + 2] += start[k + 1];
    }
    out->member = malloc((start[np + 1] + 1) * sizeof *out->member);
    if (out->member == NULL)
        goto out_of_memory;
    for (size_t x = 0; x < nheld; x++) {
        if (held_by[x] >= 0) {
            out->member[start[held_by[x] + 1]++] = held[x];
            continue;
        }
        int32_t holder[4];
        int n = point_panels(points, held[x], panels, du, dv, any, holder);
        for (int k = 0; k < n; k++)
            out->member[start[holder[k] + 1]++] = held[x];
    }
    free(held);
    free(held_by);
    return 0;

out_of_memory:
    free(held);
    free(held_by);
    buckets_free(out);
    return -1;
}

/* A panel's samples and its fit's start. */
struct samples {
    double *xyz;               /* n x 3: the first nfit join the fit */
    double *ruling;            /* nrulings x 3: of the first nrulings */
    size_t n, nfit, nrulings;
    double axis[3];            /* the cylinder's start */
};

/* Gathers panel k's samples into *out (its arrays of room for the
 * largest bucket and four sides). */
static void gather(const struct mesh *mesh, const struct fit_points *points,
                   const struct panel *panel, const struct buckets *buckets,
                   size_t k, const struct cell_sides *sides, int smooth,
                   struct samples *out)
{
    double *xyz = out->xyz;
    /* Mean ruling of the points inside, and the samples. */
    double outer[9] = {0};
    size_t n = 0;
    for (size_t m = buckets->start[k]; m < buckets->start[k + 1]; m++) {
        size_t p = buckets->member[m];
        const double *r = points->ruling + 3 * p;
        for (int a = 0; a < 3; a++)
            for (int c = 0; c < 3; c++)
                outer[3 * a + c] += r[a] * r[c];
        memcpy(xyz + 3 * n, mesh->position + 3 * (size_t)points->vertex[p],
               3 * sizeof *xyz);
        memcpy(out->ruling + 3 * n, r, 3 * sizeof *out->ruling);
        n++;
    }
    out->nrulings = n;
    /* Every FIT_SIDE_STRIDE-th sample of the sides (corners included,
     * once) joins the fit; the others only the deviation. The first
     * two sides start at a corner, the last two end at one. */
    int i = panel->i, j = panel->j;
    size_t around[4] = {
        cell_side_v(sides, i, j), cell_side_u(sides, i + 1, j),
        cell_side_v(sides, i, j + 1), cell_side_u(sides, i, j)};
    for (int pass = 0; pass < 2; pass++) {
        for (int e = 0; e < 4; e++)
            for (int step = 0; step < CELL_SIDE_SEGMENTS; step++) {
                int at = e < 2 ? step : step + 1;
                if ((at % FIT_SIDE_STRIDE == 0) == (pass == 0))
                    add_sample(sides, around[e], at, smooth, xyz, &n);
            }
        if (pass == 0)
            out->nfit = n;
    }
    out->n = n;
    if (out->nrulings > 0) {
        double value[3], vector[3][3];
        sym3_eigen(outer, value, vector);
        memcpy(out->axis, vector[2], sizeof out->axis);
    } else {
        /* No point inside: the longest extent of the samples. */
        double mean[3], value[3], vector[3][3];
        developable_principal_axes(xyz, n, mean, value, vector);
        memcpy(out->axis, vector[2], sizeof out->axis);
    }
}

/* A panel's fits, which do not depend on the threshold (only their
 * verdict does): its cylinder, and when that misses, its cones. */
struct panel_fits {
    unsigned char cylinder_done, cone_done;
    unsigned char have_cylinder;
    struct developable cylinder;
    double best_cylinder;      /* NaN without a cylinder */
    struct developable cone;   /* the cone kept; zero when none */
    double best_cone;          /* NaN without a cone */
    double cone_bending;       /* its bending radius (built_panel) */
};

/* The smallest radius of the cone d over points (n x 3, m): the normal
 * curvature across the rulings at distance rho from the axis is cos a /
 * rho (a the half-angle, tan a = |slope|), so the radius is rho sqrt(1 +
 * slope^2), least where rho is. rho is the surface's at each point's place
 * along the axis. */
static double cone_bending_radius(const struct developable *d,
                                  const double *points, size_t n)
{
    double least = INFINITY;
    for (size_t k = 0; k < n; k++) {
        const double *x = points + 3 * k;
        double h = (x[0] - d->base[0]) * d->axis[0] +
                   (x[1] - d->base[1]) * d->axis[1] +
                   (x[2] - d->base[2]) * d->axis[2];
        least = fmin(least, fabs(d->radius + d->slope * h));
    }
    return n > 0 ? least * sqrt(1 + d->slope * d->slope) : NAN;
}

static void fit_cylinder(const struct samples *s, struct panel_fits *f)
{
    f->cylinder_done = 1;
    f->best_cylinder = NAN;
    f->have_cylinder = developable_fit_cylinder(s->xyz, s->nfit, s->axis,
                                                &f->cylinder) == 0;
    if (f->have_cylinder)
        f->best_cylinder = developable_max_distance(&f->cylinder, s->xyz,
                                                    s->n);
}

/* From the cylinder and from where the rulings converge; the one nearer
 * the samples is kept (two least-squares cones can tie where their largest
 * distances do not). */
static void fit_cones(const struct samples *s, struct panel_fits *f)
{
    f->cone_done = 1;
    f->best_cone = NAN;
    memset(&f->cone, 0, sizeof f->cone);
    struct developable start[2], cone;
    start[0] = f->cylinder;
    int starts = 1 + (developable_cone_start(s->xyz, s->nfit, s->xyz,
                                             s->ruling, s->nrulings,
                                             &start[1]) == 0);
    for (int k = 0; k < starts; k++) {
        if (developable_fit_cone(s->xyz, s->nfit, &start[k], &cone) != 0)
            continue;
        double deviation = developable_max_distance(&cone, s->xyz, s->n);
        if (isfinite(deviation) && !(deviation >= f->best_cone)) {
            f->best_cone = deviation;
            f->cone = cone;
            f->cone_bending = cone_bending_radius(&cone, s->xyz, s->n);
        }
    }
}

/* 1 when panel's fits f, at threshold, need the cones. */
static int needs_cones(const struct panel *panel,
                       const struct panel_fits *f, double threshold)
{
    double limit = threshold + CLASSIFY_ROUNDING * panel->diameter;
    return f->have_cylinder && !(f->best_cylinder <= limit);
}

/* Builds the SP panel from its fits f (the cones done when needs_cones)
 * at threshold into *b. */
static void judge(const struct panel *panel, const struct panel_fits *f,
                  double threshold, struct built_panel *b)
{
    double limit = threshold + CLASSIFY_ROUNDING * panel->diameter;
    memset(&b->fit, 0, sizeof b->fit);
    b->best_cylinder = f->best_cylinder;
    b->best_cone = NAN;
    if (f->have_cylinder) {
        if (f->best_cylinder <= limit) {
            b->fitted = 1;
            b->fit = f->cylinder;
            b->sp_deviation = f->best_cylinder;
            b->bending_radius = fabs(f->cylinder.radius);
            return;
        }
        b->best_cone = f->best_cone;
        b->fit = f->cone;
        if (f->best_cone <= limit) {
            b->fitted = 1;
            b->sp_deviation = f->best_cone;
            b->bending_radius = f->cone_bending;
            return;
        }
    }
    b->type = TYPE_DP;
    b->misfit = 1;
    b->sp_deviation = fmin(b->best_cylinder, b->best_cone);
}

/* Scratch for one panel's samples: room for the largest bucket and four
 * sides. Returns 0, or -1 when out of memory. */
static int samples_alloc(size_t largest, struct samples *s)
{
    memset(s, 0, sizeof *s);
    s->xyz = malloc((largest + 4 * CELL_SIDE_SAMPLES) * 3 * sizeof *s->xyz);
    s->ruling = malloc((largest + 1) * 3 * sizeof *s->ruling);
    return s->xyz != NULL && s->ruling != NULL ? 0 : -1;
}

static void samples_free(struct samples *s)
{
    free(s->xyz);
    free(s->ruling);
    memset(s, 0, sizeof *s);
}

/* SP panels fitted between two questions to the stop: a cone search
 * takes up to about a millisecond. */
#define FITS_BETWEEN_STOPS 256

/* Builds every panel of panels into out (allocated, zeroed but for the
 * threshold and counts), fitting each SP panel k from the fits cache[k]
 * (done there as needed) or, without a cache, anew. FACET_OK, or
 * FACET_ESTOP when stop asks (out then partly built; the fits cached so
 * far are whole). */
static int build_panels(const struct mesh *mesh,
                        const struct fit_points *points,
                        const struct panelization *panels,
                        const struct cell_sides *sides,
                        const struct buckets *buckets,
                        struct panel_fits *cache, double threshold,
                        int smooth, const struct facet_stop *stop,
                        struct samples *s, struct built_option *out,
                        struct facet_error *err)
{
    size_t fitted = 0;
    for (size_t k = 0; k < panels->npanels; k++) {
        const struct panel *panel = &panels->panels[k];
        struct built_panel *b = &out->panels[k];
        b->type = panel->type;
        b->sp_deviation = b->best_cylinder = b->best_cone = NAN;
        b->bending_radius = NAN;
        if (panel->type != TYPE_SP)
            continue;
        if (fitted++ % FITS_BETWEEN_STOPS == 0) {
            int rc = facet_stop_check(stop, err);
            if (rc != FACET_OK)
                return rc;
        }
        struct panel_fits alone, *f = cache != NULL ? &cache[k] : &alone;
        if (cache == NULL)
            memset(&alone, 0, sizeof alone);
        int gathered = 0;
        if (!f->cylinder_done) {
            gather(mesh, points, panel, buckets, k, sides, smooth, s);
            gathered = 1;
            fit_cylinder(s, f);
        }
        if (!f->cone_done && needs_cones(panel, f, threshold)) {
            if (!gathered)
                gather(mesh, points, panel, buckets, k, sides, smooth, s);
            fit_cones(s, f);
        }
        judge(panel, f, threshold, b);
        if (b->fitted)
            out->sp_fitted++;
        else
            out->sp_misfits++;
    }
    return FACET_OK;
}

int built_option_fit(const struct mesh *mesh, const struct fit_points *points,
                     const struct panelization *panels,
                     const struct cell_sides *sides, double threshold,
                     int smooth, struct built_option *out,
                     struct facet_error *err)
{
    return built_option_fit_stoppable(mesh, points, panels, sides, threshold,
                                      smooth, NULL, out, err);
}

int built_option_fit_stoppable(const struct mesh *mesh,
                               const struct fit_points *points,
                               const struct panelization *panels,
                               const struct cell_sides *sides,
                               double threshold, int smooth,
                               const struct facet_stop *stop,
                               struct built_option *out,
                               struct facet_error *err)
{
    memset(out, 0, sizeof *out);
    out->npanels = panels->npanels;
    out->threshold = threshold;
    out->smooth = smooth;
    size_t np = panels->npanels;
    struct buckets buckets;
    struct samples s;
    memset(&s, 0, sizeof s);
    out->panels = calloc(np + 1, sizeof *out->panels);
    if (buckets_build(points, panels, 0, &buckets) != 0 ||
        out->panels == NULL || samples_alloc(buckets.largest, &s) != 0) {
        buckets_free(&buckets);
        samples_free(&s);
        built_option_free(out);
        return facet_error_set(err, FACET_EWORK,
                               "out of memory fitting %zu panels", np);
    }
    int rc = build_panels(mesh, points, panels, sides, &buckets, NULL,
                          threshold, smooth, stop, &s, out, err);
    buckets_free(&buckets);
    samples_free(&s);
    if (rc != FACET_OK)
        built_option_free(out);
    return rc;
}

int grid_fits_init(const struct mesh *mesh, const struct uv_index *index,
                   const struct curvature *curvature,
                   const struct fit_points *points,
                   const struct panelization *panels, struct grid_fits *out,
                   struct facet_error *err)
{
    return grid_fits_init_stoppable(mesh, index, curvature, points, panels,
                                    NULL, out, err);
}

int grid_fits_init_stoppable(const struct mesh *mesh,
                             const struct uv_index *index,
                             const struct curvature *curvature,
                             const struct fit_points *points,
                             const struct panelization *panels,
                             const struct facet_stop *stop,
                             struct grid_fits *out, struct facet_error *err)
{
    memset(out, 0, sizeof *out);
    out->mesh = mesh;
    out->points = points;
    out->nu = panels->nu;
    out->nv = panels->nv;
    out->npanels = panels->npanels;
    int rc = cell_sides_sample_every_stoppable(mesh, index, curvature,
                                               panels, stop, &out->sides,
                                               err);
    if (rc != FACET_OK) {
        grid_fits_free(out);
        return rc;
    }
    out->buckets = malloc(sizeof *out->buckets);
    out->fits = calloc(panels->npanels + 1, sizeof *out->fits);
    out->sampled = malloc(out->sides.nsides + 1);
    if (out->buckets == NULL || out->fits == NULL || out->sampled == NULL ||
        buckets_build(points, panels, 1, out->buckets) != 0) {
        free(out->buckets);
        out->buckets = NULL;
        grid_fits_free(out);
        return facet_error_set(err, FACET_EWORK,
                               "out of memory for the fits of %zu panels",
                               panels->npanels);
    }
    return FACET_OK;
}

int grid_fits_option(struct grid_fits *grid,
                     const struct panelization *panels, double threshold,
                     int smooth, struct built_option *out,
                     struct cell_sides *sides, struct facet_error *err)
{
    return grid_fits_option_stoppable(grid, panels, threshold, smooth, NULL,
                                      out, sides, err);
}

int grid_fits_option_stoppable(struct grid_fits *grid,
                               const struct panelization *panels,
                               double threshold, int smooth,
                               const struct facet_stop *stop,
                               struct built_option *out,
                               struct cell_sides *sides,
                               struct facet_error *err)
{
    assert(panels->nu == grid->nu && panels->nv == grid->nv &&
           panels->npanels == grid->npanels);
    memset(out, 0, sizeof *out);
    out->npanels = panels->npanels;
    out->threshold = threshold;
    out->smooth = smooth;
    /* The fits kept were of the other samples: fit again. */
    if (smooth != grid->smooth) {
        memset(grid->fits, 0, grid->npanels * sizeof *grid->fits);
        grid->smooth = smooth;
    }
    struct samples s;
    out->panels = calloc(panels->npanels + 1, sizeof *out->panels);
    if (out->panels == NULL ||
        samples_alloc(grid->buckets->largest, &s) != 0) {
        samples_free(&s);
        built_option_free(out);
        return facet_error_set(err, FACET_EWORK,
                               "out of memory fitting %zu panels",
                               panels->npanels);
    }
    int rc = build_panels(grid->mesh, grid->points, panels, &grid->sides,
                          grid->buckets, grid->fits, threshold, smooth, stop,
                          &s, out, err);
    samples_free(&s);
    if (rc != FACET_OK) {
        built_option_free(out);
        return rc;
    }
    /* The sides as cell_sides_sample would have sampled them for this
     * option's types: the samples of all, the marks of these. */
    cell_sides_mark(panels, grid->sampled);
    *sides = grid->sides;
    sides->sampled = grid->sampled;
    return FACET_OK;
}

void grid_fits_free(struct grid_fits *grid)
{
    if (grid->buckets != NULL)
        buckets_free(grid->buckets);
    free(grid->buckets);
    free(grid->fits);
    free(grid->sampled);
    cell_sides_free(&grid->sides);
    memset(grid, 0, sizeof *grid);
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
        snprintf(text, size, "%.1f mm", units_mm(metres));
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
             "best cone %s", units_mm(built->threshold), cylinder, cone);
}

int built_panel_of_fit(const struct panel_sp_fit *fit, double deviation,
                       struct built_panel *out)
{
    int cone = fit->shape == PANEL_SP_CONE;
    if (fit->shape == PANEL_SP_NONE || !isfinite(fit->bending_radius))
        return -1;
    for (int d = 0; d < 3; d++)
        if (!isfinite(fit->direction[d]) ||
            !isfinite(cone ? fit->apex[d] : fit->axis_point[d]))
            return -1;
    if (!isfinite(cone ? fit->half_angle : fit->radius))
        return -1;
    struct developable d = {cone ? DEVELOPABLE_CONE : DEVELOPABLE_CYLINDER,
                            {0, 0, 0}, {0, 0, 0}, cone ? 0 : fit->radius,
                            cone ? tan(fit->half_angle) : 0};
    /* a cone from its apex along the direction towards the panel: the
     * radius grows by tan(half-angle) a metre, the surface the fit's */
    for (int k = 0; k < 3; k++) {
        d.axis[k] = fit->direction[k];
        d.base[k] = cone ? fit->apex[k] : fit->axis_point[k];
    }
    *out = (struct built_panel){
        .type = TYPE_SP, .fitted = 1, .misfit = 0, .fit = d,
        .sp_deviation = deviation, .best_cylinder = NAN, .best_cone = NAN,
        .bending_radius = fit->bending_radius};
    return 0;
}

void built_panel_describe(const struct built_panel *b,
                          const double centroid[3], struct panel_sp_fit *out)
{
    for (int d = 0; d < 3; d++)
        out->axis_point[d] = out->direction[d] = out->apex[d] = NAN;
    out->radius = out->half_angle = out->bending_radius = NAN;
    out->shape = PANEL_SP_NONE;
    if (!b->fitted)
        return;
    out->bending_radius = b->bending_radius;
    double alpha = developable_describe(&b->fit, centroid, out->axis_point,
                                        out->direction, out->apex);
    if (isfinite(out->apex[0])) {
        out->shape = PANEL_SP_CONE;
        out->half_angle = alpha;
    } else {
        out->shape = PANEL_SP_CYLINDER;
        out->radius = b->fit.radius;
    }
}
