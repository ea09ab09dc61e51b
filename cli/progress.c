/*
 * progress.c: the progress bar. See progress.h.
 */
#include "progress.h"

#include <stdio.h>
#include <time.h>
#include <unistd.h>

double progress_now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + (double)t.tv_nsec * 1e-9;
}

void progress_start(struct progress *p, const char *what,
                    int64_t done_before)
{
    p->what = what;
    p->terminal = isatty(STDERR_FILENO);
    p->started = progress_now();
    p->last_drawn = 0;
    p->first_done = done_before;
    p->finished = 0;
}

static void draw(struct progress *p, int64_t done, int64_t total, int last)
{
    double elapsed = progress_now() - p->started;
    double rate = elapsed > 0 ? (double)(done - p->first_done) / elapsed : 0;
    double left = rate > 0 ? (double)(total - done) / rate : 0;
    double fraction = total > 0 ? (double)done / (double)total : 1;
    if (p->terminal) {
        char bar[31];
        int filled = (int)(fraction * 30 + 0.5);
        for (int k = 0; k < 30; k++)
            bar[k] = k < filled ? '#' : '-';
        bar[30] = '\0';
        fprintf(stderr, "\r[%s] %lld/%lld %s  %.1f/s  ETA %.0f s  ", bar,
                (long long)done, (long long)total, p->what, rate,
                last ? 0.0 : left);
        if (last)
            fputc('\n', stderr);
    } else {
        fprintf(stderr, "progress: %lld/%lld %s (%.0f%%), %.1f/s, %s %.0f s\n",
                (long long)done, (long long)total, p->what, 100 * fraction,
                rate, last ? "took" : "ETA", last ? elapsed : left);
    }
    fflush(stderr);
}

void progress_update(struct progress *p, int64_t done, int64_t total)
{
    double now = progress_now();
    double interval = p->terminal ? 0.1 : 5.0;
    if (now - p->last_drawn < interval)
        return;
    p->last_drawn = now;
    draw(p, done, total, 0);
}

void progress_finish(struct progress *p, int64_t done, int64_t total)
{
    if (p->finished)
        return;
    p->finished = 1;
    draw(p, done, total, 1);
}
