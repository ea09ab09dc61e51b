/*
 * screen_runs.c: the Runs screen: every run of the database with its
 * surface, method, status, options, Pareto options, best cost, start and
 * elapsed time; open one, delete one (after y/n), search, start a new one.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "app.h"
#include "format.h"
#include "input.h"
#include "job.h"
#include "keys.h"
#include "layout.h"

struct runs_screen {
    struct tui_screen base;
    struct run_info *runs;
    size_t n;
    size_t selected;
    size_t top;
    int64_t confirm_delete;       /* id awaiting y/n, or 0 */
    int searching;
    struct tui_input search;
    char last_search[TUI_INPUT_MAX];
    struct timespec last_load;
    int64_t runs_finished;        /* app->runs_finished when last seen */
    int rows;                     /* rows shown at the last draw */
};

static const struct tui_key_help runs_help[] = {
    {"j/k, Up/Down", "select a run"},
    {"g/G, Home/End", "first / last run"},
    {"PgUp/PgDn", "a page up / down"},
    {"Enter", "open the run's options table"},
    {"d, F8", "delete the run (asks y/n)"},
    {"R, F6", "resume a stopped (interrupted or failed) run, with a gauge"},
    {"a, F7", "a new run (New run form)"},
    {"/, F3", "search names and surfaces"},
    {"n / N", "next / previous match"},
    {"r", "reload the list (it reloads every second by itself)"},
    {NULL, NULL},
};

/* Reads the list again; returns whether a run came, went or changed. */
static int load(struct runs_screen *s, struct tui_app *app)
{
    struct run_info *runs;
    size_t n;
    struct facet_error err;
    clock_gettime(CLOCK_MONOTONIC, &s->last_load);
    if (store_run_list(app->store, &runs, &n, &err) != FACET_OK) {
        tui_error(app, "%s", err.message);
        return 1;
    }
    int changed = n != s->n;
    for (size_t k = 0; k < n && !changed; k++)
        changed = runs[k].id != s->runs[k].id ||
                  runs[k].options != s->runs[k].options ||
                  runs[k].status != s->runs[k].status ||
                  runs[k].elapsed != s->runs[k].elapsed;
    int64_t keep = s->n > 0 ? s->runs[s->selected].id : 0;
    free(s->runs);
    s->runs = runs;
    s->n = n;
    s->selected = n > 0 ? n - 1 : 0;  /* the newest by default */
    for (size_t k = 0; k < n; k++)
        if (runs[k].id == keep)
            s->selected = k;
    return changed;
}

static const char *base_name(const char *path)
{
    const char *slash = strrchr(path, '/');
    return slash ? slash + 1 : path;
}

static void runs_draw(struct tui_screen *base, struct tui_app *app,
                      int height, int width)
{
    struct runs_screen *s = (struct runs_screen *)base;
    tui_fill(0, 0, width, tui_attr(ROLE_TITLE));
    tui_putf(0, 0, width, tui_attr(ROLE_TITLE),
             " Facet runs  %s  (%zu run%s)", app->db_path, s->n,
             s->n == 1 ? "" : "s");
    int wide = width >= 100;
    /* the weld only where the names keep the room they have at 100 */
    int wider = width >= 120;
    char header[256];
    snprintf(header, sizeof header, "%4s %-11s %-10s %8s %6s %11s %9s %s%s",
             "id", "status", "method", "options", "pareto", "best cost",
             "elapsed", wider ? "weld mm started           "
                        : wide ? "started           " : "",
             "name / surface");
    tui_fill(1, 0, width, tui_attr(ROLE_HEADER));
    tui_put(1, 0, width, tui_attr(ROLE_HEADER), header);
    int rows = height - 2;
    s->rows = rows;
    if (s->n == 0) {
        tui_put(3, 2, width - 2, A_NORMAL,
                "No runs yet. Press a (or F7) for a new run, or start "
                "one with facet optimize from the shell.");
        return;
    }
    s->top = (size_t)table_model_scroll((int64_t)s->top,
                                        (int64_t)s->selected, rows,
                                        (int64_t)s->n);
    for (int r = 0; r < rows && s->top + (size_t)r < s->n; r++) {
        size_t k = s->top + (size_t)r;
        const struct run_info *run = &s->runs[k];
        char cost[32] = "-", elapsed[32], started[32], line[1400];
        char status[32], weld_mm[32], weld[48] = "";
        /* a building's welding tolerance, as facet runs shows it */
        if (wider)
            snprintf(weld, sizeof weld, "%7s ",
                     store_run_weld_text(run, weld_mm, sizeof weld_mm));
        if (isfinite(run->best_cost))
            tui_fmt_number(cost, sizeof cost, run->best_cost, 0, 1);
        tui_fmt_elapsed(elapsed, sizeof elapsed, run->elapsed);
        tui_fmt_started(started, sizeof started, run->started);
        int n = snprintf(line, sizeof line,
                         "%4lld %-11s %-10s %8lld %6lld %11s %9s %s%s%s",
                         (long long)run->id,
                         store_run_status_text(run, status, sizeof status),
                         store_run_setting_text(run, RUN_SETTING_METHOD),
                         (long long)run->options,
                         (long long)run->pareto_options, cost, elapsed,
                         weld, wide ? started : "", wide ? "  " : "");
        /* the name, and the surface when it fits too (the name is the
         * one the user gave) */
        const struct tui_field names[] = {
            {"", run->name, 0},
            {run->name[0] ? " / " : "", base_name(run->surface_path), 1},
        };
        if (n > 0 && (size_t)n < sizeof line)
            tui_fit_fields(line + n, sizeof line - (size_t)n, width - n,
                           names, 2);
        attr_t attr = k == s->selected ? tui_attr(ROLE_SELECTION)
                      : run->status == RUN_RUNNING
                          ? tui_attr(ROLE_PARETO)
                          : A_NORMAL;
        if (k == s->selected)
            tui_fill(2 + r, 0, width, attr);
        tui_put(2 + r, 0, width, attr, line);
    }
    if (s->confirm_delete)
        tui_error(app, "Delete run %lld with its options and panels? (y/n)",
                  (long long)s->confirm_delete);
}

/* Moves to the next run (dir 1) or previous (-1) whose name or surface
 * holds the search text. */
static void search_step(struct runs_screen *s, struct tui_app *app, int dir)
{
    if (s->last_search[0] == '\0' || s->n == 0)
        return;
    char status[32];
    for (size_t step = 1; step <= s->n; step++) {
        size_t k = (s->selected + s->n + (size_t)dir * step) % s->n;
        if (strstr(s->runs[k].name, s->last_search) ||
            strstr(s->runs[k].surface_path, s->last_search) ||
            strstr(store_run_setting_text(&s->runs[k], RUN_SETTING_METHOD),
                   s->last_search) ||
            strstr(store_run_status_text(&s->runs[k], status, sizeof status),
                   s->last_search)) {
            s->selected = k;
            return;
        }
    }
    tui_error(app, "no run matches '%s'", s->last_search);
}

/* Goes on with the selected run in the background (job.h); the status
 * line shows the gauge and the list follows it. */
static void resume(struct runs_screen *s, struct tui_app *app)
{
    if (s->n == 0)
        return;
    const struct run_info *run = &s->runs[s->selected];
    if (app->job != NULL) {
        tui_error(app, "a run is already working; Ctrl-X stops it");
        return;
    }
    if (run->status != RUN_INTERRUPTED && run->status != RUN_FAILED) {
        tui_error(app, "run %lld is %s; only an interrupted or failed run "
                  "resumes", (long long)run->id, run_status_name(run->status));
        return;
    }
    struct facet_error err;
    if (tui_job_resume(app->db_path, run->id, &app->job, &err) != FACET_OK) {
        tui_error(app, "resume: %s", err.message);
        return;
    }
    /* the status line stays clear, so the gauge shows there */
}

static enum tui_result runs_key(struct tui_screen *base, struct tui_app *app,
                                int key)
{
    struct runs_screen *s = (struct runs_screen *)base;
    if (s->searching) {
        if (tui_prompt_key(app, &s->search, &s->searching, key) ==
            INPUT_DONE) {
            snprintf(s->last_search, sizeof s->last_search, "%s",
                     s->search.text);
            if (s->n > 0)
                s->selected = (s->selected + s->n - 1) % s->n;
            search_step(s, app, 1);
        }
        return RESULT_HANDLED;
    }
    if (s->confirm_delete) {
        int64_t id = s->confirm_delete;
        s->confirm_delete = 0;
        app->status[0] = '\0';
        if (key != 'y' && key != 'Y') {
            tui_status(app, "run %lld kept", (long long)id);
            return RESULT_HANDLED;
        }
        struct facet_error err;
        if (store_run_delete(app->store, id, &err) != FACET_OK)
            tui_error(app, "%s", err.message);
        else
            tui_status(app, "run %lld deleted", (long long)id);
        load(s, app);
        return RESULT_HANDLED;
    }
    switch (key) {
    case 'R': case KEY_F(6):
        resume(s, app);
        return RESULT_HANDLED;
    case 'd': case KEY_F(8):
        if (s->n == 0)
            return RESULT_HANDLED;
        if (s->runs[s->selected].status == RUN_RUNNING) {
            tui_error(app, "run %lld is running; stop it first",
                      (long long)s->runs[s->selected].id);
            return RESULT_HANDLED;
        }
        s->confirm_delete = s->runs[s->selected].id;
        return RESULT_HANDLED;
    case 'a': case KEY_F(7):
        tui_push(app, screen_newrun_new(app, NULL));
        return RESULT_HANDLED;
    case KEY_MOUSE:
        /* a click selects a run, twice opens it; the wheel is the
         * frame's */
        if (app->mouse.kind != MOUSE_CLICK)
            return RESULT_UNHANDLED;
        if (app->mouse.y >= 2 && app->mouse.y < 2 + s->rows &&
            s->top + (size_t)(app->mouse.y - 2) < s->n) {
            s->selected = s->top + (size_t)(app->mouse.y - 2);
            if (app->mouse.clicks == 2)
                tui_push(app, screen_options_new(app,
                                                 s->runs[s->selected].id));
        }
        return RESULT_HANDLED;
    case 'r':
        load(s, app);
        return RESULT_HANDLED;
    case KEY_F(3):
        key = '/';
        break;
    default:
        break;
    }
    switch (tui_key_action(key)) {
    case ACTION_UP:
        if (s->selected > 0)
            s->selected--;
        return RESULT_HANDLED;
    case ACTION_DOWN:
        if (s->selected + 1 < s->n)
            s->selected++;
        return RESULT_HANDLED;
    case ACTION_PAGE_UP:
        s->selected = s->selected > 10 ? s->selected - 10 : 0;
        return RESULT_HANDLED;
    case ACTION_PAGE_DOWN:
        s->selected = s->n == 0 ? 0 : s->selected + 10 < s->n
                                          ? s->selected + 10 : s->n - 1;
        return RESULT_HANDLED;
    case ACTION_TOP:
        s->selected = 0;
        return RESULT_HANDLED;
    case ACTION_BOTTOM:
        s->selected = s->n ? s->n - 1 : 0;
        return RESULT_HANDLED;
    case ACTION_SEARCH:
        s->searching = 1;
        tui_input_set(&s->search, "");
        tui_prompt(app, "Search:", &s->search);
        return RESULT_HANDLED;
    case ACTION_NEXT:
        search_step(s, app, 1);
        return RESULT_HANDLED;
    case ACTION_PREVIOUS:
        search_step(s, app, -1);
        return RESULT_HANDLED;
    case ACTION_OPEN:
        if (s->n > 0)
            tui_push(app, screen_options_new(app, s->runs[s->selected].id));
        return RESULT_HANDLED;
    default:
        return RESULT_UNHANDLED;
    }
}

/* Reloads every second (a handful of rows), so runs that another screen
 * or process started, resumed or finished show; redraws when the list
 * changed. */
static int runs_tick(struct tui_screen *base, struct tui_app *app)
{
    struct runs_screen *s = (struct runs_screen *)base;
    if (s->runs_finished == app->runs_finished &&
        tui_seconds_since(&s->last_load) < 1.0)
        return 0;
    s->runs_finished = app->runs_finished;
    return load(s, app);
}

static void runs_destroy(struct tui_screen *base)
{
    struct runs_screen *s = (struct runs_screen *)base;
    free(s->runs);
    free(s);
}

static const struct tui_screen_class runs_class = {
    "Runs", runs_help,
    {"Help", NULL, "Search", NULL, NULL, "Resume", "New", "Delete", NULL,
     "Quit"},
    runs_draw, runs_key, runs_tick, runs_destroy,
};

struct tui_screen *screen_runs_new(struct tui_app *app)
{
    struct runs_screen *s = calloc(1, sizeof *s);
    if (s == NULL) {
        tui_error(app, "out of memory");
        return NULL;
    }
    s->base.cls = &runs_class;
    load(s, app);
    return &s->base;
}
