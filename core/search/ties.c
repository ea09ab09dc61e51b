/*
 * ties.c: tie classes of objective values. See ties.h.
 */
#include "core/search/ties.h"

#include <assert.h>
#include <math.h>
#include <stdlib.h>

double ties_tolerance(const double *values, size_t n, size_t stride)
{
    double low = INFINITY, high = -INFINITY;
    for (size_t k = 0; k < n; k++) {
        double v = values[k * stride];
        if (!isfinite(v))
            continue;
        low = fmin(low, v);
        high = fmax(high, v);
    }
    if (!(high >= low))
        return 0;
    /* Scaled before subtracting, so that a range beyond DBL_MAX stays
     * finite. */
    double range = TIES_RELATIVE * high - TIES_RELATIVE * low;
    return fmax(range, TIES_RELATIVE * fmax(fabs(high), fabs(low)));
}

struct keyed {
    double value;
    size_t index;
};

/* By value, then index: a total order, so qsort's result is unique. */
static int compare_keyed(const void *a, const void *b)
{
    const struct keyed *x = a, *y = b;
    if (x->value != y->value)
        return x->value < y->value ? -1 : 1;
    return (x->index > y->index) - (x->index < y->index);
}

int ties_merge_column(const double *values, size_t n, size_t stride,
                      double tolerance, double *out, struct facet_error *err)
{
    assert(tolerance >= 0);
    if (n == 0)
        return FACET_OK;
    struct keyed *sorted = malloc(n * sizeof *sorted);
    if (sorted == NULL)
        return facet_error_set(err, FACET_EWORK,
                               "out of memory (ties of %zu values)", n);
    for (size_t k = 0; k < n; k++) {
        assert(!isnan(values[k * stride]));
        sorted[k].value = values[k * stride];
        sorted[k].index = k;
    }
    qsort(sorted, n, sizeof *sorted, compare_keyed);
    double lowest = sorted[0].value;
    for (size_t k = 0; k < n; k++) {
        double v = sorted[k].value;
        /* A gap over the tolerance (or one that involves an infinity)
         * starts a new class. */
        if (k > 0 && !(v - sorted[k - 1].value <= tolerance &&
                       isfinite(v) && isfinite(sorted[k - 1].value)))
            lowest = v;
        out[sorted[k].index * stride] = lowest;
    }
    free(sorted);
    return FACET_OK;
}

int ties_merge(const double *objectives, size_t n, size_t m, double *out,
               struct facet_error *err)
{
    for (size_t j = 0; j < m; j++) {
        double tolerance = ties_tolerance(objectives + j, n, m);
        int rc = ties_merge_column(objectives + j, n, m, tolerance, out + j,
                                   err);
        if (rc != FACET_OK)
            return rc;
    }
    return FACET_OK;
}

int ties_compare_normalised(double a, double b)
{
    if (a == b || fabs(a - b) <= TIES_RELATIVE)
        return 0;
    return a < b ? -1 : 1;
}

/* A row to order: its merged keys, and what qsort's comparator needs to
 * read them, since qsort passes no context. */
struct ordered_row {
    const double *keys;
    size_t nkeys;
    size_t index;
    int descending;
};

static int compare_rows(const void *a, const void *b)
{
    const struct ordered_row *x = a, *y = b;
    int c = 0;
    for (size_t k = 0; k < x->nkeys && c == 0; k++)
        if (x->keys[k] != y->keys[k])
            c = x->keys[k] < y->keys[k] ? -1 : 1;
    if (c == 0)
        c = (x->index > y->index) - (x->index < y->index);
    return x->descending ? -c : c;
}

int ties_order(const double *keys, size_t n, size_t nkeys,
               const double *tolerance, int descending, size_t *order,
               struct facet_error *err)
{
    if (n == 0)
        return FACET_OK;
    double *merged = malloc(n * nkeys * sizeof *merged + 1);
    struct ordered_row *rows = malloc(n * sizeof *rows);
    int rc = FACET_OK;
    if (merged == NULL || rows == NULL)
        rc = facet_error_set(err, FACET_EWORK,
                             "out of memory (ordering %zu rows)", n);
    for (size_t k = 0; rc == FACET_OK && k < nkeys; k++)
        rc = ties_merge_column(keys + k, n, nkeys, tolerance[k], merged + k,
                               err);
    if (rc != FACET_OK)
        goto done;
    for (size_t i = 0; i < n; i++)
        rows[i] = (struct ordered_row){merged + i * nkeys, nkeys, i,
                                       descending};
    qsort(rows, n, sizeof *rows, compare_rows);
    for (size_t i = 0; i < n; i++)
        order[i] = rows[i].index;
done:
    free(merged);
    free(rows);
    return rc;
}
