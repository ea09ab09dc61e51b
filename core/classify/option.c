/*
 * option.c: evaluating one design option. See option.h.
 */
#include "core/classify/option.h"

#include <string.h>

#include "core/joint/joint_length.h"
#include "core/mould/mould.h"

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
    params.classify.threshold = threshold_mm / 1000;
    return params;
}

int option_evaluate(const struct surface *surface,
                    const struct option_params *params,
                    struct panelization *panels,
                    struct option_totals *totals, struct facet_error *err)
{
    return option_evaluate_lattice(surface, NULL, params, panels, totals,
                                   err);
}

int option_evaluate_lattice(const struct surface *surface,
                            const struct panel_lattice *lattice,
                            const struct option_params *params,
                            struct panelization *panels,
                            struct option_totals *totals,
                            struct facet_error *err)
{
    return option_evaluate_shared(surface, lattice, NULL, params, panels,
                                  totals, err);
}

int option_evaluate_shared(const struct surface *surface,
                           const struct panel_lattice *lattice,
                           const struct joint_lines *lines,
                           const struct option_params *params,
                           struct panelization *panels,
                           struct option_totals *totals,
                           struct facet_error *err)
{
    memset(panels, 0, sizeof *panels);
    memset(totals, 0, sizeof *totals);
    if (!surface->prepared)
        return facet_error_set(err, FACET_EWORK,
                               "option_evaluate: surface not prepared");
    int rc = classify_check_options(&params->classify, err);
    if (rc != FACET_OK)
        return rc;
    if (lattice != NULL && params->mode == PANEL_EXTREMES &&
        panel_lattice_has(lattice, params->nu, params->nv))
        rc = panels_build_lattice(lattice, params->nu, params->nv, panels,
                                  err);
    else
        rc = panels_build_fast(&surface->panels, params->mode, params->nu,
                               params->nv, panels, err);
    if (rc != FACET_OK)
        return rc;
    return option_classify(surface, params,
                           joint_length_lines(lines, &surface->joints,
                                              &surface->mesh, &surface->uv,
                                              panels),
                           panels, totals, err);
}

int option_classify(const struct surface *surface,
                    const struct option_params *params, double joints,
                    struct panelization *panels,
                    struct option_totals *totals, struct facet_error *err)
{
    memset(totals, 0, sizeof *totals);
    int rc = classify_check_options(&params->classify, err);
    if (rc != FACET_OK)
        return rc;
    classify_panels(panels, &params->classify, totals);
    struct mould_options mould = {
        params->mould_tol_given ? params->mould_tol
                                : params->classify.threshold,
        params->mould_mirror};
    struct mould_families families;
    rc = mould_families_build(&surface->mesh, &surface->uv, panels, &mould,
                              &families, err);
    if (rc == FACET_OK) {
        for (size_t k = 0; k < panels->npanels; k++)
            panels->panels[k].mould = families.family[k];
        for (int t = 0; t < TYPE_COUNT; t++)
            totals->moulds_of[t] = families.count[t];
        totals->moulds = families.nfamilies;
        totals->largest_family = families.largest;
        totals->singleton_families = families.singletons;
        totals->joint_length = joints;
        classify_price_terms(&params->classify, totals);
    }
    mould_families_free(&families);
    return rc;
}
