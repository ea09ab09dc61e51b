/*
 * test_sp_bending.c: the smallest radius an option's SP panels are bent to
 * (sp_min_radius), against closed forms: a cylinder of radius R gives R; a
 * cone of half-angle a, cut from slant s0 to s1 from its apex, gives the
 * radius of its normal curvature across the rulings at s0, s0 tan a (the
 * distance s0 sin a from the axis over cos a). A surface whose panels are
 * all flat has none (NaN, never 0, and shown "none"), and a run that does
 * not measure the fits leaves it not measured.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "core/evaluate/evaluate.h"
#include "core/fit/developable.h"
#include "core/fit/sp_fit.h"
#include "core/panel/panel.h"
#include "core/quantity/quantity.h"
#include "tests/support/surface_fixture.h"
#include "tests/support/temp_dir.h"

/* A grid of (n + 1) x (m + 1) vertices at point(i / n, j / m), with UVs,
 * written as quads to path. */
typedef void (*point_at)(double u, double v, double xyz[3]);

static void write_grid(const char *path, int n, int m, point_at point)
{
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    for (int j = 0; j <= m; j++)
        for (int i = 0; i <= n; i++) {
            double x[3];
            point((double)i / n, (double)j / m, x);
            fprintf(f, "v %.17g %.17g %.17g\n", x[0], x[1], x[2]);
        }
    for (int j = 0; j <= m; j++)
        for (int i = 0; i <= n; i++)
            fprintf(f, "vt %.17g %.17g\n", (double)i / n, (double)j / m);
    for (int j = 0; j < m; j++)
        for (int i = 0; i < n; i++) {
            int a = j * (n + 1) + i + 1;
            int b = a + 1, c = a + n + 2, d = a + n + 1;
            fprintf(f, "f %d/%d %d/%d %d/%d %d/%d\n", a, a, b, b, c, c, d, d);
        }
    assert_int_equal(fclose(f), 0);
}

#define CYLINDER_R 5.0

/* A quarter of a cylinder of radius 5 m, 4 m high. */
static void cylinder(double u, double v, double x[3])
{
    double t = u * M_PI / 2;
    x[0] = CYLINDER_R * cos(t);
    x[1] = CYLINDER_R * sin(t);
    x[2] = 4 * v;
}

#define CONE_A (30 * M_PI / 180)
#define CONE_S0 3.0
#define CONE_S1 10.0

/* A cone of half-angle 30 degrees, apex at the origin, axis z, from slant
 * 3 m to 10 m, 150 degrees around. */
static void cone(double u, double v, double x[3])
{
    double t = u * 150 * M_PI / 180;
    double s = CONE_S0 + (CONE_S1 - CONE_S0) * v;
    x[0] = s * sin(CONE_A) * cos(t);
    x[1] = s * sin(CONE_A) * sin(t);
    x[2] = s * cos(CONE_A);
}

/* A plane: every panel flat. */
static void plane(double u, double v, double x[3])
{
    x[0] = 6 * u;
    x[1] = 4 * v;
    x[2] = 0;
}

/* Evaluates the surface point makes at grid nu x nv, threshold t (mm),
 * the measures left out unmeasured, into *totals; its panels into *keep
 * (the caller frees them) unless keep is NULL. */
static void evaluate_kept(point_at point, int n, int m, int nu, int nv,
                          double t, unsigned unmeasured,
                          struct option_totals *totals,
                          struct panelization *keep)
{
    char dir[256], path[300];
    assert_int_equal(temp_dir_make(dir, sizeof dir, "sp_bending"), 0);
    snprintf(path, sizeof path, "%s/s.obj", dir);
    write_grid(path, n, m, point);
    struct surface s;
    struct facet_error err;
    if (surface_fixture_open(path, &s, &err) != FACET_OK)
        fail_msg("%s", err.message);
    struct option_params base;
    option_params_defaults(&base);
    base.unmeasured = unmeasured;
    /* Without the fits, SP panels are priced as classed. */
    base.classify.sp_by_class = (unmeasured & OPTION_MEASURE_FITS) != 0;
    struct option_params params = option_params_at(&base, nu, nv, t);
    struct panelization panels;
    if (option_evaluate(&s, &params, NULL, &panels, totals, &err) != FACET_OK)
        fail_msg("%s", err.message);
    if (keep != NULL)
        *keep = panels;
    else
        panelization_free(&panels);
    surface_close(&s);
    temp_dir_remove(dir);
}

static void evaluate(point_at point, int n, int m, int nu, int nv,
                     double t, unsigned unmeasured,
                     struct option_totals *totals)
{
    evaluate_kept(point, n, m, nu, nv, t, unmeasured, totals, NULL);
}

/* Each SP panel keeps its whole fit (panel.h's sp_fit, schema v13), so
 * that an export builds the panel from it without fitting it again: the
 * bending radius of every panel, their least the option's sp_min_radius
 * to the bit, and the surface built_panel_of_fit makes of it against the
 * analytic surface: the design surface's points over the panel's cell
 * (its UV box, the grid's, at 5 x 5 places) within the panel's own SP
 * deviation of it, plus the mesh's sag. */
static void check_kept_fits(point_at point, int nu, int nv, double sag)
{
    struct option_totals t;
    struct panelization panels;
    evaluate_kept(point, 120, 60, nu, nv, 3, 0, &t, &panels);
    double least = INFINITY, worst = 0;
    size_t fitted = 0;
    for (size_t k = 0; k < panels.npanels; k++) {
        const struct panel *p = &panels.panels[k];
        struct built_panel b;
        if (p->built != TYPE_SP || p->sp_fit.shape == PANEL_SP_NONE)
            continue;
        assert_int_equal(built_panel_of_fit(&p->sp_fit, p->sp_deviation, &b),
                         0);
        assert_true(b.bending_radius == p->sp_fit.bending_radius);
        least = fmin(least, b.bending_radius);
        fitted++;
        for (int a = 0; a <= 4; a++)
            for (int c = 0; c <= 4; c++) {
                double u = (p->i + a / 4.0) / nu, v = (p->j + c / 4.0) / nv;
                double x[3];
                point(u, v, x);
                double off = fabs(developable_distance(&b.fit, x)) -
                             p->sp_deviation;
                worst = fmax(worst, off);
            }
    }
    printf("%zu SP panels kept their fits: least bending radius %.6f m "
           "(sp_min_radius %.6f m); the design surface at most %.2g m "
           "beyond each panel's SP deviation from its kept fit\n", fitted,
           least, t.sp_min_radius, worst);
    assert_true(fitted == t.sp_fitted && fitted > 0);
    assert_true(least == t.sp_min_radius);
    assert_true(worst <= sag);
    panelization_free(&panels);
}

static void test_panels_keep_their_fits(void **state)
{
    (void)state;
    /* the meshes' chords sag R (1 - cos(step / 2)) off the surface:
     * under 0.2 mm for both */
    check_kept_fits(cylinder, 4, 2, 2e-4);
    check_kept_fits(cone, 4, 3, 2e-4);
}

static void test_cylinder_gives_its_radius(void **state)
{
    (void)state;
    struct option_totals t;
    evaluate(cylinder, 60, 20, 4, 2, 3, 0, &t);
    assert_true(t.sp_fitted == t.panels);
    /* The fit is to samples of the mesh, whose chords sag
     * R (1 - cos(pi / 240)) = 0.43 mm inside: the radius to 1 mm. */
    printf("cylinder R %.6f m: sp_min_radius %.6f m\n", CYLINDER_R,
           t.sp_min_radius);
    assert_true(fabs(t.sp_min_radius - CYLINDER_R) < 1e-3);
    assert_false(quantity_none(quantity_named("sp_min_radius"), &t));
}

static void test_cone_gives_its_radius_nearest_the_apex(void **state)
{
    (void)state;
    struct option_totals t;
    evaluate(cone, 120, 60, 4, 3, 3, 0, &t);
    assert_true(t.sp_fitted > 0);
    double truth = CONE_S0 * tan(CONE_A);
    printf("cone: truth %.6f m, sp_min_radius %.6f m (%zu of %zu panels "
           "fitted)\n", truth, t.sp_min_radius, t.sp_fitted, t.panels);
    /* The panels along the near rim are among those fitted; their samples
     * reach the rim, on the surface to the mesh's sag (0.1 mm here). */
    assert_true(fabs(t.sp_min_radius - truth) < 2e-3 * truth);
}

static void test_no_sp_panel_has_none(void **state)
{
    (void)state;
    struct option_totals t;
    evaluate(plane, 6, 4, 3, 2, 3, 0, &t);
    assert_true(t.count[TYPE_SP] == 0);
    assert_true(isnan(t.sp_min_radius));
    /* A view says "none", not "not measured": the fits ran. */
    assert_true(quantity_none(quantity_named("sp_min_radius"), &t));
}

static void test_not_measured_without_fits(void **state)
{
    (void)state;
    struct option_totals t;
    evaluate(cylinder, 60, 20, 4, 2, 3,
             OPTION_MEASURE_FITS | OPTION_MEASURE_JOINTS, &t);
    assert_true(isnan(t.sp_min_radius));
    assert_true(t.sp_fitted == TOTALS_UNKNOWN);
    assert_false(quantity_none(quantity_named("sp_min_radius"), &t));
    /* And the quantity says so: measured with the fits. */
    const struct quantity *q = quantity_named("sp_min_radius");
    assert_non_null(q);
    assert_int_equal(q->measure, OPTION_MEASURE_FITS);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_cylinder_gives_its_radius),
        cmocka_unit_test(test_cone_gives_its_radius_nearest_the_apex),
        cmocka_unit_test(test_no_sp_panel_has_none),
        cmocka_unit_test(test_not_measured_without_fits),
        cmocka_unit_test(test_panels_keep_their_fits),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
