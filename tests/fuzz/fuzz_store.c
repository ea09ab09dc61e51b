/*
 * fuzz_store.c: any bytes as a Facet database someone sent, opened as
 * `facet runs`, `facet options` and `facet show` open it (store_open_read
 * on a file), then read through what those commands and the workbench
 * ask of the store: the runs and their fronts, the options listed, sorted
 * and filtered, one option's row, panels and surfaces, and a browse of a
 * run's table with its counts, ranges, statistics and groups.
 *
 * A hostile file may be refused, with one line; it must never crash,
 * hang, leak, or give more rows than were asked for. Queries are not
 * checked against each other: a damaged index legitimately answers
 * otherwise than its table.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "fuzz.h"
#include "store/filter.h"
#include "store/store.h"

/* What one input reads at most: the first runs, the first options of
 * each, pages of a few rows. */
enum { RUNS = 4, SHOWN = 3, PAGE = 16 };

static void check_message(const struct facet_error *err)
{
    if (err->message[0] == '\0' || strchr(err->message, '\n') != NULL) {
        fprintf(stderr, "fuzz_store: not one line: '%s'\n", err->message);
        abort();
    }
}

/* A call's result: an error must say what, in one line. */
static int checked(int rc, const struct facet_error *err)
{
    if (rc != FACET_OK)
        check_message(err);
    return rc;
}

/* Rows received by a query's callback, refused past a limit. */
struct rows {
    int64_t n, limit;
    struct option_row last;
};

static int take_option(void *context, int64_t run,
                       const struct option_row *option)
{
    struct rows *rows = context;
    (void)run;
    rows->last = *option;
    if (++rows->n > rows->limit)
        abort();
    return 0;
}

static int take_row(void *context, const struct option_row *option)
{
    return take_option(context, 0, option);
}

/* What show reads of option number of run: its row, its panels when
 * stored, and a project's surfaces. */
static void show_option(struct store *store, const struct run_info *run,
                        int64_t number)
{
    struct facet_error err;
    struct option_row row;
    if (checked(store_option_get(store, run->id, number, &row, &err), &err))
        return;
    int stored = 0;
    if (!checked(store_panels_exist(store, run->id, number, &stored, &err),
                 &err) && stored) {
        struct panelization panels;
        checked(store_panels_get(store, run->id, number, &panels, &err),
                &err);
        panelization_free(&panels);
    }
    struct option_surface_row *surfaces = NULL;
    size_t n = 0;
    checked(store_option_surfaces_get(store, run->id, number, &surfaces, &n,
                                      &err), &err);
    free(surfaces);
}

/* The workbench on one run: its table by b, counted, paged both ways,
 * and its statistics. */
static void browse(struct store *store, const struct option_browse *b)
{
    static const char *const stats[] = {"cost", "planarity", "dp_area",
                                        "nu", "threshold_mm", "moulds",
                                        "max_gap", "sp_misfits"};
    struct facet_error err;
    int64_t count = 0;
    checked(store_browse_count(store, b, &count, &err), &err);
    checked(store_browse_count_capped(store, b, NULL, 0, PAGE, &count, &err),
            &err);
    if (count > PAGE)
        abort();
    struct rows rows = {0, PAGE, {0}};
    if (!checked(store_browse_page(store, b, NULL, 0, PAGE, take_row, &rows,
                                   &err), &err) && rows.n > 0) {
        struct option_row last = rows.last;
        int64_t position;
        checked(store_browse_position(store, b, &last, &position, &err),
                &err);
        rows = (struct rows){0, PAGE, {0}};
        checked(store_browse_page(store, b, &last, 1, PAGE, take_row, &rows,
                                  &err), &err);
        rows = (struct rows){0, PAGE, {0}};
        checked(store_browse_page(store, b, &last, 0, PAGE, take_row, &rows,
                                  &err), &err);
    }
    rows = (struct rows){0, PAGE, {0}};
    checked(store_browse_offset(store, b, 2, PAGE, take_row, &rows, &err),
            &err);
    rows = (struct rows){0, PAGE, {0}};
    checked(store_browse_sample(store, b, 2, PAGE, take_row, &rows, &err),
            &err);
    /* A count in steps, as the table makes it between keystrokes; a step
     * reads at most its rows, so a few steps end on a small file. */
    int64_t from = 0, stepped = 0;
    int done = 0;
    struct browse_tail tail;
    tail.n = 0;
    for (int step = 0; !done && step < 8; step++)
        if (checked(store_browse_count_step(store, b, 64, &from, &stepped,
                                            &done, &tail, &err), &err))
            break;
    double min, max;
    checked(store_browse_range(store, b, "cost", &min, &max, &err), &err);
    struct column_stats out[sizeof stats / sizeof stats[0]];
    int n = (int)(sizeof stats / sizeof stats[0]);
    if (!checked(store_browse_stats(store, b, stats, n, out, &err), &err)) {
        double median;
        checked(store_browse_median(store, b, "cost", out[0].count, &median,
                                    &err), &err);
    }
    struct option_group *groups = NULL;
    size_t ngroups = 0;
    checked(store_browse_groups(store, b, "nu", 0, &groups, &ngroups, &err),
            &err);
    free(groups);
    groups = NULL;
    checked(store_browse_groups(store, b, "threshold_mm", 0.5, &groups,
                                &ngroups, &err), &err);
    free(groups);
    struct class_frequency classes[CLASS_COUNT];
    checked(store_browse_classes(store, b, classes, &err), &err);
}

/* What runs, options and show read of one run, and the workbench's
 * browse of it: by number, then by cost with a filter. */
static void one_run(struct store *store, const struct run_info *run,
                    const struct filter *where)
{
    struct facet_error err;
    char status[16];
    store_run_status_text(run, status, sizeof status);
    for (int s = 0; s < RUN_SETTINGS; s++) {
        store_run_setting_text(run, (enum run_setting)s);
        checked(store_run_setting_check(run, (enum run_setting)s, &err),
                &err);
    }
    struct front_bounds bounds;
    checked(store_front_bounds(store, run->id, &bounds, &err), &err);
    struct surface_row *surfaces = NULL;
    size_t nsurfaces = 0;
    checked(store_surfaces_get(store, run->id, &surfaces, &nsurfaces, &err),
            &err);
    free(surfaces);

    struct option_query q = {run->id, 0, where, "cost,dp_area", 1, SHOWN, 0, 1};
    struct option_row *listed = NULL;
    size_t n = 0;
    if (!checked(store_options_query_rows(store, &q, &listed, &n, &err),
                 &err)) {
        if (n > SHOWN)
            abort();
        for (size_t k = 0; k < n; k++)
            show_option(store, run, listed[k].number);
    }
    free(listed);
    show_option(store, run, 1);
    show_option(store, run, run->knee);

    double min, max;
    checked(store_run_column_range(store, run->id, "cost", &min, &max, &err),
            &err);
    checked(store_run_column_range(store, run->id, "module_w", &min, &max,
                                   &err), &err);
    struct option_browse b = {run->id, 0, NULL, {{NULL, 0}}, 0, 0, 0, 0};
    browse(store, &b);
    b = (struct option_browse){run->id, 1, where,
                               {{"cost", 1}, {"nv", 0}}, 2, BROWSE_SCAN, 0,
                               0};
    browse(store, &b);
    b.feasible_first = 1;  /* the table's default: feasible options first */
    browse(store, &b);
    b.feasible_first = 0;
    b.filter_first = 1;
    b.pareto_only = 0;
    browse(store, &b);
}

/* The input as a database file of its own folder (SQLite makes its
 * -wal, -shm or -journal beside it), read, then removed with them. */
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const char *tmp = getenv("TMPDIR");
    char dir[4096];
    snprintf(dir, sizeof dir, "%s/facet-fuzz-store-XXXXXX",
             tmp && *tmp ? tmp : "/tmp");
    if (mkdtemp(dir) == NULL)
        return 0;
    char path[4200];
    snprintf(path, sizeof path, "%s/sent.db", dir);
    FILE *out = fopen(path, "wb");
    if (out == NULL || fwrite(data, 1, size, out) != size) {
        if (out != NULL)
            fclose(out);
        remove(path);
        rmdir(dir);
        return 0;
    }
    fclose(out);

    struct facet_error err;
    struct filter *where = NULL;
    if (filter_compile("cost > 0 and nu >= 2 or not feasible", &where,
                       &err) != FACET_OK)
        abort();
    struct store *store = NULL;
    if (!checked(store_open_read(path, &store, &err), &err)) {
        struct run_info *runs = NULL;
        size_t n = 0;
        if (!checked(store_run_list(store, &runs, &n, &err), &err)) {
            for (size_t k = 0; k < n && k < RUNS; k++)
                one_run(store, &runs[k], where);
        }
        free(runs);
        /* facet options without --run: every run's, sorted, limited. */
        struct option_query q = {0, 1, NULL, "planarity", 0, PAGE, 1, 1};
        struct rows rows = {0, PAGE, {0}};
        checked(store_options_query(store, &q, take_option, &rows, &err),
                &err);
        struct run_info run;
        checked(store_run_get(store, 1, &run, &err), &err);
        store_close(store);
    }
    filter_free(where);
    static const char *const sides[] = {"", "-wal", "-shm", "-journal"};
    for (size_t k = 0; k < sizeof sides / sizeof sides[0]; k++) {
        char side[4300];
        snprintf(side, sizeof side, "%s%s", path, sides[k]);
        remove(side);
    }
    rmdir(dir);
    return 0;
}
