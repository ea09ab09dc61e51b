/*
 * uv_index.h: finding triangles by their position in the UV plane.
 *
 * A bucket grid over the UV bounding box: each cell lists the triangles
 * whose UV bounding box touches it. With about one triangle per cell, a
 * point lookup costs O(1) on average, and so does finding the triangles
 * that may overlap a given one, which is how uv_check finds folds.
 *
 * The index borrows the caller's per-corner UV array; it must outlive the
 * index and not change while the index is in use.
 */
#ifndef FACET_UV_INDEX_H
#define FACET_UV_INDEX_H

#include <stddef.h>
#include <stdint.h>

#include "core/base/error.h"
#include "core/base/stop.h"

struct uv_index {
    const double *uv;          /* #T x 3 x 2 per-corner (u, v), borrowed */
    size_t ntriangles;
    double umin, vmin;         /* UV bounding box */
    double umax, vmax;
    int ncells_u, ncells_v;    /* bucket grid size */
    double cell_u, cell_v;     /* bucket size in UV */
    uint32_t *cell_start;      /* ncells_u * ncells_v + 1 */
    uint32_t *cell_triangles;  /* triangles of cell c: [cell_start[c],
                                  cell_start[c+1]) */
};

/* Builds the index over ntriangles triangles with per-corner UV uv. Returns
 * FACET_OK, FACET_EINPUT when a UV value is not finite, FACET_EWORK when
 * out of memory. Release with uv_index_free, also after a failure. */
int uv_index_build(const double *uv, size_t ntriangles, struct uv_index *out,
                   struct facet_error *err);

/* The first half of uv_index_build: the UV box and the bucket grid (every
 * field but cell_start and cell_triangles, left NULL), which follow from
 * uv alone. A prepared building's cache (project_cache.h) keeps the
 * buckets and remakes this half, so that the grid the buckets are checked
 * against is never read from the file. Same returns. */
int uv_index_frame(const double *uv, size_t ntriangles, struct uv_index *out,
                   struct facet_error *err);

/* The triangle whose UV triangle contains (u, v), with the barycentric
 * coordinates of the point in it, or UINT32_MAX when no triangle does.
 * tolerance widens each triangle by that much in barycentric terms (0 for
 * exact). The answer depends on the point alone: a point on a shared edge
 * (within rounding) goes to the first triangle of its lookup cell that
 * holds it, the same one every time. */
/* The barycentric coordinates b of (u, v) in triangle t's UV triangle
 * (b[0] + b[1] + b[2] = 1, each >= 0 inside); returns 0 (b unset) when
 * that triangle is degenerate. Inline: the walks along cell sides
 * (cell_sides.c) call it for every step. */
static inline int uv_index_barycentric(const struct uv_index *index,
                                       uint32_t t, double u, double v,
                                       double b[3])
{
    const double *c = index->uv + 6 * (size_t)t;
    double x1 = c[2] - c[0], y1 = c[3] - c[1];
    double x2 = c[4] - c[0], y2 = c[5] - c[1];
    double det = x1 * y2 - x2 * y1;
    if (det == 0)
        return 0;
    double px = u - c[0], py = v - c[1];
    b[1] = (px * y2 - x2 * py) / det;
    b[2] = (x1 * py - px * y1) / det;
    b[0] = 1 - b[1] - b[2];
    return 1;
}

uint32_t uv_index_locate(const struct uv_index *index, double u, double v,
                         double tolerance, double barycentric[3]);

void uv_index_free(struct uv_index *index);

/* What uv_check found in a UV map. */
struct uv_report {
    size_t triangles;
    size_t degenerate;   /* UV area zero (to rounding) */
    size_t flipped;      /* UV winding opposite to the majority */
    size_t overlapping;  /* pairs of triangles whose UV interiors overlap */
    double uv_area;      /* sum of |UV triangle areas| */
    double umin, vmin, umax, vmax;
};

/* Checks a per-corner UV map for degenerate, flipped and overlapping
 * triangles. A valid map for panelization has none of them. Returns
 * FACET_OK (whatever it finds: the findings are in *report), FACET_EINPUT
 * for a non-finite UV value, FACET_EWORK when out of memory. */
int uv_check(const double *uv, size_t ntriangles, struct uv_report *report,
             struct facet_error *err);

/* uv_check, asking stop (stop.h) before each row of the lookup's cells:
 * FACET_ESTOP when it fires. */
int uv_check_stoppable(const double *uv, size_t ntriangles,
                       const struct facet_stop *stop,
                       struct uv_report *report, struct facet_error *err);

#endif
