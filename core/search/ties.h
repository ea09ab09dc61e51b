/*
 * ties.h: when two values of an objective are equal.
 *
 * A run's totals are sums over panels, and two options whose totals are
 * equal in exact arithmetic (a grid and its mirror image on a symmetric
 * surface) can differ in the last bits because their panels were summed
 * in another order. Compared exactly, the one that happens to round lower
 * dominates the other, or is kept as Pareto-optimal for 1e-9 USD. So every
 * comparison of objective values in Facet (dominance, duplicates,
 * crowding, the knee, the hypervolume's ranges, NSGA-II's tournament and
 * survivor selection, the sorting of printed tables) goes through the one
 * rule here:
 *
 *   Over a set of n points (a run's options, or the population NSGA-II
 *   ranks), objective j has the tolerance
 *       tol_j = TIES_RELATIVE x max(max_j - min_j, |v_j|max),
 *   a billionth of its range over the finite values of the set, or of its
 *   largest magnitude when that is larger: rounding noise is relative to
 *   the size of the sums, and a run whose options all cost the same but
 *   for rounding (a plane: every panel flat) has a range that is itself
 *   noise. Two values of objective j tie when they are within tol_j of
 *   each other; and so that "equal" stays transitive, a chain of values
 *   each within tol_j of the next ties as a whole (single linkage: sort
 *   the values, and a gap above tol_j starts a new tie class). A tie
 *   class is represented by its lowest value (ties_merge), after which
 *   comparisons are exact.
 *
 * Why classes and not "a_j <= b_j + tol_j": that pairwise rule is not a
 * partial order (with three objectives, a can dominate b, b dominate c
 * and c dominate a, each by a margin just over tol in one objective), and
 * non-dominated sorting needs one. When every class spans at most tol_j
 * (values that differ by rounding, far from any other value) the two rules
 * agree; the tests check both.
 *
 * Dimensionless numbers made from normalised objectives (crowding
 * distances, the knee's distance) tie when they differ by at most
 * TIES_RELATIVE: their unit is already the objective's range.
 *
 * Pure computation, no globals.
 */
#ifndef FACET_TIES_H
#define FACET_TIES_H

#include <stddef.h>

#include "core/base/error.h"

/* The relative tolerance: a fraction of an objective's range. */
#define TIES_RELATIVE 1e-9

/* TIES_RELATIVE x max(max - min, max |v|) over the finite values v among
 * values[k * stride], k < n; 0 when there is none. */
double ties_tolerance(const double *values, size_t n, size_t stride);

/* Replaces each of values[k * stride], k < n, by the lowest value of its
 * tie class under tolerance (>= 0) into out[k * stride]; out may alias
 * values. Infinite values tie only with themselves; NaN is not allowed.
 * Returns FACET_OK, or FACET_EWORK when out of memory (out untouched). */
int ties_merge_column(const double *values, size_t n, size_t stride,
                      double tolerance, double *out, struct facet_error *err);

/* ties_merge_column on every objective of the n x m row-major array, each
 * with its own ties_tolerance over the n points. out may alias
 * objectives. Returns FACET_OK or FACET_EWORK (out of memory). Idempotent:
 * merging merged values changes nothing. */
int ties_merge(const double *objectives, size_t n, size_t m, double *out,
               struct facet_error *err);

/* Orders two dimensionless numbers (normalised units): 0 when they differ
 * by at most TIES_RELATIVE (equal infinities tie), else -1 or 1 like
 * strcmp. */
int ties_compare_normalised(double a, double b);

/* Orders n rows by nkeys keys with ties: keys is n x nkeys row-major
 * (key k of row i at keys[i * nkeys + k]) and tolerance[k] the tolerance
 * of key k (0 for exact, e.g. an option's number). order (n entries)
 * receives the rows sorted by key 0's tie classes over the n rows (each
 * class read as its lowest value), then key 1's, and so on, then by row
 * index; descending reverses every comparison, the index's too. Keys
 * may be +-INFINITY; NaN is not allowed. Returns FACET_OK, or FACET_EWORK
 * when out of memory (order untouched). */
int ties_order(const double *keys, size_t n, size_t nkeys,
               const double *tolerance, int descending, size_t *order,
               struct facet_error *err);

#endif
