/*
 * bench_planarize.c: issue 33's speed goal: 10,000 quads (the example
 * roof's 100 x 100 grid) planarized to below 0.1 % of their diagonal, or
 * reported infeasible, in at most 2 s on 2 cores; beside it, the figure
 * the issue measured for libigl's planarize_quad_mesh (26 s for 1,633
 * quads, worst quad left 0.47 % non-planar, no closeness term).
 *
 * Times planarize() alone (the grid's corners and the nearest-point index
 * are made before the clock starts: facet classify makes the corners
 * anyway), the median of 5 runs, wall and CPU, the calling thread's and
 * the whole process's (CHOLMOD's OpenMP and OpenBLAS threads spinning on
 * shared cores showed only in the latter: sparse_solver.h); then the
 * same grid's corners and index, timed apart.
 */
#include <stdio.h>
#include <string.h>

#include "tests/bench/bench_common.h"
#include "core/planar/planarize.h"

#define RUNS 5

int main(int argc, char **argv)
{
    int res = argc > 1 ? atoi(argv[1]) : 0;
    int side = argc > 2 ? atoi(argv[2]) : 100;
    struct surface surface;
    bench_roof(res, NULL, &surface);
    struct facet_error err;
    double start = bench_now();
    struct panelization panels;
    if (panels_build_fast(&surface.panels, PANEL_EXTREMES, side, side,
                          &panels, &err) != FACET_OK)
        bench_die("bench_planarize", "panels", &err);
    struct quad_grid grid;
    if (quad_grid_from_panels(&panels, &grid, &err) != FACET_OK)
        bench_die("bench_planarize", "grid", &err);
    struct nearest_index index;
    if (nearest_index_build(&surface.mesh, &index, &err) != FACET_OK)
        bench_die("bench_planarize", "index", &err);
    double setup = bench_now() - start;
    struct planarize_options o;
    planarize_options_defaults(&o);
    double wall[RUNS], cpu[RUNS], process[RUNS];
    struct planarize_result r;
    memset(&r, 0, sizeof r);
    for (int run = 0; run < RUNS; run++) {
        planarize_result_free(&r);
        double w0 = bench_now(), c0 = bench_cpu_now();
        double p0 = bench_process_cpu_now();
        if (planarize(&surface.mesh, &index, &grid, &o, &r, &err) != FACET_OK)
            bench_die("bench_planarize", "planarize", &err);
        wall[run] = bench_now() - w0;
        cpu[run] = bench_cpu_now() - c0;
        process[run] = bench_process_cpu_now() - p0;
    }
    double w = bench_median(wall, RUNS), c = bench_median(cpu, RUNS);
    double all = bench_median(process, RUNS);
    double load[1] = {0};
    getloadavg(load, 1);
    printf("surface: roof, %zu triangles; grid %d x %d: %zu quads, %zu "
           "corners (panels, corners and index: %.3f s)\n",
           surface.mesh.ntriangles, side, side, r.nquads, r.ncorners, setup);
    printf("load average %.2f; planarize, median of %d: %.3f s wall, %.3f s "
           "CPU of the calling thread, %.3f s of the process (every thread, "
           "user and system)\n", load[0], RUNS, w, c, all);
    printf("reached: planarity %.3g of the diagonal (start %.3g), %zu quads "
           "over 0.1 %%; closeness %.3f mm at most, %.3f mm mean; %d "
           "iterations, %s; %s under %g mm\n", r.max_relative,
           r.start_max_relative, r.over, r.max_distance * 1000,
           r.mean_distance * 1000, r.iterations,
           r.converged ? "converged" : "at the iteration limit",
           r.feasible ? "feasible" : "infeasible", o.closeness * 1000);
    printf("libigl's planarize_quad_mesh, as issue 33 measured it: 26 s for "
           "1,633 quads, worst quad 0.47 %% non-planar, no closeness term\n");
    int settled = r.over == 0 || !r.feasible;
    printf("  10,000 quads to below 0.1 %% of their diagonal or reported "
           "infeasible (issue 33): target <= 2 s: %s (%.3f s wall, %s)\n",
           settled && w <= 2.0 ? "met" : "not met", w,
           r.over == 0 ? "all planar within 0.1 %" : "reported infeasible");
    planarize_result_free(&r);
    nearest_index_free(&index);
    quad_grid_free(&grid);
    panelization_free(&panels);
    surface_close(&surface);
    return 0;
}
