/*
 * evaluate.h: one design option evaluated: the one function that turns
 * design variables into the numbers a designer compares, used alike by
 * `facet classify`, the optimiser, a building's surfaces and the panels
 * of an option a designer opens.
 *
 * An evaluation panelizes a prepared surface (surface_prepare) at the
 * option's grid, then, in this order:
 *   1. classifies and types the panels (classify.h);
 *   2. builds them as a fabricator would (sp_fit.h): an SP panel on a
 *      fitted cylinder or cone; one that none fits within the threshold
 *      (a misfit) is built and typed DP, unless the classify options
 *      type SP by class alone (the paper's typing: sp_by_class);
 *   3. measures the gap and the kink at every joint of the panels as
 *      built (joint.h), against the gap and kink limits (feasibility);
 *   4. finds the mould families of the curved panels (mould.h);
 *   5. prices it all, the joint length (joint_length.h) included.
 * The stages a run does not need are the option's params->unmeasured
 * (option.h's option_measure): each one left out leaves its quantities
 * not known, never 0, and every other number as it would be.
 *
 * Work shared across options (a search's lattice of panels, its joint
 * lines, a grid's SP fits kept across its thresholds) changes no number,
 * to the bit: tests/unit/test_optimize.c and test_cost_fast.c hold the
 * shared evaluations to the plain one.
 */
#ifndef FACET_EVALUATE_H
#define FACET_EVALUATE_H

#include <stddef.h>

#include "core/base/stop.h"
#include "core/evaluate/option.h"
#include "core/panel/panel_lattice.h"
#include "core/surface/surface.h"

struct joint_lines;
struct grid_fits;

/* What an evaluation may take from work its caller shares across
 * options, and how far it goes; a zeroed struct (or NULL): nothing shared,
 * every stage. Nothing here is owned by the evaluation. */
struct evaluation_shared {
    /* The panels of the grids lattice holds, taken from it when params
     * ask for PANEL_EXTREMES (the same panels, to rounding, in a fraction
     * of the time); NULL: none. */
    const struct panel_lattice *lattice;
    /* The joint lines (joint_lines_build) the grid's are among: the same
     * joint length, to the bit, for a batch of grids that share lines;
     * NULL: measured on the grid's own. */
    const struct joint_lines *lines;
    /* One grid at several thresholds: its SP fits and cell sides
     * (sp_fit.h's grid_fits), set up by the grid's first evaluation (again
     * 0: *fits is zeroed first, and released by the caller with
     * grid_fits_free, also after a failure) and reused by the others
     * (again 1), so that a panel's fits are made once, the first time it
     * is SP, and judged at each threshold. NULL: none kept. */
    struct grid_fits *fits;
    /* 1: panels already hold the grid's panels, from the evaluation that
     * set up fits, and joint_length is their joint length: they are only
     * classified, built and measured again at this option's threshold. */
    int again;
    double joint_length;
    /* 1: stop before the mould families: every panel's mould -1, the
     * totals' mould counts 0, priced without moulds. What a building's
     * surfaces take (core/project/project_option.h) before its families
     * are found over all of them at once (option_moulds_set). */
    int unmoulded;
    /* Receives the joints measured, the count the totals' mean gap and
     * kink are over, so that a building can weigh its surfaces' means (0
     * after a failure); NULL: not wanted. */
    size_t *joints;
    /* The caller's stop (core/base/stop.h), asked between the stages
     * and within each of them: every few thousand cells while the panels
     * are built and their widths measured, at every grid line measured
     * and every grid line of cell sides sampled, every row of joints,
     * every few hundred SP fits and mould panels. A 2000 x 2000 grid
     * takes tens of seconds, and a stop must be heard within a fraction
     * of one. NULL: never. */
    const struct facet_stop *stop;
    /* Told as each of the EVALUATION_STAGES stages starts, with its name
     * ("building the panels"), for a caller that shows one option's
     * progress (facet classify of 2000 x 2000 panels works for most of a
     * minute); NULL: not told. A stage left out is not told. */
    void (*stage)(void *context, const char *what);
    void *stage_context;
};

/* The stages evaluation_shared's stage hook may be told of: the panels,
 * their widths, the joint lines, the panels as built and their joints,
 * the mould families. */
#define EVALUATION_STAGES 5

/* Evaluates params on the prepared surface, with what shared holds (may
 * be NULL): fills *panels (caller-owned, released with panelization_free,
 * also after a failure; with shared->again it holds the grid's panels
 * already) and *totals. Returns FACET_OK, FACET_EINPUT for a bad grid or
 * option value, FACET_EWORK when out of memory or the surface is not
 * prepared, FACET_ESTOP when shared->stop fired (*totals then not valid). */
int option_evaluate(const struct surface *surface,
                    const struct option_params *params,
                    const struct evaluation_shared *shared,
                    struct panelization *panels,
                    struct option_totals *totals, struct facet_error *err);

/* The stages after classifying, for panels built and typed by their
 * caller (option_evaluate's, then changed: a planarized option's moved
 * quads, core/planar/planar_option.h): builds them as built (an SP
 * panel's fit), measures the joints, counts the slivers from the widths
 * they hold, finds the mould families and prices it all, the joint
 * length given: the very code every option's cost, gaps, kinks and
 * moulds come from. params->unmeasured is honoured as by
 * option_evaluate. Fills *totals; same returns. */
int option_evaluate_typed(const struct surface *surface,
                          const struct option_params *params,
                          double joint_length, struct panelization *panels,
                          struct option_totals *totals,
                          struct facet_error *err);

#endif
