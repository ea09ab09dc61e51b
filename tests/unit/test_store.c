/*
 * test_store.c: the SQLite result store on real files: runs, options and
 * panels round-trip bit for bit; queries sort, filter and page like SQL
 * written by hand; a study stopped between batches and resumed ends with
 * the rows of one never stopped; foreign, newer, damaged and non-database
 * files are refused with one clear line; an older schema is migrated.
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

#include "core/evaluate/evaluate.h"
#include "core/surface/example.h"
#include "store/filter.h"
#include "study/study.h"
#include "study/study_export.h"
#include "tests/support/store_fixture.h"

static char surface_path[64];
static char db_path[64];

static int setup(void **state)
{
    (void)state;
    snprintf(surface_path, sizeof surface_path,
             "/tmp/facet_test_store_%d.obj", (int)getpid());
    FILE *out = fopen(surface_path, "w");
    struct facet_error err;
    if (out == NULL || example_write("roof", 20, out, &err) != FACET_OK)
        return -1;
    fclose(out);
    return 0;
}

static int teardown(void **state)
{
    (void)state;
    unlink(surface_path);
    return 0;
}

/* A fresh database path for one test. */
static const char *fresh_db(const char *name)
{
    snprintf(db_path, sizeof db_path, "/tmp/facet_test_%s_%d.db", name,
             (int)getpid());
    store_fixture_remove(db_path);
    return db_path;
}

static void request_for(struct study_request *r, enum optimize_method method)
{
    memset(r, 0, sizeof *r);
    r->surface_path = surface_path;
    r->mesh = (struct mesh_options){UNITS_M, NULL, NULL};
    r->name = "test";
    struct optimize_settings *s = &r->settings;
    classify_defaults(&s->base.classify);
    s->base.mode = PANEL_EXTREMES;
    s->base.classify.max_panel_area = 1000;  /* coarse grids, big panels */
    s->method = method;
    s->space = (struct design_space){4, 7, 5, 8, 2, 4, 1};
    s->seed = 7;
    s->evaluations = 45;
    s->population = 8;
    s->generations = 4;
    s->jobs = 2;
    struct facet_error err;
    assert_int_equal(objectives_parse("cost,planarity,dp_area", "objectives",
                                      s->objectives, &s->nobjectives, &err),
                     FACET_OK);
}

/* Runs the exhaustive test study into store to its end; its id. */
static int64_t finished_run(struct store *store,
                            struct study_request *request)
{
    struct facet_error err;
    request_for(request, METHOD_EXHAUSTIVE);
    int64_t run;
    enum optimize_outcome outcome;
    assert_int_equal(study_start(store, request, NULL, &run, &outcome, &err),
                     FACET_OK);
    assert_int_equal(outcome, OPTIMIZE_DONE);
    return run;
}

/* Stops after a number of progress reports. */
struct stopper {
    int reports, stop_after;
};

static void count_report(void *context, const struct optimize_progress *p)
{
    (void)p;
    ((struct stopper *)context)->reports++;
}

static int stop_when_told(void *context)
{
    struct stopper *s = context;
    return s->stop_after > 0 && s->reports >= s->stop_after;
}

static void get_options(struct store *store, int64_t run,
                        struct option_row **rows, size_t *n)
{
    struct facet_error err;
    assert_int_equal(store_options_get(store, run, rows, n, &err), FACET_OK);
}

static void test_run_roundtrip(void **state)
{
    (void)state;
    struct store *store;
    struct facet_error err;
    assert_int_equal(store_open(fresh_db("roundtrip"), &store, &err),
                     FACET_OK);
    struct study_request request;
    int64_t run = finished_run(store, &request);

    struct run_info info;
    assert_int_equal(store_run_get(store, run, &info, &err), FACET_OK);
    assert_int_equal(info.status, RUN_DONE);
    assert_int_equal(info.method, METHOD_EXHAUSTIVE);
    assert_int_equal(info.options, 4 * 4 * 3);
    assert_int_equal(info.u_min, 4);
    assert_int_equal(info.v_max, 8);
    assert_true(info.finished[0] != '\0');
    assert_true(info.knee > 0);
    assert_true(info.pareto_options > 0);
    assert_true(isfinite(info.hypervolume));
    assert_int_equal(strlen(info.surface_sha256), 64);

    /* The run measured what its objectives (cost, planarity, dp_area),
     * its typing (by fit, the default) and its prices (areas only) read:
     * the SP fits and nothing else; its Pareto options in full. */
    assert_int_equal(info.measured, OPTION_MEASURE_FITS);

    /* Every option equals a fresh evaluation of its design point, bit for
     * bit, measured as the run measured it (its Pareto options in full):
     * nothing is rounded on the way through SQLite, and what was not
     * measured reads as not known. */
    struct option_row *rows;
    size_t n;
    get_options(store, run, &rows, &n);
    assert_int_equal(n, 48);
    struct surface surface;
    assert_int_equal(study_open_surface(store, &info, &surface, &err), FACET_OK);
    int knees = 0;
    size_t pareto = 0;
    for (size_t k = 0; k < n; k++) {
        assert_int_equal(rows[k].number, (int64_t)k + 1);
        struct option_params params = request.settings.base;
        params.nu = rows[k].nu;
        params.nv = rows[k].nv;
        params.classify.threshold = rows[k].threshold_mm / 1000;
        params.unmeasured = rows[k].rank == 1
                                ? 0 : OPTION_MEASURE_ALL & ~info.measured;
        struct panelization panels;
        struct option_totals totals;
        assert_int_equal(option_evaluate(&surface, &params, NULL, &panels,
                                         &totals, &err), FACET_OK);
        assert_memory_equal(&totals, &rows[k].totals, sizeof totals);
        if (rows[k].rank != 1)
            assert_true(isnan(rows[k].totals.joint_length) &&
                        rows[k].totals.moulds == TOTALS_UNKNOWN &&
                        rows[k].totals.sp_fitted != TOTALS_UNKNOWN &&
                        rows[k].totals.gaps_over == TOTALS_UNKNOWN);
        panelization_free(&panels);
        knees += rows[k].knee;
        pareto += rows[k].rank == 1;
        assert_true(rows[k].rank >= 1);
        if (rows[k].rank == 1) {
            /* The Pareto options' panels are stored and read back as
             * they were computed. */
            int exists = 0;
            assert_int_equal(store_panels_exist(store, run, rows[k].number,
                                                &exists, &err), FACET_OK);
            assert_int_equal(exists, 1);
            struct panelization stored;
            assert_int_equal(store_panels_get(store, run, rows[k].number,
                                              &stored, &err), FACET_OK);
            assert_int_equal(option_evaluate(&surface, &params, NULL, &panels,
                                             &totals, &err), FACET_OK);
            assert_int_equal(stored.npanels, panels.npanels);
            assert_int_equal(stored.nu, panels.nu);
            for (size_t p = 0; p < panels.npanels; p++) {
                assert_int_equal(stored.panels[p].i, panels.panels[p].i);
                assert_int_equal(stored.panels[p].class,
                                 panels.panels[p].class);
                assert_int_equal(stored.panels[p].type,
                                 panels.panels[p].type);
                assert_true(stored.panels[p].area == panels.panels[p].area);
                assert_true(stored.panels[p].cost == panels.panels[p].cost);
                assert_true(stored.panels[p].k1 == panels.panels[p].k1);
            }
            for (int c = 0; c < panels.nu * panels.nv; c++)
                assert_int_equal(stored.cell_panel[c], panels.cell_panel[c]);
            panelization_free(&stored);
            panelization_free(&panels);
        } else {
            int exists = 1;
            assert_int_equal(store_panels_exist(store, run, rows[k].number,
                                                &exists, &err), FACET_OK);
            assert_int_equal(exists, 0);
        }
    }
    assert_int_equal(knees, 1);
    assert_int_equal(pareto, (size_t)info.pareto_options);
    surface_close(&surface);
    free(rows);

    assert_int_equal(store_run_delete(store, run, &err), FACET_OK);
    assert_int_equal(store_run_get(store, run, &info, &err), FACET_EINPUT);
    get_options(store, run, &rows, &n);
    assert_int_equal(n, 0);
    free(rows);
    store_close(store);
}

/* What a query hands back, in order. */
struct collected {
    int64_t number[512];
    size_t n;
};

static int collect(void *context, int64_t run, const struct option_row *o)
{
    (void)run;
    struct collected *c = context;
    if (c->n < 512)
        c->number[c->n++] = o->number;
    return 0;
}

/* A row of the hand-written SQL: the option, its run, its sort keys. */
struct expected_row {
    int64_t number, run;
    double key[4];
};

/* The tie tolerance of each sort key (docs/decisions.md, Ties: a billionth of
 * the key's range over the run, or of its largest magnitude), computed
 * here from the file. */
static void key_tolerances(sqlite3 *db, const char *sort, double *tol,
                           int *nkeys)
{
    char names[128];
    snprintf(names, sizeof names, "%s", sort ? sort : "");
    *nkeys = 0;
    char *rest = names;
    for (char *name = strtok_r(rest, ",", &rest); name && *nkeys < 4;
         name = strtok_r(NULL, ",", &rest)) {
        char sql[256];
        snprintf(sql, sizeof sql, "SELECT min(%s), max(%s) FROM options",
                 name, name);
        sqlite3_stmt *s;
        assert_int_equal(sqlite3_prepare_v2(db, sql, -1, &s, NULL),
                         SQLITE_OK);
        assert_int_equal(sqlite3_step(s), SQLITE_ROW);
        double low = sqlite3_column_double(s, 0);
        double high = sqlite3_column_double(s, 1);
        sqlite3_finalize(s);
        tol[(*nkeys)++] = 1e-9 * fmax(high - low,
                                      fmax(fabs(low), fabs(high)));
    }
}

/* Orders two expected rows: keys within their tolerance tie and fall to
 * the next key, then run, then number (all reversed when descending). */
static int expected_before(const struct expected_row *a,
                           const struct expected_row *b, const double *tol,
                           int nkeys, int desc)
{
    int c = 0;
    for (int k = 0; k < nkeys && c == 0; k++)
        if (fabs(a->key[k] - b->key[k]) > tol[k])
            c = a->key[k] < b->key[k] ? -1 : 1;
    if (c == 0 && a->run != b->run)
        c = a->run < b->run ? -1 : 1;
    if (c == 0)
        c = (a->number > b->number) - (a->number < b->number);
    return desc ? c > 0 : c < 0;
}

/* The same question asked through store_options_query and as SQL written
 * by hand against the file: sql selects number, run and the sort keys of
 * the matching rows, and the rows are put in order here, with ties as
 * ties, before limit and offset apply. */
static void check_query(struct store *store, sqlite3 *db, int64_t run,
                        const char *where, const char *sort, int desc,
                        int pareto, int64_t limit, int64_t offset,
                        const char *sql)
{
    struct facet_error err;
    struct filter *filter = NULL;
    if (where != NULL)
        assert_int_equal(filter_compile(where, &filter, &err), FACET_OK);
    struct option_query q = {run, pareto, filter, sort, desc, limit, offset, 0};
    struct collected got = {{0}, 0};
    assert_int_equal(store_options_query(store, &q, collect, &got, &err),
                     FACET_OK);
    double tol[4];
    int nkeys;
    key_tolerances(db, sort, tol, &nkeys);
    static struct expected_row want[512];
    size_t n = 0;
    sqlite3_stmt *s;
    assert_int_equal(sqlite3_prepare_v2(db, sql, -1, &s, NULL), SQLITE_OK);
    while (sqlite3_step(s) == SQLITE_ROW && n < 512) {
        struct expected_row r = {sqlite3_column_int64(s, 0),
                                 sqlite3_column_int64(s, 1), {0}};
        for (int k = 0; k < nkeys; k++)
            r.key[k] = sqlite3_column_double(s, 2 + k);
        size_t at = n++;
        while (at > 0 &&
               expected_before(&r, &want[at - 1], tol, nkeys, desc)) {
            want[at] = want[at - 1];
            at--;
        }
        want[at] = r;
    }
    sqlite3_finalize(s);
    size_t first = (size_t)offset < n ? (size_t)offset : n;
    size_t count = n - first;
    if (limit > 0 && (size_t)limit < count)
        count = (size_t)limit;
    assert_int_equal(got.n, count);
    for (size_t k = 0; k < got.n; k++)
        assert_int_equal(got.number[k], want[first + k].number);
    filter_free(filter);
}

static void test_queries(void **state)
{
    (void)state;
    struct store *store;
    struct facet_error err;
    assert_int_equal(store_open(fresh_db("queries"), &store, &err),
                     FACET_OK);
    struct study_request request;
    int64_t run = finished_run(store, &request);
    sqlite3 *db;
    assert_int_equal(sqlite3_open(db_path, &db), SQLITE_OK);
    check_query(store, db, run, NULL, "cost", 0, 0, 0, 0,
                "SELECT number, run, cost FROM options");
    check_query(store, db, run, NULL, "dp_area,planarity", 1, 0, 5, 3,
                "SELECT number, run, dp_area, planarity FROM options");
    check_query(store, db, run, NULL, "planarity,cost", 0, 0, 7, 0,
                "SELECT number, run, planarity, cost FROM options");
    check_query(store, db, run, NULL, NULL, 0, 1, 0, 0,
                "SELECT number, run FROM options WHERE rank = 1");
    check_query(store, db, run, "nu >= 6 and threshold_mm < 3.5 or pareto",
                "cost", 0, 0, 0, 0,
                "SELECT number, run, cost FROM options WHERE (nu >= 6 AND"
                " threshold_mm < 3.5) OR rank = 1");
    check_query(store, db, 0, "not feasible", NULL, 0, 0, 0, 0,
                "SELECT number, run FROM options WHERE NOT feasible");

    struct option_query bad = {run, 0, NULL, "cost,nosuch", 0, 0, 0, 0};
    struct collected got = {{0}, 0};
    assert_int_equal(store_options_query(store, &bad, collect, &got, &err),
                     FACET_EINPUT);
    assert_non_null(strstr(err.message, "nosuch"));
    sqlite3_close(db);
    store_close(store);
}

/* A study stopped after some batches and resumed, possibly by another
 * process, ends with the rows of one that was never stopped. */
static void check_resume(enum optimize_method method, enum param_method uv)
{
    struct facet_error err;
    struct store *store;
    assert_int_equal(store_open(fresh_db("resume"), &store, &err), FACET_OK);
    struct study_request request;
    request_for(&request, method);
    request.uv = uv;
    int64_t whole, cut;
    enum optimize_outcome outcome;
    assert_int_equal(study_start(store, &request, NULL, &whole, &outcome,
                                 &err), FACET_OK);
    struct stopper stopper = {0, 2};
    struct study_hooks hooks = {&stopper, NULL, count_report,
                                stop_when_told, NULL, NULL, NULL};
    assert_int_equal(study_start(store, &request, &hooks, &cut, &outcome,
                                 &err), FACET_OK);
    assert_int_equal(outcome, OPTIMIZE_INTERRUPTED);
    struct run_info info;
    assert_int_equal(store_run_get(store, cut, &info, &err), FACET_OK);
    assert_int_equal(info.status, RUN_INTERRUPTED);
    assert_true(info.options > 0);
    store_close(store);

    assert_int_equal(store_open(db_path, &store, &err), FACET_OK);
    assert_int_equal(study_resume(store, cut, NULL, &outcome, &err),
                     FACET_OK);
    assert_int_equal(outcome, OPTIMIZE_DONE);
    assert_int_equal(study_resume(store, cut, NULL, &outcome, &err),
                     FACET_EINPUT);  /* done: nothing to resume */
    struct option_row *a, *b;
    size_t na, nb;
    get_options(store, whole, &a, &na);
    get_options(store, cut, &b, &nb);
    assert_int_equal(na, nb);
    for (size_t k = 0; k < na; k++) {
        assert_int_equal(a[k].number, b[k].number);
        assert_int_equal(a[k].generation, b[k].generation);
        assert_int_equal(a[k].nu, b[k].nu);
        assert_int_equal(a[k].nv, b[k].nv);
        assert_true(a[k].threshold_mm == b[k].threshold_mm);
        assert_memory_equal(&a[k].totals, &b[k].totals, sizeof a[k].totals);
        assert_int_equal(a[k].rank, b[k].rank);
        assert_int_equal(a[k].knee, b[k].knee);
    }
    free(a);
    free(b);
    store_close(store);
}

static void test_resume_exhaustive(void **state)
{
    (void)state;
    check_resume(METHOD_EXHAUSTIVE, PARAM_AUTO);
}

static void test_resume_random(void **state)
{
    (void)state;
    check_resume(METHOD_RANDOM, PARAM_AUTO);
}

static void test_resume_nsga2(void **state)
{
    (void)state;
    check_resume(METHOD_NSGA2, PARAM_AUTO);
}

/* A run made with --uv plane on a surface with vt records it, and is
 * resumed on the plane projection, not on the vt automatic choice would
 * take: its options are those of an uninterrupted plane run, and differ
 * from the vt run's. */
static void test_resume_forced_uv(void **state)
{
    (void)state;
    check_resume(METHOD_EXHAUSTIVE, PARAM_PLANE);
    struct facet_error err;
    struct store *store;
    assert_int_equal(store_open(db_path, &store, &err), FACET_OK);
    struct run_info info;
    assert_int_equal(store_run_get(store, 2, &info, &err), FACET_OK);
    assert_int_equal(info.uv, PARAM_PLANE);
    assert_int_equal(info.uv_method, PARAM_PLANE);
    struct study_request request;
    int64_t automatic = finished_run(store, &request);
    assert_int_equal(store_run_get(store, automatic, &info, &err), FACET_OK);
    assert_int_equal(info.uv, PARAM_AUTO);
    /* The roof at 20 x 20 quads: its facets sag 52 mm, more than a
     * quarter of the space's smallest threshold (2 mm). */
    assert_true(strncmp(info.warnings, "the facets sag ", 15) == 0);
    assert_int_equal(info.uv_method, PARAM_VT);
    struct option_row *a, *b;
    size_t na, nb, differ = 0;
    get_options(store, 2, &a, &na);
    get_options(store, automatic, &b, &nb);
    assert_int_equal(na, nb);
    for (size_t k = 0; k < na; k++)
        differ += a[k].totals.cost != b[k].totals.cost;
    assert_true(differ > 0);
    free(a);
    free(b);
    store_close(store);
}

/* A run left "running" by a process that is gone reads as interrupted. */
static void test_orphan_is_interrupted(void **state)
{
    (void)state;
    struct facet_error err;
    struct store *store;
    assert_int_equal(store_open(fresh_db("orphan"), &store, &err), FACET_OK);
    struct run_info run;
    store_fixture_run(&run);
    assert_int_equal(store_run_create(store, &run, &err), FACET_OK);
    store_close(store);

    /* Still ours: this process is alive. */
    assert_int_equal(store_open(db_path, &store, &err), FACET_OK);
    assert_int_equal(store_run_get(store, run.id, &run, &err), FACET_OK);
    assert_int_equal(run.status, RUN_RUNNING);
    store_close(store);

    sqlite3 *db;
    assert_int_equal(sqlite3_open(db_path, &db), SQLITE_OK);
    assert_int_equal(sqlite3_exec(db, "UPDATE runs SET writer_pid ="
                                  " 2147483646", NULL, NULL, NULL),
                     SQLITE_OK);
    sqlite3_close(db);
    assert_int_equal(store_open(db_path, &store, &err), FACET_OK);
    assert_int_equal(store_run_get(store, run.id, &run, &err), FACET_OK);
    assert_int_equal(run.status, RUN_INTERRUPTED);
    store_close(store);
}

static void write_file(const char *path, const char *bytes, size_t n)
{
    FILE *out = fopen(path, "wb");
    assert_non_null(out);
    assert_int_equal(fwrite(bytes, 1, n, out), n);
    fclose(out);
}

static void expect_refused(const char *path, const char *words)
{
    struct facet_error err;
    struct store *store = NULL;
    assert_int_equal(store_open(path, &store, &err), FACET_EINPUT);
    assert_null(store);
    if (strstr(err.message, words) == NULL)
        fail_msg("message '%s' lacks '%s'", err.message, words);
    assert_null(strchr(err.message, '\n'));
    assert_non_null(strstr(err.message, path));
}

static void sql(const char *path, const char *statements)
{
    sqlite3 *db;
    assert_int_equal(sqlite3_open(path, &db), SQLITE_OK);
    assert_int_equal(sqlite3_exec(db, statements, NULL, NULL, NULL),
                     SQLITE_OK);
    sqlite3_close(db);
}

/* A database whose panel table is gone answers "are the panels stored?"
 * with an error that names the file, not with a "no" that would send the
 * caller off to recompute them; the answer is left at 0. */
static void test_panels_exist_error(void **state)
{
    (void)state;
    struct facet_error err;
    struct store *store;
    assert_int_equal(store_open(fresh_db("panels_exist"), &store, &err),
                     FACET_OK);
    int stored = 1;
    assert_int_equal(store_panels_exist(store, 1, 1, &stored, &err),
                     FACET_OK);
    assert_int_equal(stored, 0);
    /* SQLite itself, over a second connection, removes the table. */
    sql(db_path, "DROP TABLE panel_sets");
    stored = 1;
    facet_error_clear(&err);
    int rc = store_panels_exist(store, 1, 1, &stored, &err);
    assert_true(rc == FACET_EWORK || rc == FACET_EINPUT);
    assert_int_equal(err.code, rc);
    assert_int_equal(stored, 0);
    if (strstr(err.message, "panel_sets") == NULL ||
        strstr(err.message, db_path) == NULL)
        fail_msg("message '%s' names neither table nor file", err.message);
    store_close(store);
}

/* SQLite's own count of the rows a query returns (a second connection). */
static int64_t sql_count(const char *path, const char *query)
{
    int64_t n = 0;
    assert_int_equal(store_fixture_sql_int(path, query, &n), 0);
    return n;
}

static int stop_at_second_question(void *context)
{
    return ++*(int *)context >= 2;
}

/* A stop while a fine grid's panels are written (issue 32 item 7: it
 * waited for the whole write) is heard inside the write; nothing of the
 * new set is stored, and the set stored before stays whole (SQLite's own
 * count, over a second connection). */
static void test_panels_write_stops(void **state)
{
    (void)state;
    struct store *store;
    struct facet_error err;
    assert_int_equal(store_open(fresh_db("panels_stop"), &store, &err),
                     FACET_OK);
    struct study_request request;
    int64_t run = finished_run(store, &request);
    struct run_info info;
    assert_int_equal(store_run_get(store, run, &info, &err), FACET_OK);
    char query[200];
    snprintf(query, sizeof query,
             "SELECT count(*) FROM panels WHERE run = %lld AND option = %lld",
             (long long)run, (long long)info.knee);
    int64_t before = sql_count(db_path, query);
    assert_true(before > 0);

    struct surface surface;
    assert_int_equal(study_open_surface(store, &info, &surface, &err),
                     FACET_OK);
    struct option_params params = request.settings.base;
    params.nu = params.nv = 90;  /* 8,100 panels: two questions apart */
    struct panelization panels;
    struct option_totals totals;
    assert_int_equal(option_evaluate(&surface, &params, NULL, &panels,
                                     &totals, &err), FACET_OK);
    int asked = 0;
    struct facet_stop stop = {stop_at_second_question, &asked};
    assert_int_equal(store_panels_put_stoppable(store, run, info.knee,
                                                &panels, &stop, &err),
                     FACET_ESTOP);
    assert_int_equal(asked, 2);
    assert_int_equal(sql_count(db_path, query), before);
    /* Not stopped, the same write replaces the set whole. */
    assert_int_equal(store_panels_put_stoppable(store, run, info.knee,
                                                &panels, NULL, &err),
                     FACET_OK);
    assert_int_equal(sql_count(db_path, query), 8100);
    panelization_free(&panels);
    surface_close(&surface);
    store_close(store);
}

static void test_refuses_other_files(void **state)
{
    (void)state;
    const char *path = fresh_db("text");
    write_file(path, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", 32);
    expect_refused(path, "not an SQLite database");

    path = fresh_db("foreign");
    sql(path, "CREATE TABLE invoices (id INTEGER, total REAL);");
    expect_refused(path, "another application");

    path = fresh_db("newer");
    struct facet_error err;
    struct store *store;
    assert_int_equal(store_open(path, &store, &err), FACET_OK);
    store_close(store);
    sql(path, "PRAGMA user_version = 99;");
    expect_refused(path, "newer Facet");

    /* A damaged file: a good database with its pages overwritten. */
    path = fresh_db("corrupt");
    assert_int_equal(store_open(path, &store, &err), FACET_OK);
    struct study_request request;
    int64_t run = finished_run(store, &request);
    store_close(store);
    sql(path, "PRAGMA wal_checkpoint(TRUNCATE); PRAGMA journal_mode=DELETE;");
    FILE *file = fopen(path, "r+b");
    assert_non_null(file);
    char junk[4096];
    memset(junk, 0xA5, sizeof junk);
    fseek(file, 4096, SEEK_SET);
    fwrite(junk, 1, sizeof junk, file);
    fseek(file, 3 * 4096, SEEK_SET);
    fwrite(junk, 1, sizeof junk, file);
    fclose(file);
    store = NULL;
    int rc = store_open(path, &store, &err);
    if (rc == FACET_OK) {
        /* The header pages may survive; the damage shows on reading. */
        struct option_row *rows;
        size_t n;
        rc = store_options_get(store, run, &rows, &n, &err);
        store_close(store);
    }
    assert_int_equal(rc, FACET_EINPUT);
    assert_non_null(strstr(err.message, "damaged"));
    assert_null(strchr(err.message, '\n'));
}

/* A store file named name holding one finished run (*run, made from
 * *request), then taken back by the SQL statements (to an older schema):
 * its path. */
static const char *older_file(const char *name, const char *statements,
                              int64_t *run, struct study_request *request)
{
    const char *path = fresh_db(name);
    struct facet_error err;
    struct store *store;
    assert_int_equal(store_open(path, &store, &err), FACET_OK);
    *run = finished_run(store, request);
    store_close(store);
    sql(path, statements);
    return path;
}

/* A file of schema version 1 (no views, no indexes, no runs.uv) is
 * brought up to the current version (8) when opened, and keeps its runs. */
static void test_migrates_older_schema(void **state)
{
    (void)state;
    struct study_request request;
    int64_t run;
    const char *path = older_file("migrate", STORE_FIXTURE_UNDO_V5 "DROP VIEW pareto; DROP VIEW run_summary;"
              "DROP INDEX options_by_rank; DROP INDEX options_by_cost;"
              "DROP INDEX options_by_planarity; DROP INDEX options_by_dp_area;"
              "DROP INDEX options_by_fp_area; DROP INDEX options_by_sp_area;"
              "DROP INDEX options_by_nu; DROP INDEX options_by_nv;"
              "DROP INDEX options_by_threshold;"
              "ALTER TABLE runs DROP COLUMN uv; ALTER TABLE runs DROP COLUMN warnings; ALTER TABLE runs DROP COLUMN store_panels;"
              "PRAGMA user_version = 1;", &run, &request);
    struct facet_error err;
    struct store *store;
    assert_int_equal(store_open(path, &store, &err), FACET_OK);
    struct run_info info;
    assert_int_equal(store_run_get(store, run, &info, &err), FACET_OK);
    assert_int_equal(info.options, 48);
    store_close(store);
    sqlite3 *db;
    assert_int_equal(sqlite3_open(path, &db), SQLITE_OK);
    sqlite3_stmt *s;
    assert_int_equal(sqlite3_prepare_v2(db, "SELECT (SELECT user_version"
                     " FROM pragma_user_version), (SELECT count(*) FROM"
                     " pareto), (SELECT count(*) FROM sqlite_schema WHERE"
                     " type = 'index' AND name LIKE 'options_by_%')",
                     -1, &s, NULL), SQLITE_OK);
    assert_int_equal(sqlite3_step(s), SQLITE_ROW);
    assert_int_equal(sqlite3_column_int(s, 0), store_schema_version());
    assert_int_equal(sqlite3_column_int(s, 1), info.pareto_options);
    assert_int_equal(sqlite3_column_int(s, 2), 14);
    sqlite3_finalize(s);
    sqlite3_close(db);
}

/* A file of version 3 (as the Facet before runs.uv wrote it: the same
 * tables without that column) gets the column, NULL on its old runs,
 * which read back as automatic; a new run in it records its --uv. */
static void test_migrates_v3(void **state)
{
    (void)state;
    struct study_request request;
    int64_t old;
    const char *path = older_file("migrate3", STORE_FIXTURE_UNDO_V5 "ALTER TABLE runs DROP COLUMN uv; ALTER TABLE runs DROP COLUMN warnings; ALTER TABLE runs DROP COLUMN store_panels;"
              " PRAGMA user_version = 3;", &old, &request);
    struct facet_error err;
    struct store *store;
    assert_int_equal(store_open(path, &store, &err), FACET_OK);
    struct run_info info;
    assert_int_equal(store_run_get(store, old, &info, &err), FACET_OK);
    assert_int_equal(info.uv, PARAM_AUTO);
    assert_int_equal(info.uv_method, PARAM_VT);
    assert_int_equal(info.options, 48);
    request_for(&request, METHOD_EXHAUSTIVE);
    request.uv = PARAM_PLANE;
    int64_t run;
    enum optimize_outcome outcome;
    assert_int_equal(study_start(store, &request, NULL, &run, &outcome, &err),
                     FACET_OK);
    store_close(store);
    sqlite3 *db;
    assert_int_equal(sqlite3_open(path, &db), SQLITE_OK);
    sqlite3_stmt *s;
    assert_int_equal(sqlite3_prepare_v2(db, "SELECT (SELECT user_version"
                     " FROM pragma_user_version), (SELECT count(*) FROM"
                     " pragma_table_info('runs') WHERE name = 'uv'),"
                     " (SELECT uv IS NULL FROM runs WHERE id = ?1),"
                     " (SELECT uv FROM runs WHERE id = ?2)", -1, &s, NULL),
                     SQLITE_OK);
    sqlite3_bind_int64(s, 1, old);
    sqlite3_bind_int64(s, 2, run);
    assert_int_equal(sqlite3_step(s), SQLITE_ROW);
    assert_int_equal(sqlite3_column_int(s, 0), store_schema_version());
    assert_int_equal(sqlite3_column_int(s, 1), 1);
    assert_int_equal(sqlite3_column_int(s, 2), 1);
    assert_string_equal((const char *)sqlite3_column_text(s, 3), "plane");
    sqlite3_finalize(s);
    sqlite3_close(db);
}


/* A file of version 5 (before shards) is migrated: its old run is no
 * shard and no merge (the new columns NULL, read as 0); a new run of a
 * shard records its I/N, and a merge of 2 of 3 shards reads incomplete. */
static void test_migrates_v5_shards(void **state)
{
    (void)state;
    struct study_request request;
    int64_t old;
    const char *path = older_file("migrate5", STORE_FIXTURE_UNDO_V7
                                  STORE_FIXTURE_UNDO_V6_SHARDS
                                  " PRAGMA user_version = 5;", &old,
                                  &request);
    struct facet_error err;
    struct store *store;
    assert_int_equal(store_open(path, &store, &err), FACET_OK);
    struct run_info info;
    assert_int_equal(store_run_get(store, old, &info, &err), FACET_OK);
    assert_int_equal(info.shard_index, 0);
    assert_int_equal(info.shard_count, 0);
    assert_int_equal(info.shards_merged, 0);
    assert_false(store_run_incomplete(&info));
    request_for(&request, METHOD_EXHAUSTIVE);
    request.settings.shard = (struct shard){2, 3};
    int64_t run;
    enum optimize_outcome outcome;
    assert_int_equal(study_start(store, &request, NULL, &run, &outcome, &err),
                     FACET_OK);
    assert_int_equal(store_run_get(store, run, &info, &err), FACET_OK);
    assert_int_equal(info.shard_index, 2);
    assert_int_equal(info.shard_count, 3);
    assert_false(store_run_incomplete(&info));
    info.shard_index = 0;
    info.shards_merged = 2;
    assert_int_equal(store_run_set_shard(store, &info, &err), FACET_OK);
    assert_int_equal(store_run_get(store, run, &info, &err), FACET_OK);
    assert_true(store_run_incomplete(&info));
    store_close(store);
}

/* A fresh file (db_path) holding the finished test study; its id. */
static int64_t finished_run_closed(const char *name)
{
    struct facet_error err;
    struct store *store;
    assert_int_equal(store_open(fresh_db(name), &store, &err), FACET_OK);
    struct study_request request;
    int64_t run = finished_run(store, &request);
    store_close(store);
    return run;
}

/* Each name a runs column may hold, written by SQLite itself (not by the
 * store), reads back as its enum; the expected values are written here by
 * hand, not taken from the name functions. */
static void test_run_settings_by_name(void **state)
{
    (void)state;
    struct facet_error err;
    struct store *store;
    int64_t run = finished_run_closed("settings_by_name");
    const char *path = db_path;
    static const struct {
        const char *column, *text;
        enum run_setting setting;
        int value;
    } named[] = {
        {"units", "m", RUN_SETTING_UNITS, UNITS_M},
        {"units", "cm", RUN_SETTING_UNITS, UNITS_CM},
        {"units", "mm", RUN_SETTING_UNITS, UNITS_MM},
        {"units", "in", RUN_SETTING_UNITS, UNITS_IN},
        {"units", "ft", RUN_SETTING_UNITS, UNITS_FT},
        {"method", "exhaustive", RUN_SETTING_METHOD, METHOD_EXHAUSTIVE},
        {"method", "random", RUN_SETTING_METHOD, METHOD_RANDOM},
        {"method", "nsga2", RUN_SETTING_METHOD, METHOD_NSGA2},
        {"per_panel", "extremes", RUN_SETTING_PER_PANEL, PANEL_EXTREMES},
        {"per_panel", "mean", RUN_SETTING_PER_PANEL, PANEL_MEAN},
        {"uv_method", "vt", RUN_SETTING_UV_METHOD, PARAM_VT},
        {"uv_method", "grid", RUN_SETTING_UV_METHOD, PARAM_GRID},
        {"uv_method", "plane", RUN_SETTING_UV_METHOD, PARAM_PLANE},
        {"uv_method", "harmonic", RUN_SETTING_UV_METHOD, PARAM_HARMONIC},
        {"uv_method", "", RUN_SETTING_UV_METHOD, PARAM_AUTO},
        {"uv", "vt", RUN_SETTING_UV, PARAM_VT},
        {"uv", "grid", RUN_SETTING_UV, PARAM_GRID},
        {"uv", "plane", RUN_SETTING_UV, PARAM_PLANE},
        {"uv", "harmonic", RUN_SETTING_UV, PARAM_HARMONIC},
        {"store_panels", "front", RUN_SETTING_STORE_PANELS, KEEP_FRONT},
        {"store_panels", "knee", RUN_SETTING_STORE_PANELS, KEEP_KNEE},
        {"store_panels", "none", RUN_SETTING_STORE_PANELS, KEEP_NONE},
    };
    for (size_t k = 0; k < sizeof named / sizeof *named; k++) {
        char statement[256];
        snprintf(statement, sizeof statement,
                 "UPDATE runs SET %s = '%s' WHERE id = %lld",
                 named[k].column, named[k].text, (long long)run);
        sql(path, statement);
        assert_int_equal(store_open_read(path, &store, &err), FACET_OK);
        struct run_info info;
        assert_int_equal(store_run_get(store, run, &info, &err), FACET_OK);
        const int got[RUN_SETTINGS] = {
            [RUN_SETTING_UNITS] = (int)info.units,
            [RUN_SETTING_METHOD] = (int)info.method,
            [RUN_SETTING_PER_PANEL] = (int)info.per_panel,
            [RUN_SETTING_UV_METHOD] = (int)info.uv_method,
            [RUN_SETTING_UV] = (int)info.uv,
            [RUN_SETTING_STORE_PANELS] = (int)info.store_panels};
        if (got[named[k].setting] != named[k].value)
            fail_msg("%s '%s' read as %d", named[k].column, named[k].text,
                     got[named[k].setting]);
        assert_int_equal(store_run_setting_check(&info, named[k].setting,
                                                 &err), FACET_OK);
        assert_string_equal(store_run_setting_text(&info, named[k].setting),
                            named[k].text);
        store_close(store);
    }
    sql(path, "UPDATE runs SET uv = NULL");
    assert_int_equal(store_open_read(path, &store, &err), FACET_OK);
    struct run_info info;
    assert_int_equal(store_run_get(store, run, &info, &err), FACET_OK);
    assert_int_equal(info.uv, PARAM_AUTO);
    store_close(store);
}

/* A setting column that names nothing this Facet knows is not guessed:
 * (store_panels has a CHECK: a file holding another name is damaged)
 * the run still lists (with the file's text), but resuming it or
 * evaluating its options is refused with one line naming the run, the
 * column and the value. */
static void test_run_setting_unknown(void **state)
{
    (void)state;
    static const struct {
        const char *column, *text;
    } bad[] = {
        {"units", "yd"}, {"method", "simplex"},
        {"per_panel", "median"}, {"uv_method", "conformal"},
    };
    for (size_t k = 0; k < sizeof bad / sizeof *bad; k++) {
        struct facet_error err;
        struct store *store;
        int64_t run = finished_run_closed("setting_unknown");
        const char *path = db_path;
        char statement[256];
        snprintf(statement, sizeof statement,
                 "UPDATE runs SET %s = '%s', status = 'interrupted'"
                 " WHERE id = %lld", bad[k].column, bad[k].text,
                 (long long)run);
        sql(path, statement);
        char words[3][64];
        snprintf(words[0], sizeof words[0], "run %lld", (long long)run);
        snprintf(words[1], sizeof words[1], "runs.%s", bad[k].column);
        snprintf(words[2], sizeof words[2], "'%s'", bad[k].text);

        assert_int_equal(store_open(path, &store, &err), FACET_OK);
        struct run_info *runs;
        size_t n;
        assert_int_equal(store_run_list(store, &runs, &n, &err), FACET_OK);
        assert_int_equal(n, 1);
        int shown = 0;
        for (int s = 0; s < RUN_SETTINGS; s++)
            shown += strcmp(store_run_setting_text(&runs[0], s),
                            bad[k].text) == 0;
        assert_int_equal(shown, 1);
        free(runs);

        enum optimize_outcome outcome;
        assert_int_equal(study_resume(store, run, NULL, &outcome, &err),
                         FACET_EINPUT);
        for (int w = 0; w < 3; w++)
            if (strstr(err.message, words[w]) == NULL)
                fail_msg("'%s' lacks '%s'", err.message, words[w]);
        assert_null(strchr(err.message, '\n'));
        struct run_info info;
        assert_int_equal(store_run_get(store, run, &info, &err), FACET_OK);
        assert_int_equal(info.status, RUN_INTERRUPTED);  /* not claimed */

        struct study_option option;
        int rc = study_option_load(store, run, 1, 1, &option, &err);
        study_option_free(&option);
        assert_int_equal(rc, FACET_EINPUT);
        for (int w = 0; w < 3; w++)
            if (strstr(err.message, words[w]) == NULL)
                fail_msg("'%s' lacks '%s'", err.message, words[w]);
        store_close(store);
    }
}

/* A file of version 4 (the Facet before the cost model: the same tables
 * without version 5's columns) is migrated: its old run reads as the
 * paper's model (prices 0, tolerance the threshold), its old options'
 * new columns are NULL (never computed: joint length reads as NaN, not
 * 0), and a new run in it stores its cost terms, its options' moulds and
 * joints, and its panels' mould families. */
static void test_migrates_v4(void **state)
{
    (void)state;
    struct study_request request;
    int64_t old;
    const char *path = older_file("migrate4", STORE_FIXTURE_UNDO_V5 " PRAGMA user_version = 4;",
                                  &old, &request);
    struct facet_error err;
    struct store *store;
    assert_int_equal(store_open(path, &store, &err), FACET_OK);
    struct run_info info;
    assert_int_equal(store_run_get(store, old, &info, &err), FACET_OK);
    assert_true(info.panel_cost == 0 && info.joint_cost == 0 &&
                info.mould_cost[TYPE_SP] == 0 &&
                info.mould_cost[TYPE_DP] == 0);
    assert_true(isnan(info.mould_tol_mm));
    assert_int_equal(info.mould_mirror, 0);
    struct option_row *rows;
    size_t n;
    assert_int_equal(store_options_get(store, old, &rows, &n, &err),
                     FACET_OK);
    assert_int_equal(n, 48);
    assert_true(isnan(rows[0].totals.joint_length));
    assert_true(isnan(rows[0].totals.mould_cost));
    free(rows);
    request_for(&request, METHOD_EXHAUSTIVE);
    request.settings.base.classify.panel_cost = 100;
    request.settings.base.classify.joint_cost = 10;
    request.settings.base.classify.mould_cost[TYPE_SP] = 1000;
    request.settings.base.classify.mould_cost[TYPE_DP] = 5000;
    request.settings.base.mould_tol_given = 1;
    request.settings.base.mould_tol = 0.004;
    int64_t run;
    enum optimize_outcome outcome;
    assert_int_equal(study_start(store, &request, NULL, &run, &outcome, &err),
                     FACET_OK);
    assert_int_equal(store_run_get(store, run, &info, &err), FACET_OK);
    assert_true(info.panel_cost == 100 && info.joint_cost == 10 &&
                info.mould_cost[TYPE_SP] == 1000 &&
                info.mould_cost[TYPE_DP] == 5000);
    assert_float_equal(info.mould_tol_mm, 4, 1e-12);
    store_close(store);
    /* SQLite itself: the sum of the terms is the cost of every new option,
     * the old ones are NULL, and the new run's panels carry families. */
    sqlite3 *db;
    assert_int_equal(sqlite3_open(path, &db), SQLITE_OK);
    sqlite3_stmt *s;
    assert_int_equal(sqlite3_prepare_v2(db, "SELECT (SELECT user_version"
                     " FROM pragma_user_version),"
                     " (SELECT count(*) FROM options WHERE run = ?1 AND"
                     "  moulds IS NULL AND joint_length IS NULL),"
                     " (SELECT count(*) FROM options WHERE run = ?2 AND"
                     "  abs(fp_cost + sp_cost + dp_cost + panel_cost +"
                     "  joint_cost + mould_cost - cost) <= 1e-9 * cost AND"
                     "  panel_cost = 100 * panels AND"
                     "  abs(joint_cost - 10 * joint_length) <= 1e-9 * joint_cost"
                     "  AND mould_cost = 1000 * sp_moulds + 5000 * dp_moulds"
                     "  AND moulds = sp_moulds + dp_moulds AND joint_length > 0),"
                     " (SELECT count(*) FROM options WHERE run = ?2),"
                     " (SELECT count(*) FROM panels WHERE run = ?2 AND"
                     "  (type = 'FP') = (mould_family IS NULL))," 
                     " (SELECT count(*) FROM panels WHERE run = ?2)",
                     -1, &s, NULL), SQLITE_OK);
    sqlite3_bind_int64(s, 1, old);
    sqlite3_bind_int64(s, 2, run);
    assert_int_equal(sqlite3_step(s), SQLITE_ROW);
    assert_int_equal(sqlite3_column_int(s, 0), store_schema_version());
    assert_int_equal(sqlite3_column_int(s, 1), 48);
    assert_int_equal(sqlite3_column_int(s, 2), sqlite3_column_int(s, 3));
    assert_true(sqlite3_column_int(s, 3) > 0);
    assert_int_equal(sqlite3_column_int(s, 4), sqlite3_column_int(s, 5));
    assert_true(sqlite3_column_int(s, 5) > 0);
    sqlite3_finalize(s);
    sqlite3_close(db);
}

/* A file of version 6 (the Facet before panels as built: the same tables
 * without version 7's columns) is migrated: its old run reads as typed
 * by class alone, without gap or kink limits, its old options' gaps,
 * kinks and misfits are NULL (never measured); a new run in it with a
 * kink limit stores the limit, and its options and panels agree with
 * SQLite's own reading of them: feasible exactly when no joint is over the
 * limit (and the size limit is met), kinks_over > 0 exactly when max_kink
 * is over it, each stored option's max_gap the largest of its panels' worst gaps
 * and its misfits the panels with a reason. */
static void test_migrates_v6(void **state)
{
    (void)state;
    struct study_request request;
    int64_t old;
    const char *path = older_file("migrate6", STORE_FIXTURE_UNDO_V7
                                  " PRAGMA user_version = 6;", &old,
                                  &request);
    struct facet_error err;
    struct store *store;
    assert_int_equal(store_open(path, &store, &err), FACET_OK);
    struct run_info info;
    assert_int_equal(store_run_get(store, old, &info, &err), FACET_OK);
    assert_int_equal(info.sp_fit, 0);
    assert_true(isnan(info.max_gap_mm) && isnan(info.max_kink_deg));
    request_for(&request, METHOD_EXHAUSTIVE);
    /* The roof at 20 x 20 quads: its largest kinks (4.8 degrees) are
     * where the flat part meets the vault, which starts level (truth 0). */
    request.settings.base.classify.max_kink = 3 * M_PI / 180;
    int64_t run;
    enum optimize_outcome outcome;
    assert_int_equal(study_start(store, &request, NULL, &run, &outcome, &err),
                     FACET_OK);
    assert_int_equal(store_run_get(store, run, &info, &err), FACET_OK);
    assert_int_equal(info.sp_fit, 1);
    assert_float_equal(info.max_kink_deg, 3, 1e-12);
    assert_true(isnan(info.max_gap_mm));
    store_close(store);
    sqlite3 *db;
    assert_int_equal(sqlite3_open(path, &db), SQLITE_OK);
    sqlite3_stmt *s;
    assert_int_equal(sqlite3_prepare_v2(db, "SELECT (SELECT user_version"
        " FROM pragma_user_version),"
        " (SELECT count(*) FROM options WHERE run = ?1 AND max_gap IS NULL"
        "  AND max_kink IS NULL AND sp_misfits IS NULL AND gaps_over IS NULL),"
        " (SELECT count(*) FROM options WHERE run = ?2),"
        " (SELECT count(*) FROM options WHERE run = ?2 AND"
        "  feasible = (max_kink <= 3 AND max_panel_area <= 1000) AND"
        "  (kinks_over > 0) = (max_kink > 3) AND gaps_over = 0),"
        " (SELECT count(*) FROM options WHERE run = ?2 AND feasible),"
        " (SELECT count(*) FROM options WHERE run = ?2 AND max_kink > 3),"
        " (SELECT count(*) FROM options o WHERE run = ?2 AND EXISTS"
        "  (SELECT 1 FROM panels p WHERE p.run = o.run AND"
        "   p.option = o.number) AND o.max_gap = (SELECT max(worst_gap)"
        "   FROM panels p WHERE p.run = o.run AND p.option = o.number) AND"
        "  o.sp_misfits = (SELECT count(*) FROM panels p WHERE"
        "   p.run = o.run AND p.option = o.number AND misfit_reason IS NOT"
        "   NULL)),"
        " (SELECT count(DISTINCT option) FROM panels WHERE run = ?2),"
        " (SELECT count(*) FROM panels WHERE run = ?2 AND built_type IS NULL)",
        -1, &s, NULL), SQLITE_OK);
    sqlite3_bind_int64(s, 1, old);
    sqlite3_bind_int64(s, 2, run);
    assert_int_equal(sqlite3_step(s), SQLITE_ROW);
    assert_int_equal(sqlite3_column_int(s, 0), store_schema_version());
    assert_int_equal(sqlite3_column_int(s, 1), 48);
    int n = sqlite3_column_int(s, 2);
    assert_true(n > 0);
    assert_int_equal(sqlite3_column_int(s, 3), n);
    /* Both kinds are there: the limit cuts the space. */
    printf("v6 migrated: %d options, %d feasible, %d over 3 degrees\n", n,
           sqlite3_column_int(s, 4), sqlite3_column_int(s, 5));
    assert_true(sqlite3_column_int(s, 5) > 0);
    assert_true(sqlite3_column_int(s, 5) < n);
    assert_int_equal(sqlite3_column_int(s, 6), sqlite3_column_int(s, 7));
    assert_true(sqlite3_column_int(s, 7) > 0);
    assert_int_equal(sqlite3_column_int(s, 8), 0);
    sqlite3_finalize(s);
    sqlite3_close(db);
}

/* The file's user_version, read by SQLite itself. */
static int user_version(const char *path)
{
    sqlite3 *db;
    sqlite3_stmt *s;
    assert_int_equal(sqlite3_open(path, &db), SQLITE_OK);
    assert_int_equal(sqlite3_prepare_v2(db, "PRAGMA user_version", -1, &s,
                                        NULL), SQLITE_OK);
    assert_int_equal(sqlite3_step(s), SQLITE_ROW);
    int version = sqlite3_column_int(s, 0);
    sqlite3_finalize(s);
    sqlite3_close(db);
    return version;
}

/* No open that reads migrates an older file (issue 28, item 6): each is
 * refused in one line about FACET_SETTING_MIGRATE (the CLI names facet
 * migrate), the file stays at its version (SQLite says), and
 * store_migrate, asked for, migrates it once. */
static void test_readers_never_migrate(void **state)
{
    (void)state;
    struct study_request request;
    int64_t run;
    const char *path = older_file("readers", STORE_FIXTURE_UNDO_V5
                                  "PRAGMA user_version = 4;", &run,
                                  &request);
    int (*const opens[])(const char *, struct store **,
                         struct facet_error *) = {
        store_open_read, store_open_existing, store_open_current};
    for (size_t k = 0; k < sizeof opens / sizeof opens[0]; k++) {
        struct facet_error err;
        struct store *store = NULL;
        assert_int_equal(opens[k](path, &store, &err), FACET_EINPUT);
        assert_null(store);
        assert_int_equal(err.setting, FACET_SETTING_MIGRATE);
        char words[64];
        snprintf(words, sizeof words, "older Facet (schema 4; this one "
                 "reads %d)", store_schema_version());
        if (strstr(err.message, words) == NULL ||
            strstr(err.message, path) == NULL)
            fail_msg("open %zu: '%s'", k, err.message);
        assert_null(strchr(err.message, '\n'));
        assert_int_equal(user_version(path), 4);
    }
    struct facet_error err;
    int from = 0;
    assert_int_equal(store_migrate(path, &from, &err), FACET_OK);
    assert_int_equal(from, 4);
    assert_int_equal(user_version(path), store_schema_version());
    assert_int_equal(store_migrate(path, &from, &err), FACET_OK);
    assert_int_equal(from, store_schema_version());
    struct store *store;
    assert_int_equal(store_open_read(path, &store, &err), FACET_OK);
    struct run_info info;
    assert_int_equal(store_run_get(store, run, &info, &err), FACET_OK);
    assert_int_equal(info.options, 48);
    store_close(store);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_run_roundtrip),
        cmocka_unit_test(test_run_settings_by_name),
        cmocka_unit_test(test_run_setting_unknown),
        cmocka_unit_test(test_queries),
        cmocka_unit_test(test_resume_exhaustive),
        cmocka_unit_test(test_resume_random),
        cmocka_unit_test(test_resume_nsga2),
        cmocka_unit_test(test_orphan_is_interrupted),
        cmocka_unit_test(test_refuses_other_files),
        cmocka_unit_test(test_panels_exist_error),
        cmocka_unit_test(test_panels_write_stops),
        cmocka_unit_test(test_migrates_older_schema),
        cmocka_unit_test(test_migrates_v3),
        cmocka_unit_test(test_migrates_v4),
        cmocka_unit_test(test_migrates_v5_shards),
        cmocka_unit_test(test_migrates_v6),
        cmocka_unit_test(test_resume_forced_uv),
        cmocka_unit_test(test_readers_never_migrate),
    };
    int failed = cmocka_run_group_tests(tests, setup, teardown);
    const char *names[] = {"roundtrip", "queries", "resume", "orphan",
                           "text", "foreign", "newer", "corrupt",
                           "migrate", "migrate3", "migrate4", "readers",
                           "settings_by_name", "setting_unknown"};
    for (size_t k = 0; k < sizeof names / sizeof *names; k++) {
        fresh_db(names[k]);
        unlink(db_path);
    }
    return failed;
}
