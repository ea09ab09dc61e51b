/*
 * study_project_view.c: a project run's building opened again for its
 * options' panels. See study_project_view.h.
 */
#include "study_project_view.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "core/base/sha256.h"

static void stage(const struct study_hooks *hooks, const char *what)
{
    if (hooks != NULL && hooks->stage != NULL)
        hooks->stage(hooks->context, what);
}

/* Where the run's file stored may be now, first first: as stored, then
 * its name in the folder of the database at db_path. Returns how many it
 * wrote into place[] (1 or 2). */
static int file_places(const char *db_path, const char *stored,
                       char place[2][4096])
{
    snprintf(place[0], sizeof place[0], "%s", stored);
    const char *slash = strrchr(db_path, '/');
    int folder = slash ? (int)(slash - db_path + 1) : 0;
    const char *name = strrchr(stored, '/');
    name = name ? name + 1 : stored;
    int n = snprintf(place[1], sizeof place[1], "%.*s%s", folder, db_path,
                     name);
    if (n <= 0 || (size_t)n >= sizeof place[1] ||
        strcmp(place[1], place[0]) == 0)
        return 1;
    return 2;
}

/* The file of surface row r, where it is now, into path: the first place
 * whose content has the SHA-256 the run recorded. */
static int locate_file(const struct store *store, int64_t run,
                       const struct surface_row *r, char path[4096],
                       struct facet_error *err)
{
    char place[2][4096];
    int n = file_places(store_path(store), r->file, place);
    int changed = 0;
    for (int k = 0; k < n; k++) {
        if (access(place[k], F_OK) != 0)
            continue;
        char digest[65];
        int rc = sha256_file(place[k], digest, err);
        if (rc != FACET_OK)
            return rc;
        if (strcmp(digest, r->file_sha256) == 0) {
            memcpy(path, place[k], sizeof place[k]);
            return FACET_OK;
        }
        changed = 1;
    }
    return facet_error_set(err, FACET_EINPUT,
        changed ? "%s: the file has changed since run %lld was made from "
                  "it (SHA-256 was %.12s...)"
                : "%s: no such file (run %lld's, SHA-256 %.12s..., nor "
                  "beside the database)",
        r->file, (long long)run, r->file_sha256);
}

/* Opens the files of the surfaces rows[0..n) (each file once, in order)
 * into project, unprepared. */
static int open_files(const struct store *store, const struct run_info *run,
                      const struct surface_row *rows, size_t n,
                      struct project *project, struct facet_error *err)
{
    char (*place)[4096] = calloc(n, sizeof *place);
    const char **files = calloc(n, sizeof *files);
    size_t nfiles = 0;
    int rc = place && files ? FACET_OK
                            : facet_error_set(err, FACET_EWORK,
                                              "out of memory");
    for (size_t i = 0; rc == FACET_OK && i < n; i++) {
        if (i > 0 && strcmp(rows[i].file, rows[i - 1].file) == 0)
            continue;
        rc = locate_file(store, run->id, &rows[i], place[nfiles], err);
        files[nfiles] = place[nfiles];
        nfiles++;
    }
    if (rc == FACET_OK)
        rc = project_open(files, nfiles, run->units, project, err);
    free(place);
    free(files);
    return rc;
}

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
    size_t n = 0;
    if (rc == FACET_OK)
        rc = store_surfaces_get(store, run->id, &view->surfaces, &n, err);
    if (rc == FACET_OK && n == 0)
        rc = facet_error_set(err, FACET_EINPUT,
            "run %lld: a project run without its surfaces recorded",
            (long long)run->id);
    if (rc == FACET_OK)
        rc = store_run_setting_check(run, RUN_SETTING_UV, err);
    if (rc == FACET_OK) {
        stage(hooks, "checking and reading the project's files");
        rc = open_files(store, run, view->surfaces, n, &view->project, err);
    }
    if (rc == FACET_OK) {
        stage(hooks, "preparing the project's surfaces (UV, curvature)");
        rc = project_prepare(&view->project, flip, run->uv, err);
    }
    if (rc == FACET_OK && view->project.nsurfaces != n)
        rc = facet_error_set(err, FACET_EINPUT,
            "run %lld: its files hold %zu surfaces, the run %zu",
            (long long)run->id, view->project.nsurfaces, n);
    for (size_t i = 0; rc == FACET_OK && i < n; i++) {
        const struct project_surface *ps = &view->project.surfaces[i];
        const struct surface_row *r = &view->surfaces[i];
        if (strcmp(ps->name, r->name) != 0 ||
            ps->surface.param.method != r->uv_method)
            rc = facet_error_set(err, FACET_EINPUT,
                "run %lld: surface %zu is '%s' with UV %s, the run's '%s' "
                "with UV %s", (long long)run->id, i + 1, ps->name,
                param_method_name(ps->surface.param.method), r->name,
                param_method_name(r->uv_method));
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
    free(view->surfaces);
    memset(view, 0, sizeof *view);
}
