/*
 * bench_project.c: a whole building, the example skin (180 faces,
 * 2,025,000 triangles at the default resolution): loading and preparing
 * it against reading its file, then one design option over all of it.
 *
 *   bench_project [RES [RUNS]]
 *
 * Writes the skin at RES quads a side per face (default 75) to a
 * temporary file, then, in a fresh child process each run (so that each
 * has its own peak RSS, read from wait4's rusage), times:
 *   - the baseline: a bare read() of the whole file into memory;
 *   - project_open: the file read and parsed once, each surface's mesh;
 *   - project_open + project_prepare: also every surface's UV, curvature
 *     and panel sums, all a search needs before its first option.
 * Reported: medians of RUNS runs (default 5) in seconds and as ratios to
 * the bare read, peak RSS in MB and as a ratio to the bare read's, and
 * the verdict on the 4 GB.
 *
 * Then one option over the building (project_option.h), the issue's
 * scale figure: the module 1.0 m x 1.1 m (about 50,000 panels; the bench
 * says how many and refuses fewer than 45,000), the paper's threshold and
 * prices, moulds shared across the faces, the gaps and kinks at every
 * joint. In one child that loads and prepares the skin once, the option
 * is evaluated RUNS times on 1 thread (the baseline) and RUNS times on 2;
 * reported are the medians of the wall and CPU times, the ratio of the
 * two, the child's peak RSS (the prepared project and the option), and
 * the verdict on the 1 s on 2 cores and 4 GB.
 */
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "bench_common.h"
#include "core/project/project.h"
#include "core/project/project_option.h"
#include "core/surface/example_skin.h"

#define MAX_RUNS 51
#define OPTION_WIDTH 1.0     /* m: the module of the scale figure */
#define OPTION_HEIGHT 1.1
#define OPTION_PANELS 45000  /* the least */
#define OPTION_SECONDS 1.0   /* the most, on 2 cores */
#define MEMORY_MB 4096       /* the 4 GB */

/* What the option child reports through its pipe. */
struct option_figures {
    int ok;
    size_t panels, count[TYPE_COUNT], moulds, joints;
    size_t moulds_by_face;  /* the families each face uses, summed */
    double max_gap_mm, max_kink_deg, cost;
    double wall[2][MAX_RUNS], cpu[2][MAX_RUNS];  /* 1 thread, 2 threads */
};

static double process_cpu_now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return (double)t.tv_sec + (double)t.tv_nsec * 1e-9;
}

/* The option's run: the skin's file and how many times. */
struct option_run {
    const char *path;
    int runs;
};

/* Loads and prepares the skin, evaluates the option runs times on 1 and
 * on 2 threads (in a child, bench_in_child), into *figures. */
static int run_option(void *context, void *figures)
{
    const char *path = ((struct option_run *)context)->path;
    int runs = ((struct option_run *)context)->runs;
    struct option_figures f;
    memset(&f, 0, sizeof f);
    struct project p;
    struct facet_error err;
    int rc = project_open(&path, 1, UNITS_M, &p, &err);
    if (rc == FACET_OK)
        rc = project_prepare(&p, 0, PARAM_AUTO, &err);
    struct surface_grid *grids = malloc(p.nsurfaces * sizeof *grids);
    if (rc == FACET_OK && grids == NULL)
        rc = facet_error_set(&err, FACET_EWORK, "out of memory");
    struct option_params params;
    option_params_defaults(&params);
    if (rc == FACET_OK)
        project_module_grids(&p, OPTION_WIDTH, OPTION_HEIGHT, grids);
    for (int threads = 1; threads <= 2 && rc == FACET_OK; threads++)
        for (int run = 0; run < runs && rc == FACET_OK; run++) {
            struct project_option option;
            double wall = bench_now(), cpu = process_cpu_now();
            rc = project_option_evaluate(&p, grids, &params, threads,
                                         &option, &err);
            f.wall[threads - 1][run] = bench_now() - wall;
            f.cpu[threads - 1][run] = process_cpu_now() - cpu;
            if (rc == FACET_OK && run == 0 && threads == 1) {
                const struct option_totals *t = &option.totals;
                f.panels = t->panels;
                for (int k = 0; k < TYPE_COUNT; k++)
                    f.count[k] = t->count[k];
                f.moulds = t->moulds;
                for (size_t i = 0; i < option.nsurfaces; i++)
                    f.moulds_by_face += option.surfaces[i].moulds_used;
                f.joints = option.joints;
                f.max_gap_mm = t->max_gap * 1000;
                f.max_kink_deg = t->max_kink * 180 / M_PI;
                f.cost = t->cost;
            }
            project_option_free(&option);
        }
    if (rc != FACET_OK)
        fprintf(stderr, "bench_project: %s\n", err.message);
    f.ok = rc == FACET_OK;
    free(grids);
    project_close(&p);
    *(struct option_figures *)figures = f;
    return f.ok ? 0 : 1;
}

/* Runs run_option in a child into *f, with its peak RSS (MB). */
static int measure_option(const char *path, int runs,
                          struct option_figures *f, double *megabytes)
{
    struct option_run run = {path, runs};
    struct rusage usage;
    if (bench_in_child(run_option, &run, f, sizeof *f, &usage) != 0)
        return -1;
    *megabytes = (double)usage.ru_maxrss / 1024;  /* KB on Linux */
    return 0;
}

enum job { BARE_READ, OPEN, OPEN_PREPARE };

static int run_job(enum job job, const char *path)
{
    if (job == BARE_READ) {
        int fd = open(path, O_RDONLY);
        struct stat st;
        if (fd < 0 || fstat(fd, &st) != 0)
            return 1;
        char *buffer = malloc((size_t)st.st_size + 1);
        size_t got = 0;
        while (buffer != NULL && got < (size_t)st.st_size) {
            ssize_t n = read(fd, buffer + got, (size_t)st.st_size - got);
            if (n <= 0)
                break;
            got += (size_t)n;
        }
        close(fd);
        volatile char sink = buffer != NULL && got > 0 ? buffer[got / 2] : 0;
        (void)sink;
        free(buffer);
        return got == (size_t)st.st_size ? 0 : 1;
    }
    struct project p;
    struct facet_error err;
    int rc = project_open(&path, 1, UNITS_M, &p, &err);
    if (rc == FACET_OK && job == OPEN_PREPARE)
        rc = project_prepare(&p, 0, PARAM_AUTO, &err);
    if (rc != FACET_OK)
        fprintf(stderr, "bench_project: %s\n", err.message);
    project_close(&p);
    return rc == FACET_OK ? 0 : 1;
}

/* Runs job in a child; its wall time (s) and peak RSS (MB). */
static int measure(enum job job, const char *path, double *seconds,
                   double *megabytes)
{
    double start = bench_now();
    pid_t child = fork();
    if (child < 0)
        return -1;
    if (child == 0)
        _exit(run_job(job, path));
    int status;
    struct rusage usage;
    if (wait4(child, &status, 0, &usage) != child || !WIFEXITED(status) ||
        WEXITSTATUS(status) != 0)
        return -1;
    *seconds = bench_now() - start;
    *megabytes = (double)usage.ru_maxrss / 1024;  /* KB on Linux */
    return 0;
}

int main(int argc, char **argv)
{
    int res = argc > 1 ? atoi(argv[1]) : SKIN_DEFAULT_RES;
    int runs = argc > 2 ? atoi(argv[2]) : 5;
    if (runs < 1 || runs > MAX_RUNS)
        runs = 5;
    char path[] = "/tmp/facet_bench_skin_XXXXXX";
    int fd = mkstemp(path);
    if (fd < 0)
        return 1;
    FILE *out = fdopen(fd, "w");
    struct facet_error err;
    double start = bench_now();
    if (out == NULL || skin_write(res, out, &err) != FACET_OK) {
        remove(path);
        return 1;
    }
    fclose(out);
    double write_time = bench_now() - start;
    struct stat st;
    stat(path, &st);
    printf("skin: %d faces, %d x %d quads each, %.0f triangles, %.0f MB "
           "of OBJ written in %.2f s\n", SKIN_FACES, res, res,
           2.0 * res * res * SKIN_FACES, (double)st.st_size / 1e6,
           write_time);

    const char *label[3] = {"bare read of the file (baseline)",
                            "project_open (parse, meshes)",
                            "project_open + project_prepare"};
    double seconds[3][MAX_RUNS], rss[3][MAX_RUNS];
    for (int run = 0; run < runs; run++)
        for (int job = 0; job < 3; job++)
            if (measure((enum job)job, path, &seconds[job][run],
                        &rss[job][run]) != 0) {
                fprintf(stderr, "bench_project: %s failed\n", label[job]);
                remove(path);
                return 1;
            }
    double t[3], m[3];
    for (int job = 0; job < 3; job++) {
        t[job] = bench_median(seconds[job], runs);
        m[job] = bench_median(rss[job], runs);
    }
    printf("%-36s %9s %7s %10s %7s\n", "median of runs", "time s",
           "ratio", "peak MB", "ratio");
    for (int job = 0; job < 3; job++)
        printf("%-36s %9.3f %7.1f %10.0f %7.1f\n", label[job], t[job],
               t[job] / t[0], m[job], m[job] / m[0]);
    printf("verdict: prepared skin in %.0f MB of the issue's %d: %s\n",
           m[2], MEMORY_MB, m[2] < MEMORY_MB ? "met" : "NOT met");

    static struct option_figures f;
    double option_mb;
    if (measure_option(path, runs, &f, &option_mb) != 0) {
        fprintf(stderr, "bench_project: the option over the skin failed\n");
        remove(path);
        return 1;
    }
    remove(path);
    printf("\none option over the skin: module %.1f m x %.1f m, %zu panels "
           "(FP %zu, SP %zu, DP %zu),\n  %zu moulds shared across the "
           "faces (counted face by face, %zu), %zu joints (largest gap "
           "%.2f mm, kink %.2f deg), cost %.0f USD\n", OPTION_WIDTH,
           OPTION_HEIGHT, f.panels, f.count[TYPE_FP], f.count[TYPE_SP],
           f.count[TYPE_DP], f.moulds, f.moulds_by_face, f.joints,
           f.max_gap_mm, f.max_kink_deg, f.cost);
    double wall[2], cpu[2];
    for (int k = 0; k < 2; k++) {
        wall[k] = bench_median(f.wall[k], runs);
        cpu[k] = bench_median(f.cpu[k], runs);
    }
    printf("%-36s %9s %7s %10s\n", "median of runs", "wall s", "ratio",
           "cpu s");
    printf("%-36s %9.3f %7.2f %10.3f\n", "1 thread (baseline)", wall[0],
           1.0, cpu[0]);
    printf("%-36s %9.3f %7.2f %10.3f\n", "2 threads", wall[1],
           wall[1] / wall[0], cpu[1]);
    printf("peak RSS of the prepared skin and its option: %.0f MB\n",
           option_mb);
    printf("runs: %d; load average: ", runs);
    double load[3];
    if (getloadavg(load, 3) == 3)
        printf("%.2f %.2f %.2f\n", load[0], load[1], load[2]);
    else
        printf("unknown\n");
    int panels_met = f.panels >= OPTION_PANELS;
    int time_met = wall[1] <= OPTION_SECONDS;
    int memory_met = option_mb < MEMORY_MB;
    printf("verdict: %zu panels (at least %d: %s) in %.3f s on 2 threads "
           "(at most %.0f s: %s), %.0f MB (under %d: %s): %s\n", f.panels,
           OPTION_PANELS, panels_met ? "met" : "NOT met", wall[1],
           OPTION_SECONDS, time_met ? "met" : "NOT met", option_mb,
           MEMORY_MB, memory_met ? "met" : "NOT met",
           panels_met && time_met && memory_met ? "met" : "NOT met");
    return 0;
}
