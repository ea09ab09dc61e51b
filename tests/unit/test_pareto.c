/*
 * test_pareto.c: non-dominated sorting against a brute-force peeling of
 * fronts (with ties, duplicates and constraint violations, 1 to 5
 * objectives), the fast 2-D / 3-D rankers against the general one on large
 * sets, crowding distances against a hand computation, exact hypervolume
 * against counting unit cells on integer grids, normalisation, survivor
 * selection and the knee; and ties (values equal but for rounding, within
 * the tolerance of core/search/ties.h) against a brute force with the pairwise
 * tolerance rule, and against the unmoved values.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdbool.h>
#include <stdlib.h>
#include <string.h>

#include "core/search/pareto.h"
#include "core/base/rng.h"
#include "tie_oracle.h"

/* ---- oracles ------------------------------------------------------------- */

/* Constraint-domination, straight from its definition. */
static bool dominates(const double *f, const double *violation, size_t m,
                      size_t a, size_t b)
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
        if (f[a * m + j] > f[b * m + j])
            return false;
        if (f[a * m + j] < f[b * m + j])
            better = true;
    }
    return better;
}

/* Peels fronts: front r is every remaining point that no remaining point
 * dominates. O(n^3 m) at worst. Returns the number of fronts. */
static int brute_rank(const double *f, const double *violation, size_t n,
                      size_t m, int *rank)
{
    for (size_t i = 0; i < n; i++)
        rank[i] = 0;
    size_t left = n;
    int front = 0;
    bool *in_front = malloc(n + 1);
    while (left > 0) {
        front++;
        for (size_t i = 0; i < n; i++) {
            in_front[i] = false;
            if (rank[i] != 0)
                continue;
            bool dominated = false;
            for (size_t k = 0; k < n && !dominated; k++)
                dominated = rank[k] == 0 && dominates(f, violation, m, k, i);
            in_front[i] = !dominated;
        }
        for (size_t i = 0; i < n; i++)
            if (in_front[i]) {
                rank[i] = front;
                left--;
            }
    }
    free(in_front);
    return front;
}

/* Hypervolume of integer points by counting the unit cells of
 * [0, reference) that some point's box covers: cell c is covered by p
 * when p_j <= c_j on every axis. */
static double cell_volume(const double *f, size_t n, size_t m,
                          const int *reference)
{
    size_t cells = 1;
    for (size_t j = 0; j < m; j++)
        cells *= (size_t)reference[j];
    double count = 0;
    int cell[8];
    for (size_t c = 0; c < cells; c++) {
        size_t rest = c;
        for (size_t j = 0; j < m; j++) {
            cell[j] = (int)(rest % (size_t)reference[j]);
            rest /= (size_t)reference[j];
        }
        for (size_t i = 0; i < n; i++) {
            size_t j = 0;
            while (j < m && f[i * m + j] <= cell[j])
                j++;
            if (j == m) {
                count++;
                break;
            }
        }
    }
    return count;
}

/* n x m points with integer coordinates in [0, levels), so that ties and
 * duplicates are common, or uniform reals when levels == 0. */
static double *random_points(struct rng *rng, size_t n, size_t m, int levels)
{
    double *f = malloc((n * m + 1) * sizeof *f);
    for (size_t k = 0; k < n * m; k++)
        f[k] = levels > 0 ? (double)rng_below(rng, (uint64_t)levels)
                          : rng_uniform(rng);
    return f;
}

/* ---- ranks --------------------------------------------------------------- */

static void check_against_brute(struct rng *rng, size_t n, size_t m,
                                int levels, bool constrained)
{
    double *f = random_points(rng, n, m, levels);
    double *violation = NULL;
    if (constrained) {
        violation = malloc((n + 1) * sizeof *violation);
        for (size_t i = 0; i < n; i++)
            violation[i] = rng_below(rng, 3) == 0 ? 0.0
                           : (double)rng_below(rng, 4) * 0.5;
    }
    int *rank = malloc((n + 1) * sizeof *rank);
    int *expected = malloc((n + 1) * sizeof *expected);
    int fronts = -1;
    struct facet_error err;
    assert_int_equal(pareto_rank(f, n, m, violation, rank, &fronts, &err),
                     FACET_OK);
    int expected_fronts = n > 0 ? brute_rank(f, violation, n, m, expected) : 0;
    assert_int_equal(fronts, expected_fronts);
    for (size_t i = 0; i < n; i++)
        assert_int_equal(rank[i], expected[i]);
    free(f);
    free(violation);
    free(rank);
    free(expected);
}

static void test_rank_matches_brute_force(void **state)
{
    (void)state;
    struct rng rng;
    rng_seed(&rng, 2002);
    const size_t sizes[] = {0, 1, 2, 3, 7, 30, 64, 150};
    const int levels[] = {0, 2, 5, 20};
    for (size_t m = 1; m <= 5; m++)
        for (size_t s = 0; s < sizeof sizes / sizeof *sizes; s++)
            for (size_t l = 0; l < sizeof levels / sizeof *levels; l++) {
                check_against_brute(&rng, sizes[s], m, levels[l], false);
                check_against_brute(&rng, sizes[s], m, levels[l], true);
            }
}

/* The 3-D divide and conquer on a set large enough to recurse deeply. */
static void test_rank_three_medium_brute(void **state)
{
    (void)state;
    struct rng rng;
    rng_seed(&rng, 3);
    check_against_brute(&rng, 600, 3, 0, false);
    check_against_brute(&rng, 600, 3, 12, false);
    check_against_brute(&rng, 600, 2, 40, true);
}

/* A constant extra objective changes no dominance, so ranking with it
 * takes the next ranker's path and must agree: 2-D against 3-D, 3-D
 * against the general m >= 4 sort. */
static void compare_with_extra_objective(struct rng *rng, size_t n, size_t m,
                                         int levels)
{
    double *f = random_points(rng, n, m, levels);
    /* Anti-correlate the first two objectives so fronts are large. */
    for (size_t i = 0; i < n; i++)
        f[i * m + 1] = (levels > 0 ? levels : 1) - f[i * m] + f[i * m + 1];
    double *g = malloc(n * (m + 1) * sizeof *g);
    for (size_t i = 0; i < n; i++) {
        memcpy(g + i * (m + 1), f + i * m, m * sizeof *f);
        g[i * (m + 1) + m] = 7.0;
    }
    int *a = malloc(n * sizeof *a), *b = malloc(n * sizeof *b);
    int fa, fb;
    struct facet_error err;
    assert_int_equal(pareto_rank(f, n, m, NULL, a, &fa, &err), FACET_OK);
    assert_int_equal(pareto_rank(g, n, m + 1, NULL, b, &fb, &err), FACET_OK);
    assert_int_equal(fa, fb);
    for (size_t i = 0; i < n; i++)
        assert_int_equal(a[i], b[i]);
    free(f);
    free(g);
    free(a);
    free(b);
}

static void test_rank_paths_agree(void **state)
{
    (void)state;
    struct rng rng;
    rng_seed(&rng, 11);
    compare_with_extra_objective(&rng, 20000, 2, 0);
    compare_with_extra_objective(&rng, 20000, 2, 50);
    compare_with_extra_objective(&rng, 20000, 3, 0);
    compare_with_extra_objective(&rng, 20000, 3, 30);
}

/* 100,000 points in 3-D: sampled points obey the definition of rank (no
 * dominator of equal or higher rank, a dominator of rank - 1 unless 1). */
static void test_rank_large_three(void **state)
{
    (void)state;
    const size_t n = 100000, m = 3;
    struct rng rng;
    rng_seed(&rng, 5);
    double *f = random_points(&rng, n, m, 0);
    int *rank = malloc(n * sizeof *rank);
    int fronts;
    struct facet_error err;
    assert_int_equal(pareto_rank(f, n, m, NULL, rank, &fronts, &err),
                     FACET_OK);
    assert_true(fronts > 10);
    for (int s = 0; s < 100; s++) {
        size_t q = (size_t)rng_below(&rng, n);
        bool has_parent = rank[q] == 1;
        for (size_t p = 0; p < n; p++) {
            if (!dominates(f, NULL, m, p, q))
                continue;
            assert_true(rank[p] < rank[q]);
            if (rank[p] == rank[q] - 1)
                has_parent = true;
        }
        assert_true(has_parent);
    }
    free(f);
    free(rank);
}

static void test_rank_duplicates_share(void **state)
{
    (void)state;
    double f[] = {1, 1, 1, 1, 0, 2, 2, 2, 1, 1};
    int rank[5];
    int fronts;
    struct facet_error err;
    assert_int_equal(pareto_rank(f, 5, 2, NULL, rank, &fronts, &err),
                     FACET_OK);
    assert_int_equal(fronts, 2);
    assert_int_equal(rank[0], 1);
    assert_int_equal(rank[1], 1);
    assert_int_equal(rank[2], 1);
    assert_int_equal(rank[3], 2);
    assert_int_equal(rank[4], 1);
}

static void test_rank_rejects_bad_input(void **state)
{
    (void)state;
    double f[] = {1, 2, NAN, 0};
    double violation[] = {0, -1};
    int rank[2];
    struct facet_error err;
    assert_int_equal(pareto_rank(f, 2, 2, NULL, rank, NULL, &err),
                     FACET_EINPUT);
    assert_non_null(strstr(err.message, "point 1"));
    f[2] = 3;
    assert_int_equal(pareto_rank(f, 2, 2, violation, rank, NULL, &err),
                     FACET_EINPUT);
    assert_non_null(strstr(err.message, "violation of point 1"));
    assert_int_equal(pareto_rank(f, 2, 0, NULL, rank, NULL, &err),
                     FACET_EINPUT);
}

/* ---- crowding ------------------------------------------------------------ */

static void test_crowding_hand_computed(void **state)
{
    (void)state;
    /* Front 1: (0,6) (1,3) (3,2) (4,1) (6,0) and a copy of (3,2); ranges
     * 6 and 6. By f1: 0 1 3 4 6; by f2: (6,0) (4,1) (3,2) (1,3) (0,6).
     *   (1,3): (3-0)/6 + (6-2)/6 = 7/6
     *   (3,2): (4-1)/6 + (3-1)/6 = 5/6, and its copy the same
     *   (4,1): (6-3)/6 + (2-0)/6 = 5/6
     * Front 2: two points, both infinite. Front 3: three points on a
     * vertical line: f1 has zero range and adds nothing (its ends, by the
     * f2 tie-break, are still infinite), f2 adds (9-1)/(9-1) = 1. */
    double f[] = {0, 6, 1, 3, 3, 2, 4, 1, 6, 0, 3, 2,
                  7, 7, 8, 6,
                  9, 1, 9, 5, 9, 9};
    int rank[] = {1, 1, 1, 1, 1, 1, 2, 2, 3, 3, 3};
    double crowding[11];
    struct facet_error err;
    assert_int_equal(pareto_crowding(f, 11, 2, rank, crowding, &err),
                     FACET_OK);
    assert_true(isinf(crowding[0]) && isinf(crowding[4]));
    assert_true(fabs(crowding[1] - 7.0 / 6) < 1e-12);
    assert_true(fabs(crowding[2] - 5.0 / 6) < 1e-12);
    assert_true(fabs(crowding[3] - 5.0 / 6) < 1e-12);
    assert_true(crowding[5] == crowding[2]);
    assert_true(isinf(crowding[6]) && isinf(crowding[7]));
    assert_true(isinf(crowding[8]) && isinf(crowding[10]));
    assert_true(fabs(crowding[9] - 1.0) < 1e-12);

    /* All copies of one point: a front of one distinct point. */
    double same[] = {1, 1, 1, 1, 1, 1};
    int one[] = {1, 1, 1};
    assert_int_equal(pareto_crowding(same, 3, 2, one, crowding, &err),
                     FACET_OK);
    assert_true(isinf(crowding[0]) && isinf(crowding[1]) &&
                isinf(crowding[2]));
    int bad[] = {1, 0, 1};
    assert_int_equal(pareto_crowding(same, 3, 2, bad, crowding, &err),
                     FACET_EINPUT);
}

/* ---- survivor selection -------------------------------------------------- */

static void test_select_prunes_by_crowding(void **state)
{
    (void)state;
    /* Front 1: 0 and 1. Front 2: 2..6 and 7, a copy of 4; three of it
     * are kept, so two of its five distinct points go, one at a time, and
     * the copy never comes into it. Ranges 4 and 3.5; distances:
     *   3: (2.1-1)/4 + (5-3.8)/3.5 = 0.618   <- removed first
     *   4: (4-2)/4 + (3.9-2)/3.5   = 1.043
     *   5: (5-2.1)/4 + (3.8-1.5)/3.5 = 1.382
     * then 4's neighbours are 2 and 5: (4-1)/4 + (5-2)/3.5 = 1.607, so 5
     * goes. (Cutting once by the first distances would drop 3 and 4.) */
    double f[] = {0, 1, 1, 0,
                  1, 5, 2, 3.9, 2.1, 3.8, 4, 2, 5, 1.5, 2.1, 3.8};
    size_t selected[5];
    struct facet_error err;
    assert_int_equal(pareto_select(f, 8, 2, NULL, 5, selected, &err),
                     FACET_OK);
    size_t expected[] = {0, 1, 2, 4, 6};
    for (int k = 0; k < 5; k++)
        assert_int_equal(selected[k], expected[k]);

    /* Keeping all six distinct points takes the copy last. */
    size_t seven[7];
    assert_int_equal(pareto_select(f, 8, 2, NULL, 7, seven, &err), FACET_OK);
    for (int k = 0; k < 7; k++)
        assert_int_equal(seven[k], (size_t)k);

    /* Constraint-domination: the feasible point survives first. */
    double g[] = {0, 0, 5, 5, 1, 1};
    double violation[] = {0.5, 0, 0.1};
    assert_int_equal(pareto_select(g, 3, 2, violation, 2, selected, &err),
                     FACET_OK);
    assert_int_equal(selected[0], 1);
    assert_int_equal(selected[1], 2);
    assert_int_equal(pareto_select(g, 3, 2, violation, 4, selected, &err),
                     FACET_EINPUT);
}

static void test_select_prefers_distinct(void **state)
{
    (void)state;
    /* One front: five copies of (0,1), and (1,0), (0.5,0.5). Keeping 3
     * takes one copy and both other points. */
    double f[] = {0, 1, 0, 1, 0, 1, 0, 1, 0, 1, 1, 0, 0.5, 0.5};
    size_t selected[3];
    struct facet_error err;
    assert_int_equal(pareto_select(f, 7, 2, NULL, 3, selected, &err),
                     FACET_OK);
    assert_int_equal(selected[0], 0);
    assert_int_equal(selected[1], 5);
    assert_int_equal(selected[2], 6);
}

/* ---- hypervolume --------------------------------------------------------- */

static void check_volume_cells(struct rng *rng, size_t n, size_t m)
{
    int reference[8];
    double ref[8];
    for (size_t j = 0; j < m; j++) {
        reference[j] = 3 + (int)rng_below(rng, 6);
        ref[j] = reference[j];
    }
    /* Coordinates up to 9, so some points reach or pass the reference. */
    double *f = random_points(rng, n, m, 10);
    double volume;
    struct facet_error err;
    assert_int_equal(pareto_hypervolume(f, n, m, ref, &volume, &err),
                     FACET_OK);
    assert_true(volume == cell_volume(f, n, m, reference));
    free(f);
}

static void test_hypervolume_matches_cells(void **state)
{
    (void)state;
    struct rng rng;
    rng_seed(&rng, 1);
    for (int trial = 0; trial < 200; trial++) {
        size_t n = (size_t)rng_below(&rng, 40);
        check_volume_cells(&rng, n, 2);
        check_volume_cells(&rng, n, 3);
    }
    for (int trial = 0; trial < 40; trial++) {
        check_volume_cells(&rng, (size_t)rng_below(&rng, 25), 4);
        check_volume_cells(&rng, (size_t)rng_below(&rng, 12), 5);
        check_volume_cells(&rng, (size_t)rng_below(&rng, 10), 1);
    }
}

static void test_hypervolume_known_values(void **state)
{
    (void)state;
    struct facet_error err;
    double volume;
    /* One box; a point on the reference adds nothing. */
    double a[] = {0.5, 0.25, 1, 0};
    double ref[] = {1, 1};
    assert_int_equal(pareto_hypervolume(a, 2, 2, ref, &volume, &err),
                     FACET_OK);
    assert_true(fabs(volume - 0.375) < 1e-15);
    /* Empty set. */
    assert_int_equal(pareto_hypervolume(a, 0, 2, ref, &volume, &err),
                     FACET_OK);
    assert_true(volume == 0);
    /* 3-D: two unit-corner boxes overlapping in a cube of 1/8. */
    double b[] = {0, 0.5, 0.5, 0.5, 0, 0.5};
    double ref3[] = {1, 1, 1};
    assert_int_equal(pareto_hypervolume(b, 2, 3, ref3, &volume, &err),
                     FACET_OK);
    assert_true(fabs(volume - (0.25 + 0.25 - 0.125)) < 1e-15);
    double nan_ref[] = {1, NAN};
    assert_int_equal(pareto_hypervolume(a, 2, 2, nan_ref, &volume, &err),
                     FACET_EINPUT);
}

/* Real-valued sets: a constant last objective of 0 with reference 1 makes
 * the m-D volume equal the (m-1)-D volume of the rest, linking the 2-D,
 * 3-D and sliced algorithms on thousands of points. */
static void test_hypervolume_dimensions_agree(void **state)
{
    (void)state;
    struct rng rng;
    rng_seed(&rng, 9);
    for (size_t m = 2; m <= 3; m++) {
        size_t n = m == 2 ? 3000 : 300;
        double *f = random_points(&rng, n, m, 0);
        /* Points near a front: f_last = 1 - mean of the others + noise. */
        for (size_t i = 0; i < n; i++) {
            double sum = 0;
            for (size_t j = 0; j + 1 < m; j++)
                sum += f[i * m + j];
            f[i * m + m - 1] = 1.0 - sum / (double)(m - 1) +
                               0.05 * rng_uniform(&rng);
        }
        double *g = malloc(n * (m + 1) * sizeof *g);
        for (size_t i = 0; i < n; i++) {
            memcpy(g + i * (m + 1), f + i * m, m * sizeof *f);
            g[i * (m + 1) + m] = 0;
        }
        double ref[4] = {1.1, 1.1, 1.1, 1.0};
        ref[m] = 1.0;
        double low, high;
        struct facet_error err;
        assert_int_equal(pareto_hypervolume(f, n, m, ref, &low, &err),
                         FACET_OK);
        assert_int_equal(pareto_hypervolume(g, n, m + 1, ref, &high, &err),
                         FACET_OK);
        assert_true(low > 0.1);
        assert_true(fabs(low - high) < 1e-12);
        free(f);
        free(g);
    }
}

static void test_hypervolume_normalized(void **state)
{
    (void)state;
    /* Cost 100..300, deviation 0.01..0.05: normalised, (0,1) and (1,0)
     * and (0.5, 0.25); the reference is 1.1 on both axes. */
    double f[] = {100, 0.05, 300, 0.01, 200, 0.02};
    double ideal[] = {100, 0.01}, nadir[] = {300, 0.05};
    double scaled[6];
    pareto_normalize(f, 3, 2, ideal, nadir, scaled);
    assert_true(fabs(scaled[4] - 0.5) < 1e-15);
    assert_true(fabs(scaled[5] - 0.25) < 1e-15);
    double volume;
    struct facet_error err;
    assert_int_equal(pareto_hypervolume_normalized(f, 3, 2, ideal, nadir,
                                                   &volume, &err),
                     FACET_OK);
    /* Strips by x: (0,1): 1.1 * 0.1; (0.5,0.25): 0.6 * 0.75;
     * (1,0): 0.1 * 0.25. */
    assert_true(fabs(volume - (0.11 + 0.45 + 0.025)) < 1e-12);
    /* A zero range maps to 0. */
    double flat_nadir[] = {300, 0.01};
    pareto_normalize(f, 3, 2, ideal, flat_nadir, scaled);
    assert_true(scaled[1] == 0 && scaled[3] == 0 && scaled[5] == 0);
}

/* ---- knee ---------------------------------------------------------------- */

static void test_knee_closest_to_ideal(void **state)
{
    (void)state;
    /* Normalised first front: (0,1) (0.2,0.3) (0.5,0.25) (1,0); squared
     * distances 1, 0.13, 0.3125, 1. Point 4, (0.3, 0.3) in normalised
     * terms, is dominated and so not a candidate. */
    double f[] = {0, 1, 200, 0.3, 500, 0.25, 1000, 0, 300, 0.3};
    int rank[5];
    struct facet_error err;
    assert_int_equal(pareto_rank(f, 5, 2, NULL, rank, NULL, &err), FACET_OK);
    assert_int_equal(rank[4], 2);
    size_t knee = 99;
    assert_int_equal(pareto_knee(f, 5, 2, rank, &knee, &err), FACET_OK);
    assert_int_equal(knee, 1);

    /* Dense ZDT1-like front f2 = 1 - sqrt(f1): the minimum of
     * f1^2 + (1 - sqrt f1)^2 is at sqrt f1 = s with 2 s^3 + s - 1 = 0. */
    enum { N = 1001 };
    double *g = malloc(2 * N * sizeof *g);
    int *r = malloc(N * sizeof *r);
    for (int i = 0; i < N; i++) {
        g[2 * i] = i / (double)(N - 1);
        g[2 * i + 1] = 1 - sqrt(g[2 * i]);
        r[i] = 1;
    }
    double s = 0.5;
    for (int it = 0; it < 60; it++)
        s -= (2 * s * s * s + s - 1) / (6 * s * s + 1);
    assert_int_equal(pareto_knee(g, N, 2, r, &knee, &err), FACET_OK);
    assert_true(fabs(g[2 * knee] - s * s) <= 1.0 / (N - 1));
    free(g);
    free(r);

    int none[] = {2, 2};
    assert_int_equal(pareto_knee(f, 2, 2, none, &knee, &err), FACET_EINPUT);
}


/* ---- ties ---------------------------------------------------------------- */
/* Objective values equal but for rounding must compare equal (ties.h);
 * tie_oracle.h is the brute force. */

/* n x m points on a coarse lattice (many exact ties), of the size of a
 * run's costs and areas, then each value moved by up to 1e-12 of itself,
 * as rounding in another summation order moves it. exact gets the
 * unmoved values. */
static double *near_tie_points(struct rng *rng, size_t n, size_t m,
                               int levels, double *exact)
{
    double *f = malloc((n * m + 1) * sizeof *f);
    for (size_t k = 0; k < n * m; k++) {
        double base = 1000.0 + 37.0 * (double)rng_below(rng, (uint64_t)levels);
        exact[k] = base;
        f[k] = base * (1 + 2e-12 * (rng_uniform(rng) - 0.5));
    }
    return f;
}

static void check_near_ties(struct rng *rng, size_t n, size_t m, int levels,
                            bool constrained)
{
    double *exact = malloc((n * m + 1) * sizeof *exact);
    double *f = near_tie_points(rng, n, m, levels, exact);
    double *violation = NULL;
    if (constrained) {
        violation = malloc((n + 1) * sizeof *violation);
        for (size_t i = 0; i < n; i++)
            violation[i] = rng_below(rng, 3) == 0 ? 0.0
                           : (double)rng_below(rng, 4) * 0.5;
    }
    int *rank = malloc((n + 1) * sizeof *rank);
    int *expected = malloc((n + 1) * sizeof *expected);
    int *unmoved = malloc((n + 1) * sizeof *unmoved);
    struct facet_error err;
    assert_int_equal(pareto_rank(f, n, m, violation, rank, NULL, &err),
                     FACET_OK);
    brute_rank_within(f, violation, n, m, expected);
    assert_int_equal(pareto_rank(exact, n, m, violation, unmoved, NULL, &err),
                     FACET_OK);
    for (size_t i = 0; i < n; i++) {
        assert_int_equal(rank[i], expected[i]);
        assert_int_equal(rank[i], unmoved[i]);
    }
    free(exact);
    free(f);
    free(violation);
    free(rank);
    free(expected);
    free(unmoved);
}

/* Every ranker (m = 1, 2, 3 and the general one) under planted near-ties,
 * against the brute force with the same tolerance, and against the ranks
 * of the unmoved values. */
static void test_rank_near_ties_brute(void **state)
{
    (void)state;
    struct rng rng;
    rng_seed(&rng, 1999);
    const size_t sizes[] = {2, 3, 7, 30, 120};
    const int levels[] = {2, 5, 12};
    for (size_t m = 1; m <= 5; m++)
        for (size_t s = 0; s < sizeof sizes / sizeof *sizes; s++)
            for (size_t l = 0; l < sizeof levels / sizeof *levels; l++) {
                check_near_ties(&rng, sizes[s], m, levels[l], false);
                check_near_ties(&rng, sizes[s], m, levels[l], true);
            }
    check_near_ties(&rng, 500, 3, 20, false);
}

/* Crowding, survivor selection and the knee do not see a move of 1e-12:
 * they come out as for the unmoved values (crowding to 1e-9, since the
 * gaps themselves move by that little), where exact comparisons let the
 * rounding pick ends of fronts, order copies and choose the knee. */
static void test_crowding_select_knee_near_ties(void **state)
{
    (void)state;
    struct rng rng;
    rng_seed(&rng, 77);
    for (int round = 0; round < 60; round++) {
        size_t n = 20 + (size_t)rng_below(&rng, 60);
        size_t m = 2 + (size_t)rng_below(&rng, 2);
        int levels = 3 + (int)rng_below(&rng, 6);
        double *exact = malloc(n * m * sizeof *exact);
        double *f = near_tie_points(&rng, n, m, levels, exact);
        /* Anti-correlate the first two objectives for large fronts. */
        for (size_t i = 0; i < n; i++) {
            exact[i * m + 1] = 3000 - exact[i * m] + (exact[i * m + 1] - 1000)
                               * 0.5;
            f[i * m + 1] = exact[i * m + 1] * (1 + 2e-12 *
                                               (rng_uniform(&rng) - 0.5));
        }
        int *rank = malloc(n * sizeof *rank);
        double *crowd_f = malloc(n * sizeof *crowd_f);
        double *crowd_exact = malloc(n * sizeof *crowd_exact);
        struct facet_error err;
        assert_int_equal(pareto_rank(exact, n, m, NULL, rank, NULL, &err),
                         FACET_OK);
        assert_int_equal(pareto_crowding(f, n, m, rank, crowd_f, &err),
                         FACET_OK);
        assert_int_equal(pareto_crowding(exact, n, m, rank, crowd_exact,
                                         &err), FACET_OK);
        for (size_t i = 0; i < n; i++) {
            assert_int_equal(isinf(crowd_f[i]), isinf(crowd_exact[i]));
            if (!isinf(crowd_f[i]))
                assert_true(fabs(crowd_f[i] - crowd_exact[i]) <= 1e-9);
        }
        size_t knee_f, knee_exact;
        assert_int_equal(pareto_knee(f, n, m, rank, &knee_f, &err), FACET_OK);
        assert_int_equal(pareto_knee(exact, n, m, rank, &knee_exact, &err),
                         FACET_OK);
        assert_int_equal(knee_f, knee_exact);
        size_t keep = n / 2;
        size_t *sel_f = malloc(keep * sizeof *sel_f);
        size_t *sel_exact = malloc(keep * sizeof *sel_exact);
        assert_int_equal(pareto_select(f, n, m, NULL, keep, sel_f, &err),
                         FACET_OK);
        assert_int_equal(pareto_select(exact, n, m, NULL, keep, sel_exact,
                                       &err), FACET_OK);
        for (size_t k = 0; k < keep; k++)
            assert_int_equal(sel_f[k], sel_exact[k]);
        free(exact);
        free(f);
        free(rank);
        free(crowd_f);
        free(crowd_exact);
        free(sel_f);
        free(sel_exact);
    }
}

/* The case in miniature: two options of equal cost and DP area
 * but for rounding (9e-10 USD on 1.2 million), the second flatter. The
 * flatter one alone is Pareto-optimal. */
static void test_rank_rounding_is_not_better(void **state)
{
    (void)state;
    double f[] = {
        1215639.0000000009, 3.620, 630.3,   /* option 286: 9e-10 cheaper? */
        1215639.0000000018, 3.540, 630.3,   /* option 270: flatter */
        1402103.0, 0.620, 878.3,
        1174468.0, 4.372, 575.6,
    };
    int rank[4];
    struct facet_error err;
    assert_int_equal(pareto_rank(f, 4, 3, NULL, rank, NULL, &err), FACET_OK);
    assert_int_equal(rank[0], 2);
    assert_int_equal(rank[1], 1);
    assert_int_equal(rank[2], 1);
    assert_int_equal(rank[3], 1);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_rank_matches_brute_force),
        cmocka_unit_test(test_rank_three_medium_brute),
        cmocka_unit_test(test_rank_paths_agree),
        cmocka_unit_test(test_rank_large_three),
        cmocka_unit_test(test_rank_duplicates_share),
        cmocka_unit_test(test_rank_rejects_bad_input),
        cmocka_unit_test(test_crowding_hand_computed),
        cmocka_unit_test(test_select_prunes_by_crowding),
        cmocka_unit_test(test_select_prefers_distinct),
        cmocka_unit_test(test_hypervolume_matches_cells),
        cmocka_unit_test(test_hypervolume_known_values),
        cmocka_unit_test(test_hypervolume_dimensions_agree),
        cmocka_unit_test(test_hypervolume_normalized),
        cmocka_unit_test(test_knee_closest_to_ideal),
        cmocka_unit_test(test_rank_near_ties_brute),
        cmocka_unit_test(test_crowding_select_knee_near_ties),
        cmocka_unit_test(test_rank_rounding_is_not_better),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
