/*
 * run_table.c: the paper's Table 2 for a run. See run_table.h.
 */
#include "run_table.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/numformat.h"
#include "core/ties.h"

/* The listed options cheapest first, costs equal but for rounding
 * (core/ties.h) by planarity, then DP area, then No.: into order. Returns
 * 0, or -1 when out of memory. */
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
                    int64_t run, long rows, struct facet_error *err)
{
    struct run_info info;
    int rc = store_run_get(store, run, &info, err);
    if (rc != FACET_OK)
        return rc;
    char cost[64];
    number_grouped(cost, sizeof cost, info.best_cost, 0);
    fprintf(out, "run %lld (%s%s%s): %s, %s, %lld options in %.2f s, "
            "%lld Pareto-optimal\n", (long long)info.id, info.status,
            info.name[0] ? ", " : "", info.name, info.surface_path,
            info.method, (long long)info.options, info.elapsed,
            (long long)info.pareto_options);
    char hypervolume[32] = "- (no feasible option)";
    if (isfinite(info.hypervolume))
        snprintf(hypervolume, sizeof hypervolume, "%.6f", info.hypervolume);
    fprintf(out, "objectives %s; hypervolume %s (normalised, reference "
            "point 1.1 on every axis); knee option %lld; best cost %s USD\n",
            info.objectives, hypervolume, (long long)info.knee,
            isfinite(info.best_cost) ? cost : "-");

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
    fprintf(out, "\n%6s %1s %11s %10s %14s %10s %10s %4s %4s %7s %4s\n",
            "No.", "", "planarity", "DP area", "total cost", "FP area",
            "SP area", "U", "V", "t", "rank");
    fprintf(out, "%6s %1s %11s %10s %14s %10s %10s %4s %4s %7s %4s\n", "",
            "", "m", "m^2", "USD", "m^2", "m^2", "", "", "mm", "");
    for (size_t k = 0; k < n; k++) {
        const struct option_row *o = &listed[order[k]];
        number_grouped(cost, sizeof cost, o->totals.cost, 0);
        fprintf(out, "%6lld %1s %11.3f %10.1f %14s %10.1f %10.1f %4d %4d "
                "%7.2f %4d%s%s\n", (long long)o->number,
                o->rank == 1 ? "*" : "", o->totals.planarity,
                o->totals.area_of[TYPE_DP], cost, o->totals.area_of[TYPE_FP],
                o->totals.area_of[TYPE_SP], o->nu, o->nv, o->threshold_mm,
                o->rank, o->knee ? "  knee" : "",
                o->totals.feasible ? "" : "  infeasible");
    }
    if ((int64_t)n < info.options)
        fprintf(out, "(%zu of %lld options; 'facet options %s --run %lld' "
                "lists them all)\n", n, (long long)info.options,
                db, (long long)run);
    fprintf(out, "* Pareto-optimal\n");
    free(order);
    free(listed);
    return FACET_OK;
}
