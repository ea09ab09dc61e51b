/*
 * panel_internal.h: what the three ways of measuring panels share (the
 * straightforward clipping, the single-grid way and the lattice; internal
 * to core/panel/, not part of Facet's interface).
 *
 * A panelization is measured in two passes over the surface. Pass 1 sums
 * each cell's area and moments (struct cell_moments); panels_fit turns them
 * into panels with their best-fit planes. Pass 2 takes the points of each
 * panel's surface that bound its deviation, curvature and outline
 * (cell_sample); panels_finish turns those into the panels' remaining
 * measures. panel.c's panels_build feeds both passes from the clipped
 * pieces of every triangle; panel_fast.c's panels_build_fast feeds them
 * from what panel_prep_build computed once per surface, clipping only the
 * triangles that cross a cell line. Everything else is this file's.
 */
#ifndef FACET_PANEL_INTERNAL_H
#define FACET_PANEL_INTERNAL_H

#include <assert.h>
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "core/panel/panel.h"

/* The grid of one panelization. */
struct panel_grid {
    const struct mesh *mesh;
    const struct uv_index *index;
    int nu, nv;
    double umin, vmin, du, dv;
};

/* Checks the grid side (1..PANEL_MAX_GRID) and the UV box's extent, fills
 * *g and the grid fields of *out (which it zeroes first). Returns FACET_OK
 * or FACET_EINPUT. */
int panel_grid_init(struct panel_grid *g, const struct mesh *mesh,
                    const struct uv_index *index, int nu, int nv,
                    struct panelization *out, struct facet_error *err);

/* The cell of coordinate x along one grid axis: floor((x - origin) / step)
 * clamped to 0..count-1, so the outermost lines cut nothing. count >= 1
 * and step > 0 (panel_grid_init checks both). */
static inline int panel_cell_coordinate(double x, double origin, double step,
                                        int count)
{
    assert(count >= 1 && step > 0);
    /* floor without its call or its rounding sequence (a tenth of the
     * paper study's instructions, issue 27): below 1 (and NaN) the cell
     * is 0, at count or above it is count - 1 (count is whole), and in
     * between the conversion's truncation is floor. */
    double f = (x - origin) / step;
    if (!(f >= 1))
        return 0;
    if (f >= count)
        return count - 1;
    return (int)f;
}

/* Pass 1 per cell. Moments are taken about a reference point of the
 * panel, so that surfaces far from the origin (site coordinates) keep
 * their precision. Symmetric 3x3 matrices are kept as xx, xy, xz, yy, yz,
 * zz. */
struct cell_moments {
    double reference[3];
    int has_reference;
    double area, uv_area;  /* m^2, UV units^2 */
    double first[3];       /* integral of (x - reference) dA */
    double second[6];      /* integral of (x - r)(x - r)^T dA */
    double normal_sum[3];  /* area-weighted face normals */
};

/* Area and moments of a part of one triangle about a point g of it. */
struct piece_moments {
    double area, uv_area;
    double first[3];       /* integral of (x - g) dA */
    double second[6];      /* integral of (x - g)(x - g)^T dA */
    double normal_sum[3];
};

/* Adds the triangle with corners a, b, c (m, relative to the point the
 * moments are about) and area area (m^2, not negative: an unsigned area,
 * whatever the corners' order) to the first and second moments of p: the
 * integral of x x^T over it is area/12 (a a^T + b b^T + c c^T + s s^T),
 * s = a + b + c. */
__attribute__((always_inline))
static inline void piece_moments_add_triangle(struct piece_moments *p,
                                              const double a[3],
                                              const double b[3],
                                              const double c[3],
                                              double area)
{
    assert(!(area < 0));
    double s[3] = {a[0] + b[0] + c[0], a[1] + b[1] + c[1],
                   a[2] + b[2] + c[2]};
    double w = area * (1.0 / 12), f = area * (1.0 / 3);
    p->first[0] += f * s[0];
    p->first[1] += f * s[1];
    p->first[2] += f * s[2];
    p->second[0] += w * (a[0] * a[0] + b[0] * b[0] + c[0] * c[0] +
                         s[0] * s[0]);
    p->second[1] += w * (a[0] * a[1] + b[0] * b[1] + c[0] * c[1] +
                         s[0] * s[1]);
    p->second[2] += w * (a[0] * a[2] + b[0] * b[2] + c[0] * c[2] +
                         s[0] * s[2]);
    p->second[3] += w * (a[1] * a[1] + b[1] * b[1] + c[1] * c[1] +
                         s[1] * s[1]);
    p->second[4] += w * (a[1] * a[2] + b[1] * b[2] + c[1] * c[2] +
                         s[1] * s[2]);
    p->second[5] += w * (a[2] * a[2] + b[2] * b[2] + c[2] * c[2] +
                         s[2] * s[2]);
}

/* Adds p, whose moments are about g (m), to cell m; the first part added
 * to a cell sets its reference point to g. p's areas are not negative. */
__attribute__((always_inline))
static inline void cell_moments_add(struct cell_moments *m,
                                    const double g[3],
                                    const struct piece_moments *p)
{
    assert(!(p->area < 0) && !(p->uv_area < 0));
    if (!m->has_reference) {
        m->reference[0] = g[0];
        m->reference[1] = g[1];
        m->reference[2] = g[2];
        m->has_reference = 1;
    }
    double d[3] = {g[0] - m->reference[0], g[1] - m->reference[1],
                   g[2] - m->reference[2]};
    double a = p->area;
    const double *f = p->first;
    /* About the reference: S + f d^T + d f^T + area d d^T. */
    m->second[0] += p->second[0] + 2 * f[0] * d[0] + a * d[0] * d[0];
    m->second[1] += p->second[1] + f[0] * d[1] + d[0] * f[1] +
                    a * d[0] * d[1];
    m->second[2] += p->second[2] + f[0] * d[2] + d[0] * f[2] +
                    a * d[0] * d[2];
    m->second[3] += p->second[3] + 2 * f[1] * d[1] + a * d[1] * d[1];
    m->second[4] += p->second[4] + f[1] * d[2] + d[1] * f[2] +
                    a * d[1] * d[2];
    m->second[5] += p->second[5] + 2 * f[2] * d[2] + a * d[2] * d[2];
    for (int x = 0; x < 3; x++) {
        m->first[x] += f[x] + a * d[x];
        m->normal_sum[x] += p->normal_sum[x];
    }
    m->area += a;
    m->uv_area += p->uv_area;
}

/* What panel_prep_build keeps of a point (a distinct (vertex, UV) corner)
 * and of a triangle. */
struct panel_prep_point {
    double position[3];  /* m */
    double k1, k2;       /* 1/m */
};

struct panel_prep_triangle {
    double area, uv_area;  /* m^2, UV units^2 */
    double centroid[3];    /* m */
    double second[6];      /* integral of (x - centroid)(x - ...)^T dA */
    double normal_sum[3];  /* area x unit face normal */
};

/* A vertex of a piece while splitting: UV and barycentric coordinates. */
struct split_vertex {
    double u, v;
    double b[3];
};

/* Enough for any piece of a triangle cut by four lines (at most 7
 * vertices, and a repeated one where a corner lies on a line); a split
 * that would exceed it drops the excess, which convex input never has. */
#define SPLIT_MAX 16

/* Splits the convex polygon in (count vertices, at most SPLIT_MAX) at
 * coordinate axis (0 u, 1 v) = limit into low (coordinate <= limit) and
 * high (>= limit), each SPLIT_MAX vertices, as two clip_half calls of
 * panel.c would, the cut points snapped to the line: a vertex on the line
 * goes to both sides. */
void panel_split(const struct split_vertex *in, int count, int axis,
                 double limit, struct split_vertex *low, int *nlow,
                 struct split_vertex *high, int *nhigh);

/* The point at barycentric b of the triangle with corners P: its position
 * (m) and curvature k1, k2 (1/m), interpolated as the mesh is. */
static inline void panel_point_at(const struct panel_prep_point *P[3],
                                  const double b[3], double position[3],
                                  double *k1, double *k2)
{
    for (int d = 0; d < 3; d++)
        position[d] = b[0] * P[0]->position[d] + b[1] * P[1]->position[d] +
                      b[2] * P[2]->position[d];
    *k1 = b[0] * P[0]->k1 + b[1] * P[1]->k1 + b[2] * P[2]->k1;
    *k2 = b[0] * P[0]->k2 + b[1] * P[1]->k2 + b[2] * P[2]->k2;
}

/* Receives one piece cut from a triangle by panel_split_cells: the convex
 * polygon piece[0..count) (count >= 3) in cell (column, row). A non-zero
 * return stops the walk and is returned by it. */
typedef int (*split_piece_visitor)(void *context, size_t column, size_t row,
                                   const struct split_vertex *piece,
                                   int count);

/* Splits triangle t of prep, whose corners span columns c0..c1 and rows
 * r0..r1 (c0 <= c1, r0 <= r1; u_line holds c1 - c0 lines from index c0 on,
 * v_line r1 - r0 from r0), row by row along v_line and then cell by cell along u_line
 * (column c lies below u_line[c], row r below v_line[r]), and hands every
 * piece of three or more vertices in rows row_lo..row_hi-1 to visit,
 * rows in order, columns in order within a row. Returns 0 or visit's
 * first non-zero return. Inline, so that a visitor known where it is
 * called is inlined with it, as the single-grid way's was before it
 * shared this walk with the lattice. */
static inline int panel_split_cells(const struct panel_prep *prep,
                                    uint32_t t,
                                    const double *u_line, size_t c0,
                                    size_t c1, const double *v_line,
                                    size_t r0, size_t r1, size_t row_lo,
                                    size_t row_hi, split_piece_visitor visit,
                                    void *context)
{
    assert(c0 <= c1 && r0 <= r1 && row_lo <= row_hi);
    const uint32_t *point = prep->corner + 3 * (size_t)t;
    /* Buffers taken in turn rather than copied: the rest of the triangle
     * (two), the row split off it, the rest of the row (two), the piece
     * split off that. */
    struct split_vertex buffer[6][SPLIT_MAX];
    struct split_vertex *rest = buffer[0], *rest_next = buffer[1];
    int nrest = 3;
    for (int k = 0; k < 3; k++) {
        rest[k].u = prep->point_uv[2 * point[k]];
        rest[k].v = prep->point_uv[2 * point[k] + 1];
        rest[k].b[0] = rest[k].b[1] = rest[k].b[2] = 0;
        rest[k].b[k] = 1;
    }
    for (size_t r = r0; r <= r1 && nrest >= 3; r++) {
        struct split_vertex *row;
        int nrow;
        if (r < r1) {
            int nnext;
            row = buffer[2];
            panel_split(rest, nrest, 1, v_line[r], row, &nrow, rest_next,
                        &nnext);
            struct split_vertex *swap = rest;
            rest = rest_next;
            rest_next = swap;
            nrest = nnext;
        } else {
            row = rest;
            nrow = nrest;
            nrest = 0;
        }
        if (r < row_lo)
            continue;
        if (r >= row_hi)
            break;
        struct split_vertex *row_next = buffer[3];
        for (size_t c = c0; c <= c1 && nrow >= 3; c++) {
            struct split_vertex *piece;
            int npiece;
            if (c < c1) {
                int nnext;
                piece = buffer[5];
                panel_split(row, nrow, 0, u_line[c], piece, &npiece,
                            row_next, &nnext);
                row = row_next;
                row_next = row_next == buffer[3] ? buffer[4] : buffer[3];
                nrow = nnext;
            } else {
                piece = row;
                npiece = nrow;
                nrow = 0;
            }
            if (npiece < 3)
                continue;
            int stop = visit(context, c, r, piece, npiece);
            if (stop != 0)
                return stop;
        }
    }
    return 0;
}

/* The corners of triangle t of prep relative to its centroid (m): what
 * panel_piece_moments takes. */
void panel_triangle_corners(const struct panel_prep *prep, uint32_t t,
                            double corner[3][3]);

/* The moments of a piece (count vertices, barycentric in triangle T) about
 * T's centroid, from the fan of its barycentric polygon; corner holds T's
 * corners relative to its centroid (m). */
void panel_piece_moments(const struct panel_prep_triangle *T,
                         const double corner[3][3],
                         const struct split_vertex *piece, int count,
                         struct piece_moments *m);

/* A whole triangle's sums into a cell. */
static inline void cell_moments_add_triangle(
    struct cell_moments *m, const struct panel_prep_triangle *T)
{
    assert(!(T->area < 0) && !(T->uv_area < 0));
    if (!m->has_reference) {
        memcpy(m->reference, T->centroid, sizeof m->reference);
        m->has_reference = 1;
    }
    double d[3] = {T->centroid[0] - m->reference[0],
                   T->centroid[1] - m->reference[1],
                   T->centroid[2] - m->reference[2]};
    double a = T->area;
    double ad[3] = {a * d[0], a * d[1], a * d[2]};
    m->area += a;
    m->uv_area += T->uv_area;
    m->first[0] += ad[0];
    m->first[1] += ad[1];
    m->first[2] += ad[2];
    m->second[0] += T->second[0] + ad[0] * d[0];
    m->second[1] += T->second[1] + ad[0] * d[1];
    m->second[2] += T->second[2] + ad[0] * d[2];
    m->second[3] += T->second[3] + ad[1] * d[1];
    m->second[4] += T->second[4] + ad[1] * d[2];
    m->second[5] += T->second[5] + ad[2] * d[2];
    m->normal_sum[0] += T->normal_sum[0];
    m->normal_sum[1] += T->normal_sum[1];
    m->normal_sum[2] += T->normal_sum[2];
}

/* Pass 2 per panel. */
struct cell_samples {
    double centroid[3], normal[3];  /* the panel's plane */
    double deviation;               /* largest distance from it so far */
    double k1_edge, k2_edge;  /* over samples on mesh vertices and edges */
    double k1_any, k2_any;    /* over every piece vertex: the fallback */
    int edge_samples;
    int outline;              /* index into the outlines, or -1 when the
                                 panel's diameter comes from its corners */
    double shape[9];          /* integral of the shape operator dA */
};

/* The extent of a panel's outline along 13 directions. */
struct cell_outline {
    double low[13], high[13];
    double low_point[13][3], high_point[13][3];
};

/* Directions along which the outline's extent is measured: its diameter is
 * the largest distance between the extreme points found, which is within
 * a few percent of the exact diameter and cheap for any panel size. */
extern const double panel_extent_direction[13][3];

/* Whether a point p at along (its extent along a direction) takes the
 * place of the extreme so far, best at best_point, for a maximum (sign
 * 1) or a minimum (-1). Extents within rounding of each other tie, and a
 * tie goes to the point with the larger coordinates (x, then y, then z):
 * on a symmetric surface two mirror points are extreme to the last bit,
 * and which one is kept must not depend on the order the points come in
 * (the three ways of measuring panels take them in three orders). */
static inline int outline_wins(double along, const double p[3], double best,
                               const double best_point[3], double sign)
{
    assert(sign == 1 || sign == -1);
    if (isinf(best))
        return 1;
    double tolerance = 1e-12 * fmax(fabs(along), fabs(best));
    double ahead = sign * (along - best);
    if (ahead > tolerance)
        return 1;
    if (ahead < -tolerance)
        return 0;
    for (int x = 0; x < 3; x++)
        if (p[x] != best_point[x])
            return p[x] > best_point[x];
    return 0;
}

/* Takes point p (m) into the outline o. */
static inline void cell_outline_take(struct cell_outline *o, const double p[3])
{
    for (int e = 0; e < 13; e++) {
        const double *dir = panel_extent_direction[e];
        double along = p[0] * dir[0] + p[1] * dir[1] + p[2] * dir[2];
        if (outline_wins(along, p, o->low[e], o->low_point[e], -1)) {
            o->low[e] = along;
            o->low_point[e][0] = p[0];
            o->low_point[e][1] = p[1];
            o->low_point[e][2] = p[2];
        }
        if (outline_wins(along, p, o->high[e], o->high_point[e], 1)) {
            o->high[e] = along;
            o->high_point[e][0] = p[0];
            o->high_point[e][1] = p[1];
            o->high_point[e][2] = p[2];
        }
    }
}

/* Takes point p (m) of the panel's surface, with curvature k1, k2 there,
 * into s (and its outline o when not NULL); edge says p lies on a mesh
 * vertex or edge, the paper's samples. */
static inline void cell_sample(struct cell_samples *s,
                               struct cell_outline *o, const double p[3],
                               double k1, double k2, int edge)
{
    double distance = fabs((p[0] - s->centroid[0]) * s->normal[0] +
                           (p[1] - s->centroid[1]) * s->normal[1] +
                           (p[2] - s->centroid[2]) * s->normal[2]);
    if (distance > s->deviation)
        s->deviation = distance;
    if (k1 > s->k1_any)
        s->k1_any = k1;
    if (k2 < s->k2_any)
        s->k2_any = k2;
    if (edge) {
        if (k1 > s->k1_edge)
            s->k1_edge = k1;
        if (k2 < s->k2_edge)
            s->k2_edge = k2;
        s->edge_samples++;
    }
    if (o != NULL)
        cell_outline_take(o, p);
}

/* Adds piece_area (m^2) times the shape operator of mesh triangle t at
 * barycentric point centroid to s->shape. */
void cell_samples_add_shape(struct cell_samples *s,
                            const struct mesh *mesh,
                            const struct curvature *curvature, uint32_t t,
                            double piece_area, const double centroid[3]);

/* A grid node ((nu + 1) x (nv + 1) of them, at [nj * (nu + 1) + ni]) as
 * panels_fit locates it on the surface. */
struct grid_node {
    int state;         /* 0 not yet located, 1 on the surface, -1 off it */
    double point[3];   /* where it is on the surface (m), state 1 */
};

/* Makes the panels of the cells with area (out->panels, out->cell_panel,
 * their area, plane, P_dist and corners) from the pass 1 sums, and the pass
 * 2 state for each panel: *samples (npanels) and *outlines (one per
 * panel whose outline is needed), both malloc'ed for the caller to free.
 * known (or NULL) holds the grid nodes the caller knows already (state 1),
 * the others zeroed; panels_fit locates those it needs in it. stop (NULL:
 * never) is asked every few thousand cells. Returns FACET_OK, FACET_EWORK,
 * or FACET_ESTOP when stop fired (nothing in *samples, *outlines). */
int panels_fit(const struct panel_grid *g, const struct cell_moments *sums,
               struct grid_node *known, const struct facet_stop *stop,
               struct panelization *out, struct cell_samples **samples,
               struct cell_outline **outlines, struct facet_error *err);

/* Sets each panel's deviation, k1, k2 and diameter from its samples. */
void panels_finish(enum panel_curvature_mode mode,
                   const struct cell_samples *samples,
                   const struct cell_outline *outlines,
                   struct panelization *out);

/* What panels_curvature_range takes of one mesh triangle: over its three
 * vertices, with e1 = c k1_error and e2 = c k2_error (c
 * CURVATURE_ERROR_SIGMAS), the largest k1 - e1 and k1 + e1, the least
 * k2 - e2 and k2 + e2, and the largest e1 and e2 (-INFINITY, INFINITY
 * and -INFINITY where every vertex's is NaN). They depend on the mesh
 * alone, so a prepared surface keeps them (panel_prep_build) and every
 * grid reads six numbers a triangle in order rather than twelve from its
 * vertices: that scan was 18 % of the paper's study (issue 27). */
struct triangle_curvature_range {
    double k1_low, k1_high;  /* 1/m */
    double k2_low, k2_high;  /* 1/m */
    double e1, e2;           /* 1/m */
};

/* The ranges of every triangle of mesh (#T, malloc'd, the caller's to
 * free) into *out, or NULL when curvature holds no errors (nothing to
 * range). Returns FACET_OK, or FACET_EWORK when out of memory. */
int triangle_curvature_ranges(const struct mesh *mesh,
                              const struct curvature *curvature,
                              struct triangle_curvature_range **out);

/* Sets each panel's k1_error and k2_error (panel.h) to the range each is
 * known to: by the paper's
 * extremes, k1's range is from the largest k1 - c e1 to the largest k1 +
 * c e1 over the vertices of the mesh triangles whose UV box meets its
 * cell, e1 their k1_error (curvature.h) and c CURVATURE_ERROR_SIGMAS, and
 * k2's from the least k2 - c e2 to the least k2 + c e2; each widened to
 * hold the panel's own k1, k2 (so that the errors are >= 0). So a panel's curvature counts as known
 * where some vertex knows it, whatever a worse-known vertex beside it
 * reads (a coarse cone's corner vertex, fitted one-sided on few points,
 * is known to 0.15 1/m, which alone would have turned its panel's 0.2
 * 1/m flat). The samples of a panel are interpolated between those
 * vertices, so that is the range of their extremes, on the safe side
 * where a triangle only touches the cell. By the mean (mode), and for a
 * panel with no such vertex, each is its k give or take the largest c e.
 * The same for every way of building panels, as it reads the mesh and
 * grid alone: ranges are the triangles' (triangle_curvature_ranges; NULL:
 * no errors known, each panel's range 0). The extremes of the triangles'
 * extremes are the vertices' to the bit: fmax and fmin keep the first of
 * equal values (+0, -0), so a running extreme ends at the first value no
 * other exceeds, however the values are grouped. Returns FACET_OK, or
 * FACET_EWORK when out of memory. */
int panels_curvature_range(const struct panel_grid *g,
                           const struct triangle_curvature_range *ranges,
                           enum panel_curvature_mode mode,
                           struct panelization *out);

/* Calls visit for every non-empty piece of triangle t: panels_walk_pieces
 * for one triangle. */
void panel_walk_triangle(const struct panel_grid *g, uint32_t t,
                         panel_piece_visitor visit, void *context);

/* Pass 2 for the piece of mesh triangle t in cell as panels_build takes
 * it: every piece vertex a sample, and in PANEL_MEAN mode the shape
 * operator (mean set) or not (mean clear). */
struct sample_context {
    const struct panel_grid *grid;
    const struct curvature *curvature;
    const int *cell_panel;
    struct cell_samples *samples;
    struct cell_outline *outlines;
    int points;   /* sample the piece's vertices */
    int shape;    /* add the shape operator (PANEL_MEAN) */
};
void panel_sample_piece(void *context, size_t cell, uint32_t t,
                        const struct panel_piece_vertex *piece, int count);

#endif
