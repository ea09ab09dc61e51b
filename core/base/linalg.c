/*
 * linalg.c: Cholesky solve and symmetric 2x2 eigen, for small fixed sizes.
 *
 * No allocation and no global state; see linalg.h for the contracts.
 */
#include <assert.h>
#include <math.h>

#include "core/base/linalg.h"

int linalg_cholesky_solve(int n, int lda, const double *a, const double *b,
                          double rel_tol, double *x)
{
    double l[LINALG_MAX * LINALG_MAX];

    if (!linalg_cholesky_factor(n, lda, a, rel_tol, l))
        return 0;
    linalg_cholesky_apply(n, l, b, x);
    return 1;
}

void linalg_sym2_values(double p, double q, double r, double value[2])
{
    double mean = 0.5 * (p + r);
    double radius = hypot(0.5 * (p - r), q);

    value[0] = mean + radius;
    value[1] = mean - radius;
}

void linalg_sym2_eigen(double p, double q, double r, double value[2],
                       double *theta)
{
    linalg_sym2_values(p, q, r, value);
    /* tan(2 theta) = 2q / (p - r) picks the direction of the larger value;
     * atan2(0, 0) is 0, so an isotropic matrix gets theta = 0. */
    *theta = 0.5 * atan2(2.0 * q, p - r);
}
