/*
 * joint_length.c: grid lines followed through the mesh, and the outline.
 * See joint_length.h.
 */
#include "core/joint/joint_length.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/base/sorted.h"
#include "core/base/vec3.h"

static const double *corner_position(const struct mesh *mesh, size_t t,
                                     int k)
{
    return &mesh->position[3 * (size_t)mesh->triangle[3 * t + (size_t)k]];
}

static const double *corner_uv(const struct uv_index *index, size_t t,
                               int k)
{
    return &index->uv[6 * t + 2 * (size_t)k];
}

/* The corner of triangle n at vertex v, or -1. */
static int corner_of_vertex(const struct mesh *mesh, size_t n, uint32_t v)
{
    for (int k = 0; k < 3; k++)
        if (mesh->triangle[3 * n + (size_t)k] == v)
            return k;
    return -1;
}

/* The weight edge k (corner k to k + 1) of triangle t has in the outline:
 * 1 on a boundary, 1/2 along a UV seam (the triangle across counts the
 * other half), 0 inside the UV chart. */
static double outline_weight(const struct mesh *mesh,
                             const struct uv_index *index, size_t t, int k)
{
    uint32_t n = mesh->neighbour[3 * t + (size_t)k];
    if (n == MESH_NONE)
        return 1;
    for (int e = 0; e < 2; e++) {
        uint32_t v = mesh->triangle[3 * t + (size_t)((k + e) % 3)];
        int c = corner_of_vertex(mesh, n, v);
        if (c < 0)
            return 1;
        const double *a = corner_uv(index, t, (k + e) % 3);
        const double *b = corner_uv(index, n, c);
        if (a[0] != b[0] || a[1] != b[1])
            return 0.5;
    }
    return 0;
}

double joint_outline_length(const struct mesh *mesh,
                            const struct uv_index *index)
{
    double length = 0;
    for (size_t t = 0; t < mesh->ntriangles; t++)
        for (int k = 0; k < 3; k++) {
            double w = outline_weight(mesh, index, t, k);
            if (w > 0)
                length += w * vec3_distance(corner_position(mesh, t, k),
                                            corner_position(mesh, t,
                                                            (k + 1) % 3));
        }
    return length;
}

/* The length of line x = line through a triangle whose corners lie at x[k]
 * along the line's axis and at p[k] in space, its edges on the outline
 * marked in outline (bit k: edge k to k + 1). A corner on the line counts
 * as beyond it (x >= line), so that a line along an edge is taken by one
 * of the edge's two triangles only; when it is an outline edge, by
 * neither (the outline counts it). */
static double crossing_length(const double x[3], const double *p[3],
                              unsigned outline, double line)
{
    int beyond[3], nbeyond = 0;
    for (int k = 0; k < 3; k++) {
        beyond[k] = x[k] >= line;
        nbeyond += beyond[k];
    }
    if (nbeyond == 0 || nbeyond == 3)
        return 0;
    double point[2][3];
    int at_corner[2], npoints = 0;
    for (int k = 0; k < 3; k++) {
        int a = k, b = (k + 1) % 3;
        if (beyond[a] == beyond[b])
            continue;
        int below = beyond[a] ? b : a, above = beyond[a] ? a : b;
        double xb = x[below], xa = x[above];
        const double *pb = p[below], *pa = p[above];
        at_corner[npoints] = xa == line ? above : -1;
        double f = (line - xb) / (xa - xb);
        for (int r = 0; r < 3; r++)
            point[npoints][r] = xa == line ? pa[r] : pb[r] + f * (pa[r] - pb[r]);
        npoints++;
    }
    if (at_corner[0] >= 0 && at_corner[1] >= 0 &&
        at_corner[0] != at_corner[1]) {
        int a = at_corner[0], b = at_corner[1];
        int edge = (a + 1) % 3 == b ? a : b;
        if (outline >> edge & 1)
            return 0;
    }
    return vec3_distance(point[0], point[1]);
}

/* Which edges of triangle t count in the outline (bit k: edge k). */
static unsigned outline_edges(const struct mesh *mesh,
                              const struct uv_index *index, size_t t)
{
    unsigned bits = 0;
    for (int k = 0; k < 3; k++)
        if (outline_weight(mesh, index, t, k) > 0)
            bits |= 1u << k;
    return bits;
}

/* The length of line x[axis] = line through triangle t, from the mesh. */
static double crossing_length_plain(const struct mesh *mesh,
                                    const struct uv_index *index, size_t t,
                                    int axis, double line)
{
    double x[3];
    const double *p[3];
    for (int k = 0; k < 3; k++) {
        x[k] = corner_uv(index, t, k)[axis];
        p[k] = corner_position(mesh, t, k);
    }
    return crossing_length(x, p, outline_edges(mesh, index, t), line);
}

/* Sorts triangles by their least coordinate along one axis. */
struct by_least {
    double least;
    uint32_t triangle;
};

static int compare_least(const void *a, const void *b)
{
    const struct by_least *p = a, *q = b;
    if (p->least != q->least)
        return p->least < q->least ? -1 : 1;
    return p->triangle < q->triangle ? -1 : p->triangle > q->triangle;
}

int joint_prep_build(const struct mesh *mesh, const struct uv_index *index,
                     struct joint_prep *out, struct facet_error *err)
{
    memset(out, 0, sizeof *out);
    size_t n = mesh->ntriangles;
    out->ntriangles = n;
    out->outline = joint_outline_length(mesh, index);
    struct by_least *sorted = malloc((n ? n : 1) * sizeof *sorted);
    unsigned char *outline = malloc(n ? n : 1);
    int failed = sorted == NULL || outline == NULL;
    for (int axis = 0; axis < 2; axis++) {
        out->order[axis] = malloc((n ? n : 1) * sizeof *out->order[axis]);
        out->least[axis] = malloc((n ? n : 1) * sizeof *out->least[axis]);
        out->triangle[axis] = malloc((n ? n : 1) *
                                     sizeof *out->triangle[axis]);
        failed |= out->order[axis] == NULL || out->least[axis] == NULL ||
                  out->triangle[axis] == NULL;
    }
    if (failed) {
        free(outline);
        free(sorted);
        return facet_error_set(err, FACET_EWORK,
                               "out of memory for the joint lengths");
    }
    for (size_t t = 0; t < n; t++)
        outline[t] = (unsigned char)outline_edges(mesh, index, t);
    for (int axis = 0; axis < 2; axis++) {
        double reach = 0;
        for (size_t t = 0; t < n; t++) {
            double x0 = corner_uv(index, t, 0)[axis], x1 = x0;
            for (int k = 1; k < 3; k++) {
                x0 = fmin(x0, corner_uv(index, t, k)[axis]);
                x1 = fmax(x1, corner_uv(index, t, k)[axis]);
            }
            sorted[t].least = x0;
            sorted[t].triangle = (uint32_t)t;
            reach = fmax(reach, x1 - x0);
        }
        qsort(sorted, n, sizeof *sorted, compare_least);
        for (size_t x = 0; x < n; x++) {
            uint32_t t = sorted[x].triangle;
            struct joint_triangle *to = &out->triangle[axis][x];
            out->order[axis][x] = t;
            out->least[axis][x] = sorted[x].least;
            for (int k = 0; k < 3; k++) {
                to->x[k] = corner_uv(index, t, k)[axis];
                to->vertex[k] = mesh->triangle[3 * (size_t)t + (size_t)k];
            }
            to->outline = outline[t];
        }
        /* x1 - x0 is rounded: widen it so that no triangle reaching a
         * line is missed. */
        out->reach[axis] = reach * (1 + 1e-9) + 1e-300;
    }
    free(sorted);
    free(outline);
    return FACET_OK;
}

void joint_prep_free(struct joint_prep *prep)
{
    for (int axis = 0; axis < 2; axis++) {
        free(prep->order[axis]);
        free(prep->least[axis]);
        free(prep->triangle[axis]);
    }
    memset(prep, 0, sizeof *prep);
}

/* The grid's lines along axis: line i (1..count-1) at *first + i *
 * *step; returns count, 0 when the axis has no inner line. */
static int grid_lines(const struct panelization *panels, int axis,
                      double *first, double *step)
{
    double lo[2] = {panels->umin, panels->vmin};
    double extent[2] = {panels->umax - panels->umin,
                        panels->vmax - panels->vmin};
    int n[2] = {panels->nu, panels->nv};
    if (n[axis] < 2 || !(extent[axis] > 0))
        return 0;
    *first = lo[axis];
    *step = extent[axis] / n[axis];
    return n[axis];
}

double joint_length(const struct joint_prep *prep, const struct mesh *mesh,
                    const struct uv_index *index,
                    const struct panelization *panels)
{
    (void)index;
    double length = prep->outline;
    for (int axis = 0; axis < 2; axis++) {
        double lo, d;
        int n = grid_lines(panels, axis, &lo, &d);
        const struct joint_triangle *triangle = prep->triangle[axis];
        for (int i = 1; i < n; i++) {
            double line = lo + i * d;
            /* Only a triangle whose least coordinate is below the line,
             * by no more than the reach, can have a corner either side. */
            size_t x = sorted_lower_bound(prep->least[axis],
                                          prep->ntriangles,
                                          line - prep->reach[axis]);
            for (; x < prep->ntriangles && prep->least[axis][x] < line; x++) {
                const struct joint_triangle *t = &triangle[x];
                /* Most of the window lies wholly before the line. */
                if (t->x[0] < line && t->x[1] < line && t->x[2] < line)
                    continue;
                const double *p[3];
                for (int k = 0; k < 3; k++)
                    p[k] = &mesh->position[3 * (size_t)t->vertex[k]];
                length += crossing_length(t->x, p, t->outline, line);
            }
        }
    }
    return length;
}

double joint_length_plain(const struct joint_prep *prep,
                          const struct mesh *mesh,
                          const struct uv_index *index,
                          const struct panelization *panels)
{
    double length = prep->outline;
    for (int axis = 0; axis < 2; axis++) {
        double lo, d;
        int n = grid_lines(panels, axis, &lo, &d);
        for (int i = 1; i < n; i++)
            for (size_t x = 0; x < prep->ntriangles; x++)
                length += crossing_length_plain(mesh, index,
                                                prep->order[axis][x], axis,
                                                lo + i * d);
    }
    return length;
}
