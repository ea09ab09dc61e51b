/*
 * test_slivers.c: the smallest panel by area and by width, and the slivers
 * under a width limit (issue 31, item 2), against closed forms:
 *   - an L-shaped plane, a rectangle 10.3 m x 6 m and a strip 11 m x 1 m
 *     along its foot, on 11 x 6 cells of 1 m: the outline cuts the last
 *     column at 10.3 m, leaving five panels 0.3 m x 1 m above the strip:
 *     the smallest width 0.3 m, the smallest area 0.3 m^2, five slivers
 *     under 0.5 m (and none under 0.3 m, its own width);
 *   - a plane 10 m x 6 m on 1 m cells: no sliver, every panel 1 m wide;
 *   - a right triangle of legs 3 m and 4 m as one trimmed panel: its width
 *     is its least altitude, 3 x 4 / 5 = 2.4 m; tilted out of the xy plane
 *     (z = x) its legs are 3 and 4 sqrt 2 and the least altitude
 *     12 sqrt 2 / sqrt 41;
 *   - polygon_min_width against brute force (every pair of points as the
 *     direction of a side) on random point sets.
 * A run that does not measure widths leaves them not measured (NaN and
 * unknown, stored NULL), never 0.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "core/base/rng.h"
#include "core/evaluate/evaluate.h"
#include "core/panel/panel.h"
#include "core/panel/panel_width.h"
#include "core/quantity/quantity.h"
#include "tests/support/surface_fixture.h"
#include "tests/support/temp_dir.h"

/* Writes to path the plane z = tilt x over the cells [xs[i], xs[i+1]] x
 * [ys[j], ys[j+1]] that keep(x, y) holds (x, y their far corner), each as
 * two triangles, vt = (x, y). */
typedef int (*cell_kept)(double x, double y);

static void write_plane(const char *path, const double *xs, int nx,
                        const double *ys, int ny, double tilt,
                        cell_kept keep)
{
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    for (int j = 0; j < ny; j++)
        for (int i = 0; i < nx; i++)
            fprintf(f, "v %.17g %.17g %.17g\nvt %.17g %.17g\n", xs[i], ys[j],
                    tilt * xs[i], xs[i], ys[j]);
    for (int j = 0; j + 1 < ny; j++)
        for (int i = 0; i + 1 < nx; i++) {
            if (!keep(xs[i + 1], ys[j + 1]))
                continue;
            int a = j * nx + i + 1, b = a + 1, c = b + nx, d = a + nx;
            fprintf(f, "f %d/%d %d/%d %d/%d\nf %d/%d %d/%d %d/%d\n", a, a,
                    b, b, c, c, a, a, c, c, d, d);
        }
    assert_int_equal(fclose(f), 0);
}

/* The L: everything left of 10.3 m, and the strip under 1 m. */
static int in_l(double x, double y)
{
    return x <= 10.3 || y <= 1;
}

static int everywhere(double x, double y)
{
    (void)x;
    (void)y;
    return 1;
}

/* Opens path, evaluates it at nu x nv with the width limit (m; 0: none)
 * and the measures left out unmeasured into *totals; removes dir. */
static void evaluate(const char *dir, const char *path, int nu, int nv,
                     double limit, unsigned unmeasured,
                     struct option_totals *totals)
{
    struct surface s;
    struct facet_error err;
    if (surface_fixture_open(path, &s, &err) != FACET_OK)
        fail_msg("%s", err.message);
    struct option_params base;
    option_params_defaults(&base);
    base.unmeasured = unmeasured;
    base.classify.min_panel_width = limit;
    base.classify.max_panel_area = 100;
    struct option_params params = option_params_at(&base, nu, nv, 3);
    struct panelization panels;
    if (option_evaluate(&s, &params, NULL, &panels, totals, &err) != FACET_OK)
        fail_msg("%s", err.message);
    panelization_free(&panels);
    surface_close(&s);
    temp_dir_remove(dir);
}

static void evaluate_l(int nu, int nv, double limit, unsigned unmeasured,
                       struct option_totals *t)
{
    static const double xs[] = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 10.3, 11};
    static const double ys[] = {0, 1, 2, 3, 4, 5, 6};
    char dir[256], path[300];
    assert_int_equal(temp_dir_make(dir, sizeof dir, "slivers"), 0);
    snprintf(path, sizeof path, "%s/l.obj", dir);
    write_plane(path, xs, 13, ys, 7, 0, in_l);
    evaluate(dir, path, nu, nv, limit, unmeasured, t);
}

static void test_l_plane_slivers(void **state)
{
    (void)state;
    struct option_totals t;
    evaluate_l(11, 6, 0.5, 0, &t);
    /* 10 x 6 whole cells, the last column's foot, its five slivers. */
    assert_true(t.panels == 66);
    assert_true(fabs(t.area - (10.3 * 6 + 0.7)) < 1e-9);
    assert_true(fabs(t.min_panel_width - 0.3) < 1e-9);
    assert_true(fabs(t.min_panel_area - 0.3) < 1e-9);
    assert_true(t.slivers == 5);
    assert_int_equal(t.feasible, 0);
    /* The slivers meet a limit of their own width (rounding allowed), and
     * one just under it. */
    evaluate_l(11, 6, 0.3, 0, &t);
    assert_true(t.slivers == 0);
    assert_int_equal(t.feasible, 1);
    evaluate_l(11, 6, 0.3 + 1e-6, 0, &t);
    assert_true(t.slivers == 5);
    assert_int_equal(t.feasible, 0);
}

static void test_plane_without_slivers(void **state)
{
    (void)state;
    static const double xs[] = {0, 10};
    static const double ys[] = {0, 6};
    char dir[256], path[300];
    assert_int_equal(temp_dir_make(dir, sizeof dir, "slivers"), 0);
    snprintf(path, sizeof path, "%s/p.obj", dir);
    write_plane(path, xs, 2, ys, 2, 0, everywhere);
    struct option_totals t;
    evaluate(dir, path, 10, 6, 0.5, 0, &t);
    assert_true(t.panels == 60);
    assert_true(fabs(t.min_panel_width - 1) < 1e-9);
    assert_true(fabs(t.min_panel_area - 1) < 1e-9);
    assert_true(t.slivers == 0);
    assert_int_equal(t.feasible, 1);
}

/* A right triangle of legs 4 (x) and 3 (y) on the plane z = tilt x, one
 * panel: its least altitude. */
static double triangle_width(double tilt)
{
    char dir[256], path[300];
    assert_int_equal(temp_dir_make(dir, sizeof dir, "slivers"), 0);
    snprintf(path, sizeof path, "%s/t.obj", dir);
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fprintf(f, "v 0 0 0\nv 4 0 %.17g\nv 0 3 0\nvt 0 0\nvt 4 0\nvt 0 3\n"
               "f 1/1 2/2 3/3\n", 4 * tilt);
    assert_int_equal(fclose(f), 0);
    struct option_totals t;
    evaluate(dir, path, 1, 1, 0, 0, &t);
    assert_true(t.panels == 1);
    assert_true(t.slivers == 0);  /* no limit: none under it */
    return t.min_panel_width;
}

static void test_triangle_is_its_least_altitude(void **state)
{
    (void)state;
    assert_true(fabs(triangle_width(0) - 2.4) < 1e-9);
    assert_true(fabs(triangle_width(1) - 12 * sqrt(2) / sqrt(41)) < 1e-9);
}

static void test_not_measured_is_null(void **state)
{
    (void)state;
    struct option_totals t;
    evaluate_l(11, 6, 0, OPTION_MEASURE_WIDTHS, &t);
    assert_true(isnan(t.min_panel_width));
    assert_true(t.slivers == TOTALS_UNKNOWN);
    assert_true(isnan(quantity_of_totals(quantity_named("slivers"), &t)));
    /* The area is classifying's: always there. */
    assert_true(fabs(t.min_panel_area - 0.3) < 1e-9);
}

/* The least, over every direction normal to a pair of points, of the
 * points' extent along it: the width, since a narrowest strip has a side
 * along an edge of the hull, between two of the points. */
static double brute_width(const double *xy, size_t n)
{
    double best = INFINITY;
    for (size_t i = 0; i < n; i++)
        for (size_t j = 0; j < n; j++) {
            double dx = xy[2 * j] - xy[2 * i], dy = xy[2 * j + 1] - xy[2 * i + 1];
            double l = hypot(dx, dy);
            if (i == j || l == 0)
                continue;
            double lo = INFINITY, hi = -INFINITY;
            for (size_t k = 0; k < n; k++) {
                double d = ((xy[2 * k] - xy[2 * i]) * dy -
                            (xy[2 * k + 1] - xy[2 * i + 1]) * dx) / l;
                lo = fmin(lo, d);
                hi = fmax(hi, d);
            }
            best = fmin(best, hi - lo);
        }
    return best;
}

static void test_width_against_brute_force(void **state)
{
    (void)state;
    struct rng rng;
    rng_seed(&rng, 31);
    double xy[2 * 40], copy[2 * 40], scratch[4 * 40 + 4];
    for (int trial = 0; trial < 500; trial++) {
        size_t n = 3 + (size_t)(rng_uniform(&rng) * 37);
        double stretch = 0.01 + rng_uniform(&rng) * 3;
        double angle = rng_uniform(&rng) * 2 * M_PI;
        for (size_t k = 0; k < n; k++) {
            double a = rng_uniform(&rng) - 0.5;
            double b = (rng_uniform(&rng) - 0.5) * stretch;
            xy[2 * k] = a * cos(angle) - b * sin(angle);
            xy[2 * k + 1] = a * sin(angle) + b * cos(angle);
            copy[2 * k] = xy[2 * k];
            copy[2 * k + 1] = xy[2 * k + 1];
        }
        double brute = brute_width(copy, n);
        double fast = polygon_min_width(xy, n, scratch);
        if (!(fabs(fast - brute) <= 1e-12 * (1 + brute)))
            fail_msg("trial %d, %zu points: %.17g, brute force %.17g", trial,
                     n, fast, brute);
    }
    /* A square's corners and its centre; points on one line. */
    double square[] = {0, 0, 2, 0, 2, 2, 0, 2, 1, 1};
    assert_true(fabs(polygon_min_width(square, 5, scratch) - 2) < 1e-15);
    double line[] = {0, 0, 1, 1, 2, 2, 3, 3};
    assert_true(polygon_min_width(line, 4, scratch) == 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_l_plane_slivers),
        cmocka_unit_test(test_plane_without_slivers),
        cmocka_unit_test(test_triangle_is_its_least_altitude),
        cmocka_unit_test(test_not_measured_is_null),
        cmocka_unit_test(test_width_against_brute_force),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
