/*
 * classify_flags.c: the classification flags. See classify_flags.h.
 */
#include "classify_flags.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "core/base/numparse.h"

void classify_flags_usage(FILE *out)
{
    struct option_params p;
    option_params_defaults(&p);
    const struct classify_options *c = &p.classify;
    struct surface_flags none;
    struct mesh_options mesh;
    struct facet_error ignored;
    surface_flags_init(&none);
    surface_flags_apply(&none, &mesh, &ignored);
    fprintf(out,
        "  --units U           m, cm, mm, in, ft (default %s)\n"
        "  --curvature-tol K   |k| < K (1/m) counts as zero (default\n",
        mesh_units_name(mesh.units));
    if (c->curvature_tol > 0)
        fprintf(out, "                      %g)\n", c->curvature_tol);
    else
        fputs("                      8 t / d^2, d the panel's diagonal)\n",
              out);
    fprintf(out,
        "  --per-panel MODE    extremes: k1 = max, k2 = min over the panel's\n"
        "                      samples (the paper's); mean: the\n"
        "                      area-weighted mean shape operator (default\n"
        "                      %s)\n"
        "  --flip-normals      reverse the surface normal (and every sign)\n"
        "  --prices FP,SP,DP   USD/m^2 (default %g,%g,%g)\n"
        "  --sp-as-fp          price SP area as FP (the paper's MOGD)\n"
        "  --max-panel-area M2 feasibility limit (default %g)\n"
        "  --panel-cost USD    per panel, whatever its type (default %g)\n"
        "  --joint-cost USD    per metre of joint (default %g)\n"
        "  --mould-cost SP,DP  USD per mould: a bending jig for SP, a mould for\n"
        "                      DP (default %g,%g); 0 everywhere is the paper's\n"
        "                      model, area alone\n"
        "  --mould-tol MM      curved panels within MM of each other share a\n"
        "                      mould (default: the flatness threshold)\n"
        "  --mould-mirror      mirror images share a mould too\n"
        "  --sp-fit yes|no     yes: an SP panel no cylinder or cone fits\n"
        "                      within t is built and priced DP (a misfit);\n"
        "                      no: SP by its class alone, the paper's\n"
        "                      typing (default %s)\n"
        "  --max-gap MM        feasible only when no joint's gap exceeds MM\n"
        "                      (default: no limit)\n"
        "  --max-kink DEG      feasible only when no joint's kink exceeds\n"
        "                      DEG degrees (default: no limit)\n"
        "  --object NAME       only the faces of object NAME\n"
        "  --group NAME        only the faces of group NAME\n"
        "  --uv METHOD         the UV panels follow: vt, grid (a structured\n"
        "                      quad grid's own i, j), plane, harmonic; default\n"
        "                      the first of these that applies\n",
        panel_mode_name(p.mode), c->price[TYPE_FP], c->price[TYPE_SP],
        c->price[TYPE_DP], c->max_panel_area, c->panel_cost, c->joint_cost,
        c->mould_cost[TYPE_SP], c->mould_cost[TYPE_DP],
        c->sp_by_class ? "no" : "yes");
}

void surface_flags_init(struct surface_flags *f)
{
    memset(f, 0, sizeof *f);
    const struct arg_option entries[] = {
        {"units", 0, ARG_STRING, &f->units, NULL},
        {"object", 0, ARG_STRING, &f->object, NULL},
        {"group", 0, ARG_STRING, &f->group, NULL},
        {NULL, 0, ARG_FLAG, NULL, NULL},
    };
    _Static_assert(sizeof entries == sizeof f->table,
                   "the table holds every flag and its end");
    memcpy(f->table, entries, sizeof entries);
}

int surface_flags_apply(const struct surface_flags *f,
                        struct mesh_options *mesh, struct facet_error *err)
{
    *mesh = (struct mesh_options){UNITS_M, f->object, f->group};
    if (f->units != NULL)
        return mesh_units_parse(f->units, "--units", &mesh->units, err);
    return FACET_OK;
}

void classify_flags_init(struct classify_flags *f)
{
    memset(f, 0, sizeof *f);
    /* In the order of the usage lines, the surface's flags among them. */
    const struct arg_option entries[] = {
        {"units", 0, ARG_STRING, &f->surface.units, NULL},
        {"curvature-tol", 0, ARG_STRING, &f->curvature_tol, NULL},
        {"per-panel", 0, ARG_STRING, &f->per_panel, NULL},
        {"flip-normals", 0, ARG_FLAG, NULL, &f->flip_normals},
        {"prices", 0, ARG_STRING, &f->prices, NULL},
        {"sp-as-fp", 0, ARG_FLAG, NULL, &f->sp_as_fp},
        {"max-panel-area", 0, ARG_STRING, &f->max_area, NULL},
        {"panel-cost", 0, ARG_STRING, &f->panel_cost, NULL},
        {"joint-cost", 0, ARG_STRING, &f->joint_cost, NULL},
        {"mould-cost", 0, ARG_STRING, &f->mould_cost, NULL},
        {"mould-tol", 0, ARG_STRING, &f->mould_tol, NULL},
        {"mould-mirror", 0, ARG_FLAG, NULL, &f->mould_mirror},
        {"sp-fit", 0, ARG_STRING, &f->sp_fit, NULL},
        {"max-gap", 0, ARG_STRING, &f->max_gap, NULL},
        {"max-kink", 0, ARG_STRING, &f->max_kink, NULL},
        {"object", 0, ARG_STRING, &f->surface.object, NULL},
        {"group", 0, ARG_STRING, &f->surface.group, NULL},
        {"uv", 0, ARG_STRING, &f->uv, NULL},
        {NULL, 0, ARG_FLAG, NULL, NULL},
    };
    _Static_assert(sizeof entries == sizeof f->table,
                   "the table holds every flag and its end");
    memcpy(f->table, entries, sizeof entries);
}

int classify_flags_uv(const char *text, enum param_method *uv,
                      struct facet_error *err)
{
    *uv = PARAM_AUTO;
    if (text != NULL && param_method_parse(text, uv) != 0)
        return facet_error_set(err, FACET_EINPUT,
            "--uv: '%s' is not vt, grid, plane, harmonic or auto", text);
    return FACET_OK;
}

int classify_flags_apply(const struct classify_flags *f,
                         struct option_params *params,
                         struct mesh_options *mesh, enum param_method *uv,
                         struct facet_error *err)
{
    option_params_defaults(params);
    double number;
    int rc;
    if ((rc = surface_flags_apply(&f->surface, mesh, err)))
        return rc;
    if ((rc = classify_flags_uv(f->uv, uv, err)))
        return rc;
    if (f->curvature_tol) {
        if ((rc = numparse_number(f->curvature_tol, 1e-12, 1e6,
                                  "--curvature-tol", &number, err)))
            return rc;
        params->classify.curvature_tol = number;
    }
    if (f->per_panel && (rc = panel_mode_parse(f->per_panel, "--per-panel",
                                               &params->mode, err)))
        return rc;
    if (f->prices &&
        (rc = classify_prices_parse(f->prices, "--prices", params->classify.price,
                                    err)))
        return rc;
    params->classify.sp_as_fp = f->sp_as_fp;
    if (f->max_area) {
        if ((rc = numparse_number(f->max_area, CLASSIFY_PANEL_AREA_MIN,
                                  CLASSIFY_PANEL_AREA_MAX, "--max-panel-area",
                                  &number, err)))
            return rc;
        params->classify.max_panel_area = number;
    }
    if (f->panel_cost &&
        (rc = numparse_number(f->panel_cost, 0, CLASSIFY_AMOUNT_MAX,
                              "--panel-cost", &params->classify.panel_cost,
                              err)))
        return rc;
    if (f->joint_cost &&
        (rc = numparse_number(f->joint_cost, 0, CLASSIFY_AMOUNT_MAX,
                              "--joint-cost", &params->classify.joint_cost,
                              err)))
        return rc;
    if (f->mould_cost &&
        (rc = classify_mould_costs_parse(f->mould_cost, "--mould-cost",
                                         params->classify.mould_cost, err)))
        return rc;
    if (f->mould_tol) {
        if ((rc = numparse_number(f->mould_tol, 0, CLASSIFY_MOULD_TOL_MAX_MM,
                                  "--mould-tol", &number, err)))
            return rc;
        params->mould_tol = number / 1000;
        params->mould_tol_given = 1;
    }
    params->mould_mirror = f->mould_mirror;
    if (f->sp_fit != NULL) {
        if (strcmp(f->sp_fit, "yes") == 0)
            params->classify.sp_by_class = 0;
        else if (strcmp(f->sp_fit, "no") == 0)
            params->classify.sp_by_class = 1;
        else
            return facet_error_set(err, FACET_EINPUT,
                "--sp-fit: '%s' is not yes or no", f->sp_fit);
    }
    if (f->max_gap) {
        if ((rc = numparse_number(f->max_gap, CLASSIFY_MAX_GAP_MIN_MM,
                                  CLASSIFY_MAX_GAP_MAX_MM, "--max-gap",
                                  &number, err)))
            return rc;
        params->classify.max_gap = number / 1000;
    }
    if (f->max_kink) {
        if ((rc = numparse_number(f->max_kink, CLASSIFY_MAX_KINK_MIN_DEG,
                                  CLASSIFY_MAX_KINK_MAX_DEG, "--max-kink",
                                  &number, err)))
            return rc;
        params->classify.max_kink = number * M_PI / 180;
    }
    return FACET_OK;
}
