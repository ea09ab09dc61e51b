/*
 * sorted.h: searching a sorted array of doubles.
 */
#ifndef FACET_SORTED_H
#define FACET_SORTED_H

#include <stddef.h>

/* The first place in sorted[0..n) (ascending) whose value is >= x: the
 * number of values below x. */
static inline size_t sorted_lower_bound(const double *sorted, size_t n,
                                        double x)
{
    size_t lo = 0, hi = n;
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        if (sorted[mid] < x)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo;
}

#endif
