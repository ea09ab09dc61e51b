/*
 * signals.c: the stop flag. See signals.h.
 */
#include "signals.h"

#include <signal.h>
#include <stdatomic.h>
#include <stddef.h>
#include <string.h>

/* Atomic, not a sig_atomic_t: a run has several threads, and two signals
 * sent together may land in two of them at once, each in its own handler
 * (the mask below holds only within one thread). Lock-free atomics are
 * async-signal-safe in C11. */
static atomic_int stop_signal;

static const int stop_signals[3] = {SIGINT, SIGTERM, SIGHUP};

static void on_stop(int signal_number)
{
    int none = 0;
    if (!atomic_compare_exchange_strong(&stop_signal, &none, signal_number)) {
        /* A stop was asked already, perhaps in another thread whose
         * handler has not yet put the defaults back: this is the second
         * signal, and it kills. It is blocked here until the handler
         * returns, and is then delivered with the default action. */
        struct sigaction kill_now;
        memset(&kill_now, 0, sizeof kill_now);
        kill_now.sa_handler = SIG_DFL;
        sigemptyset(&kill_now.sa_mask);
        sigaction(signal_number, &kill_now, NULL);
        raise(signal_number);
        return;
    }
    /* The first signal asks for a stop; the next one kills at once, as
     * it would without Facet's handler, for a user who will not wait for
     * the stop to be heard. That loses nothing a kill -9 would not, and
     * Facet survives those: every option is committed in an SQLite
     * transaction, so the file holds whole batches only; a run left
     * "running" by a dead writer is marked interrupted by the next one
     * and resumes; a merge's side file is its own, OUT.db is replaced
     * only by an atomic rename, and a later merge removes a side file
     * whose process is gone. sigaction is async-signal-safe. */
    struct sigaction action;
    memset(&action, 0, sizeof action);
    action.sa_handler = SIG_DFL;
    sigemptyset(&action.sa_mask);
    for (size_t k = 0; k < sizeof stop_signals / sizeof stop_signals[0]; k++)
        sigaction(stop_signals[k], &action, NULL);
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
    /* SIGHUP is there because an SSH session that drops sends it: the run
     * stops as for Ctrl-C, resumable, rather than dying mid-batch. The
     * other two are blocked while the handler runs, so that two signals
     * at once still count as one request. */
    for (size_t k = 0; k < sizeof stop_signals / sizeof stop_signals[0]; k++)
        sigaddset(&action.sa_mask, stop_signals[k]);
    for (size_t k = 0; k < sizeof stop_signals / sizeof stop_signals[0]; k++)
        sigaction(stop_signals[k], &action, NULL);
}

int signals_stop_requested(void)
{
    return atomic_load(&stop_signal);
}

int signals_stop_status(void)
{
    int signal_number = atomic_load(&stop_signal);
    return 128 + (signal_number ? signal_number : SIGINT);
}

int signals_stop_hook(void *context)
{
    (void)context;
    return signals_stop_requested() != 0;
}
