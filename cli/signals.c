/*
 * signals.c: the stop flag. See signals.h.
 */
#include "signals.h"

#include <signal.h>
#include <string.h>

static volatile sig_atomic_t stop_signal;

static void on_stop(int signal_number)
{
    stop_signal = signal_number;
}

void signals_catch_stop(void)
{
    struct sigaction action;
    memset(&action, 0, sizeof action);
    action.sa_handler = on_stop;
    /* A signal must not fail a system call under SQLite or a file write
     * with EINTR: the stop is honoured between batches. */
    action.sa_flags = SA_RESTART;
    sigemptyset(&action.sa_mask);
    sigaction(SIGINT, &action, NULL);
    sigaction(SIGTERM, &action, NULL);
    /* An SSH session that drops sends SIGHUP: the run stops as for
     * Ctrl-C, resumable, rather than dying mid-batch. */
    sigaction(SIGHUP, &action, NULL);
}

int signals_stop_requested(void)
{
    return stop_signal;
}
