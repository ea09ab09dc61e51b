/*
 * exact_sum.h: sums that do not depend on the order of their terms.
 *
 * An option's totals (areas, planarity, P_dist) are sums over its panels,
 * and two options that are equal in exact arithmetic (mirror images of one
 * another on a symmetric surface, say) list the same panel values in other
 * orders. Floating-point addition rounds differently in each order, so the
 * totals would differ in their last bits and a Pareto comparison would
 * read that noise as a difference. These sums add every term in fixed
 * point at 2^-64 of the unit (5.4e-20 m, m^2 or m^4) in a 128-bit integer,
 * where addition is exact, and round once at the end: the same terms give
 * the same total to the bit, whatever their order.
 *
 * A term's bits below 2^-64 are dropped (the same way for the same value);
 * terms of 2^36 or more (6.9e10), or not finite, are added in floating
 * point instead, and the total is then as ordinary a sum as any. Up to
 * 2^26 terms of 2^36 cannot overflow the integer.
 */
#ifndef FACET_EXACT_SUM_H
#define FACET_EXACT_SUM_H

#include <math.h>

struct exact_sum {
    __int128 fixed;   /* terms below 2^36, in units of 2^-64 */
    double rest;      /* terms too large or not finite */
};

static inline void exact_sum_init(struct exact_sum *s)
{
    s->fixed = 0;
    s->rest = 0;
}

static inline void exact_sum_add(struct exact_sum *s, double term)
{
    if (fabs(term) < 0x1p36)
        s->fixed += (__int128)(term * 0x1p64);  /* exact scaling, then
                                                   truncation */
    else
        s->rest += term;
}

static inline double exact_sum_value(const struct exact_sum *s)
{
    return (double)s->fixed * 0x1p-64 + s->rest;
}

#endif
