/*
 * stop.h: a caller's request that a long computation stop.
 *
 * Core never learns of signals, terminals or threads of the front-end: a
 * caller that lets its user interrupt reading or preparing a surface hands
 * down a struct facet_stop, and the computation asks it often enough (about
 * every few milliseconds of work) that a stop is heard within a fraction
 * of a second. What it has built so far is released, and the function
 * returns FACET_ESTOP: not a failure, nothing written, the caller says what
 * was interrupted. A NULL stop, or one whose requested is NULL, never
 * fires.
 *
 * requested may be called from several threads at once and often: it must
 * be cheap and thread-safe (reading a flag a signal handler sets, or one
 * under the caller's lock). The struct is the caller's and must outlive
 * the call it is given to.
 */
#ifndef FACET_STOP_H
#define FACET_STOP_H

#include "core/base/error.h"

struct facet_stop {
    int (*requested)(void *context);  /* non-zero: stop now */
    void *context;
};

/* Whether stop asks to stop now; 0 for NULL. */
int facet_stop_requested(const struct facet_stop *stop);

/* FACET_OK, or when stop asks to stop, FACET_ESTOP with err saying so. */
int facet_stop_check(const struct facet_stop *stop, struct facet_error *err);

/* Sets err to FACET_ESTOP ("stopped on request") and returns it: for a
 * computation that saw the request on another thread. */
int facet_stop_error(struct facet_error *err);

#endif
