/*
 * cmd_classify.c: `facet classify SURFACE.obj --grid NUxNV`, the paper's
 * CPMGC and MOGD rules on one design option: every panel's curvature,
 * class, type, area, deviation and cost, and the option's totals.
 */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "classify_flags.h"
#include "command.h"
#include "core/base/numformat.h"
#include "option_text.h"
#include "progress.h"
#include "shown.h"
#include "core/surface/coarse_mesh.h"
#include "core/base/numparse.h"
#include "core/base/numrange.h"
#include "core/evaluate/evaluate.h"
#include "core/out/outfile.h"
#include "core/out/report.h"

static void print_human(const struct surface *s,
                        const struct option_params *params,
                        const struct panelization *p,
                        const struct option_totals *t)
{
    const struct classify_options *o = &params->classify;
    shown_line(stdout, "%-16s %s (%s, %.3f m^2, %zu triangles, UV from %s)",
               "surface", s->path, mesh_units_name(s->units), s->mesh.area,
               s->mesh.ntriangles, param_method_name(s->param.method));
    char panels[40];
    number_grouped(panels, sizeof panels, (double)t->panels, 0);
    printf("%-16s %d x %d (%s panels)\n", "grid", p->nu, p->nv, panels);
    printf("%-16s %g mm\n", "threshold", o->threshold * 1000);
    if (o->curvature_tol > 0)
        printf("%-16s %g 1/m\n", "curvature tol", o->curvature_tol);
    else
        printf("%-16s 8 t / d^2 per panel\n", "curvature tol");
    printf("%-16s FP %g, SP %g, DP %g USD/m^2%s\n", "prices",
           o->price[TYPE_FP], o->price[TYPE_SP], o->price[TYPE_DP],
           o->sp_as_fp ? " (SP priced as FP)" : "");

    option_text_totals(stdout, t, o);
    double worst;
    size_t over = classify_fp_over_threshold(p, o, &worst);
    printf("%-16s %zu of %zu FP panels deviate more than %g mm", "FP beyond t",
           over, t->count[TYPE_FP], o->threshold * 1000);
    if (over > 0)
        printf(" (up to %.3f mm)", worst * 1000);
    printf("\n");
    option_text_map(stdout, p);
}

/* Writes the CSV schedule to path and the option's totals beside it
 * (PATH less .csv, plus -totals.csv), each through FILE.partial, so that a
 * failure never leaves a half-written schedule; both are replaced when
 * they exist, as a schedule is remade. */
static int write_csv(const char *path, const struct panelization *p,
                     const struct option_totals *t, struct facet_error *err)
{
    /* A schedule piped out goes alone: no place beside a stream. */
    int beside = !outfile_is_stream(path);
    char totals[4096];
    int rc = beside ? outfile_sibling(path, ".csv", "-totals.csv", totals,
                                      sizeof totals, err)
                    : FACET_OK;
    struct outfile schedule, sums;
    memset(&sums, 0, sizeof sums);
    if (rc == FACET_OK)
        rc = outfile_open(&schedule, path, 1, err);
    if (rc == FACET_OK && beside &&
        (rc = outfile_open(&sums, totals, 1, err)) != 0)
        outfile_abort(&schedule);
    if (rc != FACET_OK)
        return rc;
    report_csv(schedule.out, p);
    if (beside)
        report_totals_csv(sums.out, t);
    rc = outfile_commit(&schedule, err);
    if (beside && rc == FACET_OK)
        rc = outfile_commit(&sums, err);
    else if (beside)
        outfile_abort(&sums);
    return rc;
}

/* The threshold the help states, option_params_defaults's. */
static void default_threshold(char *out, size_t size)
{
    struct option_params p;
    option_params_defaults(&p);
    snprintf(out, size, "%g", p.classify.threshold * 1000);
}

/* The options as given (pointing into argv), NULL or 0 when absent. */
struct classify_args {
    const char *grid, *threshold, *csv;
    int json;
};

static const struct arg_option classify_command_options[] = {
    {"grid", 0, ARG_STRING, offsetof(struct classify_args, grid), "NUxNV",
     "panels along u and v (e.g. 37x49, the paper's)", NULL},
    {"threshold", 0, ARG_STRING, offsetof(struct classify_args, threshold),
     "MM", "flatness threshold t: a panel within t of its best-fit plane "
     "is made flat", default_threshold},
    {"json", 0, ARG_FLAG, offsetof(struct classify_args, json), NULL,
     "one JSON object (see docs/manual.md)", NULL},
    {"csv", 0, ARG_STRING, offsetof(struct classify_args, csv), "FILE",
     "the panel schedule, one row per panel", NULL},
    {NULL, 0, ARG_FLAG, 0, NULL, NULL, NULL},
};

/* The steps facet classify shows: reading and preparing the surface, then
 * the option's stages (evaluate.h). */
#define CLASSIFY_STEPS (2 + EVALUATION_STAGES)

struct classify_steps {
    struct progress bar;
    int done;                /* steps started */
};

/* A step starts (also an evaluation's stage hook): drawn on a terminal. */
static void classify_step(void *context, const char *what)
{
    struct classify_steps *steps = context;
    if (steps->done < CLASSIFY_STEPS)
        steps->done++;
    progress_step(&steps->bar, steps->done - 1, CLASSIFY_STEPS, what);
}

static int classify_run(int argc, char **argv, struct facet_error *err)
{
    struct classify_args a = {NULL, NULL, NULL, 0};
    struct classify_flags flags;
    memset(&flags, 0, sizeof flags);
    const struct arg_table own = {classify_command_options, &a};
    const struct arg_table shared = {classify_flags_options, &flags};
    const char *path;
    int rc = args_parse_one(argc, argv, &own, &shared, &path,
            "classify: name one OBJ file (facet classify FILE.obj --grid "
            "37x49)", err);
    if (rc != FACET_OK)
        return rc;
    const char *grid = a.grid, *threshold = a.threshold, *csv = a.csv;
    int json = a.json;

    struct option_params params;
    struct mesh_options mesh_options;
    enum param_method uv;
    if ((rc = classify_flags_apply(&flags, &params, &mesh_options, &uv,
                                   err)))
        return rc;
    if (grid == NULL)
        return facet_error_set(err, FACET_EINPUT,
            "classify: give the grid, e.g. --grid 37x49");
    if ((rc = numrange_grid(grid, PANEL_MAX_GRID, "--grid", &params.nu,
                            &params.nv, err)))
        return rc;
    if (threshold) {
        double number;
        if ((rc = numparse_number(threshold, 0, CLASSIFY_THRESHOLD_MAX_MM,
                                  "--threshold", &number, err)))
            return rc;
        params = option_params_at(&params, params.nu, params.nv, number);
    }
    int flip = flags.flip_normals;

    struct surface surface;
    struct panelization panels;
    struct option_totals totals;
    memset(&panels, 0, sizeof panels);
    /* A fine grid works for most of a minute: its steps on a terminal. */
    struct classify_steps steps;
    steps.done = 0;
    progress_start(&steps.bar, "steps", 0, 0);
    classify_step(&steps, "reading the surface");
    rc = surface_open(path, &mesh_options, &surface, err);
    if (rc == FACET_OK && flags.surface.units == NULL)
        rc = surface_units_check(&surface, err);
    if (rc == FACET_OK) {
        classify_step(&steps, "preparing the surface");
        rc = surface_prepare(&surface, flip, uv, err);
    }
    struct evaluation_shared watched;
    memset(&watched, 0, sizeof watched);
    watched.stage = classify_step;
    watched.stage_context = &steps;
    if (rc == FACET_OK)
        rc = option_evaluate(&surface, &params, &watched, &panels, &totals,
                             err);
    if (rc == FACET_OK)
        progress_steps_end(&steps.bar, CLASSIFY_STEPS);
    else if (steps.bar.terminal)
        fputc('\n', stderr);
    if (rc == FACET_OK && csv != NULL)
        rc = write_csv(csv, &panels, &totals, err);
    char coarse[400], sag[400];
    int is_coarse = 0, is_sagging = 0;
    if (rc == FACET_OK) {
        char grid_name[64];
        snprintf(grid_name, sizeof grid_name, "%d x %d panels", params.nu,
                 params.nv);
        double facet, side;
        rc = mesh_facet_size(&surface.mesh, &facet, err);
        if (rc == FACET_OK)
            rc = panels_typical_side(&panels, &side, err);
        if (rc == FACET_OK)
            is_coarse = coarse_mesh_warning(facet, side, grid_name, coarse,
                                            sizeof coarse);
        char what[64];
        snprintf(what, sizeof what, "t = %g mm",
                 params.classify.threshold * 1000);
        is_sagging = facet_sag_warning(surface.facet_sag,
                                       params.classify.threshold, what, sag,
                                       sizeof sag);
    }
    if (rc == FACET_OK) {
        for (int i = 0; i < surface.nwarnings; i++)
            shown_line(stderr, "facet: warning: %s", surface.warnings[i]);
        if (is_coarse)
            fprintf(stderr, "facet: warning: %s\n", coarse);
        if (is_sagging)
            fprintf(stderr, "facet: warning: %s\n", sag);
        if (json) {
            struct report_source source = {
                surface.path, mesh_units_name(surface.units),
                surface.mesh.area, surface.mesh.ntriangles,
                param_method_name(surface.param.method),
                panel_mode_name(params.mode),
            };
            report_json(stdout, &source, &params.classify, &panels, &totals);
        } else {
            print_human(&surface, &params, &panels, &totals);
        }
    }
    panelization_free(&panels);
    surface_close(&surface);
    return rc;
}

const struct command cmd_classify = {
    .name = "classify",
    .usage = "SURFACE.obj --grid NUxNV [--threshold MM] [--units U]\n"
             "       [--curvature-tol K] [--per-panel extremes|mean] "
             "[--flip-normals]\n"
             "       [--prices FP,SP,DP] [--sp-as-fp] [--max-panel-area M2]\n"
             "       [--panel-cost USD] [--joint-cost USD] [--mould-cost SP,DP]\n"
             "       [--mould-tol MM] [--mould-mirror] [--sp-fit yes|no]\n"
             "       [--max-gap MM] [--max-kink DEG] [--min-panel-width M]\n"
             "       [--json] [--csv FILE] [--object NAME] [--group NAME]\n"
             "       [--uv vt|grid|plane|harmonic]",
    .summary = "Divide a surface into a UV grid of panels; classify, type "
               "and price them.",
    .before = "",
    .options = classify_command_options,
    .shared = classify_flags_options,
    .after = "",
    .run = classify_run,
};
