/*
 * progress.h: progress of long work on stderr.
 *
 * On a terminal, one line redrawn in place: a bar, done/total, rate and
 * time left. Otherwise (a log, CI) a plain line at most every few seconds
 * and at the end, so logs stay readable.
 */
#ifndef FACET_PROGRESS_H
#define FACET_PROGRESS_H

#include <stdint.h>

struct progress {
    const char *what;        /* "options", shown after the counts */
    int terminal;            /* stderr is a terminal */
    double started;          /* monotonic seconds */
    double last_drawn;
    int64_t first_done;      /* done when started (resume) */
    int finished;
};

/* Starts reporting; done_before counts work already done (a resume). */
void progress_start(struct progress *p, const char *what,
                    int64_t done_before);
void progress_update(struct progress *p, int64_t done, int64_t total);
/* Ends the line. */
void progress_finish(struct progress *p, int64_t done, int64_t total);

/* Monotonic seconds. */
double progress_now(void);

/* The stage and warning hooks of a study (study/study.h) on stderr:
 * "facet: STAGE" on a terminal only (in a log the progress lines say
 * enough, and an error stays the one line on stderr), "facet: warning:
 * TEXT" always. context is not used. */
void progress_show_stage(void *context, const char *what);
void progress_show_warning(void *context, const char *text);

#endif
