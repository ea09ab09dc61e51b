/*
 * bench_front.c: the end of an NSGA-II run, where its Pareto options'
 * panels are stored (issue 18).
 *
 *   bench_front [RES] [POPULATION] [GENERATIONS]
 *
 * A study as `facet optimize --method nsga2` runs it (study_start, every
 * default of a new run: panels as built, moulds, the front's panels
 * stored) on the example roof at RES x RES quads (default 224: 100,352
 * triangles) over the paper's grids with a continuous threshold, 1:5 mm,
 * which makes a front of hundreds of options; POPULATION x GENERATIONS
 * (default 100 x 12) on 2 threads, into a fresh file. The study's stage
 * hook times each stage on the wall clock. It reports:
 *   - the run, the search, and the last stage, "storing the Pareto
 *     options' panels" (which evaluates each Pareto option again to keep
 *     its panels), as a share of the run (issue 18's goal: at most 10 %);
 *   - the process's peak memory (getrusage; goal: at most 300 MB), and the
 *     file's size;
 *   - the baseline: the search itself, evaluations per second.
 */
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include "bench_common.h"
#include "tests/support/temp_dir.h"
#include "study/study.h"

#define GOAL_SHARE 0.10
#define GOAL_PEAK_MB 300.0

/* When each stage began, by name, on the wall clock. */
struct stage_clock {
    double begin;
    double searching, pareto;   /* starts; 0 until met */
    int64_t total;
};

static void on_stage(void *context, const char *what)
{
    struct stage_clock *clock = context;
    if (strcmp(what, "evaluating options") == 0 && clock->searching == 0)
        clock->searching = bench_now();
    else if (strcmp(what, "storing the Pareto options' panels") == 0)
        clock->pareto = bench_now();
}

static void on_progress(void *context, const struct optimize_progress *p)
{
    ((struct stage_clock *)context)->total = p->total;
}

int main(int argc, char **argv)
{
    int res = argc > 1 ? atoi(argv[1]) : 224;
    int population = argc > 2 ? atoi(argv[2]) : 100;
    int generations = argc > 3 ? atoi(argv[3]) : 12;
    if (res < 2 || population < 4 || generations < 1) {
        fprintf(stderr, "usage: bench_front [RES] [POPULATION >= 4] "
                "[GENERATIONS >= 1]\n");
        return 2;
    }
    char dir[256], obj[300], db[300];
    if (temp_dir_make(dir, sizeof dir, "bench_front") != 0) {
        fprintf(stderr, "bench_front: cannot make a folder in /tmp\n");
        return 1;
    }
    snprintf(obj, sizeof obj, "%s/roof.obj", dir);
    snprintf(db, sizeof db, "%s/front.db", dir);
    struct surface surface;
    bench_roof(res, obj, &surface);  /* written for the study to read */
    double bare = bench_bare_best(&surface.mesh, 50);
    size_t triangles = surface.mesh.ntriangles;
    surface_close(&surface);

    struct study_request request;
    study_request_defaults(&request);
    request.surface_path = obj;
    struct optimize_settings *s = &request.settings;
    s->space.t_min_mm = 1;
    s->space.t_max_mm = 5;
    s->space.t_step_mm = 0;
    s->method = METHOD_NSGA2;
    s->population = population;
    s->generations = generations;
    s->jobs = 2;

    struct facet_error err;
    struct store *store;
    if (store_open(db, &store, &err) != FACET_OK) {
        fprintf(stderr, "bench_front: %s\n", err.message);
        return 1;
    }
    struct stage_clock clock = {bench_now(), 0, 0, 0};
    struct study_hooks hooks = {&clock, on_stage, on_progress, NULL, NULL,
                                NULL, NULL};
    int64_t run;
    enum optimize_outcome outcome;
    int rc = study_start(store, &request, &hooks, &run, &outcome, &err);
    double end = bench_now();
    struct run_info info;
    if (rc == FACET_OK)
        rc = store_run_get(store, run, &info, &err);
    store_close(store);
    if (rc != FACET_OK || clock.pareto == 0 || clock.searching == 0) {
        fprintf(stderr, "bench_front: %s\n",
                rc != FACET_OK ? err.message : "the run met no Pareto stage");
        return 1;
    }
    struct stat st;
    double file_mb = stat(db, &st) == 0 ? (double)st.st_size / 1e6 : -1;
    struct rusage usage;
    getrusage(RUSAGE_SELF, &usage);
    double peak_mb = (double)usage.ru_maxrss / 1024;
    temp_dir_remove(dir);

    double whole = end - clock.begin, search = clock.pareto - clock.searching;
    double pareto = end - clock.pareto, share = pareto / whole;
    double load[1] = {-1};
    getloadavg(load, 1);
    printf("surface: roof, %zu triangles; NSGA-II %d x %d over u 20:40 x "
           "v 35:50 x t 1:5 mm, 2 threads; load average %.2f\n", triangles,
           population, generations, load[0]);
    printf("run: %.2f s wall: %lld options, %lld Pareto; the search %.2f s "
           "(%.0f options/s, %.0fx a bare pass per option); the file %.0f MB\n",
           whole, (long long)info.options, (long long)info.pareto_options,
           search, (double)info.options / search,
           search / (double)info.options / bare, file_mb);
    printf("storing the Pareto options' panels: %.2f s = %.0f%% of the run "
           "(target: at most %.0f%%: %s)\n", pareto, 100 * share,
           100 * GOAL_SHARE, share <= GOAL_SHARE ? "met" : "not met");
    printf("peak memory of the process: %.0f MB (target: at most %.0f MB: "
           "%s)\n", peak_mb, GOAL_PEAK_MB,
           peak_mb <= GOAL_PEAK_MB ? "met" : "not met");
    return 0;
}
