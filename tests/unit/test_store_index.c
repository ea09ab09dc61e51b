/*
 * test_store_index.c: the options table's indexes by metric, dropped
 * while a run stores many options and built when it ends
 * (store_indexes_defer, store_indexes_build), checked against SQLite
 * itself: the list is every index of the options table but the one by
 * rank (sqlite_schema); a small run, or one smaller than the file, keeps
 * them; a run that dropped them ends with all of them, its rows unchanged;
 * a writer killed before its end leaves them to the next writer, which
 * builds them when it marks the run interrupted, and not while the writer
 * is alive; and the TUI's table sorted by a metric, and `facet options
 * --where` on the grid, are planned on their indexes (EXPLAIN QUERY
 * PLAN).
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

#include "store/store_internal.h"
#include "tests/support/store_fixture.h"
#include "tui/table_model.h"

#define ROWS 3000

static char db_path[80];

static const char *fresh_db(const char *name)
{
    snprintf(db_path, sizeof db_path, "/tmp/facet_test_index_%s_%d.db", name,
             (int)getpid());
    store_fixture_remove(db_path);
    return db_path;
}

/* The indexes of the options table in the file, as SQLite lists them,
 * one name per line, sorted. */
static void file_indexes(const char *path, char *out, size_t size)
{
    sqlite3 *db;
    sqlite3_stmt *stmt;
    assert_int_equal(sqlite3_open_v2(path, &db, SQLITE_OPEN_READONLY, NULL),
                     SQLITE_OK);
    assert_int_equal(sqlite3_prepare_v2(db,
        "SELECT name FROM sqlite_schema WHERE type = 'index' AND"
        " tbl_name = 'options' AND sql IS NOT NULL ORDER BY name", -1,
        &stmt, NULL), SQLITE_OK);
    out[0] = '\0';
    while (sqlite3_step(stmt) == SQLITE_ROW)
        snprintf(out + strlen(out), size - strlen(out), "%s\n",
                 (const char *)sqlite3_column_text(stmt, 0));
    sqlite3_finalize(stmt);
    sqlite3_close(db);
}

static int compare_names(const void *a, const void *b)
{
    return strcmp(*(const char *const *)a, *(const char *const *)b);
}

/* The indexes a file has when none is dropped: the list's, and rank's,
 * sorted as file_indexes gives them. */
static void every_index(char *out, size_t size)
{
    const char *names[64];
    size_t n = 0;
    names[n++] = "options_by_rank";
    for (size_t k = 0; store_metric_index_name(k) != NULL; k++)
        names[n++] = store_metric_index_name(k);
    qsort(names, n, sizeof names[0], compare_names);
    out[0] = '\0';
    for (size_t k = 0; k < n; k++)
        snprintf(out + strlen(out), size - strlen(out), "%s\n", names[k]);
}

/* A run of n options with metrics spread apart (no two costs equal). */
static int64_t put_run(struct store *store, int n, int64_t expected,
                       int *deferred)
{
    struct facet_error err;
    struct run_info run;
    store_fixture_run(&run);
    assert_int_equal(store_run_create(store, &run, &err), FACET_OK);
    if (deferred != NULL)
        assert_int_equal(store_indexes_defer(store, expected, deferred,
                                             &err), FACET_OK);
    struct option_row *rows = calloc((size_t)n, sizeof *rows);
    assert_non_null(rows);
    for (int k = 0; k < n; k++) {
        struct option_row *o = &rows[k];
        o->number = k + 1;
        o->nu = 1 + (k * 7) % 31;
        o->nv = 1 + (k * 11) % 29;
        o->threshold_mm = 1 + (k % 5);
        o->totals.panels = (size_t)(o->nu * o->nv);
        o->totals.cost = 1e5 + fmod(k * 7919.0, 104729.0);
        o->totals.planarity = 1e-3 * fmod(k * 104729.0, 7919.0);
        o->totals.area_of[TYPE_DP] = fmod(k * 31.0, 997.0);
        o->totals.area = 1000;
    }
    for (int first = 0; first < n; first += 500) {
        size_t batch = n - first < 500 ? (size_t)(n - first) : 500;
        assert_int_equal(store_options_put(store, run.id, rows + first,
                                           batch, &err), FACET_OK);
    }
    free(rows);
    return run.id;
}

/* The list is every index the schema gives the options table but the one
 * by rank, which a run only appends to and keeps. */
static void test_list_is_the_schema(void **state)
{
    (void)state;
    struct store *store;
    struct facet_error err;
    assert_int_equal(store_open(fresh_db("list"), &store, &err), FACET_OK);
    store_close(store);
    char have[2048], want[2048];
    file_indexes(db_path, have, sizeof have);
    every_index(want, sizeof want);
    assert_string_equal(have, want);
    store_fixture_remove(db_path);
}

/* A small run, and a big one into a file that holds more, keep them. */
static void test_kept_when_not_worth_it(void **state)
{
    (void)state;
    struct store *store;
    struct facet_error err;
    char have[2048], want[2048];
    every_index(want, sizeof want);
    assert_int_equal(store_open(fresh_db("kept"), &store, &err), FACET_OK);
    int deferred = -1;
    put_run(store, 10, STORE_BULK_ROWS - 1, &deferred);
    assert_int_equal(deferred, 0);
    file_indexes(db_path, have, sizeof have);
    assert_string_equal(have, want);
    /* the file holds more options than the new run brings */
    assert_int_equal(store_exec(store, "UPDATE runs SET options = 10000000",
                                "test", &err), FACET_OK);
    put_run(store, 10, STORE_BULK_ROWS, &deferred);
    assert_int_equal(deferred, 0);
    file_indexes(db_path, have, sizeof have);
    assert_string_equal(have, want);
    store_close(store);
    store_fixture_remove(db_path);
}

static int same_rows(const struct option_row *a, const struct option_row *b,
                     size_t n)
{
    for (size_t k = 0; k < n; k++)
        if (a[k].number != b[k].number ||
            a[k].totals.cost != b[k].totals.cost)
            return 0;
    return 1;
}

/* A run that drops them ends with every one, and its rows read the same
 * (sorted by cost, filtered) with and without them. */
static void test_dropped_then_built(void **state)
{
    (void)state;
    struct store *store;
    struct facet_error err;
    char have[2048], want[2048];
    every_index(want, sizeof want);
    assert_int_equal(store_open(fresh_db("built"), &store, &err), FACET_OK);
    int deferred = 0;
    int64_t run = put_run(store, ROWS, STORE_BULK_ROWS, &deferred);
    assert_int_equal(deferred, 1);
    file_indexes(db_path, have, sizeof have);
    assert_string_equal(have, "options_by_rank\n");

    struct filter *where;
    assert_int_equal(filter_compile("cost < 1.5e5 and nu > 3", &where, &err),
                     FACET_OK);
    struct option_query q = {run, 0, where, "cost", 0, 0, 0, 0};
    struct option_row *before, *after;
    size_t nbefore, nafter;
    assert_int_equal(store_options_query_rows(store, &q, &before, &nbefore,
                                              &err), FACET_OK);
    int built = 0;
    assert_int_equal(store_indexes_build(store, run, &built, &err),
                     FACET_OK);
    assert_int_equal(built, 1);
    file_indexes(db_path, have, sizeof have);
    assert_string_equal(have, want);
    assert_int_equal(store_options_query_rows(store, &q, &after, &nafter,
                                              &err), FACET_OK);
    assert_true(nbefore > 100);
    assert_int_equal(nbefore, nafter);
    assert_true(same_rows(before, after, nafter));
    /* built again: nothing to do */
    assert_int_equal(store_indexes_build(store, run, &built, &err),
                     FACET_OK);
    assert_int_equal(built, 0);
    assert_int_equal(store_check(store, &err), FACET_OK);
    free(before);
    free(after);
    filter_free(where);
    store_close(store);
    store_fixture_remove(db_path);
}

/* A writer killed while they were dropped: its run stays "running" while
 * it is alive (no one builds them under it), and the next writer after it
 * is gone marks the run interrupted and builds them. */
static void test_killed_writer(void **state)
{
    (void)state;
    struct store *store;
    struct facet_error err;
    char have[2048], want[2048];
    every_index(want, sizeof want);
    assert_int_equal(store_open(fresh_db("killed"), &store, &err), FACET_OK);
    int deferred = 0;
    int64_t run = put_run(store, 500, STORE_BULK_ROWS, &deferred);
    assert_int_equal(deferred, 1);
    /* another run's end leaves them to the writer still storing */
    int64_t other = put_run(store, 10, 0, NULL);
    int built = 1;
    assert_int_equal(store_indexes_build(store, other, &built, &err),
                     FACET_OK);
    assert_int_equal(built, 0);
    store_close(store);  /* no store_indexes_build: killed */

    assert_int_equal(store_open(db_path, &store, &err), FACET_OK);
    store_close(store);
    file_indexes(db_path, have, sizeof have);
    assert_string_equal(have, "options_by_rank\n");  /* writer alive */

    sqlite3 *db;
    assert_int_equal(sqlite3_open(db_path, &db), SQLITE_OK);
    assert_int_equal(sqlite3_exec(db, "UPDATE runs SET writer_pid ="
                                  " 2147483646", NULL, NULL, NULL),
                     SQLITE_OK);
    sqlite3_close(db);
    assert_int_equal(store_open(db_path, &store, &err), FACET_OK);
    struct run_info info;
    assert_int_equal(store_run_get(store, run, &info, &err), FACET_OK);
    assert_int_equal(info.status, RUN_INTERRUPTED);
    assert_int_equal(info.options, 500);
    assert_int_equal(store_check(store, &err), FACET_OK);
    store_close(store);
    file_indexes(db_path, have, sizeof have);
    assert_string_equal(have, want);
    store_fixture_remove(db_path);
}

/* --- query plans --- */

/* The SQL of every statement the store runs that orders its rows, as
 * SQLite expands it. */
struct traced {
    char *sql[512];
    int n;
};

static int trace(unsigned type, void *context, void *p, void *x)
{
    (void)x;
    struct traced *t = context;
    if (type != SQLITE_TRACE_STMT || t->n == 512)
        return 0;
    char *sql = sqlite3_expanded_sql(p);
    if (sql != NULL && strstr(sql, "ORDER BY") != NULL)  /* pages */
        t->sql[t->n++] = strdup(sql);
    sqlite3_free(sql);
    return 0;
}

/* SQLite's plan of sql on db, its lines joined by " | ". */
static void plan_of(sqlite3 *db, const char *sql, char *out, size_t size)
{
    char explain[8192];
    snprintf(explain, sizeof explain, "EXPLAIN QUERY PLAN %s", sql);
    sqlite3_stmt *stmt;
    out[0] = '\0';
    if (sqlite3_prepare_v2(db, explain, -1, &stmt, NULL) != SQLITE_OK)
        return;
    while (sqlite3_step(stmt) == SQLITE_ROW)
        snprintf(out + strlen(out), size - strlen(out), "%s | ",
                 (const char *)sqlite3_column_text(stmt, 3));
    sqlite3_finalize(stmt);
}

/* Every statement of t that orders by column (unquoted or quoted, not
 * written +column to keep off its index) is planned on options_by_column;
 * returns how many there were. */
static int check_plans(sqlite3 *db, const struct traced *t,
                       const char *column)
{
    char plain[64], quoted[64], index[64], plan[4096];
    snprintf(plain, sizeof plain, "ORDER BY %s", column);
    snprintf(quoted, sizeof quoted, "ORDER BY \"%s\"", column);
    snprintf(index, sizeof index, "INDEX options_by_%s ", column);
    int seen = 0;
    for (int k = 0; k < t->n; k++) {
        if (strstr(t->sql[k], plain) == NULL &&
            strstr(t->sql[k], quoted) == NULL)
            continue;
        seen++;
        plan_of(db, t->sql[k], plan, sizeof plan);
        /* (a descending key sorts equal values by number apart: "FOR
         * RIGHT PART OF ORDER BY" is not a sort of the run) */
        if (strstr(plan, index) == NULL ||
            strstr(plan, "TEMP B-TREE FOR ORDER BY") != NULL)
            fail_msg("%s\n  is planned %s", t->sql[k], plan);
    }
    return seen;
}

/* After a run that dropped them: the TUI's table sorted by cost and by
 * planarity, paged and jumped to its end, read their pages by the
 * metric's index, and `facet options --where` on the grid by the grid's. */
static void test_plans_use_indexes(void **state)
{
    (void)state;
    struct store *store;
    struct facet_error err;
    assert_int_equal(store_open(fresh_db("plans"), &store, &err), FACET_OK);
    int deferred = 0;
    int64_t run = put_run(store, ROWS, STORE_BULK_ROWS, &deferred);
    assert_int_equal(deferred, 1);
    assert_int_equal(store_indexes_build(store, run, NULL, &err), FACET_OK);
    assert_int_equal(store_analyze(store, &err), FACET_OK);

    struct traced t = {{0}, 0};
    sqlite3_trace_v2(store->db, SQLITE_TRACE_STMT, trace, &t);
    struct table_model m;
    struct browse_key cost[] = {{"cost", 0}}, planarity[] = {{"planarity", 1}};
    assert_int_equal(table_model_open(&m, store, run, &err), FACET_OK);
    assert_int_equal(table_model_set_sort(&m, cost, 1, &err), FACET_OK);
    for (int k = 0; k < 5; k++)
        assert_int_equal(table_model_select(&m, m.selected + 150, &err),
                         FACET_OK);
    assert_int_equal(table_model_set_sort(&m, planarity, 1, &err),
                     FACET_OK);
    assert_int_equal(table_model_count_exact(&m, &err), FACET_OK);
    assert_int_equal(table_model_select(&m, m.count - 1, &err), FACET_OK);
    table_model_close(&m);
    sqlite3_trace_v2(store->db, 0, NULL, NULL);
    sqlite3 *db;
    assert_int_equal(sqlite3_open_v2(db_path, &db, SQLITE_OPEN_READONLY,
                                     NULL), SQLITE_OK);
    assert_true(check_plans(db, &t, "cost") >= 3);
    assert_true(check_plans(db, &t, "planarity") >= 2);

    /* facet options --where 'nu = 7 and nv = 13': by an index of the
     * grid (its sort by a metric reads the whole run in order, and has
     * not used an index, so that tie classes are gathered whole) */
    for (int k = 0; k < t.n; k++)
        free(t.sql[k]);
    t.n = 0;
    sqlite3_trace_v2(store->db, SQLITE_TRACE_STMT, trace, &t);
    struct filter *where;
    assert_int_equal(filter_compile("nu = 7 and nv = 13", &where, &err),
                     FACET_OK);
    struct option_query q = {run, 0, where, NULL, 0, 0, 0, 0};
    struct option_row *rows;
    size_t n;
    assert_int_equal(store_options_query_rows(store, &q, &rows, &n, &err),
                     FACET_OK);
    assert_true(n > 0);
    free(rows);
    filter_free(where);
    sqlite3_trace_v2(store->db, 0, NULL, NULL);
    assert_int_equal(t.n, 1);
    char plan[4096];
    plan_of(db, t.sql[0], plan, sizeof plan);
    if (strstr(plan, "INDEX options_by_nu ") == NULL &&
        strstr(plan, "INDEX options_by_nv ") == NULL)
        fail_msg("%s\n  is planned %s", t.sql[0], plan);
    sqlite3_close(db);
    for (int k = 0; k < t.n; k++)
        free(t.sql[k]);
    store_close(store);
    store_fixture_remove(db_path);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_list_is_the_schema),
        cmocka_unit_test(test_kept_when_not_worth_it),
        cmocka_unit_test(test_dropped_then_built),
        cmocka_unit_test(test_killed_writer),
        cmocka_unit_test(test_plans_use_indexes),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
