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

/* The most jobs parallel_run runs at once. */
#define PARALLEL_MAX 64

/* Runs run(jobs + k * size) for k in 0..n-1 (n at most PARALLEL_MAX,
 * asserted) and returns when all are done. */
void parallel_run(void *jobs, size_t size, int n, void (*run)(void *job));

/* Threads worth starting for work on the online CPUs: at least 1, at most
 * limit. */
int parallel_cpus(int limit);

#endif
