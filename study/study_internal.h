/*
 * study_internal.h: what the study's files share (internal to study/):
 * telling the stage, where a run's file may be now, and a project's
 * part of a run (study_project.c).
 */
#ifndef FACET_STUDY_INTERNAL_H
#define FACET_STUDY_INTERNAL_H

#include "core/project/project.h"
#include "core/project/project_search.h"
#include "study.h"

/* Tells hooks (may be NULL) what the study is doing now. */
void study_stage(const struct study_hooks *hooks, const char *what);

/* The stop that reading and preparing ask (core/base/stop.h): the hooks'
 * should_stop, or one that never fires. */
struct facet_stop study_stop(const struct study_hooks *hooks);

/* Reads input files: the SHA-256 of paths[0..npaths) into digest[] on
 * one thread while parse(context, stop, err) reads them on another
 * (hashing is a fifth to a quarter of reading an OBJ). The hashes' error
 * comes first, as it names the file as it was read; a stop heard by
 * either is FACET_ESTOP. What parse made is the caller's to release, also
 * after a failure. */
int study_read_hashed(const char *const *paths, size_t npaths,
                      char (*digest)[65],
                      int (*parse)(void *context,
                                   const struct facet_stop *stop,
                                   struct facet_error *err),
                      void *context, const struct facet_stop *stop,
                      struct facet_error *err);

/* The places a run's file may be, first first: as stored (absolute since
 * runs record it so; relative to the working folder in older files), then
 * a relative path against the database's folder, then the file's name in
 * the database's folder (a database copied with its files beside it).
 * Returns how many it wrote into place[]. */
int study_surface_candidates(const char *db_path, const char *stored,
                             char place[3][4096]);

/* Reads and prepares the project of request into *project, its surface
 * rows into *rows (malloc'ed, free()), and what the run records of it
 * into run: the first file's SHA-256 (its path is there already), the
 * building's area and triangles, the first surface's UV, the module
 * range. Release project with project_close, also after a failure. */
int study_project_read(const struct study_request *request,
                       const char *db_path,
                       const struct study_hooks *hooks,
                       struct project *project, struct surface_row **rows,
                       struct run_info *run, struct facet_error *err);
/* (FACET_ESTOP, as every reading here, when the hooks' stop fires.) */

/* The warnings of a project run, once its request is known to be good
 * (so that bad input stays one line): each surface's own, "NAME: what",
 * then one line for the surfaces whose mesh is coarse for the smallest
 * module (facets at least COARSE_MESH_RATIO of its side, sqrt(width x
 * height)) and one for those whose facets sag more than
 * FACET_SAG_FRACTION of the space's smallest threshold, each naming how
 * many and the worst: to the warning hook and, one per line, into
 * run->warnings (those that fit). */
void study_project_warnings(const struct study_request *request,
                            const struct project *project,
                            const struct study_hooks *hooks,
                            struct run_info *run);

/* The search over project's modules that request asks for, its grid
 * overrides found by name (FACET_EINPUT for a name no surface has). */
int study_project_search(const struct study_request *request,
                         const struct project *project,
                         struct project_search *search,
                         struct facet_error *err);

/* Opens and prepares the project of run (a project run) into *project,
 * each of its files looked for as study_open_surface looks for a surface
 * and refused unless its SHA-256 is the one recorded; then checks that
 * the files still hold the surfaces recorded, by name, with the UV they
 * took. *overrides (malloc'ed, nsurfaces) receives the grids the run gave
 * surfaces whatever the module (nu 0: none). Release with project_close
 * and free, also after a failure. */
int study_project_reopen(struct store *store, const struct run_info *run,
                         const struct study_hooks *hooks,
                         struct project *project,
                         struct surface_grid **overrides,
                         struct facet_error *err);

/* study_open_surface, asking the hooks' stop while reading and preparing
 * (FACET_ESTOP when it fires). */
int study_open_surface_stoppable(const struct store *store,
                                 const struct run_info *run,
                                 const struct study_hooks *hooks,
                                 struct surface *surface,
                                 struct facet_error *err);

/* A run's planarized options (study_planar.c, issue 33). At most this
 * many of its front's grids are planarized: each takes seconds. */
#define STUDY_PLANARIZE_MAX 8

struct planarize_options;

/* The planarization settings of run: the defaults (planarize.h) with its
 * closeness budget. */
void study_planarize_options(const struct run_info *run,
                             struct planarize_options *o);

/* The planarized option of params' grid on the prepared surface, held to
 * run's budget, into *panels (released with panelization_free, also
 * after a failure) and *totals (planar_option.h). */
int study_planar_evaluate(const struct run_info *run,
                          const struct surface *surface,
                          const struct option_params *params,
                          const struct facet_stop *stop,
                          struct panelization *panels,
                          struct option_totals *totals,
                          struct facet_error *err);

/* When run has a closeness budget: the planarized option of each grid of
 * its Pareto front (at most STUDY_PLANARIZE_MAX, the knee's first), each
 * grid once, stored with its panels beside the classified options, then
 * the run ranked again. *stopped 1 when the hooks' stop fired (the rest
 * are made when the run is resumed). */
int study_planarize_front(struct store *store, const struct run_info *run,
                          const struct surface *surface,
                          const struct optimize_settings *settings,
                          const struct study_hooks *hooks, int *stopped,
                          struct facet_error *err);

/* qsort's order of option rows for a front larger than its budget, and
 * for the grids --planarize takes: the knee, then the largest crowding
 * distance (the ends of the front, at infinity, first), then the
 * option's number. */
int study_knee_then_spread(const void *a, const void *b);

#endif
