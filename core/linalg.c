/*
 * linalg.c: Cholesky solve and symmetric 2x2 eigen, for small fixed sizes.
 *
 * No allocation and no global state; see linalg.h for the contracts.
 */
#include <math.h>

#include "linalg.h"

int linalg_cholesky_solve(int n, int lda, const double *a, const double *b,
                          double rel_tol, double *x)
{
    double l[LINALG_MAX][LINALG_MAX];
    double y[LINALG_MAX];

    if (n < 1 || n > LINALG_MAX || lda < n)
        return 0;
    /* Factor a = l l^T, column by column. */
    for (int j = 0; j < n; j++) {
        double diag = a[j * lda + j];
        double s = diag;
        for (int k = 0; k < j; k++)
            s -= l[j][k] * l[j][k];
        if (!(s > rel_tol * fabs(diag)) || !(s > 0))
            return 0;
        l[j][j] = sqrt(s);
        for (int i = j + 1; i < n; i++) {
            double t = a[i * lda + j];
            for (int k = 0; k < j; k++)
                t -= l[i][k] * l[j][k];
            l[i][j] = t / l[j][j];
        }
    }
    /* Forward substitution l y = b, then back substitution l^T x = y. */
    for (int i = 0; i < n; i++) {
        double t = b[i];
        for (int k = 0; k < i; k++)
            t -= l[i][k] * y[k];
        y[i] = t / l[i][i];
    }
    for (int i = n - 1; i >= 0; i--) {
        double t = y[i];
        for (int k = i + 1; k < n; k++)
            t -= l[k][i] * x[k];
        x[i] = t / l[i][i];
    }
    return 1;
}

void linalg_sym2_eigen(double p, double q, double r, double value[2],
                       double *theta)
{
    double mean = 0.5 * (p + r);
    double radius = hypot(0.5 * (p - r), q);

    value[0] = mean + radius;
    value[1] = mean - radius;
    /* tan(2 theta) = 2q / (p - r) picks the direction of the larger value;
     * atan2(0, 0) is 0, so an isotropic matrix gets theta = 0. */
    *theta = 0.5 * atan2(2.0 * q, p - r);
}
