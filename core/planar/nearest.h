/*
 * nearest.h: the nearest point of a triangle mesh to a point in space.
 *
 * A planarized corner leaves the design surface; how far it went is its
 * distance to the mesh, measured exactly (the nearest point over every
 * triangle, Ericson's closest point on a triangle), not by its UV foot
 * point, which is no nearest point once the corner is off the surface.
 *
 * A bucket grid over the mesh's bounding box, about one triangle per cell,
 * each cell listing the triangles whose bounding box touches it; a query
 * searches shells of cells outwards from the point's cell until no cell
 * left can hold a nearer point. A corner within centimetres of the
 * surface looks at a few dozen triangles.
 *
 * The index borrows the mesh; it must outlive the index and not change.
 * Units: metres.
 */
#ifndef FACET_NEAREST_H
#define FACET_NEAREST_H

#include <stddef.h>
#include <stdint.h>

#include "core/base/error.h"
#include "core/surface/mesh.h"

struct nearest_index {
    const struct mesh *mesh;   /* borrowed */
    double lo[3];              /* the grid's corner (m) */
    double cell[3];            /* cell size along each axis (m) */
    int n[3];                  /* cells along each axis */
    uint32_t *cell_start;      /* n0 n1 n2 + 1 */
    uint32_t *cell_triangles;  /* triangles of cell c: [cell_start[c],
                                  cell_start[c + 1]) */
};

/* What a query found. */
struct nearest_hit {
    uint32_t triangle;   /* the triangle the nearest point lies on */
    double point[3];     /* the nearest point (m) */
    double distance;     /* from the query point to it (m) */
};

/* Builds the index over mesh into *out (caller-owned). Returns FACET_OK,
 * FACET_EINPUT for a mesh without triangles, FACET_EWORK when out of
 * memory. Release with nearest_index_free, also after a failure. */
int nearest_index_build(const struct mesh *mesh, struct nearest_index *out,
                        struct facet_error *err);

/* The nearest point of the mesh to p (m, finite) into *hit. Reentrant:
 * several threads may query one index. */
void nearest_point(const struct nearest_index *index, const double p[3],
                   struct nearest_hit *hit);

/* The nearest point of triangle (a, b, c) to p into out (m); returns the
 * squared distance. */
double nearest_on_triangle(const double p[3], const double a[3],
                           const double b[3], const double c[3],
                           double out[3]);

void nearest_index_free(struct nearest_index *index);

#endif
