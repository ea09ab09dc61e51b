/*
 * test_store_project.c: what a project run adds to the store (schema v8):
 * its surfaces, each option's rows per surface, the module columns, and a
 * file of schema 7 migrated to them. The truth is SQLite's own reading of
 * the file (sqlite3 queries here), not the store's.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <sqlite3.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "store/store.h"
#include "tests/support/store_fixture.h"

static char path[64];

static void sql(const char *statements)
{
    sqlite3 *db;
    assert_int_equal(sqlite3_open(path, &db), SQLITE_OK);
    char *message = NULL;
    if (sqlite3_exec(db, statements, NULL, NULL, &message) != SQLITE_OK)
        fail_msg("%s", message);
    sqlite3_close(db);
}

static double sql_number(const char *query)
{
    sqlite3 *db;
    sqlite3_stmt *s;
    assert_int_equal(sqlite3_open(path, &db), SQLITE_OK);
    assert_int_equal(sqlite3_prepare_v2(db, query, -1, &s, NULL), SQLITE_OK);
    assert_int_equal(sqlite3_step(s), SQLITE_ROW);
    double value = sqlite3_column_type(s, 0) == SQLITE_NULL
                       ? NAN : sqlite3_column_double(s, 0);
    sqlite3_finalize(s);
    sqlite3_close(db);
    return value;
}

static struct store *fresh(const char *name)
{
    snprintf(path, sizeof path, "/tmp/facet_test_%s_%d.db", name,
             (int)getpid());
    store_fixture_remove(path);
    struct facet_error err;
    struct store *store;
    assert_int_equal(store_open(path, &store, &err), FACET_OK);
    return store;
}

/* A project run of 1.0:2.0:0.5 x 1.2 m modules. */
static int64_t project_run(struct store *store)
{
    struct run_info run;
    store_fixture_run(&run);
    run.u_min = 1;
    run.u_max = 3;
    run.module_w_min = 1.0;
    run.module_w_max = 2.0;
    run.module_w_step = 0.5;
    run.module_h_min = run.module_h_max = 1.2;
    run.module_h_step = 0.1;
    struct facet_error err;
    assert_int_equal(store_run_create(store, &run, &err), FACET_OK);
    return run.id;
}

/* Option k of two surfaces: every figure distinct, per surface i. */
static void option_of(int k, struct option_row *row,
                      struct option_surface_row surface[2])
{
    memset(row, 0, sizeof *row);
    row->number = k;
    row->nu = k;
    row->nv = 1;
    row->threshold_mm = 3;
    row->module_w = 0.5 + 0.5 * k;
    row->module_h = 1.2;
    row->modules = (size_t)k;
    for (int i = 0; i < 2; i++) {
        struct option_surface_row *s = &surface[i];
        memset(s, 0, sizeof *s);
        s->nu = 10 * k + i;
        s->nv = 7 + i;
        s->totals.panels = (size_t)(s->nu * s->nv);
        s->totals.count[TYPE_DP] = s->totals.panels;
        s->totals.area = s->totals.area_of[TYPE_DP] = 50.25 + i;
        s->totals.cost = 1000.5 * (i + 1) + k;
        s->totals.max_deviation = 0.002 * (i + 1);
        s->totals.moulds = (size_t)(3 + i);
        s->totals.max_gap = NAN;  /* not measured: NULL */
        s->totals.max_kink = 0.5 * i;  /* rad, stored in degrees */
        s->totals.feasible = i;
        /* schema v10's, kept per surface; none on the second surface */
        s->totals.sp_min_radius = i ? NAN : 2.5 + k;
        /* schema v12's: widths not measured on the second surface */
        s->totals.min_panel_area = 0.25 + i + k;
        s->totals.min_panel_width = i ? NAN : 0.375 + k;
        s->totals.slivers = i ? TOTALS_UNKNOWN : (size_t)(2 + k);
        s->moulds_used = 5 + i;
        s->joints = 40 + i;
        row->totals.panels += s->totals.panels;
        row->totals.cost += s->totals.cost;
    }
}

/* Surfaces and rows per surface go in and come back as they were, the
 * module columns hold the option's module, and SQLite sees them. */
static void test_project_rows_round_trip(void **state)
{
    (void)state;
    struct store *store = fresh("project_rows");
    struct facet_error err;
    int64_t run = project_run(store);
    struct surface_row surfaces[2];
    memset(surfaces, 0, sizeof surfaces);
    for (int i = 0; i < 2; i++) {
        snprintf(surfaces[i].name, sizeof surfaces[i].name, "face_%d", i);
        snprintf(surfaces[i].file, sizeof surfaces[i].file, "/p/skin.obj");
        memset(surfaces[i].file_sha256, 'a' + i, 64);
        surfaces[i].triangles = 100 + i;
        surfaces[i].area = 12.5 + i;
        surfaces[i].u_length = 3.25 + i;
        surfaces[i].v_length = 4.5 + i;
        surfaces[i].uv_method = PARAM_VT;
    }
    surfaces[1].grid_nu = 5;
    surfaces[1].grid_nv = 4;
    assert_int_equal(store_surfaces_put(store, run, surfaces, 2, &err),
                     FACET_OK);
    struct option_row rows[3];
    struct option_surface_row per[3][2];
    for (int k = 0; k < 3; k++)
        option_of(k + 1, &rows[k], per[k]);
    assert_int_equal(store_project_options_put(store, run, rows, 3, &per[0][0],
                                               2, &err), FACET_OK);

    struct surface_row *back;
    size_t n;
    assert_int_equal(store_surfaces_get(store, run, &back, &n, &err),
                     FACET_OK);
    assert_int_equal(n, 2);
    for (int i = 0; i < 2; i++) {
        assert_string_equal(back[i].name, surfaces[i].name);
        assert_string_equal(back[i].file_sha256, surfaces[i].file_sha256);
        assert_true(back[i].u_length == surfaces[i].u_length);
        assert_int_equal(back[i].uv_method, PARAM_VT);
        assert_int_equal(back[i].grid_nu, surfaces[i].grid_nu);
    }
    free(back);
    struct option_surface_row *got;
    assert_int_equal(store_option_surfaces_get(store, run, 2, &got, &n, &err),
                     FACET_OK);
    assert_int_equal(n, 2);
    for (int i = 0; i < 2; i++) {
        assert_int_equal(got[i].nu, per[1][i].nu);
        assert_int_equal(got[i].totals.panels, per[1][i].totals.panels);
        assert_true(got[i].totals.cost == per[1][i].totals.cost);
        assert_true(got[i].totals.max_deviation ==
                    per[1][i].totals.max_deviation);
        assert_int_equal(got[i].moulds_used, per[1][i].moulds_used);
        assert_int_equal(got[i].joints, per[1][i].joints);
        assert_true(isnan(got[i].totals.max_gap));
        assert_int_equal(got[i].totals.feasible, i);
        assert_true(i ? isnan(got[i].totals.sp_min_radius)
                      : got[i].totals.sp_min_radius == 4.5);
        assert_true(got[i].totals.min_panel_area == 2.25 + i);
        assert_true(i ? isnan(got[i].totals.min_panel_width)
                      : got[i].totals.min_panel_width == 2.375);
        assert_true(got[i].totals.slivers ==
                    (i ? TOTALS_UNKNOWN : (size_t)4));
    }
    free(got);
    struct option_row row;
    assert_int_equal(store_option_get(store, run, 3, &row, &err), FACET_OK);
    assert_true(row.module_w == 2.0 && row.module_h == 1.2);
    assert_int_equal(row.modules, 3);
    struct run_info info;
    assert_int_equal(store_run_get(store, run, &info, &err), FACET_OK);
    assert_true(store_run_is_project(&info));
    assert_true(info.module_w_step == 0.5 && info.module_h_min == 1.2);

    /* An option stored again keeps its rows (INSERT OR IGNORE), with no
     * second set. */
    per[0][0].nu = 999;
    assert_int_equal(store_project_options_put(store, run, rows, 1, &per[0][0],
                                               2, &err), FACET_OK);
    store_close(store);
    assert_true(sql_number("SELECT count(*) FROM option_surfaces") == 6);
    assert_true(sql_number("SELECT max(nu) FROM option_surfaces") == 31);
    assert_true(sql_number("SELECT count(*) FROM option_surfaces"
                           " WHERE max_gap IS NULL") == 6);
    assert_true(sql_number("SELECT sp_min_radius FROM option_surfaces"
                           " WHERE option = 2 AND surface = 0") == 4.5);
    assert_true(sql_number("SELECT count(*) FROM option_surfaces"
                           " WHERE sp_min_radius IS NULL") == 3);
    assert_true(sql_number("SELECT min_panel_width FROM option_surfaces"
                           " WHERE option = 2 AND surface = 0") == 2.375);
    assert_true(sql_number("SELECT slivers FROM option_surfaces"
                           " WHERE option = 2 AND surface = 0") == 4);
    assert_true(sql_number("SELECT count(*) FROM option_surfaces"
                           " WHERE min_panel_width IS NULL AND slivers IS NULL"
                           " AND min_panel_area IS NOT NULL") == 3);
    assert_true(sql_number("SELECT sum(panels) FROM option_surfaces"
                           " WHERE option = 2") ==
                sql_number("SELECT panels FROM options WHERE number = 2"));
    assert_true(sql_number("SELECT module_w FROM options WHERE number = 1")
                == 1.0);
    assert_true(sql_number("SELECT grid_nu IS NULL FROM surfaces"
                           " WHERE surface = 0") == 1);
    /* Deleting the run takes its surfaces and rows with it. */
    sql("PRAGMA foreign_keys = ON; DELETE FROM runs;");
    assert_true(sql_number("SELECT (SELECT count(*) FROM option_surfaces) +"
                           " (SELECT count(*) FROM surfaces)") == 0);
    store_fixture_remove(path);
}

/* A single surface's options have no module, whatever their rows hold
 * (a row made by memset holds 0, not NULL). */
static void test_single_surface_options_have_no_module(void **state)
{
    (void)state;
    struct store *store = fresh("project_single");
    struct facet_error err;
    struct run_info run;
    store_fixture_run(&run);
    assert_int_equal(store_run_create(store, &run, &err), FACET_OK);
    struct option_row row;
    memset(&row, 0, sizeof row);
    row.number = 1;
    row.nu = row.nv = 1;
    assert_int_equal(store_options_put(store, run.id, &row, 1, &err),
                     FACET_OK);
    assert_int_equal(store_run_get(store, run.id, &run, &err), FACET_OK);
    assert_false(store_run_is_project(&run));
    store_close(store);
    assert_true(sql_number("SELECT count(module_w) + count(module_h) +"
                           " count(modules) FROM options") == 0);
    assert_true(sql_number("SELECT count(module_w_min) + count(module_h_step)"
                           " FROM runs") == 0);
    store_fixture_remove(path);
}

/* A file of schema 7 (as the Facet before projects left it) is migrated
 * to 8 when opened: its run and options as they were, the new tables
 * there and empty, the new columns NULL; a project run can then be
 * stored in it. */
static void test_migrates_v7(void **state)
{
    (void)state;
    struct store *store = fresh("project_v7");
    struct facet_error err;
    struct run_info run;
    store_fixture_run(&run);
    assert_int_equal(store_run_create(store, &run, &err), FACET_OK);
    struct option_row rows[4];
    memset(rows, 0, sizeof rows);
    for (int k = 0; k < 4; k++) {
        rows[k].number = k + 1;
        rows[k].nu = rows[k].nv = 1;
        rows[k].threshold_mm = k;
        rows[k].totals.cost = 100 + k;
    }
    assert_int_equal(store_options_put(store, run.id, rows, 4, &err),
                     FACET_OK);
    store_close(store);
    sql(STORE_FIXTURE_UNDO_V8 "PRAGMA user_version = 7;");
    assert_true(sql_number("SELECT count(*) FROM sqlite_schema WHERE name"
                           " IN ('surfaces', 'option_surfaces')") == 0);
    assert_int_equal(store_open(path, &store, &err), FACET_OK);
    struct run_info info;
    assert_int_equal(store_run_get(store, run.id, &info, &err), FACET_OK);
    assert_int_equal(info.options, 4);
    assert_false(store_run_is_project(&info));
    assert_true(isnan(info.module_w_min));
    struct option_row back;
    assert_int_equal(store_option_get(store, run.id, 4, &back, &err),
                     FACET_OK);
    assert_true(back.totals.cost == 103);
    assert_true(isnan(back.module_w));
    assert_int_equal(back.modules, TOTALS_UNKNOWN);
    int64_t project = project_run(store);
    struct option_surface_row per[2];
    option_of(1, &rows[0], per);
    assert_int_equal(store_project_options_put(store, project, rows, 1, per,
                                               2, &err), FACET_OK);
    store_close(store);
    assert_true(sql_number("SELECT user_version FROM pragma_user_version")
                == store_schema_version());
    assert_true(sql_number("SELECT count(*) FROM option_surfaces") == 2);
    assert_true(sql_number("SELECT count(*) FROM options WHERE run = 1 AND"
                           " module_w IS NULL") == 4);
    store_fixture_remove(path);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_project_rows_round_trip),
        cmocka_unit_test(test_single_surface_options_have_no_module),
        cmocka_unit_test(test_migrates_v7),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
