/*
 * linalg.c: Cholesky solve and symmetric 2x2 eigen, for small fixed sizes.
 *
 * No allocation and no global state; see linalg.h for the contracts.
 */
#include <assert.h>
#include <math.h>

#include "core/base/linalg.h"

int linalg_cholesky_factor(int n, int lda, const double *a, double rel_tol,
                           double *l)
{
    /* The sizes are the caller's code, not its data: a wrong one is a
     * bug, not a matrix that fails to be positive definite. */
    assert(n >= 1 && n <= LINALG_MAX && lda >= n);
    /* Factor a = l l^T, column by column. */
    for (int j = 0; j < n; j++) {
        double diag = a[j * lda + j];
        double s = diag;
        for (int k = 0; k < j; k++)
            s -= l[j * n + k] * l[j * n + k];
        if (!(s > rel_tol * fabs(diag)) || !(s > 0))
            return 0;
        l[j * n + j] = sqrt(s);
        for (int i = j + 1; i < n; i++) {
            double t = a[i * lda + j];
            for (int k = 0; k < j; k++)
                t -= l[i * n + k] * l[j * n + k];
            l[i * n + j] = t / l[j * n + j];
        }
    }
    return 1;
}

void linalg_cholesky_apply(int n, const double *l, const double *b, double *x)
{
    double y[LINALG_MAX];
    assert(n >= 1 && n <= LINALG_MAX);

    /* Forward substitution l y = b, then back substitution l^T x = y. */
    for (int i = 0; i < n; i++) {
        double t = b[i];
        for (int k = 0; k < i; k++)
            t -= l[i * n + k] * y[k];
        y[i] = t / l[i * n + i];
    }
    for (int i = n - 1; i >= 0; i--) {
        double t = y[i];
        for (int k = i + 1; k < n; k++)
            t -= l[k * n + i] * x[k];
        x[i] = t / l[i * n + i];
    }
}

void linalg_cholesky_apply_many(int n, const double *l, int m, int stride,
                                const double *b, double *x)
{
    double y[LINALG_MAX * LINALG_MAX];
    assert(n >= 1 && n <= LINALG_MAX && m >= 1 && m <= LINALG_MAX);
    assert(stride >= n);

    /* linalg_cholesky_apply's operations, in its order for each right-hand
     * side, the sides innermost. */
    for (int i = 0; i < n; i++)
        for (int j = 0; j < m; j++) {
            double t = b[j * stride + i];
            for (int k = 0; k < i; k++)
                t -= l[i * n + k] * y[j * LINALG_MAX + k];
            y[j * LINALG_MAX + i] = t / l[i * n + i];
        }
    for (int i = n - 1; i >= 0; i--)
        for (int j = 0; j < m; j++) {
            double t = y[j * LINALG_MAX + i];
            for (int k = i + 1; k < n; k++)
                t -= l[k * n + i] * x[j * stride + k];
            x[j * stride + i] = t / l[i * n + i];
        }
}

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
