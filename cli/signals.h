/*
 * signals.h: SIGINT, SIGTERM and SIGHUP as a request to stop, not a kill.
 *
 * Long commands (optimize) install the handler, check signals_stop_requested
 * between batches, commit what they have and mark the run interrupted. The
 * flag is the one piece of global state outside main: a signal handler can
 * reach nothing else.
 */
#ifndef FACET_SIGNALS_H
#define FACET_SIGNALS_H

/* Installs handlers for SIGINT, SIGTERM and SIGHUP that set the stop
 * flag. */
void signals_catch_stop(void);

/* Non-zero once one of them arrived: the signal's number. */
int signals_stop_requested(void);

#endif
