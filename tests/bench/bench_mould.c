/*
 * bench_mould.c: the mould families of one design option, against the
 * option's own evaluation.
 *
 *   bench_mould [RES]
 *
 * Generates the example roof at RES x RES quads (default 224: 100,352
 * triangles), prepares it once, builds and classifies its 37 x 49 panels
 * with the paper's defaults, then times:
 *   - the evaluation itself, panels_build_fast + classify_panels: the
 *     baseline;
 *   - the mould families at the flatness threshold (3 mm), proper moves
 *     only, and with mirror images allowed;
 *   - the same option as built (option_evaluate, the default: its SP
 *     panels fitted, each carrying its cylinder or cone), its families at
 *     3 mm, proper moves: the SP panels matched by their fitted surfaces
 *     (mould.h's jigs) once that is built, by shape before.
 * Each is the median of several runs, in wall time and in the thread's
 * CPU time: on a machine shared with other work the wall time counts their
 * turns too (the load average is printed), so the verdict on the issue's
 * target, the families of this option in 10 ms or less, is given for both.
 */
#include <assert.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench_common.h"
#include "core/classify/classify.h"
#include "core/evaluate/evaluate.h"
#include "core/mould/mould.h"

#define RUNS 31

/* The median wall and CPU times (s) of the families of p under options;
 * *out keeps the last run's. */
static void time_families(const struct surface *s,
                          const struct panelization *p,
                          const struct mould_options *options, int runs,
                          struct mould_families *out, double *wall,
                          double *cpu)
{
    double t[RUNS], c[RUNS];
    struct facet_error err;
    assert(runs >= 1 && runs <= RUNS);
    for (int run = 0; run < runs; run++) {
        if (run > 0)
            mould_families_free(out);
        double start = bench_now(), start_cpu = bench_cpu_now();
        if (mould_families_build(&s->mesh, &s->uv, p, options, out, &err)) {
            fprintf(stderr, "bench_mould: %s\n", err.message);
            exit(1);
        }
        t[run] = bench_now() - start;
        c[run] = bench_cpu_now() - start_cpu;
    }
    *wall = bench_median(t, runs);
    *cpu = bench_median(c, runs);
}

static const char *verdict(double seconds)
{
    return seconds <= 0.010 ? "met" : "not met";
}

static void report(const char *what, double wall, double cpu,
                   double baseline, const struct mould_families *f)
{
    printf("%s: %.3f ms wall, %.3f ms CPU = %.2fx the evaluation's CPU; "
           "%zu SP + %zu DP families (largest %zu, %zu singletons), %zu "
           "exact tests, worst member %.3f mm off its representative\n",
           what, wall * 1e3, cpu * 1e3, cpu / baseline, f->count[TYPE_SP],
           f->count[TYPE_DP], f->largest, f->singletons, f->fits,
           f->worst * 1e3);
    printf("  %s: target <= 10 ms: %s in CPU time, %s in wall time\n",
           what, verdict(cpu), verdict(wall));
}

/* A grid finer than the mesh: hostile.sh's final phase, 200 x 200 panels
 * on the roof at 160 x 160 quads, their SP panels on the facets, at a
 * tolerance of 0.5 mm, where the facets' sag leaves most SP panels
 * without a shared jig and the jig search tests each against every family
 * within the closed form's reach. Against the same panels by shape. */
static void fine_grid(void)
{
    struct facet_error err;
    struct surface surface;
    struct panelization panels;
    struct option_totals totals;
    struct option_params params, base;
    struct mould_families f;
    double wall, cpu, shape_cpu;
    bench_roof(160, NULL, &surface);
    option_params_defaults(&base);
    params = option_params_at(&base, 200, 200, 0.5);
    params.unmeasured = OPTION_MEASURE_MOULDS;
    if (option_evaluate(&surface, &params, NULL, &panels, &totals, &err))
        bench_die("bench_mould", "fine grid", &err);
    printf("fine grid: roof at 160 x 160 quads, 200 x 200 panels at "
           "0.5 mm (%zu SP panels fitted)\n", totals.sp_fitted);
    struct mould_options options = option_mould_options(&params);
    options.jigs = 0;
    time_families(&surface, &panels, &options, 3, &f, &wall, &shape_cpu);
    printf("  by shape: %.1f ms CPU, %zu SP families, %zu exact tests\n",
           shape_cpu * 1e3, f.count[TYPE_SP], f.fits);
    mould_families_free(&f);
    options.jigs = 1;
    time_families(&surface, &panels, &options, 3, &f, &wall, &cpu);
    printf("  by jig: %.1f ms CPU = %.1fx by shape, %zu SP families, %zu "
           "exact tests\n", cpu * 1e3, cpu / shape_cpu, f.count[TYPE_SP],
           f.fits);
    mould_families_free(&f);
    panelization_free(&panels);
    surface_close(&surface);
}

int main(int argc, char **argv)
{
    int res = argc > 1 ? atoi(argv[1]) : 224;
    struct facet_error err;
    struct surface surface;
    bench_roof(res, NULL, &surface);

    struct classify_options classify;
    classify_defaults(&classify);
    double t[RUNS], c[RUNS];
    struct panelization panels;
    struct option_totals totals;
    for (int run = 0; run < RUNS; run++) {
        if (run > 0)
            panelization_free(&panels);
        double start = bench_now(), start_cpu = bench_cpu_now();
        if (panels_build_fast(&surface.panels, PANEL_EXTREMES, 37, 49,
                              &panels, &err) != FACET_OK) {
            fprintf(stderr, "bench_mould: %s\n", err.message);
            return 1;
        }
        classify_panels(&panels, &classify, &totals);
        t[run] = bench_now() - start;
        c[run] = bench_cpu_now() - start_cpu;
    }
    double baseline = bench_median(t, RUNS);
    double baseline_cpu = bench_median(c, RUNS);
    double bare = bench_bare_best(&surface.mesh, 50);
    double load[1] = {-1};
    getloadavg(load, 1);

    printf("surface: roof, %zu triangles; 37x49 option: %zu panels (%zu FP, "
           "%zu SP, %zu DP)\n", surface.mesh.ntriangles, totals.panels,
           totals.count[TYPE_FP], totals.count[TYPE_SP],
           totals.count[TYPE_DP]);
    printf("load average %.2f; bare pass (sum of triangle areas): %.3f ms\n",
           load[0], bare * 1e3);
    printf("evaluation (panels_build_fast + classify): %.3f ms wall, %.3f "
           "ms CPU (medians of %d) = %.1fx the bare pass\n", baseline * 1e3,
           baseline_cpu * 1e3, RUNS, baseline / bare);
    struct mould_options options = {classify.threshold, 0, 0, NULL};
    struct mould_families f;
    double wall, cpu;
    time_families(&surface, &panels, &options, RUNS, &f, &wall, &cpu);
    report("mould families, 3 mm, proper", wall, cpu, baseline_cpu, &f);
    mould_families_free(&f);
    options.mirror = 1;
    time_families(&surface, &panels, &options, RUNS, &f, &wall, &cpu);
    report("mould families, 3 mm, mirror images too", wall, cpu,
           baseline_cpu, &f);
    mould_families_free(&f);
    panelization_free(&panels);

    struct option_params params, base;
    option_params_defaults(&base);
    params = option_params_at(&base, 37, 49, 3);
    params.unmeasured = OPTION_MEASURE_MOULDS;
    if (option_evaluate(&surface, &params, NULL, &panels, &totals, &err))
        bench_die("bench_mould", "as built", &err);
    printf("as built: %zu SP panels fitted, %zu misfits built DP\n",
           totals.sp_fitted, totals.sp_misfits);
    options = option_mould_options(&params);
    time_families(&surface, &panels, &options, RUNS, &f, &wall, &cpu);
    report("mould families as built, 3 mm, proper", wall, cpu,
           baseline_cpu, &f);
    mould_families_free(&f);
    panelization_free(&panels);
    surface_close(&surface);
    fine_grid();
    return 0;
}
