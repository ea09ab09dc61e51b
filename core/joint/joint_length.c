/*
 * joint_length.c: grid lines followed through the mesh, and the outline.
 * See joint_length.h.
 */
#include "core/joint/joint_length.h"

#include <assert.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "core/base/parallel.h"
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

/* The triangles line x = line along axis may cross: [*from, *to) of the
 * axis's order. Only a triangle whose least coordinate is below the line,
 * by no more than the reach, can have a corner either side. */
static void line_window(const struct joint_prep *prep, int axis, double line,
                        size_t *from, size_t *to)
{
    *from = sorted_lower_bound(prep->least[axis], prep->ntriangles,
                               line - prep->reach[axis]);
    *to = sorted_lower_bound(prep->least[axis], prep->ntriangles, line);
    if (*to < *from)
        *to = *from;
}

/* The length of line x = line along axis through the x-th triangle of the
 * axis's order. */
static double crossing_at(const struct joint_prep *prep,
                          const struct mesh *mesh, int axis, size_t x,
                          double line)
{
    const struct joint_triangle *t = &prep->triangle[axis][x];
    /* Most of the window lies wholly before the line. */
    if (t->x[0] < line && t->x[1] < line && t->x[2] < line)
        return 0;
    const double *p[3];
    for (int k = 0; k < 3; k++)
        p[k] = &mesh->position[3 * (size_t)t->vertex[k]];
    return crossing_length(t->x, p, t->outline, line);
}

double joint_length(const struct joint_prep *prep, const struct mesh *mesh,
                    const struct uv_index *index,
                    const struct panelization *panels)
{
    return joint_length_lines(NULL, prep, mesh, index, panels);
}

/* The index of line in lines along axis, or SIZE_MAX. */
static size_t find_line(const struct joint_lines *lines, int axis,
                        double line)
{
    size_t k = sorted_lower_bound(lines->line[axis], lines->nline[axis],
                                  line);
    return k < lines->nline[axis] && lines->line[axis][k] == line ? k
                                                                 : SIZE_MAX;
}

int joint_length_lines_stoppable(const struct joint_lines *lines,
                                 const struct joint_prep *prep,
                                 const struct mesh *mesh,
                                 const struct uv_index *index,
                                 const struct panelization *panels,
                                 const struct facet_stop *stop,
                                 double *length, struct facet_error *err)
{
    (void)index;
    if (lines != NULL &&
        (lines->box[0] != panels->umin || lines->box[1] != panels->vmin ||
         lines->box[2] != panels->umax || lines->box[3] != panels->vmax))
        lines = NULL;
    double sum = prep->outline;
    for (int axis = 0; axis < 2; axis++) {
        double lo, d;
        int n = grid_lines(panels, axis, &lo, &d);
        for (int i = 1; i < n; i++) {
            double line = lo + i * d;
            size_t k = lines != NULL ? find_line(lines, axis, line)
                                     : SIZE_MAX;
            if (k != SIZE_MAX) {
                const double *kept = lines->length[axis] +
                                     lines->start[axis][k];
                for (size_t c = 0; c < lines->count[axis][k]; c++)
                    sum += kept[c];
                continue;
            }
            int rc = facet_stop_check(stop, err);
            if (rc != FACET_OK)
                return rc;
            size_t from, to;
            line_window(prep, axis, line, &from, &to);
            for (size_t x = from; x < to; x++)
                sum += crossing_at(prep, mesh, axis, x, line);
        }
    }
    *length = sum;
    return FACET_OK;
}

double joint_length_lines(const struct joint_lines *lines,
                          const struct joint_prep *prep,
                          const struct mesh *mesh,
                          const struct uv_index *index,
                          const struct panelization *panels)
{
    double length = NAN;
    int rc = joint_length_lines_stoppable(lines, prep, mesh, index, panels,
                                          NULL, &length, NULL);
    assert(rc == FACET_OK);
    (void)rc;
    return length;
}

/* joint_lines_build's lines [k0, k1) of one axis, on one thread. */
struct lines_job {
    const struct joint_prep *prep;
    const struct mesh *mesh;
    struct joint_lines *out;
    int axis;
    size_t k0, k1;
};

static void measure_lines(void *argument)
{
    struct lines_job *job = argument;
    struct joint_lines *out = job->out;
    int axis = job->axis;
    for (size_t k = job->k0; k < job->k1; k++) {
        double line = out->line[axis][k];
        double *kept = out->length[axis] + out->start[axis][k];
        size_t from, to, count = 0;
        line_window(job->prep, axis, line, &from, &to);
        for (size_t x = from; x < to; x++) {
            double c = crossing_at(job->prep, job->mesh, axis, x, line);
            if (c != 0)
                kept[count++] = c;
        }
        out->count[axis][k] = count;
    }
}

static int compare_doubles(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

int joint_lines_build(const struct joint_prep *prep, const struct mesh *mesh,
                      const struct uv_index *index, const int *const side[2],
                      const size_t nsides[2], int jobs,
                      struct joint_lines *out, struct facet_error *err)
{
    memset(out, 0, sizeof *out);
    /* The box panel_grid_init gives every grid over index. */
    struct panelization box = {0};
    box.umin = out->box[0] = index->umin;
    box.vmin = out->box[1] = index->vmin;
    box.umax = out->box[2] = index->umax;
    box.vmax = out->box[3] = index->vmax;
    if (jobs < 1)
        jobs = 1;
    if (jobs > PARALLEL_MAX)
        jobs = PARALLEL_MAX;
    for (int axis = 0; axis < 2; axis++) {
        size_t total = 0;
        for (size_t g = 0; g < nsides[axis]; g++)
            total += side[axis][g] > 1 ? (size_t)side[axis][g] - 1 : 0;
        double *line = malloc((total ? total : 1) * sizeof *line);
        out->line[axis] = line;
        if (line == NULL)
            goto no_memory;
        /* Each grid's lines as joint_length computes them. */
        size_t n = 0;
        for (size_t g = 0; g < nsides[axis]; g++) {
            box.nu = box.nv = side[axis][g];
            double lo, d;
            int count = grid_lines(&box, axis, &lo, &d);
            for (int i = 1; i < count; i++)
                line[n++] = lo + i * d;
        }
        qsort(line, n, sizeof *line, compare_doubles);
        size_t distinct = 0;
        for (size_t k = 0; k < n; k++)
            if (distinct == 0 || line[k] != line[distinct - 1])
                line[distinct++] = line[k];
        out->nline[axis] = distinct;
        out->start[axis] = malloc((distinct + 1) * sizeof *out->start[axis]);
        out->count[axis] = malloc((distinct ? distinct : 1) *
                                  sizeof *out->count[axis]);
        if (out->start[axis] == NULL || out->count[axis] == NULL)
            goto no_memory;
        /* Room for every triangle of each line's window. */
        out->start[axis][0] = 0;
        for (size_t k = 0; k < distinct; k++) {
            size_t from, to;
            line_window(prep, axis, line[k], &from, &to);
            out->start[axis][k + 1] = out->start[axis][k] + (to - from);
        }
        size_t room = out->start[axis][distinct];
        out->length[axis] = malloc((room ? room : 1) *
                                   sizeof *out->length[axis]);
        if (out->length[axis] == NULL)
            goto no_memory;
        struct lines_job job[PARALLEL_MAX];
        int njobs = distinct < (size_t)jobs ? (int)(distinct ? distinct : 1)
                                            : jobs;
        for (int j = 0; j < njobs; j++)
            job[j] = (struct lines_job){prep, mesh, out, axis,
                                        distinct * (size_t)j / (size_t)njobs,
                                        distinct * (size_t)(j + 1) /
                                            (size_t)njobs};
        parallel_run(job, sizeof job[0], njobs, measure_lines);
    }
    return FACET_OK;
no_memory:
    return facet_error_set(err, FACET_EWORK,
                           "out of memory for the joint lines");
}

void joint_lines_free(struct joint_lines *lines)
{
    for (int axis = 0; axis < 2; axis++) {
        free(lines->line[axis]);
        free(lines->start[axis]);
        free(lines->count[axis]);
        free(lines->length[axis]);
    }
    memset(lines, 0, sizeof *lines);
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
