/*
 * extremes.h: the larger and the smaller of two doubles, as the C
 * library's fmax and fmin give them, inline.
 *
 * gcc does not inline fmax and fmin (without -ffinite-math-only it must
 * keep their NaN rule), so a loop that keeps a running extreme over every
 * vertex of every panel pays a library call per comparison: 10 % of the
 * paper's study went to __fmax and __fmin. These give the same value,
 * bit for bit, as glibc's for every pair of doubles but signalling NaNs
 * (which Facet never makes): a NaN argument is ignored (the other is
 * returned), and of two that compare equal (+0 and -0) the first.
 * tests/unit/test_extremes.c holds them to the library on the cases that
 * differ.
 */
#ifndef FACET_EXTREMES_H
#define FACET_EXTREMES_H

/* fmax(a, b) */
static inline double larger(double a, double b)
{
    return a >= b || b != b ? a : b;
}

/* fmin(a, b) */
static inline double smaller(double a, double b)
{
    return a <= b || b != b ? a : b;
}

#endif
