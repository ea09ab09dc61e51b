/*
 * signals.h: SIGINT, SIGTERM and SIGHUP as a request to stop, not a kill.
 *
 * Long commands (optimize, merge, export) install the handler and, through
 * their stop hook, hear it between batches, between options and every few
 * milliseconds while a surface is read and prepared or an option's panels
 * are built (a 2000 x 2000 grid takes tens of seconds); they commit what
 * they have and mark the run interrupted (a merge removes its side file).
 * The first signal asks; a second one kills at once, as without the
 * handler (signals.c says why that loses nothing). The flag is the one
 * piece of global state outside main: a signal handler can reach nothing
 * else.
 */
#ifndef FACET_SIGNALS_H
#define FACET_SIGNALS_H

/* Installs handlers for SIGINT, SIGTERM and SIGHUP that set the stop
 * flag and put back the default action for the next of them. */
void signals_catch_stop(void);

/* Non-zero once one of them arrived: the signal's number. */
int signals_stop_requested(void);

/* signals_stop_requested as a study's stop hook (study.h's
 * should_stop): context is not used. */
int signals_stop_hook(void *context);

/* 128 + the signal that asked to stop, as a shell reports a command
 * killed by it: 130 for Ctrl-C (or a stop without a signal), 129 for a
 * dropped SSH session, 143 for SIGTERM. */
int signals_stop_status(void);

#endif
