/*
 * panel_lattice.c: one grid's panels from a panel lattice. See
 * panel_lattice.h, and panel_lattice_internal.h for what the lattice holds.
 *
 * Pass 1 takes a cell's sums from the prefix sums, about the lattice's
 * origin, in long double: the four-term difference of sums over the whole
 * surface keeps about 1e-19 of their size, so a panel's second moment
 * keeps about 1e-13 of its own. A cell the surface covers less than half
 * of (a trimmed edge, a sliver) is summed from its fine cells instead,
 * where nothing cancels.
 *
 * Pass 2 samples what panels_build samples, less the points inside a
 * grid cell that cannot decide a maximum (distance from a plane and
 * barycentric curvature are largest at a piece's vertices): each mesh
 * point in its cell (a point on one of the grid's lines in every cell it
 * is a piece vertex of), each cut of a mesh edge by one of the grid's
 * lines in the cells on both sides, and each crossing of two of the
 * grid's lines on the surface in the four cells around it.
 */
#include "core/panel/panel_lattice_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The grid's lines among the lattice's, per axis: line_of[i] the fine line
 * of grid line i (1..n-1), first[i] the first fine column (row) of grid
 * column (row) i (0..n), and cell_of each fine column's grid column. */
struct grid_axis {
    size_t *line_of, *first;
    uint32_t *cell_of;
    unsigned char *is_line;  /* per fine line: one of the grid's */
};

static int grid_axis_make(const struct panel_lattice *L, int axis, int n,
                          double min, double step, struct grid_axis *g)
{
    size_t nfine = L->nline[axis] + 1;
    g->line_of = malloc((size_t)(n + 1) * sizeof *g->line_of);
    g->first = malloc((size_t)(n + 1) * sizeof *g->first);
    g->cell_of = malloc(nfine * sizeof *g->cell_of);
    g->is_line = calloc(nfine, 1);
    if (g->line_of == NULL || g->first == NULL || g->cell_of == NULL ||
        g->is_line == NULL)
        return FACET_EWORK;
    g->first[0] = 0;
    g->line_of[0] = 0;
    for (int i = 1; i < n; i++) {
        int on;
        size_t k = line_rank(L->line[axis], L->nline[axis], min + i * step,
                             &on);
        if (!on)
            return FACET_EINPUT;
        g->line_of[i] = k;
        g->first[i] = k + 1;
        g->is_line[k] = 1;
    }
    g->first[n] = nfine;
    for (int i = 0; i < n; i++)
        for (size_t f = g->first[i]; f < g->first[i + 1]; f++)
            g->cell_of[f] = (uint32_t)i;
    return FACET_OK;
}

static void grid_axis_free(struct grid_axis *g)
{
    free(g->line_of);
    free(g->first);
    free(g->cell_of);
    free(g->is_line);
}

/* Cell sums from the fine cells of columns a0..a1-1, rows b0..b1-1. */
static void sum_fine_cells(const struct panel_lattice *L, size_t a0,
                           size_t a1, size_t b0, size_t b1,
                           struct cell_moments *to)
{
    for (size_t r = b0; r < b1; r++)
        for (size_t c = a0; c < a1; c++) {
            const struct cell_moments *m = &L->fine[r * L->ncolumns + c];
            if (!m->has_reference)
                continue;
            struct piece_moments part;
            part.area = m->area;
            part.uv_area = m->uv_area;
            memcpy(part.first, m->first, sizeof part.first);
            memcpy(part.second, m->second, sizeof part.second);
            memcpy(part.normal_sum, m->normal_sum, sizeof part.normal_sum);
            cell_moments_add(to, m->reference, &part);
        }
}

/* Cell sums from the running sums: about the cell's centroid, which is
 * where the second moment has no cancellation left to lose. */
static void sum_from_prefix(const struct panel_lattice *L,
                            const struct lattice_sums *block,
                            struct cell_moments *to)
{
    static const int at[6][2] = {{0, 0}, {0, 1}, {0, 2},
                                 {1, 1}, {1, 2}, {2, 2}};
    long double area = block->area, mean[3];
    to->has_reference = 1;
    for (int x = 0; x < 3; x++) {
        mean[x] = block->first[x] / area;
        to->reference[x] = (double)(L->origin[x] + mean[x]);
        /* What rounding the reference left, as a first moment. */
        to->first[x] = (double)(block->first[x] -
                                area * ((long double)to->reference[x] -
                                        L->origin[x]));
        to->normal_sum[x] = (double)block->normal_sum[x];
    }
    for (int e = 0; e < 6; e++) {
        int r = at[e][0], q = at[e][1];
        to->second[e] = (double)(block->second[e] -
                                 block->first[r] * block->first[q] / area);
    }
    to->area = (double)area;
    to->uv_area = (double)block->uv_area;
}

/* Whether point p lies on one of the grid's lines. */
static inline int on_grid_line(const struct panel_lattice *L,
                               const struct grid_axis axis[2], uint32_t p)
{
    uint32_t u = L->on_line[2 * (size_t)p], v = L->on_line[2 * (size_t)p + 1];
    return (u != 0 && axis[0].is_line[u - 1]) ||
           (v != 0 && axis[1].is_line[v - 1]);
}

/* What pass 2 keeps of a panel while it samples, in one cache line:
 * sampling touches nothing else of the panel, and a grid takes some
 * 130,000 samples. */
struct sample_state {
    _Alignas(64) double normal[3];
    double offset;             /* normal . (centroid - lattice origin) */
    double deviation;          /* largest distance from the plane so far */
    double k1, k2;             /* over the samples on mesh edges */
    int edge_samples;
    int outline;               /* as in struct cell_samples */
};

struct pass2 {
    const int *cell_panel;
    const double *origin;
    struct sample_state *state;
    double *k_any;             /* 2 per panel: k1 max, k2 min over the
                                  samples inside triangles */
    struct cell_outline *outlines;
};

/* cell_sample for the panel of cell (if any), p absolute (m). */
static inline void sample_cell(struct pass2 *pass, size_t cell,
                               const double p[3], double k1, double k2,
                               int edge)
{
    int n = pass->cell_panel[cell];
    if (n < 0)
        return;
    struct sample_state *s = &pass->state[n];
    double q[3] = {p[0] - pass->origin[0], p[1] - pass->origin[1],
                   p[2] - pass->origin[2]};
    double distance = fabs(s->normal[0] * q[0] + s->normal[1] * q[1] +
                           s->normal[2] * q[2] - s->offset);
    if (distance > s->deviation)
        s->deviation = distance;
    if (edge) {
        if (k1 > s->k1)
            s->k1 = k1;
        if (k2 < s->k2)
            s->k2 = k2;
        s->edge_samples++;
    } else {
        /* Only the fallback of a panel with no edge sample at all, when
         * these are all its samples. */
        double *k = &pass->k_any[2 * (size_t)n];
        if (k1 > k[0])
            k[0] = k1;
        if (k2 < k[1])
            k[1] = k2;
    }
    if (s->outline >= 0)
        cell_outline_take(&pass->outlines[s->outline], p);
}

/* Where the grid's u-line i crosses its v-line j (both inner lines). */
static const struct lattice_corner *grid_crossing(
    const struct panel_lattice *L, const struct grid_axis axis[2], int i,
    int j)
{
    return &L->corner[axis[1].line_of[j] * L->nline[0] + axis[0].line_of[i]];
}

/* Pass 1: the cells' sums, and known[] the inner grid nodes the lattice
 * found on the surface (panels_fit locates the others). Each grid node's
 * running sums are gathered once (a node is a corner of four cells), then
 * each cell comes from its four corners. Returns FACET_OK or FACET_EWORK. */
static int grid_sums(const struct panel_lattice *L,
                     const struct panel_grid *grid,
                     const struct grid_axis axis[2],
                     struct cell_moments *sums, struct grid_node *known)
{
    int nu = grid->nu, nv = grid->nv;
    size_t W = L->ncolumns + 1, nnodes = (size_t)(nu + 1) * (size_t)(nv + 1);
    struct lattice_sums *node = malloc(nnodes * sizeof *node);
    uint32_t *node_pieces = malloc(nnodes * sizeof *node_pieces);
    if (node == NULL || node_pieces == NULL) {
        free(node);
        free(node_pieces);
        return FACET_EWORK;
    }
    for (int j = 0; j <= nv; j++)
        for (int i = 0; i <= nu; i++) {
            size_t at = axis[1].first[j] * W + axis[0].first[i];
            node[(size_t)j * (nu + 1) + i] = L->prefix[at];
            node_pieces[(size_t)j * (nu + 1) + i] = L->pieces[at];
        }
    double cell_uv_area = grid->du * grid->dv;
    for (int j = 0; j < nv; j++)
        for (int i = 0; i < nu; i++) {
            size_t n00 = (size_t)j * (nu + 1) + i, n01 = n00 + 1;
            size_t n10 = n00 + (size_t)nu + 1, n11 = n10 + 1;
            uint32_t pieces = node_pieces[n11] - node_pieces[n10] -
                              node_pieces[n01] + node_pieces[n00];
            if (pieces == 0)
                continue;
            struct lattice_sums block = node[n11];
            sums_add(&block, &node[n10], -1);
            sums_add(&block, &node[n01], -1);
            sums_add(&block, &node[n00], 1);
            struct cell_moments *to = &sums[(size_t)j * nu + i];
            if (block.area > 0 && block.uv_area >= 0.5 * cell_uv_area)
                sum_from_prefix(L, &block, to);
            else
                sum_fine_cells(L, axis[0].first[i], axis[0].first[i + 1],
                               axis[1].first[j], axis[1].first[j + 1], to);
        }
    free(node);
    free(node_pieces);
    for (int j = 1; j < nv; j++)
        for (int i = 1; i < nu; i++) {
            const struct lattice_corner *q = grid_crossing(L, axis, i, j);
            if (q->state < 0)
                continue;
            struct grid_node *k = &known[(size_t)j * (nu + 1) + i];
            k->state = 1;
            memcpy(k->point, q->at.position, sizeof k->point);
        }
    return FACET_OK;
}

/* Pass 2: the deviation, edge curvature and outline of each of out's
 * panels into samples (and outlines), from the mesh points, the cuts of
 * mesh edges by the grid's lines and the crossings of its lines. Returns
 * FACET_OK or FACET_EWORK. */
static int grid_samples(const struct panel_lattice *L,
                        const struct grid_axis axis[2],
                        const struct panelization *out,
                        struct cell_samples *samples,
                        struct cell_outline *outlines)
{
    const struct panel_prep *prep = L->prep;
    int nu = out->nu, nv = out->nv;
    size_t npanels = out->npanels ? out->npanels : 1;
    struct sample_state *state = aligned_alloc(64, npanels * sizeof *state);
    double *k_any = malloc(2 * npanels * sizeof *k_any);
    if (state == NULL || k_any == NULL) {
        free(state);
        free(k_any);
        return FACET_EWORK;
    }
    for (size_t n = 0; n < out->npanels; n++) {
        const struct cell_samples *c = &samples[n];
        struct sample_state *s = &state[n];
        memcpy(s->normal, c->normal, sizeof s->normal);
        s->offset = c->normal[0] * (c->centroid[0] - L->origin[0]) +
                    c->normal[1] * (c->centroid[1] - L->origin[1]) +
                    c->normal[2] * (c->centroid[2] - L->origin[2]);
        s->deviation = 0;
        s->k1 = -INFINITY;
        s->k2 = INFINITY;
        s->edge_samples = 0;
        s->outline = c->outline;
        k_any[2 * n] = -INFINITY;
        k_any[2 * n + 1] = INFINITY;
    }
    struct pass2 pass = {out->cell_panel, L->origin, state, k_any, outlines};
    const uint32_t *column_cell = axis[0].cell_of, *row_cell = axis[1].cell_of;
    /* The mesh points... */
    for (size_t p = 0; p < prep->npoints; p++) {
        if (on_grid_line(L, axis, (uint32_t)p))
            continue;
        size_t cell = (size_t)row_cell[L->place[2 * p + 1]] * nu +
                      column_cell[L->place[2 * p]];
        const struct panel_prep_point *P = &prep->point[p];
        sample_cell(&pass, cell, P->position, P->k1, P->k2, 1);
    }
    /* (a point on one of the grid's lines in each cell it borders)... */
    for (size_t e = 0; e < L->nextra; e++) {
        const struct lattice_extra *x = &L->extra[e];
        if (!on_grid_line(L, axis, x->point))
            continue;
        size_t cell = (size_t)row_cell[x->row] * nu + column_cell[x->column];
        const struct panel_prep_point *P = &prep->point[x->point];
        sample_cell(&pass, cell, P->position, P->k1, P->k2, 1);
    }
    /* ...where the grid's lines cut mesh edges... */
    for (int i = 1; i < nu; i++) {
        size_t k = axis[0].line_of[i];
        for (size_t n = L->cut_start[0][k]; n < L->cut_start[0][k + 1];
             n++) {
            const struct lattice_cut *x = &L->cut[0][n];
            size_t cell = (size_t)row_cell[x->across] * nu + (size_t)i;
            sample_cell(&pass, cell - 1, x->at.position, x->at.k1, x->at.k2,
                        1);
            sample_cell(&pass, cell, x->at.position, x->at.k1, x->at.k2, 1);
        }
    }
    for (int j = 1; j < nv; j++) {
        size_t k = axis[1].line_of[j];
        for (size_t n = L->cut_start[1][k]; n < L->cut_start[1][k + 1];
             n++) {
            const struct lattice_cut *x = &L->cut[1][n];
            size_t cell = (size_t)j * nu + column_cell[x->across];
            sample_cell(&pass, cell - (size_t)nu, x->at.position, x->at.k1,
                        x->at.k2, 1);
            sample_cell(&pass, cell, x->at.position, x->at.k1, x->at.k2, 1);
        }
    }
    /* ...and where they cross on the surface. */
    for (int j = 1; j < nv; j++)
        for (int i = 1; i < nu; i++) {
            const struct lattice_corner *q = grid_crossing(L, axis, i, j);
            if (q->state < 0)
                continue;
            size_t cell = (size_t)j * nu + (size_t)i;
            size_t around[4] = {cell - (size_t)nu - 1, cell - (size_t)nu,
                                cell - 1, cell};
            for (int a = 0; a < 4; a++)
                sample_cell(&pass, around[a], q->at.position, q->at.k1,
                            q->at.k2, q->state);
        }
    for (size_t n = 0; n < out->npanels; n++) {
        struct cell_samples *c = &samples[n];
        const struct sample_state *s = &state[n];
        c->deviation = s->deviation;
        c->k1_edge = s->k1;
        c->k2_edge = s->k2;
        c->edge_samples = s->edge_samples;
        c->k1_any = k_any[2 * n];
        c->k2_any = k_any[2 * n + 1];
    }
    free(state);
    free(k_any);
    return FACET_OK;
}

int panels_build_lattice(const struct panel_lattice *L, int nu, int nv,
                         struct panelization *out, struct facet_error *err)
{
    return panels_build_lattice_stoppable(L, nu, nv, NULL, out, err);
}

int panels_build_lattice_stoppable(const struct panel_lattice *L, int nu,
                                   int nv, const struct facet_stop *stop,
                                   struct panelization *out,
                                   struct facet_error *err)
{
    const struct panel_prep *prep = L->prep;
    struct panel_grid grid;
    int rc = panel_grid_init(&grid, prep->mesh, prep->index, nu, nv, out,
                             err);
    if (rc != FACET_OK)
        return rc;
    if (!panel_lattice_has(L, nu, nv))
        return facet_error_set(err, FACET_EINPUT,
            "grid %dx%d is not one of the panel lattice's", nu, nv);
    size_t ncells = (size_t)nu * (size_t)nv;
    size_t nnodes = (size_t)(nu + 1) * (size_t)(nv + 1);
    struct grid_axis axis[2];
    memset(axis, 0, sizeof axis);
    struct cell_moments *sums = calloc(ncells, sizeof *sums);
    struct grid_node *known = calloc(nnodes, sizeof *known);
    struct cell_samples *samples = NULL;
    struct cell_outline *outlines = NULL;
    rc = sums == NULL || known == NULL
             ? FACET_EWORK
             : grid_axis_make(L, 0, nu, grid.umin, grid.du, &axis[0]);
    if (rc == FACET_OK)
        rc = grid_axis_make(L, 1, nv, grid.vmin, grid.dv, &axis[1]);
    if (rc == FACET_EINPUT) {
        facet_error_set(err, FACET_EINPUT,
            "grid %dx%d: a line is missing from the panel lattice", nu, nv);
        goto done;
    }
    if (rc == FACET_OK)
        rc = grid_sums(L, &grid, axis, sums, known);
    if (rc != FACET_OK) {
        facet_error_set(err, FACET_EWORK, "out of memory (panels)");
        goto done;
    }
    if ((rc = facet_stop_check(stop, err)) != FACET_OK)
        goto done;
    rc = panels_fit(&grid, sums, known, stop, out, &samples, &outlines,
                    err);
    if (rc == FACET_OK)
        rc = facet_stop_check(stop, err);
    if (rc != FACET_OK)
        goto done;
    rc = grid_samples(L, axis, out, samples, outlines);
    if (rc != FACET_OK) {
        facet_error_set(err, FACET_EWORK, "out of memory (panels)");
        goto done;
    }
    if ((rc = facet_stop_check(stop, err)) != FACET_OK)
        goto done;
    panels_finish(PANEL_EXTREMES, samples, outlines, out);
    if (panels_curvature_range(&grid, prep->curvature_range,
                               PANEL_EXTREMES, out) != FACET_OK)
        rc = facet_error_set(err, FACET_EWORK, "out of memory (panels)");
done:
    free(sums);
    free(known);
    free(samples);
    free(outlines);
    grid_axis_free(&axis[0]);
    grid_axis_free(&axis[1]);
    return rc;
}
