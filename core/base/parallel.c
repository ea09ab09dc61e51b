/*
 * parallel.c: running a few jobs at once. See parallel.h.
 */
#include "core/base/parallel.h"

#include <assert.h>
#include <pthread.h>
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
