/*
 * bench_tui.c: the options table of `facet tui` on a run of a million
 * options, timed through tui/table_model (no curses), against issue 5's
 * target of 50 ms for each of: opening the table, re-sorting, applying a
 * filter, scrolling a page, jumping to the end.
 *
 *   bench_tui [--options N] [--db PATH] [--reps R]
 *
 * Generates N options (default 1,000,000) of one run with store_run_create
 * and store_options_put in batches of 10,000, the indexes by metric built
 * at the end as a run of many options does (store_indexes_defer and
 * store_indexes_build; fewer than 50,000 options keep them): synthetic
 * but plausible totals (grids up to 1000 x 1000, DP area against
 * planarity, so cost and planarity trade off), ranked only on the (cost,
 * planarity) front: the front's options get rank 1 through
 * store_options_set_pareto, every other option stays unranked (rank
 * NULL), as after a run whose ranking was not written. With --db PATH the database is kept and reused when it already
 * holds such a run (generation is most of the bench's time); without it a
 * temporary file is removed at the end.
 *
 * Every figure is the median and worst of R repetitions (default 5), in
 * ms, with its ratio to the baseline: the store reading 200 options of the
 * run by number (store_options_query, LIMIT 200), measured in the same
 * run, and met or not against 50 ms at the median (issue 18: every
 * keystroke); a last line sums them up. The jump to the end of a filter is
 * timed twice: at once after the filter, and after the screen's steps
 * between keys have counted it. Not measured here: drawing (the screens
 * draw a page of rows).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "bench_common.h"
#include "tests/support/store_fixture.h"
#include "store/filter.h"
#include "store/store.h"
#include "tui/table_model.h"

#define BATCH 10000
#define TARGET_MS 50.0
#define MAX_REPS 50

/* A well-mixed 64-bit hash of k (splitmix64's finaliser). */
static uint64_t mix(uint64_t k)
{
    k += 0x9e3779b97f4a7c15u;
    k = (k ^ (k >> 30)) * 0xbf58476d1ce4e5b9u;
    k = (k ^ (k >> 27)) * 0x94d049bb133111ebu;
    return k ^ (k >> 31);
}

/* A uniform number in [0, 1) from k and a stream s. */
static double uniform(uint64_t k, uint64_t s)
{
    return (double)(mix(k * 4 + s) >> 11) * 0x1.0p-53;
}

/* Option number k + 1 of the synthetic run: a grid of up to 1000 x 1000
 * panels over 1,240 m^2, a threshold of 1 to 6 mm, DP area falling with
 * the threshold, planarity (m) growing with the flat area and the grid. */
static void synthetic(int64_t k, struct option_row *o)
{
    memset(o, 0, sizeof *o);
    struct option_totals *t = &o->totals;
    o->number = k + 1;
    o->nu = 1 + (int)(k % 1000);
    o->nv = 1 + (int)((k / 1000) % 1000);
    o->threshold_mm = 1 + 0.1 * (double)(mix((uint64_t)k) % 51);
    t->panels = (size_t)o->nu * (size_t)o->nv;
    t->area = 1240.0;
    double r1 = uniform((uint64_t)k, 1), r2 = uniform((uint64_t)k, 2);
    double r3 = uniform((uint64_t)k, 3);
    double dp = t->area * (0.02 + 0.6 * r1) / (1 + 0.2 * o->threshold_mm);
    double sp = (t->area - dp) * 0.4 * r2;
    double fp = t->area - dp - sp;
    double area[TYPE_COUNT] = {fp, sp, dp};
    double price[TYPE_COUNT] = {701, 766, 1518};
    for (int type = 0; type < TYPE_COUNT; type++) {
        t->area_of[type] = area[type];
        t->cost_of[type] = area[type] * price[type];
        t->cost += t->cost_of[type];
        t->count[type] = (size_t)((double)t->panels * area[type] / t->area);
    }
    t->class_count[CLASS_FLAT] = t->count[TYPE_FP];
    t->class_area[CLASS_FLAT] = fp;
    t->planarity = (fp + sp) / t->area * o->threshold_mm * 1e-3 *
                   sqrt((double)t->panels) * (0.3 + 0.7 * r3);
    t->max_deviation = o->threshold_mm * 1e-3 * (0.5 + 0.5 * r3);
    t->max_panel_area = t->area / (double)t->panels * (1 + 0.3 * r2);
    t->p_dist = t->planarity * 0.01;
    t->feasible = t->max_panel_area <= 7.06;
}

static const double *order_cost, *order_planarity;

static int by_cost(const void *a, const void *b)
{
    int64_t i = *(const int64_t *)a, j = *(const int64_t *)b;
    if (order_cost[i] != order_cost[j])
        return order_cost[i] < order_cost[j] ? -1 : 1;
    if (order_planarity[i] != order_planarity[j])
        return order_planarity[i] < order_planarity[j] ? -1 : 1;
    return (i > j) - (i < j);
}

/* Writes n synthetic options into a new run of store; ranks the
 * (cost, planarity) front 1 and leaves the rest unranked. */
static int64_t generate(struct store *store, int64_t n)
{
    struct facet_error err;
    struct run_info info;
    memset(&info, 0, sizeof info);
    snprintf(info.name, sizeof info.name, "bench_tui %lld", (long long)n);
    snprintf(info.surface_path, sizeof info.surface_path, "synthetic.obj");
    snprintf(info.surface_sha256, sizeof info.surface_sha256, "0");
    info.uv_method = PARAM_VT;
    info.units = UNITS_M;
    info.method = METHOD_RANDOM;
    info.per_panel = PANEL_EXTREMES;
    snprintf(info.objectives, sizeof info.objectives, "cost,planarity");
    info.u_min = info.v_min = 1;
    info.u_max = info.v_max = 1000;
    info.threshold_min_mm = 1;
    info.threshold_max_mm = 6;
    info.price[TYPE_FP] = 701;
    info.price[TYPE_SP] = 766;
    info.price[TYPE_DP] = 1518;
    info.max_panel_area = 7.06;
    info.jobs = 1;
    if (store_run_create(store, &info, &err) != FACET_OK)
        bench_die("bench_tui", "creating the run", &err);
    struct option_row *batch = malloc(BATCH * sizeof *batch);
    double *cost = malloc((size_t)n * sizeof *cost);
    double *planarity = malloc((size_t)n * sizeof *planarity);
    int64_t *index = malloc((size_t)n * sizeof *index);
    if (batch == NULL || cost == NULL || planarity == NULL || index == NULL) {
        fprintf(stderr, "bench_tui: out of memory\n");
        exit(1);
    }
    double start = bench_now();
    /* as a run of many options stores them: the indexes by metric built
     * once at the end */
    int deferred = 0;
    if (store_indexes_defer(store, n, &deferred, &err) != FACET_OK)
        bench_die("bench_tui", "dropping the indexes", &err);
    for (int64_t first = 0; first < n; first += BATCH) {
        size_t m = (size_t)(n - first < BATCH ? n - first : BATCH);
        for (size_t k = 0; k < m; k++) {
            int64_t number = first + (int64_t)k;
            synthetic(number, &batch[k]);
            cost[number] = batch[k].totals.cost;
            planarity[number] = batch[k].totals.planarity;
        }
        if (store_options_put(store, info.id, batch, m, &err) != FACET_OK)
            bench_die("bench_tui", "storing options", &err);
    }
    if (deferred &&
        store_indexes_build(store, info.id, NULL, &err) != FACET_OK)
        bench_die("bench_tui", "building the indexes", &err);
    double put = bench_now() - start;
    /* the front: by cost, each option less planar than every cheaper one */
    for (int64_t k = 0; k < n; k++)
        index[k] = k;
    order_cost = cost;
    order_planarity = planarity;
    qsort(index, (size_t)n, sizeof *index, by_cost);
    int64_t *numbers = malloc((size_t)n * sizeof *numbers);
    int *rank = malloc((size_t)n * sizeof *rank);
    double *crowding = malloc((size_t)n * sizeof *crowding);
    size_t front = 0;
    double best = INFINITY;
    for (int64_t k = 0; k < n; k++)
        if (planarity[index[k]] < best) {
            best = planarity[index[k]];
            numbers[front] = index[k] + 1;
            rank[front] = 1;
            crowding[front] = 1.0;
            front++;
        }
    if (front > 0)
        crowding[0] = crowding[front - 1] = INFINITY;
    start = bench_now();
    if (store_options_set_pareto(store, info.id, numbers, rank, crowding,
                                 front, front ? numbers[front / 2] : 0, NAN,
                                 &err) != FACET_OK ||
        store_run_set_status(store, info.id, RUN_DONE, put, &err) != FACET_OK ||
        store_analyze(store, &err) != FACET_OK)  /* as a run's end does */
        bench_die("bench_tui", "ranking", &err);
    printf("generated %lld options in %.1f s (%.0f rows/s, batches of %d);"
           " %zu on the front (rank 1), the rest unranked; ranking %.2f s\n",
           (long long)n, put, (double)n / put, BATCH, front,
           bench_now() - start);
    free(batch);
    free(cost);
    free(planarity);
    free(index);
    free(numbers);
    free(rank);
    free(crowding);
    return info.id;
}

/* The run of n options named by generate, or 0. */
static int64_t find_run(struct store *store, int64_t n)
{
    struct run_info *runs;
    size_t count;
    struct facet_error err;
    char name[128];
    snprintf(name, sizeof name, "bench_tui %lld", (long long)n);
    if (store_run_list(store, &runs, &count, &err) != FACET_OK)
        bench_die("bench_tui", "listing runs", &err);
    int64_t id = 0;
    for (size_t k = 0; k < count; k++)
        if (strcmp(runs[k].name, name) == 0 && runs[k].options == n &&
            runs[k].status == RUN_DONE)
            id = runs[k].id;
    free(runs);
    return id;
}

/* --- timing --- */

static int reps = 5;
static double baseline_ms = 0;
static char over[1024];  /* the keystrokes whose median is over target */

static int compare_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* Prints one figure: median and worst of times[0..n) (ms). */
static void report(const char *what, double *times, int n, const char *note)
{
    qsort(times, (size_t)n, sizeof *times, compare_double);
    double median = times[n / 2], worst = times[n - 1];
    printf("  %-44s %8.2f ms  worst %8.2f ms  x%-7.1f %s%s%s\n", what,
           median, worst, baseline_ms > 0 ? median / baseline_ms : 0,
           median <= TARGET_MS ? "met" : "NOT met",
           note && note[0] ? "  " : "", note ? note : "");
    if (median > TARGET_MS)
        snprintf(over + strlen(over), sizeof over - strlen(over), "%s%s",
                 over[0] ? "; " : "", what);
}

static int count_rows(void *context, int64_t run, const struct option_row *o)
{
    (void)run;
    (void)o;
    ++*(int64_t *)context;
    return 0;
}

/* The baseline: 200 options of run by number, through the store. */
static double baseline(struct store *store, int64_t run)
{
    struct option_query q;
    memset(&q, 0, sizeof q);
    q.run = run;
    q.limit = 200;
    double times[MAX_REPS];
    for (int r = 0; r < reps; r++) {
        int64_t got = 0;
        struct facet_error err;
        double start = bench_now();
        if (store_options_query(store, &q, count_rows, &got, &err) !=
            FACET_OK)
            bench_die("bench_tui", "baseline", &err);
        times[r] = (bench_now() - start) * 1e3;
    }
    qsort(times, (size_t)reps, sizeof *times, compare_double);
    return times[reps / 2];
}

static void check(int rc, const char *what, const struct facet_error *err)
{
    if (rc != FACET_OK)
        bench_die("bench_tui", what, err);
}

static int last_row(void *context, const struct option_row *o)
{
    *(int64_t *)context = o->number;
    return 1;
}

/* The number of b's last option, by the store's page read by a scan. */
static int64_t last_number(struct store *store, const struct option_browse *b)
{
    struct option_browse scan = *b;
    scan.filter_first = BROWSE_SCAN;
    int64_t number = 0;
    struct facet_error err;
    check(store_browse_page(store, &scan, NULL, 1, 1, last_row, &number,
                            &err), "reading the last row", &err);
    return number;
}

static const struct browse_key by_cost_key[] = {{"cost", 0}};
static const struct browse_key by_planarity_key[] = {{"planarity", 0}};
static const struct browse_key by_nu_key[] = {{"nu", 0}};

/* Opens m as the Options screen does: sorted by cost from the start,
 * first row selected. */
static void open_table(struct table_model *m, struct store *store,
                       int64_t run)
{
    struct facet_error err;
    if (table_model_open_sorted(m, store, run, by_cost_key, 1, &err) !=
        FACET_OK)
        bench_die("bench_tui", "opening the table", &err);
}

/* What the status line says of the count ("12,345" or "10,000+"). */
static const char *count_note(const struct table_model *m, char *out,
                              size_t size)
{
    char count[40];
    table_model_count_text(m, count, sizeof count);
    snprintf(out, size, "(%s shown)", count);
    return out;
}

/* Times re-sorting from cost to keys (the selection on the first row). */
static void time_sort(struct table_model *m, const char *what,
                      const struct browse_key *keys)
{
    double times[MAX_REPS];
    struct facet_error err;
    char note[64];
    for (int r = 0; r < reps; r++) {
        check(table_model_set_sort(m, by_cost_key, 1, &err), "sorting", &err);
        check(table_model_select(m, 0, &err), "selecting", &err);
        double start = bench_now();
        check(table_model_set_sort(m, keys, 1, &err), "sorting", &err);
        times[r] = (bench_now() - start) * 1e3;
    }
    report(what, times, reps, count_note(m, note, sizeof note));
    check(table_model_set_sort(m, by_cost_key, 1, &err), "sorting", &err);
}

/* Times applying filter text from none, sorted by cost. */
static void time_filter(struct table_model *m, const char *what,
                        const char *text)
{
    double times[MAX_REPS];
    struct facet_error err;
    char note[64];
    for (int r = 0; r < reps; r++) {
        check(table_model_set_filter(m, "", &err), "filtering", &err);
        check(table_model_select(m, 0, &err), "selecting", &err);
        double start = bench_now();
        check(table_model_set_filter(m, text, &err), "filtering", &err);
        times[r] = (bench_now() - start) * 1e3;
    }
    report(what, times, reps, count_note(m, note, sizeof note));
}

/* Times pages of 20 rows down from the top (every page, every rep). */
static void time_pages(struct table_model *m, const char *what)
{
    double times[MAX_REPS * 40];
    int n = 0;
    struct facet_error err;
    for (int r = 0; r < reps; r++) {
        check(table_model_select(m, 0, &err), "selecting", &err);
        for (int page = 0; page < 40; page++) {
            double start = bench_now();
            check(table_model_select(m, m->selected + 20, &err), "paging",
                  &err);
            times[n++] = (bench_now() - start) * 1e3;
        }
    }
    report(what, times, n, "(40 pages of 20 rows from the top)");
}

/* Times the jump to the last row from the first (the screen's G/End:
 * select count - 1). counted: the count finished first by the steps the
 * screen takes between keystrokes (TABLE_COUNT_STEP rows a tick), whose
 * time (*steps_ms, may be NULL) is not the jump's. The last row is checked
 * against the store's own last page. */
static void time_end(struct table_model *m, const char *what,
                     const char *filter, int fresh_model, int counted,
                     double *steps_ms, struct store *store, int64_t run)
{
    double times[MAX_REPS], steps[MAX_REPS];
    struct facet_error err;
    char note[64];
    for (int r = 0; r < reps; r++) {
        if (fresh_model) {
            table_model_close(m);
            open_table(m, store, run);
        }
        check(table_model_set_filter(m, filter, &err), "filtering", &err);
        check(table_model_select(m, 0, &err), "selecting", &err);
        double start = bench_now();
        int exact = !counted;
        while (!exact)
            check(table_model_count_step(m, TABLE_COUNT_STEP, &exact, &err),
                  "counting", &err);
        steps[r] = (bench_now() - start) * 1e3;
        start = bench_now();
        check(table_model_select(m, m->count - 1, &err), "jumping", &err);
        times[r] = (bench_now() - start) * 1e3;
        const struct option_row *o = table_model_selection(m);
        if (o == NULL || m->selected != m->count - 1 ||
            o->number != last_number(store, &m->browse)) {
            fprintf(stderr, "bench_tui: the jump did not reach the end\n");
            exit(1);
        }
    }
    report(what, times, reps, count_note(m, note, sizeof note));
    if (steps_ms != NULL) {
        qsort(steps, (size_t)reps, sizeof *steps, compare_double);
        *steps_ms = steps[reps / 2];
    }
    check(table_model_set_filter(m, "", &err), "filtering", &err);
}

/* The Statistics screen's figures of a whole run: the counts, minima,
 * maxima and means in one query, then every median, all at once from one
 * read (store_browse_medians, what the screen does up to
 * STORE_MEDIANS_AT_ONCE options) and, as the baseline, one SQLite sort a
 * column. Over every numeric column of the options table (more than the
 * screen's 22). Goal (issue 32 item 9): under a second for 10,000. */
static void time_statistics(struct store *store, int64_t run, int64_t n)
{
    const char *columns[OPTION_QUANTITIES];
    int nc = 0;
    for (int k = 0; k < OPTION_QUANTITIES; k++)
        if (option_quantities[k].field != FIELD_NONE)
            columns[nc++] = option_quantities[k].name;
    struct option_browse b;
    memset(&b, 0, sizeof b);
    b.run = run;
    struct column_stats stats[OPTION_QUANTITIES];
    double at_once[MAX_REPS], per_column[MAX_REPS];
    struct facet_error err;
    for (int r = 0; r < reps; r++) {
        double start = bench_now();
        check(store_browse_stats(store, &b, columns, nc, stats, &err),
              "statistics", &err);
        if (n <= STORE_MEDIANS_AT_ONCE)
            check(store_browse_medians(store, &b, columns, nc, stats, &err),
                  "medians", &err);
        at_once[r] = (bench_now() - start) * 1e3;
        start = bench_now();
        check(store_browse_stats(store, &b, columns, nc, stats, &err),
              "statistics", &err);
        for (int k = 0; k < nc; k++)
            check(store_browse_median(store, &b, columns[k], stats[k].count,
                                      &stats[k].median, &err),
                  "a median", &err);
        per_column[r] = (bench_now() - start) * 1e3;
    }
    qsort(at_once, (size_t)reps, sizeof *at_once, compare_double);
    qsort(per_column, (size_t)reps, sizeof *per_column, compare_double);
    double a = at_once[reps / 2], p = per_column[reps / 2];
    printf("  statistics of %lld options, %d columns: every median %s"
           " %.1f ms, a SQLite sort a column %.1f ms (x%.2f)\n",
           (long long)n, nc, n <= STORE_MEDIANS_AT_ONCE ? "from one read"
                                                     : "(too many to hold)",
           a, p, a / p);
    if (n <= STORE_MEDIANS_AT_ONCE)
        printf("Statistics of %lld options (issue 32 item 9): %.0f ms, goal"
               " under 1000 ms: %s\n", (long long)n, a,
               a < 1000 ? "met" : "not met");
}

int main(int argc, char **argv)
{
    int64_t n = 1000000;
    const char *keep = NULL;
    int statistics = 0;
    for (int k = 1; k < argc; k++) {
        if (strcmp(argv[k], "--options") == 0 && k + 1 < argc)
            n = atoll(argv[++k]);
        else if (strcmp(argv[k], "--db") == 0 && k + 1 < argc)
            keep = argv[++k];
        else if (strcmp(argv[k], "--reps") == 0 && k + 1 < argc)
            reps = atoi(argv[++k]);
        else if (strcmp(argv[k], "--statistics") == 0)
            statistics = 1;
        else {
            fprintf(stderr, "usage: bench_tui [--options N] [--db PATH]"
                            " [--reps R] [--statistics]\n");
            return 2;
        }
    }
    if (n < 1000 || reps < 1 || reps > MAX_REPS) {
        fprintf(stderr, "bench_tui: --options >= 1000, --reps 1..%d\n",
                MAX_REPS);
        return 2;
    }
    char temporary[64];
    snprintf(temporary, sizeof temporary, "/tmp/facet_bench_tui_%d.db",
             (int)getpid());
    const char *path = keep ? keep : temporary;
    if (keep == NULL)
        store_fixture_remove(path);
    struct store *store;
    struct facet_error err;
    if (store_open(path, &store, &err) != FACET_OK)
        bench_die("bench_tui", "opening the database", &err);
    int64_t run = find_run(store, n);
    if (run == 0)
        run = generate(store, n);
    else
        printf("reusing run %lld of %s (%lld options)\n", (long long)run,
               path, (long long)n);
    if (statistics) {
        time_statistics(store, run, n);
        store_close(store);
        if (keep == NULL)
            store_fixture_remove(path);
        return 0;
    }

    baseline_ms = baseline(store, run);
    printf("baseline: 200 options by number through the store: %.2f ms\n",
           baseline_ms);
    printf("median and worst of %d, ratio of the median to the baseline,"
           " target %.0f ms:\n", reps, TARGET_MS);

    struct table_model m;
    double times[MAX_REPS];
    char note[64];
    for (int r = 0; r < reps; r++) {
        double start = bench_now();
        open_table(&m, store, run);
        times[r] = (bench_now() - start) * 1e3;
        if (r + 1 < reps)
            table_model_close(&m);
    }
    report("open the table (sorted by cost)", times, reps,
           count_note(&m, note, sizeof note));

    time_sort(&m, "re-sort by planarity (indexed)", by_planarity_key);
    time_sort(&m, "re-sort by nu", by_nu_key);

    /* a filter that about a quarter of the options pass */
    time_filter(&m, "filter 'cost < 1.2e6 and dp_area < 200'",
                "cost < 1.2e6 and dp_area < 200");
    time_filter(&m, "filter 'pareto'", "pareto");
    time_filter(&m, "filter, rare: 'nu = 7 and nv = 13'",
                "nu = 7 and nv = 13");
    check(table_model_set_filter(&m, "", &err), "filtering", &err);

    time_pages(&m, "page down (20 rows)");
    time_end(&m, "jump to the end", "", 0, 0, NULL, store, run);
    time_end(&m, "jump to the end, first time (exact count)", "", 1, 0,
             NULL, store, run);
    time_end(&m, "jump to the end of 'cost < 1.2e6 and dp_area < 200'",
             "cost < 1.2e6 and dp_area < 200", 1, 0, NULL, store, run);
    double steps_ms = 0;
    time_end(&m, "the same, counted between keys first",
             "cost < 1.2e6 and dp_area < 200", 1, 1, &steps_ms, store, run);
    printf("  (counting it between keys: %.0f ms in steps of %d rows, one"
           " a tick while no key comes)\n", steps_ms, TABLE_COUNT_STEP);
    printf("TUI on 1M options (issue 18): every keystroke at most %.0f ms at"
           " the median: %s%s%s\n", TARGET_MS, over[0] ? "not met (" : "met",
           over, over[0] ? ")" : "");
    table_model_close(&m);
    store_close(store);
    if (keep == NULL)
        store_fixture_remove(path);
    return 0;
}
