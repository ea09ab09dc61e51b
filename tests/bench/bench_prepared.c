/*
 * bench_prepared.c: a building prepared once and reused (issue 31 item
 * 3): how long a run takes before it can evaluate its first option, the
 * first time (the files read and prepared, the cache written beside the
 * database) against the second (the cache read, checked and the rest of
 * the preparation remade), on the example skin.
 *
 *   bench_prepared [RES [RUNS]]
 *
 * Writes the skin at RES quads a side per face (default 75: 2,025,000
 * triangles, 150 MB) to a temporary folder; then RUNS times (default 5)
 * each, in a fresh child process as a `facet optimize` would be:
 *   - first: no cache; study_project_prepared reads the file, prepares
 *     every surface and writes the cache beside runs.db;
 *   - second: the cache there; study_project_prepared hashes the file,
 *     reads the cache, checks it and makes the fit points (format 3
 *     keeps the rest).
 * study_project_prepared is what `facet optimize`, a resume and the
 * workbench's map call before their first evaluation. Reported: the
 * medians (wall and CPU), their ratio, the cache's size, and the verdict
 * on the 2 s for the second.
 */
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
#include "study/study_prepared.h"

#define MAX_RUNS 51
#define GOAL_SECONDS 2.0  /* the issue's: a second run starts within */

struct figures {
    int ok, reused;
    double wall, cpu;
};

static int reused_note;

static void on_note(void *context, const char *text)
{
    (void)context;
    if (strstr(text, "reused the prepared building") != NULL)
        reused_note = 1;
}

static double cpu_now(void)
{
    struct rusage u;
    getrusage(RUSAGE_SELF, &u);
    return (double)u.ru_utime.tv_sec + (double)u.ru_utime.tv_usec * 1e-6 +
           (double)u.ru_stime.tv_sec + (double)u.ru_stime.tv_usec * 1e-6;
}

/* A run's start: the building's files and its database. */
struct start {
    const char *obj, *db;
};

/* One run's start (in a child, bench_in_child) into *figures. */
static int start_run(void *context, void *figures)
{
    const char *obj = ((struct start *)context)->obj;
    const char *db = ((struct start *)context)->db;
    struct figures f = {0, 0, 0, 0};
    struct study_hooks hooks = {NULL, NULL, NULL, NULL, NULL, NULL, on_note};
    struct study_prepare want = {db, &obj, 1, NULL, UNITS_M, 0, 0,
                                 PARAM_AUTO};
    struct project p;
    char digest[1][65];
    struct facet_error err;
    double wall = bench_now(), cpu = cpu_now();
    int rc = study_project_prepared(&want, &hooks, &p, digest, &err);
    f.wall = bench_now() - wall;
    f.cpu = cpu_now() - cpu;
    if (rc != FACET_OK)
        fprintf(stderr, "bench_prepared: %s\n", err.message);
    f.ok = rc == FACET_OK;
    f.reused = reused_note;
    project_close(&p);
    *(struct figures *)figures = f;
    return f.ok ? 0 : 1;
}

static int measure(const char *obj, const char *db, struct figures *f)
{
    struct start start = {obj, db};
    return bench_in_child(start_run, &start, f, sizeof *f, NULL);
}

/* The cache files beside db: removed (remove 1) or their total size. */
static long long caches(const char *folder, int remove)
{
    char command[512];
    snprintf(command, sizeof command,
             remove ? "rm -f %s/facet-prepared-*"
                    : "cat %s/facet-prepared-* 2>/dev/null | wc -c",
             folder);
    FILE *p = popen(command, "r");
    if (p == NULL)
        return -1;
    long long n = 0;
    if (!remove && fscanf(p, "%lld", &n) != 1)
        n = -1;
    pclose(p);
    return n;
}

static void die(const char *what)
{
    fprintf(stderr, "bench_prepared: %s\n", what);
    exit(1);
}

int main(int argc, char **argv)
{
    int res = argc > 1 ? atoi(argv[1]) : SKIN_DEFAULT_RES;
    int runs = argc > 2 ? atoi(argv[2]) : 5;
    if (res < 1 || res > SKIN_MAX_RES || runs < 1 || runs > MAX_RUNS)
        die("usage: bench_prepared [RES [RUNS]]");
    char folder[] = "/tmp/facet_bench_prepared_XXXXXX";
    if (mkdtemp(folder) == NULL)
        die("cannot make a temporary folder");
    char obj[128], db[128];
    snprintf(obj, sizeof obj, "%s/skin.obj", folder);
    snprintf(db, sizeof db, "%s/runs.db", folder);
    FILE *out = fopen(obj, "w");
    struct facet_error err;
    if (out == NULL || skin_write(res, out, &err) != FACET_OK)
        die("cannot write the skin");
    fclose(out);

    double first_wall[MAX_RUNS], first_cpu[MAX_RUNS];
    double second_wall[MAX_RUNS], second_cpu[MAX_RUNS];
    int failed = 0, all_reused = 1;
    for (int r = 0; r < runs && !failed; r++) {
        struct figures f;
        caches(folder, 1);
        failed |= measure(obj, db, &f) != 0 || f.reused;
        first_wall[r] = f.wall;
        first_cpu[r] = f.cpu;
    }
    long long bytes = caches(folder, 0);
    for (int r = 0; r < runs && !failed; r++) {
        struct figures f;
        failed |= measure(obj, db, &f) != 0;
        all_reused &= f.reused;
        second_wall[r] = f.wall;
        second_cpu[r] = f.cpu;
    }
    char command[160];
    snprintf(command, sizeof command, "rm -rf %s", folder);
    if (system(command) != 0)
        fprintf(stderr, "bench_prepared: could not remove %s\n", folder);
    if (failed || !all_reused) {
        printf("  bench_prepared: FAILED (%s)\n",
               failed ? "a run failed" : "a second run did not reuse");
        return 1;
    }
    double fw = bench_median(first_wall, runs);
    double fc = bench_median(first_cpu, runs);
    double sw = bench_median(second_wall, runs);
    double sc = bench_median(second_cpu, runs);
    printf("  skin at res %d, cache %.0f MB; medians of %d runs each\n",
           res, (double)bytes / 1e6, runs);
    printf("  first run's start (read, prepare, keep): %7.2f s wall, "
           "%7.2f s CPU\n", fw, fc);
    printf("  second run's start (cache read, checked): %6.2f s wall, "
           "%7.2f s CPU (%.2fx the first's wall, %.2fx its CPU)\n", sw, sc,
           sw / fw, sc / fc);
    printf("  verdict (issue 31): a second run starts evaluating within "
           "%.0f s: %.2f s, %s\n", GOAL_SECONDS, sw,
           sw <= GOAL_SECONDS ? "met" : "not met");
    return 0;
}
