/*
 * study_project.c: what a study does differently for a project (a
 * building of many surfaces, core/project/project.h): reading and
 * preparing its files, recording its surfaces, the search over its
 * modules, and reopening it to resume. The run itself goes as a single
 * surface's does (study.c). See study.h.
 */
#include "study_internal.h"
#include "study/study_prepared.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "core/base/sha256.h"
#include "core/project/project_seams.h"
#include "core/panel/panel.h"
#include "core/surface/coarse_mesh.h"
#include "core/base/units.h"

/* The surface rows of a prepared project whose files' digests are
 * digest[] into *rows (malloc'ed). */
static int project_rows(const struct project *project,
                        char (*digest)[65], struct surface_row **rows,
                        struct facet_error *err)
{
    *rows = calloc(project->nsurfaces ? project->nsurfaces : 1,
                   sizeof **rows);
    if (*rows == NULL)
        return facet_error_set(err, FACET_EWORK, "out of memory");
    for (size_t i = 0; i < project->nsurfaces; i++) {
        const struct project_surface *ps = &project->surfaces[i];
        struct surface_row *r = &(*rows)[i];
        size_t f = 0;
        while (f + 1 < project->nfiles && project->files[f] != ps->file)
            f++;
        char absolute[4096];
        const char *path = realpath(ps->file, absolute) ? absolute
                                                        : ps->file;
        if (strlen(ps->name) >= sizeof r->name ||
            strlen(path) >= sizeof r->file)
            return facet_error_set(err, FACET_EINPUT,
                "%.200s: object '%.200s': name or path too long", path,
                ps->name);
        /* Whole, as checked above. */
        memcpy(r->name, ps->name, strlen(ps->name) + 1);
        memcpy(r->file, path, strlen(path) + 1);
        memcpy(r->file_sha256, digest[f], 65);
        r->triangles = (int64_t)ps->surface.mesh.ntriangles;
        r->area = ps->surface.mesh.area;
        r->u_length = ps->u_length;
        r->v_length = ps->v_length;
        r->uv_method = ps->surface.param.method;
    }
    return FACET_OK;
}

/* Tells line to the warning hook and appends it to text (size bytes, *used
 * of them taken) when it fits. */
static void warn_line(const struct study_hooks *hooks, const char *line,
                      char *text, size_t size, size_t *used)
{
    if (hooks != NULL && hooks->warning != NULL)
        hooks->warning(hooks->context, line);
    int wrote = snprintf(text + *used, size - *used, "%s%s",
                         *used ? "\n" : "", line);
    if (wrote < 0 || (size_t)wrote >= size - *used) {
        text[*used] = '\0';
        return;  /* told, not stored: the column is full */
    }
    *used += (size_t)wrote;
}

/* See study_internal.h. */
void study_project_warnings(const struct study_request *request,
                            const struct project *project,
                            const struct study_hooks *hooks,
                            struct run_info *run)
{
    char *text = run->warnings;
    size_t size = sizeof run->warnings;
    size_t used = 0;
    text[0] = '\0';
    double side = sqrt(request->module.width_min *
                       request->module.height_min);
    double t_min = units_m_of_mm(request->settings.space.t_min_mm);
    size_t coarse = 0, sagging = 0;
    const char *coarsest = NULL, *saggiest = NULL;
    double worst_facet = 0, worst_sag = 0;
    for (size_t i = 0; i < project->nsurfaces; i++) {
        const struct project_surface *ps = &project->surfaces[i];
        for (int k = 0; k < ps->surface.nwarnings; k++) {
            char line[400];
            snprintf(line, sizeof line, "%.60s: %s", ps->name,
                     ps->surface.warnings[k]);
            warn_line(hooks, line, text, size, &used);
        }
        double facet;
        if (mesh_facet_size(&ps->surface.mesh, &facet, NULL) == FACET_OK &&
            side > 0 && facet >= COARSE_MESH_RATIO * side) {
            coarse++;
            if (facet > worst_facet) {
                worst_facet = facet;
                coarsest = ps->name;
            }
        }
        if (facet_sag_matters(ps->surface.facet_sag, t_min)) {
            sagging++;
            if (ps->surface.facet_sag > worst_sag) {
                worst_sag = ps->surface.facet_sag;
                saggiest = ps->name;
            }
        }
    }
    char line[600];
    if (coarse > 0) {
        char grid[160];
        snprintf(grid, sizeof grid, "the smallest module, %g x %g m, on %zu "
                 "of %zu surfaces (worst %.60s)", request->module.width_min,
                 request->module.height_min, coarse, project->nsurfaces,
                 coarsest);
        if (coarse_mesh_warning(worst_facet, side, grid, line, sizeof line))
            warn_line(hooks, line, text, size, &used);
    }
    if (sagging > 0) {
        char what[160];
        snprintf(what, sizeof what, "the smallest threshold, t = %g mm, on "
                 "%zu of %zu surfaces (worst %.60s)",
                 request->settings.space.t_min_mm, sagging,
                 project->nsurfaces, saggiest);
        if (facet_sag_warning(worst_sag, t_min, what, line, sizeof line))
            warn_line(hooks, line, text, size, &used);
    }
}

/* Reads and prepares the project of request into *project, its surface
 * rows into *rows (malloc'ed), and what the run records of it into run:
 * the first file's SHA-256 (its path is there already), the building's
 * area and triangles, the first surface's UV, the module range. */
int study_project_read(const struct study_request *request,
                        const char *db_path,
                        const struct study_hooks *hooks,
                        struct project *project, struct surface_row **rows,
                        struct run_info *run, struct facet_error *err)
{
    *rows = NULL;
    if (request->mesh.object != NULL || request->mesh.group != NULL)
        return facet_error_set(err, FACET_EINPUT,
            "a project takes every object of its files: no object or "
            "group is selected in one");
    char (*digest)[65] = calloc(request->nfiles, sizeof *digest);
    if (digest == NULL)
        return facet_error_set(err, FACET_EWORK, "out of memory");
    struct study_prepare want = {db_path, request->files, request->nfiles,
                                 NULL, request->mesh.units,
                                 request->units_named, request->flip_normals,
                                 request->uv};
    int rc = study_project_prepared(&want, hooks, project, digest, err);
    if (rc == FACET_OK) {
        struct facet_stop stop = study_stop(hooks);
        study_stage(hooks, "finding the seams between the surfaces");
        rc = project_seams_keep(project, request->weld, &stop, err);
    }
    if (rc == FACET_OK)
        rc = project_rows(project, digest, rows, err);
    if (rc == FACET_OK) {
        memcpy(run->surface_sha256, digest[0], 65);
        run->weld_mm = units_mm(request->weld);
        run->surface_area = project->area;
        run->triangles = (int64_t)project->ntriangles;
        run->uv_method = project->surfaces[0].surface.param.method;
        run->module_w_min = request->module.width_min;
        run->module_w_max = request->module.width_max;
        run->module_w_step = request->module.width_step;
        run->module_h_min = request->module.height_min;
        run->module_h_max = request->module.height_max;
        run->module_h_step = request->module.height_step;
    }
    free(digest);
    return rc;
}

/* The search over project's modules that request asks for, its
 * overrides found by name. */
int study_project_search(const struct study_request *request,
                             const struct project *project,
                             struct project_search *search,
                             struct facet_error *err)
{
    struct surface_grid *grids = NULL;
    if (request->noverrides > 0) {
        grids = calloc(project->nsurfaces, sizeof *grids);
        if (grids == NULL)
            return facet_error_set(err, FACET_EWORK, "out of memory");
    }
    for (size_t k = 0; k < request->noverrides; k++) {
        const struct project_surface *ps =
            project_find(project, request->override_names[k]);
        if (ps == NULL) {
            free(grids);
            return facet_error_set(err, FACET_EINPUT,
                "no surface named '%s' in the project (facet info lists "
                "them)", request->override_names[k]);
        }
        grids[ps - project->surfaces] = request->overrides[k];
    }
    int rc = project_search_init(search, project, &request->module, grids,
                                 err);
    free(grids);
    return rc;
}

int study_project_space(const struct module_range *range,
                        struct design_space *space, struct facet_error *err)
{
    size_t widths = module_widths(range), heights = module_heights(range);
    if (widths > PANEL_MAX_GRID || heights > PANEL_MAX_GRID)
        return facet_error_set(err, FACET_EINPUT,
            "the module range holds %zu widths and %zu heights: at most %d "
            "each (take a larger step)", widths, heights, PANEL_MAX_GRID);
    space->u_min = 1;
    space->u_max = (int)widths;
    space->v_min = 1;
    space->v_max = (int)heights;
    return FACET_OK;
}

/* Opens and prepares the project of run (a project run) into *project,
 * each of its files looked for as study_open_surface looks for a
 * surface, and refused unless its SHA-256 is the one recorded; then
 * checks that the files still hold the surfaces recorded, by name, with
 * the UV they took. *overrides (malloc'ed, nsurfaces) receives the
 * grids the run gave surfaces whatever the module (nu 0: none). Release
 * with project_close and free, also after a failure. */
int study_project_reopen(struct store *store, const struct run_info *run,
                         const struct study_hooks *hooks,
                         struct project *project,
                         struct surface_grid **overrides,
                         struct facet_error *err)
{
    struct facet_stop stop = study_stop(hooks);
    memset(project, 0, sizeof *project);
    *overrides = NULL;
    struct surface_row *rows;
    size_t n;
    int rc = store_surfaces_get(store, run->id, &rows, &n, err);
    if (rc != FACET_OK)
        return rc;
    if (n == 0) {
        free(rows);
        return facet_error_set(err, FACET_EINPUT,
            "run %lld: a project run without its surfaces recorded",
            (long long)run->id);
    }
    /* The files in order, each once, and where each is now. */
    char (*place)[4096] = calloc(n, sizeof *place);
    char (*known)[65] = calloc(n, sizeof *known);
    const char **files = calloc(n, sizeof *files);
    size_t nfiles = 0;
    if (place == NULL || known == NULL || files == NULL)
        rc = facet_error_set(err, FACET_EWORK, "out of memory");
    for (size_t i = 0; rc == FACET_OK && i < n; i++) {
        if (i > 0 && strcmp(rows[i].file, rows[i - 1].file) == 0)
            continue;
        char candidate[3][4096];
        int ncandidates = study_surface_candidates(store_path(store), rows[i].file,
                                             candidate);
        int found = 0, changed = 0;
        for (int k = 0; rc == FACET_OK && !found && k < ncandidates; k++) {
            if (access(candidate[k], F_OK) != 0)
                continue;
            char digest[65];
            rc = sha256_file_stoppable(candidate[k], &stop, digest, err);
            if (rc == FACET_OK && strcmp(digest, rows[i].file_sha256) == 0) {
                memcpy(place[nfiles], candidate[k], sizeof candidate[k]);
                memcpy(known[nfiles], digest, sizeof digest);
                files[nfiles] = place[nfiles];
                nfiles++;
                found = 1;
            } else if (rc == FACET_OK) {
                changed = 1;
            }
        }
        if (rc == FACET_OK && !found)
            rc = facet_error_set(err, FACET_EINPUT,
                changed ? "%s: the file has changed since run %lld was made "
                          "from it (SHA-256 was %.12s...)"
                        : "%s: no such file (run %lld's, SHA-256 %.12s..., "
                          "nor beside the database)",
                rows[i].file, (long long)run->id, rows[i].file_sha256);
    }
    if (rc == FACET_OK)
        rc = store_run_setting_check(run, RUN_SETTING_UV, err);
    if (rc == FACET_OK) {
        /* The files were found by their SHA-256s: known, not hashed
         * again. The units were the run's own, checked when it began. */
        struct study_prepare want = {store_path(store), files, nfiles,
                                     (const char (*)[65])known,
                                     run->units, 1, run->flip_normals,
                                     run->uv};
        char (*digest)[65] = calloc(nfiles ? nfiles : 1, sizeof *digest);
        rc = digest == NULL
            ? facet_error_set(err, FACET_EWORK, "out of memory")
            : study_project_prepared(&want, hooks, project, digest, err);
        free(digest);
    }
    /* Its seams at its welding tolerance; a run made before seams were
     * measured (NULL) finds none, so its options stay alike. */
    if (rc == FACET_OK && run->weld_mm > 0)
        rc = project_seams_keep(project, units_m_of_mm(run->weld_mm), &stop,
                                err);
    if (rc == FACET_OK && project->nsurfaces != n)
        rc = facet_error_set(err, FACET_EINPUT,
            "run %lld: its files hold %zu surfaces, the run %zu",
            (long long)run->id, project->nsurfaces, n);
    for (size_t i = 0; rc == FACET_OK && i < n; i++) {
        const struct project_surface *ps = &project->surfaces[i];
        if (strcmp(ps->name, rows[i].name) != 0 ||
            ps->surface.param.method != rows[i].uv_method)
            rc = facet_error_set(err, FACET_EINPUT,
                "run %lld: surface %zu is '%s' with UV %s, the run's '%s' "
                "with UV %s", (long long)run->id, i + 1, ps->name,
                param_method_name(ps->surface.param.method), rows[i].name,
                param_method_name(rows[i].uv_method));
    }
    if (rc == FACET_OK) {
        *overrides = calloc(n, sizeof **overrides);
        if (*overrides == NULL)
            rc = facet_error_set(err, FACET_EWORK, "out of memory");
        for (size_t i = 0; rc == FACET_OK && i < n; i++)
            (*overrides)[i] = (struct surface_grid){rows[i].grid_nu,
                                                    rows[i].grid_nv};
    }
    free(place);
    free(known);
    free(files);
    free(rows);
    return rc;
}

