/*
 * bench_optimize.c: the paper's whole design space written to SQLite.
 *
 *   bench_optimize [RES] [ROWS]
 *
 * The example roof at RES x RES quads (default 224: 100,352 triangles),
 * u 20:40 x v 35:50 at 3 mm (336 grids), exhaustive, every option
 * committed to a fresh store file through the same study that `facet
 * optimize` runs. Reports:
 *   - the whole run, reading and preparing the surface included (study_start
 *     does both), options/s, and as a ratio to its floor, a bare pass per
 *     option (issue 18: at most 3x); the preparation alone;
 *   - the split: the lattice of the space's lines (built once per run;
 *     issue 18: at most 60 MB),
 *     the 336 evaluations alone on every core, and storage alone (the
 *     same rows put again into a fresh file), rows/s;
 *   - evaluation on one thread, the baseline for the parallel speed-up;
 *   - the stages of the evaluation on one thread, medians of 3 in CPU
 *     time: panels and classes alone; with the joint length and mould
 *     families (issue 15's target: at most 2x the first); the whole
 *     evaluation, panels as built with their SP fits, gaps and kinks
 *     (issue 16's target: at most 1.5x the second);
 *   - per option, the evaluation as a ratio to a bare pass over the
 *     triangles (the machine-independent figure);
 *   - the same evaluations with each grid on its own (no lattice), the
 *     baseline the lattice is measured against;
 *   - bulk storage: ROWS options (default 1,000,000) in batches of 1,000
 *     into a file that ends with its indexes (issue 18: at least 50,000
 *     rows/s), against the bare floor measured here: the same rows in one
 *     transaction into the options table without its indexes by metric;
 *     and the old path, indexes kept while storing, on 50,000 rows; the
 *     file's indexes at the end counted in SQLite's sqlite_schema.
 */
#include <sqlite3.h>
#include <string.h>

#include "bench_common.h"
#include "tests/support/evaluation_stages.h"
#include "tests/support/store_fixture.h"
#include "core/base/parallel.h"
#include "study/study.h"

static void die(const struct facet_error *err)
{
    fprintf(stderr, "bench_optimize: %s\n", err->message);
    exit(1);
}

/* How bulk_store writes: the bare floor (the indexes by metric dropped,
 * every row in one transaction, never built), a run of many options as a
 * study stores it (dropped, batches, built at the end), or the old path
 * (kept while storing). */
enum bulk_way { BULK_BARE, BULK_DEFER, BULK_KEEP };

/* What bulk_store took, in seconds: wall time, and this thread's CPU
 * time (the machine is shared: other work's turns count in the wall). */
struct bulk_time {
    double wall, cpu;
};

/* Stores rows[0..n) as a new run like info into a fresh file at db, in
 * batches of batch (0: one), the way way says; the time it took, the
 * indexes' build included and the file closed. */
static struct bulk_time bulk_store(const char *db,
                                   const struct option_row *rows, long n,
                                   long batch, enum bulk_way way,
                                   const struct run_info *info)
{
    struct facet_error err;
    struct store *store;
    struct run_info run = *info;
    store_fixture_remove(db);
    if (store_open(db, &store, &err) != FACET_OK ||
        store_run_create(store, &run, &err) != FACET_OK)
        die(&err);
    double start = bench_now(), start_cpu = bench_cpu_now();
    int deferred = 0;
    if (way != BULK_KEEP &&
        (store_indexes_defer(store, n, &deferred, &err) != FACET_OK ||
         !deferred)) {
        fprintf(stderr, "bench_optimize: the indexes were not dropped\n");
        exit(1);
    }
    long step = batch > 0 ? batch : n;
    for (long k = 0; k < n; k += step)
        if (store_options_put(store, run.id, rows + k,
                              (size_t)(n - k < step ? n - k : step),
                              &err) != FACET_OK)
            die(&err);
    if (way == BULK_DEFER &&
        store_indexes_build(store, run.id, NULL, &err) != FACET_OK)
        die(&err);
    store_close(store);
    return (struct bulk_time){bench_now() - start,
                              bench_cpu_now() - start_cpu};
}

/* How many indexes the options table of the file at db has, by SQLite's
 * own schema table, into *have, and how many it should (rank's and those
 * by metric) into *want. */
static void file_indexes(const char *db, int *have, int *want)
{
    sqlite3 *handle;
    sqlite3_stmt *stmt;
    *have = -1;
    if (sqlite3_open_v2(db, &handle, SQLITE_OPEN_READONLY, NULL) ==
            SQLITE_OK &&
        sqlite3_prepare_v2(handle, "SELECT count(*) FROM sqlite_schema"
                           " WHERE type = 'index' AND tbl_name = 'options'"
                           " AND sql IS NOT NULL", -1, &stmt,
                           NULL) == SQLITE_OK) {
        if (sqlite3_step(stmt) == SQLITE_ROW)
            *have = sqlite3_column_int(stmt, 0);
        sqlite3_finalize(stmt);
    }
    sqlite3_close(handle);
    *want = 1;  /* options_by_rank */
    while (store_metric_index_name((size_t)*want - 1) != NULL)
        (*want)++;
}

int main(int argc, char **argv)
{
    int res = argc > 1 ? atoi(argv[1]) : 224;
    long bulk = argc > 2 ? atol(argv[2]) : 1000000;
    int jobs = parallel_cpus(PARALLEL_MAX);
    struct facet_error err;
    char obj[] = "/tmp/facet_bench_optimize.obj";
    char db[] = "/tmp/facet_bench_optimize.db";
    struct surface surface;
    bench_roof(res, obj, &surface);
    double bare = bench_bare_best(&surface.mesh, 50);

    struct study_request request;
    memset(&request, 0, sizeof request);
    request.surface_path = obj;
    request.mesh = (struct mesh_options){UNITS_M, NULL, NULL};
    request.name = "bench";
    struct optimize_settings *s = &request.settings;
    classify_defaults(&s->base.classify);
    s->base.mode = PANEL_EXTREMES;
    s->base.classify.sp_as_fp = 1;
    s->method = METHOD_EXHAUSTIVE;
    s->space = (struct design_space){20, 40, 35, 50, 3, 3, 0};
    s->seed = 1;
    s->jobs = jobs;
    if (objectives_parse("cost,planarity,dp_area", "objectives", s->objectives,
                         &s->nobjectives, &err) != FACET_OK)
        die(&err);

    /* The whole run, as facet optimize does it: study_start reads and
     * prepares the surface (timed apart below as well: it is done once
     * per surface, whatever the space). */
    store_fixture_remove(db);
    struct store *store;
    if (store_open(db, &store, &err) != FACET_OK)
        die(&err);
    double start = bench_now();
    int64_t run;
    enum optimize_outcome outcome;
    if (study_start(store, &request, NULL, &run, &outcome, &err) != FACET_OK)
        die(&err);
    double whole = bench_now() - start;
    struct run_info info;
    if (store_run_get(store, run, &info, &err) != FACET_OK)
        die(&err);
    struct option_row *rows;
    size_t n;
    if (store_options_get(store, run, &rows, &n, &err) != FACET_OK)
        die(&err);
    store_close(store);

    double prepare_start = bench_now();
    struct surface again;
    struct mesh_options mesh = {UNITS_M, NULL, NULL};
    if (surface_open(obj, &mesh, &again, &err) != FACET_OK ||
        surface_prepare(&again, 0, PARAM_AUTO, &err) != FACET_OK)
        die(&err);
    double prepare = bench_now() - prepare_start;
    surface_close(&again);

    /* Evaluation alone, on every core and on one. */
    struct design_point *points = malloc(n * sizeof *points);
    struct option_totals *totals = malloc(n * sizeof *totals);
    for (size_t k = 0; k < n; k++)
        points[k] = (struct design_point){rows[k].nu, rows[k].nv,
                                          rows[k].threshold_mm};
    /* The lattice every grid of the space is taken from, as the run
     * builds it, then the grids from it, and each grid on its own (the
     * way without a lattice) for comparison. */
    start = bench_now();
    struct panel_lattice *lattice;
    if (optimize_lattice(&surface, s, &lattice, &err) != FACET_OK)
        die(&err);
    if (lattice == NULL) {
        fprintf(stderr, "bench_optimize: no lattice for the paper's space\n");
        return 1;
    }
    double lattice_time = bench_now() - start;
    double lattice_mb = (double)panel_lattice_bytes(lattice) / 1e6;
    start = bench_now();
    if (optimize_evaluate(&surface, lattice, &s->base, points, n, jobs,
                          totals, &err) != FACET_OK)
        die(&err);
    double evaluate_all = bench_now() - start;
    start = bench_now();
    if (optimize_evaluate(&surface, lattice, &s->base, points, n, 1, totals,
                          &err) != FACET_OK)
        die(&err);
    double evaluate_one = bench_now() - start;
    /* What each stage of the evaluation costs (evaluation_stages.h), all
     * on this one thread, taken in turns: panels and classes alone (the
     * paper's evaluation), then with the joint length (the lines measured
     * once, as a run does) and the mould families (issue 15), then the
     * whole evaluation, panels as built with their SP fits, gaps and
     * kinks too (issue 16). Medians of COST_RUNS each, in the thread's
     * CPU time (on a machine shared with other work the wall time counts
     * their turns too) and in wall time. */
    enum { COST_RUNS = 3 };
    double stage_cpu[3][COST_RUNS], stage_wall[3][COST_RUNS];
    for (int rep = 0; rep < COST_RUNS; rep++) {
        for (int stage = 0; stage < 3; stage++) {
            start = bench_now();
            double start_cpu = bench_cpu_now();
            if (stage == 2) {
                if (optimize_evaluate(&surface, lattice, &s->base, points, n,
                                      1, totals, &err) != FACET_OK)
                    die(&err);
            } else {
                struct joint_lines lines;
                memset(&lines, 0, sizeof lines);
                if (stage == STAGE_MOULDS &&
                    optimize_joint_lines(&surface, &s->space, 1, &lines,
                                         &err) != FACET_OK)
                    die(&err);
                for (size_t k = 0; k < n; k++) {
                    struct option_totals staged;
                    struct option_params params = option_params_at(
                        &s->base, points[k].nu, points[k].nv,
                        points[k].threshold_mm);
                    if (evaluation_stage_run(&surface, lattice,
                                             stage == STAGE_MOULDS ? &lines
                                                                   : NULL,
                                             &params,
                                             (enum evaluation_stage)stage,
                                             &staged, &err) != FACET_OK)
                        die(&err);
                }
                joint_lines_free(&lines);
            }
            stage_cpu[stage][rep] = bench_cpu_now() - start_cpu;
            stage_wall[stage][rep] = bench_now() - start;
        }
    }
    double cpu[3], wall[3];
    for (int stage = 0; stage < 3; stage++) {
        cpu[stage] = bench_median(stage_cpu[stage], COST_RUNS);
        wall[stage] = bench_median(stage_wall[stage], COST_RUNS);
    }
    panel_lattice_free(lattice);
    start = bench_now();
    if (optimize_evaluate(&surface, NULL, &s->base, points, n, jobs, totals,
                          &err) != FACET_OK)
        die(&err);
    double alone_all = bench_now() - start;
    start = bench_now();
    if (optimize_evaluate(&surface, NULL, &s->base, points, n, 1, totals,
                          &err) != FACET_OK)
        die(&err);
    double alone_one = bench_now() - start;

    /* Storage alone: the same rows into a fresh file, one batch per 16
     * options as the run commits them. */
    store_fixture_remove(db);
    if (store_open(db, &store, &err) != FACET_OK ||
        store_run_create(store, &info, &err) != FACET_OK)
        die(&err);
    start = bench_now();
    for (size_t k = 0; k < n; k += 16)
        if (store_options_put(store, info.id, rows + k,
                              n - k < 16 ? n - k : 16, &err) != FACET_OK)
            die(&err);
    double storage = bench_now() - start;

    store_close(store);

    /* Bulk: a million options (the run's rows again and again, numbered
     * on) in batches of a thousand, into a file that ends with all its
     * indexes, against the bare floor: the same rows in one transaction
     * into a table without its indexes by metric, and the old path
     * (indexes kept while storing) on fewer rows. */
    struct option_row *many = malloc((size_t)bulk * sizeof *many);
    if (many == NULL) {
        fprintf(stderr, "bench_optimize: out of memory\n");
        return 1;
    }
    for (long k = 0; k < bulk; k++) {
        many[k] = rows[(size_t)k % n];
        many[k].number = (int64_t)n + k + 1;
    }
    struct bulk_time bare_time = bulk_store(db, many, bulk, 0, BULK_BARE,
                                            &info);
    struct bulk_time bulk_time = bulk_store(db, many, bulk, 1000,
                                            BULK_DEFER, &info);
    int indexes = 0, expected = 0;
    file_indexes(db, &indexes, &expected);
    long kept_rows = bulk < 50000 ? bulk : 50000;
    struct bulk_time kept_time = bulk_store(db, many, kept_rows, 1000,
                                            BULK_KEEP, &info);
    free(many);
    store_fixture_remove(db);
    unlink(obj);

    double load[1] = {-1};
    getloadavg(load, 1);
    printf("surface: roof, %zu triangles; space u 20:40 x v 35:50 at 3 mm "
           "= %zu options; %d threads\n", surface.mesh.ntriangles, n, jobs);
    printf("whole run into SQLite: %.3f s = %.0f options/s (target: under "
           "1 s: %s); surface preparation, once per surface: %.3f s\n",
           whole, (double)n / whole, whole < 1 ? "met" : "NOT met",
           prepare);
    printf("  paper space into SQLite (issue 18): the run, reading and "
           "preparing the surface included, %.3f s = %.1fx its floor of %zu "
           "bare passes (%.3f s) (target: at most 3x: %s)\n", whole,
           whole / ((double)n * bare), n, (double)n * bare,
           whole <= 3 * (double)n * bare ? "met" : "not met");
    printf("  lattice of the space's lines, once per run: %.3f s, %.0f MB "
           "(target, issue 18: at most 60 MB: %s)\n", lattice_time,
           lattice_mb, lattice_mb <= 60 ? "met" : "not met");
    printf("  evaluation alone: %.3f s on %d threads (%.0f options/s), "
           "%.3f s on 1 thread: %.2fx speed-up\n", evaluate_all, jobs,
           (double)n / evaluate_all, evaluate_one,
           evaluate_one / evaluate_all);
    printf("  stages of the evaluation on 1 thread, CPU (wall), medians of "
           "%d, load average %.2f: panels and classes %.3f s (%.3f s); with "
           "joint length and moulds %.3f s (%.3f s); as built, with SP fits, "
           "gaps and kinks, the whole evaluation %.3f s (%.3f s)\n",
           COST_RUNS, load[0], cpu[0], wall[0], cpu[1], wall[1], cpu[2],
           wall[2]);
    printf("  moulds and joint length (issue 15): %.2fx panels and classes "
           "alone (target: at most 2x: %s)\n", cpu[1] / cpu[0],
           cpu[1] <= 2 * cpu[0] ? "met" : "not met");
    printf("  panels as built: SP fits, gaps and kinks (issue 16): %.2fx the "
           "evaluation without them (target: at most 1.5x: %s); the whole "
           "evaluation %.2fx panels and classes alone\n", cpu[2] / cpu[1],
           cpu[2] <= 1.5 * cpu[1] ? "met" : "not met", cpu[2] / cpu[0]);
    printf("  storage alone: %.4f s for %zu rows in batches of 16 = %.0f "
           "rows/s (%.1f%% of the run)\n", storage, n,
           (double)n / storage, 100 * storage / whole);
    printf("  per option: %.2f ms = %.1fx a bare pass over the triangles "
           "(%.3f ms)\n", 1e3 * evaluate_one / (double)n,
           evaluate_one / (double)n / bare, 1e3 * bare);
    printf("  each grid on its own (no lattice): %.3f s on %d threads, "
           "%.2f ms per option on 1 = %.1fx a bare pass; the lattice, its "
           "build included, is %.2fx faster on %d threads\n", alone_all,
           jobs, 1e3 * alone_one / (double)n, alone_one / (double)n / bare,
           alone_all / (lattice_time + evaluate_all), jobs);
    double bulk_rate = (double)bulk / bulk_time.cpu;
    printf("bulk storage: %ld rows in batches of 1,000, the indexes by "
           "metric built at the end: %.2f s CPU (%.2f s wall) = %.0f rows/s "
           "(%.0f wall), %.2fx the rate of the bare floor: the same rows in "
           "one transaction without those indexes, %.2f s CPU (%.2f s "
           "wall) = %.0f rows/s (%.0f wall); the old path, indexes kept "
           "while storing, %ld rows: %.0f rows/s (%.0f wall)\n", bulk,
           bulk_time.cpu, bulk_time.wall, bulk_rate,
           (double)bulk / bulk_time.wall, bare_time.cpu / bulk_time.cpu,
           bare_time.cpu, bare_time.wall, (double)bulk / bare_time.cpu,
           (double)bulk / bare_time.wall, kept_rows,
           (double)kept_rows / kept_time.cpu,
           (double)kept_rows / kept_time.wall);
    printf("  the file at the end, by SQLite's sqlite_schema: %d of the %d "
           "indexes of the options table\n", indexes, expected);
    printf("  storage (issue 18): %.0f rows/s in CPU time into a file that "
           "ends with its indexes (target: at least 50,000: %s)\n",
           bulk_rate,
           bulk_rate >= 50000 && indexes == expected ? "met" : "not met");
    free(points);
    free(totals);
    free(rows);
    surface_close(&surface);
    return 0;
}
