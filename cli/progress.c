/*
 * progress.c: the progress bar. See progress.h.
 */
#include "progress.h"

#include <stdio.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "shown.h"
double progress_now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + (double)t.tv_nsec * 1e-9;
}

void progress_fit_add(struct progress_fit *fit, double n, double w,
                      double t)
{
    fit->nn += n * n;
    fit->nw += n * w;
    fit->ww += w * w;
    fit->tn += t * n;
    fit->tw += t * w;
}

double progress_fit_left(const struct progress_fit *fit, double items_left,
                         double work_left)
{
    if (!(fit->ww > 0))
        return -1;
    double det = fit->nn * fit->ww - fit->nw * fit->nw;
    /* Told apart only when the work per item varies enough. */
    if (det > 1e-6 * fit->nn * fit->ww) {
        double per_item = (fit->tn * fit->ww - fit->tw * fit->nw) / det;
        double per_work = (fit->nn * fit->tw - fit->nw * fit->tn) / det;
        if (per_item >= 0 && per_work >= 0)
            return per_item * (items_left > 0 ? items_left : 0) +
                   per_work * (work_left > 0 ? work_left : 0);
    }
    return fit->tw / fit->ww * (work_left > 0 ? work_left : 0);
}

void progress_start(struct progress *p, const char *what,
                    int64_t done_before, double work_before)
{
    p->what = what;
    p->terminal = isatty(STDERR_FILENO);
    p->started = progress_now();
    p->last_drawn = 0;
    p->first_done = done_before;
    p->first_work = work_before;
    p->drawn_width = 0;
    p->work_done = work_before;
    p->work_total = work_before;
    memset(&p->fit, 0, sizeof p->fit);
    p->finished = 0;
}

static void draw(struct progress *p, int64_t done, int64_t total, int last)
{
    double elapsed = progress_now() - p->started;
    int64_t since = done - p->first_done;
    /* A rate needs work done over a time worth the name; until then the
     * line says so rather than "0.0/s, ETA 0 s". */
    int measured = since > 0 && (elapsed >= 0.05 || (last && elapsed > 0));
    double rate = measured ? (double)since / elapsed : 0;
    char rate_text[32] = "-/s", left_text[32] = "-";
    if (measured) {
        snprintf(rate_text, sizeof rate_text, "%.1f/s", rate);
        /* By the options and the work left, at the costs fitted to what
         * was done: finer grids take longer. */
        double left = progress_fit_left(&p->fit, (double)(total - done),
                                        p->work_total - p->work_done);
        if (left >= 0)
            snprintf(left_text, sizeof left_text, "%.0f s", left);
    }
    double fraction = total > 0 ? (double)done / (double)total : 1;
    if (p->terminal) {
        char bar[31];
        int filled = (int)(fraction * 30 + 0.5);
        for (int k = 0; k < 30; k++)
            bar[k] = k < filled ? '#' : '-';
        bar[30] = '\0';
        if (last)
            fprintf(stderr, "\r[%s] %lld/%lld %s  %s  took %.1f s  \n", bar,
                    (long long)done, (long long)total, p->what, rate_text,
                    elapsed);
        else
            fprintf(stderr, "\r[%s] %lld/%lld %s  %s  ETA %s  ", bar,
                    (long long)done, (long long)total, p->what, rate_text,
                    left_text);
    } else if (last) {
        fprintf(stderr, "progress: %lld/%lld %s (%.0f%%), %s, took %.1f s\n",
                (long long)done, (long long)total, p->what, 100 * fraction,
                rate_text, elapsed);
    } else {
        fprintf(stderr, "progress: %lld/%lld %s (%.0f%%), %s, ETA %s\n",
                (long long)done, (long long)total, p->what, 100 * fraction,
                rate_text, left_text);
    }
    fflush(stderr);
}

void progress_update(struct progress *p, int64_t done, int64_t total,
                     double work_done, double work_total)
{
    p->work_done = work_done;
    p->work_total = work_total;
    double now = progress_now();
    if (done > p->first_done && work_done > p->first_work)
        progress_fit_add(&p->fit, (double)(done - p->first_done),
                         work_done - p->first_work, now - p->started);
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

/* Draws step done of total on a terminal, over the last one: what, then
 * the seconds so far unless last (what then says the time taken). */
static void draw_step(struct progress *p, int done, int total,
                      const char *what, int last)
{
    char bar[31];
    int filled = total > 0 ? (int)(30.0 * done / total + 0.5) : 30;
    for (int k = 0; k < 30; k++)
        bar[k] = k < filled ? '#' : '-';
    bar[30] = '\0';
    int width = last ? fprintf(stderr, "\r[%s] %d/%d %s", bar, done, total,
                               what)
                     : fprintf(stderr, "\r[%s] %d/%d %s, %.0f s", bar, done,
                               total, what, progress_now() - p->started);
    /* Blanks over what a longer step left. */
    for (int k = width; k < p->drawn_width; k++)
        fputc(' ', stderr);
    p->drawn_width = width;
    fflush(stderr);
}

void progress_step(struct progress *p, int done, int total,
                   const char *what)
{
    if (p->terminal)
        draw_step(p, done, total, what, 0);
}

void progress_steps_end(struct progress *p, int total)
{
    if (!p->terminal || p->finished)
        return;
    p->finished = 1;
    char took[48];
    snprintf(took, sizeof took, "took %.1f s", progress_now() - p->started);
    draw_step(p, total, total, took, 1);
    fputc('\n', stderr);
}

void progress_show_stage(void *context, const char *what)
{
    (void)context;
    if (isatty(STDERR_FILENO))
        shown_line(stderr, "facet: %s", what);
}

void progress_show_note(void *context, const char *text)
{
    (void)context;
    shown_line(stderr, "facet: note: %s", text);
}

void progress_show_warning(void *context, const char *text)
{
    (void)context;
    /* a warning can quote the surface file (shown.h) */
    shown_line(stderr, "facet: warning: %s", text);
}
