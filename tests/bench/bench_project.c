/*
 * bench_project.c: loading and preparing a whole building, the example
 * skin (180 faces, 2,025,000 triangles at the default resolution), against
 * reading its file.
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
#include "core/surface/example_skin.h"

#define MAX_RUNS 51

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
    remove(path);
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
    printf("runs: %d; load average: ", runs);
    double load[3];
    if (getloadavg(load, 3) == 3)
        printf("%.2f %.2f %.2f\n", load[0], load[1], load[2]);
    else
        printf("unknown\n");
    printf("verdict: prepared skin in %.0f MB of the issue's 4096: %s\n",
           m[2], m[2] < 4096 ? "met" : "NOT met");
    return 0;
}
