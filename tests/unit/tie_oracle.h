/*
 * tie_oracle.h: the brute force that ranks with ties, for the unit tests
 * (include after cmocka.h).
 *
 * Objective values equal but for rounding must compare equal
 * (core/search/ties.h):
 * tol_j = 1e-9 x max(range, largest magnitude) of objective j over the
 * points. The oracle is the pairwise rule, straight from that definition,
 * with the tolerance computed here on its own: a dominates b when
 * a_j <= b_j + tol_j for every j and a_j < b_j - tol_j for some j, under
 * constraint-domination; fronts are peeled one at a time in O(n^2). It
 * checks that the data keep every group of near-equal values more than
 * 2 tol from any other value, so that "within tol" is an equivalence there
 * and the pairwise rule and the implementation's tie classes must agree.
 */
#ifndef FACET_TIE_ORACLE_H
#define FACET_TIE_ORACLE_H

#include <math.h>
#include <stdbool.h>
#include <stdlib.h>

static inline void tie_tolerances(const double *f, size_t n, size_t m,
                                  double *tol)
{
    for (size_t j = 0; j < m; j++) {
        double low = INFINITY, high = -INFINITY, size = 0;
        for (size_t i = 0; i < n; i++) {
            low = fmin(low, f[i * m + j]);
            high = fmax(high, f[i * m + j]);
            size = fmax(size, fabs(f[i * m + j]));
        }
        tol[j] = n > 0 ? 1e-9 * fmax(high - low, size) : 0;
    }
}

/* Near-equal groups are tight: no two values lie between tol and 2 tol
 * apart, so "within tol" is an equivalence on the data. */
static inline void assert_groups_tight(const double *f, size_t n,
                                       size_t m, const double *tol)
{
    for (size_t j = 0; j < m; j++)
        for (size_t a = 0; a < n; a++)
            for (size_t b = 0; b < n; b++) {
                double d = fabs(f[a * m + j] - f[b * m + j]);
                assert_false(d > tol[j] && d <= 2 * tol[j]);
            }
}

static inline bool dominates_within(const double *f,
                                    const double *violation, size_t m,
                                    const double *tol, size_t a, size_t b)
{
    if (violation != NULL) {
        bool fa = violation[a] == 0, fb = violation[b] == 0;
        if (fa != fb)
            return fa;
        if (!fa)
            return violation[a] < violation[b];
    }
    bool better = false;
    for (size_t j = 0; j < m; j++) {
        if (f[a * m + j] > f[b * m + j] + tol[j])
            return false;
        if (f[a * m + j] < f[b * m + j] - tol[j])
            better = true;
    }
    return better;
}

/* Layered non-dominated sort under the pairwise tolerance rule, O(n^2)
 * per front. Fails if a layer comes out empty (a dominance cycle). */
static inline void brute_rank_within(const double *f,
                                     const double *violation, size_t n,
                                     size_t m, int *rank)
{
    double tol[8];
    tie_tolerances(f, n, m, tol);
    assert_groups_tight(f, n, m, tol);
    for (size_t i = 0; i < n; i++)
        rank[i] = 0;
    bool *in_front = malloc(n + 1);
    size_t left = n;
    for (int front = 1; left > 0; front++) {
        size_t added = 0;
        for (size_t i = 0; i < n; i++) {
            in_front[i] = false;
            if (rank[i] != 0)
                continue;
            bool dominated = false;
            for (size_t k = 0; k < n && !dominated; k++)
                dominated = rank[k] == 0 &&
                            dominates_within(f, violation, m, tol, k, i);
            in_front[i] = !dominated;
        }
        for (size_t i = 0; i < n; i++)
            if (in_front[i]) {
                rank[i] = front;
                added++;
            }
        assert_true(added > 0);
        left -= added;
    }
    free(in_front);
}

#endif
