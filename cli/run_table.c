/*
 * run_table.c: the paper's Table 2 for a run. See run_table.h.
 */
#include "run_table.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/base/numformat.h"
#include "core/base/text.h"
#include "core/search/ties.h"
#include "study/study.h"
#include "option_table.h"
#include "text_table.h"

/* The listed options cheapest first, costs equal but for rounding
 * (core/search/ties.h) by planarity, then DP area, then No.: into order.
 * Returns 0, or non-zero when out of memory. */
static int order_by_cost(const struct option_row *listed, size_t n,
                         size_t *order)
{
    enum { KEYS = 4 };
    double *keys = malloc((n * KEYS + 1) * sizeof *keys);
    if (keys == NULL)
        return -1;
    for (size_t k = 0; k < n; k++) {
        keys[k * KEYS + 0] = listed[k].totals.cost;
        keys[k * KEYS + 1] = listed[k].totals.planarity;
        keys[k * KEYS + 2] = listed[k].totals.area_of[TYPE_DP];
        keys[k * KEYS + 3] = (double)listed[k].number;
    }
    double tolerance[KEYS] = {0, 0, 0, 0};
    for (int j = 0; j < 3; j++)
        tolerance[j] = ties_tolerance(keys + j, n, KEYS);
    int rc = ties_order(keys, n, KEYS, tolerance, 0, order, NULL);
    free(keys);
    return rc;
}

/* Which limits the infeasible options of listed (n) break, in one line
 * into line: how many are over the panel area limit, hold slivers under
 * the width limit, or joints over the gap or kink limit (an option may
 * break several). "" when every option listed is feasible. */
static void violations_line(const struct run_info *info,
                            const struct option_row *listed, size_t n,
                            char *line, size_t size)
{
    size_t infeasible = 0, breaking[LIMIT_COUNT] = {0};
    for (size_t k = 0; k < n; k++) {
        const struct option_totals *t = &listed[k].totals;
        if (t->feasible)
            continue;
        infeasible++;
        double term[LIMIT_COUNT];
        unsigned broken = classify_broken_limits(t, info->max_panel_area,
                                                 term);
        for (int l = 0; l < LIMIT_COUNT; l++)
            breaking[l] += (broken & 1u << l) != 0;
    }
    size_t area = breaking[LIMIT_PANEL_AREA];
    size_t width = breaking[LIMIT_PANEL_WIDTH];
    size_t gap = breaking[LIMIT_GAP], kink = breaking[LIMIT_KINK];
    size_t planar = breaking[LIMIT_PLANARIZE];
    line[0] = '\0';
    if (infeasible == 0)
        return;
    size_t used = (size_t)snprintf(line, size, "infeasible: %zu listed",
                                   infeasible);
    if (area > 0 && used < size)
        used += (size_t)snprintf(line + used, size - used,
                                 "; %zu over the panel area limit "
                                 "(--max-panel-area %g m^2)", area,
                                 info->max_panel_area);
    if (width > 0 && used < size)
        used += (size_t)snprintf(line + used, size - used,
                                 "; %zu with slivers under the width limit "
                                 "(--min-panel-width %g m)", width,
                                 info->min_panel_width);
    if (gap > 0 && used < size)
        used += (size_t)snprintf(line + used, size - used,
                                 "; %zu with gaps over the limit "
                                 "(--max-gap %g mm)", gap, info->max_gap_mm);
    if (kink > 0 && used < size)
        used += (size_t)snprintf(line + used, size - used,
                                 "; %zu with kinks over the limit "
                                 "(--max-kink %g deg)", kink,
                                 info->max_kink_deg);
    if (planar > 0 && used < size)
        snprintf(line + used, size - used,
                 "; %zu planarized, not planar within %g mm of the surface "
                 "(--planarize)", planar, info->planarize_closeness_mm);
}

int run_table_print(FILE *out, struct store *store, const char *db,
                    int64_t run, long rows, int wide, struct facet_error *err)
{
    struct run_info info;
    int rc = store_run_get(store, run, &info, err);
    if (rc != FACET_OK)
        return rc;
    char cost[64];
    number_grouped(cost, sizeof cost, info.best_cost, 0);
    char line[2400];
    char name[sizeof info.name], path[sizeof info.surface_path];
    text_for_terminal(info.name, name, sizeof name);
    text_for_terminal(info.surface_path, path, sizeof path);
    snprintf(line, sizeof line, "run %lld (%s%s%s): %s, %s, %lld options in "
             "%.2f s, %lld Pareto-optimal", (long long)info.id, run_status_name(info.status),
             name[0] ? ", " : "", name, path,
             store_run_setting_text(&info, RUN_SETTING_METHOD),
             (long long)info.options, info.elapsed,
             (long long)info.pareto_options);
    text_wrap(out, line, text_table_width(out, wide));
    char hypervolume[32] = "- (no feasible option)";
    if (isfinite(info.hypervolume))
        snprintf(hypervolume, sizeof hypervolume, "%.6f", info.hypervolume);
    snprintf(line, sizeof line, "objectives %s; hypervolume %s (normalised, "
             "reference point 1.1 on every axis); knee option %lld; best "
             "cost %s USD", info.objectives, hypervolume,
             (long long)info.knee, isfinite(info.best_cost) ? cost : "-");
    text_wrap(out, line, text_table_width(out, wide));

    /* The Pareto options first, then the next fronts, cheapest first
     * within each, up to rows: a front longer than rows is cut too, and
     * the line under the table says so. */
    struct option_query q = {run, 0, NULL, "rank,cost", 0, rows, 0, 1};
    struct option_row *listed;
    size_t n;
    rc = store_options_query_rows(store, &q, &listed, &n, err);
    if (rc != FACET_OK)
        return rc;
    size_t *order = malloc((n + 1) * sizeof *order);
    if (order == NULL || order_by_cost(listed, n, order) != 0) {
        free(order);
        free(listed);
        return facet_error_set(err, FACET_EWORK, "out of memory (table)");
    }
    struct option_table_column columns[OPTION_TABLE_MAX];
    int ncolumns = option_table_for_objectives(info.objectives, columns);
    if (store_run_is_project(&info))
        option_table_for_project(columns, ncolumns);
    struct text_column heads[OPTION_TABLE_MAX + 1];
    option_table_heads(columns, ncolumns, heads);
    heads[ncolumns] = (struct text_column){"", "", 15, 1, 9, 0};
    struct text_table t = {heads, ncolumns + 1, {0}, 0, 0};
    text_table_fit(&t, text_table_width(out, wide));
    fputc('\n', out);
    text_table_head(out, &t);
    for (size_t k = 0; k < n; k++) {
        const struct option_row *o = &listed[order[k]];
        char text[OPTION_TABLE_MAX][OPTION_TABLE_CELL], marks[32];
        const char *cell[OPTION_TABLE_MAX + 1];
        option_table_cells(columns, ncolumns, run, o, text, cell);
        snprintf(marks, sizeof marks, "%s%s%s", o->knee ? "knee" : "",
                 o->knee && !o->totals.feasible ? " " : "",
                 o->totals.feasible ? "" : "infeasible");
        cell[ncolumns] = marks;
        text_table_row(out, &t, cell);
    }
    if ((int64_t)n < info.pareto_options) {
        snprintf(line, sizeof line, "(%zu of %lld options, the cheapest %zu "
                 "of %lld Pareto-optimal; 'facet options %s --run %lld "
                 "--pareto' lists the front)", n, (long long)info.options, n,
                 (long long)info.pareto_options, db, (long long)run);
        text_wrap(out, line, text_table_width(out, wide));
    } else if ((int64_t)n < info.options) {
        snprintf(line, sizeof line, "(%zu of %lld options; 'facet options %s "
                 "--run %lld' lists them all)", n, (long long)info.options,
                 db, (long long)run);
        text_wrap(out, line, text_table_width(out, wide));
    }
    fprintf(out, "* Pareto-optimal\n");
    violations_line(&info, listed, n, line, sizeof line);
    if (line[0] != '\0')
        text_wrap(out, line, text_table_width(out, wide));
    text_table_foot(out, &t);
    free(order);
    free(listed);
    struct front_bounds bounds;
    if ((rc = store_front_bounds(store, run, &bounds, err)) != FACET_OK)
        return rc;
    char note[1024];
    if (study_front_edge_note(&info, &bounds, note, sizeof note)) {
        snprintf(line, sizeof line, "note: %s", note);
        text_wrap(out, line, text_table_width(out, wide));
    }
    return FACET_OK;
}
