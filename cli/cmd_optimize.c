/*
 * cmd_optimize.c: `facet optimize SURFACE.obj --db FILE`, the paper's MOGD:
 * search grid sizes and flatness thresholds for the Pareto-optimal
 * trade-offs, every option committed to SQLite as it is evaluated, and the
 * paper's Table 2 for the run at the end. The work is study/study.h's; this
 * file parses the design space and reports.
 */
#include <errno.h>
#include <limits.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "args.h"
#include "classify_flags.h"
#include "command.h"
#include "progress.h"
#include "run_table.h"
#include "signals.h"
#include "core/base/numformat.h"
#include "core/base/numparse.h"
#include "core/base/numrange.h"
#include "core/base/units.h"
#include "core/obj/infile.h"
#include "core/project/module.h"
#include "core/project/seam.h"
#include "study/study.h"
#include "study/study_estimate.h"

/* The largest --planarize budget (mm), as facet planarize's --closeness:
 * 10 m off a facade is no budget. */
#define PLANARIZE_MAX_MM 10000.0

/* Rows of the table a run ends with, unless --table says. */
#define TABLE_ROWS 20

/* --- what the user sees while it runs --- */

#define OPTIMIZE_NOTES 4

struct optimize_view {
    struct progress bar;
    int bar_started;
    int64_t first_done;
    /* The study's notes (a prepared building reused or rebuilt), told
     * once the run is done: a run that fails says its one error line. */
    int nnotes;
    char notes[OPTIMIZE_NOTES][1024];
};

static void keep_note(void *context, const char *text)
{
    struct optimize_view *view = context;
    if (view->nnotes < OPTIMIZE_NOTES)
        snprintf(view->notes[view->nnotes++], sizeof view->notes[0], "%s",
                 text);
}

static void show_progress(void *context, const struct optimize_progress *p)
{
    struct optimize_view *view = context;
    if (!view->bar_started) {
        progress_start(&view->bar, "options", p->done, p->work_done);
        view->bar_started = 1;
    }
    if (p->done >= p->total)
        progress_finish(&view->bar, p->done, p->total);
    else
        progress_update(&view->bar, p->done, p->total, p->work_done,
                        p->work_total);
}

static void show_started(void *context, int64_t run)
{
    (void)context;
    if (isatty(STDERR_FILENO))
        fprintf(stderr, "facet: run %lld\n", (long long)run);
}

/* A run estimated to take longer than this is announced before it starts,
 * with how long and how to stop and go on. */
#define LONG_RUN_SECONDS 3600.0

/* Says on stderr how long request's run will take at the rate of the
 * earlier runs in store (study_estimate.h), when that is hours; nothing
 * when it is shorter or there is no earlier run to time it by. */
static void announce_long_run(struct store *store, const char *db,
                              const struct study_request *request)
{
    struct study_rate rate;
    struct facet_error err;
    if (study_rate_measure(store, request->surface_path, &rate, &err) !=
        FACET_OK)
        return;
    int64_t options;
    double seconds;
    study_estimate(&rate, &request->settings, request->nfiles > 0, &options,
                   &seconds);
    if (seconds < LONG_RUN_SECONDS)
        return;
    char count[32], time[32];
    number_grouped(count, sizeof count, (double)options, 0);
    if (seconds < 48 * 3600.0)
        snprintf(time, sizeof time, "%.1f h", seconds / 3600);
    else
        snprintf(time, sizeof time, "%.1f days", seconds / 86400);
    fprintf(stderr, "facet: %s options (%s%s), about %s at the rate of the "
            "%d earlier run%s in %s; Ctrl-C stops it, every option "
            "evaluated is kept, and --resume goes on\n", count,
            optimize_method_name(request->settings.method),
            request->settings.method == METHOD_NSGA2 ? ", at most" : "",
            time, rate.runs, rate.runs == 1 ? "" : "s", db);
}

/* The search flags as given (pointing into argv), NULL when absent. */
struct search_flags {
    const char *u, *v, *threshold, *method, *evals, *pop, *gens, *seed;
    const char *objectives, *jobs, *shard;
    const char *module, *grid;
};

/* The flags' names in the messages of the design space's checks. */
static const struct design_space_names flag_names = {"--u", "--v",
                                                      "--threshold"};

/* Sets the design space, method and the rest of *s that the flags give
 * over the defaults already in *s (study_request_defaults). */
static int parse_search(const struct search_flags *f,
                        struct optimize_settings *s, struct facet_error *err)
{
    int rc;
    long number;
    if (f->module && (f->u || f->v))
        return facet_error_set(err, FACET_EINPUT,
            "--module sizes a project's panels: no --u or --v with it");
    if (f->u && (rc = design_space_parse_sides(f->u, "--u", &s->space.u_min,
                                      &s->space.u_max, err)))
        return rc;
    if (f->v && (rc = design_space_parse_sides(f->v, "--v", &s->space.v_min,
                                      &s->space.v_max, err)))
        return rc;
    if (f->threshold &&
        (rc = design_space_parse_threshold(f->threshold, "--threshold",
                                           &s->space, err)))
        return rc;
    if ((rc = design_space_check(&s->space, &flag_names, err)))
        return rc;
    if ((rc = study_method_parse(f->method ? f->method : "auto",
                                 "--method", &s->space, &s->method, err)))
        return rc;
    if ((rc = optimize_method_check(s->method, &s->space, &flag_names, err)))
        return rc;
    if (f->evals) {
        if ((rc = args_int(f->evals, 1, 100000000, "--evals", &number, err)))
            return rc;
        s->evaluations = number;
    }
    if (f->pop) {
        if ((rc = args_int(f->pop, 4, 100000, "--pop", &number, err)))
            return rc;
        s->population = (int)number;
    }
    if (f->gens) {
        if ((rc = args_int(f->gens, 1, 100000, "--gens", &number, err)))
            return rc;
        s->generations = (int)number;
    }
    if (f->seed) {
        /* SQLite keeps a seed as a signed 64-bit integer: up to 2^63 - 1,
         * refused beyond rather than wrapped. */
        if ((rc = args_int(f->seed, 0, LONG_MAX, "--seed", &number, err)))
            return rc;
        s->seed = (uint64_t)number;
    }
    if (f->objectives &&
        (rc = objectives_parse(f->objectives, "--objectives", s->objectives,
                               &s->nobjectives, err)))
        return rc;
    if (f->jobs) {
        if ((rc = args_int(f->jobs, 1, 64, "--jobs", &number, err)))
            return rc;
        s->jobs = (int)number;
    }
    if (f->shard &&
        (rc = shard_parse(f->shard, "--shard", &s->shard, err)))
        return rc;
    return FACET_OK;
}

/* Everything facet optimize takes from its arguments, parsed and checked
 * before any file is opened. The caller owns it and must not move it once
 * parsed: the request points into it. */
struct optimize_command {
    struct search_flags search;
    struct classify_flags flags;
    const char *db, *resume, *name, *table, *surface, *store_panels;
    const char *measure, *planarize, *weld;
    int wide;
    const char *path[PROJECT_FILES_MAX];
    int count;
    long rows, run_number;
    struct study_request request;
    struct surface_grid_overrides grids;
};

/* --- the defaults the help states, study_request_defaults's --- */

static struct optimize_settings default_settings(void)
{
    struct study_request r;
    study_request_defaults(&r);
    return r.settings;
}

static void default_u(char *out, size_t size)
{
    struct optimize_settings s = default_settings();
    snprintf(out, size, "%d:%d, the paper's", s.space.u_min, s.space.u_max);
}

static void default_v(char *out, size_t size)
{
    struct optimize_settings s = default_settings();
    snprintf(out, size, "%d:%d, the paper's", s.space.v_min, s.space.v_max);
}

static void default_threshold(char *out, size_t size)
{
    snprintf(out, size, "%g", default_settings().space.t_min_mm);
}

static void default_method(char *out, size_t size)
{
    char grouped[32];
    number_grouped(grouped, sizeof grouped, STUDY_EXHAUSTIVE_LIMIT, 0);
    snprintf(out, size, "auto: exhaustive up to %s points, nsga2 above",
             grouped);
}

static void default_evals(char *out, size_t size)
{
    snprintf(out, size, "%lld", (long long)default_settings().evaluations);
}

static void default_pop(char *out, size_t size)
{
    snprintf(out, size, "%d", default_settings().population);
}

static void default_gens(char *out, size_t size)
{
    snprintf(out, size, "%d", default_settings().generations);
}

static void default_seed(char *out, size_t size)
{
    snprintf(out, size, "%llu", (unsigned long long)default_settings().seed);
}

static void default_objectives(char *out, size_t size)
{
    struct optimize_settings s = default_settings();
    objectives_format(out, size, s.objectives, s.nobjectives);
}

static void default_store_panels(char *out, size_t size)
{
    struct study_request r;
    study_request_defaults(&r);
    snprintf(out, size, "%s", study_keep_panels_name(r.store_panels));
}

static void default_weld(char *out, size_t size)
{
    struct study_request r;
    study_request_defaults(&r);
    snprintf(out, size, "%g", units_mm(r.weld));
}

static void default_measure(char *out, size_t size)
{
    struct study_request r;
    study_request_defaults(&r);
    snprintf(out, size, "%s", r.measure_all ? "all" : "needed");
}

static void default_table(char *out, size_t size)
{
    snprintf(out, size, "%d", TABLE_ROWS);
}

static const struct arg_option optimize_options[] = {
    {"db", 0, ARG_STRING, offsetof(struct optimize_command, db), "FILE",
     "the SQLite result store (created if missing)", NULL},
    {"u", 0, ARG_STRING, offsetof(struct optimize_command, search.u), "A:B",
     "panels along u", default_u},
    {"v", 0, ARG_STRING, offsetof(struct optimize_command, search.v), "A:B",
     "panels along v", default_v},
    {"threshold", 0, ARG_STRING,
     offsetof(struct optimize_command, search.threshold), "T",
     "flatness threshold in mm: one value, a range A:B, or A:B:STEP for "
     "exhaustive", default_threshold},
    {"method", 0, ARG_STRING,
     offsetof(struct optimize_command, search.method),
     "auto|exhaustive|random|nsga2",
     "auto, exhaustive, random or nsga2", default_method},
    {"evals", 0, ARG_STRING, offsetof(struct optimize_command, search.evals),
     "N", "random: points to draw", default_evals},
    {"pop", 0, ARG_STRING, offsetof(struct optimize_command, search.pop), "N",
     "nsga2: population", default_pop},
    {"gens", 0, ARG_STRING, offsetof(struct optimize_command, search.gens),
     "N", "nsga2: generations", default_gens},
    {"seed", 0, ARG_STRING, offsetof(struct optimize_command, search.seed),
     "S", "the same seed gives the same options", default_seed},
    {"objectives", 0, ARG_STRING,
     offsetof(struct optimize_command, search.objectives), "LIST",
     "metrics to minimise, max:NAME to maximise", default_objectives},
    {"jobs", 'j', ARG_STRING, offsetof(struct optimize_command, search.jobs),
     "N", "threads (default: every core)", NULL},
    {"shard", 0, ARG_STRING, offsetof(struct optimize_command, search.shard),
     "I/N", "evaluate shard I of N only (exhaustive, random: every Nth grid "
     "or point, of a project every Nth distinct grid vector; nsga2: an "
     "island with its own seed); join them with facet merge", NULL},
    {"module", 0, ARG_STRING,
     offsetof(struct optimize_command, search.module), "W x H",
     "a project (an OBJ of many objects, or several files): panel modules "
     "WMIN:WMAX x HMIN:HMAX in m, each range optionally :STEP (default "
     "0.1); each surface takes round(length / module)", NULL},
    {"grid", 0, ARG_STRING, offsetof(struct optimize_command, search.grid),
     "NAME=NUxNV", "with --module: that surface's own grid whatever the "
     "module (comma-separated list)", NULL},
    {"weld", 0, ARG_STRING, offsetof(struct optimize_command, weld), "MM",
     "with --module: two surfaces meet along a seam where their boundaries "
     "are within MM (its joints measured with the faces': gap, and kink "
     "beyond the design's own crease)", default_weld},
    {"resume", 0, ARG_STRING, offsetof(struct optimize_command, resume),
     "RUN", "go on with an interrupted run", NULL},
    {"surface", 0, ARG_STRING, offsetof(struct optimize_command, surface),
     "FILE", "with --resume: the run's surface has moved; record its new "
     "place (same SHA-256)", NULL},
    {"name", 0, ARG_STRING, offsetof(struct optimize_command, name), "TEXT",
     "a name for the run", NULL},
    {"store-panels", 0, ARG_STRING,
     offsetof(struct optimize_command, store_panels), "front|knee|none",
     "whose panels to store at the end: front (the Pareto options', up to "
     "16 or 1 in 40 of the run's: the knee, then the most spread), knee or "
     "none; fewer when the disk cannot hold them (said); any other "
     "option's when first looked at: show, export, tui",
     default_store_panels},
    {"planarize", 0, ARG_STRING,
     offsetof(struct optimize_command, planarize), "MM",
     "also planarize the Pareto front's grids (at most 8, the knee's "
     "first): each grid's corners moved off the surface, within MM, until "
     "its quads are planar (facet planarize), stored as a planarized "
     "option beside the classified ones and ranked with them", NULL},
    {"measure", 0, ARG_STRING, offsetof(struct optimize_command, measure),
     "needed|all",
     "needed: each option is measured for what the objectives, limits and "
     "prices read, the Pareto options in full (the rest read 'not "
     "measured', NULL in SQL); all: every option in full (a shard always "
     "is)", default_measure},
    {"table", 0, ARG_STRING, offsetof(struct optimize_command, table), "N",
     "rows of the final table, 0 for all", default_table},
    {"wide", 0, ARG_FLAG, offsetof(struct optimize_command, wide), NULL,
     "every column of it, whatever the terminal", NULL},
    {NULL, 0, ARG_FLAG, 0, NULL, NULL, NULL},
};

/* Parses and checks argv into *c (cleared here); opens no file. */
static int optimize_parse(int argc, char **argv, struct optimize_command *c,
                          struct facet_error *err)
{
    memset(c, 0, sizeof *c);
    struct search_flags *search = &c->search;
    const struct arg_table own = {optimize_options, c};
    const struct arg_table shared = {classify_flags_options, &c->flags};
    int rc = args_parse_surfaces(argc, argv, &own, &shared, c->path,
                                 &c->count, err);
    if (rc != FACET_OK)
        return rc;
    if (c->db == NULL)
        return facet_error_set(err, FACET_EINPUT,
            "optimize: name the result database, e.g. --db runs.db");
    c->rows = TABLE_ROWS;
    if (c->table &&
        (rc = args_int(c->table, 0, 1000000000, "--table", &c->rows, err)))
        return rc;
    if (c->resume) {
        if ((rc = args_int(c->resume, 1, 1L << 62, "--resume",
                           &c->run_number, err)))
            return rc;
        if (c->count != 0)
            return facet_error_set(err, FACET_EINPUT,
                "optimize --resume: the run knows its surface; give no "
                "OBJ file");
    } else if (c->surface != NULL) {
        return facet_error_set(err, FACET_EINPUT,
            "optimize: --surface re-points a run for --resume; a new run "
            "takes its OBJ file as its argument");
    } else if (c->count == 0) {
        return facet_error_set(err, FACET_EINPUT,
            "optimize: name an OBJ file (facet optimize FILE.obj --db "
            "runs.db)");
    } else if (c->count > 1 && search->module == NULL) {
        return facet_error_set(err, FACET_EINPUT,
            "optimize: a project of %d files needs a panel module: give "
            "--module WMIN:WMAX x HMIN:HMAX", c->count);
    }
    if (c->resume && (search->module || search->grid))
        return facet_error_set(err, FACET_EINPUT,
            "optimize --resume: the run knows its module range; give no "
            "--module or --grid");
    if (c->resume && c->planarize)
        return facet_error_set(err, FACET_EINPUT,
            "optimize --resume: the run knows its closeness budget; give no "
            "--planarize");
    if (c->resume && c->weld)
        return facet_error_set(err, FACET_EINPUT,
            "optimize --resume: the run knows its welding tolerance; give "
            "no --weld");
    if (c->weld && !search->module)
        return facet_error_set(err, FACET_EINPUT,
            "optimize: --weld is where a project's surfaces meet; it needs "
            "--module");
    if (search->grid && !search->module)
        return facet_error_set(err, FACET_EINPUT,
            "optimize: --grid gives a project's surface its own grid; "
            "it needs --module");

    struct study_request *request = &c->request;
    study_request_defaults(request);
    if (!c->resume && search->module) {
        if ((rc = module_parse(search->module, "--module", &request->module,
                               err)) ||
            (rc = study_project_space(&request->module,
                                      &request->settings.space, err)))
            return rc;
        if (search->grid &&
            (rc = surface_grid_overrides_parse(search->grid, "--grid",
                                               &c->grids, err)))
            return rc;
        request->files = c->path;
        request->nfiles = (size_t)c->count;
        request->override_names = (const char *const *)c->grids.name;
        request->overrides = c->grids.grid;
        request->noverrides = c->grids.n;
        if (c->weld &&
            (rc = seam_weld_parse(c->weld, "--weld", &request->weld, err)))
            return rc;
    }
    if (!c->resume) {
        if ((rc = classify_flags_apply(&c->flags, &request->settings.base,
                                       &request->mesh, &request->uv, err)))
            return rc;
        if ((rc = parse_search(search, &request->settings, err)))
            return rc;
        if (c->store_panels &&
            (rc = study_keep_panels_parse(c->store_panels, "--store-panels",
                                          &request->store_panels, err)))
            return rc;
        if (c->measure && strcmp(c->measure, "all") != 0 &&
            strcmp(c->measure, "needed") != 0)
            return facet_error_set(err, FACET_EINPUT,
                "--measure: '%s' is neither all nor needed", c->measure);
        request->measure_all = c->measure && strcmp(c->measure, "all") == 0;
        if (c->planarize) {
            double mm;
            if ((rc = numparse_number(c->planarize, 0, PLANARIZE_MAX_MM,
                                      "--planarize", &mm, err)))
                return rc;
            if (mm == 0)
                return facet_error_set(err, FACET_EINPUT,
                    "--planarize: a budget of 0 mm moves no corner; give "
                    "the closeness budget in mm, e.g. --planarize 5");
            request->planarize_closeness = mm / 1000;
        }
        request->surface_path = c->path[0];
        request->units_named = c->flags.surface.units != NULL;
        request->flip_normals = c->flags.flip_normals;
        request->name = c->name ? c->name : "";
        if ((rc = study_request_check(request, err)))
            return rc;
    }
    return FACET_OK;
}

int optimize_args_check(int argc, char **argv, struct facet_error *err)
{
    struct optimize_command *c = malloc(sizeof *c);
    if (c == NULL)
        return facet_error_set(err, FACET_EWORK, "out of memory");
    int rc = optimize_parse(argc, argv, c, err);
    free(c);
    return rc;
}

static int optimize_with(struct optimize_command *c, struct facet_error *err)
{
    int rc;
    /* A surface that cannot be read is refused before the database is
     * created or touched. */
    if (!c->resume) {
        for (int k = 0; k < c->count; k++) {
            int fd;
            struct stat st;
            if ((rc = infile_open(c->path[k], &fd, &st, err)))
                return rc;
            close(fd);
        }
    }
    /* Caught before the database is opened: creating it takes a while on
     * a busy disk, and a stop sent then (to a job a script started in the
     * background, which inherits SIGINT ignored) must still be heard. */
    signals_catch_stop();
    struct store *store;
    if ((rc = store_open(c->db, &store, err)) != FACET_OK)
        return rc;
    struct optimize_view view;
    memset(&view, 0, sizeof view);
    /* Warnings come before the progress bar starts. */
    struct study_hooks hooks = {&view, progress_show_stage, show_progress,
                                signals_stop_hook, show_started,
                                progress_show_warning, keep_note};
    enum optimize_outcome outcome;
    int64_t run = c->run_number;
    if (c->resume && c->surface != NULL)
        rc = study_repoint_surface(store, run, c->surface, err);
    if (c->resume) {
        /* A run that could not be re-pointed is not started anew. */
        if (rc == FACET_OK)
            rc = study_resume(store, run, &hooks, &outcome, err);
    } else {
        announce_long_run(store, c->db, &c->request);
        rc = study_start(store, &c->request, &hooks, &run, &outcome, err);
    }
    if (view.bar_started && !view.bar.finished)
        fputc('\n', stderr);
    if (rc == FACET_ESTOP) {
        /* Stopped before the run was recorded: nothing to resume. */
        store_close(store);
        fprintf(stderr, "facet: interrupted while reading and preparing the "
                "surface; no run was recorded\n");
        return signals_stop_status();
    }
    for (int k = 0; rc == FACET_OK && k < view.nnotes; k++)
        progress_show_note(NULL, view.notes[k]);
    if (rc == FACET_OK) {
        if (outcome == OPTIMIZE_INTERRUPTED)
            fprintf(stderr, "facet: run %lld interrupted; every evaluated "
                    "option is stored. Go on with: facet optimize --db %s "
                    "--resume %lld\n", (long long)run, c->db,
                    (long long)run);
        rc = run_table_print(stdout, store, c->db, run, c->rows, c->wide,
                             err);
    }
    store_close(store);
    if (rc == FACET_OK && outcome == OPTIMIZE_INTERRUPTED)
        return signals_stop_status();
    return rc;
}

static int optimize_main(int argc, char **argv, struct facet_error *err)
{
    struct optimize_command *c = malloc(sizeof *c);
    if (c == NULL)
        return facet_error_set(err, FACET_EWORK, "out of memory");
    int rc = optimize_parse(argc, argv, c, err);
    if (rc == FACET_OK)
        rc = optimize_with(c, err);
    free(c);
    return rc;
}

const struct command cmd_optimize = {
    .name = "optimize",
    .usage = "SURFACE.obj --db FILE [--u A:B] [--v A:B]\n"
             "       [--threshold MM|A:B[:STEP]]\n"
             "       [--method auto|exhaustive|random|nsga2] [--evals N] "
             "[--pop N] [--gens N]\n"
             "       [--seed S] [--objectives LIST] [--jobs N] [--name TEXT]"
             " [--table N]\n"
             "       [--planarize MM]\n"
             "       [classification options]\n"
             "   or: facet optimize PROJECT.obj [MORE.obj ...] --db FILE\n"
             "       --module WMIN:WMAX x HMIN:HMAX [--grid NAME=NUxNV,...]\n"
             "       [--weld MM]\n"
             "       [--threshold ...] [...]\n"
             "   or: facet optimize --db FILE --resume RUN [--surface FILE]",
    .summary = "Search grid sizes and thresholds for the Pareto-optimal "
               "options; store them.",
    .before = "",
    .options = optimize_options,
    .shared = classify_flags_options,
    .after =
        "examples:\n"
        "  facet optimize roof.obj --db runs.db --sp-as-fp "
        "--max-panel-area 1.92\n"
        "  facet optimize roof.obj --db runs.db --threshold 1:10 --method "
        "nsga2 --seed 7\n"
        "  facet optimize skin.obj --db runs.db --module 1.2:2.0x1.0:1.6 \\\n"
        "      --threshold 2:6:2\n",
    .run = optimize_main,
};
