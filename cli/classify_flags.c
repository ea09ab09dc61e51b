/*
 * classify_flags.c: the classification flags. See classify_flags.h.
 */
#include "classify_flags.h"

#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include "core/base/numparse.h"

/* --- the defaults the help states, option_params_defaults's --- */

static struct classify_options default_classify(void)
{
    struct option_params p;
    option_params_defaults(&p);
    return p.classify;
}

static void default_units(char *out, size_t size)
{
    struct surface_flags none = {NULL, NULL, NULL};
    struct mesh_options mesh;
    struct facet_error ignored;
    surface_flags_apply(&none, &mesh, &ignored);
    snprintf(out, size, "%s", mesh_units_name(mesh.units));
}

static void default_curvature_tol(char *out, size_t size)
{
    struct classify_options c = default_classify();
    if (c.curvature_tol > 0)
        snprintf(out, size, "%g", c.curvature_tol);
    else
        snprintf(out, size, "8 t / d^2, d the panel's diagonal");
}

static void default_per_panel(char *out, size_t size)
{
    struct option_params p;
    option_params_defaults(&p);
    snprintf(out, size, "%s", panel_mode_name(p.mode));
}

static void default_prices(char *out, size_t size)
{
    struct classify_options c = default_classify();
    snprintf(out, size, "%g,%g,%g", c.price[TYPE_FP], c.price[TYPE_SP],
             c.price[TYPE_DP]);
}

static void default_max_area(char *out, size_t size)
{
    snprintf(out, size, "%g", default_classify().max_panel_area);
}

static void default_panel_cost(char *out, size_t size)
{
    snprintf(out, size, "%g", default_classify().panel_cost);
}

static void default_joint_cost(char *out, size_t size)
{
    snprintf(out, size, "%g", default_classify().joint_cost);
}

static void default_mould_cost(char *out, size_t size)
{
    struct classify_options c = default_classify();
    snprintf(out, size, "%g,%g", c.mould_cost[TYPE_SP],
             c.mould_cost[TYPE_DP]);
}

static void default_sp_fit(char *out, size_t size)
{
    snprintf(out, size, "%s", default_classify().sp_by_class ? "no" : "yes");
}

/* --- the tables --- */

/* The surface's flags say the same in both tables. */
static const char units_help[] = "what one OBJ unit is: m, cm, mm, in, ft";
static const char object_help[] =
    "only the faces of object NAME (o statement)";
static const char group_help[] = "only the faces of group NAME (g statement)";

const struct arg_option surface_flags_options[] = {
    {"units", 0, ARG_STRING, offsetof(struct surface_flags, units),
     "m|cm|mm|in|ft",
     units_help, default_units},
    {"object", 0, ARG_STRING, offsetof(struct surface_flags, object), "NAME",
     object_help, NULL},
    {"group", 0, ARG_STRING, offsetof(struct surface_flags, group), "NAME",
     group_help, NULL},
    {NULL, 0, ARG_FLAG, 0, NULL, NULL, NULL},
};

const struct arg_option classify_flags_options[] = {
    {"units", 0, ARG_STRING, offsetof(struct classify_flags, surface.units),
     "m|cm|mm|in|ft", units_help, default_units},
    {"curvature-tol", 0, ARG_STRING,
     offsetof(struct classify_flags, curvature_tol), "K",
     "|k| < K (1/m) counts as zero", default_curvature_tol},
    {"per-panel", 0, ARG_STRING, offsetof(struct classify_flags, per_panel),
     "extremes|mean", "extremes: k1 = max, k2 = min over the panel's samples (the "
     "paper's); mean: the area-weighted mean shape operator",
     default_per_panel},
    {"flip-normals", 0, ARG_FLAG,
     offsetof(struct classify_flags, flip_normals), NULL,
     "reverse the surface normal (and every sign)", NULL},
    {"prices", 0, ARG_STRING, offsetof(struct classify_flags, prices),
     "FP,SP,DP", "USD/m^2", default_prices},
    {"sp-as-fp", 0, ARG_FLAG, offsetof(struct classify_flags, sp_as_fp),
     NULL, "price SP area as FP (the paper's MOGD)", NULL},
    {"max-panel-area", 0, ARG_STRING,
     offsetof(struct classify_flags, max_area), "M2", "feasibility limit",
     default_max_area},
    {"panel-cost", 0, ARG_STRING, offsetof(struct classify_flags, panel_cost),
     "USD", "per panel, whatever its type", default_panel_cost},
    {"joint-cost", 0, ARG_STRING, offsetof(struct classify_flags, joint_cost),
     "USD", "per metre of joint", default_joint_cost},
    {"mould-cost", 0, ARG_STRING, offsetof(struct classify_flags, mould_cost),
     "SP,DP", "USD per mould: a bending jig for SP, a mould for DP; 0 "
     "everywhere is the paper's model, area alone", default_mould_cost},
    {"mould-tol", 0, ARG_STRING, offsetof(struct classify_flags, mould_tol),
     "MM", "curved panels within MM of each other share a mould (default: "
     "the flatness threshold)", NULL},
    {"mould-mirror", 0, ARG_FLAG,
     offsetof(struct classify_flags, mould_mirror), NULL,
     "mirror images share a mould too", NULL},
    {"sp-fit", 0, ARG_STRING, offsetof(struct classify_flags, sp_fit),
     "yes|no", "yes: an SP panel no cylinder or cone fits within t is built "
     "and priced DP (a misfit); no: SP by its class alone, the paper's "
     "typing", default_sp_fit},
    {"max-gap", 0, ARG_STRING, offsetof(struct classify_flags, max_gap), "MM",
     "feasible only when no joint's gap exceeds MM (default: no limit)",
     NULL},
    {"max-kink", 0, ARG_STRING, offsetof(struct classify_flags, max_kink),
     "DEG", "feasible only when no joint's kink exceeds DEG degrees "
     "(default: no limit)", NULL},
    {"min-panel-width", 0, ARG_STRING,
     offsetof(struct classify_flags, min_width), "M",
     "feasible only when no panel is narrower than M metres, its outline's "
     "least width in its plane (a sliver; default: no limit)", NULL},
    {"object", 0, ARG_STRING, offsetof(struct classify_flags, surface.object),
     "NAME", object_help, NULL},
    {"group", 0, ARG_STRING, offsetof(struct classify_flags, surface.group),
     "NAME", group_help, NULL},
    {"uv", 0, ARG_STRING, offsetof(struct classify_flags, uv),
     "vt|grid|plane|harmonic|auto",
     "the UV panels follow: vt, grid (a structured quad grid's own i, j), "
     "plane, harmonic; default the first of these that applies", NULL},
    {NULL, 0, ARG_FLAG, 0, NULL, NULL, NULL},
};

int surface_flags_apply(const struct surface_flags *f,
                        struct mesh_options *mesh, struct facet_error *err)
{
    *mesh = (struct mesh_options){UNITS_M, f->object, f->group};
    if (f->units != NULL)
        return mesh_units_parse(f->units, "--units", &mesh->units, err);
    return FACET_OK;
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
    if (f->min_width) {
        if ((rc = numparse_number(f->min_width, CLASSIFY_PANEL_WIDTH_MIN,
                                  CLASSIFY_PANEL_WIDTH_MAX,
                                  "--min-panel-width", &number, err)))
            return rc;
        params->classify.min_panel_width = number;
    }
    return FACET_OK;
}
