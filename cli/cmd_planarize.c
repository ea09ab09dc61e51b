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
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "classify_flags.h"
#include "command.h"
#include "progress.h"
#include "shown.h"
#include "core/base/numparse.h"
#include "core/base/numrange.h"
#include "core/base/units.h"
#include "core/out/json.h"
#include "core/out/outfile.h"
#include "core/out/planar_obj.h"
#include "core/planar/planar_option.h"
#include "core/planar/planarize.h"
#include "core/surface/surface.h"

/* The largest budget taken (mm): 10 m off a facade is no budget. */
#define CLOSENESS_MAX_MM 10000.0

struct planarize_args {
    const char *grid, *closeness, *planarity, *obj;
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
             "unless the budget is large.\n",
    .run = planarize_run,
};
