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
#include "command.h"
#include "option_text.h"
#include "core/option.h"
#include "core/report.h"

/* Parses "37x49" into nu, nv. */
static int parse_grid(const char *text, int *nu, int *nv,
                      struct facet_error *err)
{
    char extra;
    if (text == NULL)
        return facet_error_set(err, FACET_EINPUT,
            "classify: give the grid, e.g. --grid 37x49");
    if (sscanf(text, "%dx%d%c", nu, nv, &extra) != 2 &&
        sscanf(text, "%dX%d%c", nu, nv, &extra) != 2)
        return facet_error_set(err, FACET_EINPUT,
            "--grid: '%s' is not NUxNV (e.g. 37x49)", text);
    if (*nu < 1 || *nv < 1 || *nu > PANEL_MAX_GRID || *nv > PANEL_MAX_GRID)
        return facet_error_set(err, FACET_EINPUT,
            "--grid: %dx%d is out of range (each side 1 to %d)", *nu, *nv,
            PANEL_MAX_GRID);
    return FACET_OK;
}

static void print_human(const struct surface *s,
                        const struct option_params *params,
                        const struct panelization *p,
                        const struct option_totals *t)
{
    const struct classify_options *o = &params->classify;
    printf("%-16s %s (%s, %.3f m^2, %zu triangles, UV from %s)\n",
           "surface", s->path, mesh_units_name(s->units), s->mesh.area,
           s->mesh.ntriangles, param_method_name(s->param.method));
    printf("%-16s %d x %d (%zu panels)\n", "grid", p->nu, p->nv, t->panels);
    printf("%-16s %g mm\n", "threshold", o->threshold * 1000);
    if (o->curvature_tol > 0)
        printf("%-16s %g 1/m\n", "curvature tol", o->curvature_tol);
    else
        printf("%-16s 8 t / d^2 per panel\n", "curvature tol");
    printf("%-16s FP %g, SP %g, DP %g USD/m^2%s\n", "prices",
           o->price[TYPE_FP], o->price[TYPE_SP], o->price[TYPE_DP],
           o->sp_as_fp ? " (SP priced as FP)" : "");

    option_text_totals(stdout, t, o);
    option_text_map(stdout, p);
}

/* Writes the CSV schedule to path through path.partial, so that a failure
 * never leaves a half-written schedule. */
static int write_csv(const char *path, const struct panelization *p,
                     struct facet_error *err)
{
    char partial[4096];
    if (snprintf(partial, sizeof partial, "%s.partial", path) >=
        (int)sizeof partial)
        return facet_error_set(err, FACET_EINPUT, "--csv: path too long");
    FILE *out = fopen(partial, "w");
    if (out == NULL)
        return facet_error_set(err, FACET_EINPUT, "--csv: cannot write %s: %s",
                               path, strerror(errno));
    report_csv(out, p);
    int failed = ferror(out);
    if (fclose(out) != 0 || failed) {
        remove(partial);
        return facet_error_set(err, FACET_EWORK, "--csv: writing %s failed",
                               path);
    }
    if (rename(partial, path) != 0) {
        remove(partial);
        return facet_error_set(err, FACET_EWORK, "--csv: cannot write %s: %s",
                               path, strerror(errno));
    }
    return FACET_OK;
}

static int classify_run(int argc, char **argv, struct facet_error *err)
{
    const char *grid = NULL, *threshold = NULL, *units = NULL, *tol = NULL;
    const char *per_panel = NULL, *prices = NULL, *max_area = NULL;
    const char *csv = NULL, *object = NULL, *group = NULL;
    int flip = 0, sp_as_fp = 0, json = 0;
    const struct arg_option options[] = {
        {"grid", 0, ARG_STRING, &grid, NULL},
        {"threshold", 0, ARG_STRING, &threshold, NULL},
        {"units", 0, ARG_STRING, &units, NULL},
        {"curvature-tol", 0, ARG_STRING, &tol, NULL},
        {"per-panel", 0, ARG_STRING, &per_panel, NULL},
        {"flip-normals", 0, ARG_FLAG, NULL, &flip},
        {"prices", 0, ARG_STRING, &prices, NULL},
        {"sp-as-fp", 0, ARG_FLAG, NULL, &sp_as_fp},
        {"max-panel-area", 0, ARG_STRING, &max_area, NULL},
        {"json", 0, ARG_FLAG, NULL, &json},
        {"csv", 0, ARG_STRING, &csv, NULL},
        {"object", 0, ARG_STRING, &object, NULL},
        {"group", 0, ARG_STRING, &group, NULL},
        {NULL, 0, ARG_FLAG, NULL, NULL},
    };
    const char *path[1];
    int count;
    int rc = args_parse(argc, argv, options, path, 1, &count, err);
    if (rc != FACET_OK)
        return rc;
    if (count != 1)
        return facet_error_set(err, FACET_EINPUT,
            "classify: name one OBJ file (facet classify FILE.obj --grid "
            "37x49)");

    struct option_params params;
    memset(&params, 0, sizeof params);
    classify_defaults(&params.classify);
    params.mode = PANEL_EXTREMES;
    struct mesh_options mesh_options = {UNITS_M, object, group};
    double number;
    if ((rc = parse_grid(grid, &params.nu, &params.nv, err)) != FACET_OK)
        return rc;
    if (units && (rc = mesh_units_parse(units, &mesh_options.units, err)))
        return rc;
    if (threshold) {
        if ((rc = args_double(threshold, 0, 1e6, "--threshold", &number,
                              err)))
            return rc;
        params.classify.threshold = number / 1000;
    }
    if (tol) {
        if ((rc = args_double(tol, 1e-12, 1e6, "--curvature-tol", &number,
                              err)))
            return rc;
        params.classify.curvature_tol = number;
    }
    if (per_panel) {
        if (strcmp(per_panel, "mean") == 0)
            params.mode = PANEL_MEAN;
        else if (strcmp(per_panel, "extremes") != 0)
            return facet_error_set(err, FACET_EINPUT,
                "--per-panel: '%s' is not extremes or mean", per_panel);
    }
    if (prices && (rc = args_parse_prices(prices, params.classify.price, err)))
        return rc;
    params.classify.sp_as_fp = sp_as_fp;
    if (max_area) {
        if ((rc = args_double(max_area, 1e-9, 1e9, "--max-panel-area",
                              &number, err)))
            return rc;
        params.classify.max_panel_area = number;
    }

    struct surface surface;
    struct panelization panels;
    struct option_totals totals;
    memset(&panels, 0, sizeof panels);
    rc = surface_open(path[0], &mesh_options, &surface, err);
    if (rc == FACET_OK)
        rc = surface_prepare(&surface, flip, err);
    if (rc == FACET_OK)
        rc = option_evaluate(&surface, &params, &panels, &totals, err);
    if (rc == FACET_OK && csv != NULL)
        rc = write_csv(csv, &panels, err);
    if (rc == FACET_OK) {
        for (int i = 0; i < surface.nwarnings; i++)
            fprintf(stderr, "facet: warning: %s\n", surface.warnings[i]);
        if (json) {
            struct report_source source = {
                surface.path, mesh_units_name(surface.units),
                surface.mesh.area, surface.mesh.ntriangles,
                param_method_name(surface.param.method),
                params.mode == PANEL_MEAN ? "mean" : "extremes",
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
             "       [--json] [--csv FILE] [--object NAME] [--group NAME]",
    .summary = "Divide a surface into a UV grid of panels; classify, type "
               "and price them.",
    .options =
        "  --grid NUxNV        panels along u and v (e.g. 37x49, the paper's)\n"
        "  --threshold MM      flatness threshold t: a panel within t of its\n"
        "                      best-fit plane is made flat (default 3)\n"
        "  --units U           m (default), cm, mm, in, ft\n"
        "  --curvature-tol K   |k| < K (1/m) counts as zero (default\n"
        "                      8 t / d^2, d the panel's diagonal)\n"
        "  --per-panel MODE    extremes: k1 = max, k2 = min over the panel's\n"
        "                      samples (the paper's, default); mean: the\n"
        "                      area-weighted mean shape operator\n"
        "  --flip-normals      reverse the surface normal (and every sign)\n"
        "  --prices FP,SP,DP   USD/m^2 (default 701,766,1518)\n"
        "  --sp-as-fp          price SP area as FP (the paper's MOGD)\n"
        "  --max-panel-area M2 feasibility limit (default 7.06)\n"
        "  --json              one JSON object (see README)\n"
        "  --csv FILE          the panel schedule, one row per panel\n"
        "  --object NAME       only the faces of object NAME\n"
        "  --group NAME        only the faces of group NAME\n",
    .run = classify_run,
};
