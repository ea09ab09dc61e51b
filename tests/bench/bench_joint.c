/*
 * bench_joint.c: the cost of panels as built (the SP fit) and of the gap
 * and kink at every joint, for one design option.
 *
 *   bench_joint [RES]
 *
 * Generates the example roof at RES x RES quads (default 224: 100,352
 * triangles), prepares it once, and times, each the median of several
 * runs:
 *   - the option's panels and classes (panels_build_fast + classify_panels
 *     at 37 x 49): the baseline;
 *   - its cell sides sampled, its SP panels fitted and its joints measured
 *     (cell_sides_sample + built_option_fit + joints_measure).
 * Times are the thread's CPU time (both are single-threaded), so that
 * other load on the machine does not count, as it does in wall time.
 * Prints the ratio of the second to the first and whether the second meets
 * its target of 10 ms, then the option's figures (max gap, max kink, SP
 * misfits). The per-surface gathering of fit points (fit_points_build) is
 * timed apart: it is done once per surface, like the curvature.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "bench_common.h"
#include "core/classify/classify.h"
#include "core/joint/joint.h"

#define RUNS 21
#define TARGET_MS 10.0

static void fail(const struct facet_error *err)
{
    fprintf(stderr, "bench_joint: %s\n", err->message);
    exit(1);
}

int main(int argc, char **argv)
{
    int res = argc > 1 ? atoi(argv[1]) : 224;
    struct facet_error err;
    struct surface surface;
    bench_roof(res, NULL, &surface);
    struct classify_options options;
    classify_defaults(&options);
    double max_gap = 0.006, max_kink = 1.0 * 3.14159265358979323846 / 180;

    double start = bench_now();
    struct fit_points points;
    if (fit_points_build(&surface.panels, &points, &err) != FACET_OK)
        fail(&err);
    double points_time = bench_now() - start;

    double base[RUNS], joint[RUNS], stage[3][RUNS];
    struct option_totals totals;
    struct built_option built;
    struct joints joints;
    memset(&built, 0, sizeof built);
    memset(&joints, 0, sizeof joints);
    for (int run = 0; run < RUNS; run++) {
        struct panelization panels;
        start = bench_cpu_now();
        if (panels_build_fast(&surface.panels, PANEL_EXTREMES, 37, 49,
                              &panels, &err) != FACET_OK)
            fail(&err);
        classify_panels(&panels, &options, &totals);
        base[run] = bench_cpu_now() - start;

        built_option_free(&built);
        joints_free(&joints);
        struct cell_sides sides;
        double t0 = bench_cpu_now();
        if (cell_sides_sample(&surface.mesh, &surface.uv,
                              &surface.curvature, &panels, &sides,
                              &err) != FACET_OK)
            fail(&err);
        double t1 = bench_cpu_now();
        if (built_option_fit(&surface.mesh, &points, &panels, &sides,
                             options.threshold, &built, &err) != FACET_OK)
            fail(&err);
        double t2 = bench_cpu_now();
        if (joints_measure(&panels, &built, &sides, max_gap, max_kink,
                           &joints, &err) != FACET_OK)
            fail(&err);
        double t3 = bench_cpu_now();
        joint[run] = t3 - t0;
        stage[0][run] = t1 - t0;
        stage[1][run] = t2 - t1;
        stage[2][run] = t3 - t2;
        cell_sides_free(&sides);
        panelization_free(&panels);
    }
    double base_ms = bench_median(base, RUNS) * 1e3;
    double bare_ms = bench_bare_best(&surface.mesh, 50) * 1e3;
    double joint_ms = bench_median(joint, RUNS) * 1e3;

    printf("surface: roof, %zu triangles, %zu vertices, %.1f m^2\n",
           surface.mesh.ntriangles, surface.mesh.nvertices,
           surface.mesh.area);
    printf("bare pass (sum of triangle areas): %.3f ms\n", bare_ms);
    printf("fit points (once per surface): %.3f ms for %zu points\n",
           points_time * 1e3, points.npoints);
    printf("baseline, 37x49 panels + classes: %.3f ms (median of %d; "
           "%zu panels: %zu FP, %zu SP, %zu DP)\n", base_ms, RUNS,
           totals.panels, totals.count[TYPE_FP], totals.count[TYPE_SP],
           totals.count[TYPE_DP]);
    printf("gap + kink + SP fit: %.3f ms (median of %d) = %.2fx the "
           "baseline: %s (target <= %.0f ms)\n", joint_ms, RUNS,
           joint_ms / base_ms, joint_ms <= TARGET_MS ? "met" : "not met",
           TARGET_MS);
    printf("  of which: cell sides %.3f ms, SP fit %.3f ms, joints %.3f ms "
           "(medians)\n", bench_median(stage[0], RUNS) * 1e3,
           bench_median(stage[1], RUNS) * 1e3,
           bench_median(stage[2], RUNS) * 1e3);
    printf("joints: %zu; gap max %.2f mm, mean %.2f mm, %zu over %.0f mm; "
           "kink max %.2f deg, mean %.2f deg, %zu over %.0f deg\n",
           joints.nedges, joints.max_gap * 1e3, joints.mean_gap * 1e3,
           joints.gaps_over, max_gap * 1e3, joints.max_kink * 180 / M_PI,
           joints.mean_kink * 180 / M_PI, joints.kinks_over,
           max_kink * 180 / M_PI);
    printf("SP panels: %zu fitted (cylinder or cone within t = %.0f mm), "
           "%zu misfits built DP\n", built.sp_fitted,
           options.threshold * 1e3, built.sp_misfits);
    size_t cones = 0;
    double worst_sp = 0;
    for (size_t k = 0; k < built.npanels; k++) {
        if (built.panels[k].fitted) {
            cones += built.panels[k].fit.shape == DEVELOPABLE_CONE;
            worst_sp = fmax(worst_sp, built.panels[k].sp_deviation);
        }
    }
    printf("  of the fitted: %zu cones; largest sp_deviation %.2f mm\n",
           cones, worst_sp * 1e3);
    int shown = 0;
    for (size_t k = 0; k < built.npanels && shown < 3; k++) {
        char reason[160];
        built_panel_reason(&built, k, reason, sizeof reason);
        if (reason[0] != '\0') {
            printf("  misfit %zu: %s\n", k, reason);
            shown++;
        }
    }
    built_option_free(&built);
    joints_free(&joints);
    fit_points_free(&points);
    surface_close(&surface);
    return 0;
}
