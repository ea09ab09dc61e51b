/*
 * param_chart.c: the charts of a UV map, by union-find over the edges
 * where UV is continuous. See param_chart.h.
 */
#include "core/surface/param_chart.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static uint32_t find_root(uint32_t *parent, uint32_t x)
{
    while (parent[x] != x) {
        parent[x] = parent[parent[x]];
        x = parent[x];
    }
    return x;
}

/* Whether corner a of triangle s and corner b of triangle t have the same
 * UV to tol. */
static int same_uv(const double *uv, size_t s, int a, size_t t, int b,
                   double tol)
{
    return fabs(uv[6 * s + 2 * a] - uv[6 * t + 2 * b]) <= tol &&
           fabs(uv[6 * s + 2 * a + 1] - uv[6 * t + 2 * b + 1]) <= tol;
}

static int corner_of(const uint32_t *tri, uint32_t vertex)
{
    for (int k = 0; k < 3; k++)
        if (tri[k] == vertex)
            return k;
    return -1;
}

static int out_of_memory(struct facet_error *err, size_t ntriangles)
{
    return facet_error_set(err, FACET_EWORK,
                           "out of memory (UV charts of %zu triangles)",
                           ntriangles);
}

int param_charts(const struct mesh *mesh, const double *uv,
                 struct uv_chart *chart, size_t max, size_t *count,
                 struct facet_error *err)
{
    *count = 0;
    size_t nt = mesh->ntriangles;
    if (nt == 0)
        return FACET_OK;
    double umin = INFINITY, umax = -INFINITY, vmin = INFINITY,
           vmax = -INFINITY;
    for (size_t c = 0; c < 3 * nt; c++) {
        umin = fmin(umin, uv[2 * c]);
        umax = fmax(umax, uv[2 * c]);
        vmin = fmin(vmin, uv[2 * c + 1]);
        vmax = fmax(vmax, uv[2 * c + 1]);
    }
    double tol = 1e-9 * fmax(umax - umin, vmax - vmin);
    uint32_t *parent = malloc(nt * sizeof *parent);
    uint32_t *index = malloc(nt * sizeof *index);
    if (parent == NULL || index == NULL) {
        free(parent);
        free(index);
        return out_of_memory(err, nt);
    }
    for (size_t t = 0; t < nt; t++)
        parent[t] = (uint32_t)t;
    for (size_t t = 0; t < nt; t++) {
        const uint32_t *tri = mesh->triangle + 3 * t;
        for (int k = 0; k < 3; k++) {
            uint32_t n = mesh->neighbour[3 * t + k];
            if (n == MESH_NONE || n < t)
                continue;
            const uint32_t *other = mesh->triangle + 3 * (size_t)n;
            int a = corner_of(other, tri[k]);
            int b = corner_of(other, tri[(k + 1) % 3]);
            if (a < 0 || b < 0 || !same_uv(uv, t, k, n, a, tol) ||
                !same_uv(uv, t, (k + 1) % 3, n, b, tol))
                continue;
            uint32_t x = find_root(parent, (uint32_t)t);
            uint32_t y = find_root(parent, n);
            if (x != y)
                parent[x < y ? y : x] = x < y ? x : y;
        }
    }
    /* Number the charts, then fill their sizes and boxes. */
    size_t charts = 0;
    for (size_t t = 0; t < nt; t++)
        if (find_root(parent, (uint32_t)t) == t)
            index[t] = (uint32_t)charts++;
    struct uv_chart *all = calloc(charts, sizeof *all);
    if (all == NULL) {
        free(parent);
        free(index);
        return out_of_memory(err, nt);
    }
    for (size_t c = 0; c < charts; c++) {
        all[c].umin = all[c].vmin = INFINITY;
        all[c].umax = all[c].vmax = -INFINITY;
    }
    for (size_t t = 0; t < nt; t++) {
        struct uv_chart *c = &all[index[find_root(parent, (uint32_t)t)]];
        c->triangles++;
        for (int k = 0; k < 3; k++) {
            c->umin = fmin(c->umin, uv[6 * t + 2 * k]);
            c->umax = fmax(c->umax, uv[6 * t + 2 * k]);
            c->vmin = fmin(c->vmin, uv[6 * t + 2 * k + 1]);
            c->vmax = fmax(c->vmax, uv[6 * t + 2 * k + 1]);
        }
    }
    /* The largest first (a selection: max is small). */
    for (size_t k = 0; k < max && k < charts; k++) {
        size_t best = k;
        for (size_t c = k + 1; c < charts; c++)
            if (all[c].triangles > all[best].triangles)
                best = c;
        struct uv_chart swap = all[k];
        all[k] = all[best];
        all[best] = swap;
        chart[k] = all[k];
    }
    free(all);
    free(parent);
    free(index);
    *count = charts;
    return FACET_OK;
}
