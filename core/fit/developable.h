/*
 * developable.h: the single-curved panels a fabricator rolls: circular
 * cylinders and circular cones, and their least-squares fit to points.
 *
 * One form holds both: the surface at distance radius + slope * h from an
 * axis, h measured along the axis from a base point. slope = 0 is a
 * cylinder ("rotational cylindrical" in practice); slope != 0 is a cone
 * whose rulings converge at the apex base - (radius / slope) axis, with
 * half-angle atan |slope|. Keeping the cylinder as the cone of slope 0
 * lets a cone fit start from the cylinder and stay well-conditioned however
 * far its apex lies.
 *
 * Distances are measured in the half-plane through the axis and the point
 * (the nappe the panel lies on), which is exact for points on the panel's
 * side of the axis and of the apex, as a panel's samples are.
 */
#ifndef FACET_DEVELOPABLE_H
#define FACET_DEVELOPABLE_H

#include <stddef.h>

enum developable_shape { DEVELOPABLE_CYLINDER, DEVELOPABLE_CONE };

struct developable {
    enum developable_shape shape;
    double axis[3];     /* unit axis direction */
    double base[3];     /* a point of the axis (m) */
    double radius;      /* distance of the surface from the axis at base (m) */
    double slope;       /* change of that distance per metre along the axis:
                           0 for a cylinder, +-tan(half-angle) for a cone */
};

/* Signed distance (m) of x from the surface d: positive away from the
 * axis. */
double developable_distance(const struct developable *d, const double x[3]);

/* The point of d nearest x into point (m) and d's unit normal there, away
 * from the axis, into normal (either may be NULL). */
void developable_nearest(const struct developable *d, const double x[3],
                         double point[3], double normal[3]);

/* Fits a circular cylinder to points (n x 3, m) in the least-squares sense
 * (the sum of squared distances): the axis starts along axis_guess (unit;
 * the panel's rulings), the cross-section is the algebraic circle fit of
 * the points projected along it, and Levenberg-Marquardt then refines axis,
 * position and radius together. Returns 0 and fills *out, or -1 when the
 * points define no cylinder (fewer than 5, or straight across the axis). */
int developable_fit_cylinder(const double *points, size_t n,
                             const double axis_guess[3],
                             struct developable *out);

/* Fits a circular cone to points (n x 3, m) in the least-squares sense,
 * refining axis, position, radius and slope together from start: a fitted
 * cylinder (the cone whose rulings are parallel) or a cone_start. At every
 * step radius and slope are the best for the axis (a line fit in the
 * half-plane through the axis), which keeps the fit from crawling along the
 * valley where they trade off against the axis. Returns 0 and fills *out,
 * or -1 when fewer than 6 points, the fit leaves the finite or its apex
 * lies among the points (no panel one can roll: not farther from their
 * centroid than the farthest of them). */
int developable_fit_cone(const double *points, size_t n,
                         const struct developable *start,
                         struct developable *out);

/* Places a surface congruent to start nearest points (n x 3, m) in the
 * least-squares sense: a cylinder of start's radius, or a cone of start's
 * slope (its half-angle), moved rigidly (the axis tilted and shifted, a
 * cone's apex along it too) from where start puts it, which should be
 * near the points. What a panel laid on another's bending jig is held
 * to (mould.h). With enough > 0 (m) the fit stops as soon as every point
 * is within enough of the surface, and once a step would move the
 * surface by under enough / 100 (root mean square at the points) instead
 * of 0.1 um: the caller wants a verdict at enough, and measures the
 * placement returned itself. A least-squares placement, so the largest
 * distance it leaves may exceed the least any placement could by a
 * little (a third, for a circle's arc on another's). Returns 0 and fills
 * *out, or -1 when fewer than 5 points or the fit leaves the finite. */
int developable_fit_congruent(const double *points, size_t n,
                              const struct developable *start,
                              double enough, struct developable *out);

/* A start for a cone fit: the cone whose apex is where the rulings
 * converge, the point nearest (least squares) the lines through at[k]
 * along ruling[k] (nrulings x 3 each, rulings unit), its axis the normal of
 * the plane the directions from the apex to points (n x 3) lie on (a
 * cone's directions from its apex make one angle with its axis). Returns
 * 0 and fills *out, or -1 when the rulings do not meet within 20 times the
 * points' extent (parallel to within their noise: a cylinder's case) or the
 * points give no axis. */
int developable_cone_start(const double *points, size_t n, const double *at,
                           const double *ruling, size_t nrulings,
                           struct developable *out);

/* The spread of points (n x 3, n >= 1): their mean into mean, and the
 * eigenvalues value[0] <= value[1] <= value[2] of their scatter matrix
 * (the sum of (x - mean)(x - mean)^T) with unit eigenvectors vector[k]:
 * vector[2] along their longest extent, vector[0] normal to the plane they
 * lie nearest. */
void developable_principal_axes(const double *points, size_t n,
                                double mean[3], double value[3],
                                double vector[3][3]);

/* What a fabricator reads of d, seen from x (a point of the panel, m):
 * the foot of x on the axis into axis_point (m) and the axis direction
 * (unit) into direction, pointed from the apex towards x's side for a
 * cone, with its largest component positive for a cylinder (the fit's
 * own sign is arbitrary; this one is the same for the same surface).
 * Of a cone also its apex (m, into apex; NaN for a cylinder) and its
 * half-angle (rad, returned; 0 for a cylinder). apex may be NULL. */
double developable_describe(const struct developable *d, const double x[3],
                            double axis_point[3], double direction[3],
                            double apex[3]);

/* The largest |distance| (m) of points (n x 3) from d. */
double developable_max_distance(const struct developable *d,
                                const double *points, size_t n);

#endif
