/*
 * bench_joint.c: the cost of panels as built (the SP fit) and of the gap
 * and kink at every joint, for one design option.
 *
 *   bench_joint [RES [RUNS [SPACE_RUNS]]]
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
 *
 * (The paper's whole space with and without panels as built is timed by
 * bench_optimize, with the other stages of the evaluation.)
 *
 * Last, every other of the paper's grids in u and in v
 * (study_request_defaults: u 20:40 x v 35:50, a quarter of them) at
 * three thresholds each (as a stepped space evaluates them, a grid's
 * points together): the cell sides, SP fits and joints of each option
 * alone, and with its grid's fits kept across the thresholds (sp_fit.h's
 * grid_fits), each timed on the same options in the same pass, SPACE_RUNS
 * passes (default 3; 0 skips them, for a profile of the one option).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "core/evaluate/evaluate.h"
#include "bench_common.h"
#include "core/classify/classify.h"
#include "core/surface/coarse_mesh.h"
#include "core/joint/joint.h"
#include "study/study.h"

#define RUNS 21
#define RUNS_MAX 2001
#define TARGET_MS 10.0
#define SPACE_RUNS 3
#define SPACE_RUNS_MAX 21
#define MAX_GAP 0.006                      /* m */
#define MAX_KINK (1.0 * M_PI / 180)        /* rad */

static void fail(const struct facet_error *err)
{
    fprintf(stderr, "bench_joint: %s\n", err->message);
    exit(1);
}

/* An option's cell sides, SP fits and joints, on its own: its panels as
 * built into *built (release with built_option_free). */
static void joints_alone(const struct surface *surface,
                         const struct fit_points *points,
                         const struct panelization *panels, double threshold,
                         struct built_option *built)
{
    struct facet_error err;
    struct cell_sides sides;
    struct joints measured;
    if (cell_sides_sample(&surface->mesh, &surface->uv, &surface->curvature,
                          panels, &sides, &err) != FACET_OK ||
        built_option_fit(&surface->mesh, points, panels, &sides, threshold,
                         facet_sag_matters(surface->facet_sag, threshold),
                         built, &err) != FACET_OK ||
        joints_measure(panels, built, &sides, MAX_GAP, MAX_KINK, &measured,
                       &err) != FACET_OK)
        fail(&err);
    joints_free(&measured);
    cell_sides_free(&sides);
}

/* The thresholds a stepped space evaluates at each grid (mm), out of
 * order as a search may meet them. */
static const double STEPPED_MM[] = {3, 2, 4};
#define NSTEPPED 3
/* Every other grid side of the paper's space, in u and in v: a quarter of
 * its grids, every size among them, so that make bench keeps to its
 * budget. */
#define GRID_STEP 2

/* One pass over the paper's grids at each of STEPPED_MM: the cell sides,
 * SP fits and joints of each option alone (cell_sides_sample +
 * built_option_fit), and with one grid_fits per grid, timed in turn on
 * the same options: CPU times (s) into *alone and *grid; counts the
 * panels whose verdict differs (none expected) into *flips. */
static void stepped_pass(const struct surface *surface,
                         const struct panel_lattice *lattice,
                         const struct fit_points *points,
                         const struct optimize_settings *s, double *alone,
                         double *grid_s, size_t *flips)
{
    struct facet_error err;
    const struct design_space *space = &s->space;
    *alone = *grid_s = 0;
    for (int nu = space->u_min; nu <= space->u_max; nu += GRID_STEP)
        for (int nv = space->v_min; nv <= space->v_max; nv += GRID_STEP) {
            struct grid_fits grid;
            struct panelization panels;
            for (int x = 0; x < NSTEPPED; x++) {
                struct option_params params = option_params_at(
                    &s->base, nu, nv, STEPPED_MM[x]);
                struct option_totals totals;
                const struct evaluation_shared shared = {.lattice =
                                                             lattice};
                if (option_evaluate(surface, &params, &shared, &panels,
                                    &totals, &err) != FACET_OK)
                    fail(&err);
                double t0 = bench_cpu_now();
                struct cell_sides view;
                struct built_option built, cached;
                struct joints measured;
                joints_alone(surface, points, &panels,
                             params.classify.threshold, &built);
                double t1 = bench_cpu_now();
                if ((x == 0 &&
                     grid_fits_init(&surface->mesh, &surface->uv,
                                    &surface->curvature, points, &panels,
                                    &grid, &err) != FACET_OK) ||
                    grid_fits_option(&grid, &panels,
                                     params.classify.threshold,
                                     facet_sag_matters(surface->facet_sag,
                                         params.classify.threshold),
                                     &cached,
                                     &view, &err) != FACET_OK ||
                    joints_measure(&panels, &cached, &view, MAX_GAP,
                                   MAX_KINK, &measured, &err) != FACET_OK)
                    fail(&err);
                joints_free(&measured);
                double t2 = bench_cpu_now();
                *alone += t1 - t0;
                *grid_s += t2 - t1;
                for (size_t k = 0; k < built.npanels; k++)
                    *flips += built.panels[k].misfit !=
                              cached.panels[k].misfit;
                built_option_free(&built);
                built_option_free(&cached);
                panelization_free(&panels);
            }
            grid_fits_free(&grid);
        }
}

/* The paper's grids at several thresholds, each option's joints alone and
 * with its grid's fits kept (grid_fits); prints the ratio. */
static void stepped_bench(const struct surface *surface,
                          const struct panel_lattice *lattice,
                          const struct optimize_settings *s,
                          const struct fit_points *points, int runs)
{
    const struct design_space *space = &s->space;
    double alone[SPACE_RUNS_MAX], grid[SPACE_RUNS_MAX];
    size_t flips = 0;
    for (int run = 0; run < runs; run++)
        stepped_pass(surface, lattice, points, s, &alone[run], &grid[run],
                     &flips);
    size_t n = (size_t)((space->u_max - space->u_min) / GRID_STEP + 1) *
               (size_t)((space->v_max - space->v_min) / GRID_STEP + 1) *
               NSTEPPED;
    double alone_s = bench_median(alone, runs);
    double grid_s = bench_median(grid, runs);
    printf("every other paper grid in u and v at t = %g, %g, %g mm (%zu "
           "options, 1 thread): "
           "cell sides + SP fit + joints %.3f s each option alone, %.3f s "
           "with its grid's fits kept (medians of %d) = %.2fx; %.2f ms per "
           "option alone, %.2f with; %zu verdicts differ\n", STEPPED_MM[0],
           STEPPED_MM[1], STEPPED_MM[2], n, alone_s, grid_s, runs,
           grid_s / alone_s, 1e3 * alone_s / (double)n,
           1e3 * grid_s / (double)n, flips);
}

int main(int argc, char **argv)
{
    int res = argc > 1 ? atoi(argv[1]) : 224;
    /* More runs than the default serve a profiler (perf record), which
     * then sees the option's work rather than the surface's preparation. */
    int runs = argc > 2 ? atoi(argv[2]) : RUNS;
    if (runs < 1 || runs > RUNS_MAX)
        runs = RUNS;
    int space_runs = argc > 3 ? atoi(argv[3]) : SPACE_RUNS;
    if (space_runs < 0 || space_runs > SPACE_RUNS_MAX)
        space_runs = SPACE_RUNS;
    struct facet_error err;
    struct surface surface;
    bench_roof(res, NULL, &surface);
    struct classify_options options;
    classify_defaults(&options);
    double max_gap = MAX_GAP, max_kink = MAX_KINK;

    double start = bench_now();
    struct fit_points points;
    if (fit_points_build(&surface.panels, &points, &err) != FACET_OK)
        fail(&err);
    double points_time = bench_now() - start;

    static double base[RUNS_MAX], joint[RUNS_MAX], stage[3][RUNS_MAX];
    struct option_totals totals;
    struct built_option built;
    struct joints joints;
    memset(&built, 0, sizeof built);
    memset(&joints, 0, sizeof joints);
    for (int run = 0; run < runs; run++) {
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
                             options.threshold,
                             facet_sag_matters(surface.facet_sag,
                                               options.threshold),
                             &built, &err) != FACET_OK)
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
    double base_ms = bench_median(base, runs) * 1e3;
    double bare_ms = bench_bare_best(&surface.mesh, 50) * 1e3;
    double joint_ms = bench_median(joint, runs) * 1e3;

    printf("surface: roof, %zu triangles, %zu vertices, %.1f m^2\n",
           surface.mesh.ntriangles, surface.mesh.nvertices,
           surface.mesh.area);
    printf("bare pass (sum of triangle areas): %.3f ms\n", bare_ms);
    printf("fit points (once per surface): %.3f ms for %zu points\n",
           points_time * 1e3, points.npoints);
    printf("baseline, 37x49 panels + classes: %.3f ms (median of %d; "
           "%zu panels: %zu FP, %zu SP, %zu DP)\n", base_ms, runs,
           totals.panels, totals.count[TYPE_FP], totals.count[TYPE_SP],
           totals.count[TYPE_DP]);
    printf("gap + kink + SP fit: %.3f ms (median of %d) = %.2fx the "
           "baseline: %s (target <= %.0f ms)\n", joint_ms, runs,
           joint_ms / base_ms, joint_ms <= TARGET_MS ? "met" : "not met",
           TARGET_MS);
    printf("  of which: cell sides %.3f ms, SP fit %.3f ms, joints %.3f ms "
           "(medians)\n", bench_median(stage[0], runs) * 1e3,
           bench_median(stage[1], runs) * 1e3,
           bench_median(stage[2], runs) * 1e3);
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
    if (space_runs > 0) {
        /* The paper's space (study_request_defaults) and its lattice. */
        struct study_request request;
        study_request_defaults(&request);
        struct panel_lattice *lattice;
        if (optimize_lattice(&surface, &request.settings, &lattice,
                             &err) != FACET_OK)
            fail(&err);
        stepped_bench(&surface, lattice, &request.settings, &points,
                      space_runs);
        panel_lattice_free(lattice);
    }
    fit_points_free(&points);
    surface_close(&surface);
    return 0;
}
