/*
 * bench_classify.c: the cost of one design option, against a bare pass.
 *
 *   bench_classify [RES]
 *
 * Generates the example roof at RES x RES quads (default 224: 100,352
 * triangles), prepares it once (UV lookup, curvature), then times:
 *   - a bare pass over every triangle, summing their areas from the
 *     positions (the least any evaluation must do): the baseline;
 *   - one 37 x 49 evaluation (panelize, classify, price);
 *   - the vertex curvature, per vertex.
 * Each is the best of several runs; the evaluation is also given as a ratio
 * to the baseline, which holds across machines.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "core/example.h"
#include "core/option.h"

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec + t.tv_nsec * 1e-9;
}

static double bare_pass(const struct mesh *mesh)
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

int main(int argc, char **argv)
{
    int res = argc > 1 ? atoi(argv[1]) : 224;
    char path[] = "/tmp/facet_bench_classify_XXXXXX";
    int fd = mkstemp(path);
    FILE *out = fd >= 0 ? fdopen(fd, "w") : NULL;
    struct facet_error err;
    if (out == NULL || example_write("roof", res, out, &err) != FACET_OK) {
        fprintf(stderr, "bench_classify: cannot write the roof\n");
        return 1;
    }
    fclose(out);
    struct surface surface;
    struct mesh_options options = {UNITS_M, NULL, NULL};
    int rc = surface_open(path, &options, &surface, &err);
    unlink(path);
    if (rc == FACET_OK)
        rc = surface_prepare(&surface, 0, &err);
    if (rc != FACET_OK) {
        fprintf(stderr, "bench_classify: %s\n", err.message);
        return 1;
    }

    double best_curvature = INFINITY;
    for (int run = 0; run < 3; run++) {
        struct curvature c;
        double start = now();
        curvature_at_vertices(&surface.mesh, 0, &c, &err);
        best_curvature = fmin(best_curvature, now() - start);
        curvature_free(&c);
    }

    volatile double sink = 0;
    double best_bare = INFINITY;
    for (int run = 0; run < 50; run++) {
        double start = now();
        sink += bare_pass(&surface.mesh);
        best_bare = fmin(best_bare, now() - start);
    }

    struct option_params params;
    memset(&params, 0, sizeof params);
    params.nu = 37;
    params.nv = 49;
    params.mode = PANEL_EXTREMES;
    classify_defaults(&params.classify);
    double best_eval = INFINITY;
    struct option_totals totals;
    for (int run = 0; run < 30; run++) {
        struct panelization panels;
        double start = now();
        option_evaluate(&surface, &params, &panels, &totals, &err);
        best_eval = fmin(best_eval, now() - start);
        panelization_free(&panels);
    }
    (void)sink;

    printf("surface: roof, %zu triangles, %zu vertices, %.1f m^2\n",
           surface.mesh.ntriangles, surface.mesh.nvertices,
           surface.mesh.area);
    printf("bare pass (sum of triangle areas): %.3f ms\n", best_bare * 1e3);
    printf("one 37x49 evaluation: %.3f ms = %.1fx the bare pass "
           "(%zu panels: %zu FP, %zu SP, %zu DP)\n", best_eval * 1e3,
           best_eval / best_bare, totals.panels, totals.count[TYPE_FP],
           totals.count[TYPE_SP], totals.count[TYPE_DP]);
    printf("curvature: %.3f ms for %zu vertices = %.2f us per vertex "
           "(done once per surface)\n", best_curvature * 1e3,
           surface.mesh.nvertices,
           best_curvature * 1e6 / (double)surface.mesh.nvertices);
    surface_close(&surface);
    return 0;
}
