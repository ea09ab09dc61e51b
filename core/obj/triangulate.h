/*
 * triangulate.h: splitting one polygon into triangles.
 *
 * A polygon of n corners always becomes n - 2 triangles, so callers can
 * size their output before triangulating. A planar (or nearly planar)
 * simple polygon, convex or not, is cut by ear clipping in its best-fit
 * plane (the plane of its Newell normal), so every triangle lies inside it
 * and the triangles keep the polygon's winding. A polygon that ear clipping
 * cannot finish (degenerate, collinear, self-intersecting) is finished as a
 * fan, which still gives n - 2 triangles. Polygons of more than
 * TRIANGULATE_MAX_EAR_CORNERS corners are fanned outright, since ear
 * clipping is quadratic.
 *
 * Nothing here allocates except the caller's reusable scratch.
 */
#ifndef FACET_TRIANGULATE_H
#define FACET_TRIANGULATE_H

#include <stddef.h>
#include <stdint.h>

#include "core/base/error.h"

#define TRIANGULATE_MAX_EAR_CORNERS 20000

/* Working memory for triangulate_polygon, reused from polygon to polygon.
 * Zero-initialise it before first use; release it with
 * triangulate_scratch_free. */
struct triangulate_scratch {
    double *plane;    /* capacity x 2: corners projected to 2D */
    uint32_t *prev;   /* capacity: ring of corners not yet cut off */
    uint32_t *next;
    size_t capacity;  /* corners the arrays can hold */
};

/* Frees the scratch arrays and zeroes *scratch. */
void triangulate_scratch_free(struct triangulate_scratch *scratch);

/* Triangulates the polygon whose corners, in order, are
 *   point     n x 3 corner positions (any unit)
 * and writes
 *   triangle  (n - 2) x 3 corner numbers in 0..n-1, each triangle wound as
 *             the polygon is.
 * n must be at least 3 and below UINT32_MAX. Triangles and quads need no
 * scratch (it may then be NULL). Returns FACET_OK, or FACET_EWORK if the
 * scratch cannot grow (out of memory), with err set. */
int triangulate_polygon(const double *point, size_t n, uint32_t *triangle,
                        struct triangulate_scratch *scratch,
                        struct facet_error *err);

/* Triangulates the quad a, b, c, d (each x y z) exactly as
 * triangulate_polygon would, without copying its corners: along the
 * diagonal from its one reflex corner, else along a-c. Writes 2 x 3 corner
 * numbers (0 = a .. 3 = d) to triangle. */
void triangulate_quad(const double *a, const double *b, const double *c,
                      const double *d, uint32_t *triangle);

#endif
