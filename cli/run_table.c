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
#include "text_table.h"

/* The listed options cheapest first, costs equal but for rounding
 * (core/search/ties.h) by planarity, then DP area, then No.: into order.
 * Returns 0, or -1 when out of memory. */
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
    int rc = ties_order(keys, n, KEYS, tolerance, 0, order);
    free(keys);
    return rc;
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
             info.method, (long long)info.options, info.elapsed,
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
     * within each, up to rows. */
    long limit = rows == 0 ? 0
                 : (long)info.pareto_options > rows ? (long)info.pareto_options
                                                    : rows;
    struct option_query q = {run, 0, NULL, "rank,cost", 0, limit, 0};
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
    static const struct text_column columns[] = {
        {"No.", "", 6, 0, 0, 0},
        {"", "", 1, 0, 0, 0},
        {"planarity", "m", 11, 0, 9, 0},
        {"DP area", "m^2", 10, 0, 9, 0},
        {"total cost", "USD", 14, 0, 9, 0},
        {"FP area", "m^2", 10, 0, 3, 0},
        {"SP area", "m^2", 10, 0, 2, 0},
        {"U", "", 4, 0, 8, 0},
        {"V", "", 4, 0, 8, 0},
        {"t", "mm", 7, 0, 7, 0},
        {"rank", "", 4, 0, 5, 0},
        {"", "", 15, 1, 9, 0},
    };
    struct text_table t = {columns, sizeof columns / sizeof columns[0],
                           {0}, 0, 0};
    text_table_fit(&t, text_table_width(out, wide));
    fputc('\n', out);
    text_table_head(out, &t);
    for (size_t k = 0; k < n; k++) {
        const struct option_row *o = &listed[order[k]];
        char number[24], planarity[32], dp[32], fp[32], sp[32], u[16], v[16];
        char th[32], rank[16], marks[32];
        number_grouped(cost, sizeof cost, o->totals.cost, 0);
        snprintf(number, sizeof number, "%lld", (long long)o->number);
        snprintf(planarity, sizeof planarity, "%.3f", o->totals.planarity);
        snprintf(dp, sizeof dp, "%.1f", o->totals.area_of[TYPE_DP]);
        snprintf(fp, sizeof fp, "%.1f", o->totals.area_of[TYPE_FP]);
        snprintf(sp, sizeof sp, "%.1f", o->totals.area_of[TYPE_SP]);
        snprintf(u, sizeof u, "%d", o->nu);
        snprintf(v, sizeof v, "%d", o->nv);
        snprintf(th, sizeof th, "%.2f", o->threshold_mm);
        snprintf(rank, sizeof rank, "%d", o->rank);
        snprintf(marks, sizeof marks, "%s%s%s", o->knee ? "knee" : "",
                 o->knee && !o->totals.feasible ? " " : "",
                 o->totals.feasible ? "" : "infeasible");
        const char *cell[] = {number, o->rank == 1 ? "*" : "", planarity,
                              dp, cost, fp, sp, u, v, th, rank, marks};
        text_table_row(out, &t, cell);
    }
    if ((int64_t)n < info.options) {
        snprintf(line, sizeof line, "(%zu of %lld options; 'facet options %s "
                 "--run %lld' lists them all)", n, (long long)info.options,
                 db, (long long)run);
        text_wrap(out, line, text_table_width(out, wide));
    }
    fprintf(out, "* Pareto-optimal\n");
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
