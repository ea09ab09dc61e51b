/*
 * sym3.h: eigen-decomposition of a symmetric 3x3 matrix.
 *
 * Small and exact enough for best-fit planes and shape operators: cyclic
 * Jacobi rotations, which converge to machine precision in a handful of
 * sweeps and never produce NaN for finite input.
 */
#ifndef FACET_SYM3_H
#define FACET_SYM3_H

/* Decomposes the symmetric matrix a (row-major, 3x3; only read) into
 * eigenvalues value[0] <= value[1] <= value[2] and unit eigenvectors
 * vector[k][0..2] belonging to value[k]. */
void sym3_eigen(const double a[9], double value[3], double vector[3][3]);

#endif
