/*
 * bench_common.h: what every C benchmark shares: a monotonic clock, the
 * example roof at a given resolution, prepared, and the bare pass over its
 * triangles that serves as the baseline the figures are ratios against.
 * Header-only (static inline functions, each benchmark taking what it
 * needs) because each benchmark is one file.
 */
#ifndef FACET_BENCH_COMMON_H
#define FACET_BENCH_COMMON_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <sys/resource.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "core/surface/example.h"
#include "core/surface/surface.h"

/* Says on stderr which benchmark failed doing what, and why, and exits:
 * a benchmark that cannot do its work has no figure to give. */
static inline void bench_die(const char *bench, const char *what,
                             const struct facet_error *err)
{
    fprintf(stderr, "%s: %s: %s\n", bench, what, err->message);
    exit(1);
}

static inline double bench_now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + (double)t.tv_nsec * 1e-9;
}

/* The calling thread's CPU time (s): on a machine shared with other work,
 * wall time counts their turns too. */
static inline double bench_cpu_now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return (double)t.tv_sec + (double)t.tv_nsec * 1e-9;
}

/* The whole process's CPU time (s), every thread's, user and system: a
 * library's helper threads spinning show here and not in the above. */
static inline double bench_process_cpu_now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return (double)t.tv_sec + (double)t.tv_nsec * 1e-9;
}

static inline int bench_compare_doubles(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* The median of t[0..n) (n >= 1), which it sorts. */
static inline double bench_median(double *t, int n)
{
    qsort(t, (size_t)n, sizeof *t, bench_compare_doubles);
    return t[n / 2];
}

/* Runs work(context, figures) in a forked child, so that each
 * measurement starts from a fresh process (its own peak memory, no cache
 * warmed by the last): the child fills size bytes of figures and sends
 * them back through a pipe into the parent's figures, with the child's
 * resource use into *usage (may be NULL). Returns 0 when work returned 0
 * and the figures came whole, else -1. */
static inline int bench_in_child(int (*work)(void *context, void *figures),
                                 void *context, void *figures, size_t size,
                                 struct rusage *usage)
{
    int pipe_fd[2];
    if (pipe(pipe_fd) != 0)
        return -1;
    pid_t child = fork();
    if (child < 0)
        return -1;
    if (child == 0) {
        close(pipe_fd[0]);
        int rc = work(context, figures);
        ssize_t wrote = write(pipe_fd[1], figures, size);
        _exit(rc == 0 && wrote == (ssize_t)size ? 0 : 1);
    }
    close(pipe_fd[1]);
    size_t got = 0;
    while (got < size) {
        ssize_t n = read(pipe_fd[0], (char *)figures + got, size - got);
        if (n <= 0)
            break;
        got += (size_t)n;
    }
    close(pipe_fd[0]);
    int status;
    struct rusage own;
    if (wait4(child, &status, 0, usage != NULL ? usage : &own) != child ||
        !WIFEXITED(status) || WEXITSTATUS(status) != 0 || got != size)
        return -1;
    return 0;
}

/* Sums the triangle areas from the positions: the least any evaluation
 * must do. */
static inline double bench_bare_pass(const struct mesh *mesh)
{
    double area = 0;
    for (size_t t = 0; t < mesh->ntriangles; t++) {
        const uint32_t *tri = mesh->triangle + 3 * t;
        const double *a = mesh->position + 3 * (size_t)tri[0];
        const double *b = mesh->position + 3 * (size_t)tri[1];
        const double *c = mesh->position + 3 * (size_t)tri[2];
        double e[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
        double f[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
        double n[3] = {e[1] * f[2] - e[2] * f[1], e[2] * f[0] - e[0] * f[2],
                       e[0] * f[1] - e[1] * f[0]};
        area += 0.5 * sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    }
    return area;
}

/* Best time of a bare pass over runs repetitions (seconds). */
static inline double bench_bare_best(const struct mesh *mesh, int runs)
{
    volatile double sink = 0;
    double best = INFINITY;
    for (int run = 0; run < runs; run++) {
        double start = bench_now();
        sink += bench_bare_pass(mesh);
        best = fmin(best, bench_now() - start);
    }
    (void)sink;
    return best;
}

/* Writes the example roof at res x res quads to path (kept when path is
 * not NULL, else a temporary file) and opens and prepares it. Exits on
 * failure: a benchmark without its surface has nothing to say. */
static inline void bench_roof(int res, const char *keep_path,
                       struct surface *surface)
{
    char temporary[] = "/tmp/facet_bench_roof_XXXXXX";
    const char *path = keep_path;
    FILE *out;
    if (path == NULL) {
        int fd = mkstemp(temporary);
        out = fd >= 0 ? fdopen(fd, "w") : NULL;
        path = temporary;
    } else {
        out = fopen(path, "w");
    }
    struct facet_error err;
    if (out == NULL || example_write("roof", res, out, &err) != FACET_OK) {
        fprintf(stderr, "bench: cannot write the roof\n");
        exit(1);
    }
    fclose(out);
    struct mesh_options options = {UNITS_M, NULL, NULL};
    int rc = surface_open(path, &options, surface, &err);
    if (keep_path == NULL)
        unlink(path);
    if (rc == FACET_OK)
        rc = surface_prepare(surface, 0, PARAM_AUTO, &err);
    if (rc != FACET_OK) {
        fprintf(stderr, "bench: %s\n", err.message);
        exit(1);
    }
}

#endif
