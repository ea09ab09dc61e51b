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
 *     only, and with mirror images allowed.
 * Each is the median of several runs. The target: the families of
 * this option in 10 ms or less.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench_common.h"
#include "core/classify/classify.h"
#include "core/mould/mould.h"

#define RUNS 31

static int compare_doubles(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

static double median(double *t, int n)
{
    qsort(t, (size_t)n, sizeof *t, compare_doubles);
    return t[n / 2];
}

/* The median time (s) of the families of p under options; *out keeps the
 * last run's. */
static double time_families(const struct surface *s,
                            const struct panelization *p,
                            const struct mould_options *options,
                            struct mould_families *out)
{
    double t[RUNS];
    struct facet_error err;
    for (int run = 0; run < RUNS; run++) {
        if (run > 0)
            mould_families_free(out);
        double start = bench_now();
        if (mould_families_build(&s->mesh, &s->uv, p, options, out, &err)) {
            fprintf(stderr, "bench_mould: %s\n", err.message);
            exit(1);
        }
        t[run] = bench_now() - start;
    }
    return median(t, RUNS);
}

static void report(const char *what, double seconds, double baseline,
                   const struct mould_families *f)
{
    printf("%s: %.3f ms = %.2fx the evaluation; %zu SP + %zu DP families "
           "(largest %zu, %zu singletons), %zu exact tests, worst member "
           "%.3f mm off its representative: %s (<= 10 ms)\n", what,
           seconds * 1e3, seconds / baseline, f->count[TYPE_SP],
           f->count[TYPE_DP], f->largest, f->singletons, f->fits,
           f->worst * 1e3, seconds <= 0.010 ? "met" : "not met");
}

int main(int argc, char **argv)
{
    int res = argc > 1 ? atoi(argv[1]) : 224;
    struct facet_error err;
    struct surface surface;
    bench_roof(res, NULL, &surface);

    struct classify_options classify;
    classify_defaults(&classify);
    double t[RUNS];
    struct panelization panels;
    struct option_totals totals;
    for (int run = 0; run < RUNS; run++) {
        if (run > 0)
            panelization_free(&panels);
        double start = bench_now();
        if (panels_build_fast(&surface.panels, PANEL_EXTREMES, 37, 49,
                              &panels, &err) != FACET_OK) {
            fprintf(stderr, "bench_mould: %s\n", err.message);
            return 1;
        }
        classify_panels(&panels, &classify, &totals);
        t[run] = bench_now() - start;
    }
    double baseline = median(t, RUNS);
    double bare = bench_bare_best(&surface.mesh, 50);

    printf("surface: roof, %zu triangles; 37x49 option: %zu panels (%zu FP, "
           "%zu SP, %zu DP)\n", surface.mesh.ntriangles, totals.panels,
           totals.count[TYPE_FP], totals.count[TYPE_SP],
           totals.count[TYPE_DP]);
    printf("bare pass (sum of triangle areas): %.3f ms\n", bare * 1e3);
    printf("evaluation (panels_build_fast + classify): %.3f ms "
           "(median of %d) = %.1fx the bare pass\n", baseline * 1e3, RUNS,
           baseline / bare);
    struct mould_options options = {classify.threshold, 0};
    struct mould_families f;
    double proper = time_families(&surface, &panels, &options, &f);
    report("mould families, 3 mm, proper", proper, baseline, &f);
    mould_families_free(&f);
    options.mirror = 1;
    double mirrored = time_families(&surface, &panels, &options, &f);
    report("mould families, 3 mm, mirror images too", mirrored, baseline,
           &f);
    mould_families_free(&f);
    panelization_free(&panels);
    surface_close(&surface);
    return 0;
}
