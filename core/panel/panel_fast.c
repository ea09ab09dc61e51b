/*
 * panel_fast.c: panels from per-surface sums, clipping only what crosses a
 * cell line. See panel.h (panel_prep_build, panels_build_fast) and
 * panel_internal.h for what it shares with panel.c's panels_build.
 *
 * Once per surface: the distinct (vertex, UV) corners ("points") with their
 * position and curvature, and per triangle its area, UV area, centroid,
 * second moment about the centroid, area-weighted normal and its
 * vertices' curvature extremes (panels_curvature_range's).
 *
 * Per grid, pass 1: each point's cell, once; a triangle whose corners share
 * a cell adds its sums to the cell's in O(1); one that crosses a line is
 * split along the lines it crosses, row by row and then cell by cell, and
 * each piece's moments come from its barycentric fan. Pass 2 samples each
 * point once in its cell (the distance from the plane is largest at piece
 * vertices, and a triangle inside a cell has only its corners), then the
 * pieces of the crossing triangles. A point within 1e-6 cell of a line
 * the triangles are clipped at is sampled with its triangles instead, as
 * panels_build takes it, so that rounding never moves it to the wrong side.
 */
#include "core/panel/panel.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/panel/panel_internal.h"

int panel_prep_build(const struct mesh *mesh, const struct uv_index *index,
                     const struct curvature *curvature,
                     struct panel_prep *out, struct facet_error *err)
{
    memset(out, 0, sizeof *out);
    out->mesh = mesh;
    out->index = index;
    out->curvature = curvature;
    size_t nt = mesh->ntriangles, ncorners = 3 * nt;
    if (ncorners >= (size_t)INT32_MAX)
        return facet_error_set(err, FACET_EINPUT,
            "%zu triangles are too many to panelize", nt);
    out->triangle = malloc((nt ? nt : 1) * sizeof *out->triangle);
    out->corner = malloc((ncorners ? ncorners : 1) * sizeof *out->corner);
    out->point = malloc((ncorners ? ncorners : 1) * sizeof *out->point);
    out->point_uv = malloc((ncorners ? ncorners : 1) * 2 *
                           sizeof *out->point_uv);
    uint32_t *head = malloc((mesh->nvertices ? mesh->nvertices : 1) *
                            sizeof *head);
    uint32_t *next = malloc((ncorners ? ncorners : 1) * sizeof *next);
    if (out->triangle == NULL || out->corner == NULL || out->point == NULL ||
        out->point_uv == NULL || head == NULL || next == NULL) {
        free(head);
        free(next);
        return facet_error_set(err, FACET_EWORK, "out of memory (panels)");
    }
    for (size_t v = 0; v < mesh->nvertices; v++)
        head[v] = UINT32_MAX;

    for (size_t t = 0; t < nt; t++) {
        struct panel_prep_triangle *T = &out->triangle[t];
        const uint32_t *tri = mesh->triangle + 3 * t;
        const double *uv = index->uv + 6 * t;
        /* The corners, each (vertex, UV) once. */
        for (int k = 0; k < 3; k++) {
            uint32_t v = tri[k], p = head[v];
            double u = uv[2 * k], w = uv[2 * k + 1];
            while (p != UINT32_MAX && !(out->point_uv[2 * p] == u &&
                                        out->point_uv[2 * p + 1] == w))
                p = next[p];
            if (p == UINT32_MAX) {
                p = (uint32_t)out->npoints++;
                struct panel_prep_point *P = &out->point[p];
                out->point_uv[2 * p] = u;
                out->point_uv[2 * p + 1] = w;
                memcpy(P->position, mesh->position + 3 * (size_t)v,
                       sizeof P->position);
                P->k1 = curvature->k1[v];
                P->k2 = curvature->k2[v];
                next[p] = head[v];
                head[v] = p;
            }
            out->corner[3 * t + k] = p;
        }

        /* Its sums, about its centroid. */
        const double *x[3];
        for (int k = 0; k < 3; k++)
            x[k] = mesh->position + 3 * (size_t)tri[k];
        double a[3], b[3], c[3], ab[3], ac[3], n[3];
        for (int d = 0; d < 3; d++) {
            T->centroid[d] = (x[0][d] + x[1][d] + x[2][d]) / 3;
            a[d] = x[0][d] - T->centroid[d];
            b[d] = x[1][d] - T->centroid[d];
            c[d] = x[2][d] - T->centroid[d];
            ab[d] = b[d] - a[d];
            ac[d] = c[d] - a[d];
        }
        n[0] = ab[1] * ac[2] - ab[2] * ac[1];
        n[1] = ab[2] * ac[0] - ab[0] * ac[2];
        n[2] = ab[0] * ac[1] - ab[1] * ac[0];
        T->area = 0.5 * sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        T->uv_area = 0.5 * fabs((uv[2] - uv[0]) * (uv[5] - uv[1]) -
                                (uv[4] - uv[0]) * (uv[3] - uv[1]));
        struct piece_moments m;
        memset(&m, 0, sizeof m);
        piece_moments_add_triangle(&m, a, b, c, T->area);
        memcpy(T->second, m.second, sizeof T->second);
        for (int d = 0; d < 3; d++)
            T->normal_sum[d] = T->area * mesh->face_normal[3 * t + d];
    }
    free(head);
    free(next);
    if (triangle_curvature_ranges(mesh, curvature, &out->curvature_range) !=
        FACET_OK)
        return facet_error_set(err, FACET_EWORK, "out of memory (panels)");
    size_t kept = out->npoints ? out->npoints : 1;
    struct panel_prep_point *shrunk =
        realloc(out->point, kept * sizeof *out->point);
    if (shrunk != NULL)
        out->point = shrunk;
    double *shrunk_uv = realloc(out->point_uv,
                                kept * 2 * sizeof *out->point_uv);
    if (shrunk_uv != NULL)
        out->point_uv = shrunk_uv;
    return FACET_OK;
}

int panel_prep_add_ranges(struct panel_prep *prep, struct facet_error *err)
{
    assert(prep->curvature_range == NULL);
    if (triangle_curvature_ranges(prep->mesh, prep->curvature,
                                  &prep->curvature_range) != FACET_OK)
        return facet_error_set(err, FACET_EWORK, "out of memory (panels)");
    return FACET_OK;
}

void panel_prep_free(struct panel_prep *prep)
{
    free(prep->point_uv);
    free(prep->point);
    free(prep->corner);
    free(prep->triangle);
    free(prep->curvature_range);
    memset(prep, 0, sizeof *prep);
}

/* A point's cell along one axis, as panel_cell_coordinate gives it, and
 * whether it lies within 1e-6 cell of a line triangles are clipped at (not
 * the outermost): near is set then, and left alone otherwise. */
static inline int point_cell(double x, double origin, double step,
                             double inverse, int count, uint32_t *near)
{
    double q = (x - origin) * inverse;
    if (q > 0 && q < count) {
        int i = (int)q;
        double fraction = q - i;
        if (fraction >= 1e-6 && fraction <= 1 - 1e-6)
            return i;
    }
    /* By a line, or outside the box: exactly as panel_cell_coordinate,
     * which the product with the inverse may round to the other side. */
    double line = nearbyint(q);
    if (line >= 1 && line <= count - 1 && fabs(q - line) < 1e-6)
        *near = 1;
    return panel_cell_coordinate(x, origin, step, count);
}

#define CELL_I(packed) ((int)((packed) & 0xffffu))
#define CELL_J(packed) ((int)(((packed) >> 16) & 0x7fffu))
#define CELL_NEAR(packed) ((packed) >> 31)

/* One panelization in progress. */
struct fast {
    const struct panel_prep *prep;
    const struct panel_grid *grid;
    struct cell_moments *sums;          /* pass 1, ncells */
    const int *cell_panel;              /* pass 2 */
    struct cell_samples *samples;
    struct cell_outline *outlines;
    const uint32_t *cell_of;            /* packed cell of each point */
    const double *line_u, *line_v;      /* the lines after cells i, j:
                                           umin + (i + 1) du, ... */
};

/* Pass 1 for one piece of triangle t. */
static void piece_sums(struct fast *f, const struct panel_prep_triangle *T,
                       const double corner[3][3], size_t cell,
                       const struct split_vertex *piece, int count)
{
    struct piece_moments m;
    panel_piece_moments(T, corner, piece, count, &m);
    cell_moments_add(&f->sums[cell], T->centroid, &m);
}

/* Pass 2 for one piece of triangle t: every vertex a sample. */
static void piece_samples(struct fast *f, const struct panel_prep_point *P[3],
                          size_t cell, const struct split_vertex *piece,
                          int count)
{
    int n = f->cell_panel[cell];
    if (n < 0)
        return;
    struct cell_samples *s = &f->samples[n];
    struct cell_outline *o = s->outline >= 0 ? &f->outlines[s->outline]
                                             : NULL;
    for (int k = 0; k < count; k++) {
        const double *b = piece[k].b;
        double x[3], k1, k2;
        panel_point_at(P, b, x, &k1, &k2);
        cell_sample(s, o, x, k1, k2,
                    b[0] <= 1e-12 || b[1] <= 1e-12 || b[2] <= 1e-12);
    }
}

/* Pass 1 or 2 for triangle t when it crosses exactly one line, coordinate
 * axis = limit, between cells low and high, and no corner lies on it:
 * one corner a alone on its side, b and c on the other. The piece on a's
 * side is the triangle a, x_b, x_c (x cut from edge a-b at t_b), the
 * other the quad x_b, b, c, x_c, fanned as b, c, x_c and b, x_c, x_b; their
 * areas are the fractions t_b t_c, 1 - t_c and t_c (1 - t_b) of the
 * triangle's, each without cancellation. Returns 0, doing nothing, when a
 * corner lies on the line. */
static int cross_one_line(struct fast *f, uint32_t t, int axis, double limit,
                          size_t low, size_t high, int sums)
{
    const uint32_t *point = f->prep->corner + 3 * (size_t)t;
    const double *uv = f->prep->point_uv;
    double d[3];
    int above = 0;
    for (int k = 0; k < 3; k++) {
        d[k] = uv[2 * point[k] + axis] - limit;
        if (d[k] == 0)
            return 0;
        above += d[k] > 0;
    }
    if (above == 0 || above == 3)
        return 0;  /* it only touches the line, to rounding */
    int a = 0;
    if (above == 1)
        a = d[0] > 0 ? 0 : d[1] > 0 ? 1 : 2;
    else
        a = d[0] < 0 ? 0 : d[1] < 0 ? 1 : 2;
    int b = a == 2 ? 0 : a + 1, c = b == 2 ? 0 : b + 1;
    double tb = d[a] / (d[a] - d[b]), sb = d[b] / (d[b] - d[a]);
    double tc = d[a] / (d[a] - d[c]), sc = d[c] / (d[c] - d[a]);
    size_t cell_a = d[a] > 0 ? high : low, cell_bc = d[a] > 0 ? low : high;
    const struct panel_prep_point *P[3] = {&f->prep->point[point[a]],
                                           &f->prep->point[point[b]],
                                           &f->prep->point[point[c]]};
    if (sums) {
        const struct panel_prep_triangle *T = &f->prep->triangle[t];
        double x[3][3], xb[3], xc[3];
        for (int k = 0; k < 3; k++)
            for (int e = 0; e < 3; e++)
                x[k][e] = P[k]->position[e] - T->centroid[e];
        for (int e = 0; e < 3; e++) {
            xb[e] = x[0][e] + tb * (x[1][e] - x[0][e]);
            xc[e] = x[0][e] + tc * (x[2][e] - x[0][e]);
        }
        /* The smaller side directly, the other as the rest of the
         * triangle, so neither loses precision. */
        double fa = tb * tc, f1 = sc, f2 = tc * sb;
        struct piece_moments m, rest;
        memset(&m, 0, sizeof m);
        int small_a = fa <= 0.5;
        if (small_a) {
            piece_moments_add_triangle(&m, x[0], xb, xc, fa * T->area);
        } else {
            piece_moments_add_triangle(&m, x[1], x[2], xc, f1 * T->area);
            piece_moments_add_triangle(&m, x[1], xc, xb, f2 * T->area);
        }
        double fm = small_a ? fa : f1 + f2, fr = small_a ? f1 + f2 : fa;
        m.area = fm * T->area;
        m.uv_area = fm * T->uv_area;
        rest.area = fr * T->area;
        rest.uv_area = fr * T->uv_area;
        for (int e = 0; e < 3; e++) {
            m.normal_sum[e] = fm * T->normal_sum[e];
            rest.normal_sum[e] = fr * T->normal_sum[e];
            rest.first[e] = -m.first[e];
        }
        for (int e = 0; e < 6; e++)
            rest.second[e] = T->second[e] - m.second[e];
        cell_moments_add(&f->sums[small_a ? cell_a : cell_bc], T->centroid,
                         &m);
        cell_moments_add(&f->sums[small_a ? cell_bc : cell_a], T->centroid,
                         &rest);
        return 1;
    }

    /* Pass 2: the cut points belong to both pieces; a corner is sampled
     * here only when it lies by the line (else with the points). */
    double xb[3], xc[3];
    for (int e = 0; e < 3; e++) {
        xb[e] = P[0]->position[e] + tb * (P[1]->position[e] -
                                          P[0]->position[e]);
        xc[e] = P[0]->position[e] + tc * (P[2]->position[e] -
                                          P[0]->position[e]);
    }
    double k1b = P[0]->k1 + tb * (P[1]->k1 - P[0]->k1);
    double k2b = P[0]->k2 + tb * (P[1]->k2 - P[0]->k2);
    double k1c = P[0]->k1 + tc * (P[2]->k1 - P[0]->k1);
    double k2c = P[0]->k2 + tc * (P[2]->k2 - P[0]->k2);
    size_t cells[2] = {low, high};
    for (int side = 0; side < 2; side++) {
        int n = f->cell_panel[cells[side]];
        if (n < 0)
            continue;
        struct cell_samples *s = &f->samples[n];
        struct cell_outline *o = s->outline >= 0 ? &f->outlines[s->outline]
                                                 : NULL;
        cell_sample(s, o, xb, k1b, k2b, 1);
        cell_sample(s, o, xc, k1c, k2c, 1);
        for (int k = 0; k < 3; k++) {
            int corner = k == 0 ? a : k == 1 ? b : c;
            size_t cell = (corner == a) ? cell_a : cell_bc;
            if (cell == cells[side] && CELL_NEAR(f->cell_of[point[corner]]))
                cell_sample(s, o, P[k]->position, P[k]->k1, P[k]->k2, 1);
        }
    }
    return 1;
}

/* One crossing triangle being split: what its pieces need. */
struct splitting {
    struct fast *f;
    const struct panel_prep_triangle *T;
    const struct panel_prep_point *P[3];
    double corner[3][3];  /* pass 1: relative to the triangle's centroid */
    int sums;             /* pass 1, else pass 2 */
};

static int split_piece(void *context, size_t column, size_t row,
                       const struct split_vertex *piece, int count)
{
    struct splitting *s = context;
    size_t cell = row * (size_t)s->f->grid->nu + column;
    if (s->sums)
        piece_sums(s->f, s->T, s->corner, cell, piece, count);
    else
        piece_samples(s->f, s->P, cell, piece, count);
    return 0;
}

/* Splits triangle t, whose corners span cells i0..i1 x j0..j1, along the
 * lines between them and hands every piece to pass 1 (sums set) or 2. */
static void split_triangle(struct fast *f, uint32_t t, int i0, int i1,
                           int j0, int j1, int sums)
{
    const uint32_t *point = f->prep->corner + 3 * (size_t)t;
    struct splitting s = {f, &f->prep->triangle[t], {NULL, NULL, NULL},
                          {{0}}, sums};
    for (int k = 0; k < 3; k++)
        s.P[k] = &f->prep->point[point[k]];
    if (sums)
        panel_triangle_corners(f->prep, t, s.corner);
    panel_split_cells(f->prep, t, f->line_u, (size_t)i0, (size_t)i1,
                      f->line_v, (size_t)j0, (size_t)j1, 0, SIZE_MAX,
                      split_piece, &s);
}

/* Pass 1 (sums set) or 2 for triangle t, whose corners span cells
 * i0..i1 x j0..j1 (more than one). */
static void cross(struct fast *f, uint32_t t, int i0, int i1, int j0, int j1,
                  int sums)
{
    const struct panel_grid *g = f->grid;
    if (i1 == i0 + 1 && j1 == j0) {
        size_t low = (size_t)j0 * g->nu + i0;
        if (cross_one_line(f, t, 0, f->line_u[i0], low, low + 1, sums))
            return;
    } else if (j1 == j0 + 1 && i1 == i0) {
        size_t low = (size_t)j0 * g->nu + i0;
        if (cross_one_line(f, t, 1, f->line_v[j0], low, low + g->nu, sums))
            return;
    }
    split_triangle(f, t, i0, i1, j0, j1, sums);
}

static inline int min3(int a, int b, int c)
{
    int m = a < b ? a : b;
    return m < c ? m : c;
}

static inline int max3(int a, int b, int c)
{
    int m = a > b ? a : b;
    return m > c ? m : c;
}

int panels_build_fast(const struct panel_prep *prep,
                      enum panel_curvature_mode mode, int nu, int nv,
                      struct panelization *out, struct facet_error *err)
{
    return panels_build_fast_stoppable(prep, mode, nu, nv, NULL, out, err);
}

/* Triangles divided between two questions to the stop: well under a
 * millisecond on the finest grids. */
#define STOP_EVERY_TRIANGLES 256

int panels_build_fast_stoppable(const struct panel_prep *prep,
                                enum panel_curvature_mode mode, int nu,
                                int nv, const struct facet_stop *stop,
                                struct panelization *out,
                                struct facet_error *err)
{
    struct panel_grid grid;
    int rc = panel_grid_init(&grid, prep->mesh, prep->index, nu, nv, out,
                             err);
    if (rc != FACET_OK)
        return rc;
    size_t ncells = (size_t)nu * (size_t)nv;
    size_t nt = prep->mesh->ntriangles;
    struct cell_moments *sums = calloc(ncells, sizeof *sums);
    uint32_t *cell_of = malloc((prep->npoints ? prep->npoints : 1) *
                               sizeof *cell_of);
    uint32_t *listed = malloc((nt ? nt : 1) * sizeof *listed);
    double *line = malloc((size_t)(nu + nv) * sizeof *line);
    if (sums == NULL || cell_of == NULL || listed == NULL || line == NULL) {
        free(sums);
        free(cell_of);
        free(listed);
        free(line);
        return facet_error_set(err, FACET_EWORK, "out of memory (panels)");
    }
    /* The lines triangles are clipped at, as panels_build places them. */
    for (int i = 0; i < nu; i++)
        line[i] = grid.umin + (i + 1) * grid.du;
    for (int j = 0; j < nv; j++)
        line[nu + j] = grid.vmin + (j + 1) * grid.dv;

    /* Each point's cell, packed: i, j << 16, near << 31. */
    double inverse_u = 1 / grid.du, inverse_v = 1 / grid.dv;
    for (size_t p = 0; p < prep->npoints; p++) {
        const double *uv = prep->point_uv + 2 * p;
        uint32_t near = 0;
        int i = point_cell(uv[0], grid.umin, grid.du, inverse_u, nu, &near);
        int j = point_cell(uv[1], grid.vmin, grid.dv, inverse_v, nv, &near);
        cell_of[p] = (uint32_t)i | (uint32_t)j << 16 | near << 31;
    }

    /* Pass 1; listed keeps the triangles pass 2 must look at. */
    struct fast f = {prep, &grid, sums, NULL, NULL, NULL, cell_of, line,
                     line + nu};
    size_t nlisted = 0;
    for (size_t t = 0; t < nt; t++) {
        /* A triangle of a fine grid crosses hundreds of cells. */
        if (t % STOP_EVERY_TRIANGLES == 0 && facet_stop_requested(stop)) {
            free(sums);
            free(cell_of);
            free(listed);
            free(line);
            return facet_stop_error(err);
        }
        const uint32_t *point = prep->corner + 3 * (size_t)t;
        uint32_t a = cell_of[point[0]], b = cell_of[point[1]],
                 c = cell_of[point[2]];
        if (a == b && b == c) {
            cell_moments_add_triangle(
                &sums[(size_t)CELL_J(a) * nu + CELL_I(a)],
                &prep->triangle[t]);
            if (CELL_NEAR(a))
                listed[nlisted++] = (uint32_t)t;
            continue;
        }
        int i0 = min3(CELL_I(a), CELL_I(b), CELL_I(c));
        int i1 = max3(CELL_I(a), CELL_I(b), CELL_I(c));
        int j0 = min3(CELL_J(a), CELL_J(b), CELL_J(c));
        int j1 = max3(CELL_J(a), CELL_J(b), CELL_J(c));
        listed[nlisted++] = (uint32_t)t;
        if (i0 == i1 && j0 == j1)
            cell_moments_add_triangle(&sums[(size_t)j0 * nu + i0],
                                      &prep->triangle[t]);
        else
            cross(&f, (uint32_t)t, i0, i1, j0, j1, 1);
    }

    struct cell_samples *samples = NULL;
    struct cell_outline *outlines = NULL;
    rc = facet_stop_check(stop, err);
    if (rc == FACET_OK)
        rc = panels_fit(&grid, sums, NULL, stop, out, &samples, &outlines,
                        err);
    free(sums);
    if (rc == FACET_OK && (rc = facet_stop_check(stop, err)) != FACET_OK) {
        free(samples);
        free(outlines);
    }
    if (rc != FACET_OK) {
        free(cell_of);
        free(listed);
        free(line);
        return rc;
    }
    f.cell_panel = out->cell_panel;
    f.samples = samples;
    f.outlines = outlines;

    /* Pass 2: every point not by a line once, in its cell... */
    for (size_t p = 0; p < prep->npoints; p++) {
        uint32_t packed = cell_of[p];
        if (CELL_NEAR(packed))
            continue;
        int n = out->cell_panel[(size_t)CELL_J(packed) * nu +
                                CELL_I(packed)];
        if (n < 0)
            continue;
        const struct panel_prep_point *P = &prep->point[p];
        struct cell_samples *s = &samples[n];
        cell_sample(s, s->outline >= 0 ? &outlines[s->outline] : NULL,
                    P->position, P->k1, P->k2, 1);
    }
    /* ...then the pieces of the listed triangles. */
    for (size_t k = 0; k < nlisted && rc == FACET_OK; k++) {
        if (k % STOP_EVERY_TRIANGLES == 0 &&
            (rc = facet_stop_check(stop, err)) != FACET_OK)
            break;
        uint32_t t = listed[k];
        const uint32_t *point = prep->corner + 3 * (size_t)t;
        uint32_t a = cell_of[point[0]], b = cell_of[point[1]],
                 c = cell_of[point[2]];
        int i0 = min3(CELL_I(a), CELL_I(b), CELL_I(c));
        int i1 = max3(CELL_I(a), CELL_I(b), CELL_I(c));
        int j0 = min3(CELL_J(a), CELL_J(b), CELL_J(c));
        int j1 = max3(CELL_J(a), CELL_J(b), CELL_J(c));
        if (i0 != i1 || j0 != j1) {
            cross(&f, t, i0, i1, j0, j1, 0);
            continue;
        }
        int n = out->cell_panel[(size_t)j0 * nu + i0];
        if (n < 0)
            continue;
        struct cell_samples *s = &samples[n];
        for (int corner = 0; corner < 3; corner++) {
            const struct panel_prep_point *P = &prep->point[point[corner]];
            cell_sample(s, s->outline >= 0 ? &outlines[s->outline] : NULL,
                        P->position, P->k1, P->k2, 1);
        }
    }
    if (rc == FACET_OK && mode == PANEL_MEAN) {
        /* The shape operator as panels_build takes it, piece by piece. */
        static const double third[3] = {1.0 / 3, 1.0 / 3, 1.0 / 3};
        struct sample_context sc = {&grid, prep->curvature, out->cell_panel,
                                    samples, outlines, 0, 1};
        for (size_t t = 0; t < nt; t++) {
            const uint32_t *point = prep->corner + 3 * t;
            uint32_t a = cell_of[point[0]], b = cell_of[point[1]],
                     c = cell_of[point[2]];
            int n = out->cell_panel[(size_t)CELL_J(a) * nu + CELL_I(a)];
            if (a == b && b == c && !CELL_NEAR(a) && n >= 0)
                cell_samples_add_shape(&samples[n], prep->mesh,
                                       prep->curvature, (uint32_t)t,
                                       prep->triangle[t].area, third);
            else
                panel_walk_triangle(&grid, (uint32_t)t, panel_sample_piece,
                                    &sc);
        }
    }
    if (rc == FACET_OK)
        rc = facet_stop_check(stop, err);
    if (rc == FACET_OK) {
        panels_finish(mode, samples, outlines, out);
        if (panels_curvature_range(&grid, prep->curvature_range, mode,
                                   out) != FACET_OK)
            rc = facet_error_set(err, FACET_EWORK, "out of memory (panels)");
    }
    free(samples);
    free(outlines);
    free(cell_of);
    free(listed);
    free(line);
    return rc;
}
