/*
 * test_store_older.c: the options of a run an older Facet stored, before
 * schema v5 counted moulds and measured joints, read as not known, never
 * as 0. The file is made here: options with mould counts, joints and cost
 * terms stored, then the file taken back to schema v4 with SQLite
 * (STORE_FIXTURE_UNDO_V5) and opened again, which migrates it and leaves
 * the new columns NULL. The truth is SQLite's NULL: every reading path
 * (the row, the registry, the CLI's table, show's text, the JSON, the
 * workbench's cells and legend figures) says "-" or null, a sort by a
 * column with no values keeps SQL's order, and writing such a row back
 * keeps NULL.
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

#include "cli/option_table.h"
#include "cli/option_text.h"
#include "core/out/report.h"
#include "core/search/metric.h"
#include "store/store.h"
#include "tests/support/store_fixture.h"
#include "tui/format.h"

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

static int64_t sql_int(const char *query)
{
    int64_t value = 0;
    assert_int_equal(store_fixture_sql_int(path, query, &value), 0);
    return value;
}

/* Five options of run 1 with every v5 figure non-zero (so a 0 read back
 * is wrong, not a coincidence), stored at the current schema, the file
 * then taken back to v4 and opened again: the store, migrated. */
static struct store *older_store(void)
{
    snprintf(path, sizeof path, "/tmp/facet_test_older_%d.db", (int)getpid());
    store_fixture_remove(path);
    struct facet_error err;
    struct store *store;
    assert_int_equal(store_open(path, &store, &err), FACET_OK);
    struct run_info run;
    store_fixture_run(&run);
    assert_int_equal(store_run_create(store, &run, &err), FACET_OK);
    struct option_row rows[5];
    memset(rows, 0, sizeof rows);
    for (int k = 0; k < 5; k++) {
        struct option_totals *t = &rows[k].totals;
        rows[k].number = k + 1;
        rows[k].nu = rows[k].nv = 4 + k;
        rows[k].threshold_mm = 3;
        t->panels = t->count[TYPE_DP] = (size_t)(16 + k);
        t->area = t->area_of[TYPE_DP] = 100;
        t->cost_of[TYPE_DP] = t->area_cost = 151800 - k;
        t->moulds = 7;
        t->moulds_of[TYPE_SP] = 3;
        t->moulds_of[TYPE_DP] = 4;
        t->largest_family = 5;
        t->singleton_families = 2;
        t->joint_length = 12.5;
        t->panel_cost = t->joint_cost = t->mould_cost = 10;
        t->cost = t->area_cost + 30;
        t->feasible = 1;
    }
    assert_int_equal(store_options_put(store, run.id, rows, 5, &err),
                     FACET_OK);
    store_close(store);
    sql(STORE_FIXTURE_UNDO_V5 "PRAGMA user_version = 4;");
    assert_int_equal(store_open(path, &store, &err), FACET_OK);
    return store;
}

static int setup(void **state)
{
    *state = older_store();
    return 0;
}

static int teardown(void **state)
{
    store_close(*state);  /* NULL: closed by the test */
    store_fixture_remove(path);
    return 0;
}

/* The row holds TOTALS_UNKNOWN and NaN, and every column of the registry
 * that SQLite holds as NULL reads as NaN (the truth: SQLite's NULL). */
static void test_row_and_registry(void **state)
{
    struct store *store = *state;
    struct facet_error err;
    struct option_row *rows;
    size_t n;
    assert_int_equal(store_options_get(store, 1, &rows, &n, &err), FACET_OK);
    assert_int_equal(n, 5);
    const struct option_totals *t = &rows[0].totals;
    assert_true(t->moulds == TOTALS_UNKNOWN);
    assert_true(t->moulds_of[TYPE_SP] == TOTALS_UNKNOWN);
    assert_true(t->moulds_of[TYPE_DP] == TOTALS_UNKNOWN);
    assert_true(t->largest_family == TOTALS_UNKNOWN);
    assert_true(t->singleton_families == TOTALS_UNKNOWN);
    assert_true(isnan(t->joint_length) && isnan(t->area_cost));
    assert_true(t->panels == 16 && t->cost == 151830);
    int nulls = 0;
    for (int k = 0; k < OPTION_QUANTITIES; k++) {
        const struct quantity *c = &option_quantities[k];
        if (c->writer != WRITTEN_WITH_OPTION)
            continue;
        char query[256];
        snprintf(query, sizeof query, "SELECT %s IS NULL FROM options"
                 " WHERE run = 1 AND number = 1", c->name);
        int null = (int)sql_int(query);
        double value = quantity_value(c, &rows[0]);
        if (null != (isnan(value) != 0))
            fail_msg("%s: NULL %d in the file, %g read", c->name, null,
                     value);
        nulls += null;
        char text[64];
        quantity_text(text, sizeof text, c, value, c->decimals);
        if (null)
            assert_string_equal(text, "-");
    }
    assert_int_equal(nulls, 36);  /* the columns of versions 5 (10), 7 (8),
                                     8 (3: no module), 10 (1), 12 (3),
                                     14 (4: what a planarization reached)
                                     and 15 (7: a building's seams) */
    /* An option stored before planarized options is a classified one
     * (v14's planarized defaults to 0), and reached nothing (NULL). */
    assert_int_equal(sql_int("SELECT count(*) FROM options WHERE"
                             " planarized = 0 AND closeness_reached IS NULL"
                             " AND planarity_reached IS NULL"
                             " AND planar_over IS NULL"), 5);
    assert_int_equal(t->planarized, 0);
    assert_true(t->planar_over == TOTALS_UNKNOWN);
    /* Nor were its seams measured (v15: NULL, never 0). */
    assert_int_equal(sql_int("SELECT count(*) FROM options WHERE"
                             " seams IS NULL AND seam_max_gap IS NULL"
                             " AND seam_max_kink IS NULL"
                             " AND seam_max_crease IS NULL"), 5);
    assert_true(t->seams == TOTALS_UNKNOWN && isnan(t->seam_max_gap));
    assert_true(isnan(quantity_of_totals(quantity_named("moulds"), t)));
    assert_true(isnan(quantity_of_totals(quantity_named("dp_moulds"), t)));
    free(rows);
}

/* What the CLI and the workbench show: "-" in the options table and the
 * workbench's cells, "- (not stored ...)" in show's totals (no "nan", no
 * 0 moulds), null in the JSON of show and export. */
static void test_display(void **state)
{
    struct store *store = *state;
    struct facet_error err;
    struct option_row row;
    assert_int_equal(store_option_get(store, 1, 2, &row, &err), FACET_OK);

    const struct option_table_column cli[] = {
        {"moulds", 8, 1}, {"joint_length", 8, 1}, {"dp_moulds", 8, 1}};
    char text[3][OPTION_TABLE_CELL];
    const char *cell[3];
    option_table_cells(cli, 3, 1, &row, text, cell);
    for (int k = 0; k < 3; k++)
        assert_string_equal(cell[k], "-");

    for (int k = 0; k < tui_option_column_count; k++) {
        const struct tui_column *c = &tui_option_columns[k];
        if (c->column == NULL || (strcmp(c->column, "moulds") != 0 &&
                                  strstr(c->column, "_moulds") == NULL))
            continue;
        char out[64];
        tui_fmt_cell(out, sizeof out, c, &row);
        const char *p = out;
        while (*p == ' ')
            p++;
        assert_string_equal(p, "-");
    }

    struct classify_options classify;
    classify_defaults(&classify);
    char *shown = NULL;
    size_t size = 0;
    FILE *out = open_memstream(&shown, &size);
    option_text_totals(out, &row.totals, &classify);
    fclose(out);
    assert_null(strstr(shown, "nan"));
    assert_non_null(strstr(shown, "\nmoulds           - (not measured in "
                                  "this run, or stored by an older Facet"));
    assert_non_null(strstr(shown, "\njoint length     - (not measured in "
                                  "this run, or stored by an older Facet"));
    assert_non_null(strstr(shown, "\ncost terms       - (not measured in "
                                  "this run, or stored by an older Facet"));
    assert_null(strstr(shown, "moulds           0"));
    free(shown);

    struct panelization none;
    memset(&none, 0, sizeof none);
    struct report_source source = {"x.obj", "m", 100, 32, "grid",
                                   "extremes"};
    out = open_memstream(&shown, &size);
    report_json(out, &source, &classify, &none, &row.totals);
    fclose(out);
    const char *nulls[] = {"\"moulds\":null", "\"sp_moulds\":null",
                           "\"dp_moulds\":null", "\"largest_family\":null",
                           "\"single_moulds\":null", "\"joint_length\":null"};
    for (size_t k = 0; k < sizeof nulls / sizeof nulls[0]; k++)
        if (strstr(shown, nulls[k]) == NULL)
            fail_msg("%s lacks %s", shown, nulls[k]);
    free(shown);
    out = open_memstream(&shown, &size);
    report_totals_csv(out, &row.totals);
    fclose(out);
    /* moulds .. single_moulds: five empty fields after the joint length */
    assert_non_null(strstr(shown, ",1,,,,,,,"));
    free(shown);
}

/* Appends o's number to numbers[1..], counting in numbers[0]. */
static int page_row(void *context, const struct option_row *o)
{
    int64_t *numbers = context;
    numbers[++numbers[0]] = o->number;
    return 0;
}

static int count_row(void *context, int64_t run, const struct option_row *o)
{
    (void)run;
    return page_row(context, o);
}

/* A sort by a column no option of the run has a value of is one tie
 * class, ordered by the next key (cost: 5, 4, ..., 1), in both
 * directions; before, the tie order's assertion on NaN aborted the
 * program. */
static void test_sort_by_unknown(void **state)
{
    struct store *store = *state;
    struct facet_error err;
    const char *sorts[] = {"moulds,cost", "joint_length,cost",
                           "largest_family,cost"};
    for (int d = 0; d < 2; d++)
        for (size_t k = 0; k < 3; k++) {
            int64_t numbers[8] = {0};
            struct option_query q = {1, 0, NULL, sorts[k], d, 0, 0, 0};
            assert_int_equal(store_options_query(store, &q, count_row,
                                                 numbers, &err), FACET_OK);
            assert_int_equal(numbers[0], 5);
            for (int r = 1; r <= 5; r++)
                assert_int_equal(numbers[r], d ? r : 6 - r);
        }
}

/* An option read with counts not known and stored again (as into a new
 * run) keeps NULL: never -1 or 18446744073709551615. */
static void test_written_back_null(void **state)
{
    struct store *store = *state;
    struct facet_error err;
    struct option_row *rows;
    size_t n;
    assert_int_equal(store_options_get(store, 1, &rows, &n, &err), FACET_OK);
    struct run_info run;
    store_fixture_run(&run);
    assert_int_equal(store_run_create(store, &run, &err), FACET_OK);
    assert_int_equal(store_options_put(store, run.id, rows, n, &err),
                     FACET_OK);
    free(rows);
    store_close(store);
    *state = NULL;
    char query[200];
    snprintf(query, sizeof query, "SELECT count(*) FROM options WHERE"
             " run = %lld AND moulds IS NULL AND sp_moulds IS NULL AND"
             " dp_moulds IS NULL AND largest_family IS NULL AND"
             " single_moulds IS NULL AND panels = 16 + number - 1",
             (long long)run.id);
    assert_int_equal(sql_int(query), 5);
}

/* The workbench pages a run sorted by a column none of its options has a
 * value of two rows at a time: every option once, by number (the order of
 * SQLite's ORDER BY: NULLs tie, then number), forward and backward, in
 * both directions of the key, and an option's position and the count
 * after it are SQLite's; before, a page after a NULL key found nothing. */
static void test_browse_by_unknown(void **state)
{
    struct store *store = *state;
    struct facet_error err;
    const char *columns[] = {"moulds", "joint_length", "mould_cost"};
    for (size_t c = 0; c < 3; c++)
        for (int d = 0; d < 2; d++)
            for (int backward = 0; backward < 2; backward++) {
                struct option_browse b = {.run = 1, .nkeys = 2};
                b.keys[0] = (struct browse_key){columns[c], d};
                b.keys[1] = (struct browse_key){"sp_moulds", !d};
                int64_t numbers[16] = {0};
                struct option_row after;
                int pages = 0;
                for (;;) {
                    int64_t before = numbers[0];
                    assert_int_equal(store_browse_page(store, &b,
                        before ? &after : NULL, backward, 2, page_row,
                        numbers, &err), FACET_OK);
                    if (numbers[0] == before || ++pages > 5)
                        break;
                    assert_int_equal(store_option_get(store, 1,
                        numbers[numbers[0]], &after, &err), FACET_OK);
                }
                assert_int_equal(numbers[0], 5);
                for (int r = 1; r <= 5; r++)
                    assert_int_equal(numbers[r], backward ? 6 - r : r);
                struct option_row fourth;
                assert_int_equal(store_option_get(store, 1, 4, &fourth,
                                                  &err), FACET_OK);
                int64_t position, rest;
                assert_int_equal(store_browse_position(store, &b, &fourth,
                                                       &position, &err),
                                 FACET_OK);
                assert_int_equal(position, 3);
                assert_int_equal(store_browse_count_capped(store, &b,
                    &fourth, 0, 100, &rest, &err), FACET_OK);
                assert_int_equal(rest, 1);
            }
}

/* SQLite's one number of query over the file at path (attached as old, the
 * file before the migration), NaN for NULL. */
static double sql_number(const char *query)
{
    sqlite3 *db;
    assert_int_equal(sqlite3_open(path, &db), SQLITE_OK);
    char attach[160];
    snprintf(attach, sizeof attach, "ATTACH '%s.v15' AS old", path);
    assert_int_equal(sqlite3_exec(db, attach, NULL, NULL, NULL), SQLITE_OK);
    sqlite3_stmt *s;
    if (sqlite3_prepare_v2(db, query, -1, &s, NULL) != SQLITE_OK)
        fail_msg("%s: %s", query, sqlite3_errmsg(db));
    assert_int_equal(sqlite3_step(s), SQLITE_ROW);
    double value = sqlite3_column_type(s, 0) == SQLITE_NULL
                       ? NAN : sqlite3_column_double(s, 0);
    sqlite3_finalize(s);
    sqlite3_close(db);
    return value;
}

/* A v15 file (issue 27, schema v16): its options' gaps in mm and kinks
 * in degrees, its seams' gap in m and angles in rad. Migrated, every
 * gap column users query is in mm and every kink and crease in degrees,
 * SQLite's own arithmetic on the old file's values (its seams' m times
 * 1000, rad times 180 over pi; an option's own as they were), option_held
 * keeps them in m and rad (the seams' as they were, an option's own
 * SQLite's mm / 1000 and degrees x pi / 180), and Facet reads the seams'
 * values to the bit the v15 file held them. */
static void test_v15_gaps_in_one_unit(void **state)
{
    (void)state;
    snprintf(path, sizeof path, "/tmp/facet_test_v15_%d.db", (int)getpid());
    char old[80];
    snprintf(old, sizeof old, "%s.v15", path);
    store_fixture_remove(path);
    store_fixture_remove(old);
    struct facet_error err;
    struct store *store;
    assert_int_equal(store_open(path, &store, &err), FACET_OK);
    struct run_info run;
    store_fixture_run(&run);
    assert_int_equal(store_run_create(store, &run, &err), FACET_OK);
    enum { N = 40 };
    struct option_row rows[N];
    memset(rows, 0, sizeof rows);
    for (int k = 0; k < N; k++) {
        struct option_totals *t = &rows[k].totals;
        option_totals_classified(t);
        rows[k].number = k + 1;
        rows[k].nu = rows[k].nv = 4;
        rows[k].threshold_mm = 3;
        t->panels = t->count[TYPE_DP] = 16;
        t->area = t->area_of[TYPE_DP] = 100;
        /* m and rad of no round number, so that a rounding shows */
        t->max_gap = 0.0123456789 * (k + 1) / 7;
        t->mean_gap = t->max_gap / 3;
        t->max_kink = 0.0345678912 * (k + 1) / 11;
        t->mean_kink = t->max_kink / 3;
        t->seams = 2;
        t->seam_length = 4;
        t->seam_max_gap = 0.0098765432 * (k + 1) / 13;
        t->seam_max_kink = 0.0234567891 * (k + 1) / 17;
        t->seam_max_crease = 0.523598775598 + k / 19.0;
    }
    assert_int_equal(store_options_put(store, run.id, rows, N, &err),
                     FACET_OK);
    store_close(store);
    sql(STORE_FIXTURE_UNDO_V16 "PRAGMA user_version = 15;");
    /* the file as v15 wrote it, kept to compare with */
    char copy[200];
    snprintf(copy, sizeof copy, "cp '%s' '%s'", path, old);
    assert_int_equal(system(copy), 0);
    assert_int_equal(sql_int("SELECT count(*) FROM sqlite_schema"
                             " WHERE name = 'option_held'"), 0);
    assert_int_equal(store_open(path, &store, &err), FACET_OK);
    store_close(store);
    assert_int_equal(sql_int("PRAGMA user_version"), 16);
    /* pi as core/base/units.h has it, as SQLite reads the migration's */
    assert_true(sql_number("SELECT 3.141592653589793") == M_PI);
    static const char *const same[] = {
        /* the seams: the old m and rad, in mm and degrees by SQLite */
        "SELECT count(*) FROM options o JOIN old.options p USING (run, number)"
        " WHERE o.seam_max_gap = p.seam_max_gap * 1000"
        " AND o.seam_max_kink = p.seam_max_kink * 180 / 3.141592653589793"
        " AND o.seam_max_crease = p.seam_max_crease * 180 / 3.141592653589793",
        /* an option's own mm and degrees, as they were */
        "SELECT count(*) FROM options o JOIN old.options p USING (run, number)"
        " WHERE o.max_gap = p.max_gap AND o.mean_gap = p.mean_gap"
        " AND o.max_kink = p.max_kink AND o.mean_kink = p.mean_kink",
        /* held as core holds them: the seams' old m and rad as they were,
         * an option's own from the old mm and degrees */
        "SELECT count(*) FROM option_held h"
        " JOIN old.options p ON p.run = h.run AND p.number = h.option"
        " WHERE h.seam_max_gap = p.seam_max_gap"
        " AND h.seam_max_kink = p.seam_max_kink"
        " AND h.seam_max_crease = p.seam_max_crease"
        " AND h.max_gap = p.max_gap / 1000"
        " AND h.mean_gap = p.mean_gap / 1000"
        " AND h.max_kink = p.max_kink * 3.141592653589793 / 180"
        " AND h.mean_kink = p.mean_kink * 3.141592653589793 / 180",
    };
    for (size_t q = 0; q < sizeof same / sizeof same[0]; q++)
        if (sql_number(same[q]) != N)
            fail_msg("%g of %d options: %s", sql_number(same[q]), N,
                     same[q]);
    /* One unit per family: a seam's gap and an option's are comparable
     * in SQL (the seam gaps here are about the options' gaps' size). */
    assert_true(sql_number("SELECT max(seam_max_gap) / max(max_gap)"
                           " FROM options") > 0.1);
    assert_true(sql_number("SELECT max(seam_max_gap) / max(max_gap)"
                           " FROM options") < 10);
    /* Facet reads the seams it stored to the bit, and an option's own
     * as SQLite's m. */
    assert_int_equal(store_open(path, &store, &err), FACET_OK);
    for (int k = 0; k < N; k++) {
        struct option_row back;
        assert_int_equal(store_option_get(store, run.id, k + 1, &back, &err),
                         FACET_OK);
        /* the v15 file's m and rad, to the bit */
        char query[200];
        static const char *const seam[] = {"seam_max_gap", "seam_max_kink",
                                           "seam_max_crease"};
        const double got[] = {back.totals.seam_max_gap,
                              back.totals.seam_max_kink,
                              back.totals.seam_max_crease};
        for (int c = 0; c < 3; c++) {
            snprintf(query, sizeof query, "SELECT %s FROM old.options"
                     " WHERE number = %d", seam[c], k + 1);
            if (!(got[c] == sql_number(query)))
                fail_msg("option %d: %s reads %.17g, v15 held %.17g", k + 1,
                         seam[c], got[c], sql_number(query));
        }
        snprintf(query, sizeof query, "SELECT max_gap FROM option_held"
                 " WHERE option = %d", k + 1);
        assert_true(back.totals.max_gap == sql_number(query));
    }
    store_close(store);
    store_fixture_remove(path);
    store_fixture_remove(old);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(test_row_and_registry, setup,
                                        teardown),
        cmocka_unit_test_setup_teardown(test_display, setup,
                                        teardown),
        cmocka_unit_test_setup_teardown(test_sort_by_unknown, setup,
                                        teardown),
        cmocka_unit_test_setup_teardown(test_written_back_null, setup,
                                        teardown),
        cmocka_unit_test_setup_teardown(test_browse_by_unknown, setup,
                                        teardown),
        cmocka_unit_test(test_v15_gaps_in_one_unit),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
