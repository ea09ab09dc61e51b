/*
 * study_project_view.c: a project run's building opened again for its
 * options' panels. See study_project_view.h.
 */
#include "study_project_view.h"

#include <stdlib.h>
#include <string.h>

#include "study_internal.h"

int study_project_view_open(struct store *store, const struct run_info *run,
                            const struct study_hooks *hooks,
                            struct study_project_view *view,
                            struct facet_error *err)
{
    memset(view, 0, sizeof *view);
    view->run = run->id;
    if (!store_run_is_project(run))
        return facet_error_set(err, FACET_EINPUT,
                               "run %lld is of a single surface, not a "
                               "project", (long long)run->id);
    struct mesh_options mesh;
    int flip;
    int rc = study_settings(run, &view->settings, &mesh, &flip, err);
    /* An option opened again is measured as its run measured it, so that
     * its panels, map and export say what the store holds: no widths
     * (ten evaluations' work and more on every face) unless the run took
     * them. */
    view->settings.base.unmeasured = OPTION_MEASURE_ALL & ~run->measured;
    if (rc == FACET_OK) {
        /* the files found, checked and read: most of the time, with
         * preparing (no stage of its own there to tell) */
        study_stage(hooks, "reading, checking and preparing the project's "
                    "surfaces (UV, curvature)");
        struct surface_grid *overrides = NULL;
        rc = study_project_reopen(store, run, hooks, &view->project,
                                  &overrides, err);
        free(overrides);
    }
    return rc;
}

int study_project_view_option(struct store *store,
                              const struct study_project_view *view,
                              int64_t number, struct project_option *out,
                              struct facet_error *err)
{
    memset(out, 0, sizeof *out);
    struct option_row option;
    int rc = store_option_get(store, view->run, number, &option, err);
    if (rc != FACET_OK)
        return rc;
    struct option_surface_row *rows;
    size_t n;
    rc = store_option_surfaces_get(store, view->run, number, &rows, &n, err);
    if (rc != FACET_OK)
        return rc;
    struct surface_grid *grids =
        malloc((n ? n : 1) * sizeof *grids);
    if (grids == NULL)
        rc = facet_error_set(err, FACET_EWORK, "out of memory");
    else if (n != view->project.nsurfaces)
        rc = facet_error_set(err, FACET_EINPUT,
            "option %lld of run %lld has %zu surface rows, its project %zu "
            "surfaces", (long long)number, (long long)view->run, n,
            view->project.nsurfaces);
    for (size_t i = 0; rc == FACET_OK && i < n; i++)
        grids[i] = (struct surface_grid){rows[i].nu, rows[i].nv};
    if (rc == FACET_OK) {
        struct option_params params = option_params_at(
            &view->settings.base, option.nu, option.nv, option.threshold_mm);
        rc = project_option_evaluate(&view->project, grids, &params,
                                     view->settings.jobs, out, err);
    }
    free(grids);
    free(rows);
    return rc;
}

void study_project_view_close(struct study_project_view *view)
{
    project_close(&view->project);
    memset(view, 0, sizeof *view);
}
