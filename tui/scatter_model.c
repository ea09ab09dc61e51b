/*
 * scatter_model.c: scaling and navigation of the scatter plot. See
 * scatter_model.h.
 */
#include "scatter_model.h"

#include <math.h>
#include <stdlib.h>

int scatter_cell(double value, double min, double max, int cells)
{
    if (!isfinite(value) || cells < 1)
        return -1;
    if (!(max > min))
        return cells / 2;
    double t = (value - min) / (max - min);
    int cell = (int)floor(t * cells);
    if (cell < 0)
        cell = 0;
    if (cell >= cells)
        cell = cells - 1;
    return cell;
}

int scatter_level(double z, double min, double max, int levels)
{
    int level = scatter_cell(z, min, max, levels);
    return !(max > min) || level < 0 ? 0 : level;
}

int scatter_ticks(double min, double max, int max_ticks, double *ticks,
                  double *step)
{
    *step = 0;
    if (!isfinite(min) || !isfinite(max) || max_ticks < 1 || max < min)
        return 0;
    if (!(max > min)) {
        ticks[0] = min;
        return 1;
    }
    static const double mantissa[3] = {1, 2, 5};
    double raw = (max - min) / max_ticks;
    int e = (int)floor(log10(raw)) - 1;
    for (;; e++)
        for (int k = 0; k < 3; k++) {
            double d = mantissa[k] * pow(10, e);
            double first = ceil(min / d - 1e-9), last = floor(max / d + 1e-9);
            if (last - first + 1 > max_ticks)
                continue;
            int n = 0;
            for (double t = first; t <= last && n < max_ticks; t++) {
                double v = t * d;
                /* a multiple by a rounding error outside the range, or a
                 * -0, is the range's end */
                ticks[n++] = fabs(v) < d * 1e-9 ? 0 : v;
            }
            *step = d;
            return n;
        }
}

void scatter_range(const struct scatter_point *points, size_t n, int axis,
                   double *min, double *max)
{
    *min = *max = NAN;
    for (size_t k = 0; k < n; k++) {
        double v = axis == 0 ? points[k].x : axis == 1 ? points[k].y
                                                       : points[k].z;
        if (!isfinite(v))
            continue;
        if (isnan(*min) || v < *min)
            *min = v;
        if (isnan(*max) || v > *max)
            *max = v;
    }
}

/* A point's place in the front's order: its x, y and index, so that
 * qsort needs no pointer to the points beside it. */
struct front_key {
    double x, y;
    size_t k;
};

static int by_x_then_y(const void *a, const void *b)
{
    const struct front_key *p = a, *q = b;
    if (p->x != q->x)
        return p->x < q->x ? -1 : 1;
    if (p->y != q->y)
        return p->y < q->y ? -1 : 1;
    return p->k < q->k ? -1 : p->k > q->k;
}

size_t scatter_front(const struct scatter_point *points, size_t n,
                     size_t *front)
{
    struct front_key *keys = malloc((n ? n : 1) * sizeof *keys);
    if (keys == NULL)
        return 0;  /* no front drawn rather than a wrong one */
    size_t m = 0;
    for (size_t k = 0; k < n; k++)
        if (isfinite(points[k].x) && isfinite(points[k].y))
            keys[m++] = (struct front_key){points[k].x, points[k].y, k};
    qsort(keys, m, sizeof *keys, by_x_then_y);
    /* by x ascending: a point is on the front when its y is below every
     * y before it */
    size_t kept = 0;
    double best = INFINITY;
    for (size_t k = 0; k < m; k++)
        if (keys[k].y < best) {
            best = keys[k].y;
            front[kept++] = keys[k].k;
        }
    free(keys);
    return kept;
}

size_t scatter_step(const struct scatter_point *points, size_t n,
                    size_t current, int dx, int dy)
{
    if (current >= n || (dx == 0 && dy == 0))
        return current;
    double xmin, xmax, ymin, ymax;
    scatter_range(points, n, 0, &xmin, &xmax);
    scatter_range(points, n, 1, &ymin, &ymax);
    double xs = xmax > xmin ? xmax - xmin : 1, ys = ymax > ymin ? ymax - ymin
                                                                 : 1;
    const struct scatter_point *c = &points[current];
    size_t best = current;
    double best_score = INFINITY;
    for (size_t k = 0; k < n; k++) {
        if (k == current)
            continue;
        const struct scatter_point *p = &points[k];
        double along = dx ? (p->x - c->x) / xs * dx : (p->y - c->y) / ys * dy;
        double across = dx ? fabs(p->y - c->y) / ys : fabs(p->x - c->x) / xs;
        /* a point at the same place counts as ahead when it comes later */
        if (along < 0 || (along == 0 && across == 0 &&
                          ((dx + dy > 0) != (k > current))))
            continue;
        if (along == 0 && across > 0)
            continue;
        double score = along + 3 * across;
        if (score < best_score) {
            best_score = score;
            best = k;
        }
    }
    return best;
}
