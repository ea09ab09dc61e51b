/*
 * study_project_view.h: a project run's building opened again to look at
 * its options surface by surface (the TUI's panel map of a project
 * option). A project run keeps each surface's totals of every option
 * (option_surfaces), not its panels: the panels are evaluated again on
 * demand, over the run's own files, with the run's settings and the
 * option's stored grids, so that they add up to what the run stored.
 *
 * Opening (reading the files, checking their SHA-256, preparing every
 * surface) is the slow part: the skin example's 2M triangles take
 * seconds and about 1 GB. A caller that browses several options of one
 * run keeps the view open and evaluates each option on it (about 0.3 s
 * for the skin's 50,000 panels).
 *
 * Ownership: study_project_view_open fills a caller-owned view, released
 * with study_project_view_close, also after a failure.
 */
#ifndef FACET_STUDY_PROJECT_VIEW_H
#define FACET_STUDY_PROJECT_VIEW_H

#include <stdint.h>

#include "core/project/project.h"
#include "core/project/project_option.h"
#include "store/store.h"
#include "study/study.h"

struct study_project_view {
    int64_t run;                      /* the run's id */
    struct project project;           /* its surfaces, prepared */
    struct optimize_settings settings;  /* the run's */
};

/* Opens and prepares the project of run (a project run: store_run_is_
 * project) into *view, with study_project_reopen (study_internal.h):
 * each file the run recorded (the surfaces table) looked for where it
 * was, then beside store's file, and refused unless its SHA-256 is the
 * one recorded; the surfaces it holds must be the run's, by name and UV.
 * hooks (may be NULL) hears the stage. Returns FACET_OK, FACET_EINPUT for
 * a run of a single surface, a file missing or changed, FACET_EWORK when
 * out of memory, with err naming the file. */
int study_project_view_open(struct store *store, const struct run_info *run,
                            const struct study_hooks *hooks,
                            struct study_project_view *view,
                            struct facet_error *err);

/* Evaluates option number of view's run over its project, into *out
 * (caller-owned, project_option_free, also after a failure): each
 * surface's grid as the option stored it (option_surfaces), its
 * threshold, the run's classification, prices and limits, on the run's
 * threads. Returns FACET_OK, FACET_EINPUT for an option of another run or
 * without its surface rows. */
int study_project_view_option(struct store *store,
                              const struct study_project_view *view,
                              int64_t number, struct project_option *out,
                              struct facet_error *err);

void study_project_view_close(struct study_project_view *view);

#endif
