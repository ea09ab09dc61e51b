/*
 * bench_curvature.c: the vertex curvature against the estimator it
 * replaced (issue 27: at most 1.3 times its time, one thread).
 *
 *   bench_curvature [RUNS [RES [DATA_DIR]]]
 *
 * The baseline is the estimator of d218719 (before the osculating
 * correction, the thin fits and the Newton steps), taken from git and
 * built beside today's with its public names prefixed base_ (Makefile:
 * CURVATURE_BASE). Each surface is estimated RUNS times (default 7) by
 * each, alternating (base, today, base, today, ...), so that what the
 * other work on a shared machine does falls on both; the figures are the
 * medians and their ratio, on one thread (the calling thread's CPU time)
 * and on the online CPUs (wall time). Surfaces: the example roof at RES x
 * RES quads (default 224: 100,352 triangles), and the open surfaces of
 * real designs among the files of DATA_DIR (default ../shared/data), each
 * estimated several times a run so that a run takes long enough to time,
 * and the sum of their medians; they are skipped, and said so, when the
 * folder is not there.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "bench_common.h"
#include "core/base/parallel.h"
#include "core/surface/curvature.h"

#define GOAL_RATIO 1.3  /* issue 27: today's time over the baseline's */
#define RUNS_MAX 63

/* The baseline (curvature_base.o): the same contract as today's. */
int base_curvature_at_vertices(const struct mesh *mesh, int flip_normals,
                               struct curvature *out,
                               struct facet_error *err);
int base_curvature_at_vertices_jobs(const struct mesh *mesh, int flip_normals,
                                    int jobs, struct curvature *out,
                                    struct facet_error *err);
void base_curvature_free(struct curvature *curvature);

/* Real surfaces of ../shared/data: open ones, as designers' files are
 * (the closed models there are not panelized). */
static const char *const real_files[] = {
    "botanic-garden-bubble-0.obj", "conical1.obj", "hemisphere.obj",
    "igloo.obj", "barrel.obj", "compas_quadmesh.obj", "compas_hypar.obj",
};
enum { NREAL = sizeof real_files / sizeof real_files[0] };

/* One estimation of mesh by today's (base 0) or the baseline (base 1)
 * estimator, reps times, on one thread (jobs 1: CPU time of this thread)
 * or the default (jobs 0: wall time). Returns seconds. */
static double time_once(const struct mesh *mesh, int base, int jobs,
                        int reps)
{
    struct facet_error err;
    int threaded = jobs == 0;
    double start = threaded ? bench_now() : bench_cpu_now();
    for (int r = 0; r < reps; r++) {
        struct curvature c;
        int rc = base ? threaded
                            ? base_curvature_at_vertices(mesh, 0, &c, &err)
                            : base_curvature_at_vertices_jobs(mesh, 0, jobs,
                                                              &c, &err)
                      : threaded
                            ? curvature_at_vertices(mesh, 0, &c, &err)
                            : curvature_at_vertices_jobs(mesh, 0, jobs, &c,
                                                         &err);
        if (rc != FACET_OK)
            bench_die("bench_curvature", "curvature", &err);
        if (base)
            base_curvature_free(&c);
        else
            curvature_free(&c);
    }
    return (threaded ? bench_now() : bench_cpu_now()) - start;
}

/* Medians over runs alternating the baseline and today's estimator on
 * mesh (reps estimations a run): time[0] the baseline's, time[1] today's. */
static void measure(const struct mesh *mesh, int reps, int jobs, int runs,
                    double *time)
{
    double t[2][RUNS_MAX];
    for (int run = 0; run < runs; run++) {
        t[0][run] = time_once(mesh, 1, jobs, reps);
        t[1][run] = time_once(mesh, 0, jobs, reps);
    }
    time[0] = bench_median(t[0], runs);
    time[1] = bench_median(t[1], runs);
}

/* Prints one line: the two medians per estimation and their ratio. */
static void report(const char *what, size_t nvertices, int reps, int runs,
                   const double *time, int goal)
{
    double ratio = time[1] / time[0];
    printf("  %-38s base %8.2f ms, today %8.2f ms (%.2f us/vertex): "
           "%.2fx", what, time[0] * 1e3 / reps, time[1] * 1e3 / reps,
           time[1] * 1e6 / ((double)nvertices * reps), ratio);
    if (goal)
        printf(" (target: at most %.1fx, one thread (issue 27): %s)",
               GOAL_RATIO, ratio <= GOAL_RATIO ? "met" : "not met");
    printf(" [median of %d]\n", runs);
}

int main(int argc, char **argv)
{
    int runs = argc > 1 ? atoi(argv[1]) : 7;
    int res = argc > 2 ? atoi(argv[2]) : 224;
    const char *data = argc > 3 ? argv[3] : "../shared/data";
    if (runs < 1 || runs > RUNS_MAX || res < 2) {
        fprintf(stderr, "usage: bench_curvature [RUNS 1..%d [RES [DIR]]]\n",
                RUNS_MAX);
        return 2;
    }
    int cpus = parallel_cpus(8);

    struct surface roof;
    bench_roof(res, NULL, &roof);
    double time[2];
    char what[96];
    printf("baseline: the estimator of d218719; ratios are today's time "
           "over the baseline's, medians of %d alternating runs\n", runs);
    printf("roof, %zu triangles, %zu vertices:\n", roof.mesh.ntriangles,
           roof.mesh.nvertices);
    measure(&roof.mesh, 1, 1, runs, time);
    report("roof, one thread (CPU)", roof.mesh.nvertices, 1, runs, time, 1);
    measure(&roof.mesh, 1, 0, runs, time);
    snprintf(what, sizeof what, "roof, %d threads (wall)", cpus);
    report(what, roof.mesh.nvertices, 1, runs, time, 0);
    surface_close(&roof);

    struct surface real[NREAL];
    const struct mesh *meshes[NREAL];
    const char *names[NREAL];
    int reps[NREAL], nreal = 0;
    size_t vertices = 0;
    if (access(data, R_OK) != 0) {
        printf("real surfaces: skipped, %s is not there\n", data);
        return 0;
    }
    for (int i = 0; i < NREAL; i++) {
        char path[512];
        struct mesh_options options = {UNITS_M, NULL, NULL};
        struct facet_error err;
        snprintf(path, sizeof path, "%s/%s", data, real_files[i]);
        if (access(path, R_OK) != 0) {
            printf("  %s: skipped, not in %s\n", real_files[i], data);
            continue;
        }
        if (surface_open(path, &options, &real[nreal], &err) != FACET_OK)
            bench_die("bench_curvature", path, &err);
        meshes[nreal] = &real[nreal].mesh;
        names[nreal] = real_files[i];
        /* about 10,000 vertices a run: long enough to time */
        size_t nv = real[nreal].mesh.nvertices;
        reps[nreal] = nv >= 10000 ? 1 : (int)(10000 / (nv ? nv : 1));
        nreal++;
    }
    printf("real surfaces of %s, one thread (CPU):\n", data);
    double sum[2] = {0, 0};
    for (int i = 0; i < nreal; i++) {
        measure(meshes[i], reps[i], 1, runs, time);
        snprintf(what, sizeof what, "%s (%zu v)", names[i],
                 meshes[i]->nvertices);
        report(what, meshes[i]->nvertices, reps[i], runs, time, 0);
        vertices += meshes[i]->nvertices;
        sum[0] += time[0] / reps[i];
        sum[1] += time[1] / reps[i];
    }
    if (nreal > 0) {
        snprintf(what, sizeof what, "all %d, sum of their medians", nreal);
        report(what, vertices, 1, runs, sum, 1);
    }
    for (int i = 0; i < nreal; i++)
        surface_close(&real[i]);
    return 0;
}
