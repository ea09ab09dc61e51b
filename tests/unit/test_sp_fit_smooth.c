/*
 * test_sp_fit_smooth.c: single-curved panels of a mesh whose facets sag
 * more than t, measured against the surface the mesh samples.
 *
 * The surface: a strip whose vertices lie on one cylinder, R = 7.567 m
 * (axis y), 40 facets around and 60 along 35 m, each facet's chord
 * sagging 4.1 mm from the cylinder across: a designer's cylinder, meshed
 * coarsely. Every panel of it is ruled, and each is a piece of that
 * cylinder, so at t = 3 mm none may be built DP. Measured on the facets,
 * every SP panel of 20 x 35 and 6 x 6 was a misfit ("best cylinder 3.8
 * mm"). The truth here is the cylinder itself: each fitted cylinder's
 * distance from it over the panel's cell, computed in closed form from the
 * fit's axis and radius, must be within t.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "core/classify/classify.h"
#include "core/fit/sp_fit.h"
#include "core/joint/cell_sides.h"
#include "core/surface/coarse_mesh.h"
#include "core/surface/surface.h"
#include "tests/support/surface_fixture.h"
#include "tests/support/temp_dir.h"

#define RADIUS 7.567
#define SAG 0.0041
#define AROUND 40
#define ALONG 60
#define LENGTH 35.0
#define THRESHOLD 0.003

/* The angle one facet spans: its chord's midpoint lies SAG inside. */
static double facet_angle(void)
{
    return 2 * acos(1 - SAG / RADIUS);
}

/* The cylinder's point at UV (u, v) in 0..1: vt is (i / AROUND, j /
 * ALONG) at vertex (i, j). */
static void cylinder_at(double u, double v, double x[3])
{
    double theta = u * AROUND * facet_angle();
    x[0] = RADIUS * sin(theta);
    x[1] = v * LENGTH;
    x[2] = RADIUS * cos(theta);
}

static void write_strip(const char *path)
{
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    for (int j = 0; j <= ALONG; j++)
        for (int i = 0; i <= AROUND; i++) {
            double u = (double)i / AROUND, v = (double)j / ALONG, x[3];
            cylinder_at(u, v, x);
            fprintf(f, "v %.17g %.17g %.17g\nvt %.17g %.17g\n", x[0], x[1],
                    x[2], u, v);
        }
    for (int j = 0; j < ALONG; j++)
        for (int i = 0; i < AROUND; i++) {
            int a = j * (AROUND + 1) + i + 1, b = a + 1;
            int c = a + AROUND + 2, d = a + AROUND + 1;
            fprintf(f, "f %d/%d %d/%d %d/%d\nf %d/%d %d/%d %d/%d\n", a, a,
                    b, b, c, c, a, a, c, c, d, d);
        }
    assert_int_equal(fclose(f), 0);
}

/* The largest distance (m) of the true cylinder from fit d over cell
 * (i, j) of the nu x nv grid on UV 0..1, on a 21 x 21 lattice of the
 * cell: |distance from d's axis - d's radius there|, in closed form. */
static double true_deviation(const struct developable *d, int i, int j,
                             int nu, int nv)
{
    double most = 0;
    for (int a = 0; a <= 20; a++)
        for (int b = 0; b <= 20; b++) {
            double x[3], w[3], along = 0, r2 = 0;
            cylinder_at((i + a / 20.0) / nu, (j + b / 20.0) / nv, x);
            for (int k = 0; k < 3; k++) {
                w[k] = x[k] - d->base[k];
                along += w[k] * d->axis[k];
            }
            for (int k = 0; k < 3; k++) {
                double across = w[k] - along * d->axis[k];
                r2 += across * across;
            }
            most = fmax(most, fabs(sqrt(r2) - (d->radius + d->slope * along)));
        }
    return most;
}

static void classify_at(struct panelization *panels, double t)
{
    struct classify_options options;
    struct option_totals totals;
    classify_defaults(&options);
    options.threshold = t;
    classify_panels(panels, &options, &totals);
}

/* The grid nu x nv at t = 3 mm: all ruled; built with the sag's own
 * choice of samples, none DP and every fit within t of the cylinder;
 * built on the facets, misfits (the defect, kept as the contrast). */
static void check_grid(const struct surface *s, int nu, int nv)
{
    struct facet_error err;
    struct panelization panels;
    struct cell_sides sides;
    struct built_option built, facets;
    if (panels_build_fast(&s->panels, PANEL_EXTREMES, nu, nv, &panels,
                          &err) != FACET_OK)
        fail_msg("%s", err.message);
    classify_at(&panels, THRESHOLD);
    int smooth = facet_sag_matters(s->facet_sag, THRESHOLD);
    assert_true(smooth);
    if (cell_sides_sample(&s->mesh, &s->uv, &s->curvature, &panels, &sides,
                          &err) != FACET_OK ||
        built_option_fit(&s->mesh, &s->fit, &panels, &sides, THRESHOLD,
                         smooth, &built, &err) != FACET_OK ||
        built_option_fit(&s->mesh, &s->fit, &panels, &sides, THRESHOLD, 0,
                         &facets, &err) != FACET_OK)
        fail_msg("%s", err.message);
    double area = 0, dp = 0, worst = 0, worst_measured = 0;
    for (size_t k = 0; k < panels.npanels; k++) {
        const struct panel *p = &panels.panels[k];
        const struct built_panel *b = &built.panels[k];
        assert_int_equal(p->type, TYPE_SP);
        area += p->area;
        if (b->type == TYPE_DP)
            dp += p->area;
        assert_true(b->fitted);
        worst = fmax(worst, true_deviation(&b->fit, p->i, p->j, nu, nv));
        worst_measured = fmax(worst_measured, b->sp_deviation);
    }
    printf("%d x %d at t = 3 mm, facets sagging %.3f mm: DP %.1f %% as "
           "built, fits within %.4f mm of the cylinder (measured %.4f mm); "
           "on the facets %zu of %zu misfits\n", nu, nv, s->facet_sag * 1e3,
           100 * dp / area, worst * 1e3, worst_measured * 1e3,
           facets.sp_misfits, panels.npanels);
    assert_true(dp == 0);
    assert_true(worst < THRESHOLD);
    assert_true(worst_measured < THRESHOLD);
    assert_true(facets.sp_misfits > 0);
    built_option_free(&built);
    built_option_free(&facets);
    cell_sides_free(&sides);
    panelization_free(&panels);
}

/* A grid kept across thresholds that cross the sag's quarter (3 mm:
 * smooth; 20 mm: facets; 3 mm again) gives what each threshold's fit
 * alone gives, to the bit. */
static void check_kept(const struct surface *s)
{
    struct facet_error err;
    struct panelization panels;
    struct grid_fits grid;
    if (panels_build_fast(&s->panels, PANEL_EXTREMES, 12, 14, &panels,
                          &err) != FACET_OK ||
        grid_fits_init(&s->mesh, &s->uv, &s->curvature, &s->fit, &panels,
                       &grid, &err) != FACET_OK)
        fail_msg("%s", err.message);
    const double t[] = {0.003, 0.02, 0.003};
    for (int x = 0; x < 3; x++) {
        classify_at(&panels, t[x]);
        int smooth = facet_sag_matters(s->facet_sag, t[x]);
        assert_int_equal(smooth, x != 1);
        struct cell_sides sides, view;
        struct built_option alone, kept;
        if (cell_sides_sample(&s->mesh, &s->uv, &s->curvature, &panels,
                              &sides, &err) != FACET_OK ||
            built_option_fit(&s->mesh, &s->fit, &panels, &sides, t[x],
                             smooth, &alone, &err) != FACET_OK ||
            grid_fits_option(&grid, &panels, t[x], smooth, &kept, &view,
                             &err) != FACET_OK)
            fail_msg("%s", err.message);
        for (size_t k = 0; k < panels.npanels; k++) {
            const struct built_panel *a = &alone.panels[k], *b = &kept.panels[k];
            assert_int_equal(a->type, b->type);
            assert_true(memcmp(&a->sp_deviation, &b->sp_deviation,
                               sizeof a->sp_deviation) == 0);
            assert_true(memcmp(&a->fit.radius, &b->fit.radius,
                               sizeof a->fit.radius) == 0);
        }
        built_option_free(&alone);
        built_option_free(&kept);
        cell_sides_free(&sides);
    }
    grid_fits_free(&grid);
    panelization_free(&panels);
}

static void test_cylinder_strip(void **state)
{
    (void)state;
    char dir[256], path[512];
    assert_int_equal(temp_dir_make(dir, sizeof dir, "sp_smooth"), 0);
    snprintf(path, sizeof path, "%s/strip.obj", dir);
    write_strip(path);
    struct surface s;
    struct facet_error err;
    if (surface_fixture_open(path, &s, &err) != FACET_OK)
        fail_msg("%s", err.message);
    /* Every facet's chord across sags SAG: the estimate reads it. */
    printf("facet sag %.4f mm, truth %.4f mm\n", s.facet_sag * 1e3,
           SAG * 1e3);
    assert_true(fabs(s.facet_sag - SAG) < 0.02 * SAG);
    check_grid(&s, 20, 35);
    check_grid(&s, 6, 6);
    check_kept(&s);
    surface_close(&s);
    temp_dir_remove(dir);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_cylinder_strip),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
