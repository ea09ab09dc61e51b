/*
 * test_parallel.c: the one CPU count and the one thread fan-out of Facet
 * (core/base/parallel.h), which curvature, the UV check, the OBJ reader,
 * `facet optimize` and the TUI's New run all use: the count is the online
 * CPUs as sysconf reports them, clamped to [1, limit]; every job runs
 * exactly once, job 0 on the calling thread; more jobs than PARALLEL_MAX
 * stop the program (they were silently left undone); the threads for
 * pieces of work, and the failure reported from several jobs', by hand.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <fcntl.h>
#include <pthread.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include "core/base/parallel.h"

static void test_cpus_clamped(void **state)
{
    (void)state;
    long online = sysconf(_SC_NPROCESSORS_ONLN);
    assert_int_equal(parallel_cpus(1), 1);
    for (int limit = 1; limit <= 2 * PARALLEL_MAX; limit++) {
        long expect = online < 1 ? 1 : online < limit ? online : limit;
        assert_int_equal(parallel_cpus(limit), expect);
    }
}

struct job {
    int runs;
    pthread_t thread;
};

static void run_job(void *argument)
{
    struct job *job = argument;
    job->runs++;
    job->thread = pthread_self();
}

static void test_every_job_once(void **state)
{
    (void)state;
    static const int counts[] = {0, 1, 2, 7, PARALLEL_MAX};
    for (size_t c = 0; c < sizeof counts / sizeof counts[0]; c++) {
        struct job job[PARALLEL_MAX + 1] = {{0}};
        parallel_run(job, sizeof job[0], counts[c], run_job);
        for (int k = 0; k < counts[c]; k++)
            assert_int_equal(job[k].runs, 1);
        assert_int_equal(job[counts[c]].runs, 0);
        if (counts[c] > 0)
            assert_true(pthread_equal(job[0].thread, pthread_self()));
    }
}

/* PARALLEL_MAX + 1 jobs: the assert stops a child process with SIGABRT
 * rather than running 64 of them and returning as if all were done. */
static void test_too_many_jobs_stop(void **state)
{
    (void)state;
    pid_t child = fork();
    assert_true(child >= 0);
    if (child == 0) {
        int null = open("/dev/null", O_WRONLY);
        if (null >= 0)
            dup2(null, STDERR_FILENO);
        struct job job[PARALLEL_MAX + 1] = {{0}};
        parallel_run(job, sizeof job[0], PARALLEL_MAX + 1, run_job);
        _exit(job[PARALLEL_MAX].runs == 1 ? 0 : 3);
    }
    int status;
    assert_int_equal(waitpid(child, &status, 0), child);
    assert_true(WIFSIGNALED(status));
    assert_int_equal(WTERMSIG(status), SIGABRT);
}

/* Threads for pieces of work: 1 .. PARALLEL_MAX, no more than the
 * pieces. */
static void test_jobs_clamped(void **state)
{
    (void)state;
    assert_int_equal(parallel_jobs(0, 10), 1);
    assert_int_equal(parallel_jobs(-3, 10), 1);
    assert_int_equal(parallel_jobs(2, 0), 1);
    assert_int_equal(parallel_jobs(2, 1), 1);
    assert_int_equal(parallel_jobs(2, 180), 2);
    assert_int_equal(parallel_jobs(8, 3), 3);
    assert_int_equal(parallel_jobs(PARALLEL_MAX + 5, 1000), PARALLEL_MAX);
}

/* Failures kept in the jobs' own structs: the least piece's is
 * reported, whichever job holds it. */
struct failing_job {
    int other;
    struct parallel_failure failure;
    double more;
};

static void test_first_failure(void **state)
{
    (void)state;
    struct failing_job jobs[3];
    for (int k = 0; k < 3; k++)
        parallel_failure_clear(&jobs[k].failure);
    struct facet_error err;
    facet_error_clear(&err);
    assert_int_equal(parallel_first_failure(&jobs[0].failure,
                                            sizeof jobs[0], 3, &err),
                     FACET_OK);
    assert_string_equal(err.message, "");
    jobs[0].failure.piece = 9;
    jobs[0].failure.rc = facet_error_set(&jobs[0].failure.err, FACET_EWORK,
                                         "piece 9");
    jobs[2].failure.piece = 4;
    jobs[2].failure.rc = facet_error_set(&jobs[2].failure.err, FACET_EINPUT,
                                         "piece 4");
    assert_int_equal(parallel_first_failure(&jobs[0].failure,
                                            sizeof jobs[0], 3, &err),
                     FACET_EINPUT);
    assert_string_equal(err.message, "piece 4");
    /* Only the first two jobs: piece 9. */
    assert_int_equal(parallel_first_failure(&jobs[0].failure,
                                            sizeof jobs[0], 2, &err),
                     FACET_EWORK);
    assert_string_equal(err.message, "piece 9");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_cpus_clamped),
        cmocka_unit_test(test_every_job_once),
        cmocka_unit_test(test_too_many_jobs_stop),
        cmocka_unit_test(test_jobs_clamped),
        cmocka_unit_test(test_first_failure),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
