/*
 * classify.c: Table 1, panel types, the threshold rule, cost and totals.
 * See classify.h.
 */
#include "core/classify/classify.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/base/exact_sum.h"
#include "core/base/numparse.h"
#include "core/fit/sp_fit.h"
#include "core/base/units.h"

double totals_count(size_t count)
{
    return count == TOTALS_UNKNOWN ? NAN : (double)count;
}

void classify_defaults(struct classify_options *options)
{
    /* Every field a default, the ones below and those that are 0 (no
     * price per panel, joint or mould; no width limit), whatever the
     * caller's memory held. */
    memset(options, 0, sizeof *options);
    options->threshold = 0.003;
    options->curvature_tol = 0;
    options->price[TYPE_FP] = 701;
    options->price[TYPE_SP] = 766;
    options->price[TYPE_DP] = 1518;
    options->sp_as_fp = 0;
    options->max_panel_area = 7.06;
    options->sp_by_class = 0;
    options->max_gap = 0;
    options->max_kink = 0;
}

/* The sign of a curvature k[1] known to lie in [k[0], k[2]] (1/m): 0
 * within the zero tolerance eps widened by rounding (a value computed as
 * eps (1 + 1e-15) is eps), and 0 where the range holds 0, the estimate
 * not knowing the sign; else the sign of k[1]. An exact 0 is always 0,
 * whatever eps. */
static int sign_within(const double k[3], double eps)
{
    if (fabs(k[1]) <= eps * (1 + CLASSIFY_ROUNDING) ||
        (k[0] <= 0 && k[2] >= 0))
        return 0;
    return k[1] > 0 ? 1 : -1;
}

enum panel_class classify_curvature(double k1, double k2, double eps)
{
    const double r1[3] = {k1, k1, k1}, r2[3] = {k2, k2, k2};
    return classify_curvature_within(r1, r2, eps);
}

enum panel_class classify_curvature_within(const double k1[3],
                                           const double k2[3], double eps)
{
    int s1 = sign_within(k1, eps), s2 = sign_within(k2, eps);

    /* K = 0: one curvature at most is non-zero, and H takes its sign, as
     * k1 + k2 does after zeroing. No test of |H| here: a ruled panel with
     * eps < |k1| < 2 eps has |H| < eps and would turn flat. */
    if (s1 == 0 || s2 == 0) {
        int s = s1 ? s1 : s2;
        return s < 0 ? CLASS_RULED_CONVEX
             : s > 0 ? CLASS_RULED_CONCAVE : CLASS_FLAT;
    }
    /* K > 0: both curvatures non-zero and of one sign, which H shares. */
    if (s1 == s2)
        return s1 < 0 ? CLASS_CONVEX_ROUND : CLASS_CONCAVE_ROUND;
    /* K < 0, the saddle rule: a saddle when the two curvatures cancel to
     * within the zero tolerance (|k1 + k2| / 2 <= eps), else a feature
     * curve on the side of the larger curvature. */
    const double h[3] = {(k1[0] + k2[0]) / 2, (k1[1] + k2[1]) / 2,
                         (k1[2] + k2[2]) / 2};
    int sign_h = sign_within(h, eps);
    return sign_h < 0 ? CLASS_CONVEX_FEATURE_CURVE
         : sign_h > 0 ? CLASS_CONCAVE_FEATURE_CURVE : CLASS_SADDLE;
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
    /* Never below the curvature of a sag of rounding size, so that t = 0
     * still leaves a plane flat: its fitted curvature is rounding noise,
     * and 8 * 0 / d^2 would call every sign of that noise a curvature. */
    double sag = fmax(options->threshold, CLASSIFY_ROUNDING * panel->diameter);
    return 8 * sag / (panel->diameter * panel->diameter);
}

int classify_within_threshold(const struct classify_options *options,
                              const struct panel *panel)
{
    double rounding = CLASSIFY_ROUNDING *
                      (isfinite(panel->diameter) ? panel->diameter : 0);
    return panel->deviation <= options->threshold + rounding;
}

size_t classify_fp_over_threshold(const struct panelization *p,
                                  const struct classify_options *options,
                                  double *worst)
{
    size_t count = 0;
    double largest = 0;
    for (size_t n = 0; n < p->npanels; n++) {
        const struct panel *panel = &p->panels[n];
        if (panel->type == TYPE_FP &&
            !classify_within_threshold(options, panel)) {
            count++;
            largest = fmax(largest, panel->deviation);
        }
    }
    if (worst != NULL)
        *worst = largest;
    return count;
}

double classify_area_excess(double max_panel_area, double limit)
{
    if (max_panel_area <= limit * (1 + CLASSIFY_ROUNDING))
        return 0;
    return max_panel_area - limit;
}

void classify_types(struct panelization *p,
                    const struct classify_options *options)
{
    p->threshold = options->threshold;
    for (size_t n = 0; n < p->npanels; n++) {
        struct panel *panel = &p->panels[n];
        panel->K = panel->k1 * panel->k2;
        panel->H = (panel->k1 + panel->k2) / 2;
        panel->curvature_tol = classify_tolerance(options, panel);
        /* the range each curvature is known to (panel.h), unless the user
         * fixed eps: then it is taken as the whole of the allowance */
        double k1[3] = {panel->k1, panel->k1, panel->k1};
        double k2[3] = {panel->k2, panel->k2, panel->k2};
        if (!(options->curvature_tol > 0)) {
            k1[0] -= panel->k1_error[0];
            k1[2] += panel->k1_error[1];
            k2[0] -= panel->k2_error[0];
            k2[2] += panel->k2_error[1];
        }
        panel->class = classify_curvature_within(k1, k2,
                                                 panel->curvature_tol);
        /* Flat because neither curvature's sign is known is no evidence
         * of flatness: a panel that leaves its plane by more than t is
         * classed by its estimates themselves, never typed FP for the
         * noise (an FP panel is within t, or flat by its curvatures). */
        if (panel->class == CLASS_FLAT && !(options->curvature_tol > 0) &&
            !classify_within_threshold(options, panel)) {
            double a[3] = {panel->k1, panel->k1, panel->k1};
            double b[3] = {panel->k2, panel->k2, panel->k2};
            panel->class = classify_curvature_within(a, b,
                                                     panel->curvature_tol);
        }
        panel->type = panel_type_of_class(panel->class);
        if (classify_within_threshold(options, panel))
            panel->type = TYPE_FP;
    }
}

void classify_panels(struct panelization *p,
                     const struct classify_options *options,
                     struct option_totals *totals)
{
    classify_types(p, options);
    classify_totals(p, options, totals);
}

void option_totals_classified(struct option_totals *totals)
{
    totals->planarized = 0;
    totals->closeness_reached = NAN;
    totals->closeness_mean = NAN;
    totals->planarity_reached = NAN;
    totals->planar_over = TOTALS_UNKNOWN;
    totals->seams = TOTALS_UNKNOWN;
    totals->seam_length = NAN;
    totals->seam_max_gap = NAN;
    totals->seam_max_kink = NAN;
    totals->seam_max_crease = NAN;
    totals->seam_gaps_over = TOTALS_UNKNOWN;
    totals->seam_kinks_over = TOTALS_UNKNOWN;
}

void classify_totals(struct panelization *p,
                     const struct classify_options *options,
                     struct option_totals *totals)
{
    memset(totals, 0, sizeof *totals);
    option_totals_classified(totals);
    totals->feasible = 1;
    struct option_area_sums sums;
    option_area_sums_init(&sums);
    for (size_t n = 0; n < p->npanels; n++) {
        struct panel *panel = &p->panels[n];
        enum panel_type priced_as = panel->type;
        if (options->sp_as_fp && priced_as == TYPE_SP)
            priced_as = TYPE_FP;
        panel->price = options->price[priced_as];
        panel->cost = panel->area * panel->price;

        totals->panels++;
        totals->count[panel->type]++;
        totals->class_count[panel->class]++;
        option_area_sums_add_panel(&sums, panel);
        if (panel->type != TYPE_DP)
            totals->max_deviation = fmax(totals->max_deviation,
                                         panel->deviation);
        totals->max_panel_area = fmax(totals->max_panel_area, panel->area);
        totals->min_panel_area = totals->panels == 1
                                     ? panel->area
                                     : fmin(totals->min_panel_area,
                                            panel->area);
    }
    if (totals->panels == 0)
        totals->min_panel_area = NAN;
    /* Widths are option_evaluate's to measure (panel_width.h). */
    totals->min_panel_width = NAN;
    totals->slivers = TOTALS_UNKNOWN;
    option_area_sums_value(&sums, totals);
    classify_price_areas(options, totals);
    totals->feasible =
        classify_violation(totals, options->max_panel_area) == 0;
}

void option_area_sums_init(struct option_area_sums *sums)
{
    for (int t = 0; t < TYPE_COUNT; t++)
        exact_sum_init(&sums->area_of[t]);
    for (int c = 0; c < CLASS_COUNT; c++)
        exact_sum_init(&sums->class_area[c]);
    exact_sum_init(&sums->area);
    exact_sum_init(&sums->planarity);
    exact_sum_init(&sums->p_dist);
}

void option_area_sums_add_panel(struct option_area_sums *sums,
                                const struct panel *panel)
{
    exact_sum_add(&sums->area_of[panel->type], panel->area);
    exact_sum_add(&sums->class_area[panel->class], panel->area);
    exact_sum_add(&sums->area, panel->area);
    if (panel->type != TYPE_DP) {
        exact_sum_add(&sums->planarity, panel->deviation);
        exact_sum_add(&sums->p_dist, panel->p_dist);
    }
}

void option_area_sums_value(const struct option_area_sums *sums,
                            struct option_totals *totals)
{
    for (int t = 0; t < TYPE_COUNT; t++)
        totals->area_of[t] = exact_sum_value(&sums->area_of[t]);
    for (int c = 0; c < CLASS_COUNT; c++)
        totals->class_area[c] = exact_sum_value(&sums->class_area[c]);
    totals->area = exact_sum_value(&sums->area);
    totals->planarity = exact_sum_value(&sums->planarity);
    totals->p_dist = exact_sum_value(&sums->p_dist);
}

void classify_price_areas(const struct classify_options *options,
                          struct option_totals *totals)
{
    /* Cost from the areas per type, not from the panels one by one: two
     * options whose type areas are equal then cost the same to the bit,
     * whatever order their panels were summed in. */
    for (int t = 0; t < TYPE_COUNT; t++) {
        enum panel_type priced_as = (enum panel_type)t;
        if (options->sp_as_fp && priced_as == TYPE_SP)
            priced_as = TYPE_FP;
        totals->cost_of[t] = totals->area_of[t] * options->price[priced_as];
    }
    totals->area_cost = totals->cost_of[TYPE_FP] + totals->cost_of[TYPE_SP] +
                        totals->cost_of[TYPE_DP];
    totals->cost = totals->area_cost;
}

unsigned classify_broken_limits(const struct option_totals *totals,
                                double max_panel_area,
                                double term[LIMIT_COUNT])
{
    /* Joints not measured are none over a limit: a run measures them
     * whenever it has a gap or kink limit (option_measures_needed). */
    term[LIMIT_PANEL_AREA] =
        classify_area_excess(totals->max_panel_area, max_panel_area);
    term[LIMIT_PANEL_WIDTH] = totals->slivers == TOTALS_UNKNOWN
                                  ? 0 : (double)totals->slivers;
    term[LIMIT_GAP] = totals->gaps_over == TOTALS_UNKNOWN
                          ? 0 : (double)totals->gaps_over;
    term[LIMIT_KINK] = totals->kinks_over == TOTALS_UNKNOWN
                           ? 0 : (double)totals->kinks_over;
    term[LIMIT_PLANARIZE] = totals->planar_over == TOTALS_UNKNOWN
                                ? 0 : (double)totals->planar_over;
    unsigned broken = 0;
    for (int k = 0; k < LIMIT_COUNT; k++)
        if (term[k] > 0)
            broken |= 1u << k;
    return broken;
}

double classify_violation(const struct option_totals *totals,
                          double max_panel_area)
{
    double term[LIMIT_COUNT];
    classify_broken_limits(totals, max_panel_area, term);
    /* summed in the order it always was, so a stored ranking's
     * constraint-domination reads the same bits */
    return term[LIMIT_PANEL_AREA] + term[LIMIT_GAP] + term[LIMIT_KINK] +
           term[LIMIT_PANEL_WIDTH] + term[LIMIT_PLANARIZE];
}

void classify_price_terms(const struct classify_options *options,
                          struct option_totals *totals)
{
    /* A term without a price is 0 whether or not its quantity was
     * measured (a run measures what it prices: option_measures_needed). */
    totals->panel_cost = (double)totals->panels * options->panel_cost;
    totals->joint_cost = options->joint_cost == 0
                             ? 0 : totals->joint_length * options->joint_cost;
    totals->mould_cost = 0;
    for (int t = 0; t < TYPE_COUNT; t++)
        if (options->mould_cost[t] != 0)
            totals->mould_cost += totals_count(totals->moulds_of[t]) *
                                  options->mould_cost[t];
    totals->cost = totals->area_cost + totals->panel_cost +
                   totals->joint_cost + totals->mould_cost;
}

int classify_check_options(const struct classify_options *options,
                           struct facet_error *err)
{
    if (!isfinite(options->threshold) || options->threshold < 0)
        return facet_error_set(err, FACET_EINPUT,
            "threshold %g mm is not a length (give 0 or more)",
            units_mm(options->threshold));
    if (!isfinite(options->curvature_tol) || options->curvature_tol < 0)
        return facet_error_set(err, FACET_EINPUT,
            "curvature tolerance %g 1/m must be 0 or more",
            options->curvature_tol);
    for (int t = 0; t < TYPE_COUNT; t++)
        if (!isfinite(options->price[t]) || options->price[t] < 0)
            return facet_error_set(err, FACET_EINPUT,
                "price of %s %g USD/m^2 must be 0 or more",
                panel_type_name((enum panel_type)t), options->price[t]);
    if (!isfinite(options->max_gap) || options->max_gap < 0)
        return facet_error_set(err, FACET_EINPUT,
            "gap limit %g mm must be 0 (none) or more",
            units_mm(options->max_gap));
    if (!isfinite(options->max_kink) || options->max_kink < 0)
        return facet_error_set(err, FACET_EINPUT,
            "kink limit %g degrees must be 0 (none) or more",
            units_deg(options->max_kink));
    if (!isfinite(options->min_panel_width) || options->min_panel_width < 0)
        return facet_error_set(err, FACET_EINPUT,
            "panel width limit %g m must be 0 (none) or more",
            options->min_panel_width);
    if (!isfinite(options->max_panel_area) || options->max_panel_area <= 0)
        return facet_error_set(err, FACET_EINPUT,
            "maximum panel area %g m^2 must be more than 0",
            options->max_panel_area);
    double terms[2 + TYPE_COUNT] = {options->panel_cost, options->joint_cost,
                                    options->mould_cost[TYPE_FP],
                                    options->mould_cost[TYPE_SP],
                                    options->mould_cost[TYPE_DP]};
    static const char *const term_name[2 + TYPE_COUNT] = {
        "panel cost", "joint cost", "FP mould cost", "SP mould cost",
        "DP mould cost"};
    static const char *const term_unit[2 + TYPE_COUNT] = {
        "USD per panel", "USD/m", "USD", "USD", "USD"};
    for (int k = 0; k < 2 + TYPE_COUNT; k++)
        if (!isfinite(terms[k]) || terms[k] < 0)
            return facet_error_set(err, FACET_EINPUT,
                                   "%s %g %s must be 0 or more",
                                   term_name[k], terms[k], term_unit[k]);
    return FACET_OK;
}

/* Parses n comma-separated amounts (finite, 0 to CLASSIFY_AMOUNT_MAX) of
 * text into out. Returns 0, or -1 when text is not that. */
static int amounts_parse(const char *text, double *out, int n)
{
    const char *p = text;
    for (int k = 0; k < n; k++) {
        const char *end;
        if (numparse_double(p, p + strlen(p), &out[k], &end) != NUMPARSE_OK)
            end = p;
        while (*end == ' ')
            end++;
        if (end == p || !isfinite(out[k]) || out[k] < 0 ||
            out[k] > CLASSIFY_AMOUNT_MAX ||
            *end != (k + 1 < n ? ',' : '\0'))
            return -1;
        p = end + 1;
    }
    return 0;
}

int classify_mould_costs_parse(const char *text, const char *what,
                               double mould_cost[TYPE_COUNT],
                               struct facet_error *err)
{
    mould_cost[TYPE_FP] = 0;
    if (amounts_parse(text, &mould_cost[TYPE_SP], 2) != 0)
        return facet_error_set(err, FACET_EINPUT,
            "%s: '%s' is not SP,DP in USD per mould (e.g. 2000,15000)",
            what, text);
    return FACET_OK;
}

int classify_prices_parse(const char *text, const char *what,
                          double price[TYPE_COUNT], struct facet_error *err)
{
    if (amounts_parse(text, price, TYPE_COUNT) != 0)
        return facet_error_set(err, FACET_EINPUT,
            "%s: '%s' is not FP,SP,DP in USD/m^2 (e.g. "
            "701,766,1518)", what, text);
    return FACET_OK;
}

void classify_misfit_reason(const struct panelization *p, size_t panel,
                            char *text, size_t size)
{
    const struct panel *x = &p->panels[panel];
    /* One panel as sp_fit.h built it: its one wording of the reason. */
    struct built_panel built;
    memset(&built, 0, sizeof built);
    built.type = x->built;
    built.misfit = x->misfit;
    built.sp_deviation = x->sp_deviation;
    built.best_cylinder = x->best_cylinder;
    built.best_cone = x->best_cone;
    struct built_option option = {1, &built, 0, (size_t)x->misfit,
                                  p->threshold, 0};
    built_panel_reason(&option, 0, text, size);
}
