/*
 * project_load.h: a project run's building opened and prepared in a
 * thread (study_project_view_open), while the workbench stays
 * responsive: the skin example takes seconds to read and prepare. The
 * thread opens its own connection to the database, reports its stage
 * under a lock, and keeps the view it made for the panel maps of the
 * run's options, which the workbench holds while that run is browsed
 * (tui_app.project). No curses here.
 */
#ifndef FACET_TUI_PROJECT_LOAD_H
#define FACET_TUI_PROJECT_LOAD_H

#include <stdint.h>

#include "study/study_project_view.h"

struct tui_project_load;

/* What the UI shows of a load. */
struct tui_project_load_state {
    int64_t run;
    char stage[128];      /* "preparing the project's surfaces", ... */
    double seconds;       /* since it started */
    int finished;         /* the thread has ended */
    int rc;               /* its result, when finished */
    struct facet_error err;
};

/* Starts opening run's project from the database at db_path. Release
 * with tui_project_load_free. */
int tui_project_load_start(const char *db_path, int64_t run,
                           struct tui_project_load **out,
                           struct facet_error *err);

/* A consistent copy of the load's state. */
void tui_project_load_state(struct tui_project_load *load,
                            struct tui_project_load_state *out);

/* The prepared project once the load has finished with FACET_OK, else
 * NULL. Owned by load. */
const struct study_project_view *
tui_project_load_view(struct tui_project_load *load);

/* Waits for the thread (preparing cannot be stopped half-way) and frees
 * the load and its project. NULL: nothing. */
void tui_project_load_free(struct tui_project_load *load);

#endif
