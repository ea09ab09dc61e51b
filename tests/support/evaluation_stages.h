/*
 * evaluation_stages.h: one design option evaluated up to a stage of
 * option_evaluate (evaluate.h), for the benchmarks that time each
 * stage's cost against the stages before it: what a search paid per
 * option before the cost model (issue 15), and before panels as built
 * (issue 16).
 *
 * Test support, not part of Facet: tests/ links it, the binary does not.
 * The full evaluation is option_evaluate itself, not a stage here.
 */
#ifndef FACET_EVALUATION_STAGES_H
#define FACET_EVALUATION_STAGES_H

#include "core/evaluate/evaluate.h"
#include "core/joint/joint_length.h"

enum evaluation_stage {
    STAGE_CLASSES,  /* panels from the lattice, classified and priced by
                       area: the paper's evaluation */
    STAGE_MOULDS,   /* and the joint length and mould families of the
                       panels as classified: the cost model, before the
                       panels are built (no SP fit, gap or kink) */
};

/* Evaluates params on surface up to stage, the panels taken from lattice
 * (which must hold params' grid), the joint length from lines where they
 * hold the grid's (NULL: none; as a run measures them once); fills
 * *totals. Returns FACET_OK or the first error (err says which). */
int evaluation_stage_run(const struct surface *surface,
                         const struct panel_lattice *lattice,
                         const struct joint_lines *lines,
                         const struct option_params *params,
                         enum evaluation_stage stage,
                         struct option_totals *totals,
                         struct facet_error *err);

#endif
