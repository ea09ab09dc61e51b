/*
 * front.h: the Pareto analysis of a run's options.
 *
 * Ranks every option by constraint-domination (Deb et al. 2002: feasible
 * options before infeasible ones, infeasible ones by how far they exceed
 * the panel size limit), computes crowding distances per front, the exact
 * hypervolume of the first front in normalised objective space, and the
 * knee option. The numbers a designer sees about the front come from here.
 * Objective values equal but for rounding are equal throughout (ties.h:
 * the tolerance of each objective over the run's options).
 */
#ifndef FACET_FRONT_H
#define FACET_FRONT_H

#include <stddef.h>

#include "core/search/metric.h"
#include "core/search/optimize.h"

struct front {
    size_t n;
    int *rank;              /* n: 1 = Pareto-optimal */
    double *crowding;       /* n: crowding distance within its front */
    size_t knee;            /* index of the knee option, or SIZE_MAX */
    double hypervolume;     /* of rank 1, objectives normalised to [0, 1]
                               over the run's options, reference point 1.1
                               on every axis; NaN with no feasible option */
    size_t pareto;          /* options of rank 1 */
};

/* Analyses options[0..n) under the objectives (nobjectives in
 * 1..OBJECTIVES_MAX, asserted), with max_panel_area the feasibility limit
 * (m^2). Fills *out (release with front_free). */
int front_analyse(const struct evaluated_option *options, size_t n,
                  const struct objective *objectives, int nobjectives,
                  double max_panel_area, struct front *out,
                  struct facet_error *err);

void front_free(struct front *front);

#endif
