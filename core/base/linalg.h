/*
 * linalg.h: the small dense linear algebra the geometry code needs.
 *
 * Fixed-size, allocation-free helpers for systems of at most LINALG_MAX
 * unknowns: a Cholesky solve for the normal equations of small least-squares
 * fits, and the closed-form eigen-decomposition of a symmetric 2x2 matrix.
 * Larger problems do not belong here. (Symmetric 3x3 eigen is sym3.h.)
 * The Cholesky factor and solves are static inline, so that a caller
 * with a constant size gets their loops unrolled (the vertex curvature's
 * passes, issue 27); their operations and order do not depend on it, so
 * neither do their bits.
 */
#ifndef FACET_LINALG_H
#define FACET_LINALG_H

#include <assert.h>
#include <math.h>

#define LINALG_MAX 16  /* largest n linalg_cholesky_solve accepts */

/* Solves a x = b for the leading n x n block of the symmetric matrix a
 * (row-major with row stride lda >= n; only the lower triangle is read; a and
 * b are not modified). n must be in 1..LINALG_MAX (asserted). It cannot
 * fail otherwise: it answers whether the block is safely positive
 * definite, 1 with x[0..n) filled, or 0 with x untouched when a pivot
 * falls below rel_tol times the diagonal entry it came from (rel_tol
 * ~1e-10 rejects rank-deficient fits, such as a quadric through collinear
 * points). */
int linalg_cholesky_solve(int n, int lda, const double *a, const double *b,
                          double rel_tol, double *x);

/* linalg_cholesky_solve in two steps, for one matrix and several right-hand
 * sides: _factor writes the factor of a (as _solve tests it; returns 0 when
 * it is not safely positive definite) into l, n x n with row stride n, and
 * _apply solves l l^T x = b with it. Sizes as _solve. */
static inline int linalg_cholesky_factor(int n, int lda, const double *a,
                                         double rel_tol, double *l)
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

static inline void linalg_cholesky_apply(int n, const double *l,
                                         const double *b, double *x)
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

/* linalg_cholesky_apply for m right-hand sides at once (m in
 * 1..LINALG_MAX), b + k * stride to x + k * stride for k < m: each x the
 * same to the bit as linalg_cholesky_apply's, in about the time of one,
 * as their substitutions, each a chain of divisions, overlap. */
static inline void linalg_cholesky_apply_many(int n, const double *l, int m,
                                              int stride, const double *b,
                                              double *x)
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

/* Eigen-decomposition of the symmetric matrix [[p, q], [q, r]]: value[0] >=
 * value[1], and the unit eigenvector of value[0] is (cos theta, sin theta),
 * that of value[1] is (-sin theta, cos theta); *theta is returned in
 * (-pi/2, pi/2]. Finite input gives finite output (theta = 0 when the
 * matrix is a multiple of the identity). */
void linalg_sym2_eigen(double p, double q, double r, double value[2],
                       double *theta);

/* The eigenvalues of linalg_sym2_eigen alone, the same to the bit. */
void linalg_sym2_values(double p, double q, double r, double value[2]);

#endif
