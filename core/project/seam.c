/*
 * seam.c: where two surfaces of a building meet. See seam.h.
 */
#include "core/project/seam.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/base/numparse.h"
#include "core/base/units.h"
#include "core/base/vec3.h"

/* A boundary edge, from its triangle's corner k to corner k + 1 (the
 * winding's direction). */
struct boundary_edge {
    uint32_t triangle;
    uint32_t vertex[2];
};

/* One cell of the grid over b's boundary an edge reaches (within weld). */
struct cell_entry {
    int64_t key[3];
    size_t edge;
};

struct edge_grid {
    double cell;
    struct cell_entry *entry;
    size_t nentries;
};

static size_t boundary_edges(const struct mesh *mesh,
                             struct boundary_edge *out)
{
    size_t n = 0;
    for (size_t t = 0; t < mesh->ntriangles; t++)
        for (int k = 0; k < 3; k++) {
            if (mesh->neighbour[3 * t + (size_t)k] != MESH_NONE)
                continue;
            if (out != NULL) {
                out[n].triangle = (uint32_t)t;
                out[n].vertex[0] = mesh->triangle[3 * t + (size_t)k];
                out[n].vertex[1] = mesh->triangle[3 * t + (size_t)(k + 1) % 3];
            }
            n++;
        }
    return n;
}

static const double *position(const struct mesh *mesh, uint32_t v)
{
    return mesh->position + 3 * (size_t)v;
}

static int compare_entries(const void *x, const void *y)
{
    const struct cell_entry *a = x, *b = y;
    for (int d = 0; d < 3; d++)
        if (a->key[d] != b->key[d])
            return a->key[d] < b->key[d] ? -1 : 1;
    return a->edge < b->edge ? -1 : a->edge > b->edge;
}

static int64_t cell_of(double x, double cell)
{
    return (int64_t)floor(x / cell);
}

/* Puts each of b's edges into every cell its box, widened by weld, meets.
 * Returns 0, or -1 when out of memory. */
static int grid_build(const struct mesh *b, const struct boundary_edge *edge,
                      size_t nedges, double weld, struct edge_grid *g)
{
    memset(g, 0, sizeof *g);
    double total = 0;
    for (size_t e = 0; e < nedges; e++)
        total += vec3_distance(position(b, edge[e].vertex[0]),
                               position(b, edge[e].vertex[1]));
    g->cell = fmax(2 * weld, nedges ? total / (double)nedges : 1);
    if (!(g->cell > 0))
        g->cell = 1;
    for (int pass = 0; pass < 2; pass++) {
        size_t n = 0;
        for (size_t e = 0; e < nedges; e++) {
            const double *p = position(b, edge[e].vertex[0]);
            const double *q = position(b, edge[e].vertex[1]);
            int64_t lo[3], hi[3];
            for (int d = 0; d < 3; d++) {
                lo[d] = cell_of(fmin(p[d], q[d]) - weld, g->cell);
                hi[d] = cell_of(fmax(p[d], q[d]) + weld, g->cell);
            }
            for (int64_t x = lo[0]; x <= hi[0]; x++)
                for (int64_t y = lo[1]; y <= hi[1]; y++)
                    for (int64_t z = lo[2]; z <= hi[2]; z++) {
                        if (pass == 1)
                            g->entry[n] = (struct cell_entry){{x, y, z}, e};
                        n++;
                    }
        }
        if (pass == 0) {
            g->entry = malloc((n ? n : 1) * sizeof *g->entry);
            if (g->entry == NULL)
                return -1;
        } else {
            g->nentries = n;
        }
    }
    qsort(g->entry, g->nentries, sizeof *g->entry, compare_entries);
    return 0;
}

/* The nearest point of segment p..q to x, and its parameter 0..1. */
static double nearest_on_segment(const double p[3], const double q[3],
                                 const double x[3], double out[3])
{
    double d[3], r[3];
    vec3_sub(q, p, d);
    vec3_sub(x, p, r);
    double length2 = vec3_dot(d, d);
    double f = length2 > 0 ? vec3_dot(r, d) / length2 : 0;
    f = f < 0 ? 0 : f > 1 ? 1 : f;
    for (int k = 0; k < 3; k++)
        out[k] = p[k] + f * d[k];
    return f;
}

/* The nearest of b's boundary edges to x within weld: its index, or
 * SIZE_MAX; its nearest point into near, the parameter into *f. */
static size_t nearest_edge(const struct mesh *b,
                           const struct boundary_edge *edge,
                           const struct edge_grid *g, const double x[3],
                           double weld, double near[3], double *f)
{
    struct cell_entry probe = {{cell_of(x[0], g->cell),
                                cell_of(x[1], g->cell),
                                cell_of(x[2], g->cell)}, 0};
    size_t lo = 0, hi = g->nentries;
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        if (compare_entries(&g->entry[mid], &probe) < 0)
            lo = mid + 1;
        else
            hi = mid;
    }
    size_t best = SIZE_MAX;
    double best_distance = weld;
    for (size_t k = lo; k < g->nentries; k++) {
        const struct cell_entry *c = &g->entry[k];
        if (c->key[0] != probe.key[0] || c->key[1] != probe.key[1] ||
            c->key[2] != probe.key[2])
            break;
        double point[3];
        double t = nearest_on_segment(position(b, edge[c->edge].vertex[0]),
                                      position(b, edge[c->edge].vertex[1]),
                                      x, point);
        double distance = vec3_distance(point, x);
        if (distance <= best_distance) {
            best_distance = distance;
            best = c->edge;
            memcpy(near, point, sizeof point);
            *f = t;
        }
    }
    return best;
}

/* The curvature fit's unit normal at fraction f along edge e. */
static void normal_along(const struct curvature *curvature,
                         const struct boundary_edge *e, double f,
                         double out[3])
{
    const double *n0 = curvature->surface_normal + 3 * (size_t)e->vertex[0];
    const double *n1 = curvature->surface_normal + 3 * (size_t)e->vertex[1];
    for (int k = 0; k < 3; k++)
        out[k] = (1 - f) * n0[k] + f * n1[k];
    vec3_normalize(out);
}

static int boxes_apart(const struct mesh *a, const struct mesh *b,
                       double weld)
{
    for (int d = 0; d < 3; d++)
        if (a->bbox_min[d] > b->bbox_max[d] + weld ||
            b->bbox_min[d] > a->bbox_max[d] + weld)
            return 1;
    return 0;
}

int seam_find(const struct mesh *a, const struct curvature *curvature_a,
              const struct mesh *b, const struct curvature *curvature_b,
              double weld, double spacing, struct seam *out,
              struct facet_error *err)
{
    memset(out, 0, sizeof *out);
    if (!(weld >= 0) || !isfinite(weld))
        return facet_error_set(err, FACET_EINPUT,
            "welding tolerance %g m: must be a finite length of 0 or more",
            weld);
    if (!(spacing > 0) || !isfinite(spacing))
        return facet_error_set(err, FACET_EINPUT,
            "seam sample spacing %g m: must be a finite length above 0",
            spacing);
    if (boxes_apart(a, b, weld))
        return FACET_OK;
    size_t na = boundary_edges(a, NULL), nb = boundary_edges(b, NULL);
    struct boundary_edge *ea = malloc((na ? na : 1) * sizeof *ea);
    struct boundary_edge *eb = malloc((nb ? nb : 1) * sizeof *eb);
    struct edge_grid grid = {0, NULL, 0};
    size_t capacity = 0;
    int rc = FACET_OK;
    if (ea == NULL || eb == NULL || grid_build(b, eb, boundary_edges(b, eb),
                                               weld, &grid) != 0)
        rc = FACET_EWORK;
    if (rc == FACET_OK)
        boundary_edges(a, ea);
    for (size_t e = 0; rc == FACET_OK && e < na; e++) {
        const double *p = position(a, ea[e].vertex[0]);
        const double *q = position(a, ea[e].vertex[1]);
        double length = vec3_distance(p, q);
        size_t pieces = (size_t)ceil(length / spacing);
        if (pieces < 1)
            pieces = 1;
        if (out->npoints + pieces + 1 > capacity) {
            size_t want = 2 * capacity + pieces + 1;
            struct seam_point *grown =
                realloc(out->points, want * sizeof *grown);
            if (grown == NULL) {
                rc = FACET_EWORK;
                break;
            }
            out->points = grown;
            capacity = want;
        }
        size_t first = out->npoints;
        int whole = 1;
        /* Which way b runs along this edge, decided once, at its middle:
         * an end of the edge may meet b where b's outline turns a corner,
         * and the nearest edge of b there may run across, not along, so
         * that its direction says nothing about b's winding. */
        double middle[3], near_middle[3], g_middle;
        for (int k = 0; k < 3; k++)
            middle[k] = 0.5 * (p[k] + q[k]);
        size_t along = nearest_edge(b, eb, &grid, middle, weld, near_middle,
                                    &g_middle);
        if (along == SIZE_MAX)
            continue;
        double da[3], db[3];
        vec3_sub(q, p, da);
        vec3_sub(position(b, eb[along].vertex[1]),
                 position(b, eb[along].vertex[0]), db);
        /* Consistently wound faces run a shared edge opposite ways. */
        int turned = vec3_dot(da, db) > 0;
        for (size_t s = 0; s <= pieces && whole; s++) {
            double f = (double)s / (double)pieces;
            struct seam_point *x = &out->points[first + s];
            for (int k = 0; k < 3; k++)
                x->at[k] = p[k] + f * (q[k] - p[k]);
            double g;
            size_t across = nearest_edge(b, eb, &grid, x->at, weld,
                                         x->across, &g);
            if (across == SIZE_MAX) {
                whole = 0;
                break;
            }
            x->triangle_a = ea[e].triangle;
            x->triangle_b = eb[across].triangle;
            double *na_ = x->normal_a, *nb_ = x->normal_b;
            normal_along(curvature_a, &ea[e], f, na_);
            normal_along(curvature_b, &eb[across], g, nb_);
            if (turned)
                for (int k = 0; k < 3; k++)
                    nb_[k] = -nb_[k];
            x->crease = vec3_angle(na_, nb_);
        }
        if (!whole)
            continue;
        for (size_t s = 0; s <= pieces; s++) {
            const struct seam_point *x = &out->points[first + s];
            out->max_crease = fmax(out->max_crease, x->crease);
            out->max_apart = fmax(out->max_apart,
                                  vec3_distance(x->at, x->across));
        }
        out->npoints = first + pieces + 1;
        out->nedges++;
        out->length += length;
    }
    free(ea);
    free(eb);
    free(grid.entry);
    if (rc != FACET_OK) {
        seam_free(out);
        return facet_error_set(err, FACET_EWORK,
                               "out of memory finding a seam");
    }
    return FACET_OK;
}

void seam_free(struct seam *seam)
{
    free(seam->points);
    memset(seam, 0, sizeof *seam);
}

int seam_weld_parse(const char *text, const char *what, double *weld,
                    struct facet_error *err)
{
    double mm;
    int rc = numparse_number(text, units_mm(SEAM_WELD_MIN),
                             units_mm(SEAM_WELD_MAX), what, &mm, err);
    if (rc == FACET_OK)
        *weld = units_m_of_mm(mm);
    return rc;
}
