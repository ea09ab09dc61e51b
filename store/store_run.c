/*
 * store_run.c: the runs table: creating a run, reading it back, its status
 * as it goes, deleting it. See store.h.
 */
#include "store_internal.h"

#include <assert.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "core/base/text.h"

/* The columns of runs in the order run_from_row reads them. */
#define RUN_COLUMNS \
    "id, name, status, started, coalesce(finished, ''), elapsed," \
    " surface_path, surface_sha256, units, coalesce(object, '')," \
    " coalesce(group_name, ''), method, seed, u_min, u_max, v_min, v_max," \
    " threshold_min_mm, threshold_max_mm, threshold_step_mm, price_fp," \
    " price_sp, price_dp, sp_as_fp, max_panel_area_limit," \
    " coalesce(curvature_tol, 0), per_panel, flip_normals, objectives," \
    " coalesce(population, 0), coalesce(generations, 0)," \
    " coalesce(evaluations, 0), jobs, version, options," \
    " coalesce(writer_pid, 0), coalesce(writer_host, '')," \
    " hypervolume, coalesce(knee, 0), coalesce(pareto_options, 0)," \
    " best_cost, coalesce(surface_area, 0), coalesce(triangles, 0)," \
    " coalesce(uv_method, ''), coalesce(uv, ''), warnings, store_panels"

/* The cost model's columns (schema v5), the panels as built (v7), read
 * after RUN_COLUMNS, then the shards' (schema v6, store_shard.c). */
#define RUN_COST_COLUMNS \
    "price_panel, price_joint, price_sp_mould, price_dp_mould," \
    " mould_tol_mm, mould_mirror, sp_fit, max_gap_mm, max_kink_deg," \
    " measured, min_panel_width, planarize_closeness_mm, weld_mm, " \
    STORE_SHARD_COLUMNS ", " STORE_MODULE_COLUMNS

static void copy_text(char *to, size_t size, sqlite3_stmt *stmt, int col)
{
    const unsigned char *text = sqlite3_column_text(stmt, col);
    snprintf(to, size, "%s", text ? (const char *)text : "");
}

static const char *const run_status_names[] = {
    [RUN_RUNNING] = "running", [RUN_DONE] = "done",
    [RUN_INTERRUPTED] = "interrupted", [RUN_FAILED] = "failed"};
enum { RUN_STATUS_COUNT = sizeof run_status_names / sizeof *run_status_names };

const char *run_status_name(enum run_status status)
{
    assert((unsigned)status < RUN_STATUS_COUNT);
    return run_status_names[status];
}

int run_status_parse(const char *text, enum run_status *out)
{
    for (int k = 0; k < RUN_STATUS_COUNT; k++)
        if (strcmp(text, run_status_names[k]) == 0) {
            *out = (enum run_status)k;
            return 0;
        }
    return -1;
}

static const char *const keep_names[] = {
    [KEEP_FRONT] = "front", [KEEP_KNEE] = "knee", [KEEP_NONE] = "none"};

const char *study_keep_panels_name(enum study_keep_panels keep)
{
    return keep_names[keep];
}

int study_keep_panels_parse(const char *text, const char *what,
                            enum study_keep_panels *out,
                            struct facet_error *err)
{
    for (int k = 0; k < (int)(sizeof keep_names / sizeof *keep_names); k++)
        if (strcmp(text, keep_names[k]) == 0) {
            *out = (enum study_keep_panels)k;
            return FACET_OK;
        }
    return facet_error_set(err, FACET_EINPUT,
                           "%s: '%s' is not front, knee or none", what, text);
}

/* The columns of runs that hold the settings, by enum run_setting. */
static const char *const setting_column[RUN_SETTINGS] = {
    [RUN_SETTING_UNITS] = "units", [RUN_SETTING_METHOD] = "method",
    [RUN_SETTING_PER_PANEL] = "per_panel",
    [RUN_SETTING_UV_METHOD] = "uv_method", [RUN_SETTING_UV] = "uv",
    [RUN_SETTING_STORE_PANELS] = "store_panels"};

/* An automatic UV is "" in the file (NULL for uv): a run of a Facet that
 * did not record the UV it took, or one that asked for none. */
static const char *uv_text(enum param_method method)
{
    return method == PARAM_AUTO ? "" : param_method_name(method);
}

/* Reads the setting column col holds into its field of *r; text that
 * names nothing is kept in r->unknown instead. */
static void setting_from_row(sqlite3_stmt *s, int col,
                             enum run_setting setting, struct run_info *r)
{
    const unsigned char *column = sqlite3_column_text(s, col);
    const char *text = column ? (const char *)column : "";
    struct facet_error ignored;
    int rc = 0;
    switch (setting) {
    case RUN_SETTING_UNITS:
        rc = mesh_units_parse(text, "", &r->units, &ignored);
        break;
    case RUN_SETTING_METHOD:
        rc = optimize_method_parse(text, "", &r->method, &ignored);
        break;
    case RUN_SETTING_PER_PANEL:
        rc = panel_mode_parse(text, "", &r->per_panel, &ignored);
        break;
    case RUN_SETTING_UV_METHOD:
        rc = param_method_parse(text[0] ? text : "auto", &r->uv_method);
        break;
    case RUN_SETTING_UV:
        rc = param_method_parse(text[0] ? text : "auto", &r->uv);
        break;
    case RUN_SETTING_STORE_PANELS:
        rc = study_keep_panels_parse(text, "", &r->store_panels, &ignored);
        break;
    case RUN_SETTINGS:
        assert(0);
    }
    if (rc != 0)
        snprintf(r->unknown[setting], sizeof r->unknown[setting], "%s",
                 text[0] ? text : "(empty)");
}

int store_run_setting_check(const struct run_info *run,
                            enum run_setting setting,
                            struct facet_error *err)
{
    assert((unsigned)setting < RUN_SETTINGS);
    if (run->unknown[setting][0] == '\0')
        return FACET_OK;
    /* The file's own text: a newline or an escape in it would break the
     * one-line message (error.h) or reach the terminal. */
    char shown[sizeof run->unknown[setting]];
    text_for_terminal(run->unknown[setting], shown, sizeof shown);
    return facet_error_set(err, FACET_EINPUT,
        "run %lld: runs.%s holds '%s', which this Facet does not know "
        "(written by a newer Facet?)", (long long)run->id,
        setting_column[setting], shown);
}

const char *store_run_setting_text(const struct run_info *run,
                                   enum run_setting setting)
{
    assert((unsigned)setting < RUN_SETTINGS);
    if (run->unknown[setting][0] != '\0')
        return run->unknown[setting];
    switch (setting) {
    case RUN_SETTING_UNITS: return mesh_units_name(run->units);
    case RUN_SETTING_METHOD: return optimize_method_name(run->method);
    case RUN_SETTING_PER_PANEL: return panel_mode_name(run->per_panel);
    case RUN_SETTING_UV_METHOD: return uv_text(run->uv_method);
    case RUN_SETTING_UV: return uv_text(run->uv);
    case RUN_SETTING_STORE_PANELS:
        return study_keep_panels_name(run->store_panels);
    case RUN_SETTINGS: break;
    }
    assert(0);
    return "";
}

/* The columns of RUN_COST_COLUMNS from result column c on. */
static void run_costs_from_row(sqlite3_stmt *s, int c, struct run_info *r)
{
    r->panel_cost = sqlite3_column_double(s, c++);
    r->joint_cost = sqlite3_column_double(s, c++);
    r->mould_cost[TYPE_FP] = 0;
    r->mould_cost[TYPE_SP] = sqlite3_column_double(s, c++);
    r->mould_cost[TYPE_DP] = sqlite3_column_double(s, c++);
    r->mould_tol_mm = store_column_or_nan(s, c++);
    r->mould_mirror = sqlite3_column_int(s, c++);
    r->sp_fit = sqlite3_column_int(s, c++);
    r->max_gap_mm = store_column_or_nan(s, c++);
    r->max_kink_deg = store_column_or_nan(s, c++);
    const unsigned char *measured = sqlite3_column_text(s, c++);
    r->measured = measured == NULL
                      ? OPTION_MEASURE_ALL
                      : option_measures_parse((const char *)measured);
    r->min_panel_width = store_column_or_nan(s, c++);
    r->planarize_closeness_mm = store_column_or_nan(s, c++);
    r->weld_mm = store_column_or_nan(s, c++);
    store_shard_from_row(s, c, r);
    store_module_from_row(s, c + 3, r);
}

/* Writes r's RUN_COST_COLUMNS to its row. */
static int run_costs_write(struct store *store, const struct run_info *r,
                           struct facet_error *err)
{
    sqlite3_stmt *s;
    int rc = store_prepare(store,
        "UPDATE runs SET price_panel = ?2, price_joint = ?3,"
        " price_sp_mould = ?4, price_dp_mould = ?5, mould_tol_mm = ?6,"
        " mould_mirror = ?7, sp_fit = ?8, max_gap_mm = ?9,"
        " max_kink_deg = ?10, measured = ?11, min_panel_width = ?12,"
        " planarize_closeness_mm = ?13, weld_mm = ?14 WHERE id = ?1", &s,
        "creating a run", err);
    if (rc != FACET_OK)
        return rc;
    sqlite3_bind_int64(s, 1, r->id);
    sqlite3_bind_double(s, 2, r->panel_cost);
    sqlite3_bind_double(s, 3, r->joint_cost);
    sqlite3_bind_double(s, 4, r->mould_cost[TYPE_SP]);
    sqlite3_bind_double(s, 5, r->mould_cost[TYPE_DP]);
    store_bind_or_null(s, 6, r->mould_tol_mm);
    sqlite3_bind_int(s, 7, r->mould_mirror);
    sqlite3_bind_int(s, 8, r->sp_fit);
    store_bind_or_null(s, 9, r->max_gap_mm);
    store_bind_or_null(s, 10, r->max_kink_deg);
    char measured[OPTION_MEASURES_TEXT];
    option_measures_format(r->measured, measured, sizeof measured);
    sqlite3_bind_text(s, 11, measured, -1, SQLITE_TRANSIENT);
    store_bind_or_null(s, 12, r->min_panel_width);
    /* A run made with no budget (a zeroed run_info) made none: NULL. */
    store_bind_or_null(s, 13, r->planarize_closeness_mm > 0
                                  ? r->planarize_closeness_mm : NAN);
    /* A single surface's run (a zeroed run_info) found no seams: NULL. */
    store_bind_or_null(s, 14, r->weld_mm > 0 ? r->weld_mm : NAN);
    if (sqlite3_step(s) != SQLITE_DONE)
        rc = store_fail(store, "creating a run", err);
    sqlite3_finalize(s);
    return rc;
}

static void run_from_row(const struct store *store, sqlite3_stmt *s,
                         struct run_info *r)
{
    memset(r, 0, sizeof *r);
    int c = 0;
    r->id = sqlite3_column_int64(s, c++);
    copy_text(r->name, sizeof r->name, s, c++);
    const unsigned char *status = sqlite3_column_text(s, c++);
    /* runs.status CHECKs the names; a file that holds another (written
     * by hand) reads as failed: resumable, never taken for done. */
    if (status == NULL ||
        run_status_parse((const char *)status, &r->status) != 0)
        r->status = RUN_FAILED;
    copy_text(r->started, sizeof r->started, s, c++);
    copy_text(r->finished, sizeof r->finished, s, c++);
    r->elapsed = sqlite3_column_double(s, c++);
    copy_text(r->surface_path, sizeof r->surface_path, s, c++);
    copy_text(r->surface_sha256, sizeof r->surface_sha256, s, c++);
    setting_from_row(s, c++, RUN_SETTING_UNITS, r);
    copy_text(r->object, sizeof r->object, s, c++);
    copy_text(r->group, sizeof r->group, s, c++);
    setting_from_row(s, c++, RUN_SETTING_METHOD, r);
    r->seed = (uint64_t)sqlite3_column_int64(s, c++);
    r->u_min = sqlite3_column_int(s, c++);
    r->u_max = sqlite3_column_int(s, c++);
    r->v_min = sqlite3_column_int(s, c++);
    r->v_max = sqlite3_column_int(s, c++);
    r->threshold_min_mm = sqlite3_column_double(s, c++);
    r->threshold_max_mm = sqlite3_column_double(s, c++);
    r->threshold_step_mm = sqlite3_column_double(s, c++);
    for (int t = 0; t < TYPE_COUNT; t++)
        r->price[t] = sqlite3_column_double(s, c++);
    r->sp_as_fp = sqlite3_column_int(s, c++);
    r->max_panel_area = sqlite3_column_double(s, c++);
    r->curvature_tol = sqlite3_column_double(s, c++);
    setting_from_row(s, c++, RUN_SETTING_PER_PANEL, r);
    r->flip_normals = sqlite3_column_int(s, c++);
    copy_text(r->objectives, sizeof r->objectives, s, c++);
    r->population = sqlite3_column_int(s, c++);
    r->generations = sqlite3_column_int(s, c++);
    r->evaluations = sqlite3_column_int64(s, c++);
    r->jobs = sqlite3_column_int(s, c++);
    copy_text(r->version, sizeof r->version, s, c++);
    r->options = sqlite3_column_int64(s, c++);
    r->writer_pid = sqlite3_column_int64(s, c++);
    copy_text(r->writer_host, sizeof r->writer_host, s, c++);
    r->hypervolume = store_column_or_nan(s, c++);
    r->knee = sqlite3_column_int64(s, c++);
    r->pareto_options = sqlite3_column_int64(s, c++);
    r->best_cost = store_column_or_nan(s, c++);
    r->surface_area = sqlite3_column_double(s, c++);
    r->triangles = sqlite3_column_int64(s, c++);
    setting_from_row(s, c++, RUN_SETTING_UV_METHOD, r);
    setting_from_row(s, c++, RUN_SETTING_UV, r);
    copy_text(r->warnings, sizeof r->warnings, s, c++);
    setting_from_row(s, c++, RUN_SETTING_STORE_PANELS, r);
    /* A writer marks such runs when it opens the file; a reader cannot
     * write, so it reads them as what they are. */
    if (store->read_only && r->status == RUN_RUNNING &&
        store_run_writer_gone(r->writer_pid, r->writer_host))
        r->status = RUN_INTERRUPTED;
    run_costs_from_row(s, c, r);
}

static void bind_text_or_null(sqlite3_stmt *s, int col, const char *text)
{
    if (text[0] == '\0')
        sqlite3_bind_null(s, col);
    else
        sqlite3_bind_text(s, col, text, -1, SQLITE_TRANSIENT);
}

int store_run_create(struct store *store, struct run_info *r,
                     struct facet_error *err)
{
    sqlite3_stmt *s;
    int rc = store_prepare(store,
        "INSERT INTO runs (name, status, started, surface_path,"
        " surface_sha256, units, object, group_name, method, seed, u_min,"
        " u_max, v_min, v_max, threshold_min_mm, threshold_max_mm,"
        " threshold_step_mm, price_fp, price_sp, price_dp, sp_as_fp,"
        " max_panel_area_limit, curvature_tol, per_panel, flip_normals,"
        " objectives, population, generations, evaluations, jobs, version,"
        " writer_pid, writer_host, surface_area, triangles, uv_method, uv,"
        " warnings, store_panels)"
        " VALUES (?1, 'running', ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10, ?11,"
        " ?12, ?13, ?14, ?15, ?16, ?17, ?18, ?19, ?20, ?21, ?22, ?23, ?24,"
        " ?25, ?26, ?27, ?28, ?29, ?30, ?31, ?32, ?33, ?34, ?35, ?36, ?37,"
        " ?38)",
        &s, "creating a run", err);
    if (rc != FACET_OK)
        return rc;
    store_now(r->started);
    r->status = RUN_RUNNING;
    r->finished[0] = '\0';
    r->writer_pid = (int64_t)getpid();
    memset(r->writer_host, 0, sizeof r->writer_host);
    gethostname(r->writer_host, sizeof r->writer_host - 1);
    sqlite3_bind_text(s, 1, r->name, -1, SQLITE_TRANSIENT);
    sqlite3_bind_text(s, 2, r->started, -1, SQLITE_TRANSIENT);
    sqlite3_bind_text(s, 3, r->surface_path, -1, SQLITE_TRANSIENT);
    sqlite3_bind_text(s, 4, r->surface_sha256, -1, SQLITE_TRANSIENT);
    sqlite3_bind_text(s, 5, mesh_units_name(r->units), -1, SQLITE_STATIC);
    bind_text_or_null(s, 6, r->object);
    bind_text_or_null(s, 7, r->group);
    sqlite3_bind_text(s, 8, optimize_method_name(r->method), -1,
                      SQLITE_STATIC);
    sqlite3_bind_int64(s, 9, (sqlite3_int64)r->seed);
    sqlite3_bind_int(s, 10, r->u_min);
    sqlite3_bind_int(s, 11, r->u_max);
    sqlite3_bind_int(s, 12, r->v_min);
    sqlite3_bind_int(s, 13, r->v_max);
    sqlite3_bind_double(s, 14, r->threshold_min_mm);
    sqlite3_bind_double(s, 15, r->threshold_max_mm);
    sqlite3_bind_double(s, 16, r->threshold_step_mm);
    for (int t = 0; t < TYPE_COUNT; t++)
        sqlite3_bind_double(s, 17 + t, r->price[t]);
    sqlite3_bind_int(s, 20, r->sp_as_fp);
    sqlite3_bind_double(s, 21, r->max_panel_area);
    if (r->curvature_tol > 0)
        sqlite3_bind_double(s, 22, r->curvature_tol);
    sqlite3_bind_text(s, 23, panel_mode_name(r->per_panel), -1,
                      SQLITE_STATIC);
    sqlite3_bind_int(s, 24, r->flip_normals);
    sqlite3_bind_text(s, 25, r->objectives, -1, SQLITE_TRANSIENT);
    if (r->population > 0)
        sqlite3_bind_int(s, 26, r->population);
    if (r->generations > 0)
        sqlite3_bind_int(s, 27, r->generations);
    if (r->evaluations > 0)
        sqlite3_bind_int64(s, 28, r->evaluations);
    sqlite3_bind_int(s, 29, r->jobs);
    sqlite3_bind_text(s, 30, FACET_VERSION, -1, SQLITE_STATIC);
    sqlite3_bind_int64(s, 31, r->writer_pid);
    sqlite3_bind_text(s, 32, r->writer_host, -1, SQLITE_TRANSIENT);
    sqlite3_bind_double(s, 33, r->surface_area);
    sqlite3_bind_int64(s, 34, r->triangles);
    sqlite3_bind_text(s, 35, uv_text(r->uv_method), -1, SQLITE_STATIC);
    bind_text_or_null(s, 36, uv_text(r->uv));
    sqlite3_bind_text(s, 37, r->warnings, -1, SQLITE_TRANSIENT);
    sqlite3_bind_text(s, 38, study_keep_panels_name(r->store_panels), -1,
                      SQLITE_STATIC);
    if (sqlite3_step(s) != SQLITE_DONE)
        rc = store_fail(store, "creating a run", err);
    else
        r->id = sqlite3_last_insert_rowid(store->db);
    snprintf(r->version, sizeof r->version, "%s", FACET_VERSION);
    r->options = 0;
    r->elapsed = 0;
    r->hypervolume = NAN;
    r->best_cost = NAN;
    sqlite3_finalize(s);
    if (rc == FACET_OK)
        rc = run_costs_write(store, r, err);
    if (rc == FACET_OK)
        rc = store_run_set_shard(store, r, err);
    if (rc == FACET_OK)
        rc = store_run_set_module(store, r, err);
    return rc;
}

int store_run_get(struct store *store, int64_t id, struct run_info *run,
                  struct facet_error *err)
{
    sqlite3_stmt *s;
    int rc = store_prepare(store, "SELECT " RUN_COLUMNS ", " RUN_COST_COLUMNS
                           " FROM runs WHERE id = ?1", &s, "reading a run",
                           err);
    if (rc != FACET_OK)
        return rc;
    sqlite3_bind_int64(s, 1, id);
    int step = sqlite3_step(s);
    if (step == SQLITE_ROW)
        run_from_row(store, s, run);
    else if (step == SQLITE_DONE)
        rc = facet_error_set(err, FACET_EINPUT, "%s: no run %lld "
                             "('facet runs %s' lists them)", store->path,
                             (long long)id, store->path);
    else
        rc = store_fail(store, "reading a run", err);
    sqlite3_finalize(s);
    return rc;
}

int store_run_list(struct store *store, struct run_info **runs,
                   size_t *count, struct facet_error *err)
{
    *runs = NULL;
    *count = 0;
    sqlite3_stmt *s;
    int rc = store_prepare(store, "SELECT " RUN_COLUMNS ", " RUN_COST_COLUMNS
                           " FROM runs ORDER BY id", &s, "listing runs", err);
    if (rc != FACET_OK)
        return rc;
    size_t capacity = 0;
    int step;
    while ((step = sqlite3_step(s)) == SQLITE_ROW) {
        if (*count == capacity) {
            capacity = capacity ? 2 * capacity : 16;
            struct run_info *grown = realloc(*runs, capacity * sizeof **runs);
            if (grown == NULL) {
                rc = facet_error_set(err, FACET_EWORK, "out of memory");
                break;
            }
            *runs = grown;
        }
        run_from_row(store, s, &(*runs)[(*count)++]);
    }
    if (rc == FACET_OK && step != SQLITE_DONE)
        rc = store_fail(store, "listing runs", err);
    sqlite3_finalize(s);
    if (rc != FACET_OK) {
        free(*runs);
        *runs = NULL;
        *count = 0;
    }
    return rc;
}

int store_run_claim(struct store *store, int64_t id, struct run_info *run,
                    struct facet_error *err)
{
    /* Read and taken in one write transaction: a second process that
     * resumes the same run waits on the lock, then sees it running. */
    int rc = store_exec(store, "BEGIN IMMEDIATE", "claiming a run", err);
    if (rc != FACET_OK)
        return rc;
    rc = store_run_get(store, id, run, err);
    if (rc == FACET_OK && run->status == RUN_DONE)
        rc = facet_error_set(err, FACET_EINPUT,
            "run %lld is done: nothing to resume", (long long)id);
    if (rc == FACET_OK && run->status == RUN_RUNNING &&
        !store_run_writer_gone(run->writer_pid, run->writer_host))
        rc = facet_error_set(err, FACET_EINPUT,
            "run %lld is being written by process %lld on %s: stop it "
            "first", (long long)id, (long long)run->writer_pid,
            run->writer_host);
    if (rc == FACET_OK)
        rc = store_run_set_status(store, id, RUN_RUNNING, run->elapsed, err);
    if (rc == FACET_OK)
        rc = store_exec(store, "COMMIT", "claiming a run", err);
    if (rc != FACET_OK)
        sqlite3_exec(store->db, "ROLLBACK", NULL, NULL, NULL);
    return rc;
}

int store_run_live_writer(struct store *store, int64_t except,
                          struct run_info *run, int *live,
                          struct facet_error *err)
{
    *live = 0;
    struct run_info *runs;
    size_t n;
    int rc = store_run_list(store, &runs, &n, err);
    if (rc != FACET_OK)
        return rc;
    for (size_t k = 0; k < n && !*live; k++)
        if (runs[k].id != except && runs[k].status == RUN_RUNNING &&
            !store_run_writer_gone(runs[k].writer_pid, runs[k].writer_host)) {
            *run = runs[k];
            *live = 1;
        }
    free(runs);
    return FACET_OK;
}

int store_run_set_surface(struct store *store, int64_t id, const char *path,
                          struct facet_error *err)
{
    sqlite3_stmt *s;
    int rc = store_prepare(store,
        "UPDATE runs SET surface_path = ?2 WHERE id = ?1", &s,
        "re-pointing a run", err);
    if (rc != FACET_OK)
        return rc;
    sqlite3_bind_int64(s, 1, id);
    sqlite3_bind_text(s, 2, path, -1, SQLITE_TRANSIENT);
    if (sqlite3_step(s) != SQLITE_DONE)
        rc = store_fail(store, "re-pointing a run", err);
    else if (sqlite3_changes(store->db) == 0)
        rc = facet_error_set(err, FACET_EINPUT, "%s: no run %lld",
                             store->path, (long long)id);
    sqlite3_finalize(s);
    return rc;
}

int store_run_set_status(struct store *store, int64_t id,
                         enum run_status status, double elapsed,
                         struct facet_error *err)
{
    sqlite3_stmt *s;
    int running = status == RUN_RUNNING;
    int rc = store_prepare(store,
        "UPDATE runs SET status = ?2, elapsed = ?3,"
        " finished = CASE WHEN ?2 = 'running' THEN NULL ELSE ?4 END,"
        " writer_pid = CASE WHEN ?2 = 'running' THEN ?5 ELSE writer_pid END,"
        " writer_host = CASE WHEN ?2 = 'running' THEN ?6"
        "  ELSE writer_host END,"
        " options = (SELECT count(*) FROM options WHERE run = ?1)"
        " WHERE id = ?1", &s, "updating a run", err);
    if (rc != FACET_OK)
        return rc;
    char now[32], host[64] = "";
    store_now(now);
    gethostname(host, sizeof host - 1);
    sqlite3_bind_int64(s, 1, id);
    sqlite3_bind_text(s, 2, run_status_name(status), -1, SQLITE_STATIC);
    sqlite3_bind_double(s, 3, elapsed);
    sqlite3_bind_text(s, 4, now, -1, SQLITE_TRANSIENT);
    sqlite3_bind_int64(s, 5, running ? (int64_t)getpid() : 0);
    sqlite3_bind_text(s, 6, host, -1, SQLITE_TRANSIENT);
    if (sqlite3_step(s) != SQLITE_DONE)
        rc = store_fail(store, "updating a run", err);
    else if (sqlite3_changes(store->db) == 0)
        rc = facet_error_set(err, FACET_EINPUT, "%s: no run %lld",
                             store->path, (long long)id);
    sqlite3_finalize(s);
    return rc;
}

int store_run_delete(struct store *store, int64_t id,
                     struct facet_error *err)
{
    sqlite3_stmt *s;
    int rc = store_prepare(store, "DELETE FROM runs WHERE id = ?1", &s,
                           "deleting a run", err);
    if (rc != FACET_OK)
        return rc;
    sqlite3_bind_int64(s, 1, id);
    if (sqlite3_step(s) != SQLITE_DONE)
        rc = store_fail(store, "deleting a run", err);
    else if (sqlite3_changes(store->db) == 0)
        rc = facet_error_set(err, FACET_EINPUT, "%s: no run %lld",
                             store->path, (long long)id);
    sqlite3_finalize(s);
    return rc;
}

const char *store_run_weld_text(const struct run_info *run, char *text,
                                size_t size)
{
    if (isfinite(run->weld_mm))
        snprintf(text, size, "%g", run->weld_mm);
    else
        snprintf(text, size, "-");
    return text;
}
