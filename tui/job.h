/*
 * job.h: a New run (or a resumed one) working in a thread while the
 * workbench stays responsive. The thread opens its own connection to the database, runs
 * study_start through it (every batch committed as it is evaluated, so the
 * options table fills in live), and reports its stage and progress under
 * a lock; the UI polls a snapshot and may ask it to stop, which leaves the
 * run interrupted and resumable. No curses here.
 */
#ifndef FACET_TUI_JOB_H
#define FACET_TUI_JOB_H

#include <stdint.h>

#include "study/study.h"

struct tui_job;

/* What the UI shows of a job. */
struct tui_job_state {
    int64_t run;          /* the run's id once recorded, else 0 */
    int64_t done, total;  /* options */
    char stage[128];      /* "preparing the surface", ... */
    char warning[400];    /* the run's first warning (study_hooks), or "" */
    int stopping;         /* stop was asked */
    int finished;         /* the thread has ended */
    int rc;               /* its result, when finished */
    enum optimize_outcome outcome;
    struct facet_error err;
};

/* Starts request (copied, strings too) against the database at db_path.
 * Release with tui_job_free. */
int tui_job_start(const char *db_path, const struct study_request *request,
                  struct tui_job **out, struct facet_error *err);

/* Goes on with run (interrupted or failed) through study_resume, in a
 * thread as tui_job_start does; the state's run is run from the start.
 * Release with tui_job_free. */
int tui_job_resume(const char *db_path, int64_t run, struct tui_job **out,
                   struct facet_error *err);

/* A consistent copy of the job's state. */
void tui_job_state(struct tui_job *job, struct tui_job_state *out);

/* Asks the study to stop: heard within a fraction of a second, inside an
 * option of a fine grid too (optimize.h). */
void tui_job_stop(struct tui_job *job);

/* Stops the job if it still works, waits for its thread, frees it. */
void tui_job_free(struct tui_job *job);

#endif
