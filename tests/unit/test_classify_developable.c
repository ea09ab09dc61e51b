/*
 * test_classify_developable.c: Table 1 on coarse analytic meshes, against
 * the curvature of each surface's formula (issue 29 items 1 and 2).
 *
 *   - A cone and a parabolic cylinder are developable: K = 0 everywhere by
 *     their formulas, and their one non-zero curvature is far beyond the
 *     zero tolerance at every grid tried here. Table 1 then calls every
 *     panel ruled; none may get a K != 0 class (DP), none may turn flat.
 *     Before the zero test knew how well each vertex's curvature is known,
 *     the rims' estimation error (about 1 % of the other curvature) was
 *     read as curvature: up to 100 % of the area was typed DP at t = 3 mm,
 *     and every panel at t = 0.
 *   - Guards, so that no fix passes by calling everything zero: a sphere
 *     cap (K > 0 everywhere) keeps every panel convex_round, and a hypar
 *     (K < 0 everywhere) keeps every panel a K < 0 class, both with their
 *     smallest curvature by the formula three times the zero tolerance or more.
 *
 * The meshes are written from the formulas (tests/support's writer), on
 * 10 x 10 to 40 x 40 quads; the truths are the formulas' curvatures, so
 * nothing here is Facet's own earlier output.
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
#include "core/surface/surface.h"
#include "tests/support/surface_fixture.h"

/* ---- The surfaces ------------------------------------------------------ */

/* The cone of the issue: half-angle 30 degrees about z, apex at the
 * origin, slant 3 to 10 m (t), 150 degrees around (s). Its curvature
 * across is cot(30 deg) / slant (0.17 to 0.58 1/m), along 0. */
#define CONE_HALF_ANGLE (M_PI / 6)
static void cone(const void *shape, double s, double t, double p[3])
{
    (void)shape;
    double around = s * 150 * M_PI / 180, slant = 3 + 7 * t;
    double r = slant * sin(CONE_HALF_ANGLE);
    p[0] = r * cos(around);
    p[1] = r * sin(around);
    p[2] = slant * cos(CONE_HALF_ANGLE);
}

/* z = x^2 / 8 over x in -5..5 m (s), y in 0..8 m (t): curvature
 * 1 / (4 (1 + x^2 / 16)^1.5) across, at least 0.061 1/m, and 0 along. */
static void parabolic(const void *shape, double s, double t, double p[3])
{
    (void)shape;
    double x = -5 + 10 * s;
    p[0] = x;
    p[1] = 8 * t;
    p[2] = x * x / 8;
}

/* A sphere cap of R = 9 m over the square -4..4 m: k1 = k2 = -1/R. */
#define CAP_R 9.0
static void cap(const void *shape, double s, double t, double p[3])
{
    (void)shape;
    double x = -4 + 8 * s, y = -4 + 8 * t;
    p[0] = x;
    p[1] = y;
    p[2] = sqrt(CAP_R * CAP_R - x * x - y * y);
}

/* The hypar z = x y / 10 over -5..5 m squared. */
#define HYPAR_C 10.0
static void hypar(const void *shape, double s, double t, double p[3])
{
    (void)shape;
    double x = -5 + 10 * s, y = -5 + 10 * t;
    p[0] = x;
    p[1] = y;
    p[2] = x * y / HYPAR_C;
}

/* A catenoid of waist c = 3 m, half way round (s), z from -3 to 3 m (t):
 * a minimal surface, k = +-1 / (c cosh^2(z / c)) at every point, so the
 * paper's extremes over any panel, max k1 and min k2, are taken where
 * cosh is least and cancel exactly: Table 1 says saddle. */
#define CATENOID_C 3.0
static void catenoid(const void *shape, double s, double t, double p[3])
{
    (void)shape;
    double around = M_PI * s, z = -3 + 6 * t;
    double r = CATENOID_C * cosh(z / CATENOID_C);
    p[0] = r * cos(around);
    p[1] = r * sin(around);
    p[2] = z;
}

/* The smaller |principal curvature| of z = x y / c at (x, y), by the
 * formula: K = -1 / (c^2 W^4), H = -x y / (c^3 W^3), W^2 = 1 + (x^2 +
 * y^2) / c^2, k = H -+ sqrt(H^2 - K). */
static double hypar_smaller_k(double x, double y)
{
    double w2 = 1 + (x * x + y * y) / (HYPAR_C * HYPAR_C);
    double K = -1 / (HYPAR_C * HYPAR_C * w2 * w2);
    double H = -x * y / (HYPAR_C * HYPAR_C * HYPAR_C * w2 * sqrt(w2));
    double root = sqrt(H * H - K);
    return fmin(fabs(H - root), fabs(H + root));
}

static void open_quads(surface_formula f, int n, struct surface *s)
{
    struct facet_error err;
    if (surface_fixture_formula(f, NULL, n, n, FORMULA_QUADS, s, &err) !=
        FACET_OK)
        fail_msg("%s", err.message);
}

/* p classified at threshold t, by the paper's extremes, as classify and
 * every run do (classify_panels). */
static void classified(const struct surface *s, int nu, int nv, double t,
                       struct panelization *p)
{
    struct facet_error err;
    if (panels_build_fast(&s->panels, PANEL_EXTREMES, nu, nv, p, &err) !=
        FACET_OK)
        fail_msg("panels %dx%d: %s", nu, nv, err.message);
    struct classify_options options;
    classify_defaults(&options);
    options.threshold = t;
    struct option_totals totals;
    classify_panels(p, &options, &totals);
}

/* The share of p's area whose class has K != 0 (a DP class), and into
 * *flat that whose class is flat. */
static double share_k_nonzero(const struct panelization *p, double *flat)
{
    double area = 0, wrong = 0, flat_area = 0;
    for (size_t n = 0; n < p->npanels; n++) {
        const struct panel *panel = &p->panels[n];
        area += panel->area;
        if (panel_type_of_class(panel->class) == TYPE_DP)
            wrong += panel->area;
        if (panel->class == CLASS_FLAT)
            flat_area += panel->area;
    }
    *flat = flat_area / area;
    return wrong / area;
}

/* ---- Tests ------------------------------------------------------------- */

/* A developable surface: at every grid, t = 3 mm and t = 0, no panel has
 * a K != 0 class, and none is flat (the formula's curvature across is at
 * least smallest_k, three times every eps here or more: checked). */
static void check_developable(const char *name, surface_formula f, int mesh,
                              const int (*grids)[2], size_t ngrids,
                              double smallest_k)
{
    struct surface s;
    open_quads(f, mesh, &s);
    static const double thresholds[] = {0.003, 0};
    int failed = 0;
    for (size_t g = 0; g < ngrids; g++)
        for (size_t x = 0; x < 2; x++) {
            struct panelization p;
            classified(&s, grids[g][0], grids[g][1], thresholds[x], &p);
            double eps_t = 0;
            for (size_t n = 0; n < p.npanels; n++)
                eps_t = fmax(eps_t, 8 * fmax(thresholds[x], 1e-9 *
                                             p.panels[n].diameter) /
                                        (p.panels[n].diameter *
                                         p.panels[n].diameter));
            /* The truth is ruled only while the curvature across is
             * clearly beyond the threshold's tolerance. */
            assert_true(smallest_k > 3 * eps_t);
            double flat, wrong = share_k_nonzero(&p, &flat);
            print_message("%s %dx%d quads at %dx%d panels, t = %g mm: %.1f %% "
                          "of the area K != 0 (truth 0), %.1f %% flat "
                          "(truth 0)\n", name, mesh, mesh, grids[g][0],
                          grids[g][1], thresholds[x] * 1e3, 100 * wrong,
                          100 * flat);
            if (wrong > 0 || flat > 0)
                failed = 1;
            panelization_free(&p);
        }
    surface_close(&s);
    assert_false(failed);
}

static void test_cone(void **state)
{
    (void)state;
    static const int coarse[][2] = {{3, 3}, {5, 5}, {8, 8}};
    static const int finer[][2] = {{3, 3}, {8, 8}};
    /* the least curvature across: cot(30 deg) / 10 m */
    double k = 1 / (tan(CONE_HALF_ANGLE) * 10);
    check_developable("cone", cone, 10, coarse, 3, k);
    check_developable("cone", cone, 20, finer, 2, k);
    check_developable("cone", cone, 40, finer, 1, k);
}

static void test_parabolic_cylinder(void **state)
{
    (void)state;
    static const int grids[][2] = {{3, 3}, {6, 6}};
    double k = 0.25 / pow(1 + 25.0 / 16, 1.5);
    check_developable("z = x^2/8", parabolic, 10, grids, 2, k);
}

/* The guards: a curvature the formula says is there stays there. */
static void test_curved_kept(void **state)
{
    (void)state;
    static const int grids[][2] = {{3, 3}, {5, 5}, {8, 8}};
    static const double thresholds[] = {0.003, 0};
    /* hypar's smallest |k| is at the domain's corners (W largest) */
    double hypar_k = hypar_smaller_k(5, 5);
    for (int kind = 0; kind < 2; kind++) {
        struct surface s;
        open_quads(kind == 0 ? cap : hypar, 10, &s);
        for (size_t g = 0; g < 3; g++)
            for (size_t x = 0; x < 2; x++) {
                struct panelization p;
                classified(&s, grids[g][0], grids[g][1], thresholds[x], &p);
                double right = 0, area = 0;
                for (size_t n = 0; n < p.npanels; n++) {
                    const struct panel *panel = &p.panels[n];
                    double d = panel->diameter;
                    double eps_t = 8 * fmax(thresholds[x], 1e-9 * d) / (d * d);
                    assert_true((kind == 0 ? 1 / CAP_R : hypar_k) >
                                3 * eps_t);
                    area += panel->area;
                    if (kind == 0 ? panel->class == CLASS_CONVEX_ROUND
                                  : panel->K < 0 &&
                                    (panel->class == CLASS_SADDLE ||
                                     panel->class ==
                                         CLASS_CONVEX_FEATURE_CURVE ||
                                     panel->class ==
                                         CLASS_CONCAVE_FEATURE_CURVE))
                        right += panel->area;
                }
                print_message("%s at %dx%d, t = %g mm: %.1f %% of the area "
                              "of the formula's class\n",
                              kind == 0 ? "sphere cap" : "hypar",
                              grids[g][0], grids[g][1], thresholds[x] * 1e3,
                              100 * right / area);
                assert_true(right == area);
                panelization_free(&p);
            }
        surface_close(&s);
    }
}

/* A minimal surface: every panel a saddle, as the formula's extremes
 * cancel (the issue: 6 of 9 to 12 of 25 panels of coarse catenoids came
 * out feature curves). Its least |k|, 1 / (c cosh^2(1)), is 0.14 1/m. */
static void test_catenoid_saddles(void **state)
{
    (void)state;
    static const int grids[][2] = {{3, 3}, {5, 5}};
    static const double thresholds[] = {0.003, 0};
    struct surface s;
    open_quads(catenoid, 10, &s);
    double k = 1 / (CATENOID_C * cosh(1) * cosh(1));
    int failed = 0;
    for (size_t g = 0; g < 2; g++)
        for (size_t x = 0; x < 2; x++) {
            struct panelization p;
            classified(&s, grids[g][0], grids[g][1], thresholds[x], &p);
            double area = 0, saddle = 0;
            for (size_t n = 0; n < p.npanels; n++) {
                const struct panel *panel = &p.panels[n];
                double d = panel->diameter;
                assert_true(k > 3 * 8 * fmax(thresholds[x], 1e-9 * d) /
                                    (d * d));
                area += panel->area;
                if (panel->class == CLASS_SADDLE)
                    saddle += panel->area;
            }
            print_message("catenoid 10x10 quads at %dx%d panels, t = %g mm: "
                          "%.1f %% of the area saddle (truth 100)\n",
                          grids[g][0], grids[g][1], thresholds[x] * 1e3,
                          100 * saddle / area);
            if (saddle != area)
                failed = 1;
            panelization_free(&p);
        }
    surface_close(&s);
    assert_false(failed);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_cone),
        cmocka_unit_test(test_parabolic_cylinder),
        cmocka_unit_test(test_curved_kept),
        cmocka_unit_test(test_catenoid_saddles),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
