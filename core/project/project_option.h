/*
 * project_option.h: one design option evaluated over a whole building.
 *
 * An option over a project is a grid per surface (project_grids.h: from
 * the building's module, or given) and the option's other settings
 * (option_params: the threshold, prices, limits, mould settings; its own
 * nu x nv is not read). Its evaluation:
 *
 *   1. evaluates every surface as a single surface is (evaluate.h:
 *      option_evaluate, unmoulded, with that surface's grid: panels,
 *      classification, panels as built, gaps and kinks at its joints,
 *      joint length), the surfaces split across threads, each surface one
 *      piece of work with its own panels and totals;
 *   2. finds the mould families once over every SP and DP panel of the
 *      building (mould_families_build_parts): a mould serves congruent
 *      panels of any surface, so the families are shared, and the panels
 *      are taken in surface order, then panel order;
 *   3. gives each surface its panels' families (option_moulds_set) and sums
 *      the building's totals.
 * Nothing depends on the number of threads: each surface's work is its
 * own, and everything that combines surfaces runs in surface order on one
 * thread, so the numbers are the same to the bit whatever `jobs` is.
 *
 * A surface's totals are its panels' as a single surface's would be
 * (areas, counts, costs by area, panel and joint, deviation, gaps, kinks,
 * feasibility against the limits), except the moulds: moulds, moulds_of,
 * largest_family and singleton_families count the families it starts (a
 * family starts at its first panel in the building's order), and its
 * mould_cost prices those. So every family is counted and priced on
 * exactly one surface, and the surfaces' mould counts add up to the
 * building's; the families a surface's panels use (some started on an
 * earlier surface) are moulds_used. A project of one surface is that
 * surface's option_evaluate, to the bit.
 *
 * The building's totals:
 *   - sums over the surfaces: panels and every count (per type, per class,
 *     SP misfits and fits, gaps and kinks over their limits), and
 *     the areas (per type, per class, in all), planarity, P_dist and the
 *     joint length, each an order-free sum (exact_sum.h) of the surfaces'
 *     values;
 *   - maxima over the surfaces: the largest deviation, panel area, gap
 *     and kink;
 *   - the mean gap and mean kink: the mean over every joint of the
 *     building, each surface's mean weighted by its share of the joints
 *     (sum of joints_s / joints x mean_s, in surface order), 0 without
 *     joints;
 *   - the moulds from the shared families (not the sum of what each
 *     surface would need on its own): moulds, moulds_of, largest_family,
 *     singleton_families;
 *   - the cost priced once from those (classify_price_areas on the summed
 *     areas, classify_price_terms on the panels, joint length and
 *     moulds), so equal areas cost the same to the bit;
 *   - feasible when the whole building is: its largest panel within the
 *     size limit and no joint of any surface over the gap or kink limit.
 * The joints measured are those inside each surface and, once the
 * project keeps its seams (project_seams_keep) and the option measures
 * joints, those at the seams where two surfaces meet (project_seams.h):
 * the building's seam totals (seams .. seam_kinks_over: NaN and
 * TOTALS_UNKNOWN otherwise), and each seam joint taken into the
 * building's max and mean gap and kink and its gaps and kinks over the
 * limits, its kink as what the panels add to the design's crease (a
 * 90 degree corner is not a defect), so into its feasibility too.
 *
 * Memory: the panels of every surface are kept, with the building's
 * families (about 370 bytes a panel), and the mould search holds about
 * 1.9 KB a panel while it runs: the skin's 50,000 panels add under 100 MB
 * to its prepared project (tests/bench/bench_project.c).
 */
#ifndef FACET_PROJECT_OPTION_H
#define FACET_PROJECT_OPTION_H

#include <stddef.h>

#include "core/base/error.h"
#include "core/evaluate/option.h"
#include "core/mould/mould.h"
#include "core/project/project.h"
#include "core/project/project_grids.h"

/* One surface's part of an option over a project. */
struct project_surface_option {
    struct surface_grid grid;     /* its nu x nv */
    struct panelization panels;   /* its panels, as option_evaluate's; each
                                     panel's mould is its family in the
                                     building's numbering (families) */
    struct option_totals totals;  /* its totals, its moulds those it starts
                                     (above) */
    size_t moulds_used;           /* families its panels belong to */
    size_t moulds_used_of[TYPE_COUNT];  /* the same per type (FP: 0) */
    size_t joints;                /* joints measured: the count its mean
                                     gap and kink are over */
};

struct project_option {
    size_t nsurfaces;
    struct project_surface_option *surfaces;  /* owned, nsurfaces, in the
                                                 project's order */
    struct option_totals totals;  /* the building's (above) */
    size_t joints;                /* joints measured, over every surface */
    size_t seam_joints;           /* joints measured at its seams */
    struct mould_families families;  /* the building's families, over the
        panels of every surface in order (surface i's panel k is number
        first_panel(i) + k, first_panel the panels of the surfaces before
        it), owned */
};

/* Evaluates params with surface i's grid grids[i] (i < project->nsurfaces,
 * each side 1..PANEL_MAX_GRID) over project, prepared (project_prepare),
 * on up to jobs threads (1..PARALLEL_MAX), into *out (caller-owned,
 * released with project_option_free, also after a failure). Returns
 * FACET_OK, FACET_EINPUT for a bad grid or option value, FACET_EWORK when
 * out of memory, with err naming the first surface, in project order,
 * that failed. */
int project_option_evaluate(const struct project *project,
                            const struct surface_grid *grids,
                            const struct option_params *params, int jobs,
                            struct project_option *out,
                            struct facet_error *err);

/* project_option_evaluate, asking stop inside every surface's stages and
 * the building's mould families (evaluate.h, mould.h): also FACET_ESTOP
 * (stop.h) when it asks. */
int project_option_evaluate_stoppable(const struct project *project,
                                      const struct surface_grid *grids,
                                      const struct option_params *params,
                                      int jobs,
                                      const struct facet_stop *stop,
                                      struct project_option *out,
                                      struct facet_error *err);

void project_option_free(struct project_option *option);

#endif
