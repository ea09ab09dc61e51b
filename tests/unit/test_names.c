/*
 * test_names.c: every enum that is written as text (in the store, in a
 * report, in a setting the user types) reads back as itself through its
 * name/parse pair, and an unknown name is refused, with the field named
 * as the caller named it.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <string.h>

#include "core/panel/panel.h"
#include "core/search/optimize.h"
#include "core/surface/mesh.h"
#include "core/surface/param.h"
#include "store/store.h"
#include "study/study.h"

static void test_run_status(void **state)
{
    (void)state;
    const enum run_status all[] = {RUN_RUNNING, RUN_DONE, RUN_INTERRUPTED,
                                   RUN_FAILED};
    /* the names runs.status CHECKs (schema.c), written out here */
    const char *const sql[] = {"running", "done", "interrupted", "failed"};
    for (int k = 0; k < 4; k++) {
        enum run_status back = RUN_FAILED;
        assert_string_equal(run_status_name(all[k]), sql[k]);
        assert_int_equal(run_status_parse(sql[k], &back), 0);
        assert_int_equal(back, all[k]);
    }
    enum run_status back = RUN_DONE;
    assert_int_equal(run_status_parse("Done", &back), -1);
    assert_int_equal(run_status_parse("", &back), -1);
    assert_int_equal(back, RUN_DONE);
}

static void test_panel_mode(void **state)
{
    (void)state;
    const enum panel_curvature_mode all[] = {PANEL_EXTREMES, PANEL_MEAN};
    const char *const text[] = {"extremes", "mean"};
    struct facet_error err;
    for (int k = 0; k < 2; k++) {
        enum panel_curvature_mode back = all[1 - k];
        assert_string_equal(panel_mode_name(all[k]), text[k]);
        assert_int_equal(panel_mode_parse(text[k], "Per panel", &back, &err),
                         FACET_OK);
        assert_int_equal(back, all[k]);
    }
    enum panel_curvature_mode back;
    assert_int_equal(panel_mode_parse("median", "Per panel", &back, &err),
                     FACET_EINPUT);
    assert_string_equal(err.message,
                        "Per panel: 'median' is not extremes or mean");
}

static void test_optimize_method(void **state)
{
    (void)state;
    const enum optimize_method all[] = {METHOD_EXHAUSTIVE, METHOD_RANDOM,
                                        METHOD_NSGA2};
    const char *const text[] = {"exhaustive", "random", "nsga2"};
    struct facet_error err;
    for (int k = 0; k < 3; k++) {
        enum optimize_method back = all[(k + 1) % 3];
        assert_string_equal(optimize_method_name(all[k]), text[k]);
        assert_int_equal(optimize_method_parse(text[k], "Method", &back,
                                               &err), FACET_OK);
        assert_int_equal(back, all[k]);
    }
    enum optimize_method back;
    assert_int_equal(optimize_method_parse("nsga3", "Method", &back, &err),
                     FACET_EINPUT);
    assert_string_equal(err.message, "Method: 'nsga3' unknown (choose "
                        "exhaustive, random or nsga2)");
}

static void test_keep_panels(void **state)
{
    (void)state;
    /* the names runs.store_panels CHECKs (schema.c), in the enum's order */
    const char *const text[] = {"front", "knee", "none"};
    struct facet_error err;
    enum study_keep_panels keep = KEEP_FRONT;
    for (int k = 0; k < 3; k++) {
        assert_int_equal(study_keep_panels_parse(text[k], "Keep", &keep,
                                                 &err), FACET_OK);
        assert_string_equal(study_keep_panels_name(keep), text[k]);
    }
    assert_int_equal(keep, KEEP_NONE);
    assert_int_equal(study_keep_panels_parse("knee", "Keep", &keep, &err),
                     FACET_OK);
    assert_int_equal(keep, KEEP_KNEE);
    assert_int_equal(study_keep_panels_parse("all", "Keep", &keep, &err),
                     FACET_EINPUT);
    assert_string_equal(err.message, "Keep: 'all' is not front, knee or none");
}

static void test_units_and_uv(void **state)
{
    (void)state;
    const enum mesh_units units[] = {UNITS_M, UNITS_CM, UNITS_MM, UNITS_IN,
                                     UNITS_FT};
    const char *const text[] = {"m", "cm", "mm", "in", "ft"};
    struct facet_error err;
    for (int k = 0; k < 5; k++) {
        enum mesh_units back = units[(k + 1) % 5];
        assert_string_equal(mesh_units_name(units[k]), text[k]);
        assert_int_equal(mesh_units_parse(text[k], "Units", &back, &err),
                         FACET_OK);
        assert_int_equal(back, units[k]);
    }
    enum mesh_units u;
    assert_int_equal(mesh_units_parse("yd", "Units", &u, &err), FACET_EINPUT);
    assert_non_null(strstr(err.message, "Units: units 'yd' unknown"));
    const enum param_method uv[] = {PARAM_AUTO, PARAM_VT, PARAM_GRID,
                                    PARAM_PLANE, PARAM_HARMONIC};
    const char *const uv_text[] = {"auto", "vt", "grid", "plane",
                                   "harmonic"};
    for (int k = 0; k < 5; k++) {
        enum param_method back = uv[(k + 1) % 5];
        assert_string_equal(param_method_name(uv[k]), uv_text[k]);
        assert_int_equal(param_method_parse(uv_text[k], &back), 0);
        assert_int_equal(back, uv[k]);
    }
    enum param_method m;
    assert_int_equal(param_method_parse("conformal", &m), -1);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_run_status),
        cmocka_unit_test(test_panel_mode),
        cmocka_unit_test(test_optimize_method),
        cmocka_unit_test(test_keep_panels),
        cmocka_unit_test(test_units_and_uv),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
