/*
 * unroll.h: panels laid flat, the patterns a fabricator cuts.
 *
 * A panel's outline (panel_geometry.h) goes into the plane of its pattern
 * as the panel is built (sp_fit.h):
 *   - FP, and DP (not developable: its outline projected, for the record
 *     only), in the panel's best-fit plane: the projected outline
 *     (outline_plane) in an orthonormal frame of that plane whose first
 *     axis runs along the panel's first side (corner 0 to 1) where it has
 *     one;
 *   - SP built on a fitted cylinder or cone, by the exact development of
 *     that surface, each outline point first moved to its nearest point on
 *     it (developable_nearest): a cylinder of radius R to (R theta, h),
 *     theta the angle around the axis and h the height along it; a cone of
 *     half-angle a to polar coordinates (s, theta sin a), s the slant
 *     distance from the apex. The development is an isometry: lengths and
 *     areas measured on the fitted surface are those of the pattern.
 * Every pattern is seen from the side the panel's normal points to (its
 * outer face), never mirrored: a loop that winds counter-clockwise seen
 * from the normal's side winds counter-clockwise in the pattern.
 *
 * Units: metres in and out. Pure computation; no I/O.
 */
#ifndef FACET_UNROLL_H
#define FACET_UNROLL_H

#include <stddef.h>

#include "core/base/error.h"
#include "core/fit/developable.h"
#include "core/fit/sp_fit.h"
#include "core/panel/panel.h"
#include "core/panel/panel_geometry.h"

/* points (n x 3, m, on the plane through origin with unit normal normal)
 * into plane coordinates out (n x 2, m): the frame's first axis is along
 * (projected into the plane; any direction across normal when along is
 * NULL or normal to the plane), the second normal x first. */
void unroll_plane(const double origin[3], const double normal[3],
                  const double along[3], const double *points, size_t n,
                  double *out);

/* points (n x 3, m, near d) developed into out (n x 2, m): each moved to
 * its nearest point on d, then a cylinder's (R theta, h), a cone's (s cos
 * phi, s sin phi) with phi = theta sin a. theta is measured from the
 * direction of the points' mean, so a panel of less than a full turn
 * never crosses theta's cut. facing (unit, or NULL for the outside of d)
 * is the side the pattern is seen from. */
void unroll_developable(const struct developable *d, const double *points,
                        size_t n, const double facing[3], double *out);

/* The patterns of every panel of a panelization. */
struct flat_patterns {
    size_t npanels;
    size_t npoints;            /* the geometry's loop_start[nloops] */
    double *flat;              /* npoints x 2: outline point k of the
                                  geometry (outline[k]) in its panel's
                                  pattern (m) */
    enum panel_type *developed;/* npanels: how each was laid flat: TYPE_FP
                                  in its plane, TYPE_SP on its fit,
                                  TYPE_DP projected (not developable) */
    double *area;              /* npanels: the pattern's area (m^2), its
                                  loops' signed areas added (a hole
                                  subtracts) */
};

/* Lays every panel of panels (geometry built from them) flat, as above;
 * fit (npanels, or NULL when no panel is built on a fit) gives each
 * panel's cylinder or cone where fit[k].fitted, and a panel built SP is
 * developed on it (one built SP without a fit is refused: FACET_EINPUT).
 * Fills *out (release with flat_patterns_free, also after a failure).
 * Returns FACET_OK, FACET_EINPUT or FACET_EWORK (out of memory). */
int flat_patterns_build(const struct panel_geometry *geometry,
                        const struct panelization *panels,
                        const struct built_panel *fit,
                        struct flat_patterns *out, struct facet_error *err);

void flat_patterns_free(struct flat_patterns *patterns);

/* The turn (rad, counter-clockwise) that brings the points (n x 2)
 * into their bounding box of least area, lying landscape (at least as
 * wide as tall): the box of their convex hull along each hull edge, the
 * least kept (ties: the first edge in the hull's order from its lowest,
 * leftmost point). 0 for fewer than 3 points or no area. Scratch the
 * caller gives: hull, 4 n + 2 doubles, and order, n. */
double unroll_least_box_turn(const double *points, size_t n,
                             double *scratch, size_t *order);

/* The signed area (m^2) of the closed polygon points (n x 2):
 * positive counter-clockwise. */
double unroll_polygon_area(const double *points, size_t n);

#endif
