/*
 * progress.h: progress of long work on stderr.
 *
 * On a terminal, one line redrawn in place: a bar, done/total, rate and
 * time left. Otherwise (a log, CI) a plain line at most every few seconds
 * and at the end, so logs stay readable. The time left follows the work
 * left, which a caller may weigh apart from the count shown (a search's
 * options by their panels: progress_fit).
 */
#ifndef FACET_PROGRESS_H
#define FACET_PROGRESS_H

#include <stdint.h>

/* The time taken so far as a cost per item plus a cost per unit of work,
 * fitted in least squares (no constant) to what each update saw since the
 * start: an option's fixed cost and its cost per panel, which neither the
 * count nor the panels alone give (a walk of small grids is all fixed
 * cost, one of fine grids all panels). Sums over the updates. */
struct progress_fit {
    double nn, nw, ww, tn, tw;  /* items n, work w, seconds t */
};

/* Adds an update: n items and w work done in t seconds, since the start. */
void progress_fit_add(struct progress_fit *fit, double n, double w,
                      double t);

/* Seconds left for items_left items of work_left work at the fitted
 * costs; where the two cannot be told apart (each item the same work, or
 * a cost that comes out negative), at the work's rate alone; -1 with
 * nothing measured. */
double progress_fit_left(const struct progress_fit *fit, double items_left,
                         double work_left);

struct progress {
    const char *what;        /* "options", shown after the counts */
    int terminal;            /* stderr is a terminal */
    double started;          /* monotonic seconds */
    double last_drawn;
    int64_t first_done;      /* done when started (resume) */
    double first_work;       /* work done when started */
    double work_done, work_total;  /* the last update's */
    struct progress_fit fit;       /* of the updates since the start */
    int finished;
    int drawn_width;         /* columns of the last step drawn */
};

/* Starts reporting; done_before counts what was done already (a resume),
 * work_before its work. */
void progress_start(struct progress *p, const char *what,
                    int64_t done_before, double work_before);
/* done of total shown; the time left from work_done of work_total (in
 * any unit: the counts themselves when every item takes as long). */
void progress_update(struct progress *p, int64_t done, int64_t total,
                     double work_done, double work_total);
/* Ends the line. */
void progress_finish(struct progress *p, int64_t done, int64_t total);

/* A command of a few long steps of different kinds (facet classify: read,
 * prepare, then an option's stages), on a terminal only, as its stages
 * are (progress_show_stage): "[#####-----] 3/7 WHAT, 12 s", redrawn in
 * place; no rate or time left, which steps unlike each other do not
 * give. progress_steps_end ends the line with the time taken. */
void progress_step(struct progress *p, int done, int total,
                   const char *what);
void progress_steps_end(struct progress *p, int total);

/* Monotonic seconds. */
double progress_now(void);


/* The stage and warning hooks of a study (study/study.h) on stderr:
 * "facet: STAGE" on a terminal only (in a log the progress lines say
 * enough, and an error stays the one line on stderr), "facet: warning:
 * TEXT" always, "facet: note: TEXT" (study_hooks' note) always too.
 * context is not used. */
void progress_show_stage(void *context, const char *what);
void progress_show_warning(void *context, const char *text);
void progress_show_note(void *context, const char *text);

#endif
