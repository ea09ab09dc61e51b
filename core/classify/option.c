/*
 * option.c: evaluating one design option. See option.h.
 */
#include "core/classify/option.h"

#include <string.h>

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
    classify_panels(panels, &params->classify, totals);
    return FACET_OK;
}
