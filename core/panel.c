/*
 * panel.c: clipping the mesh to the UV grid and measuring every panel.
 * See panel.h.
 *
 * Two passes over the clipped pieces, which are cheap to recompute and so
 * are never stored: the first sums each panel's area and its first and
 * second moments (for the least-squares plane), the second, once the planes
 * are known, takes the largest distance from the plane, samples curvature
 * and finds the outline's extent.
 */
#include "panel.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "sym3.h"
#include "vec3.h"

/* What pass 1 accumulates per cell. Moments are taken about a reference
 * point of the panel, so that surfaces far from the origin (site
 * coordinates) keep their precision. */
struct cell_sums {
    double reference[3];
    int has_reference;
    double area, uv_area;
    double first[3];       /* integral of (x - reference) dA */
    double second[9];      /* integral of (x - r)(x - r)^T dA */
    double normal_sum[3];  /* area-weighted face normals */
    /* Pass 2: */
    int need_outline;          /* trimmed or not all corners on the surface */
    double extreme_low[13], extreme_high[13];  /* outline extent */
    double extreme_low_point[13][3], extreme_high_point[13][3];
    double k1_edge, k2_edge;   /* over samples on mesh vertices and edges */
    double k1_any, k2_any;     /* over every piece vertex: the fallback */
    int edge_samples;
    double shape[9];           /* integral of the shape operator dA */
};

/* Directions along which the outline's extent is measured: its diameter is
 * the largest distance between the extreme points found, which is within
 * a few percent of the exact diameter and cheap for any panel size. */
static const double extent_direction[13][3] = {
    {1, 0, 0}, {0, 1, 0}, {0, 0, 1},
    {1, 1, 0}, {1, -1, 0}, {1, 0, 1}, {1, 0, -1}, {0, 1, 1}, {0, 1, -1},
    {1, 1, 1}, {1, 1, -1}, {1, -1, 1}, {-1, 1, 1},
};

/* Clips the convex piece in (count vertices) to the half-plane
 * side * (coordinate - limit) >= 0, coordinate being u (axis 0) or v
 * (axis 1), into out; returns out's vertex count. */
static int clip_half(const struct panel_piece_vertex *in, int count,
                     struct panel_piece_vertex *out, int axis, double limit,
                     double side)
{
    int n = 0;
    for (int k = 0; k < count; k++) {
        const struct panel_piece_vertex *p = &in[k];
        const struct panel_piece_vertex *q = &in[(k + 1) % count];
        double dp = side * ((axis == 0 ? p->u : p->v) - limit);
        double dq = side * ((axis == 0 ? q->u : q->v) - limit);
        if (dp >= 0)
            out[n++] = *p;
        if ((dp >= 0) != (dq >= 0)) {
            double t = dp / (dp - dq);
            struct panel_piece_vertex *x = &out[n++];
            x->u = p->u + t * (q->u - p->u);
            x->v = p->v + t * (q->v - p->v);
            for (int c = 0; c < 3; c++)
                x->b[c] = p->b[c] + t * (q->b[c] - p->b[c]);
            /* Snap the cut coordinate so neighbouring cells share it. */
            if (axis == 0)
                x->u = limit;
            else
                x->v = limit;
        }
    }
    return n;
}

/* clip_half on poly itself; returns the new vertex count. */
static int clip_in_place(struct panel_piece_vertex *poly, int count, int axis,
                         double limit, double side)
{
    struct panel_piece_vertex clipped[PANEL_PIECE_MAX];
    if (count < 3)
        return 0;
    int n = clip_half(poly, count, clipped, axis, limit, side);
    memcpy(poly, clipped, sizeof clipped[0] * (size_t)n);
    return n;
}

struct grid_walk {
    const struct mesh *mesh;
    const struct uv_index *index;
    int nu, nv;
    double umin, vmin, du, dv;
};

static int cell_coordinate(double x, double origin, double step, int count)
{
    double f = floor((x - origin) / step);
    if (!(f > 0))
        return 0;
    if (f >= count)
        return count - 1;
    return (int)f;
}

/* Calls visit for every non-empty piece of every triangle in every cell. The
 * grid's outermost lines are not clipped against, so that no sliver of the
 * surface is lost to rounding at the UV box's edges. */
static void walk_pieces(const struct grid_walk *g, panel_piece_visitor visit,
                        void *context)
{
    const double *uv = g->index->uv;
    for (size_t t = 0; t < g->mesh->ntriangles; t++) {
        const double *c = uv + 6 * t;
        double u0 = fmin(c[0], fmin(c[2], c[4]));
        double u1 = fmax(c[0], fmax(c[2], c[4]));
        double v0 = fmin(c[1], fmin(c[3], c[5]));
        double v1 = fmax(c[1], fmax(c[3], c[5]));
        int i0 = cell_coordinate(u0, g->umin, g->du, g->nu);
        int i1 = cell_coordinate(u1, g->umin, g->du, g->nu);
        int j0 = cell_coordinate(v0, g->vmin, g->dv, g->nv);
        int j1 = cell_coordinate(v1, g->vmin, g->dv, g->nv);
        struct panel_piece_vertex start[3];
        for (int k = 0; k < 3; k++) {
            start[k].u = c[2 * k];
            start[k].v = c[2 * k + 1];
            start[k].b[0] = start[k].b[1] = start[k].b[2] = 0;
            start[k].b[k] = 1;
        }
        if (i0 == i1 && j0 == j1) {
            /* Inside one cell: the triangle is its own piece. */
            visit(context, (size_t)j0 * g->nu + i0, (uint32_t)t, start, 3);
            continue;
        }
        for (int j = j0; j <= j1; j++)
            for (int i = i0; i <= i1; i++) {
                struct panel_piece_vertex a[PANEL_PIECE_MAX];
                int n = 3;
                memcpy(a, start, sizeof start);
                /* A side the whole triangle lies within cuts nothing. */
                if (i > i0)
                    n = clip_in_place(a, n, 0, g->umin + i * g->du, 1);
                if (i < i1)
                    n = clip_in_place(a, n, 0, g->umin + (i + 1) * g->du, -1);
                if (j > j0)
                    n = clip_in_place(a, n, 1, g->vmin + j * g->dv, 1);
                if (j < j1)
                    n = clip_in_place(a, n, 1, g->vmin + (j + 1) * g->dv, -1);
                if (n >= 3)
                    visit(context, (size_t)j * g->nu + i, (uint32_t)t, a, n);
            }
    }
}

void panels_walk_pieces(const struct mesh *mesh,
                        const struct uv_index *index, int nu, int nv,
                        panel_piece_visitor visit, void *context)
{
    /* The same grid panels_build makes, so the pieces are its pieces. */
    struct grid_walk grid = {
        mesh, index, nu, nv, index->umin, index->vmin,
        (index->umax - index->umin) / nu, (index->vmax - index->vmin) / nv,
    };
    if (nu < 1 || nv < 1 || !(grid.du > 0) || !(grid.dv > 0))
        return;
    walk_pieces(&grid, visit, context);
}

void panel_piece_point(const struct mesh *mesh, uint32_t t,
                       const struct panel_piece_vertex *p, double out[3])
{
    const uint32_t *tri = mesh->triangle + 3 * (size_t)t;
    for (int k = 0; k < 3; k++)
        out[k] = p->b[0] * mesh->position[3 * tri[0] + k] +
                 p->b[1] * mesh->position[3 * tri[1] + k] +
                 p->b[2] * mesh->position[3 * tri[2] + k];
}

struct pass_context {
    const struct grid_walk *grid;
    const struct curvature *curvature;
    enum panel_curvature_mode mode;
    struct cell_sums *sums;
    struct panelization *out;
};

/* Pass 1: area and moments, exact for the planar piece (fanned into
 * triangles; the integral of x x^T over a triangle of area A with corners
 * a, b, c is A/12 (a a^T + b b^T + c c^T + s s^T), s = a + b + c). */
static void sum_moments(void *context, size_t cell, uint32_t t,
                        const struct panel_piece_vertex *piece, int count)
{
    struct pass_context *pc = context;
    struct cell_sums *s = &pc->sums[cell];
    const struct mesh *mesh = pc->grid->mesh;
    double point[PANEL_PIECE_MAX][3];
    for (int k = 0; k < count; k++)
        panel_piece_point(mesh, t, &piece[k], point[k]);
    if (!s->has_reference) {
        memcpy(s->reference, point[0], sizeof s->reference);
        s->has_reference = 1;
    }
    for (int k = 0; k < count; k++)
        for (int c = 0; c < 3; c++)
            point[k][c] -= s->reference[c];

    for (int k = 1; k + 1 < count; k++) {
        const double *a = point[0], *b = point[k], *c = point[k + 1];
        double ab[3], ac[3], n[3];
        for (int x = 0; x < 3; x++) {
            ab[x] = b[x] - a[x];
            ac[x] = c[x] - a[x];
        }
        vec3_cross(ab, ac, n);
        double area = 0.5 * sqrt(vec3_dot(n, n));
        double uv_area = 0.5 * fabs((piece[k].u - piece[0].u) *
                                    (piece[k + 1].v - piece[0].v) -
                                    (piece[k + 1].u - piece[0].u) *
                                    (piece[k].v - piece[0].v));
        s->area += area;
        s->uv_area += uv_area;
        double sum[3];
        for (int x = 0; x < 3; x++) {
            sum[x] = a[x] + b[x] + c[x];
            s->first[x] += area * sum[x] / 3;
        }
        for (int r = 0; r < 3; r++)
            for (int q = 0; q < 3; q++)
                s->second[3 * r + q] += area / 12 *
                    (a[r] * a[q] + b[r] * b[q] + c[r] * c[q] +
                     sum[r] * sum[q]);
        for (int x = 0; x < 3; x++)
            s->normal_sum[x] += area * mesh->face_normal[3 * (size_t)t + x];
    }
}

/* Pass 2: distance from the plane, curvature samples, outline extent. */
static void sample_piece(void *context, size_t cell, uint32_t t,
                         const struct panel_piece_vertex *piece, int count)
{
    struct pass_context *pc = context;
    struct cell_sums *s = &pc->sums[cell];
    struct panel *panel = &pc->out->panels[pc->out->cell_panel[cell]];
    const struct mesh *mesh = pc->grid->mesh;
    const struct curvature *cv = pc->curvature;
    const uint32_t *tri = mesh->triangle + 3 * (size_t)t;

    double centroid[3] = {0, 0, 0}, piece_area = 0;
    for (int k = 0; k < count; k++) {
        double p[3], d[3];
        panel_piece_point(mesh, t, &piece[k], p);
        for (int x = 0; x < 3; x++)
            d[x] = p[x] - panel->centroid[x];
        double distance = fabs(vec3_dot(d, panel->normal));
        if (distance > panel->deviation)
            panel->deviation = distance;
        for (int e = 0; s->need_outline && e < 13; e++) {
            double along = vec3_dot(p, extent_direction[e]);
            if (along < s->extreme_low[e]) {
                s->extreme_low[e] = along;
                memcpy(s->extreme_low_point[e], p, sizeof p);
            }
            if (along > s->extreme_high[e]) {
                s->extreme_high[e] = along;
                memcpy(s->extreme_high_point[e], p, sizeof p);
            }
        }

        const double *b = piece[k].b;
        double k1 = b[0] * cv->k1[tri[0]] + b[1] * cv->k1[tri[1]] +
                    b[2] * cv->k1[tri[2]];
        double k2 = b[0] * cv->k2[tri[0]] + b[1] * cv->k2[tri[1]] +
                    b[2] * cv->k2[tri[2]];
        if (k1 > s->k1_any)
            s->k1_any = k1;
        if (k2 < s->k2_any)
            s->k2_any = k2;
        /* The paper's samples: mesh vertices inside the cell and points
         * where the cell's border cuts a mesh edge (one barycentric 0). */
        if (b[0] <= 1e-12 || b[1] <= 1e-12 || b[2] <= 1e-12) {
            if (k1 > s->k1_edge)
                s->k1_edge = k1;
            if (k2 < s->k2_edge)
                s->k2_edge = k2;
            s->edge_samples++;
        }
        for (int x = 0; x < 3; x++)
            centroid[x] += b[x] / count;
    }

    if (pc->mode == PANEL_MEAN) {
        /* The shape operator is linear over the triangle, so its integral
         * over the piece is the piece's area times its value at the piece's
         * area centroid; the vertex average is close enough for the small
         * pieces a cell cuts, and exact for triangles. */
        for (int k = 1; k + 1 < count; k++) {
            double a[3], bb[3], c[3], ab[3], ac[3], n[3];
            panel_piece_point(mesh, t, &piece[0], a);
            panel_piece_point(mesh, t, &piece[k], bb);
            panel_piece_point(mesh, t, &piece[k + 1], c);
            for (int x = 0; x < 3; x++) {
                ab[x] = bb[x] - a[x];
                ac[x] = c[x] - a[x];
            }
            vec3_cross(ab, ac, n);
            piece_area += 0.5 * sqrt(vec3_dot(n, n));
        }
        for (int corner = 0; corner < 3; corner++) {
            uint32_t v = tri[corner];
            const double *d1 = cv->dir1 + 3 * (size_t)v;
            const double *d2 = cv->dir2 + 3 * (size_t)v;
            for (int r = 0; r < 3; r++)
                for (int q = 0; q < 3; q++)
                    s->shape[3 * r + q] += piece_area * centroid[corner] *
                        (cv->k1[v] * d1[r] * d1[q] +
                         cv->k2[v] * d2[r] * d2[q]);
        }
    }
}

/* The panel's k1 >= k2 from the mean shape operator: its two eigenvalues
 * whose eigenvectors lie in the panel's plane. */
static void mean_curvature_of(const struct cell_sums *s, struct panel *panel)
{
    double projected[9], value[3], vector[3][3];
    double p[9];
    for (int r = 0; r < 3; r++)
        for (int q = 0; q < 3; q++)
            p[3 * r + q] = (r == q) - panel->normal[r] * panel->normal[q];
    /* P S P / area, P the projection onto the plane. */
    for (int r = 0; r < 3; r++)
        for (int q = 0; q < 3; q++) {
            double sum = 0;
            for (int x = 0; x < 3; x++)
                for (int y = 0; y < 3; y++)
                    sum += p[3 * r + x] * s->shape[3 * x + y] * p[3 * y + q];
            projected[3 * r + q] = panel->area > 0 ? sum / panel->area : 0;
        }
    sym3_eigen(projected, value, vector);
    /* Drop the eigenvalue whose vector is along the normal. */
    int normal_k = 0;
    double best = -1;
    for (int k = 0; k < 3; k++) {
        double along = fabs(vec3_dot(vector[k], panel->normal));
        if (along > best) {
            best = along;
            normal_k = k;
        }
    }
    double kept[2];
    int n = 0;
    for (int k = 0; k < 3; k++)
        if (k != normal_k)
            kept[n++] = value[k];
    panel->k1 = fmax(kept[0], kept[1]);
    panel->k2 = fmin(kept[0], kept[1]);
}

/* Locates the cell corners on the surface and measures the quad. */
static void measure_corners(const struct grid_walk *g, struct panel *panel)
{
    static const int offset[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    double extent = fmax(g->du * g->nu, g->dv * g->nv);
    panel->ncorners = 0;
    for (int c = 0; c < 4; c++) {
        double u = g->umin + (panel->i + offset[c][0]) * g->du;
        double v = g->vmin + (panel->j + offset[c][1]) * g->dv;
        double b[3];
        uint32_t t = uv_index_locate(g->index, u, v, 1e-9 * (extent > 0),
                                     b);
        if (t == UINT32_MAX) {
            panel->corner[c][0] = panel->corner[c][1] =
                panel->corner[c][2] = NAN;
            continue;
        }
        struct panel_piece_vertex p = {u, v, {b[0], b[1], b[2]}};
        panel_piece_point(g->mesh, t, &p, panel->corner[c]);
        panel->ncorners++;
    }
    panel->corner_planarity = NAN;
    if (panel->ncorners == 4) {
        double d1[3], d2[3], w[3], n[3];
        for (int x = 0; x < 3; x++) {
            d1[x] = panel->corner[2][x] - panel->corner[0][x];
            d2[x] = panel->corner[3][x] - panel->corner[1][x];
            w[x] = panel->corner[1][x] - panel->corner[0][x];
        }
        vec3_cross(d1, d2, n);
        double length = sqrt(vec3_dot(n, n));
        panel->corner_planarity = length > 0 ? fabs(vec3_dot(w, n)) / length : 0;
    }
}

int panels_build(const struct mesh *mesh, const struct uv_index *index,
                 const struct curvature *curvature,
                 enum panel_curvature_mode mode, int nu, int nv,
                 struct panelization *out, struct facet_error *err)
{
    memset(out, 0, sizeof *out);
    if (nu < 1 || nv < 1 || nu > PANEL_MAX_GRID || nv > PANEL_MAX_GRID)
        return facet_error_set(err, FACET_EINPUT,
            "grid %dx%d is out of range (each side 1 to %d)", nu, nv,
            PANEL_MAX_GRID);
    out->nu = nu;
    out->nv = nv;
    out->umin = index->umin;
    out->vmin = index->vmin;
    out->umax = index->umax;
    out->vmax = index->vmax;

    struct grid_walk grid = {
        mesh, index, nu, nv, index->umin, index->vmin,
        (index->umax - index->umin) / nu, (index->vmax - index->vmin) / nv,
    };
    if (!(grid.du > 0) || !(grid.dv > 0))
        return facet_error_set(err, FACET_EINPUT,
            "the UV map has no extent (all texture coordinates equal in u "
            "or in v)");

    size_t ncells = (size_t)nu * (size_t)nv;
    struct cell_sums *sums = calloc(ncells, sizeof *sums);
    out->cell_panel = malloc(ncells * sizeof *out->cell_panel);
    if (sums == NULL || out->cell_panel == NULL) {
        free(sums);
        return facet_error_set(err, FACET_EWORK, "out of memory (panels)");
    }
    struct pass_context pc = {&grid, curvature, mode, sums, out};
    walk_pieces(&grid, sum_moments, &pc);

    for (size_t c = 0; c < ncells; c++) {
        out->cell_panel[c] = sums[c].area > 0 ? (int)out->npanels : -1;
        if (sums[c].area > 0)
            out->npanels++;
    }
    out->panels = calloc(out->npanels ? out->npanels : 1,
                         sizeof *out->panels);
    if (out->panels == NULL) {
        free(sums);
        return facet_error_set(err, FACET_EWORK, "out of memory (panels)");
    }

    double cell_uv_area = grid.du * grid.dv;
    for (size_t c = 0; c < ncells; c++) {
        if (out->cell_panel[c] < 0)
            continue;
        struct cell_sums *s = &sums[c];
        struct panel *panel = &out->panels[out->cell_panel[c]];
        panel->i = (int)(c % (size_t)nu);
        panel->j = (int)(c / (size_t)nu);
        panel->area = s->area;
        panel->uv_area = s->uv_area;
        panel->trimmed = s->uv_area < cell_uv_area * (1 - 1e-9);

        double mean[3], covariance[9], value[3], vector[3][3];
        for (int x = 0; x < 3; x++) {
            mean[x] = s->first[x] / s->area;
            panel->centroid[x] = s->reference[x] + mean[x];
        }
        for (int r = 0; r < 3; r++)
            for (int q = 0; q < 3; q++)
                covariance[3 * r + q] = s->second[3 * r + q] / s->area -
                                        mean[r] * mean[q];
        sym3_eigen(covariance, value, vector);
        memcpy(panel->normal, vector[0], sizeof panel->normal);
        if (vec3_dot(panel->normal, s->normal_sum) < 0)
            for (int x = 0; x < 3; x++)
                panel->normal[x] = -panel->normal[x];
        panel->p_dist = fmax(value[0], 0) * s->area;

        for (int e = 0; e < 13; e++) {
            s->extreme_low[e] = INFINITY;
            s->extreme_high[e] = -INFINITY;
        }
        s->k1_edge = s->k1_any = -INFINITY;
        s->k2_edge = s->k2_any = INFINITY;
        measure_corners(&grid, panel);
        s->need_outline = panel->trimmed || panel->ncorners < 4;
    }

    walk_pieces(&grid, sample_piece, &pc);

    for (size_t c = 0; c < ncells; c++) {
        if (out->cell_panel[c] < 0)
            continue;
        struct cell_sums *s = &sums[c];
        struct panel *panel = &out->panels[out->cell_panel[c]];
        if (mode == PANEL_MEAN) {
            mean_curvature_of(s, panel);
        } else if (s->edge_samples > 0) {
            panel->k1 = s->k1_edge;
            panel->k2 = s->k2_edge;
        } else {
            panel->k1 = s->k1_any;
            panel->k2 = s->k2_any;
        }
        if (!s->need_outline) {
            panel->diameter = fmax(vec3_distance(panel->corner[0],
                                            panel->corner[2]),
                                   vec3_distance(panel->corner[1],
                                            panel->corner[3]));
        } else {
            double diameter = 0;
            for (int a = 0; a < 13; a++)
                for (int b = 0; b < 13; b++) {
                    diameter = fmax(diameter,
                        vec3_distance(s->extreme_low_point[a],
                                 s->extreme_high_point[b]));
                    diameter = fmax(diameter,
                        vec3_distance(s->extreme_low_point[a],
                                 s->extreme_low_point[b]));
                }
            panel->diameter = diameter;
        }
    }
    free(sums);
    return FACET_OK;
}

void panelization_free(struct panelization *panelization)
{
    free(panelization->panels);
    free(panelization->cell_panel);
    memset(panelization, 0, sizeof *panelization);
}
