/*
 * pareto.h: Pareto dominance on sets of objective vectors.
 *
 * Pure computation on caller-owned arrays: non-dominated sorting (ranks),
 * crowding distance, NSGA-II survivor selection, exact hypervolume,
 * normalisation and the knee of a front. No I/O, no globals. Every
 * objective is minimised.
 *
 * Shapes: objectives is n x m, row-major (point i's objective j is
 * objectives[i * m + j]); violation, rank and crowding have n entries.
 *
 * Ties: every function but the hypervolume first merges each objective's
 * tie classes over the n points it is given (ties.h: values within a
 * billionth of the objective's range, or of its largest magnitude, are
 * equal), so that rounding never decides dominance, duplicates, crowding,
 * selection or the knee. The hypervolume measures what it is given.
 *
 * Dominance: a dominates b when a is no worse in every objective and
 * better in at least one (after merging ties). Identical points do not
 * dominate each other, so duplicates (points equal in every objective, to
 * the tolerance) always share a rank.
 *
 * Constraint-domination (Deb et al. 2002): with a violation array
 * (>= 0, 0 = feasible), a dominates b when a is feasible and b is not;
 * or both are infeasible and a's violation is smaller; or both are
 * feasible and a dominates b. Infeasible points with equal violation share
 * a rank, whatever their objectives.
 *
 * Errors: FACET_EINPUT for m == 0, a NaN objective or violation, a negative
 * violation, or a bad rank array; FACET_EWORK when out of memory.
 */
#ifndef FACET_PARETO_H
#define FACET_PARETO_H

#include <stddef.h>

#include "core/base/error.h"

/* The reference point of pareto_hypervolume_normalized, on every axis. */
#define PARETO_NORMALIZED_REFERENCE 1.1

/* Non-dominated sorting. rank[i] becomes the front of point i: 1 for the
 * points no other point dominates, 2 for those dominated only by front 1,
 * and so on (1 + the largest rank of the points dominating it). violation
 * may be NULL (all feasible). *nfronts (if not NULL) becomes the number of
 * fronts, 0 for n == 0. n must be below INT_MAX.
 *
 * Time, for u distinct points: O(n log n) to sort and merge duplicates,
 * then O(u) for m = 1, O(u log u) for m = 2 (one sweep with a binary
 * search over the fronts' lowest second objective), O(u log^2 u) for m = 3
 * (divide and conquer on the first objective, Fenwick tree of maxima on
 * the third), and for m >= 4 the Efficient Non-dominated Sort with binary
 * search over fronts (Zhang et al. 2015): O(m u^2) at worst, much less
 * when there are many fronts. Memory O(n). */
int pareto_rank(const double *objectives, size_t n, size_t m,
                const double *violation, int *rank, int *nfronts,
                struct facet_error *err);

/* Crowding distance (Deb et al. 2002) of every point within its front
 * (points of equal rank[i]). For each objective, the points of a front
 * are sorted by it; the two ends get +INFINITY and the others add the gap
 * between their neighbours divided by the front's range in that
 * objective (an objective with zero range adds nothing). A front of at
 * most two distinct points is all +INFINITY.
 *
 * Duplicates: identical points of a front are counted once, and every
 * copy gets the distance of that one point, so a copy neither inflates
 * nor hides its neighbours. Ties in one objective are broken by the other
 * objectives, then by index, so the result does not depend on the sort.
 * Crowding distances within TIES_RELATIVE of each other count as equal
 * wherever they are compared (selection, NSGA-II's tournament).
 * rank values must be >= 1 (as pareto_rank gives). */
int pareto_crowding(const double *objectives, size_t n, size_t m,
                    const int *rank, double *crowding,
                    struct facet_error *err);

/* NSGA-II survivor selection: the keep best of n points, by rank
 * (constraint-domination when violation is not NULL), whole fronts first.
 * The last front, which fits only in part, is pruned one point at a time:
 * the distinct point of least crowding distance goes (the highest index
 * among equals), and its neighbours' distances are updated before the
 * next removal (Kukkonen and Deb 2006; Deb 2002 cuts once by the
 * distances over the whole front, which leaves gaps where two close
 * points both go). Normalising ranges stay those of the whole front.
 * Copies of a point in that front are taken only after all its distinct
 * points, by larger crowding then lower index. selected (keep entries)
 * receives the chosen indices in increasing order. keep must be <= n.
 * Time O(n log n) plus O(k^2) for a last front of k points. */
int pareto_select(const double *objectives, size_t n, size_t m,
                  const double *violation, size_t keep, size_t *selected,
                  struct facet_error *err);

/* Exact hypervolume of the region dominated by the points and bounded by
 * reference (m entries): the Lebesgue measure of the union of the boxes
 * [p, reference]. Points that do not strictly dominate the reference
 * (some p_j >= reference_j) are ignored; dominated points and duplicates
 * add nothing. The result goes to *volume (0 for no point).
 *
 * Time: O(n log n) for m = 2 (sort and sweep); O(n^2) worst case for
 * m = 3 (sweep over the third objective keeping the 2-D staircase of
 * the points below, each insertion O(log n) search plus an O(n) shift);
 * for m >= 4 slicing along the last objective (HSO), O(n^(m-1)): meant for
 * fronts of up to a few hundred points. */
int pareto_hypervolume(const double *objectives, size_t n, size_t m,
                       const double *reference, double *volume,
                       struct facet_error *err);

/* Scales every objective to [0, 1] by the given ideal (maps to 0) and
 * nadir (maps to 1) points, m entries each: out[i*m+j] =
 * (objectives[i*m+j] - ideal[j]) / (nadir[j] - ideal[j]). An objective
 * with nadir[j] == ideal[j] maps to 0. Values outside [ideal, nadir] map
 * outside [0, 1]. out (n x m, caller-owned) may alias objectives. */
void pareto_normalize(const double *objectives, size_t n, size_t m,
                      const double *ideal, const double *nadir, double *out);

/* Hypervolume after pareto_normalize, with the reference point
 * PARETO_NORMALIZED_REFERENCE (1.1) on every axis: the usual choice, which
 * lets the extreme points of a front contribute. The result is in
 * normalised units, at most 1.1^m. */
int pareto_hypervolume_normalized(const double *objectives, size_t n,
                                  size_t m, const double *ideal,
                                  const double *nadir, double *volume,
                                  struct facet_error *err);

/* The knee of the first front: among the points with rank[i] == 1, the
 * one closest (Euclidean) to the ideal point after normalising each
 * objective by the front's own minimum (0) and maximum (1), the "closest
 * to ideal" compromise. Ties (distances within TIES_RELATIVE) go to the
 * lower index. *knee becomes that
 * index. FACET_EINPUT when no point has rank 1 (n == 0). */
int pareto_knee(const double *objectives, size_t n, size_t m,
                const int *rank, size_t *knee, struct facet_error *err);

#endif
