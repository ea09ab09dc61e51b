/*
 * classify.c: Table 1, panel types, the threshold rule, cost and totals.
 * See classify.h.
 */
#include "classify.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

void classify_defaults(struct classify_options *options)
{
    options->threshold = 0.003;
    options->curvature_tol = 0;
    options->price[TYPE_FP] = 701;
    options->price[TYPE_SP] = 766;
    options->price[TYPE_DP] = 1518;
    options->sp_as_fp = 0;
    options->max_panel_area = 7.06;
}

static int sign_of(double x, double eps)
{
    if (fabs(x) < eps)
        return 0;
    return x > 0 ? 1 : -1;
}

enum panel_class classify_curvature(double k1, double k2, double eps)
{
    int s1 = sign_of(k1, eps), s2 = sign_of(k2, eps);
    double k1z = s1 ? k1 : 0, k2z = s2 ? k2 : 0;
    int sign_k = s1 * s2;
    int sign_h = sign_of((k1z + k2z) / 2, eps);
    if (sign_k < 0)
        return sign_h < 0 ? CLASS_CONVEX_FEATURE_CURVE
             : sign_h > 0 ? CLASS_CONCAVE_FEATURE_CURVE : CLASS_SADDLE;
    if (sign_k == 0)
        return sign_h < 0 ? CLASS_RULED_CONVEX
             : sign_h > 0 ? CLASS_RULED_CONCAVE : CLASS_FLAT;
    return sign_h < 0 ? CLASS_CONVEX_ROUND : CLASS_CONCAVE_ROUND;
}

enum panel_type panel_type_of_class(enum panel_class class)
{
    switch (class) {
    case CLASS_FLAT:
        return TYPE_FP;
    case CLASS_RULED_CONVEX:
    case CLASS_RULED_CONCAVE:
        return TYPE_SP;
    default:
        return TYPE_DP;
    }
}

const char *panel_class_name(enum panel_class class)
{
    static const char *const names[CLASS_COUNT] = {
        "convex_feature_curve", "saddle", "concave_feature_curve",
        "ruled_convex", "flat", "ruled_concave",
        "convex_round", "concave_round",
    };
    return (unsigned)class < CLASS_COUNT ? names[class] : "?";
}

const char *panel_type_name(enum panel_type type)
{
    static const char *const names[TYPE_COUNT] = {"FP", "SP", "DP"};
    return (unsigned)type < TYPE_COUNT ? names[type] : "?";
}

double classify_tolerance(const struct classify_options *options,
                          const struct panel *panel)
{
    if (options->curvature_tol > 0)
        return options->curvature_tol;
    if (!(panel->diameter > 0))
        return INFINITY;
    return 8 * options->threshold / (panel->diameter * panel->diameter);
}

void classify_panels(struct panelization *p,
                     const struct classify_options *options,
                     struct option_totals *totals)
{
    memset(totals, 0, sizeof *totals);
    totals->feasible = 1;
    for (size_t n = 0; n < p->npanels; n++) {
        struct panel *panel = &p->panels[n];
        panel->K = panel->k1 * panel->k2;
        panel->H = (panel->k1 + panel->k2) / 2;
        panel->curvature_tol = classify_tolerance(options, panel);
        panel->class = classify_curvature(panel->k1, panel->k2,
                                          panel->curvature_tol);
        panel->type = panel_type_of_class(panel->class);
        if (panel->deviation <= options->threshold)
            panel->type = TYPE_FP;
        enum panel_type priced_as = panel->type;
        if (options->sp_as_fp && priced_as == TYPE_SP)
            priced_as = TYPE_FP;
        panel->price = options->price[priced_as];
        panel->cost = panel->area * panel->price;

        totals->panels++;
        totals->count[panel->type]++;
        totals->area_of[panel->type] += panel->area;
        totals->cost_of[panel->type] += panel->cost;
        totals->class_count[panel->class]++;
        totals->class_area[panel->class] += panel->area;
        totals->area += panel->area;
        totals->cost += panel->cost;
        if (panel->type != TYPE_DP) {
            totals->planarity += panel->deviation;
            totals->p_dist += panel->p_dist;
            totals->max_deviation = fmax(totals->max_deviation,
                                         panel->deviation);
        }
        totals->max_panel_area = fmax(totals->max_panel_area, panel->area);
    }
    totals->feasible = totals->max_panel_area <= options->max_panel_area;
}

int classify_check_options(const struct classify_options *options,
                           struct facet_error *err)
{
    if (!isfinite(options->threshold) || options->threshold < 0)
        return facet_error_set(err, FACET_EINPUT,
            "threshold %g mm is not a length (give 0 or more)",
            options->threshold * 1000);
    if (!isfinite(options->curvature_tol) || options->curvature_tol < 0)
        return facet_error_set(err, FACET_EINPUT,
            "curvature tolerance %g 1/m must be 0 or more",
            options->curvature_tol);
    for (int t = 0; t < TYPE_COUNT; t++)
        if (!isfinite(options->price[t]) || options->price[t] < 0)
            return facet_error_set(err, FACET_EINPUT,
                "price of %s %g USD/m^2 must be 0 or more",
                panel_type_name((enum panel_type)t), options->price[t]);
    if (!isfinite(options->max_panel_area) || options->max_panel_area <= 0)
        return facet_error_set(err, FACET_EINPUT,
            "maximum panel area %g m^2 must be more than 0",
            options->max_panel_area);
    return FACET_OK;
}

int classify_prices_parse(const char *text, double price[TYPE_COUNT],
                          struct facet_error *err)
{
    const char *p = text;
    for (int t = 0; t < TYPE_COUNT; t++) {
        char *end;
        price[t] = strtod(p, &end);
        while (*end == ' ')
            end++;
        if (end == p || !isfinite(price[t]) || price[t] < 0 ||
            price[t] > 1e9 || *end != (t + 1 < TYPE_COUNT ? ',' : '\0'))
            return facet_error_set(err, FACET_EINPUT,
                "--prices: '%s' is not FP,SP,DP in USD/m^2 (e.g. "
                "701,766,1518)", text);
        p = end + 1;
    }
    return FACET_OK;
}
