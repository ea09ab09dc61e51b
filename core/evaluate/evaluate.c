/*
 * evaluate.c: one design option evaluated, stage by stage. See
 * evaluate.h.
 */
#include "core/evaluate/evaluate.h"

#include <assert.h>
#include <math.h>
#include <string.h>

#include "core/fit/sp_fit.h"
#include "core/joint/cell_sides.h"
#include "core/joint/joint.h"
#include "core/joint/joint_length.h"
#include "core/mould/mould.h"
#include "core/panel/panel_geometry.h"
#include "core/panel/panel_width.h"
#include "core/quantity/quantity.h"
#include "core/surface/coarse_mesh.h"

/* Tells shared's stage hook, if any, that stage what starts. */
static void stage(const struct evaluation_shared *shared, const char *what)
{
    if (shared->stage != NULL)
        shared->stage(shared->stage_context, what);
}

/* Builds the panels of params' grid over surface: from lattice when it
 * holds the grid and params ask for PANEL_EXTREMES, else panels_build_fast.
 * The checks every evaluation starts with come first. */
static int build_panels(const struct surface *surface,
                        const struct panel_lattice *lattice,
                        const struct option_params *params,
                        const struct facet_stop *stop,
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
        return panels_build_lattice_stoppable(lattice, params->nu,
                                              params->nv, stop, panels, err);
    return panels_build_fast_stoppable(&surface->panels, params->mode,
                                       params->nu, params->nv, stop, panels,
                                       err);
}

/* A limit of 0 is none: no joint is over it. */
static double limit_or_none(double limit)
{
    return limit > 0 ? limit : INFINITY;
}

/* Sets every panel's worst_gap_side from the joints of panels: the side
 * (panel.h's numbering) of its joint of the largest gap, the first of
 * equal ones. A joint's panel[0] is the left or lower one (joint.h). */
static void set_worst_sides(struct panelization *panels,
                            const struct joints *joints)
{
    for (size_t k = 0; k < panels->npanels; k++)
        panels->panels[k].worst_gap_side = -1;
    size_t u_sides = (size_t)(panels->nu + 1) * (size_t)panels->nv;
    for (size_t e = 0; e < joints->nedges; e++) {
        const struct joint_edge *edge = &joints->edges[e];
        int across_u = edge->side < u_sides;
        for (int s = 0; s < 2; s++) {
            struct panel *panel = &panels->panels[edge->panel[s]];
            double best = joints->worst_gap[edge->panel[s]];
            if (panel->worst_gap_side >= 0 || edge->gap < best)
                continue;
            panel->worst_gap_side = across_u ? (s == 0 ? 1 : 3)
                                             : (s == 0 ? 2 : 0);
        }
    }
}

/* Sets what build_and_measure would without fits or joints: every panel
 * built as typed, its fit and joints not known; the totals summed and
 * their as-built counts and joints not known. */
static void leave_unbuilt(const struct classify_options *options,
                          struct panelization *panels,
                          struct option_totals *totals)
{
    static const struct built_panel unbuilt;  /* fitted 0: no surface */
    for (size_t k = 0; k < panels->npanels; k++) {
        struct panel *panel = &panels->panels[k];
        panel->built = panel->type;
        panel->misfit = 0;
        panel->sp_deviation = NAN;
        panel->best_cylinder = NAN;
        panel->best_cone = NAN;
        panel->worst_gap = NAN;
        panel->worst_gap_side = -1;
        panel->worst_kink = NAN;
        built_panel_describe(&unbuilt, panel->centroid, &panel->sp_fit);
    }
    classify_totals(panels, options, totals);
    quantity_totals_forget(totals, OPTION_MEASURE_FITS | OPTION_MEASURE_JOINTS);
    totals->feasible =
        classify_violation(totals, options->max_panel_area) == 0;
}

/* Builds the classified panels as built (sp_fit.h): each panel's built
 * type, misfit and deviation from its fit, the misfits retyped DP unless
 * the options type SP by class alone; then prices them and sums *totals
 * (classify_totals) and measures the joints of the panels as built
 * (joint.h) into the panels' worst gap and kink and the totals, and how
 * many it measured into *measured. With fits, the grid's SP fits and
 * sides kept across its thresholds (sp_fit.h's grid_fits) serve, to the
 * same results. */
static int build_and_measure(const struct surface *surface,
                             const struct classify_options *options,
                             unsigned unmeasured, struct grid_fits *fits,
                             const struct facet_stop *stop,
                             struct panelization *panels,
                             struct option_totals *totals,
                             size_t *measured, struct facet_error *err)
{
    /* Joints are measured on the panels as built: no fits, no joints. */
    assert(!(unmeasured & OPTION_MEASURE_FITS) ||
           (unmeasured & OPTION_MEASURE_JOINTS));
    if (unmeasured & OPTION_MEASURE_FITS) {
        assert(options->sp_by_class);
        leave_unbuilt(options, panels, totals);
        *measured = 0;
        return FACET_OK;
    }
    struct cell_sides sides;
    struct built_option built;
    struct joints joints;
    memset(&sides, 0, sizeof sides);
    memset(&built, 0, sizeof built);
    memset(&joints, 0, sizeof joints);
    int rc;
    /* Facets that sag a fair part of t would be measured as the panels'
     * own deviation: the fits are then measured on the smooth surface. */
    int smooth = facet_sag_matters(surface->facet_sag, options->threshold);
    int measure_joints = !(unmeasured & OPTION_MEASURE_JOINTS);
    if (fits != NULL) {
        /* The sides are the grid's, borrowed: not freed here. */
        rc = grid_fits_option_stoppable(fits, panels, options->threshold,
                                        smooth, stop, &built, &sides, err);
    } else {
        /* Without joints, the fits alone read the sides: the SP panels'
         * points, sampled alone. */
        if (measure_joints)
            rc = cell_sides_sample_stoppable(&surface->mesh, &surface->uv,
                                             &surface->curvature, panels,
                                             stop, &sides, err);
        else
            rc = cell_sides_sample_fits_stoppable(&surface->mesh,
                                                  &surface->uv,
                                                  &surface->curvature,
                                                  panels, smooth, stop,
                                                  &sides, err);
        if (rc == FACET_OK)
            rc = built_option_fit_stoppable(&surface->mesh, &surface->fit,
                                            panels, &sides,
                                            options->threshold, smooth, stop,
                                            &built, err);
    }
    if (rc == FACET_OK && measure_joints)
        rc = joints_measure_stoppable(panels, &built, &sides,
                                      limit_or_none(options->max_gap),
                                      limit_or_none(options->max_kink), stop,
                                      &joints, err);
    if (rc == FACET_OK) {
        for (size_t k = 0; k < panels->npanels; k++) {
            struct panel *panel = &panels->panels[k];
            const struct built_panel *b = &built.panels[k];
            panel->built = b->type;
            panel->misfit = b->misfit;
            panel->sp_deviation = b->sp_deviation;
            panel->best_cylinder = b->best_cylinder;
            panel->best_cone = b->best_cone;
            built_panel_describe(b, panel->centroid, &panel->sp_fit);
            panel->worst_gap = measure_joints ? joints.worst_gap[k] : NAN;
            panel->worst_kink = measure_joints ? joints.worst_kink[k] : NAN;
            if (b->misfit && !options->sp_by_class)
                panel->type = TYPE_DP;
        }
        if (measure_joints) {
            set_worst_sides(panels, &joints);
        } else {
            for (size_t k = 0; k < panels->npanels; k++)
                panels->panels[k].worst_gap_side = -1;
        }
        classify_totals(panels, options, totals);
        totals->sp_misfits = built.sp_misfits;
        totals->sp_fitted = built.sp_fitted;
        totals->sp_min_radius = NAN;
        for (size_t k = 0; k < panels->npanels; k++)
            if (built.panels[k].fitted)
                totals->sp_min_radius = fmin(totals->sp_min_radius,
                                             built.panels[k].bending_radius);
        totals->max_gap = measure_joints ? joints.max_gap : NAN;
        totals->mean_gap = measure_joints ? joints.mean_gap : NAN;
        totals->max_kink = measure_joints ? joints.max_kink : NAN;
        totals->mean_kink = measure_joints ? joints.mean_kink : NAN;
        totals->gaps_over = measure_joints ? joints.gaps_over
                                           : TOTALS_UNKNOWN;
        totals->kinks_over = measure_joints ? joints.kinks_over
                                            : TOTALS_UNKNOWN;
        *measured = joints.nedges;
        totals->feasible =
            classify_violation(totals, options->max_panel_area) == 0;
    }
    joints_free(&joints);
    built_option_free(&built);
    if (fits == NULL)
        cell_sides_free(&sides);
    return rc;
}

/* Every panel's width (panel_width.h) from its outline, or NaN when
 * widths are not measured: it depends on the grid alone, so the grid's
 * first evaluation sets it and its other thresholds keep it. */
static int measure_widths(const struct surface *surface, unsigned unmeasured,
                          const struct facet_stop *stop,
                          struct panelization *panels,
                          struct facet_error *err)
{
    if (unmeasured & OPTION_MEASURE_WIDTHS) {
        for (size_t k = 0; k < panels->npanels; k++)
            panels->panels[k].width = NAN;
        return FACET_OK;
    }
    struct panel_geometry geometry;
    int rc = panel_geometry_build_stoppable(&surface->mesh, &surface->uv,
                                            panels, stop, &geometry, err);
    if (rc == FACET_OK)
        rc = facet_stop_check(stop, err);
    if (rc == FACET_OK)
        rc = panel_widths_set_stoppable(&geometry, panels, stop, err);
    panel_geometry_free(&geometry);
    return rc;
}

/* The smallest width of panels and the slivers, the panels narrower than
 * the limit (rounding allowed, CLASSIFY_ROUNDING: a 0.5 m panel measured
 * a hair under meets a 0.5 m limit), into totals, and the option's
 * feasibility again; nothing when widths are not measured. */
static void count_slivers(const struct classify_options *options,
                          unsigned unmeasured,
                          const struct panelization *panels,
                          struct option_totals *totals)
{
    if (unmeasured & OPTION_MEASURE_WIDTHS)
        return;
    totals->min_panel_width = NAN;
    totals->slivers = 0;
    for (size_t k = 0; k < panels->npanels; k++) {
        double width = panels->panels[k].width;
        totals->min_panel_width = k == 0 ? width
                                         : fmin(totals->min_panel_width,
                                                width);
        if (options->min_panel_width > 0 &&
            width * (1 + CLASSIFY_ROUNDING) < options->min_panel_width)
            totals->slivers++;
    }
    totals->feasible =
        classify_violation(totals, options->max_panel_area) == 0;
}

/* The stages after the panels: classifies and types them, builds and
 * measures them (build_and_measure), then finds their mould families
 * unless shared->unmoulded, and prices it all, the joint length given. */
static int classify_and_build(const struct surface *surface,
                              const struct option_params *params,
                              const struct evaluation_shared *shared,
                              double joint_length, int typed,
                              struct panelization *panels,
                              struct option_totals *totals,
                              struct facet_error *err)
{
    memset(totals, 0, sizeof *totals);
    size_t measured = 0;
    if (shared->joints != NULL)
        *shared->joints = 0;
    int rc = classify_check_options(&params->classify, err);
    if (rc == FACET_OK)
        rc = facet_stop_check(shared->stop, err);
    if (rc != FACET_OK)
        return rc;
    if (typed)
        panels->threshold = params->classify.threshold;
    else
        classify_types(panels, &params->classify);
    stage(shared, "fitting panels, measuring joints");
    rc = build_and_measure(surface, &params->classify, params->unmeasured,
                           shared->fits, shared->stop, panels, totals,
                           &measured, err);
    if (shared->joints != NULL)
        *shared->joints = measured;
    if (rc != FACET_OK)
        return rc;
    count_slivers(&params->classify, params->unmeasured, panels, totals);
    for (size_t k = 0; k < panels->npanels; k++)
        panels->panels[k].mould = -1;
    totals->joint_length = joint_length;
    classify_price_terms(&params->classify, totals);
    if (shared->unmoulded)
        return FACET_OK;
    if (params->unmeasured & OPTION_MEASURE_MOULDS) {
        /* An FP panel needs no mould: 0 is known without measuring. */
        quantity_totals_forget(totals, OPTION_MEASURE_MOULDS);
        totals->moulds_of[TYPE_FP] = 0;
        classify_price_terms(&params->classify, totals);
        return FACET_OK;
    }
    if ((rc = facet_stop_check(shared->stop, err)) != FACET_OK)
        return rc;
    stage(shared, "finding the mould families");
    struct mould_options mould = option_mould_options(params);
    mould.stop = shared->stop;
    struct mould_families families;
    rc = mould_families_build(&surface->mesh, &surface->uv, panels, &mould,
                              &families, err);
    if (rc == FACET_OK)
        option_moulds_set(params, &families, 0, panels, totals);
    mould_families_free(&families);
    return rc;
}

int option_evaluate(const struct surface *surface,
                    const struct option_params *params,
                    const struct evaluation_shared *shared,
                    struct panelization *panels,
                    struct option_totals *totals, struct facet_error *err)
{
    static const struct evaluation_shared nothing_shared;
    if (shared == NULL)
        shared = &nothing_shared;
    if (shared->again) {
        /* The grid's panels and fits, kept from its first threshold. */
        assert(shared->fits != NULL);
        return classify_and_build(surface, params, shared,
                                  shared->joint_length, 0, panels, totals,
                                  err);
    }
    if (shared->fits != NULL)
        memset(shared->fits, 0, sizeof *shared->fits);
    stage(shared, "building the panels");
    int rc = facet_stop_check(shared->stop, err);
    if (rc == FACET_OK)
        rc = build_panels(surface, shared->lattice, params, shared->stop,
                          panels, totals, err);
    if (rc == FACET_OK)
        rc = facet_stop_check(shared->stop, err);
    if (rc == FACET_OK) {
        stage(shared, "measuring the panels' widths");
        rc = measure_widths(surface, params->unmeasured, shared->stop,
                            panels, err);
    }
    if (rc == FACET_OK)
        rc = facet_stop_check(shared->stop, err);
    if (rc != FACET_OK)
        return rc;
    if (shared->fits != NULL && !(params->unmeasured & OPTION_MEASURE_FITS)) {
        rc = grid_fits_init_stoppable(&surface->mesh, &surface->uv,
                                      &surface->curvature, &surface->fit,
                                      panels, shared->stop, shared->fits,
                                      err);
        if (rc != FACET_OK)
            return rc;
    }
    double joint_length = NAN;
    if (!(params->unmeasured & OPTION_MEASURE_JOINT_LENGTH)) {
        stage(shared, "measuring the joint lines");
        rc = joint_length_lines_stoppable(shared->lines, &surface->joints,
                                          &surface->mesh, &surface->uv,
                                          panels, shared->stop,
                                          &joint_length, err);
        if (rc != FACET_OK)
            return rc;
    }
    return classify_and_build(surface, params, shared, joint_length, 0,
                              panels, totals, err);
}

int option_evaluate_typed(const struct surface *surface,
                          const struct option_params *params,
                          double joint_length, struct panelization *panels,
                          struct option_totals *totals,
                          struct facet_error *err)
{
    static const struct evaluation_shared nothing_shared;
    return classify_and_build(surface, params, &nothing_shared,
                              joint_length, 1, panels, totals, err);
}
