/*
 * evaluation_stages.c: an option evaluated up to a stage. See
 * evaluation_stages.h.
 */
#include "tests/support/evaluation_stages.h"

#include "core/mould/mould.h"

int evaluation_stage_run(const struct surface *surface,
                         const struct panel_lattice *lattice,
                         const struct joint_lines *lines,
                         const struct option_params *params,
                         enum evaluation_stage stage,
                         struct option_totals *totals,
                         struct facet_error *err)
{
    struct panelization panels;
    int rc = panels_build_lattice(lattice, params->nu, params->nv, &panels,
                                  err);
    if (rc != FACET_OK)
        return rc;
    classify_panels(&panels, &params->classify, totals);
    if (stage == STAGE_MOULDS) {
        totals->joint_length = joint_length_lines(lines, &surface->joints,
                                                  &surface->mesh,
                                                  &surface->uv, &panels);
        struct mould_options mould = option_mould_options(params);
        struct mould_families families;
        rc = mould_families_build(&surface->mesh, &surface->uv, &panels,
                                  &mould, &families, err);
        if (rc == FACET_OK)
            totals->moulds = families.nfamilies;
        mould_families_free(&families);
    }
    panelization_free(&panels);
    return rc;
}
