/*
 * study.c: an optimisation run written through the store. See study.h.
 */
#include "core/evaluate/evaluate.h"
#include "study.h"
#include "study_internal.h"

#include <assert.h>
#include <errno.h>
#include <sys/statvfs.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "core/project/project_search.h"
#include "core/project/seam.h"
#include "core/surface/coarse_mesh.h"
#include "core/search/front.h"
#include "core/base/parallel.h"
#include "core/base/sha256.h"
#include "core/base/text.h"
#include "core/base/units.h"

/* What the optimiser's hooks need to reach the store. */
struct study_state {
    struct store *store;
    int64_t run;
    const struct study_hooks *hooks;
    struct option_row *rows;     /* conversion buffer for a batch */
    size_t capacity;
    double free_before;          /* bytes free on the database's disk
                                    before the last batch; < 0: unknown */
    double batch_bytes;          /* what the last batch took of it */
    struct project_search *project;  /* a project run's, else NULL */
    struct option_surface_row *surface_rows;  /* a batch's, per surface */
    size_t surface_capacity;
};

/* What a run keeps free on its database's disk beyond its next batch, so
 * that a run stopped by a full disk can still write its status (a few
 * pages of the WAL): SQLite cannot roll a committed WAL back to make room,
 * so a disk filled by the options themselves would leave the run marked
 * running. */
#define STUDY_DISK_RESERVE (64.0 * 1024)

static double disk_free_bytes(const char *db_path);
static void format_bytes(double bytes, char *out, size_t size);

/* Refuses the next batch when the disk cannot take it and the reserve: a
 * batch takes about what the last one took (the WAL copies every page a
 * commit touches, so it is far more than the options' own bytes). */
static int check_batch_room(struct study_state *state,
                            struct facet_error *err)
{
    double free_now = disk_free_bytes(store_path(state->store));
    if (free_now < 0)
        return FACET_OK;
    if (state->free_before >= free_now)
        state->batch_bytes = state->free_before - free_now;
    state->free_before = free_now;
    if (free_now >= 2 * state->batch_bytes + STUDY_DISK_RESERVE)
        return FACET_OK;
    char have[32];
    format_bytes(free_now, have, sizeof have);
    return facet_error_set(err, FACET_EWORK,
        "%s: database or disk is full (%s free, kept to record the run's "
        "end): the options stored so far are kept; make room and resume "
        "the run", store_path(state->store), have);
}

/* Monotonic seconds, for the run's elapsed time. */
static double clock_seconds(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + (double)t.tv_nsec * 1e-9;
}

void study_stage(const struct study_hooks *hooks, const char *what)
{
    if (hooks != NULL && hooks->stage != NULL)
        hooks->stage(hooks->context, what);
}

struct facet_stop study_stop(const struct study_hooks *hooks)
{
    struct facet_stop stop = {NULL, NULL};
    if (hooks != NULL) {
        stop.requested = hooks->should_stop;
        stop.context = hooks->context;
    }
    return stop;
}

static void option_row_of(const struct evaluated_option *e,
                          struct option_row *row)
{
    memset(row, 0, sizeof *row);
    row->number = e->number;
    row->generation = e->generation;
    row->nu = e->point.nu;
    row->nv = e->point.nv;
    row->threshold_mm = e->point.threshold_mm;
    row->totals = e->totals;
    row->module_w = row->module_h = NAN;
    row->modules = TOTALS_UNKNOWN;
}

static void evaluated_of(const struct option_row *row,
                         struct evaluated_option *e)
{
    memset(e, 0, sizeof *e);
    e->number = row->number;
    e->generation = row->generation;
    e->point.nu = row->nu;
    e->point.nv = row->nv;
    e->point.threshold_mm = row->threshold_mm;
    e->totals = row->totals;
}

static int store_batch(void *context, const struct evaluated_option *options,
                       size_t n, struct facet_error *err)
{
    struct study_state *state = context;
    if (n > state->capacity) {
        struct option_row *grown = realloc(state->rows, n * sizeof *grown);
        if (grown == NULL)
            return facet_error_set(err, FACET_EWORK, "out of memory");
        state->rows = grown;
        state->capacity = n;
    }
    for (size_t k = 0; k < n; k++)
        option_row_of(&options[k], &state->rows[k]);
    int rc = check_batch_room(state, err);
    if (rc != FACET_OK)
        return rc;
    if (state->project == NULL)
        return store_options_put(state->store, state->run, state->rows, n,
                                 err);
    /* A project's options come with their surfaces' rows, which its
     * evaluator kept from this very batch (optimize.h). */
    const struct project_search *p = state->project;
    size_t ns = p->project->nsurfaces;
    if (n * ns > state->surface_capacity) {
        struct option_surface_row *grown =
            realloc(state->surface_rows, n * ns * sizeof *grown);
        if (grown == NULL)
            return facet_error_set(err, FACET_EWORK, "out of memory");
        state->surface_rows = grown;
        state->surface_capacity = n * ns;
    }
    for (size_t k = 0; k < n; k++) {
        struct option_row *row = &state->rows[k];
        project_search_module(p, &options[k].point, &row->module_w,
                              &row->module_h);
        row->modules = project_search_modules(p, &options[k].point);
        const struct project_surface_row *from = project_search_rows(p, k);
        for (size_t i = 0; i < ns; i++)
            state->surface_rows[k * ns + i] = (struct option_surface_row){
                from[i].grid.nu, from[i].grid.nv, from[i].totals,
                (int64_t)from[i].moulds_used, (int64_t)from[i].joints};
    }
    return store_project_options_put(state->store, state->run, state->rows,
                                     n, state->surface_rows, ns, err);
}

static void report_progress(void *context, const struct optimize_progress *p)
{
    struct study_state *state = context;
    if (state->hooks != NULL && state->hooks->progress != NULL)
        state->hooks->progress(state->hooks->context, p);
}

static int stop_requested(void *context)
{
    struct study_state *state = context;
    return state->hooks != NULL && state->hooks->should_stop != NULL &&
           state->hooks->should_stop(state->hooks->context);
}

void study_request_defaults(struct study_request *r)
{
    memset(r, 0, sizeof *r);
    r->name = "";
    r->mesh = (struct mesh_options){UNITS_M, NULL, NULL};
    r->uv = PARAM_AUTO;
    r->store_panels = KEEP_FRONT;
    r->weld = SEAM_WELD_DEFAULT;
    struct optimize_settings *s = &r->settings;
    s->space = (struct design_space){20, 40, 35, 50, 3, 3, 0};
    s->method = study_auto_method(&s->space);
    option_params_defaults(&s->base);
    s->objectives[0] = objective_named("cost");
    s->objectives[1] = objective_named("planarity");
    s->objectives[2] = objective_named("dp_area");
    s->nobjectives = 3;
    s->seed = 1;
    s->evaluations = 1000;
    s->population = 100;
    s->generations = 50;
    s->jobs = parallel_cpus(PARALLEL_MAX);
}

/* The cost model beyond area, the mould settings and the panels as built
 * (the SP typing, the gap and kink limits), between a run's settings and
 * the parameters its options are evaluated with. The mould
 * tolerance is NaN in the run (NULL in the store) and not given in the
 * parameters when it is each option's flatness threshold. */
static void costs_from_run(struct option_params *params,
                           const struct run_info *run)
{
    params->classify.panel_cost = run->panel_cost;
    params->classify.joint_cost = run->joint_cost;
    memcpy(params->classify.mould_cost, run->mould_cost,
           sizeof run->mould_cost);
    params->mould_tol_given = !isnan(run->mould_tol_mm);
    params->mould_tol = params->mould_tol_given
                            ? units_m_of_mm(run->mould_tol_mm) : 0;
    params->mould_mirror = run->mould_mirror;
    params->classify.sp_by_class = !run->sp_fit;
    params->classify.max_gap = isnan(run->max_gap_mm)
                                  ? 0 : units_m_of_mm(run->max_gap_mm);
    params->classify.max_kink = isnan(run->max_kink_deg)
                                    ? 0 : units_rad_of_deg(run->max_kink_deg);
    params->classify.min_panel_width = isnan(run->min_panel_width)
                                           ? 0 : run->min_panel_width;
}

static void costs_to_run(struct run_info *run,
                         const struct option_params *params)
{
    run->panel_cost = params->classify.panel_cost;
    run->joint_cost = params->classify.joint_cost;
    memcpy(run->mould_cost, params->classify.mould_cost,
           sizeof run->mould_cost);
    run->mould_tol_mm = params->mould_tol_given
                           ? units_mm(params->mould_tol) : NAN;
    run->mould_mirror = params->mould_mirror;
    run->sp_fit = !params->classify.sp_by_class;
    run->max_gap_mm = params->classify.max_gap > 0
                          ? units_mm(params->classify.max_gap) : NAN;
    run->max_kink_deg = params->classify.max_kink > 0
                            ? units_deg(params->classify.max_kink) : NAN;
    run->min_panel_width = params->classify.min_panel_width > 0
                               ? params->classify.min_panel_width : NAN;
}

int study_settings(const struct run_info *run,
                   struct optimize_settings *s, struct mesh_options *mesh,
                   int *flip_normals, struct facet_error *err)
{
    memset(s, 0, sizeof *s);
    option_params_defaults(&s->base);
    int rc = store_run_setting_check(run, RUN_SETTING_METHOD, err);
    if (rc == FACET_OK)
        rc = objectives_parse(run->objectives, "the run's objectives",
                              s->objectives, &s->nobjectives, err);
    if (rc == FACET_OK)
        rc = store_run_setting_check(run, RUN_SETTING_UNITS, err);
    if (rc == FACET_OK)
        rc = store_run_setting_check(run, RUN_SETTING_PER_PANEL, err);
    if (rc != FACET_OK)
        return rc;
    s->method = run->method;
    mesh->units = run->units;
    s->base.mode = run->per_panel;
    s->space = (struct design_space){run->u_min, run->u_max, run->v_min,
                                     run->v_max, run->threshold_min_mm,
                                     run->threshold_max_mm,
                                     run->threshold_step_mm};
    s->base = option_params_at(&s->base, 0, 0, run->threshold_min_mm);
    s->base.classify.curvature_tol = run->curvature_tol;
    memcpy(s->base.classify.price, run->price, sizeof run->price);
    s->base.classify.sp_as_fp = run->sp_as_fp;
    s->base.classify.max_panel_area = run->max_panel_area;
    costs_from_run(&s->base, run);
    s->seed = run->seed;
    s->evaluations = run->evaluations;
    s->population = run->population;
    s->generations = run->generations;
    s->jobs = run->jobs > 0 ? run->jobs : 1;
    /* A merge of shards searches no share: its settings are the whole
     * run's. */
    if (run->shard_index > 0)
        s->shard = (struct shard){run->shard_index, run->shard_count};
    mesh->object = run->object[0] ? run->object : NULL;
    mesh->group = run->group[0] ? run->group : NULL;
    *flip_normals = run->flip_normals;
    return design_space_check(&s->space, NULL, err);
}

/* Reading a surface: its SHA-256 and the surface itself at once, the
 * hash on a thread of its own (it is a quarter of reading a
 * 100,000-triangle OBJ). */
/* What reading a single surface parses: the file into the surface. */
struct surface_read {
    const char *path;
    const struct mesh_options *mesh;
    struct surface *surface;
};

static int surface_parse(void *context, const struct facet_stop *stop,
                         struct facet_error *err)
{
    struct surface_read *r = context;
    return surface_open_stoppable(r->path, r->mesh, stop, r->surface, err);
}

/* The SHA-256 of path into digest and the surface it holds into *surface
 * (the caller's to release with surface_close, also after a failure). */
static int read_surface(const char *path, const struct mesh_options *mesh,
                        const struct facet_stop *stop, char digest[65],
                        struct surface *surface, struct facet_error *err)
{
    struct surface_read read = {path, mesh, surface};
    return study_read_hashed(&path, 1, (char (*)[65])digest, surface_parse,
                             &read, stop, err);
}

/* The places a run's surface may be, first first: as stored (absolute
 * since runs record it so; relative to the working folder in older files),
 * then a relative path against the database's folder, then the file's name
 * in the database's folder (a database copied with its surface beside
 * it). Returns how many it wrote into place[]. */
int study_surface_candidates(const char *db_path, const char *stored,
                             char place[3][4096])
{
    int n = 0;
    snprintf(place[n++], sizeof place[0], "%s", stored);
    char folder[4096];
    snprintf(folder, sizeof folder, "%s", db_path);
    char *slash = strrchr(folder, '/');
    if (slash != NULL)
        slash[1] = '\0';
    else
        snprintf(folder, sizeof folder, "./");
    const char *name = strrchr(stored, '/');
    name = name ? name + 1 : stored;
    const char *tail[2] = {stored[0] != '/' ? stored : NULL, name};
    for (int k = 0; k < 2; k++) {
        if (tail[k] == NULL)
            continue;
        size_t a = strlen(folder), b = strlen(tail[k]);
        if (a + b >= sizeof place[0])
            continue;  /* too long to be a file anyway */
        memcpy(place[n], folder, a);
        memcpy(place[n] + a, tail[k], b + 1);
        if (strcmp(place[n], place[n - 1]) != 0)
            n++;
    }
    return n;
}

int study_open_surface(const struct store *store, const struct run_info *run,
                       struct surface *surface, struct facet_error *err)
{
    return study_open_surface_stoppable(store, run, NULL, surface, err);
}

int study_open_surface_stoppable(const struct store *store,
                                 const struct run_info *run,
                                 const struct study_hooks *hooks,
                                 struct surface *surface,
                                 struct facet_error *err)
{
    struct facet_stop stop = study_stop(hooks);
    struct optimize_settings settings;
    struct mesh_options mesh;
    int flip;
    memset(surface, 0, sizeof *surface);
    if (store_run_is_project(run))
        return facet_error_set(err, FACET_EINPUT,
            "run %lld is a project of several surfaces: its surfaces are "
            "opened together, as its building, not one by one",
            (long long)run->id);
    int rc = study_settings(run, &settings, &mesh, &flip, err);
    if (rc != FACET_OK)
        return rc;
    /* The method the run took, not what would be chosen today: a run
     * started by an older Facet keeps its UV. */
    if ((rc = store_run_setting_check(run, RUN_SETTING_UV_METHOD, err)))
        return rc;
    enum param_method uv = run->uv_method;
    char place[3][4096];
    int nplaces = study_surface_candidates(store_path(store), run->surface_path,
                                     place);
    int changed = 0;
    struct facet_error first;
    facet_error_clear(&first);
    for (int k = 0; k < nplaces; k++) {
        if (access(place[k], F_OK) != 0)
            continue;
        char digest[65];
        rc = read_surface(place[k], &mesh, &stop, digest, surface, err);
        if (rc != FACET_OK)
            return rc;
        if (strcmp(digest, run->surface_sha256) == 0)
            return surface_prepare_stoppable(surface, flip, uv, &stop, err);
        if (!changed)
            facet_error_about(&first, FACET_SETTING_SURFACE, FACET_EINPUT,
                "%s: the file has changed since run %lld was made from it "
                "(SHA-256 %.12s..., was %.12s...); give the original's "
                "place", place[k], (long long)run->id, digest,
                run->surface_sha256);
        changed = 1;
        surface_close(surface);
        memset(surface, 0, sizeof *surface);
    }
    if (changed) {
        *err = first;
        return FACET_EINPUT;
    }
    return facet_error_about(err, FACET_SETTING_SURFACE, FACET_EINPUT,
        "%s: no such file (run %lld's surface, SHA-256 %.12s..., nor "
        "beside the database); if it has moved, give its new place",
        run->surface_path, (long long)run->id, run->surface_sha256);
}

int study_repoint_surface(struct store *store, int64_t run_id,
                          const char *path, struct facet_error *err)
{
    struct run_info run;
    int rc = store_run_get(store, run_id, &run, err);
    if (rc != FACET_OK)
        return rc;
    if (store_run_is_project(&run))
        return facet_error_set(err, FACET_EINPUT,
            "run %lld is a project: its files are looked for where they "
            "were and beside the database", (long long)run_id);
    char digest[65];
    if ((rc = sha256_file(path, digest, err)) != FACET_OK)
        return rc;
    if (strcmp(digest, run.surface_sha256) != 0)
        return facet_error_set(err, FACET_EINPUT,
            "%s: not run %lld's surface (SHA-256 %.12s..., the "
            "run's is %.12s...)", path, (long long)run_id, digest,
            run.surface_sha256);
    char absolute[4096];
    if (realpath(path, absolute) == NULL)
        return facet_error_set(err, FACET_EINPUT, "%s: %s", path,
                               strerror(errno));
    if (strlen(absolute) >= sizeof run.surface_path)
        return facet_error_set(err, FACET_EINPUT,
                               "%.200s...: path too long", path);
    if (store_read_only(store))
        return facet_error_set(err, FACET_EINPUT,
            "%s is read-only here, so run %lld cannot be "
            "re-pointed; copy the database where it can be written",
            store_path(store), (long long)run_id);
    return store_run_set_surface(store, run_id, absolute, err);
}

int study_rank(struct store *store, int64_t run, struct facet_error *err)
{
    struct run_info info;
    struct optimize_settings settings;
    struct mesh_options mesh;
    int flip;
    int rc = store_run_get(store, run, &info, err);
    if (rc == FACET_OK)
        rc = study_settings(&info, &settings, &mesh, &flip, err);
    if (rc != FACET_OK)
        return rc;
    struct option_row *rows;
    size_t n;
    rc = store_options_get(store, run, &rows, &n, err);
    if (rc != FACET_OK)
        return rc;
    struct evaluated_option *options = malloc((n ? n : 1) * sizeof *options);
    int64_t *numbers = malloc((n ? n : 1) * sizeof *numbers);
    struct front front;
    memset(&front, 0, sizeof front);
    if (options == NULL || numbers == NULL)
        rc = facet_error_set(err, FACET_EWORK, "out of memory");
    for (size_t k = 0; rc == FACET_OK && k < n; k++) {
        evaluated_of(&rows[k], &options[k]);
        numbers[k] = rows[k].number;
    }
    if (rc == FACET_OK)
        rc = front_analyse(options, n, settings.objectives,
                           settings.nobjectives,
                           settings.base.classify.max_panel_area, &front,
                           err);
    if (rc == FACET_OK)
        rc = store_options_set_pareto(store, run, numbers, front.rank,
                                      front.crowding, n,
                                      front.knee < n ? numbers[front.knee]
                                                     : 0,
                                      front.hypervolume, err);
    front_free(&front);
    free(options);
    free(numbers);
    free(rows);
    return rc;
}

/* Evaluates option on surface with the run's settings. */
static int evaluate_option(const struct run_info *run,
                           const struct surface *surface,
                           const struct option_row *option,
                           struct panelization *panels,
                           struct option_totals *totals,
                           struct facet_error *err)
{
    struct optimize_settings settings;
    struct mesh_options mesh;
    int flip;
    int rc = study_settings(run, &settings, &mesh, &flip, err);
    if (rc != FACET_OK)
        return rc;
    struct option_params params = option_params_at(
        &settings.base, option->nu, option->nv, option->threshold_mm);
    if (option->totals.planarized) {
        /* Its panels were stored when it was made; made again, they are
         * planarized again, never classified in its place. */
        params.unmeasured = 0;
        return study_planar_evaluate(run, surface, &params, NULL, panels,
                                     totals, err);
    }
    return option_evaluate(surface, &params, NULL, panels, totals, err);
}

int study_option_panels(struct store *store, const struct run_info *run,
                        const struct surface *surface, int64_t number,
                        struct panelization *panels,
                        struct option_totals *totals,
                        struct facet_error *err)
{
    memset(panels, 0, sizeof *panels);
    struct option_row option;
    int rc = store_option_get(store, run->id, number, &option, err);
    if (rc != FACET_OK)
        return rc;
    *totals = option.totals;
    int stored;
    rc = store_panels_exist(store, run->id, number, &stored, err);
    if (rc != FACET_OK)
        return rc;
    if (stored)
        return store_panels_get(store, run->id, number, panels, err);
    struct surface own;
    memset(&own, 0, sizeof own);
    if (surface == NULL) {
        rc = study_open_surface(store, run, &own, err);
        surface = &own;
    }
    if (rc == FACET_OK)
        rc = evaluate_option(run, surface, &option, panels, totals, err);
    /* Stored for the next look, when the file may be written: the panels,
     * and the option's row measured in full where its run measured it
     * only for what the run reads. */
    if (rc == FACET_OK && !store_read_only(store))
        rc = store_panels_put(store, run->id, number, panels, err);
    if (rc == FACET_OK && run->measured != OPTION_MEASURE_ALL &&
        option_totals_measures(&option.totals) != OPTION_MEASURE_ALL) {
        /* What the run measured stays as it measured it, to the bit; the
         * rest is this evaluation's. */
        struct option_row measured = option;
        option_totals_fill(&measured.totals, totals);
        if (!store_read_only(store))
            rc = store_options_measured(store, run->id, &measured, 1, err);
    }
    if (surface == &own)
        surface_close(&own);
    return rc;
}

/* The bytes free to the writer on the disk of the database at db_path
 * (its folder's file system), or -1 when that cannot be told. */
static double disk_free_bytes(const char *db_path)
{
    char folder[4096];
    snprintf(folder, sizeof folder, "%s", db_path);
    char *slash = strrchr(folder, '/');
    if (slash == NULL)
        snprintf(folder, sizeof folder, ".");
    else if (slash == folder)
        slash[1] = '\0';
    else
        *slash = '\0';
    struct statvfs fs;
    if (statvfs(folder, &fs) != 0)
        return -1;
    return (double)fs.f_bavail * (double)fs.f_frsize;
}

/* bytes as a person reads them: "850 kB", "12.3 MB", "4.1 GB". */
static void format_bytes(double bytes, char *out, size_t size)
{
    const double kilobyte = 1000;
    if (bytes < 1e6)
        snprintf(out, size, "%.0f kB", bytes / kilobyte);
    else if (bytes < 1e9)
        snprintf(out, size, "%.1f MB", bytes / 1e6);
    else
        snprintf(out, size, "%.1f GB", bytes / 1e9);
}

/* Refuses, before any work, a run whose options (those not stored yet)
 * cannot fit the free disk space of its database. */
static int check_room(const struct store *store,
                      const struct optimize_settings *settings,
                      int64_t stored, struct facet_error *err)
{
    double free_bytes = disk_free_bytes(store_path(store));
    int64_t left = optimize_total(settings) - stored;
    double need = (double)(left > 0 ? left : 0) * STUDY_OPTION_BYTES;
    if (free_bytes >= 0 && need > free_bytes) {
        char a[32], b[32];
        format_bytes(need, a, sizeof a);
        format_bytes(free_bytes, b, sizeof b);
        return facet_error_set(err, FACET_EINPUT,
            "%s: the run's %lld options need about %s and its disk has %s "
            "free: make room, or search a smaller space", store_path(store),
            (long long)left, a, b);
    }
    return FACET_OK;
}

/* Whether the user asked the study to stop (the hook, if any). */
static int should_stop(const struct study_hooks *hooks)
{
    return hooks != NULL && hooks->should_stop != NULL &&
           hooks->should_stop(hooks->context);
}

/* Stores the panels of every Pareto option of run not stored yet,
 * evaluating them on every core. */
size_t study_front_budget(int64_t options)
{
    int64_t budget = options / STUDY_FRONT_SHARE;
    return budget < STUDY_FRONT_MIN ? STUDY_FRONT_MIN : (size_t)budget;
}

int study_knee_then_spread(const void *a, const void *b)
{
    const struct option_row *x = a, *y = b;
    if (x->knee != y->knee)
        return x->knee ? -1 : 1;
    if (x->crowding != y->crowding)
        return x->crowding > y->crowding ? -1 : 1;
    return (x->number > y->number) - (x->number < y->number);
}

/* Measures run's Pareto options in full where the run measured them only
 * for what it reads, and stores the panels of those its panel policy
 * keeps (the knee, the whole front, or the knee and the most spread when
 * the front is larger than its share of the run), from one evaluation
 * each, on every core. */
static int store_front_panels(struct store *store, const struct run_info *run,
                              const struct surface *surface,
                              const struct panel_lattice *lattice,
                              const struct optimize_settings *settings,
                              const struct study_hooks *hooks, int *stopped,
                              struct facet_error *err)
{
    *stopped = 0;
    /* Only the front is read (by the rank index), not the whole run. */
    struct option_query q = {run->id, 1, NULL, NULL, 0, 0, 0, 0};
    struct option_row *rows = NULL;
    size_t n = 0, nfront = 0;
    int rc = store_run_setting_check(run, RUN_SETTING_STORE_PANELS, err);
    if (rc != FACET_OK)
        return rc;
    int keep = run->store_panels != KEEP_NONE;
    int knee_only = run->store_panels == KEEP_KNEE;
    rc = store_options_query_rows(store, &q, &rows, &n, err);
    struct design_point *points = malloc((n ? n : 1) * sizeof *points);
    size_t *from = malloc((n ? n : 1) * sizeof *from);
    int *wants_panels = calloc(n ? n : 1, sizeof *wants_panels);
    if (rc == FACET_OK &&
        (points == NULL || from == NULL || wants_panels == NULL))
        rc = facet_error_set(err, FACET_EWORK, "out of memory");
    /* A front larger than its share of the run: the knee and the most
     * spread of the others, the rest when first looked at. */
    struct run_info ranked;  /* its options counted by the ranking */
    if (rc == FACET_OK)
        rc = store_run_get(store, run->id, &ranked, err);
    size_t budget = rc == FACET_OK ? study_front_budget(ranked.options) : 0;
    if (rc == FACET_OK && keep && !knee_only && n > budget)
        qsort(rows, n, sizeof *rows, study_knee_then_spread);
    else
        budget = n;
    for (size_t k = 0; rc == FACET_OK && k < n; k++) {
        int stored = 1;
        if (keep && !(knee_only && !rows[k].knee) && k < budget)
            rc = store_panels_exist(store, run->id, rows[k].number, &stored,
                                    err);
        wants_panels[k] = !stored;
        int unmeasured =
            (OPTION_MEASURE_ALL & ~option_totals_measures(&rows[k].totals))
            != 0 && run->measured != OPTION_MEASURE_ALL;
        if (rc == FACET_OK && (wants_panels[k] || unmeasured)) {
            points[nfront] = (struct design_point){rows[k].nu, rows[k].nv,
                                                   rows[k].threshold_mm};
            from[nfront++] = k;
        }
    }
    /* What the panels take on disk, against what it has: a front of fine
     * grids can need more than the disk holds (two 1000 x 1000 options:
     * 611 MB). Then the knee alone, or nothing, with the reason said;
     * facet show and export compute an option's panels when asked. */
    double free_bytes = disk_free_bytes(store_path(store));
    double need = 0, knee_need = 0;
    size_t knee_at = n;
    for (size_t f = 0; f < nfront; f++) {
        const struct option_row *r = &rows[from[f]];
        if (!wants_panels[from[f]])
            continue;
        need += (double)r->nu * r->nv * STUDY_PANEL_BYTES;
        if (r->knee) {
            knee_at = from[f];
            knee_need = (double)r->nu * r->nv * STUDY_PANEL_BYTES;
        }
    }
    if (rc == FACET_OK && free_bytes >= 0 && need > free_bytes) {
        char text[400], a[32], b[32];
        int keep_knee = knee_at < n && knee_need <= free_bytes;
        format_bytes(need, a, sizeof a);
        format_bytes(free_bytes, b, sizeof b);
        snprintf(text, sizeof text, "the front's panels need about %s and "
                 "the disk has %s free: %s stored (facet show and export "
                 "compute an option's panels when asked)", a, b,
                 keep_knee ? "only the knee's are" : "none are");
        if (hooks != NULL && hooks->warning != NULL)
            hooks->warning(hooks->context, text);
        for (size_t k = 0; k < n; k++)
            wants_panels[k] = wants_panels[k] && keep_knee && k == knee_at;
    }
    /* Measured in full, with the panels a designer opens. */
    struct option_params full = settings->base;
    full.unmeasured = 0;
    struct panelization *panels = NULL;
    struct option_totals *totals = NULL;
    struct option_row *measured = NULL;
    if (rc == FACET_OK && nfront > 0) {
        panels = calloc(nfront, sizeof *panels);
        totals = malloc(nfront * sizeof *totals);
        measured = malloc(nfront * sizeof *measured);
        if (panels == NULL || totals == NULL || measured == NULL)
            rc = facet_error_set(err, FACET_EWORK, "out of memory");
        /* In chunks, with a stop heard between them: a front of fine
         * grids takes a while, and Ctrl-C must leave the run resumable. */
        size_t chunk = 4 * (size_t)(settings->jobs > 0 ? settings->jobs : 1);
        /* And inside a chunk: the panels of one option of a fine grid
         * take tens of seconds to make. */
        struct facet_stop stop = study_stop(hooks);
        for (size_t first = 0; rc == FACET_OK && first < nfront;
             first += chunk) {
            if (should_stop(hooks)) {
                *stopped = 1;
                break;
            }
            size_t count = nfront - first < chunk ? nfront - first : chunk;
            rc = optimize_evaluate_panels(surface, lattice, &full,
                                          points + first, count,
                                          settings->jobs, &stop,
                                          panels + first, totals + first,
                                          err);
            if (rc == FACET_ESTOP) {
                facet_error_clear(err);
                rc = FACET_OK;
                *stopped = 1;
                break;
            }
            size_t nmeasured = 0;
            for (size_t f = first;
                 rc == FACET_OK && !*stopped && f < first + count; f++) {
                const struct option_row *r = &rows[from[f]];
                /* What the run measured, measured again: the same. */
                assert(totals[f].cost == r->totals.cost &&
                       totals[f].planarity == r->totals.planarity &&
                       totals[f].panels == r->totals.panels);
                if (run->measured != OPTION_MEASURE_ALL) {
                    measured[nmeasured] = *r;
                    measured[nmeasured++].totals = totals[f];
                }
                /* A fine grid's panels take seconds to write: a stop
                 * inside leaves the option's panels unstored (show and
                 * export make them when asked), its measures kept. */
                if (wants_panels[from[f]])
                    rc = store_panels_put_stoppable(store, run->id,
                                                    r->number, &panels[f],
                                                    &stop, err);
                if (rc == FACET_ESTOP) {
                    facet_error_clear(err);
                    rc = FACET_OK;
                }
                if (should_stop(hooks))
                    *stopped = 1;
            }
            if (rc == FACET_OK && nmeasured > 0)
                rc = store_options_measured(store, run->id, measured,
                                            nmeasured, err);
            for (size_t f = first; f < first + count; f++)
                panelization_free(&panels[f]);
        }
    }
    free(panels);
    free(totals);
    free(measured);
    free(points);
    free(from);
    free(wants_panels);
    free(rows);
    return rc;
}

int study_finish(struct store *store, const struct run_info *run,
                 const struct surface *surface,
                 const struct panel_lattice *lattice,
                 const struct optimize_settings *settings,
                 const struct study_hooks *hooks,
                 enum optimize_outcome *outcome, struct facet_error *err)
{
    study_stage(hooks, "ranking options");
    int rc = study_rank(store, run->id, err);
    if (rc == FACET_OK)
        rc = store_analyze(store, err);
    /* A stop heard after the last batch still leaves the run resumable:
     * ranked, its front's panels stored later. */
    if (rc == FACET_OK && *outcome == OPTIMIZE_DONE && should_stop(hooks))
        *outcome = OPTIMIZE_INTERRUPTED;
    if (rc == FACET_OK && *outcome == OPTIMIZE_DONE && surface != NULL) {
        study_stage(hooks, "storing the Pareto options' panels");
        int stopped;
        rc = store_front_panels(store, run, surface, lattice, settings,
                                hooks, &stopped, err);
        if (stopped)
            *outcome = OPTIMIZE_INTERRUPTED;
    }
    if (rc == FACET_OK && *outcome == OPTIMIZE_DONE && surface != NULL) {
        int stopped;
        rc = study_planarize_front(store, run, surface, settings, hooks,
                                   &stopped, err);
        if (stopped)
            *outcome = OPTIMIZE_INTERRUPTED;
    }
    return rc;
}

/* Runs the optimiser for run (recorded, status running) on the prepared
 * surface, then ranks and finishes it. elapsed_before: seconds of earlier
 * sessions. */
static int study_go(struct store *store, struct run_info *run,
                    const struct surface *surface,
                    struct project_search *project,
                    const struct optimize_settings *asked,
                    const struct study_hooks *hooks, double started,
                    enum optimize_outcome *outcome, struct facet_error *err)
{
    /* Every option measured for what the run recorded it needs, however
     * often it is resumed; its front in full at its end. */
    struct optimize_settings run_settings = *asked;
    run_settings.base.unmeasured = OPTION_MEASURE_ALL & ~run->measured;
    const struct optimize_settings *settings = &run_settings;
    struct study_state state = {store, run->id, hooks, NULL, 0, -1, 0,
                                project, NULL, 0};
    struct optimize_hooks optimize_hooks = {&state, store_batch,
                                            report_progress, stop_requested};
    struct option_row *rows = NULL;
    struct evaluated_option *stored = NULL;
    size_t nstored = 0;
    int rc = store_options_get(store, run->id, &rows, &nstored, err);
    if (rc == FACET_OK && nstored > 0) {
        stored = malloc(nstored * sizeof *stored);
        if (stored == NULL)
            rc = facet_error_set(err, FACET_EWORK, "out of memory");
        /* The search's own options only: a planarized option shares its
         * design point with the classified one it was made beside
         * (study_planar.c), and is no evaluation of that point. */
        size_t kept = 0;
        for (size_t k = 0; rc == FACET_OK && k < nstored; k++)
            if (!rows[k].totals.planarized)
                evaluated_of(&rows[k], &stored[kept++]);
        nstored = kept;
    }
    free(rows);
    /* The panels of the run and of its front from one lattice, so that
     * the stored panels add up to their options' totals. */
    struct panel_lattice *lattice = NULL;
    if (rc == FACET_OK && project == NULL) {
        study_stage(hooks, "dividing the surface along the space's grid lines");
        struct facet_stop stop = study_stop(hooks);
        rc = optimize_lattice_stoppable(surface, settings, &stop, &lattice,
                                        err);
    }
    /* Stopped while dividing: the run, recorded, ends interrupted like
     * one stopped between batches, and resumes. */
    int stopped = rc == FACET_ESTOP;
    if (stopped) {
        facet_error_clear(err);
        rc = FACET_OK;
        *outcome = OPTIMIZE_INTERRUPTED;
    }
    /* A run of many options stores them without the indexes by metric
     * and builds those once at its end (store_indexes_defer). */
    int deferred = 0;
    int64_t total = 0;
    if (rc == FACET_OK)
        rc = optimize_total_with(project ? &project->evaluator : NULL,
                                 settings, &total, err);
    if (rc == FACET_OK)
        rc = store_indexes_defer(store, total - (int64_t)nstored, &deferred,
                                 err);
    if (!stopped)
        study_stage(hooks, "evaluating options");
    if (rc == FACET_OK && !stopped && project != NULL)
        rc = optimize_run_with(&project->evaluator, settings, stored,
                               nstored, &optimize_hooks, outcome, err);
    else if (rc == FACET_OK && !stopped)
        rc = optimize_run(surface, lattice, settings, stored, nstored,
                          &optimize_hooks, outcome, err);
    free(stored);
    free(state.rows);
    free(state.surface_rows);

    struct facet_error later;
    facet_error_clear(&later);
    /* Built however the run ended (ranking does not touch them), before
     * the statistics and the front's panels read them; the error of a
     * failed run stays the one told. */
    if (deferred) {
        study_stage(hooks, "indexing options");
        int index_rc = store_indexes_build(store, run->id, NULL,
                                           rc == FACET_OK ? err : &later);
        if (rc == FACET_OK)
            rc = index_rc;
    }
    if (rc == FACET_OK)
        rc = study_finish(store, run, surface, lattice, settings, hooks,
                          outcome, err);
    panel_lattice_free(lattice);
    enum run_status status = rc != FACET_OK ? RUN_FAILED
                             : *outcome == OPTIMIZE_DONE ? RUN_DONE
                                                         : RUN_INTERRUPTED;
    /* The status is written even after a failure, with its own error
     * kept apart so the first error is the one reported. */
    int status_rc = store_run_set_status(store, run->id, status,
                                         run->elapsed + clock_seconds() -
                                             started,
                                         rc == FACET_OK ? err : &later);
    return rc != FACET_OK ? rc : status_rc;
}

/* The warnings of a new run on the prepared surface: the surface's own,
 * a mesh coarser than the finest grid of the space's panels (by the
 * UV's cover of its box, before any option is evaluated), and facets that
 * sag a fair part of the space's smallest threshold. Each goes to
 * the warning hook and, one per line, into text (size bytes). */
static void collect_warnings(const struct surface *surface,
                             const struct design_space *space,
                             const struct study_hooks *hooks, char *text,
                             size_t size)
{
    char lines[SURFACE_MAX_WARNINGS + 2][400];
    int n = 0;
    for (int k = 0; k < surface->nwarnings; k++)
        snprintf(lines[n++], sizeof lines[0], "%s", surface->warnings[k]);
    const struct uv_report *uv = &surface->param.report;
    double box = (uv->umax - uv->umin) * (uv->vmax - uv->vmin);
    double fill = box > 0 ? uv->uv_area / box : 1;
    double side = grid_panel_side(surface->mesh.area, fill, space->u_max,
                                  space->v_max);
    char grid[80];
    snprintf(grid, sizeof grid, "the finest grid of the space, %d x %d",
             space->u_max, space->v_max);
    double facet;
    if (mesh_facet_size(&surface->mesh, &facet, NULL) == FACET_OK &&
        facet > 0 && coarse_mesh_warning(facet, side, grid, lines[n],
                                         sizeof lines[0]))
        n++;
    /* Against the smallest threshold: the one the sag matters most to. */
    char what[80];
    snprintf(what, sizeof what, "the smallest threshold of the space, t = "
             "%g mm", space->t_min_mm);
    if (facet_sag_warning(surface->facet_sag, units_m_of_mm(space->t_min_mm), what,
                          lines[n], sizeof lines[0]))
        n++;
    size_t used = 0;
    text[0] = '\0';
    for (int k = 0; k < n; k++) {
        if (hooks != NULL && hooks->warning != NULL)
            hooks->warning(hooks->context, lines[k]);
        int wrote = snprintf(text + used, size - used, "%s%s",
                             used ? "\n" : "", lines[k]);
        if (wrote < 0 || (size_t)wrote >= size - used)
            break;
        used += (size_t)wrote;
    }
}

enum optimize_method study_auto_method(const struct design_space *space)
{
    int continuous = space->t_max_mm > space->t_min_mm &&
                     space->t_step_mm == 0;
    return !continuous && design_space_size(space) <= STUDY_EXHAUSTIVE_LIMIT
               ? METHOD_EXHAUSTIVE : METHOD_NSGA2;
}

int study_method_parse(const char *text, const char *what,
                       const struct design_space *space,
                       enum optimize_method *out, struct facet_error *err)
{
    if (strcmp(text, "auto") == 0) {
        *out = study_auto_method(space);
        return FACET_OK;
    }
    if (optimize_method_parse(text, what, out, NULL) == FACET_OK)
        return FACET_OK;
    return facet_error_set(err, FACET_EINPUT,
        "%s: '%s' unknown (choose auto, exhaustive, random or nsga2)", what,
        text);
}

int study_request_check(const struct study_request *request,
                        struct facet_error *err)
{
    /* Stored whole or refused: a name cut at a byte count can end inside
     * a character, and a control character in one reaches terminals. */
    size_t most = sizeof ((struct run_info *)0)->name - 1;
    if (strlen(request->name) > most)
        return facet_error_set(err, FACET_EINPUT,
            "the run's name is %zu bytes: at most %zu", strlen(request->name),
            most);
    if (!text_is_clean(request->name))
        return facet_error_set(err, FACET_EINPUT,
            "the run's name is not clean UTF-8 text (control characters or "
            "invalid bytes)");
    if (request->planarize_closeness > 0 && request->nfiles > 0)
        return facet_error_set(err, FACET_EINPUT,
            "planarized options are made for a single surface, not yet "
            "for a building's surfaces");
    if (request->planarize_closeness > 0 && request->settings.shard.count > 0)
        return facet_error_set(err, FACET_EINPUT,
            "planarized options are made from a run's front, which a "
            "shard does not know: not for a shard");
    if (request->nfiles > 0 && !(request->weld >= SEAM_WELD_MIN &&
                                 request->weld <= SEAM_WELD_MAX))
        return facet_error_set(err, FACET_EINPUT,
            "the welding tolerance is %g mm: from %g to %g mm",
            units_mm(request->weld), units_mm(SEAM_WELD_MIN),
            units_mm(SEAM_WELD_MAX));
    return design_space_check(&request->settings.space, NULL, err);
}

/* Reads and prepares the single surface of request into *surface,
 * recording what it is into run (its path already there): its SHA-256,
 * area, triangles, UV and warnings. A file that names several objects (or
 * groups) is a project: refused unless request selects one of them. */
static int surface_read(const struct study_request *request,
                        const struct study_hooks *hooks,
                        struct surface *surface, struct run_info *run,
                        struct facet_error *err)
{
    study_stage(hooks, "reading the surface");
    struct facet_stop stop = study_stop(hooks);
    int rc = read_surface(request->surface_path, &request->mesh, &stop,
                          run->surface_sha256, surface, err);
    size_t named = rc == FACET_OK && !surface->selected
                       ? project_count_named(&surface->obj) : 0;
    if (named > 1)
        return facet_error_about(err, FACET_SETTING_MODULE, FACET_EINPUT,
            "%s: a project of %zu surfaces (its objects or groups) needs a "
            "panel module", request->surface_path, named);
    if (rc == FACET_OK && !request->units_named)
        rc = surface_units_check(surface, err);
    if (rc == FACET_OK) {
        study_stage(hooks, "preparing the surface (UV, curvature)");
        rc = surface_prepare_stoppable(surface, request->flip_normals,
                                       request->uv, &stop, err);
    }
    if (rc != FACET_OK)
        return rc;
    collect_warnings(surface, &request->settings.space, hooks, run->warnings,
                     sizeof run->warnings);
    run->surface_area = surface->mesh.area;
    run->triangles = (int64_t)surface->mesh.ntriangles;
    run->uv_method = surface->param.method;
    return FACET_OK;
}

int study_start(struct store *store, const struct study_request *request,
                const struct study_hooks *hooks, int64_t *run_id,
                enum optimize_outcome *outcome, struct facet_error *err)
{
    *run_id = 0;
    *outcome = OPTIMIZE_INTERRUPTED;
    const struct optimize_settings *s = &request->settings;
    int rc = design_space_check(&s->space, NULL, err);
    if (rc == FACET_OK)
        rc = store_check(store, err);
    if (rc == FACET_OK)
        rc = check_room(store, s, 0, err);
    if (rc != FACET_OK)
        return rc;
    double started = clock_seconds();
    struct run_info run;
    memset(&run, 0, sizeof run);
    if ((rc = study_request_check(request, err)) != FACET_OK)
        return rc;
    snprintf(run.name, sizeof run.name, "%s", request->name);
    run.store_panels = request->store_panels;
    /* Recorded absolute, so the run's surface is found from any folder;
     * a path realpath cannot resolve fails below, when it is read. */
    char absolute[4096];
    const char *recorded = realpath(request->surface_path, absolute)
                               ? absolute : request->surface_path;
    if (strlen(recorded) >= sizeof run.surface_path)
        return facet_error_set(err, FACET_EINPUT, "%.200s...: path too long",
                               recorded);
    memcpy(run.surface_path, recorded, strlen(recorded) + 1);
    struct surface surface;
    memset(&surface, 0, sizeof surface);
    struct project project;
    memset(&project, 0, sizeof project);
    struct project_search search;
    memset(&search, 0, sizeof search);
    struct surface_row *surfaces = NULL;
    int is_project = request->nfiles > 0;
    if (is_project) {
        rc = study_project_read(request, store_path(store), hooks, &project,
                                &surfaces, &run, err);
        if (rc == FACET_OK)
            rc = study_project_search(request, &project, &search, err);
        for (size_t i = 0; rc == FACET_OK && i < project.nsurfaces; i++) {
            surfaces[i].grid_nu = search.overrides[i].nu;
            surfaces[i].grid_nv = search.overrides[i].nv;
        }
        if (rc == FACET_OK)
            study_project_warnings(request, &project, hooks, &run);
    } else {
        rc = surface_read(request, hooks, &surface, &run, err);
    }
    if (rc != FACET_OK) {
        project_search_free(&search);
        project_close(&project);
        free(surfaces);
        surface_close(&surface);
        return rc;
    }
    run.units = request->mesh.units;
    run.uv = request->uv;
    run.method = s->method;
    run.seed = s->seed;
    run.u_min = s->space.u_min;
    run.u_max = s->space.u_max;
    run.v_min = s->space.v_min;
    run.v_max = s->space.v_max;
    run.threshold_min_mm = s->space.t_min_mm;
    run.threshold_max_mm = s->space.t_max_mm;
    run.threshold_step_mm = s->space.t_step_mm;
    memcpy(run.price, s->base.classify.price, sizeof run.price);
    run.sp_as_fp = s->base.classify.sp_as_fp;
    costs_to_run(&run, &s->base);
    run.max_panel_area = s->base.classify.max_panel_area;
    run.curvature_tol = s->base.classify.curvature_tol;
    run.planarize_closeness_mm = request->planarize_closeness > 0
                                     ? units_mm(request->planarize_closeness)
                                     : NAN;
    run.per_panel = s->base.mode;
    run.flip_normals = request->flip_normals;
    snprintf(run.object, sizeof run.object, "%s",
             request->mesh.object ? request->mesh.object : "");
    snprintf(run.group, sizeof run.group, "%s",
             request->mesh.group ? request->mesh.group : "");
    objectives_format(run.objectives, sizeof run.objectives, s->objectives,
                      s->nobjectives);
    run.population = s->method == METHOD_NSGA2 ? s->population : 0;
    run.generations = s->method == METHOD_NSGA2 ? s->generations : 0;
    run.evaluations = s->method == METHOD_RANDOM ? s->evaluations : 0;
    run.jobs = s->jobs;
    run.shard_index = s->shard.index;
    run.shard_count = s->shard.count;
    /* Measured in full: a shard, since the whole run's front is known
     * only at the merge, which has no surface to measure it with; and a
     * building, whose per-surface rows hold every quantity, but for the
     * panels' widths, which cost ten evaluations' work and more on every
     * surface (option.h): measured when the run reads them (a width limit
     * or objective) or is asked to measure all, NULL otherwise. A
     * building's shards measure as the building does, so that their
     * merge is its run. */
    run.measured = request->measure_all
                       ? OPTION_MEASURE_ALL
                   : is_project
                       ? (OPTION_MEASURE_ALL & ~OPTION_MEASURE_WIDTHS) |
                             optimize_measures_needed(s)
                   : s->shard.count > 0 ? OPTION_MEASURE_ALL
                                        : optimize_measures_needed(s);
    rc = store_run_create(store, &run, err);
    if (rc == FACET_OK && is_project)
        rc = store_surfaces_put(store, run.id, surfaces, project.nsurfaces,
                                err);
    if (rc == FACET_OK) {
        *run_id = run.id;
        if (hooks != NULL && hooks->started != NULL)
            hooks->started(hooks->context, run.id);
        rc = study_go(store, &run, is_project ? NULL : &surface,
                      is_project ? &search : NULL, s, hooks, started,
                      outcome, err);
    } else if (run.id > 0) {
        /* Recorded, its surfaces not: failed, not left running. */
        struct facet_error ignored;
        store_run_set_status(store, run.id, RUN_FAILED, 0, &ignored);
    }
    project_search_free(&search);
    project_close(&project);
    free(surfaces);
    surface_close(&surface);
    return rc;
}

int study_resume(struct store *store, int64_t run_id,
                 const struct study_hooks *hooks,
                 enum optimize_outcome *outcome, struct facet_error *err)
{
    *outcome = OPTIMIZE_INTERRUPTED;
    double started = clock_seconds();
    struct run_info run;
    int rc = store_check(store, err);
    if (rc == FACET_OK)
        rc = store_run_get(store, run_id, &run, err);
    struct optimize_settings settings;
    struct mesh_options mesh;
    int flip;
    if (rc == FACET_OK)
        rc = study_settings(&run, &settings, &mesh, &flip, err);
    if (rc == FACET_OK)
        rc = check_room(store, &settings, run.options, err);
    /* Claimed before the surface is read (which takes a while), so that a
     * second --resume of the run is refused, not run twice. */
    if (rc == FACET_OK)
        rc = store_run_claim(store, run_id, &run, err);
    if (rc != FACET_OK)
        return rc;
    struct surface surface;
    memset(&surface, 0, sizeof surface);
    struct project project;
    memset(&project, 0, sizeof project);
    struct project_search search;
    memset(&search, 0, sizeof search);
    int is_project = store_run_is_project(&run);
    if (is_project) {
        study_stage(hooks, "preparing the project's surfaces (UV, curvature)");
        struct surface_grid *overrides = NULL;
        rc = study_project_reopen(store, &run, hooks, &project, &overrides,
                                  err);
        struct module_range range = {run.module_w_min, run.module_w_max,
                                     run.module_w_step, run.module_h_min,
                                     run.module_h_max, run.module_h_step};
        if (rc == FACET_OK)
            rc = project_search_init(&search, &project, &range, overrides,
                                     err);
        free(overrides);
    } else {
        study_stage(hooks, "preparing the surface (UV, curvature)");
        rc = study_open_surface_stoppable(store, &run, hooks, &surface, err);
    }
    if (rc != FACET_OK) {
        /* Given back as it was found, resumable once the surface is. */
        struct facet_error ignored;
        store_run_set_status(store, run_id, RUN_INTERRUPTED, run.elapsed,
                             &ignored);
    }
    if (rc == FACET_ESTOP) {
        /* Stopped while reading: the run is interrupted as it was, and
         * that is the outcome, not an error. */
        facet_error_clear(err);
        rc = FACET_OK;
        *outcome = OPTIMIZE_INTERRUPTED;
        project_search_free(&search);
        project_close(&project);
        surface_close(&surface);
        return rc;
    }
    if (rc == FACET_OK) {
        if (hooks != NULL && hooks->started != NULL)
            hooks->started(hooks->context, run_id);
        rc = study_go(store, &run, is_project ? NULL : &surface,
                      is_project ? &search : NULL, &settings, hooks,
                      started, outcome, err);
    }
    project_search_free(&search);
    project_close(&project);
    surface_close(&surface);
    return rc;
}

int study_front_edge_note(const struct run_info *run,
                          const struct front_bounds *b, char *text,
                          size_t size)
{
    static const char *const grid_variable[3] = {"U", "V",
                                                 "the threshold"};
    static const char *const module_variable[3] = {
        "the module width", "the module height", "the threshold"};
    static const char *const grid_unit[3] = {"", "", " mm"};
    static const char *const module_unit[3] = {" m", " m", " mm"};
    int project = store_run_is_project(run);
    const char *const *variable = project ? module_variable : grid_variable;
    const char *const *unit = project ? module_unit : grid_unit;
    double low[3] = {run->u_min, run->v_min, run->threshold_min_mm};
    double high[3] = {run->u_max, run->v_max, run->threshold_max_mm};
    if (project) {
        /* The bounds of a project's range are modules, not indices. */
        low[0] = run->module_w_min;
        high[0] = run->module_w_min + (run->u_max - 1) * run->module_w_step;
        low[1] = run->module_h_min;
        high[1] = run->module_h_min + (run->v_max - 1) * run->module_h_step;
    }
    size_t used = 0;
    text[0] = '\0';
    for (int k = 0; k < FRONT_BOUNDS; k++) {
        int v = k / 2, top = k % 2;
        if (b->at[k] == 0 || !(high[v] > low[v]))
            continue;
        int wrote = snprintf(text + used, size - used,
            "%s%lld of %lld Pareto options sit at %s = %g%s, the %s of its "
            "range %g:%g", used ? "; " : "", (long long)b->at[k],
            (long long)b->pareto, variable[v], top ? high[v] : low[v],
            unit[v], top ? "top" : "bottom", low[v], high[v]);
        if (wrote < 0 || (size_t)wrote >= size - used)
            break;
        used += (size_t)wrote;
    }
    if (used == 0)
        return 0;
    if (used < size)
        snprintf(text + used, size - used,
                 ": the front may go on beyond it; widen the range there "
                 "before taking the bound for an optimum");
    return 1;
}
