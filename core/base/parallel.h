/*
 * parallel.h: running a few jobs at once, one thread each.
 *
 * The jobs are an array of structs the caller owns; each thread runs the
 * caller's function on one element. Job 0 runs on the calling thread, so
 * one job costs no thread at all, and a job whose thread cannot start runs
 * on the calling thread afterwards: the work is always done, only perhaps
 * not in parallel. The caller collects results (and errors) from its
 * structs when parallel_run returns.
 */
#ifndef FACET_PARALLEL_H
#define FACET_PARALLEL_H

#include <stddef.h>

#include "core/base/error.h"

/* The most jobs parallel_run runs at once. */
#define PARALLEL_MAX 64

/* Runs run(jobs + k * size) for k in 0..n-1 (n at most PARALLEL_MAX,
 * asserted) and returns when all are done. */
void parallel_run(void *jobs, size_t size, int n, void (*run)(void *job));

/* Threads worth starting for work on the online CPUs: at least 1, at most
 * limit. */
int parallel_cpus(int limit);

/* jobs as threads for pieces of work: at least 1, at most PARALLEL_MAX
 * and at most pieces (one thread a piece is the most that can help). */
int parallel_jobs(int jobs, size_t pieces);

/* A job's first failure over the pieces it took in rising order (each job
 * keeps one, caller-owned in its struct): the piece, or SIZE_MAX for none,
 * and its code and message. */
struct parallel_failure {
    size_t piece;
    int rc;
    struct facet_error err;
};

/* No failure yet. */
void parallel_failure_clear(struct parallel_failure *failure);

/* The failure of the least piece among n jobs' (the first at first, each
 * next one stride bytes on: the member of the caller's job structs), so
 * that the error reported does not depend on which thread took what:
 * copies its message into *err and returns its code, or FACET_OK when no
 * job failed. */
int parallel_first_failure(const struct parallel_failure *first,
                           size_t stride, int n, struct facet_error *err);

#endif
