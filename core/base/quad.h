/*
 * quad.h: how far a quad of four corners is from planar.
 *
 * The one measure of a quad's planarity Facet states, for a panel's
 * corners (panel.h's corner_planarity) and for a planarized grid
 * (core/planar/): the distance between the lines of its two diagonals,
 * |(c1 - c0) . n| with n the unit normal to both diagonals. It is 0 for
 * a planar quad and scales with the quad (m); divided by the longer
 * diagonal it is the quad's relative planarity. Corners go round the
 * quad: c0, c1, c2, c3, the diagonals c0-c2 and c1-c3.
 */
#ifndef FACET_QUAD_H
#define FACET_QUAD_H

/* The distance between the diagonals of quad c (m, >= 0); 0 when the
 * diagonals are parallel (a degenerate quad, which is planar). */
double quad_planarity(const double c[4][3]);

/* The longer diagonal of quad c (m). */
double quad_diagonal(const double c[4][3]);

#endif
