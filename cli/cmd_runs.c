/*
 * cmd_runs.c: `facet runs DB`, one line per run of a result store.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "command.h"
#include "core/out/json.h"
#include "core/base/numformat.h"
#include "core/base/text.h"
#include "text_table.h"
#include "store/store.h"
#include "study/study.h"

static void print_json(const struct run_info *runs,
                       const struct front_bounds *bounds, size_t n)
{
    static const char *const bound_name[FRONT_BOUNDS][2] = {
        {"nu", "min"}, {"nu", "max"}, {"nv", "min"}, {"nv", "max"},
        {"threshold_mm", "min"}, {"threshold_mm", "max"}};
    struct json_writer w;
    json_init(&w, stdout);
    json_begin_array(&w);
    for (size_t k = 0; k < n; k++) {
        const struct run_info *r = &runs[k];
        json_begin_object(&w);
        json_key(&w, "id"); json_integer(&w, r->id);
        json_key(&w, "name"); json_string(&w, r->name);
        json_key(&w, "status"); json_string(&w, run_status_name(r->status));
        /* A shard: index and count; a merge: count and how many merged. */
        if (r->shard_count > 0) {
            json_key(&w, "shard"); json_integer(&w, r->shard_index);
            json_key(&w, "shards"); json_integer(&w, r->shard_count);
            json_key(&w, "incomplete");
            json_bool(&w, store_run_incomplete(r));
        }
        json_key(&w, "surface"); json_string(&w, r->surface_path);
        json_key(&w, "surface_sha256"); json_string(&w, r->surface_sha256);
        json_key(&w, "units");
        json_string(&w, store_run_setting_text(r, RUN_SETTING_UNITS));
        json_key(&w, "method");
        json_string(&w, store_run_setting_text(r, RUN_SETTING_METHOD));
        json_key(&w, "seed"); json_integer(&w, (long long)r->seed);
        json_key(&w, "u");
        json_begin_array(&w);
        json_integer(&w, r->u_min);
        json_integer(&w, r->u_max);
        json_end_array(&w);
        json_key(&w, "v");
        json_begin_array(&w);
        json_integer(&w, r->v_min);
        json_integer(&w, r->v_max);
        json_end_array(&w);
        json_key(&w, "threshold_mm");
        json_begin_array(&w);
        json_number(&w, r->threshold_min_mm);
        json_number(&w, r->threshold_max_mm);
        json_number(&w, r->threshold_step_mm);
        json_end_array(&w);
        json_key(&w, "objectives"); json_string(&w, r->objectives);
        json_key(&w, "sp_fit"); json_bool(&w, r->sp_fit);
        /* null without a limit (json_number writes NaN as null) */
        json_key(&w, "max_gap_mm"); json_number(&w, r->max_gap_mm);
        json_key(&w, "max_kink_deg"); json_number(&w, r->max_kink_deg);
        json_key(&w, "min_panel_width"); json_number(&w, r->min_panel_width);
        /* a building's welding tolerance; null for a single surface */
        json_key(&w, "weld_mm"); json_number(&w, r->weld_mm);
        json_key(&w, "options"); json_integer(&w, r->options);
        json_key(&w, "pareto_options"); json_integer(&w, r->pareto_options);
        json_key(&w, "knee");
        if (r->knee > 0)
            json_integer(&w, r->knee);
        else
            json_null(&w);
        json_key(&w, "hypervolume");
        if (isfinite(r->hypervolume))
            json_number(&w, r->hypervolume);
        else
            json_null(&w);
        json_key(&w, "best_cost");
        if (isfinite(r->best_cost))
            json_number(&w, r->best_cost);
        else
            json_null(&w);
        json_key(&w, "started"); json_string(&w, r->started);
        json_key(&w, "finished");
        if (r->finished[0])
            json_string(&w, r->finished);
        else
            json_null(&w);
        json_key(&w, "elapsed"); json_number(&w, r->elapsed);
        json_key(&w, "version"); json_string(&w, r->version);
        /* What the run warned of when it began, one string each. */
        json_key(&w, "warnings");
        json_begin_array(&w);
        for (const char *line = r->warnings; *line != '\0';) {
            const char *end = strchr(line, '\n');
            size_t len = end ? (size_t)(end - line) : strlen(line);
            char one[sizeof r->warnings];
            snprintf(one, sizeof one, "%.*s", (int)len, line);
            json_string(&w, one);
            line += len + (end != NULL);
        }
        json_end_array(&w);
        /* The bounds of the design space Pareto options sit on (an
         * artefact of the range, not an optimum): [{variable, bound,
         * value, pareto}]. */
        json_key(&w, "front_at_bounds");
        json_begin_array(&w);
        double value[FRONT_BOUNDS] = {r->u_min, r->u_max, r->v_min, r->v_max,
                                      r->threshold_min_mm,
                                      r->threshold_max_mm};
        for (int b = 0; b < FRONT_BOUNDS; b++) {
            if (bounds[k].at[b] == 0 || !(value[b | 1] > value[b & ~1]))
                continue;
            json_begin_object(&w);
            json_key(&w, "variable"); json_string(&w, bound_name[b][0]);
            json_key(&w, "bound"); json_string(&w, bound_name[b][1]);
            json_key(&w, "value"); json_number(&w, value[b]);
            json_key(&w, "pareto"); json_integer(&w, bounds[k].at[b]);
            json_end_object(&w);
        }
        json_end_array(&w);
        json_end_object(&w);
    }
    json_end_array(&w);
    json_finish(&w);
}

/* How run types SP panels, the joint limits its options are held to and
 * a building's welding tolerance, in one line. */
static void run_built_note(const struct run_info *r, char *line,
                           size_t size)
{
    char gap[48] = "no gap limit", kink[48] = "no kink limit";
    char width[56] = "no width limit", weld[64];
    if (isfinite(r->weld_mm))
        snprintf(weld, sizeof weld, "--weld %g mm", r->weld_mm);
    else
        snprintf(weld, sizeof weld, "%s",
                 store_run_is_project(r) ? "no seams (an older Facet's run)"
                                         : "no weld: not a building");
    if (isfinite(r->min_panel_width))
        snprintf(width, sizeof width, "--min-panel-width %g m",
                 r->min_panel_width);
    if (isfinite(r->max_gap_mm))
        snprintf(gap, sizeof gap, "--max-gap %g mm", r->max_gap_mm);
    if (isfinite(r->max_kink_deg))
        snprintf(kink, sizeof kink, "--max-kink %g deg", r->max_kink_deg);
    snprintf(line, size, "run %lld: --sp-fit %s (%s), %s, %s, %s, %s",
             (long long)r->id, r->sp_fit ? "yes" : "no",
             r->sp_fit ? "SP misfits built DP" : "SP by class alone", gap,
             kink, width, weld);
}

static void print_human(const struct run_info *runs,
                        const struct front_bounds *bounds, size_t n,
                        int wide)
{
    static const struct text_column columns[] = {
        {"run", "", 4, 0, 0, 0},
        {"status", "", 11, 1, 0, 0},
        {"method", "", 10, 1, 3, 0},
        {"options", "", 8, 0, 5, 0},
        {"pareto", "", 6, 0, 4, 0},
        {"best cost", "USD", 14, 0, 6, 0},
        {"HV", "", 8, 0, 2, 0},
        {"elapsed", "s", 9, 0, 2, 0},
        {"weld", "mm", 6, 0, 2, 0},
        {"started", "UTC", 20, 1, 1, 0},
        {"name / surface", "", 14, 1, 0, 1},
    };
    struct text_table t = {columns, 11, {0}, 0, 0};
    text_table_fit(&t, text_table_width(stdout, wide));
    text_table_head(stdout, &t);
    for (size_t k = 0; k < n; k++) {
        const struct run_info *r = &runs[k];
        char id[24], options[24], pareto[24], elapsed[32];
        char cost[64] = "-", hv[32] = "-", label[1200], weld[32];
        store_run_weld_text(r, weld, sizeof weld);
        snprintf(id, sizeof id, "%lld", (long long)r->id);
        snprintf(options, sizeof options, "%lld", (long long)r->options);
        snprintf(pareto, sizeof pareto, "%lld", (long long)r->pareto_options);
        snprintf(elapsed, sizeof elapsed, "%.2f", r->elapsed);
        if (isfinite(r->best_cost))
            number_grouped(cost, sizeof cost, r->best_cost, 0);
        if (isfinite(r->hypervolume))
            snprintf(hv, sizeof hv, "%.4f", r->hypervolume);
        /* Names and paths came from users and files: shown, not obeyed
         * (no escape sequence reaches the terminal). */
        char name[sizeof r->name], path[sizeof r->surface_path];
        text_for_terminal(r->name, name, sizeof name);
        text_for_terminal(r->surface_path, path, sizeof path);
        snprintf(label, sizeof label, "%s%s%s", name, name[0] ? " / " : "",
                 path);
        char status[32];
        store_run_status_text(r, status, sizeof status);
        const char *cell[] = {id, status,
                              store_run_setting_text(r, RUN_SETTING_METHOD),
                              options, pareto,
                              cost, hv, elapsed, weld, r->started, label};
        text_table_row(stdout, &t, cell);
    }
    if (n == 0)
        printf("(no runs yet: facet optimize SURFACE.obj --db FILE)\n");
    text_table_foot(stdout, &t);
    for (size_t k = 0; k < n; k++) {
        char note[1024];
        char line[1500];
        for (const char *at = runs[k].warnings; *at != '\0';) {
            const char *end = strchr(at, '\n');
            size_t len = end ? (size_t)(end - at) : strlen(at);
            snprintf(line, sizeof line, "run %lld: warning: %.*s",
                     (long long)runs[k].id, (int)len, at);
            text_wrap(stdout, line, text_table_width(stdout, wide));
            at += len + (end != NULL);
        }
        run_built_note(&runs[k], line, sizeof line);
        text_wrap(stdout, line, text_table_width(stdout, wide));
        if (study_front_edge_note(&runs[k], &bounds[k], note, sizeof note)) {
            snprintf(line, sizeof line, "run %lld: %s", (long long)runs[k].id,
                     note);
            text_wrap(stdout, line, text_table_width(stdout, wide));
        }
    }
}

/* The options as given, 0 when absent. */
struct runs_args {
    int json, wide;
};

static const struct arg_option runs_options[] = {
    {"wide", 0, ARG_FLAG, offsetof(struct runs_args, wide), NULL,
     "every column, whatever the terminal's width", NULL},
    {"json", 0, ARG_FLAG, offsetof(struct runs_args, json), NULL,
     "one JSON array of runs", NULL},
    {NULL, 0, ARG_FLAG, 0, NULL, NULL, NULL},
};

static int runs_main(int argc, char **argv, struct facet_error *err)
{
    struct runs_args a = {0, 0};
    const struct arg_table own = {runs_options, &a};
    const char *path;
    int rc = args_parse_one(argc, argv, &own, NULL, &path,
            "runs: name the result database (facet runs runs.db)", err);
    if (rc != FACET_OK)
        return rc;
    int json = a.json, wide = a.wide;
    struct store *store;
    if ((rc = store_open_read(path, &store, err)) != FACET_OK)
        return rc;
    struct run_info *runs = NULL;
    size_t n = 0;
    rc = store_run_list(store, &runs, &n, err);
    struct front_bounds *bounds = NULL;
    if (rc == FACET_OK && (bounds = calloc(n ? n : 1, sizeof *bounds)) == NULL)
        rc = facet_error_set(err, FACET_EWORK, "out of memory");
    for (size_t k = 0; rc == FACET_OK && k < n; k++)
        rc = store_front_bounds(store, runs[k].id, &bounds[k], err);
    if (rc == FACET_OK) {
        if (json)
            print_json(runs, bounds, n);
        else
            print_human(runs, bounds, n, wide);
    }
    free(bounds);
    free(runs);
    store_close(store);
    return rc;
}

const struct command cmd_runs = {
    .name = "runs",
    .usage = "DB [--wide] [--json]",
    .summary = "List the runs of a result store, one line each.",
    .before = "",
    .options = runs_options,
    .after = "examples:\n"
               "  facet runs runs.db\n"
               "  facet runs runs.db --json |\n"
               "      python3 -c 'import json,sys; "
               "print(json.load(sys.stdin)[-1][\"status\"])'\n",
    .run = runs_main,
};
