/*
 * bench_nsga2.c: NSGA-II speed and quality on ZDT1.
 *
 *   bench_nsga2 [RUNS] [PROBLEM]
 *
 * Runs NSGA-II (population 100, 250 generations = 25,000 evaluations, the
 * defaults of nsga2_settings_default: SBX eta 20 with probability 0.9,
 * polynomial mutation eta 20 with probability 1/30) RUNS times (default
 * 10) with seeds 1..RUNS on ZDT1 (or PROBLEM: zdt1, zdt2, zdt3), 30
 * variables. Prints one line per run and a summary line
 *
 *   facet: evaluations/s E (best of RUNS) hypervolume H (mean) ...
 *
 * where H is the hypervolume of the final population's raw objectives
 * w.r.t. (1.1, 1.1), and "archive" the same over every evaluated point.
 * tests/bench/bench_nsga2.sh compares these with DEAP.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "core/search/nsga2.h"
#include "core/search/pareto.h"

#define PI 3.14159265358979323846
#define NVARS 30

struct zdt {
    int which;            /* 1, 2 or 3 */
    double *archive;      /* every evaluated objective pair */
    size_t evaluated;
    size_t capacity;
};

static int zdt_evaluate(void *context, size_t count, const double *vars,
                        double *objectives, double *violation,
                        struct facet_error *err)
{
    struct zdt *zdt = context;
    for (size_t i = 0; i < count; i++) {
        const double *x = vars + i * NVARS;
        double sum = 0;
        for (size_t k = 1; k < NVARS; k++)
            sum += x[k];
        double g = 1 + 9 * sum / (NVARS - 1);
        double f1 = x[0], r = f1 / g, h;
        if (zdt->which == 1)
            h = 1 - sqrt(r);
        else if (zdt->which == 2)
            h = 1 - r * r;
        else
            h = 1 - sqrt(r) - r * sin(10 * PI * f1);
        objectives[2 * i] = f1;
        objectives[2 * i + 1] = g * h;
        violation[i] = 0;
    }
    if (zdt->evaluated + count > zdt->capacity)
        return facet_error_set(err, FACET_EWORK, "archive full");
    memcpy(zdt->archive + 2 * zdt->evaluated, objectives,
           2 * count * sizeof(double));
    zdt->evaluated += count;
    return 0;
}

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec + t.tv_nsec * 1e-9;
}

int main(int argc, char **argv)
{
    int runs = argc > 1 ? atoi(argv[1]) : 10;
    int which = 1;
    if (argc > 2 && sscanf(argv[2], "zdt%d", &which) != 1)
        which = 0;
    if (runs < 1 || which < 1 || which > 3) {
        fprintf(stderr, "usage: bench_nsga2 [RUNS] [zdt1|zdt2|zdt3]\n");
        return 2;
    }
    double lower[NVARS] = {0}, upper[NVARS];
    for (int v = 0; v < NVARS; v++)
        upper[v] = 1;
    struct zdt zdt = {.which = which, .capacity = 25000};
    zdt.archive = malloc(2 * zdt.capacity * sizeof(double));
    struct nsga2_problem problem = {
        .nvars = NVARS, .lower = lower, .upper = upper, .nobjectives = 2,
        .evaluate = zdt_evaluate, .context = &zdt};
    struct nsga2_settings settings;
    nsga2_settings_default(&settings, NVARS);

    double best_rate = 0, sum_volume = 0, sum_archive = 0;
    double reference[2] = {1.1, 1.1};
    for (int run = 1; run <= runs; run++) {
        settings.seed = (uint64_t)run;
        zdt.evaluated = 0;
        struct nsga2_population result;
        struct facet_error err;
        double start = now();
        if (nsga2_run(&problem, &settings, NULL, NULL, NULL, &result, &err)) {
            fprintf(stderr, "bench_nsga2: %s\n", err.message);
            return 1;
        }
        double seconds = now() - start;
        double volume, archive;
        if (pareto_hypervolume(result.objectives, result.size, 2, reference,
                               &volume, &err) ||
            pareto_hypervolume(zdt.archive, zdt.evaluated, 2, reference,
                               &archive, &err)) {
            fprintf(stderr, "bench_nsga2: %s\n", err.message);
            return 1;
        }
        double rate = zdt.evaluated / seconds;
        printf("facet run %d: %zu evaluations in %.4f s, %.0f/s, "
               "hypervolume %.6f, archive %.6f\n",
               run, zdt.evaluated, seconds, rate, volume, archive);
        if (rate > best_rate)
            best_rate = rate;
        sum_volume += volume;
        sum_archive += archive;
        nsga2_free(&result);
    }
    printf("facet: evaluations/s %.0f (best of %d) hypervolume %.6f "
           "(mean of %d, ZDT%d, reference 1.1,1.1) archive %.6f\n",
           best_rate, runs, sum_volume / runs, runs, which,
           sum_archive / runs);
    free(zdt.archive);
    return 0;
}
