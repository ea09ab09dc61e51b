/*
 * test_classify.c: Table 1, the zero tolerance, the threshold rule and the
 * totals, each against numbers worked out by hand.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/classify/classify.h"
#include "core/evaluate/option.h"
#include "core/base/sym3.h"

static void test_table_one(void **state)
{
    (void)state;
    double eps = 1e-3;
    /* K < 0: split by the sign of H. */
    assert_int_equal(classify_curvature(0.01, -0.05, eps),
                     CLASS_CONVEX_FEATURE_CURVE);
    assert_int_equal(classify_curvature(0.05, -0.01, eps),
                     CLASS_CONCAVE_FEATURE_CURVE);
    assert_int_equal(classify_curvature(0.02, -0.0205, eps), CLASS_SADDLE);
    /* K = 0. */
    assert_int_equal(classify_curvature(0, -0.1, eps), CLASS_RULED_CONVEX);
    assert_int_equal(classify_curvature(0.1, 0, eps), CLASS_RULED_CONCAVE);
    assert_int_equal(classify_curvature(0, 0, eps), CLASS_FLAT);
    /* K > 0: a dome from outside is convex (k1, k2 < 0). */
    assert_int_equal(classify_curvature(-0.05, -0.05, eps),
                     CLASS_CONVEX_ROUND);
    assert_int_equal(classify_curvature(0.05, 0.04, eps),
                     CLASS_CONCAVE_ROUND);
}

static void test_zero_tolerance(void **state)
{
    (void)state;
    /* Below eps a curvature is zero: a barely curved cylinder is flat. */
    assert_int_equal(classify_curvature(0.0009, -0.0009, 1e-3), CLASS_FLAT);
    assert_int_equal(classify_curvature(1e-4, -0.05, 1e-3),
                     CLASS_RULED_CONVEX);
    assert_int_equal(classify_curvature(-1e-4, -0.05, 1e-3),
                     CLASS_RULED_CONVEX);
    /* eps itself, and eps to rounding, count as zero (|k| <= eps (1 +
     * 1e-9)); a millionth beyond it does not. */
    assert_int_equal(classify_curvature(1e-3, 1e-3, 1e-3), CLASS_FLAT);
    assert_int_equal(classify_curvature(1e-3 * (1 + 1e-12), 0, 1e-3),
                     CLASS_FLAT);
    assert_int_equal(classify_curvature(1e-3 * (1 + 1e-6), 1e-3 * (1 + 1e-6),
                                        1e-3),
                     CLASS_CONCAVE_ROUND);
    /* A ruled panel stays ruled when |H| < eps: k1 = 1.5 eps, k2 = 0. */
    assert_int_equal(classify_curvature(1.5e-3, 0, 1e-3),
                     CLASS_RULED_CONCAVE);
    assert_int_equal(classify_curvature(0, -1.5e-3, 1e-3),
                     CLASS_RULED_CONVEX);

    struct classify_options options;
    classify_defaults(&options);
    struct panel panel;
    memset(&panel, 0, sizeof panel);
    panel.diameter = 2;
    /* 8 t / d^2 with t = 3 mm, d = 2 m. */
    assert_true(fabs(classify_tolerance(&options, &panel) - 0.006) < 1e-15);
    options.curvature_tol = 0.5;
    assert_true(classify_tolerance(&options, &panel) == 0.5);
}

static void test_types(void **state)
{
    (void)state;
    assert_int_equal(panel_type_of_class(CLASS_FLAT), TYPE_FP);
    assert_int_equal(panel_type_of_class(CLASS_RULED_CONVEX), TYPE_SP);
    assert_int_equal(panel_type_of_class(CLASS_RULED_CONCAVE), TYPE_SP);
    for (int c = 0; c < CLASS_COUNT; c++)
        if (c != CLASS_FLAT && c != CLASS_RULED_CONVEX &&
            c != CLASS_RULED_CONCAVE)
            assert_int_equal(panel_type_of_class((enum panel_class)c),
                             TYPE_DP);
    assert_string_equal(panel_class_name(CLASS_CONVEX_FEATURE_CURVE),
                        "convex_feature_curve");
    assert_string_equal(panel_class_name(CLASS_CONCAVE_ROUND),
                        "concave_round");
    assert_string_equal(panel_type_name(TYPE_SP), "SP");
}

/* Three panels: a flat one, a ruled one 5 mm off its plane, a dome piece
 * 2 mm off its plane (which the threshold rule makes flat). */
static void test_threshold_cost_and_totals(void **state)
{
    (void)state;
    struct panel panels[4];
    memset(panels, 0, sizeof panels);
    double area[4] = {1.5, 2.0, 1.0, 3.0};
    double k1[4] = {0, 0, -0.2, -0.2};
    double k2[4] = {0, -0.2, -0.2, -0.3};
    double deviation[4] = {0.0001, 0.005, 0.002, 0.010};
    for (int n = 0; n < 4; n++) {
        panels[n].area = area[n];
        panels[n].k1 = k1[n];
        panels[n].k2 = k2[n];
        panels[n].deviation = deviation[n];
        panels[n].diameter = 1.5;
    }
    struct panelization p;
    memset(&p, 0, sizeof p);
    p.panels = panels;
    p.npanels = 4;
    struct classify_options options;
    classify_defaults(&options);
    struct option_totals t;
    classify_panels(&p, &options, &t);

    assert_int_equal(panels[0].type, TYPE_FP);
    assert_int_equal(panels[1].type, TYPE_SP);
    assert_int_equal(panels[1].class, CLASS_RULED_CONVEX);
    assert_int_equal(panels[2].class, CLASS_CONVEX_ROUND);
    assert_int_equal(panels[2].type, TYPE_FP);  /* within 3 mm */
    assert_int_equal(panels[3].type, TYPE_DP);
    assert_true(fabs(panels[3].K - 0.06) < 1e-15);
    assert_true(fabs(panels[3].H + 0.25) < 1e-15);

    assert_int_equal(t.panels, 4);
    assert_int_equal(t.count[TYPE_FP], 2);
    assert_int_equal(t.count[TYPE_SP], 1);
    assert_int_equal(t.count[TYPE_DP], 1);
    assert_true(fabs(t.area_of[TYPE_FP] - 2.5) < 1e-12);
    assert_true(fabs(t.area - 7.5) < 1e-12);
    /* 2.5 x 701 + 2 x 766 + 3 x 1518 */
    assert_true(fabs(t.cost - 7838.5) < 1e-9);
    assert_true(fabs(t.cost_of[TYPE_DP] - 4554) < 1e-9);
    /* DP panels deviate by 0: 0.1 + 5 + 2 mm. */
    assert_true(fabs(t.planarity - 0.0071) < 1e-12);
    assert_true(fabs(t.max_deviation - 0.005) < 1e-15);
    assert_true(t.max_panel_area == 3.0);
    assert_true(t.feasible);

    options.sp_as_fp = 1;
    options.max_panel_area = 1.92;
    classify_panels(&p, &options, &t);
    assert_true(fabs(t.cost - (4.5 * 701 + 3 * 1518)) < 1e-9);
    assert_int_equal(t.count[TYPE_SP], 1);
    assert_false(t.feasible);
}

/* The totals do not depend on the panels' order: 500 panels of random
 * areas, deviations and curvatures, in 20 random orders, give totals equal
 * to the bit (a plain running sum differs in the last bits for most
 * orders), and each total is within 1e-15 of the exact sum, taken as a
 * long double sum of the values sorted by size. */
/* A panel flat only because neither curvature's sign is known (its
 * ranges hold 0) but that leaves its plane by more than t is not FP: an
 * FP panel is within t, or flat by its curvatures themselves. (Found by
 * export_cover.sh on compas_quadmesh at t = 0: a trimmed panel typed FP
 * exported 4 % less area than its schedule, its projection on a plane it
 * does not lie in.) The same panel within t is FP. */
static void test_flat_by_noise_is_not_fp(void **state)
{
    (void)state;
    struct panel panels[2];
    memset(panels, 0, sizeof panels);
    for (int n = 0; n < 2; n++) {
        panels[n].area = 1;
        panels[n].diameter = 1.5;
        panels[n].k1 = 0.04;
        panels[n].k2 = -0.03;
        panels[n].k1_error[0] = panels[n].k1_error[1] = 0.1;
        panels[n].k2_error[0] = panels[n].k2_error[1] = 0.1;
    }
    panels[0].deviation = 0.004;   /* beyond t = 3 mm */
    panels[1].deviation = 0.002;   /* within it */
    struct panelization p;
    memset(&p, 0, sizeof p);
    p.panels = panels;
    p.npanels = 2;
    struct classify_options options;
    classify_defaults(&options);
    struct option_totals t;
    classify_panels(&p, &options, &t);
    /* eps = 8 t / d^2 = 0.0107: both estimates clear it, K < 0, and
     * they cancel to H = 0.005 within eps: a saddle */
    assert_int_not_equal(panels[0].type, TYPE_FP);
    assert_int_not_equal(panels[0].class, CLASS_FLAT);
    assert_int_equal(panels[0].class, CLASS_SADDLE);
    assert_int_equal(panels[1].type, TYPE_FP);
    assert_int_equal(classify_fp_over_threshold(&p, &options, NULL), 0);
}

static void test_totals_independent_of_order(void **state)
{
    (void)state;
    enum { N = 500 };
    struct panel *panels = calloc(N, sizeof *panels);
    assert_non_null(panels);
    unsigned seed = 12345;
    for (int n = 0; n < N; n++) {
        seed = seed * 1103515245u + 12345u;
        panels[n].area = 0.1 + (seed >> 8) / 16777216.0 * 3;
        seed = seed * 1103515245u + 12345u;
        panels[n].deviation = (seed >> 8) / 16777216.0 * 0.01;
        panels[n].p_dist = panels[n].area * panels[n].deviation *
                           panels[n].deviation / 3;
        seed = seed * 1103515245u + 12345u;
        panels[n].k1 = ((seed >> 8) / 16777216.0 - 0.5) * 0.2;
        panels[n].k2 = panels[n].k1 - 0.01;
        panels[n].diameter = 2;
        panels[n].i = n;
    }
    struct classify_options options;
    classify_defaults(&options);
    struct panelization p = {0};
    p.npanels = N;
    p.panels = panels;
    struct option_totals first, again;
    classify_panels(&p, &options, &first);
    size_t plain_differs = 0;
    double plain_first = 0;
    for (int order = 0; order < 20; order++) {
        for (int n = N - 1; n > 0; n--) {
            seed = seed * 1103515245u + 12345u;
            int k = (int)((seed >> 8) % (unsigned)(n + 1));
            struct panel swap = panels[n];
            panels[n] = panels[k];
            panels[k] = swap;
        }
        classify_panels(&p, &options, &again);
        assert_memory_equal(&first, &again, sizeof first);
        double plain = 0;
        for (int n = 0; n < N; n++)
            plain += panels[n].area;
        if (order == 0)
            plain_first = plain;
        else if (plain != plain_first)
            plain_differs++;
    }
    print_message("a plain sum of the areas differed in %zu of 19 orders\n",
                  plain_differs);
    /* The exact sum, against a careful one. */
    double *area = malloc(N * sizeof *area);
    assert_non_null(area);
    for (int n = 0; n < N; n++)
        area[n] = panels[n].area;
    for (int a = 1; a < N; a++)  /* insertion sort, smallest first */
        for (int b = a; b > 0 && area[b] < area[b - 1]; b--) {
            double swap = area[b];
            area[b] = area[b - 1];
            area[b - 1] = swap;
        }
    long double careful = 0;
    for (int n = 0; n < N; n++)
        careful += area[n];
    assert_true(fabsl((long double)first.area - careful) <=
                1e-15L * careful);
    free(area);
    free(panels);
}

/* classify_defaults sets every field, whatever the memory held: before,
 * the panel, joint and mould prices and the width limit were left as
 * they were (stack garbage refused as a width limit, or priced). */
static void test_defaults_set_every_field(void **state)
{
    (void)state;
    struct classify_options options;
    memset(&options, 0xff, sizeof options);  /* NaN in every double */
    classify_defaults(&options);
    assert_true(options.panel_cost == 0 && options.joint_cost == 0);
    for (int t = 0; t < TYPE_COUNT; t++)
        assert_true(options.mould_cost[t] == 0);
    assert_true(options.min_panel_width == 0);
    assert_true(options.max_gap == 0 && options.max_kink == 0);
    struct facet_error err;
    assert_int_equal(classify_check_options(&options, &err), FACET_OK);
}

static void test_bad_options(void **state)
{
    (void)state;
    struct classify_options options;
    struct facet_error err;
    classify_defaults(&options);
    assert_int_equal(classify_check_options(&options, &err), FACET_OK);
    options.threshold = NAN;
    assert_int_equal(classify_check_options(&options, &err), FACET_EINPUT);
    classify_defaults(&options);
    options.price[TYPE_DP] = -1;
    assert_int_equal(classify_check_options(&options, &err), FACET_EINPUT);
    assert_non_null(strstr(err.message, "DP"));
}

static void test_sym3(void **state)
{
    (void)state;
    double a[9] = {4, 1, 2, 1, 3, 0.5, 2, 0.5, 6};
    double value[3], vector[3][3];
    sym3_eigen(a, value, vector);
    assert_true(value[0] <= value[1] && value[1] <= value[2]);
    assert_true(fabs(value[0] + value[1] + value[2] - 13) < 1e-12);
    for (int k = 0; k < 3; k++)
        for (int r = 0; r < 3; r++) {
            double av = a[3 * r] * vector[k][0] + a[3 * r + 1] * vector[k][1] +
                        a[3 * r + 2] * vector[k][2];
            assert_true(fabs(av - value[k] * vector[k][r]) < 1e-12);
        }
    double diagonal[9] = {2, 0, 0, 0, -1, 0, 0, 0, 0};
    sym3_eigen(diagonal, value, vector);
    assert_true(value[0] == -1 && value[1] == 0 && value[2] == 2);
}

/* A design point's threshold is written in mm and classified in m: a
 * panel 2.5 mm off its plane is within a 3 mm threshold and outside a
 * 2 mm one, and a 3 mm sag over a 2 m diagonal is the curvature
 * k = 8 s / d^2 = 0.006 1/m (the sagitta of a circular arc) that the
 * default tolerance takes. */
static void test_design_point_threshold_in_metres(void **state)
{
    (void)state;
    struct option_params base;
    option_params_defaults(&base);
    base.classify.price[TYPE_DP] = 1234;
    struct option_params p = option_params_at(&base, 12, 34, 3);
    assert_int_equal(p.nu, 12);
    assert_int_equal(p.nv, 34);
    assert_true(p.classify.price[TYPE_DP] == 1234);  /* the rest kept */
    assert_true(fabs(p.classify.threshold - 0.003) < 1e-15);
    struct panel panel;
    memset(&panel, 0, sizeof panel);
    panel.diameter = 2;
    panel.deviation = 0.0025;
    assert_true(classify_within_threshold(&p.classify, &panel));
    struct option_params tight = option_params_at(&base, 12, 34, 2);
    assert_false(classify_within_threshold(&tight.classify, &panel));
    assert_true(fabs(classify_tolerance(&p.classify, &panel) - 0.006) <
                1e-12);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_table_one),
        cmocka_unit_test(test_design_point_threshold_in_metres),
        cmocka_unit_test(test_zero_tolerance),
        cmocka_unit_test(test_types),
        cmocka_unit_test(test_threshold_cost_and_totals),
        cmocka_unit_test(test_totals_independent_of_order),
        cmocka_unit_test(test_flat_by_noise_is_not_fp),
        cmocka_unit_test(test_defaults_set_every_field),
        cmocka_unit_test(test_bad_options),
        cmocka_unit_test(test_sym3),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
