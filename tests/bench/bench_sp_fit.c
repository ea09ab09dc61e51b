/*
 * bench_sp_fit.c: the SP fits of the study as built, alone.
 *
 *   bench_sp_fit [STRIDE [PASSES]]
 *
 * The study as built (issue 27: u 20:40 x v 35:50 at 3 mm on the
 * 100k-triangle roof) spends most of what it adds to classification in the
 * SP fits. This times only them: for every STRIDE-th grid of that space
 * (default 3), its panels classified untimed, then its sides sampled as
 * such a run samples them (cell_sides_sample_fits_stoppable: the SP
 * panels' sides) and built_option_fit, each timed in the thread's CPU
 * time; a pass sums the grids, and the medians of PASSES passes (default
 * 5) are printed with the counts fitted and misfit, which must not move. Built against another
 * libfacet.a (an older commit's), the same source gives the baseline:
 * alternate the two binaries and compare their medians.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench_common.h"
#include "core/classify/classify.h"
#include "core/surface/coarse_mesh.h"
#include "core/fit/sp_fit.h"
#include "core/joint/cell_sides.h"

#define MAX_PASSES 64

int main(int argc, char **argv)
{
    int stride = argc > 1 ? atoi(argv[1]) : 3;
    int passes = argc > 2 ? atoi(argv[2]) : 5;
    if (stride < 1 || passes < 1 || passes > MAX_PASSES) {
        fprintf(stderr, "usage: bench_sp_fit [STRIDE [PASSES <= 64]]\n");
        return 2;
    }
    struct surface surface;
    bench_roof(224, NULL, &surface);
    struct classify_options options;
    classify_defaults(&options);
    options.sp_as_fp = 1;
    options.threshold = 0.003;
    double times[MAX_PASSES], sampling[MAX_PASSES];
    size_t fitted = 0, misfits = 0;
    for (int pass = 0; pass < passes; pass++) {
        double spent = 0, sampled = 0;
        fitted = misfits = 0;
        int k = 0;
        for (int nu = 20; nu <= 40; nu++)
            for (int nv = 35; nv <= 50; nv++) {
                if (k++ % stride != 0)
                    continue;
                struct facet_error err;
                struct panelization panels;
                struct option_totals totals;
                struct cell_sides sides;
                struct built_option built;
                if (panels_build_fast(&surface.panels, PANEL_EXTREMES, nu,
                                      nv, &panels, &err) != FACET_OK)
                    bench_die("bench_sp_fit", "panels", &err);
                classify_panels(&panels, &options, &totals);
                int smooth = facet_sag_matters(surface.facet_sag,
                                               options.threshold);
                double start = bench_cpu_now();
                if (cell_sides_sample_fits_stoppable(
                        &surface.mesh, &surface.uv, &surface.curvature,
                        &panels, smooth, NULL, &sides, &err) != FACET_OK)
                    bench_die("bench_sp_fit", "sides", &err);
                sampled += bench_cpu_now() - start;
                start = bench_cpu_now();
                if (built_option_fit(&surface.mesh, &surface.fit, &panels,
                                     &sides, options.threshold, smooth,
                                     &built,
                                     &err) != FACET_OK)
                    bench_die("bench_sp_fit", "fits", &err);
                spent += bench_cpu_now() - start;
                fitted += built.sp_fitted;
                misfits += built.sp_misfits;
                built_option_free(&built);
                cell_sides_free(&sides);
                panelization_free(&panels);
            }
        times[pass] = spent;
        sampling[pass] = sampled;
    }
    printf("bench_sp_fit: SP fits of every %d-th grid of the paper's space "
           "at 3 mm: %.1f ms, their sides sampled %.1f ms (medians of %d "
           "passes, thread CPU); %zu fitted, %zu misfits\n", stride,
           bench_median(times, passes) * 1e3,
           bench_median(sampling, passes) * 1e3, passes, fitted, misfits);
    surface_close(&surface);
    return 0;
}
