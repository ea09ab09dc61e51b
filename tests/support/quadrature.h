/*
 * quadrature.h: the area of a parametric surface S(s, t) on the unit
 * square, by midpoint quadrature of |S_s x S_t| with central differences:
 * an oracle independent of any triangulation, for the example tests.
 */
#ifndef FACET_TEST_QUADRATURE_H
#define FACET_TEST_QUADRATURE_H

/* point(data, s, t, p) writes S(s, t) into p. n x n midpoints. */
double quadrature_area(void (*point)(const void *data, double s, double t,
                                     double p[3]),
                       const void *data, int n);

#endif
