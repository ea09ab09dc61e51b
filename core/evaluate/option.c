/*
 * option.c: a design option's parameters and the measures it may leave
 * out. See option.h; its evaluation is evaluate.c.
 */
#include "core/evaluate/option.h"
#include "core/surface/coarse_mesh.h"

#include <assert.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "core/fit/sp_fit.h"
#include "core/joint/cell_sides.h"
#include "core/joint/joint.h"
#include "core/joint/joint_length.h"
#include "core/mould/mould.h"
#include "core/quantity/quantity.h"
#include "core/base/units.h"

struct mould_options option_mould_options(const struct option_params *params)
{
    struct mould_options mould = {
        .tolerance = params->mould_tol_given ? params->mould_tol
                                             : params->classify.threshold,
        .mirror = params->mould_mirror,
        /* Typed by class, as the paper does, an SP panel need not fit its
         * surface: the moulds are the paper's too. */
        .jigs = !params->classify.sp_by_class};
    return mould;
}

static const char *const measure_names[] = {"fits", "joints", "moulds",
                                            "joint_length", "widths"};
enum { MEASURE_NAMES = sizeof measure_names / sizeof *measure_names };

void option_measures_format(unsigned measures, char *out, size_t size)
{
    assert(size >= OPTION_MEASURES_TEXT);
    size_t len = 0;
    out[0] = '\0';
    for (int k = 0; k < MEASURE_NAMES; k++)
        if (measures & (1u << k))
            len += (size_t)snprintf(out + len, size - len, "%s%s",
                                    len ? "," : "", measure_names[k]);
}

unsigned option_measures_parse(const char *text)
{
    unsigned measures = 0;
    while (*text != '\0') {
        size_t length = strcspn(text, ",");
        int known = 0;
        for (int k = 0; k < MEASURE_NAMES; k++)
            if (strlen(measure_names[k]) == length &&
                strncmp(measure_names[k], text, length) == 0) {
                measures |= 1u << k;
                known = 1;
            }
        if (!known)
            return OPTION_MEASURE_ALL;
        text += length + (text[length] == ',');
    }
    return measures;
}

unsigned option_totals_measures(const struct option_totals *totals)
{
    unsigned measures = 0;
    if (totals->sp_fitted != TOTALS_UNKNOWN)
        measures |= OPTION_MEASURE_FITS;
    if (totals->gaps_over != TOTALS_UNKNOWN)
        measures |= OPTION_MEASURE_JOINTS;
    if (totals->moulds != TOTALS_UNKNOWN)
        measures |= OPTION_MEASURE_MOULDS;
    if (!isnan(totals->joint_length))
        measures |= OPTION_MEASURE_JOINT_LENGTH;
    if (totals->slivers != TOTALS_UNKNOWN)
        measures |= OPTION_MEASURE_WIDTHS;
    return measures;
}

void option_totals_fill(struct option_totals *t,
                        const struct option_totals *m)
{
    unsigned missing = ~option_totals_measures(t) & option_totals_measures(m);
    quantity_totals_copy(t, m, missing);
}

unsigned option_measures_needed(const struct classify_options *classify,
                                unsigned objective_measures)
{
    unsigned needed = objective_measures;
    if (classify->max_gap > 0 || classify->max_kink > 0)
        needed |= OPTION_MEASURE_JOINTS;
    if (classify->joint_cost != 0)
        needed |= OPTION_MEASURE_JOINT_LENGTH;
    if (classify->min_panel_width > 0)
        needed |= OPTION_MEASURE_WIDTHS;
    for (int t = 0; t < TYPE_COUNT; t++)
        if (classify->mould_cost[t] != 0)
            needed |= OPTION_MEASURE_MOULDS;
    /* Joints are measured on the panels as built; a type by fit is the
     * fit's verdict. */
    if (!classify->sp_by_class || (needed & OPTION_MEASURE_JOINTS))
        needed |= OPTION_MEASURE_FITS;
    return needed;
}

void option_params_defaults(struct option_params *params)
{
    memset(params, 0, sizeof *params);
    classify_defaults(&params->classify);
    params->mode = PANEL_EXTREMES;
}

struct option_params option_params_at(const struct option_params *base,
                                      int nu, int nv, double threshold_mm)
{
    struct option_params params = *base;
    params.nu = nu;
    params.nv = nv;
    params.classify.threshold = units_m_of_mm(threshold_mm);
    return params;
}

void option_moulds_set(const struct option_params *params,
                       const struct mould_families *families, size_t first,
                       struct panelization *panels,
                       struct option_totals *totals)
{
    assert(first + panels->npanels <= families->npanels);
    for (int t = 0; t < TYPE_COUNT; t++)
        totals->moulds_of[t] = 0;
    totals->moulds = 0;
    totals->largest_family = 0;
    totals->singleton_families = 0;
    for (size_t k = 0; k < panels->npanels; k++) {
        int f = families->family[first + k];
        panels->panels[k].mould = f;
        /* A family starts at its representative, its first panel. */
        if (f < 0 || families->representative[f] != first + k)
            continue;
        size_t size = families->size[f];
        totals->moulds_of[panels->panels[k].type]++;
        totals->moulds++;
        totals->largest_family = size > totals->largest_family
                                     ? size : totals->largest_family;
        totals->singleton_families += size == 1;
    }
    classify_price_terms(&params->classify, totals);
}
