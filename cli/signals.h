/*
 * signals.h: SIGINT and SIGTERM as a request to stop, not a kill.
 *
 * Long commands (optimize) install the handler, check signals_stop_requested
 * between batches, commit what they have and mark the run interrupted. The
 * flag is the one piece of global state outside main: a signal handler can
 * reach nothing else.
 */
#ifndef FACET_SIGNALS_H
#define FACET_SIGNALS_H

/* Installs handlers for SIGINT and SIGTERM that set the stop flag. */
void signals_catch_stop(void);

/* Non-zero once SIGINT or SIGTERM arrived; which one is returned. */
int signals_stop_requested(void);

#endif
