/*
 * test_study_policy.c: the one run policy that `facet optimize` and the
 * TUI's New run take (study.h): the defaults of a new run are the paper's
 * (Table 2's design space: u 20..40, v 35..50 panels, t = 3 mm; 336
 * points, searched exhaustively), and "auto" picks exhaustive up to
 * STUDY_EXHAUSTIVE_LIMIT points with a stepped threshold, NSGA-II
 * otherwise.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <string.h>

#include "study/study.h"

static void test_defaults_are_the_papers(void **state)
{
    (void)state;
    struct study_request r;
    memset(&r, 0xff, sizeof r);  /* every field must be set */
    study_request_defaults(&r);
    const struct optimize_settings *s = &r.settings;
    assert_int_equal(s->space.u_min, 20);
    assert_int_equal(s->space.u_max, 40);
    assert_int_equal(s->space.v_min, 35);
    assert_int_equal(s->space.v_max, 50);
    assert_true(s->space.t_min_mm == 3 && s->space.t_max_mm == 3 &&
                s->space.t_step_mm == 0);
    assert_int_equal(design_space_size(&s->space), 21 * 16);
    assert_int_equal(s->method, METHOD_EXHAUSTIVE);
    assert_true(s->base.classify.threshold == 0.003);
    assert_true(s->base.classify.price[TYPE_FP] == 701 &&
                s->base.classify.price[TYPE_SP] == 766 &&
                s->base.classify.price[TYPE_DP] == 1518);
    assert_int_equal(s->base.mode, PANEL_EXTREMES);
    assert_int_equal(s->nobjectives, 3);
    assert_string_equal(s->objectives[0].quantity->name, "cost");
    assert_string_equal(s->objectives[1].quantity->name, "planarity");
    assert_string_equal(s->objectives[2].quantity->name, "dp_area");
    assert_true(s->seed == 1);
    assert_int_equal(s->evaluations, 1000);
    assert_int_equal(s->population, 100);
    assert_int_equal(s->generations, 50);
    assert_true(s->jobs >= 1);
    assert_int_equal(r.mesh.units, UNITS_M);
    assert_null(r.mesh.object);
    assert_null(r.mesh.group);
    assert_int_equal(r.uv, PARAM_AUTO);
    assert_int_equal(r.store_panels, KEEP_FRONT);
    assert_null(r.surface_path);
    assert_string_equal(r.name, "");
    struct facet_error err;
    r.surface_path = "roof.obj";
    assert_int_equal(study_request_check(&r, &err), FACET_OK);
}

static void test_auto_method(void **state)
{
    (void)state;
    struct facet_error err;
    enum optimize_method m = METHOD_RANDOM;
    /* 1 x 1 x 100,000 steps: at the limit, exhaustive */
    struct design_space at = {1, 1, 1, 1, 0, 99999, 1};
    assert_int_equal(design_space_size(&at), STUDY_EXHAUSTIVE_LIMIT);
    assert_int_equal(study_method_parse("auto", "Method", &at, &m, &err),
                     FACET_OK);
    assert_int_equal(m, METHOD_EXHAUSTIVE);
    struct design_space past = {1, 1, 1, 1, 0, 100000, 1};
    assert_int_equal(study_method_parse("auto", "Method", &past, &m, &err),
                     FACET_OK);
    assert_int_equal(m, METHOD_NSGA2);
    struct design_space continuous = {20, 40, 35, 50, 1, 5, 0};
    assert_int_equal(study_method_parse("auto", "Method", &continuous, &m,
                                        &err), FACET_OK);
    assert_int_equal(m, METHOD_NSGA2);
    assert_int_equal(study_method_parse("random", "Method", &at, &m, &err),
                     FACET_OK);
    assert_int_equal(m, METHOD_RANDOM);
    assert_int_equal(study_method_parse("best", "Method", &at, &m, &err),
                     FACET_EINPUT);
    assert_string_equal(err.message, "Method: 'best' unknown (choose auto, "
                        "exhaustive, random or nsga2)");
    /* exhaustive over a continuous range is refused, naming the field */
    assert_int_equal(optimize_method_check(METHOD_EXHAUSTIVE, &continuous,
                                           NULL, &err), FACET_EINPUT);
    assert_non_null(strstr(err.message, "threshold 1:5: the exhaustive "
                                        "method needs a step"));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_defaults_are_the_papers),
        cmocka_unit_test(test_auto_method),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
