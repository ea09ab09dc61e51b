/*
 * uv_index.c: the UV bucket grid, point location and the UV map check.
 * See uv_index.h.
 */
#include "core/surface/uv_index.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/base/parallel.h"

/* Cells per triangle: about one keeps buckets short without wasting memory. */
#define MAX_CELLS_PER_AXIS 4096

/* fmin and fmax for numbers that are not NaN (every UV value here is
 * finite: uv_index_build refuses others), without the library call. */
static inline double min2(double a, double b)
{
    return b < a ? b : a;
}

static inline double max2(double a, double b)
{
    return b > a ? b : a;
}

static void triangle_box(const double *uv, size_t t, double box[4])
{
    const double *c = uv + 6 * t;
    box[0] = min2(c[0], min2(c[2], c[4]));
    box[1] = min2(c[1], min2(c[3], c[5]));
    box[2] = max2(c[0], max2(c[2], c[4]));
    box[3] = max2(c[1], max2(c[3], c[5]));
}

static int cell_of(double x, double origin, double size, int count)
{
    double f = (x - origin) / size;
    if (!(f > 0))
        return 0;
    if (f >= count)
        return count - 1;
    return (int)f;
}

int uv_index_frame(const double *uv, size_t ntriangles, struct uv_index *out,
                   struct facet_error *err)
{
    memset(out, 0, sizeof *out);
    out->uv = uv;
    out->ntriangles = ntriangles;
    out->umin = out->vmin = INFINITY;
    out->umax = out->vmax = -INFINITY;
    for (size_t i = 0; i < 6 * ntriangles; i++) {
        if (!isfinite(uv[i]))
            return facet_error_set(err, FACET_EINPUT,
                "texture coordinate of triangle %zu is not a finite number",
                i / 6 + 1);
        if (i % 2 == 0) {
            out->umin = fmin(out->umin, uv[i]);
            out->umax = fmax(out->umax, uv[i]);
        } else {
            out->vmin = fmin(out->vmin, uv[i]);
            out->vmax = fmax(out->vmax, uv[i]);
        }
    }
    if (ntriangles == 0) {
        out->umin = out->vmin = 0;
        out->umax = out->vmax = 1;
    }

    /* Square-ish cells, about one per triangle. */
    double width = fmax(out->umax - out->umin, 1e-300);
    double height = fmax(out->vmax - out->vmin, 1e-300);
    double cells = ntriangles > 0 ? (double)ntriangles : 1;
    double nu = ceil(sqrt(cells * width / height));
    double nv = ceil(cells / nu);
    out->ncells_u = (int)fmin(fmax(nu, 1), MAX_CELLS_PER_AXIS);
    out->ncells_v = (int)fmin(fmax(nv, 1), MAX_CELLS_PER_AXIS);
    out->cell_u = width / out->ncells_u;
    out->cell_v = height / out->ncells_v;
    return FACET_OK;
}

int uv_index_build(const double *uv, size_t ntriangles, struct uv_index *out,
                   struct facet_error *err)
{
    int rc = uv_index_frame(uv, ntriangles, out, err);
    if (rc != FACET_OK)
        return rc;
    size_t ncells = (size_t)out->ncells_u * (size_t)out->ncells_v;
    out->cell_start = calloc(ncells + 1, sizeof *out->cell_start);
    if (out->cell_start == NULL)
        return facet_error_set(err, FACET_EWORK, "out of memory (UV index)");

    /* Count, prefix-sum, fill: two passes over the triangles. */
    size_t entries = 0;
    for (int pass = 0; pass < 2; pass++) {
        for (size_t t = 0; t < ntriangles; t++) {
            double box[4];
            triangle_box(uv, t, box);
            int i0 = cell_of(box[0], out->umin, out->cell_u, out->ncells_u);
            int i1 = cell_of(box[2], out->umin, out->cell_u, out->ncells_u);
            int j0 = cell_of(box[1], out->vmin, out->cell_v, out->ncells_v);
            int j1 = cell_of(box[3], out->vmin, out->cell_v, out->ncells_v);
            for (int j = j0; j <= j1; j++)
                for (int i = i0; i <= i1; i++) {
                    size_t c = (size_t)j * out->ncells_u + i;
                    if (pass == 0)
                        out->cell_start[c + 1]++;
                    else
                        out->cell_triangles[out->cell_start[c]++] =
                            (uint32_t)t;
                }
        }
        if (pass == 0) {
            for (size_t c = 0; c < ncells; c++) {
                entries += out->cell_start[c + 1];
                if (entries > UINT32_MAX)
                    return facet_error_set(err, FACET_EWORK,
                        "UV index too large: the UV map has triangles "
                        "spanning most of its range");
                out->cell_start[c + 1] = (uint32_t)entries;
            }
            out->cell_triangles = malloc((entries ? entries : 1) *
                                         sizeof *out->cell_triangles);
            if (out->cell_triangles == NULL)
                return facet_error_set(err, FACET_EWORK,
                                       "out of memory (UV index)");
        }
    }
    /* The fill pass advanced each start to the next cell's; shift back. */
    memmove(out->cell_start + 1, out->cell_start, ncells * sizeof(uint32_t));
    out->cell_start[0] = 0;
    return FACET_OK;
}

void uv_index_free(struct uv_index *index)
{
    free(index->cell_start);
    free(index->cell_triangles);
    memset(index, 0, sizeof *index);
}

/* fmin for the barycentric margins, which a huge or tiny triangle can
 * make NaN: the other value when one is NaN, as fmin, without the library
 * call (locating a point is the inner loop of sampling a surface). */
static inline double min_number(double a, double b)
{
    if (a != a)
        return b;
    return b < a ? b : a;
}

uint32_t uv_index_locate(const struct uv_index *index, double u, double v,
                         double tolerance, double barycentric[3])
{
    if (index->ntriangles == 0 || !(u >= index->umin - index->cell_u) ||
        !(u <= index->umax + index->cell_u) ||
        !(v >= index->vmin - index->cell_v) ||
        !(v <= index->vmax + index->cell_v))
        return UINT32_MAX;
    int i = cell_of(u, index->umin, index->cell_u, index->ncells_u);
    int j = cell_of(v, index->vmin, index->cell_v, index->ncells_v);
    size_t c = (size_t)j * index->ncells_u + i;

    /* Keep the best candidate so that a point just outside every triangle
     * by rounding still finds the nearest one within tolerance. */
    uint32_t best = UINT32_MAX;
    double best_margin = -INFINITY;
    for (uint32_t k = index->cell_start[c]; k < index->cell_start[c + 1];
         k++) {
        uint32_t t = index->cell_triangles[k];
        double b[3];
        if (!uv_index_barycentric(index, t, u, v, b))
            continue;
        double margin = min_number(b[0], min_number(b[1], b[2]));
        if (margin >= 0) {
            memcpy(barycentric, b, sizeof b);
            return t;
        }
        if (margin >= -tolerance && margin > best_margin) {
            best_margin = margin;
            best = t;
            memcpy(barycentric, b, sizeof b);
        }
    }
    return best;
}

static double signed_area(const double *c)
{
    return 0.5 * ((c[2] - c[0]) * (c[5] - c[1]) -
                  (c[4] - c[0]) * (c[3] - c[1]));
}

/* Whether the projections of triangles a and b onto the normal of one edge
 * of a are separated (overlapping by no more than tolerance). */
static int separated_by_edges_of(const double *a, const double *b,
                                 double tolerance)
{
    for (int e = 0; e < 3; e++) {
        const double *p = a + 2 * e, *q = a + 2 * ((e + 1) % 3);
        double nx = q[1] - p[1], ny = p[0] - q[0];
        double length = hypot(nx, ny);
        if (length == 0)
            continue;
        nx /= length;
        ny /= length;
        double amin = INFINITY, amax = -INFINITY;
        double bmin = INFINITY, bmax = -INFINITY;
        for (int k = 0; k < 3; k++) {
            double pa = a[2 * k] * nx + a[2 * k + 1] * ny;
            double pb = b[2 * k] * nx + b[2 * k + 1] * ny;
            amin = min2(amin, pa);
            amax = max2(amax, pa);
            bmin = min2(bmin, pb);
            bmax = max2(bmax, pb);
        }
        if (amax <= bmin + tolerance || bmax <= amin + tolerance)
            return 1;
    }
    return 0;
}

/* Whether the interiors of two UV triangles overlap by more than tolerance:
 * triangles sharing an edge or a corner do not. */
static int interiors_overlap(const double *a, const double *b,
                             double tolerance)
{
    return !separated_by_edges_of(a, b, tolerance) &&
           !separated_by_edges_of(b, a, tolerance);
}

/* uv_check's pair test over the cell rows [j0, j1) of index. */
struct overlap_job {
    const struct uv_index *index;
    const double *uv;
    double tiny_area, tolerance;
    int j0, j1;
    size_t overlapping;   /* out: the overlapping pairs found */
    const struct facet_stop *stop;  /* asked before each row of cells */
    int stopped;          /* out: it fired */
};

enum { OVERLAP_THREADS_MAX = 8, OVERLAP_THREADS_FROM = 20000 };

static void overlap_rows(void *argument)
{
    struct overlap_job *job = argument;
    const struct uv_index *index = job->index;
    const double *uv = job->uv;
    for (int j = job->j0; j < job->j1; j++) {
        if (facet_stop_requested(job->stop)) {
            job->stopped = 1;
            return;
        }
        for (int i = 0; i < index->ncells_u; i++) {
            size_t c = (size_t)j * index->ncells_u + i;
            for (uint32_t x = index->cell_start[c];
                 x < index->cell_start[c + 1]; x++) {
                uint32_t s = index->cell_triangles[x];
                const double *a = uv + 6 * (size_t)s;
                if (fabs(signed_area(a)) <= job->tiny_area)
                    continue;
                double box_a[4];
                triangle_box(uv, s, box_a);
                for (uint32_t y = x + 1; y < index->cell_start[c + 1]; y++) {
                    uint32_t t = index->cell_triangles[y];
                    const double *b = uv + 6 * (size_t)t;
                    if (fabs(signed_area(b)) <= job->tiny_area)
                        continue;
                    double box_b[4];
                    triangle_box(uv, t, box_b);
                    double lo_u = max2(box_a[0], box_b[0]);
                    double lo_v = max2(box_a[1], box_b[1]);
                    if (lo_u > min2(box_a[2], box_b[2]) ||
                        lo_v > min2(box_a[3], box_b[3]))
                        continue;
                    if (cell_of(lo_u, index->umin, index->cell_u,
                                index->ncells_u) != i ||
                        cell_of(lo_v, index->vmin, index->cell_v,
                                index->ncells_v) != j)
                        continue;
                    if (interiors_overlap(a, b, job->tolerance))
                        job->overlapping++;
                }
            }
        }
    }
}

int uv_check(const double *uv, size_t ntriangles, struct uv_report *report,
             struct facet_error *err)
{
    return uv_check_stoppable(uv, ntriangles, NULL, report, err);
}

int uv_check_stoppable(const double *uv, size_t ntriangles,
                       const struct facet_stop *stop,
                       struct uv_report *report, struct facet_error *err)
{
    memset(report, 0, sizeof *report);
    report->triangles = ntriangles;
    struct uv_index index;
    int rc = uv_index_build(uv, ntriangles, &index, err);
    if (rc != FACET_OK) {
        uv_index_free(&index);
        return rc;
    }
    report->umin = index.umin;
    report->vmin = index.vmin;
    report->umax = index.umax;
    report->vmax = index.vmax;

    double extent = fmax(index.umax - index.umin, index.vmax - index.vmin);
    double tiny_area = 1e-14 * extent * extent;
    double tolerance = 1e-9 * extent;
    size_t positive = 0, negative = 0;
    for (size_t t = 0; t < ntriangles; t++) {
        double a = signed_area(uv + 6 * t);
        report->uv_area += fabs(a);
        if (fabs(a) <= tiny_area)
            report->degenerate++;
        else if (a > 0)
            positive++;
        else
            negative++;
    }
    report->flipped = positive < negative ? positive : negative;

    /* Test each pair of triangles that share a cell, once: in the cell that
     * holds the lower-left corner of their bounding boxes' intersection.
     * Rows of cells are shared among the online CPUs (at most 8) when
     * there are enough triangles to pay for threads. */
    struct overlap_job job[OVERLAP_THREADS_MAX];
    int njobs = ntriangles < OVERLAP_THREADS_FROM
                ? 1 : parallel_cpus(OVERLAP_THREADS_MAX);
    if (njobs > index.ncells_v)
        njobs = index.ncells_v;
    for (int k = 0; k < njobs; k++)
        job[k] = (struct overlap_job){&index, uv, tiny_area, tolerance,
            (int)((long)index.ncells_v * k / njobs),
            (int)((long)index.ncells_v * (k + 1) / njobs), 0, stop, 0};
    parallel_run(job, sizeof job[0], njobs, overlap_rows);
    for (int k = 0; k < njobs; k++)
        if (job[k].stopped) {
            uv_index_free(&index);
            return facet_stop_error(err);
        }
    for (int k = 1; k < njobs; k++)
        job[0].overlapping += job[k].overlapping;
    report->overlapping = job[0].overlapping;
    uv_index_free(&index);
    return FACET_OK;
}
