/*
 * cmd_planarize.c: `facet planarize SURFACE.obj --grid NUxNV --closeness
 * MM`, the corners of a UV panel grid moved off the design surface, within
 * a closeness budget, until every quad is planar (core/planar/planarize.h);
 * what it reached, and whether that is feasible, said plainly.
 *
 * The grid's corners are the ones facet classify places (the panels of
 * panels_build_fast, quad_grid.h). Exit status: 0 whether the grid is
 * feasible or not (the output says which, "feasible": false in JSON);
 * 2 for bad input, 1 for a failure while working.
 *
 * With --db FILE the option is stored like any option: a new run in FILE
 * (made when missing) of the one grid, its classified option and its
 * planarized one beside it (study_start with the run's planarize budget,
 * study_planar.c: the very code of facet optimize --planarize), ranked,
 * with its panels; facet show, export and tui then see it. What it says
 * is read back from the store.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "args.h"
#include "classify_flags.h"
#include "command.h"
#include "progress.h"
#include "shown.h"
#include "signals.h"
#include "core/base/numparse.h"
#include "core/base/numrange.h"
#include "core/base/units.h"
#include "core/obj/infile.h"
#include "core/out/json.h"
#include "core/out/outfile.h"
#include "core/out/planar_obj.h"
#include "core/planar/planar_option.h"
#include "core/planar/planarize.h"
#include "core/surface/surface.h"
#include "store/store.h"
#include "study/study.h"

/* The largest budget taken (mm): 10 m off a facade is no budget. */
#define CLOSENESS_MAX_MM 10000.0

struct planarize_args {
    const char *grid, *closeness, *planarity, *obj, *db;
    int json, force;
};

static void default_closeness(char *out, size_t size)
{
    snprintf(out, size, "%g", PLANARIZE_CLOSENESS_DEFAULT * 1000);
}

static void default_planarity(char *out, size_t size)
{
    snprintf(out, size, "%g", PLANARIZE_PLANARITY_DEFAULT);
}

static const struct arg_option planarize_command_options[] = {
    {"grid", 0, ARG_STRING, offsetof(struct planarize_args, grid), "NUxNV",
     "panels along u and v (e.g. 37x49); their corners are moved", NULL},
    {"closeness", 0, ARG_STRING, offsetof(struct planarize_args, closeness),
     "MM", "the budget: how far a corner may end from the surface",
     default_closeness},
    {"planarity", 0, ARG_STRING, offsetof(struct planarize_args, planarity),
     "TOL", "the tolerance: a quad's distance between its diagonals over "
     "its longer diagonal (0.001 is 0.1 %)", default_planarity},
    {"obj", 0, ARG_STRING, offsetof(struct planarize_args, obj), "FILE",
     "write the planarized quads as OBJ", NULL},
    {"db", 0, ARG_STRING, offsetof(struct planarize_args, db), "FILE",
     "store the option as a new run in FILE (made when missing), beside "
     "the grid's classified option, for facet show, export and tui", NULL},
    {"force", 0, ARG_FLAG, offsetof(struct planarize_args, force), NULL,
     "replace the OBJ file when it exists", NULL},
    {"json", 0, ARG_FLAG, offsetof(struct planarize_args, json), NULL,
     "one JSON object (see docs/manual.md)", NULL},
    {NULL, 0, ARG_FLAG, 0, NULL, NULL, NULL},
};

/* Each iteration on the progress bar. */
static void show_iteration(void *context, int iteration, int most)
{
    progress_update(context, iteration, most, iteration, most);
}

static void print_human(const struct surface *s,
                        const struct planarize_options *o,
                        const struct planarize_result *r,
                        const struct option_totals *t)
{
    shown_line(stdout, "%-16s %s (%s, %.3f m^2, %zu triangles, UV from %s)",
               "surface", s->path, mesh_units_name(s->units), s->mesh.area,
               s->mesh.ntriangles, param_method_name(s->param.method));
    printf("%-16s %d x %d: %zu quads, %zu corners\n", "grid", r->grid.nu,
           r->grid.nv, r->nquads, r->ncorners);
    printf("%-16s budget %g mm; reached %.3f mm at most, %.3f mm on "
           "average%s\n", "closeness", o->closeness * 1000,
           r->max_distance * 1000, r->mean_distance * 1000,
           r->max_distance <= o->closeness ? "" : ": OVER the budget");
    printf("%-16s tolerance %g of the diagonal; reached %.3g (%.3f mm), "
           "from %.3g at the start\n", "planarity", o->planarity,
           r->max_relative, r->max_planarity * 1000, r->start_max_relative);
    printf("%-16s %zu of %zu over the tolerance\n", "quads not planar",
           r->over, r->nquads);
    printf("%-16s %.3f mm at most\n", "corners moved", r->max_moved * 1000);
    printf("%-16s %d (%s)\n", "iterations", r->iterations,
           r->converged ? "converged" : "stopped at the limit");
    printf("%-16s %.0f USD at the paper's prices: %zu FP, %zu DP panels; "
           "gaps up to %.3f mm, kinks up to %.3f deg\n", "as an option",
           t->cost, t->count[TYPE_FP], t->count[TYPE_DP], units_mm(t->max_gap),
           units_deg(t->max_kink));
    if (r->feasible)
        printf("%-16s feasible: every quad planar within %g of its diagonal, "
               "every corner within %g mm of the surface\n", "result",
               o->planarity, o->closeness * 1000);
    else if (r->over == 0)
        printf("%-16s INFEASIBLE under the %g mm budget: planar only with "
               "corners up to %.3f mm off the surface\n", "result",
               o->closeness * 1000, r->max_distance * 1000);
    else
        printf("%-16s INFEASIBLE under the %g mm budget: %zu quads still "
               "over the tolerance, corners up to %.3f mm off the "
               "surface\n", "result", o->closeness * 1000, r->over,
               r->max_distance * 1000);
}

static void print_json(const struct surface *s,
                       const struct planarize_options *o,
                       const struct planarize_result *r,
                       const struct option_totals *t)
{
    struct json_writer w;
    json_init(&w, stdout);
    json_begin_object(&w);
    json_key(&w, "surface");
    json_string(&w, s->path);
    json_key(&w, "nu");
    json_integer(&w, r->grid.nu);
    json_key(&w, "nv");
    json_integer(&w, r->grid.nv);
    json_key(&w, "quads");
    json_integer(&w, (long long)r->nquads);
    json_key(&w, "corners");
    json_integer(&w, (long long)r->ncorners);
    json_key(&w, "closeness_budget_mm");
    json_number(&w, o->closeness * 1000);
    json_key(&w, "closeness_max_mm");
    json_number(&w, r->max_distance * 1000);
    json_key(&w, "closeness_mean_mm");
    json_number(&w, r->mean_distance * 1000);
    json_key(&w, "moved_max_mm");
    json_number(&w, r->max_moved * 1000);
    json_key(&w, "planarity_measure");
    json_string(&w, "distance between the diagonals over the longer "
                    "diagonal");
    json_key(&w, "planarity_tolerance");
    json_number(&w, o->planarity);
    json_key(&w, "planarity_max");
    json_number(&w, r->max_relative);
    json_key(&w, "planarity_max_mm");
    json_number(&w, r->max_planarity * 1000);
    json_key(&w, "planarity_start_max");
    json_number(&w, r->start_max_relative);
    json_key(&w, "quads_over");
    json_integer(&w, (long long)r->over);
    json_key(&w, "iterations");
    json_integer(&w, r->iterations);
    json_key(&w, "converged");
    json_bool(&w, r->converged);
    json_key(&w, "feasible");
    json_bool(&w, r->feasible);
    /* The option it makes, priced and joined as any option (at the
     * paper's prices and classification: planar_option.h). */
    json_key(&w, "quads_missed");
    json_integer(&w, (long long)t->planar_over);
    json_key(&w, "cost_usd");
    json_number(&w, t->cost);
    json_key(&w, "fp_count");
    json_integer(&w, (long long)t->count[TYPE_FP]);
    json_key(&w, "dp_count");
    json_integer(&w, (long long)t->count[TYPE_DP]);
    json_key(&w, "max_gap_mm");
    json_number(&w, units_mm(t->max_gap));
    json_key(&w, "max_kink_deg");
    json_number(&w, units_deg(t->max_kink));
    json_end_object(&w);
    json_finish(&w);
}

static int write_obj(const char *path, int force, const struct surface *s,
                     const struct planarize_options *o,
                     const struct planarize_result *r,
                     struct facet_error *err)
{
    struct outfile f;
    int rc = outfile_open(&f, path, force, err);
    if (rc != FACET_OK)
        return rc;
    rc = planar_obj_write(f.out, s->path, o, r, err);
    if (rc != FACET_OK) {
        outfile_abort(&f);
        return rc;
    }
    return outfile_commit(&f, err);
}

/* The run's planarized and classified options, as stored. */
static void print_stored_human(const char *db, int64_t run,
                               const struct planarize_options *o,
                               const struct option_row *p,
                               const struct option_row *c)
{
    const struct option_totals *t = &p->totals;
    shown_line(stdout, "%-16s run %lld of %s: option %lld planarized, "
               "option %lld the grid classified", "stored", (long long)run,
               db, (long long)p->number, (long long)c->number);
    printf("%-16s %d x %d: %zu panels\n", "grid", p->nu, p->nv, t->panels);
    printf("%-16s budget %g mm; reached %.3f mm at most, %.3f mm on "
           "average%s\n", "closeness", o->closeness * 1000,
           t->closeness_reached * 1000, t->closeness_mean * 1000,
           t->closeness_reached <= o->closeness ? "" : ": OVER the budget");
    printf("%-16s tolerance %g of the diagonal; reached %.3g\n",
           "planarity", o->planarity, t->planarity_reached);
    printf("%-16s %lld of %zu over the tolerance or beyond the budget\n",
           "quads missed", (long long)t->planar_over, t->panels);
    printf("%-16s %.0f USD: %zu FP, %zu DP panels (classified: %.0f USD, "
           "%zu FP, %zu SP, %zu DP)\n", "as an option", t->cost,
           t->count[TYPE_FP], t->count[TYPE_DP], c->totals.cost,
           c->totals.count[TYPE_FP], c->totals.count[TYPE_SP],
           c->totals.count[TYPE_DP]);
    if (t->planar_over == 0)
        printf("%-16s feasible: every quad planar within %g of its diagonal, "
               "every corner within %g mm of the surface\n", "result",
               o->planarity, o->closeness * 1000);
    else
        printf("%-16s INFEASIBLE under the %g mm budget: %lld quads not "
               "planar or beyond it, corners up to %.3f mm off the "
               "surface\n", "result", o->closeness * 1000,
               (long long)t->planar_over, t->closeness_reached * 1000);
}

static void print_stored_json(const char *db, int64_t run,
                              const struct planarize_options *o,
                              const struct option_row *p,
                              const struct option_row *c)
{
    const struct option_totals *t = &p->totals;
    struct json_writer w;
    json_init(&w, stdout);
    json_begin_object(&w);
    json_key(&w, "db");
    json_string(&w, db);
    json_key(&w, "run");
    json_integer(&w, run);
    json_key(&w, "option");
    json_integer(&w, p->number);
    json_key(&w, "classified_option");
    json_integer(&w, c->number);
    json_key(&w, "nu");
    json_integer(&w, p->nu);
    json_key(&w, "nv");
    json_integer(&w, p->nv);
    json_key(&w, "closeness_budget_mm");
    json_number(&w, o->closeness * 1000);
    json_key(&w, "closeness_max_mm");
    json_number(&w, t->closeness_reached * 1000);
    json_key(&w, "closeness_mean_mm");
    json_number(&w, t->closeness_mean * 1000);
    json_key(&w, "planarity_tolerance");
    json_number(&w, o->planarity);
    json_key(&w, "planarity_max");
    json_number(&w, t->planarity_reached);
    json_key(&w, "quads_missed");
    json_integer(&w, t->planar_over);
    json_key(&w, "feasible");
    json_bool(&w, t->planar_over == 0);
    json_key(&w, "cost_usd");
    json_number(&w, t->cost);
    json_key(&w, "classified_cost_usd");
    json_number(&w, c->totals.cost);
    json_end_object(&w);
    json_finish(&w);
}

/* --db: the grid's run recorded in a->db by study_start, its planarized
 * option beside its classified one, then said from the store. */
static int planarize_store(const struct planarize_args *a, const char *path,
                           const struct mesh_options *mesh, int units_named,
                           int nu, int nv, const struct planarize_options *o,
                           struct facet_error *err)
{
    if (a->obj != NULL)
        return facet_error_set(err, FACET_EINPUT,
            "planarize: --obj and --db: write the stored option's quads "
            "with facet export %s --run RUN --option N --obj FILE", a->db);
    if (o->planarity != PLANARIZE_PLANARITY_DEFAULT)
        return facet_error_set(err, FACET_EINPUT,
            "planarize: --planarity and --db: a stored run planarizes to "
            "the default tolerance (%g); give no --planarity",
            PLANARIZE_PLANARITY_DEFAULT);
    if (!(o->closeness > 0))
        return facet_error_set(err, FACET_EINPUT,
            "planarize: --closeness 0 and --db: a stored run planarizes "
            "within a budget above 0 mm, e.g. --closeness 5");
    struct study_request request;
    study_request_defaults(&request);
    request.surface_path = path;
    request.mesh = *mesh;
    request.units_named = units_named;
    struct design_space *space = &request.settings.space;
    space->u_min = space->u_max = nu;
    space->v_min = space->v_max = nv;
    request.settings.method = study_auto_method(space);
    request.planarize_closeness = o->closeness;
    int rc = study_request_check(&request, err);
    /* A surface that cannot be read is refused before the database is
     * created or touched. */
    int fd;
    struct stat st;
    if (rc == FACET_OK && (rc = infile_open(path, &fd, &st, err)) == FACET_OK)
        close(fd);
    if (rc != FACET_OK)
        return rc;
    signals_catch_stop();
    struct store *store;
    if ((rc = store_open(a->db, &store, err)) != FACET_OK)
        return rc;
    struct study_hooks hooks = {NULL, progress_show_stage, NULL,
                                signals_stop_hook, NULL,
                                progress_show_warning, progress_show_note};
    enum optimize_outcome outcome;
    int64_t run = 0;
    rc = study_start(store, &request, &hooks, &run, &outcome, err);
    if (rc == FACET_ESTOP) {
        store_close(store);
        fprintf(stderr, "facet: interrupted while reading and preparing the "
                "surface; no run was recorded\n");
        return signals_stop_status();
    }
    if (rc == FACET_OK && outcome == OPTIMIZE_INTERRUPTED) {
        store_close(store);
        fprintf(stderr, "facet: run %lld interrupted before its planarized "
                "option was stored\n", (long long)run);
        return signals_stop_status();
    }
    struct option_row *rows = NULL;
    size_t n = 0;
    if (rc == FACET_OK)
        rc = store_options_get(store, run, &rows, &n, err);
    const struct option_row *planar = NULL, *classified = NULL;
    for (size_t k = 0; rc == FACET_OK && k < n; k++) {
        if (rows[k].totals.planarized && planar == NULL)
            planar = &rows[k];
        else if (!rows[k].totals.planarized && classified == NULL)
            classified = &rows[k];
    }
    if (rc == FACET_OK && (planar == NULL || classified == NULL))
        rc = facet_error_set(err, FACET_EWORK,
            "run %lld of %s holds no planarized option beside its "
            "classified one", (long long)run, a->db);
    if (rc == FACET_OK) {
        if (a->json)
            print_stored_json(a->db, run, o, planar, classified);
        else
            print_stored_human(a->db, run, o, planar, classified);
    }
    free(rows);
    store_close(store);
    return rc;
}

static int planarize_run(int argc, char **argv, struct facet_error *err)
{
    struct planarize_args a;
    memset(&a, 0, sizeof a);
    struct surface_flags flags;
    memset(&flags, 0, sizeof flags);
    const struct arg_table own = {planarize_command_options, &a};
    const struct arg_table shared = {surface_flags_options, &flags};
    const char *path;
    int rc = args_parse_one(argc, argv, &own, &shared, &path,
            "planarize: name one OBJ file (facet planarize FILE.obj --grid "
            "20x30 --closeness 5)", err);
    if (rc != FACET_OK)
        return rc;
    struct mesh_options mesh_options;
    if ((rc = surface_flags_apply(&flags, &mesh_options, err)))
        return rc;
    if (a.grid == NULL)
        return facet_error_set(err, FACET_EINPUT,
            "planarize: give the grid, e.g. --grid 20x30");
    int nu, nv;
    if ((rc = numrange_grid(a.grid, PANEL_MAX_GRID, "--grid", &nu, &nv, err)))
        return rc;
    struct planarize_options o;
    planarize_options_defaults(&o);
    if (a.closeness != NULL) {
        double mm;
        if ((rc = numparse_number(a.closeness, 0, CLOSENESS_MAX_MM,
                                  "--closeness", &mm, err)))
            return rc;
        o.closeness = mm / 1000;
    }
    if (a.planarity != NULL) {
        if ((rc = numparse_number(a.planarity, 0, 1, "--planarity",
                                  &o.planarity, err)))
            return rc;
        if (o.planarity == 0)
            return facet_error_set(err, FACET_EINPUT,
                "--planarity: 0 cannot be reached; give a tolerance above "
                "0, e.g. 0.001 (0.1 %% of the diagonal)");
    }
    if (a.db != NULL)
        return planarize_store(&a, path, &mesh_options, flags.units != NULL,
                               nu, nv, &o, err);
    if (a.obj != NULL && (rc = outfile_check(a.obj, a.force, err)))
        return rc;

    struct surface surface;
    struct panelization panels;
    struct option_totals totals;
    struct nearest_index index;
    struct planarize_result result;
    memset(&panels, 0, sizeof panels);
    memset(&index, 0, sizeof index);
    memset(&result, 0, sizeof result);
    rc = surface_open(path, &mesh_options, &surface, err);
    if (rc == FACET_OK && flags.units == NULL)
        rc = surface_units_check(&surface, err);
    if (rc == FACET_OK)
        rc = surface_prepare(&surface, 0, PARAM_AUTO, err);
    if (rc == FACET_OK)
        rc = nearest_index_build(&surface.mesh, &index, err);
    if (rc == FACET_OK) {
        struct progress bar;
        progress_start(&bar, "iterations", 0, 0);
        o.progress = show_iteration;
        o.progress_context = &bar;
        struct option_params base, params;
        option_params_defaults(&base);
        params = option_params_at(&base, nu, nv,
                                  units_mm(base.classify.threshold));
        rc = planar_option_evaluate(&surface, &index, &params, &o, &panels,
                                    &totals, &result, err);
        if (rc == FACET_OK)
            progress_finish(&bar, result.iterations, result.iterations);
        else if (bar.terminal)
            fputc('\n', stderr);
    }
    if (rc == FACET_OK && a.obj != NULL)
        rc = write_obj(a.obj, a.force, &surface, &o, &result, err);
    if (rc == FACET_OK) {
        for (int i = 0; i < surface.nwarnings; i++)
            shown_line(stderr, "facet: warning: %s", surface.warnings[i]);
        if (a.json)
            print_json(&surface, &o, &result, &totals);
        else
            print_human(&surface, &o, &result, &totals);
    }
    planarize_result_free(&result);
    panelization_free(&panels);
    nearest_index_free(&index);
    surface_close(&surface);
    return rc;
}

const struct command cmd_planarize = {
    .name = "planarize",
    .usage = "SURFACE.obj --grid NUxNV [--closeness MM]\n"
             "       [--planarity TOL] [--obj FILE] [--force] [--json]\n"
             "       [--db FILE]\n"
             "       [--units U] [--object NAME] [--group NAME]",
    .summary = "Move a UV grid's panel corners off the surface, within a "
               "closeness budget, until every quad is planar; say when it "
               "cannot.",
    .before = "",
    .options = planarize_command_options,
    .shared = surface_flags_options,
    .after = "\nThe exit status is 0 whether or not the grid is feasible: "
             "the output says\nwhich (\"result\", and \"feasible\" in "
             "JSON). A grid along a hypar's rulings, or\nany grid that does "
             "not follow a conjugate net of the surface, is infeasible\n"
             "unless the budget is large.\n"
             "\nWith --db FILE the option is stored as a new run in FILE, "
             "the grid's\nclassified option beside it, so that facet show, "
             "export and tui see it as\nany option (facet optimize "
             "--planarize does the same for a front's grids).\n",
    .run = planarize_run,
};
