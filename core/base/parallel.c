/*
 * parallel.c: running a few jobs at once. See parallel.h.
 */
#include "core/base/parallel.h"

#include <assert.h>
#include <pthread.h>
#include <stdint.h>
#include <unistd.h>

struct call {
    void (*run)(void *job);
    void *job;
};

static void *call_thread(void *argument)
{
    struct call *call = argument;
    call->run(call->job);
    return NULL;
}

void parallel_run(void *jobs, size_t size, int n, void (*run)(void *job))
{
    /* Jobs past PARALLEL_MAX would silently not run. */
    assert(n <= PARALLEL_MAX);
    pthread_t thread[PARALLEL_MAX];
    int started[PARALLEL_MAX] = {0};
    struct call call[PARALLEL_MAX];
    char *job = jobs;
    for (int k = 1; k < n; k++) {
        call[k] = (struct call){run, job + (size_t)k * size};
        started[k] = pthread_create(&thread[k], NULL, call_thread,
                                    &call[k]) == 0;
    }
    if (n > 0)
        run(job);
    for (int k = 1; k < n; k++) {
        if (started[k])
            pthread_join(thread[k], NULL);
        else
            run(job + (size_t)k * size);
    }
}

int parallel_cpus(int limit)
{
    long cpus = sysconf(_SC_NPROCESSORS_ONLN);
    if (cpus < 1)
        cpus = 1;
    return cpus < limit ? (int)cpus : limit;
}

int parallel_jobs(int jobs, size_t pieces)
{
    if (jobs > PARALLEL_MAX)
        jobs = PARALLEL_MAX;
    if (jobs > 0 && (size_t)jobs > pieces)
        jobs = (int)pieces;
    return jobs < 1 ? 1 : jobs;
}

void parallel_failure_clear(struct parallel_failure *failure)
{
    failure->piece = SIZE_MAX;
    failure->rc = FACET_OK;
    facet_error_clear(&failure->err);
}

int parallel_first_failure(const struct parallel_failure *first,
                           size_t stride, int n, struct facet_error *err)
{
    const struct parallel_failure *least = NULL;
    for (int k = 0; k < n; k++) {
        const struct parallel_failure *f =
            (const struct parallel_failure *)((const char *)first +
                                              (size_t)k * stride);
        if (f->piece != SIZE_MAX && (least == NULL || f->piece < least->piece))
            least = f;
    }
    if (least == NULL)
        return FACET_OK;
    *err = least->err;
    return least->rc;
}
