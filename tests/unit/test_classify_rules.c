/*
 * test_classify_rules.c: the classification rules on whole analytic
 * surfaces, through the real pipeline (OBJ file, surface_prepare,
 * option_evaluate), against what the surface's formula says:
 *   - a ruled panel never turns flat (the H test), on a cylinder whose
 *     panels have eps <= 1/R < 2 eps;
 *   - a panel typed FP lies within t of its plane, on every analytic
 *     surface at many grids, long thin panels included;
 *   - limits hold to rounding: a 2 m x 2 m panel meets a 4 m^2 limit;
 *   - t = 0 leaves a plane flat and makes nothing curved FP;
 *   - the paper's 5 x 5 hypar validation (section 4.1): only K < 0.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "core/classify/classify.h"
#include "core/surface/example.h"
#include "core/evaluate/evaluate.h"
#include "core/surface/surface.h"
#include "tests/support/surface_fixture.h"

/* ---- Analytic surfaces, written as OBJ with vt = their parameters ---- */

struct shape {
    const char *name;
    double a, b, c;       /* the shape's dimensions, by kind */
    int kind;             /* SHAPE_* */
};

enum { SHAPE_CYLINDER, SHAPE_PLANE };

/* Cylinder: radius a, arc b (radians) about the y axis, length c along y,
 * normal outwards (k = -1/R across, 0 along). Plane: a x b in z = 0. */
static void shape_point(const void *of, double s, double t, double p[3])
{
    const struct shape *shape = of;
    if (shape->kind == SHAPE_CYLINDER) {
        double angle = (s - 0.5) * shape->b;
        p[0] = shape->a * sin(angle);
        p[1] = t * shape->c;
        p[2] = shape->a * cos(angle);
    } else {
        p[0] = s * shape->a;
        p[1] = t * shape->b;
        p[2] = 0;
    }
}

/* Writes shape on ns x nt quads to a new temporary file (the shared
 * writer of tests/support); returns its path (caller frees and unlinks).
 * The cylinder's s runs along +x and t along +y, so the faces' winding
 * points its normal along +z, outwards. */
static char *shape_write(const struct shape *shape, int ns, int nt)
{
    char *path = surface_fixture_formula_write(shape_point, shape, ns, nt,
                                               FORMULA_QUADS);
    assert_non_null(path);
    return path;
}

/* Writes the named example at res to a temporary file; returns its path. */
static char *example_file(const char *name, int res)
{
    char *path = strdup("/tmp/facet_test_rules_XXXXXX");
    int fd = mkstemp(path);
    assert_true(fd >= 0);
    FILE *out = fdopen(fd, "w");
    assert_non_null(out);
    struct facet_error err;
    if (example_write(name, res, out, &err) != FACET_OK)
        fail_msg("example_write %s: %s", name, err.message);
    assert_int_equal(fclose(out), 0);
    return path;
}

static void surface_load(const char *path, struct surface *surface)
{
    struct facet_error err;
    struct mesh_options options = {UNITS_M, NULL, NULL};
    if (surface_open(path, &options, surface, &err) != FACET_OK ||
        surface_prepare(surface, 0, PARAM_AUTO, &err) != FACET_OK)
        fail_msg("%s: %s", path, err.message);
}

static void evaluate(const struct surface *surface, int nu, int nv,
                     double threshold, enum panel_curvature_mode mode,
                     struct panelization *panels,
                     struct option_totals *totals)
{
    struct option_params params;
    memset(&params, 0, sizeof params);
    params.nu = nu;
    params.nv = nv;
    params.mode = mode;
    classify_defaults(&params.classify);
    params.classify.threshold = threshold;
    struct facet_error err;
    if (option_evaluate(surface, &params, NULL, panels, totals, &err) != FACET_OK)
        fail_msg("option_evaluate %dx%d: %s", nu, nv, err.message);
}

/* ---- Tests -------------------------------------------------------------- */

/* A cylinder of R = 6 m over 90 degrees, 20 m long, at 18 x 200: panels
 * 0.52 m across and 0.1 m along, so eps = 8 t / d^2 = 0.085 1/m and
 * 1/R = 0.167 < 2 eps. Every panel sags 3.8 mm across (> t = 3 mm), and
 * every one is ruled by the formula: k = -1/R across, exactly 0 along. */
static void test_ruled_never_flat(void **state)
{
    (void)state;
    struct shape cylinder = {"cylinder", 6, M_PI / 2, 20, SHAPE_CYLINDER};
    char *path = shape_write(&cylinder, 72, 200);
    struct surface surface;
    surface_load(path, &surface);
    static const int grids[][2] = {{18, 200}, {18, 40}, {200, 18},
                                   {12, 100}, {24, 60}};
    for (size_t g = 0; g < sizeof grids / sizeof grids[0]; g++) {
        struct panelization panels;
        struct option_totals totals;
        evaluate(&surface, grids[g][0], grids[g][1], 0.003, PANEL_EXTREMES,
                 &panels, &totals);
        size_t ruled = 0, flat_beyond = 0, checked = 0;
        for (size_t n = 0; n < panels.npanels; n++) {
            const struct panel *p = &panels.panels[n];
            double eps = p->curvature_tol, k = 1 / cylinder.a;
            /* Classes the formula decides clearly: 1/R at least 1 %
             * beyond eps either way (the estimator is within 0.2 %). */
            if (fabs(k - eps) < 0.01 * eps)
                continue;
            checked++;
            if (k > eps) {
                ruled += p->class == CLASS_RULED_CONVEX;
                if (p->class == CLASS_FLAT)
                    flat_beyond++;
            } else {
                assert_int_equal(p->class, CLASS_FLAT);
                ruled++;  /* rightly flat: count it as agreeing */
            }
        }
        print_message("cylinder R 6 m at %dx%d: %zu of %zu panels as the "
                      "formula says, %zu ruled turned flat; %zu FP, %zu SP\n",
                      grids[g][0], grids[g][1], ruled, checked, flat_beyond,
                      totals.count[TYPE_FP], totals.count[TYPE_SP]);
        assert_true(checked > panels.npanels / 2);
        assert_int_equal(flat_beyond, 0);
        assert_int_equal(ruled, checked);
        panelization_free(&panels);
    }
    /* 18 x 200 in numbers: nothing is FP, since every panel deviates
     * 3.8 mm; before the rule was fixed all 3,600 were flat FP. */
    struct panelization panels;
    struct option_totals totals;
    evaluate(&surface, 18, 200, 0.003, PANEL_EXTREMES, &panels, &totals);
    assert_int_equal(totals.count[TYPE_FP], 0);
    assert_int_equal(totals.count[TYPE_SP], 3600);
    for (size_t n = 0; n < panels.npanels; n++)
        assert_true(panels.panels[n].deviation > 0.0035);
    panelization_free(&panels);
    surface_close(&surface);
    unlink(path);
    free(path);
}

/* Every panel typed FP lies within t of its plane, on every analytic
 * surface, at square grids and at long thin ones, with the paper's
 * curvature by extremes. (The mean shape operator averages the two sides
 * of an inflection to nothing, so by the mean a wave's panel across one
 * can be flat and deviate more than t: classify counts those, see
 * test_mean_flat_counted.) */
static void test_fp_within_threshold(void **state)
{
    (void)state;
    static const char *const names[] = {"plane", "cylinder", "dome", "hypar",
                                        "torus", "wave"};
    static const int grids[][2] = {{4, 4},  {10, 10}, {25, 25}, {40, 3},
                                   {3, 40}, {2, 120}, {120, 2}, {60, 60},
                                   {200, 7}, {7, 200}};
    static const double thresholds[] = {0.001, 0.003, 0.02};
    for (size_t s = 0; s < sizeof names / sizeof names[0]; s++) {
        char *path = example_file(names[s], 120);
        struct surface surface;
        surface_load(path, &surface);
        size_t fp = 0, panels_seen = 0;
        double worst = 0;
        for (size_t g = 0; g < sizeof grids / sizeof grids[0]; g++)
            for (size_t t = 0; t < 3; t++)
                for (int mode = 0; mode < 1; mode++) {
                    struct panelization panels;
                    struct option_totals totals;
                    evaluate(&surface, grids[g][0], grids[g][1],
                             thresholds[t], (enum panel_curvature_mode)mode,
                             &panels, &totals);
                    for (size_t n = 0; n < panels.npanels; n++) {
                        const struct panel *p = &panels.panels[n];
                        panels_seen++;
                        if (p->type != TYPE_FP)
                            continue;
                        fp++;
                        double over = p->deviation / thresholds[t];
                        if (over > worst)
                            worst = over;
                        if (p->deviation > thresholds[t] * (1 + 1e-9))
                            fail_msg("%s %dx%d t %g mm %s: FP panel (%d,%d) "
                                     "%s deviates %.3f mm", names[s],
                                     grids[g][0], grids[g][1],
                                     thresholds[t] * 1000,
                                     mode ? "mean" : "extremes", p->i, p->j,
                                     panel_class_name(p->class),
                                     p->deviation * 1000);
                    }
                    panelization_free(&panels);
                }
        print_message("%-8s %zu of %zu panels FP, the worst at %.3f t\n",
                      names[s], fp, panels_seen, worst);
        surface_close(&surface);
        unlink(path);
        free(path);
    }
}

/* A 10 m x 8 m plane at 5 x 4: every panel is 2 m x 2 m, whatever its sum
 * rounds to, and meets a 4 m^2 limit. */
static void test_limits_to_rounding(void **state)
{
    (void)state;
    struct shape plane = {"plane", 10, 8, 0, SHAPE_PLANE};
    char *path = shape_write(&plane, 30, 24);
    struct surface surface;
    surface_load(path, &surface);
    struct option_params params;
    memset(&params, 0, sizeof params);
    params.nu = 5;
    params.nv = 4;
    params.mode = PANEL_EXTREMES;
    classify_defaults(&params.classify);
    params.classify.max_panel_area = 4;
    struct panelization panels;
    struct option_totals totals;
    struct facet_error err;
    assert_int_equal(option_evaluate(&surface, &params, NULL, &panels, &totals,
                                     &err), FACET_OK);
    assert_int_equal(panels.npanels, 20);
    for (size_t n = 0; n < panels.npanels; n++)
        assert_true(fabs(panels.panels[n].area - 4) < 1e-12);
    print_message("largest panel %.17g m^2 under a limit of 4\n",
                  totals.max_panel_area);
    assert_true(totals.feasible);
    assert_true(classify_area_excess(totals.max_panel_area, 4) == 0);
    /* Beyond rounding it is over. */
    assert_true(classify_area_excess(4.00001, 4) > 0);
    assert_false(classify_area_excess(4 * (1 + 1e-6), 4) == 0);
    panelization_free(&panels);
    surface_close(&surface);
    unlink(path);
    free(path);
}

/* t = 0: only panels planar to rounding are FP. A plane is all flat FP; a
 * cylinder (every panel bent) has none; a stepped range from 0 works. */
static void test_threshold_zero(void **state)
{
    (void)state;
    static const char *const names[] = {"plane", "cylinder", "dome", "hypar"};
    for (size_t s = 0; s < 4; s++) {
        char *path = example_file(names[s], 60);
        struct surface surface;
        surface_load(path, &surface);
        static const int grids[][2] = {{4, 4}, {13, 7}, {30, 30}};
        for (size_t g = 0; g < 3; g++) {
            struct panelization panels;
            struct option_totals totals;
            evaluate(&surface, grids[g][0], grids[g][1], 0, PANEL_EXTREMES,
                     &panels, &totals);
            if (s == 0) {
                assert_int_equal(totals.class_count[CLASS_FLAT],
                                 panels.npanels);
                assert_int_equal(totals.count[TYPE_FP], panels.npanels);
            } else {
                assert_int_equal(totals.count[TYPE_FP], 0);
                assert_int_equal(totals.class_count[CLASS_FLAT], 0);
            }
            panelization_free(&panels);
        }
        surface_close(&surface);
        unlink(path);
        free(path);
    }
    /* An exact zero has no sign, whatever eps. */
    assert_int_equal(classify_curvature(0, 0, 0), CLASS_FLAT);
    assert_int_equal(classify_curvature(0, -1e-300, 0), CLASS_RULED_CONVEX);
}

/* The paper's validation (section 4.1): the hypar z = xy/20 on a 5 x 5
 * grid gives only K < 0 areas. By the extremes, every panel's k1 > 0 >
 * k2; the panels on the two diagonals, where H changes sign, are saddles
 * by the saddle rule, and the others split by the sign of H: docs/method.md
 * ("The paper's hypar validation") states the counts this test holds. */
static void test_paper_hypar(void **state)
{
    (void)state;
    char *path = example_file("hypar", 0);
    struct surface surface;
    surface_load(path, &surface);
    struct panelization panels;
    struct option_totals totals;
    evaluate(&surface, 5, 5, 0.003, PANEL_EXTREMES, &panels, &totals);
    size_t k_negative = totals.class_count[CLASS_CONVEX_FEATURE_CURVE] +
                        totals.class_count[CLASS_CONCAVE_FEATURE_CURVE] +
                        totals.class_count[CLASS_SADDLE];
    print_message("hypar 5x5: %zu convex feature-curve, %zu concave, "
                  "%zu saddle\n",
                  totals.class_count[CLASS_CONVEX_FEATURE_CURVE],
                  totals.class_count[CLASS_CONCAVE_FEATURE_CURVE],
                  totals.class_count[CLASS_SADDLE]);
    assert_int_equal(k_negative, 25);
    /* z = xy/20 is symmetric under (x, y) -> (-x, y) with z -> -z, which
     * swaps the sides of H: as many convex as concave. */
    assert_int_equal(totals.class_count[CLASS_CONVEX_FEATURE_CURVE],
                     totals.class_count[CLASS_CONCAVE_FEATURE_CURVE]);
    panelization_free(&panels);
    surface_close(&surface);
    unlink(path);
    free(path);
}

/* classify_broken_limits names the limits an option breaks, and its
 * terms are classify_violation's: hand-worked totals, each limit alone,
 * several at once, one not measured (none over), and a feasible one. */
static void test_broken_limits(void **state)
{
    (void)state;
    struct option_totals t;
    memset(&t, 0, sizeof t);
    double term[LIMIT_COUNT];
    t.max_panel_area = 3.0;
    assert_int_equal(classify_broken_limits(&t, 4, term), 0);
    assert_true(classify_violation(&t, 4) == 0);

    t.max_panel_area = 5.5;  /* 1.5 m^2 over a 4 m^2 limit */
    assert_int_equal(classify_broken_limits(&t, 4, term),
                     1u << LIMIT_PANEL_AREA);
    assert_true(fabs(term[LIMIT_PANEL_AREA] - 1.5) < 1e-12);
    assert_true(classify_violation(&t, 4) == term[LIMIT_PANEL_AREA]);

    t.max_panel_area = 3.0;
    t.gaps_over = 3;
    t.kinks_over = 1;
    t.slivers = TOTALS_UNKNOWN;  /* not measured: none over */
    assert_int_equal(classify_broken_limits(&t, 4, term),
                     1u << LIMIT_GAP | 1u << LIMIT_KINK);
    assert_true(term[LIMIT_GAP] == 3 && term[LIMIT_KINK] == 1 &&
                term[LIMIT_PANEL_WIDTH] == 0);
    assert_true(classify_violation(&t, 4) == 4);

    t.max_panel_area = 6.0;
    t.slivers = 2;
    t.gaps_over = TOTALS_UNKNOWN;
    assert_int_equal(classify_broken_limits(&t, 4, term),
                     1u << LIMIT_PANEL_AREA | 1u << LIMIT_PANEL_WIDTH |
                         1u << LIMIT_KINK);
    assert_true(classify_violation(&t, 4) == 2.0 + 0 + 1 + 2);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_ruled_never_flat),
        cmocka_unit_test(test_fp_within_threshold),
        cmocka_unit_test(test_limits_to_rounding),
        cmocka_unit_test(test_threshold_zero),
        cmocka_unit_test(test_paper_hypar),
        cmocka_unit_test(test_broken_limits),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
