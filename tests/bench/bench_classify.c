/*
 * bench_classify.c: the cost of one design option, against a bare pass.
 *
 *   bench_classify [RES]
 *
 * Generates the example roof at RES x RES quads (default 224: 100,352
 * triangles), prepares it once (UV lookup, curvature), then times:
 *   - a bare pass over every triangle, summing their areas from the
 *     positions (the least any evaluation must do): the baseline;
 *   - one 37 x 49 evaluation (panelize, classify, price), the median of
 *     31, against issue 18's goal of at most 5 bare passes;
 *   - the vertex curvature, per vertex;
 *   - the same evaluation with every panel's width measured too (slivers:
 *     option.h's OPTION_MEASURE_WIDTHS, left out of the one above so that
 *     its figure stays comparable with earlier runs), the median of 7.
 * The bare pass and the curvature are the best of several runs (the floor);
 * the evaluation is also given as a ratio to the baseline, which holds
 * across machines.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "bench_common.h"
#include "core/evaluate/evaluate.h"

#define EVAL_RUNS 31
#define GOAL_RATIO 5.0  /* issue 18: one evaluation, in bare passes */

int main(int argc, char **argv)
{
    int res = argc > 1 ? atoi(argv[1]) : 224;
    struct facet_error err;
    struct surface surface;
    bench_roof(res, NULL, &surface);

    double best_curvature = INFINITY;
    for (int run = 0; run < 3; run++) {
        struct curvature c;
        double start = bench_now();
        curvature_at_vertices(&surface.mesh, 0, &c, &err);
        best_curvature = fmin(best_curvature, bench_now() - start);
        curvature_free(&c);
    }

    double best_bare = bench_bare_best(&surface.mesh, 50);

    struct option_params params;
    memset(&params, 0, sizeof params);
    params.nu = 37;
    params.nv = 49;
    params.mode = PANEL_EXTREMES;
    classify_defaults(&params.classify);
    params.unmeasured = OPTION_MEASURE_WIDTHS;
    double eval_times[EVAL_RUNS];
    struct option_totals totals;
    for (int run = 0; run < EVAL_RUNS; run++) {
        struct panelization panels;
        double start = bench_now();
        option_evaluate(&surface, &params, NULL, &panels, &totals, &err);
        eval_times[run] = bench_now() - start;
        panelization_free(&panels);
    }
    double eval = bench_median(eval_times, EVAL_RUNS);
    struct option_params with_widths = params;
    with_widths.unmeasured = 0;
    double width_times[7];
    struct option_totals measured;
    for (int run = 0; run < 7; run++) {
        struct panelization panels;
        double start = bench_now();
        option_evaluate(&surface, &with_widths, NULL, &panels, &measured,
                        &err);
        width_times[run] = bench_now() - start;
        panelization_free(&panels);
    }
    double widths = bench_median(width_times, 7);

    printf("surface: roof, %zu triangles, %zu vertices, %.1f m^2\n",
           surface.mesh.ntriangles, surface.mesh.nvertices,
           surface.mesh.area);
    printf("bare pass (sum of triangle areas): %.3f ms\n", best_bare * 1e3);
    printf("one 37x49 evaluation: %.3f ms (median of %d) = %.1fx the bare "
           "pass (%zu panels: %zu FP, %zu SP, %zu DP) (target: at most "
           "%.0fx: %s)\n", eval * 1e3, EVAL_RUNS, eval / best_bare,
           totals.panels, totals.count[TYPE_FP], totals.count[TYPE_SP],
           totals.count[TYPE_DP], GOAL_RATIO,
           eval <= GOAL_RATIO * best_bare ? "met" : "not met");
    printf("the same with every panel's width (slivers): %.3f ms (median "
           "of 7) = %.1fx the evaluation without (smallest width %.3f m)\n",
           widths * 1e3, widths / eval, measured.min_panel_width);
    printf("curvature: %.3f ms for %zu vertices = %.2f us per vertex "
           "(done once per surface)\n", best_curvature * 1e3,
           surface.mesh.nvertices,
           best_curvature * 1e6 / (double)surface.mesh.nvertices);
    surface_close(&surface);
    return 0;
}
