/*
 * panel.c: clipping the mesh to the UV grid and measuring every panel.
 * See panel.h; panel_internal.h says what this file shares with panel_fast.c.
 *
 * panels_build is the straightforward measurement: two passes over the
 * clipped pieces of every triangle, which are cheap to recompute and so are
 * never stored. The first sums each panel's area and its first and second
 * moments (for the least-squares plane), the second, once the planes are
 * known, takes the largest distance from the plane, samples curvature and
 * finds the outline's extent. panels_build_fast (panel_fast.c) gives the
 * same panels from per-surface sums and is what option_evaluate uses;
 * panels_build is the oracle it is tested against. Fitting the planes and
 * finishing the panels from the two passes' sums is here, for both.
 */
#include "core/panel/panel.h"

#include <assert.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/panel/panel_internal.h"
#include "core/base/extremes.h"
#include "core/base/sym3.h"
#include "core/base/quad.h"
#include "core/base/vec3.h"

const char *panel_mode_name(enum panel_curvature_mode mode)
{
    return mode == PANEL_MEAN ? "mean" : "extremes";
}

int panel_mode_parse(const char *text, const char *what,
                     enum panel_curvature_mode *out, struct facet_error *err)
{
    static const enum panel_curvature_mode all[] = {PANEL_EXTREMES,
                                                    PANEL_MEAN};
    for (size_t k = 0; k < sizeof all / sizeof all[0]; k++)
        if (strcmp(text, panel_mode_name(all[k])) == 0) {
            *out = all[k];
            return FACET_OK;
        }
    return facet_error_set(err, FACET_EINPUT,
                           "%s: '%s' is not extremes or mean", what, text);
}

const double panel_extent_direction[13][3] = {
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

int panel_grid_init(struct panel_grid *g, const struct mesh *mesh,
                    const struct uv_index *index, int nu, int nv,
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
    *g = (struct panel_grid){
        mesh, index, nu, nv, index->umin, index->vmin,
        (index->umax - index->umin) / nu, (index->vmax - index->vmin) / nv,
    };
    if (!(g->du > 0) || !(g->dv > 0))
        return facet_error_set(err, FACET_EINPUT,
            "the UV map has no extent (all texture coordinates equal in u "
            "or in v)");
    return FACET_OK;
}

/* The grid's outermost lines are not clipped against, so that no sliver of
 * the surface is lost to rounding at the UV box's edges. */
void panel_walk_triangle(const struct panel_grid *g, uint32_t t,
                         panel_piece_visitor visit, void *context)
{
    const double *c = g->index->uv + 6 * (size_t)t;
    double u0 = smaller(c[0], smaller(c[2], c[4]));
    double u1 = larger(c[0], larger(c[2], c[4]));
    double v0 = smaller(c[1], smaller(c[3], c[5]));
    double v1 = larger(c[1], larger(c[3], c[5]));
    int i0 = panel_cell_coordinate(u0, g->umin, g->du, g->nu);
    int i1 = panel_cell_coordinate(u1, g->umin, g->du, g->nu);
    int j0 = panel_cell_coordinate(v0, g->vmin, g->dv, g->nv);
    int j1 = panel_cell_coordinate(v1, g->vmin, g->dv, g->nv);
    struct panel_piece_vertex start[3];
    for (int k = 0; k < 3; k++) {
        start[k].u = c[2 * k];
        start[k].v = c[2 * k + 1];
        start[k].b[0] = start[k].b[1] = start[k].b[2] = 0;
        start[k].b[k] = 1;
    }
    if (i0 == i1 && j0 == j1) {
        /* Inside one cell: the triangle is its own piece. */
        visit(context, (size_t)j0 * g->nu + i0, t, start, 3);
        return;
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
                visit(context, (size_t)j * g->nu + i, t, a, n);
        }
}

void panels_walk_pieces(const struct mesh *mesh,
                        const struct uv_index *index, int nu, int nv,
                        panel_piece_visitor visit, void *context)
{
    /* The same grid panels_build makes, so the pieces are its pieces. */
    struct panel_grid grid = {
        mesh, index, nu, nv, index->umin, index->vmin,
        (index->umax - index->umin) / nu, (index->vmax - index->vmin) / nv,
    };
    if (nu < 1 || nv < 1 || !(grid.du > 0) || !(grid.dv > 0))
        return;
    for (size_t t = 0; t < mesh->ntriangles; t++)
        panel_walk_triangle(&grid, (uint32_t)t, visit, context);
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

struct moments_context {
    const struct mesh *mesh;
    struct cell_moments *sums;
};

/* Pass 1: area and moments, exact for the planar piece (fanned into
 * triangles about its first vertex). */
static void sum_piece_moments(void *context, size_t cell, uint32_t t,
                              const struct panel_piece_vertex *piece,
                              int count)
{
    struct moments_context *mc = context;
    const struct mesh *mesh = mc->mesh;
    double origin[3], point[PANEL_PIECE_MAX][3];
    panel_piece_point(mesh, t, &piece[0], origin);
    for (int k = 0; k < count; k++) {
        panel_piece_point(mesh, t, &piece[k], point[k]);
        for (int c = 0; c < 3; c++)
            point[k][c] -= origin[c];
    }
    struct piece_moments p;
    memset(&p, 0, sizeof p);
    for (int k = 1; k + 1 < count; k++) {
        double n[3];
        vec3_cross(point[k], point[k + 1], n);
        double area = 0.5 * sqrt(vec3_dot(n, n));
        p.area += area;
        p.uv_area += 0.5 * fabs((piece[k].u - piece[0].u) *
                                (piece[k + 1].v - piece[0].v) -
                                (piece[k + 1].u - piece[0].u) *
                                (piece[k].v - piece[0].v));
        piece_moments_add_triangle(&p, point[0], point[k], point[k + 1],
                                   area);
    }
    for (int x = 0; x < 3; x++)
        p.normal_sum[x] = p.area * mesh->face_normal[3 * (size_t)t + x];
    cell_moments_add(&mc->sums[cell], origin, &p);
}

void cell_samples_add_shape(struct cell_samples *s,
                            const struct mesh *mesh,
                            const struct curvature *cv, uint32_t t,
                            double piece_area, const double centroid[3])
{
    const uint32_t *tri = mesh->triangle + 3 * (size_t)t;
    for (int corner = 0; corner < 3; corner++) {
        uint32_t v = tri[corner];
        const double *d1 = cv->dir1 + 3 * (size_t)v;
        const double *d2 = cv->dir2 + 3 * (size_t)v;
        for (int r = 0; r < 3; r++)
            for (int q = 0; q < 3; q++)
                s->shape[3 * r + q] += piece_area * centroid[corner] *
                    (cv->k1[v] * d1[r] * d1[q] + cv->k2[v] * d2[r] * d2[q]);
    }
}

/* Pass 2: distance from the plane, curvature samples, outline extent. */
void panel_sample_piece(void *context, size_t cell, uint32_t t,
                        const struct panel_piece_vertex *piece, int count)
{
    struct sample_context *sc = context;
    int n = sc->cell_panel[cell];
    if (n < 0)
        return;  /* a piece without area where no panel is */
    struct cell_samples *s = &sc->samples[n];
    struct cell_outline *o = s->outline >= 0 ? &sc->outlines[s->outline]
                                             : NULL;
    const struct mesh *mesh = sc->grid->mesh;
    const struct curvature *cv = sc->curvature;
    const uint32_t *tri = mesh->triangle + 3 * (size_t)t;

    double centroid[3] = {0, 0, 0};
    for (int k = 0; k < count; k++) {
        const double *b = piece[k].b;
        if (sc->points) {
            double p[3];
            panel_piece_point(mesh, t, &piece[k], p);
            double k1 = b[0] * cv->k1[tri[0]] + b[1] * cv->k1[tri[1]] +
                        b[2] * cv->k1[tri[2]];
            double k2 = b[0] * cv->k2[tri[0]] + b[1] * cv->k2[tri[1]] +
                        b[2] * cv->k2[tri[2]];
            /* The paper's samples: mesh vertices inside the cell and
             * points where the cell's border cuts a mesh edge (one
             * barycentric 0). */
            cell_sample(s, o, p, k1, k2,
                        b[0] <= 1e-12 || b[1] <= 1e-12 || b[2] <= 1e-12);
        }
        for (int x = 0; x < 3; x++)
            centroid[x] += b[x] / count;
    }

    if (sc->shape) {
        /* The shape operator is linear over the triangle, so its integral
         * over the piece is the piece's area times its value at the piece's
         * area centroid; the vertex average is close enough for the small
         * pieces a cell cuts, and exact for triangles. */
        double piece_area = 0;
        for (int k = 1; k + 1 < count; k++) {
            double a[3], bb[3], c[3], ab[3], ac[3], nn[3];
            panel_piece_point(mesh, t, &piece[0], a);
            panel_piece_point(mesh, t, &piece[k], bb);
            panel_piece_point(mesh, t, &piece[k + 1], c);
            vec3_sub(bb, a, ab);
            vec3_sub(c, a, ac);
            vec3_cross(ab, ac, nn);
            piece_area += 0.5 * sqrt(vec3_dot(nn, nn));
        }
        cell_samples_add_shape(s, mesh, cv, t, piece_area, centroid);
    }
}

/* The panel's k1 >= k2 from the mean shape operator: its two eigenvalues
 * whose eigenvectors lie in the panel's plane. */
static void mean_curvature_of(const struct cell_samples *s,
                              struct panel *panel)
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

/* A grid node located on the surface, shared by the panels around it. */
/* Locates the cell corners on the surface (each grid node once, in nodes)
 * and measures the quad. */
static void measure_corners(const struct panel_grid *g,
                            struct grid_node *nodes, struct panel *panel)
{
    static const int offset[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    double extent = fmax(g->du * g->nu, g->dv * g->nv);
    panel->ncorners = 0;
    for (int c = 0; c < 4; c++) {
        int ni = panel->i + offset[c][0], nj = panel->j + offset[c][1];
        struct grid_node *node = &nodes[(size_t)nj * (g->nu + 1) + ni];
        if (node->state == 0) {
            double u = g->umin + ni * g->du;
            double v = g->vmin + nj * g->dv;
            double b[3];
            uint32_t t = uv_index_locate(g->index, u, v,
                                         1e-9 * (extent > 0), b);
            node->state = -1;
            if (t != UINT32_MAX) {
                struct panel_piece_vertex p = {u, v, {b[0], b[1], b[2]}};
                panel_piece_point(g->mesh, t, &p, node->point);
                node->state = 1;
            }
        }
        if (node->state < 0) {
            panel->corner[c][0] = panel->corner[c][1] =
                panel->corner[c][2] = NAN;
            continue;
        }
        memcpy(panel->corner[c], node->point, sizeof node->point);
        panel->ncorners++;
    }
    panel->corner_planarity = NAN;
    if (panel->ncorners == 4)
        panel->corner_planarity = quad_planarity(panel->corner);
}

/* Which way the plane's normal n should point: the side of the surface
 * normals (normal_sum). When the panel has no side (its normals cancel
 * along n, as a whole ring of a tube does) the dot product is rounding
 * noise, and a fixed choice keeps every way of summing the panel to the
 * same normal: the first clearly non-zero component positive. */
static int normal_side(const double n[3], const double normal_sum[3])
{
    double dot = vec3_dot(n, normal_sum);
    if (fabs(dot) > 1e-9 * sqrt(vec3_dot(normal_sum, normal_sum)))
        return dot < 0 ? -1 : 1;
    for (int x = 0; x < 3; x++)
        if (fabs(n[x]) > 1e-3)
            return n[x] < 0 ? -1 : 1;
    return 1;
}

/* Cells fitted between two questions to the stop: milliseconds. */
#define STOP_EVERY_CELLS 4096

int panels_fit(const struct panel_grid *g, const struct cell_moments *sums,
               struct grid_node *known, const struct facet_stop *stop,
               struct panelization *out, struct cell_samples **samples_out,
               struct cell_outline **outlines_out, struct facet_error *err)
{
    size_t ncells = (size_t)g->nu * (size_t)g->nv;
    *samples_out = NULL;
    *outlines_out = NULL;
    out->cell_panel = malloc(ncells * sizeof *out->cell_panel);
    if (out->cell_panel == NULL)
        return facet_error_set(err, FACET_EWORK, "out of memory (panels)");
    for (size_t c = 0; c < ncells; c++) {
        out->cell_panel[c] = sums[c].area > 0 ? (int)out->npanels : -1;
        if (sums[c].area > 0)
            out->npanels++;
    }
    size_t npanels = out->npanels ? out->npanels : 1;
    size_t nnodes = (size_t)(g->nu + 1) * (size_t)(g->nv + 1);
    out->panels = calloc(npanels, sizeof *out->panels);
    struct cell_samples *samples = malloc(npanels * sizeof *samples);
    struct grid_node *nodes = known != NULL ? known
                                            : calloc(nnodes, sizeof *nodes);
    if (out->panels == NULL || samples == NULL || nodes == NULL) {
        free(samples);
        if (known == NULL)
            free(nodes);
        return facet_error_set(err, FACET_EWORK, "out of memory (panels)");
    }

    double cell_uv_area = g->du * g->dv;
    size_t noutlines = 0;
    for (size_t c = 0; c < ncells; c++) {
        if (c % STOP_EVERY_CELLS == 0 && facet_stop_requested(stop)) {
            free(samples);
            if (known == NULL)
                free(nodes);
            return facet_stop_error(err);
        }
        if (out->cell_panel[c] < 0)
            continue;
        const struct cell_moments *s = &sums[c];
        struct panel *panel = &out->panels[out->cell_panel[c]];
        panel->i = (int)(c % (size_t)g->nu);
        panel->j = (int)(c / (size_t)g->nu);
        panel->area = s->area;
        panel->uv_area = s->uv_area;
        panel->trimmed = s->uv_area < cell_uv_area * (1 - 1e-9);

        static const int at[3][3] = {{0, 1, 2}, {1, 3, 4}, {2, 4, 5}};
        double mean[3], covariance[9], value[3], vector[3][3];
        for (int x = 0; x < 3; x++) {
            mean[x] = s->first[x] / s->area;
            panel->centroid[x] = s->reference[x] + mean[x];
        }
        for (int r = 0; r < 3; r++)
            for (int q = 0; q < 3; q++)
                covariance[3 * r + q] = s->second[at[r][q]] / s->area -
                                        mean[r] * mean[q];
        sym3_eigen(covariance, value, vector);
        memcpy(panel->normal, vector[0], sizeof panel->normal);
        if (normal_side(panel->normal, s->normal_sum) < 0)
            for (int x = 0; x < 3; x++)
                panel->normal[x] = -panel->normal[x];
        panel->p_dist = fmax(value[0], 0) * s->area;
        measure_corners(g, nodes, panel);

        struct cell_samples *sample = &samples[out->cell_panel[c]];
        memset(sample, 0, sizeof *sample);
        memcpy(sample->centroid, panel->centroid, sizeof sample->centroid);
        memcpy(sample->normal, panel->normal, sizeof sample->normal);
        sample->k1_edge = sample->k1_any = -INFINITY;
        sample->k2_edge = sample->k2_any = INFINITY;
        sample->outline = -1;
        if (panel->trimmed || panel->ncorners < 4)
            sample->outline = (int)noutlines++;
    }
    if (known == NULL)
        free(nodes);

    struct cell_outline *outlines =
        malloc((noutlines ? noutlines : 1) * sizeof *outlines);
    if (outlines == NULL) {
        free(samples);
        return facet_error_set(err, FACET_EWORK, "out of memory (panels)");
    }
    for (size_t o = 0; o < noutlines; o++)
        for (int e = 0; e < 13; e++) {
            outlines[o].low[e] = INFINITY;
            outlines[o].high[e] = -INFINITY;
            memset(outlines[o].low_point[e], 0, sizeof outlines[o].low_point[e]);
            memset(outlines[o].high_point[e], 0,
                   sizeof outlines[o].high_point[e]);
        }
    *samples_out = samples;
    *outlines_out = outlines;
    return FACET_OK;
}

void panels_finish(enum panel_curvature_mode mode,
                   const struct cell_samples *samples,
                   const struct cell_outline *outlines,
                   struct panelization *out)
{
    for (size_t n = 0; n < out->npanels; n++) {
        const struct cell_samples *s = &samples[n];
        struct panel *panel = &out->panels[n];
        panel->deviation = s->deviation;
        if (mode == PANEL_MEAN) {
            mean_curvature_of(s, panel);
        } else if (s->edge_samples > 0) {
            panel->k1 = s->k1_edge;
            panel->k2 = s->k2_edge;
        } else {
            panel->k1 = s->k1_any;
            panel->k2 = s->k2_any;
        }
        if (s->outline < 0) {
            panel->diameter = fmax(vec3_distance(panel->corner[0],
                                                 panel->corner[2]),
                                   vec3_distance(panel->corner[1],
                                                 panel->corner[3]));
        } else {
            const struct cell_outline *o = &outlines[s->outline];
            double diameter = 0;
            for (int a = 0; a < 13; a++)
                for (int b = 0; b < 13; b++) {
                    diameter = larger(diameter,
                        vec3_distance(o->low_point[a], o->high_point[b]));
                    diameter = larger(diameter,
                        vec3_distance(o->low_point[a], o->low_point[b]));
                }
            panel->diameter = diameter;
        }
    }
}

int panels_build(const struct mesh *mesh, const struct uv_index *index,
                 const struct curvature *curvature,
                 enum panel_curvature_mode mode, int nu, int nv,
                 struct panelization *out, struct facet_error *err)
{
    struct panel_grid grid;
    int rc = panel_grid_init(&grid, mesh, index, nu, nv, out, err);
    if (rc != FACET_OK)
        return rc;
    size_t ncells = (size_t)nu * (size_t)nv;
    struct cell_moments *sums = calloc(ncells, sizeof *sums);
    if (sums == NULL)
        return facet_error_set(err, FACET_EWORK, "out of memory (panels)");
    struct moments_context mc = {mesh, sums};
    for (size_t t = 0; t < mesh->ntriangles; t++)
        panel_walk_triangle(&grid, (uint32_t)t, sum_piece_moments, &mc);

    struct cell_samples *samples;
    struct cell_outline *outlines;
    rc = panels_fit(&grid, sums, NULL, NULL, out, &samples, &outlines, err);
    free(sums);
    if (rc != FACET_OK)
        return rc;
    struct sample_context sc = {&grid, curvature, out->cell_panel, samples,
                                outlines, 1, mode == PANEL_MEAN};
    for (size_t t = 0; t < mesh->ntriangles; t++)
        panel_walk_triangle(&grid, (uint32_t)t, panel_sample_piece, &sc);
    panels_finish(mode, samples, outlines, out);
    free(samples);
    free(outlines);
    struct triangle_curvature_range *ranges;
    rc = triangle_curvature_ranges(mesh, curvature, &ranges);
    if (rc == FACET_OK)
        rc = panels_curvature_range(&grid, ranges, mode, out);
    free(ranges);
    if (rc != FACET_OK)
        return facet_error_set(err, FACET_EWORK, "out of memory (panels)");
    return FACET_OK;
}

int triangle_curvature_ranges(const struct mesh *mesh,
                              const struct curvature *curvature,
                              struct triangle_curvature_range **out)
{
    *out = NULL;
    if (curvature->k1_error == NULL || curvature->k2_error == NULL)
        return FACET_OK;
    const double c = CURVATURE_ERROR_SIGMAS;
    size_t nt = mesh->ntriangles;
    struct triangle_curvature_range *range =
        malloc((nt ? nt : 1) * sizeof *range);
    if (range == NULL)
        return FACET_EWORK;
    for (size_t t = 0; t < nt; t++) {
        struct triangle_curvature_range r = {-INFINITY, -INFINITY, INFINITY,
                                             INFINITY, -INFINITY, -INFINITY};
        const uint32_t *tri = mesh->triangle + 3 * t;
        for (int k = 0; k < 3; k++) {
            uint32_t v = tri[k];
            double k1 = curvature->k1[v], k2 = curvature->k2[v];
            double e1 = c * curvature->k1_error[v];
            double e2 = c * curvature->k2_error[v];
            r.k1_low = larger(r.k1_low, k1 - e1);
            r.k1_high = larger(r.k1_high, k1 + e1);
            r.k2_low = smaller(r.k2_low, k2 - e2);
            r.k2_high = smaller(r.k2_high, k2 + e2);
            r.e1 = larger(r.e1, e1);
            r.e2 = larger(r.e2, e2);
        }
        range[t] = r;
    }
    *out = range;
    return FACET_OK;
}

int panels_curvature_range(const struct panel_grid *g,
                           const struct triangle_curvature_range *ranges,
                           enum panel_curvature_mode mode,
                           struct panelization *out)
{
    /* per panel: the extremes of k1 -+ c e1 and k2 -+ c e2 over the
     * vertices, and the largest c e1, c e2 (for the mean mode) */
    double *over = malloc(6 * (out->npanels ? out->npanels : 1) *
                          sizeof *over);
    if (over == NULL)
        return FACET_EWORK;
    for (size_t n = 0; n < out->npanels; n++) {
        double *o = over + 6 * n;
        o[0] = o[1] = -INFINITY;  /* max of k1 - c e1, of k1 + c e1 */
        o[2] = o[3] = INFINITY;   /* min of k2 - c e2, of k2 + c e2 */
        o[4] = o[5] = 0;          /* max of c e1, of c e2 */
    }
    const struct mesh *mesh = g->mesh;
    for (size_t t = 0; ranges != NULL && t < mesh->ntriangles; t++) {
        const double *uv = g->index->uv + 6 * t;
        double u0 = smaller(uv[0], smaller(uv[2], uv[4]));
        double u1 = larger(uv[0], larger(uv[2], uv[4]));
        double v0 = smaller(uv[1], smaller(uv[3], uv[5]));
        double v1 = larger(uv[1], larger(uv[3], uv[5]));
        if (!isfinite(u0 + u1 + v0 + v1))
            continue;
        const struct triangle_curvature_range *r = &ranges[t];
        int i0 = panel_cell_coordinate(u0, g->umin, g->du, g->nu);
        int i1 = panel_cell_coordinate(u1, g->umin, g->du, g->nu);
        int j0 = panel_cell_coordinate(v0, g->vmin, g->dv, g->nv);
        int j1 = panel_cell_coordinate(v1, g->vmin, g->dv, g->nv);
        for (int j = j0; j <= j1; j++)
            for (int i = i0; i <= i1; i++) {
                int n = out->cell_panel[(size_t)j * g->nu + i];
                if (n < 0)
                    continue;
                /* Neither o nor r is ever NaN (r's NaNs were left out),
                 * so larger(o, x) is x > o ? x : o, ties kept as o: one
                 * maxsd or minsd, without larger's NaN branch. */
                double *o = over + 6 * (size_t)n;
                o[0] = r->k1_low > o[0] ? r->k1_low : o[0];
                o[1] = r->k1_high > o[1] ? r->k1_high : o[1];
                o[2] = r->k2_low < o[2] ? r->k2_low : o[2];
                o[3] = r->k2_high < o[3] ? r->k2_high : o[3];
                o[4] = r->e1 > o[4] ? r->e1 : o[4];
                o[5] = r->e2 > o[5] ? r->e2 : o[5];
            }
    }
    for (size_t n = 0; n < out->npanels; n++) {
        struct panel *panel = &out->panels[n];
        const double *o = over + 6 * n;
        if (mode == PANEL_MEAN || !(o[0] <= o[1])) {
            /* the mean of the shape operator, or no vertex: its k give
             * or take the largest error */
            panel->k1_error[0] = panel->k1_error[1] = o[4];
            panel->k2_error[0] = panel->k2_error[1] = o[5];
            continue;
        }
        /* the range of the extremes, never narrower than the samples'
         * own k1, k2 */
        panel->k1_error[0] = fmax(panel->k1 - o[0], 0);
        panel->k1_error[1] = fmax(o[1] - panel->k1, 0);
        panel->k2_error[0] = fmax(panel->k2 - o[2], 0);
        panel->k2_error[1] = fmax(o[3] - panel->k2, 0);
    }
    free(over);
    return FACET_OK;
}

double panel_corner_distance(const struct panelization *panels, size_t n)
{
    assert(n < panels->npanels);
    return panels->corner_distance != NULL ? panels->corner_distance[n] : NAN;
}

double panel_corner_moved(const struct panelization *panels, size_t n)
{
    assert(n < panels->npanels);
    return panels->corner_moved != NULL ? panels->corner_moved[n] : NAN;
}

void panelization_free(struct panelization *panelization)
{
    free(panelization->panels);
    free(panelization->cell_panel);
    free(panelization->corner_distance);
    free(panelization->corner_moved);
    memset(panelization, 0, sizeof *panelization);
}
