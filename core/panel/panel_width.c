/*
 * panel_width.c: each panel's width, the caliper width of its projected
 * outline. See panel_width.h.
 */
#include "core/panel/panel_width.h"

#include <assert.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/base/vec3.h"

static int by_x_then_y(const void *a, const void *b)
{
    const double *p = a, *q = b;
    if (p[0] != q[0])
        return p[0] < q[0] ? -1 : 1;
    if (p[1] != q[1])
        return p[1] < q[1] ? -1 : 1;
    return 0;
}

/* Twice the signed area of o, a, b: positive when they turn left. */
static double turn(const double *o, const double *a, const double *b)
{
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

/* The convex hull of xy (n points, sorted by x then y) counter-clockwise
 * into hull, without points on its edges (Andrew's monotone chain); its
 * count. */
static size_t hull_of(const double *xy, size_t n, double *hull)
{
    size_t k = 0;
    for (size_t i = 0; i < n; i++) {
        while (k >= 2 && turn(hull + 2 * (k - 2), hull + 2 * (k - 1),
                              xy + 2 * i) <= 0)
            k--;
        hull[2 * k] = xy[2 * i];
        hull[2 * k + 1] = xy[2 * i + 1];
        k++;
    }
    size_t lower = k + 1;
    for (size_t i = n - 1; i-- > 0;) {
        while (k >= lower && turn(hull + 2 * (k - 2), hull + 2 * (k - 1),
                                  xy + 2 * i) <= 0)
            k--;
        hull[2 * k] = xy[2 * i];
        hull[2 * k + 1] = xy[2 * i + 1];
        k++;
    }
    return k - 1;  /* the first point closes the chain */
}

double polygon_min_width(double *xy, size_t n, double *scratch)
{
    if (n < 3)
        return 0;
    qsort(xy, n, 2 * sizeof *xy, by_x_then_y);
    double *h = scratch;
    size_t m = hull_of(xy, n, h);
    if (m < 3)
        return 0;
    /* Rotating calipers: for each edge, the hull point farthest from its
     * line moves forward with the edge, so one pass finds them all. */
    double best = INFINITY;
    size_t j = 1;
    for (size_t i = 0; i < m; i++) {
        const double *a = h + 2 * i, *b = h + 2 * ((i + 1) % m);
        while (turn(a, b, h + 2 * ((j + 1) % m)) > turn(a, b, h + 2 * j))
            j = (j + 1) % m;
        double length = hypot(b[0] - a[0], b[1] - a[1]);
        best = fmin(best, turn(a, b, h + 2 * j) / length);
    }
    return best;
}

int panel_widths_set(const struct panel_geometry *g,
                     struct panelization *panels, struct facet_error *err)
{
    return panel_widths_set_stoppable(g, panels, NULL, err);
}

/* Panels measured between two questions to the stop: milliseconds. */
#define STOP_EVERY_PANELS 4096

int panel_widths_set_stoppable(const struct panel_geometry *g,
                               struct panelization *panels,
                               const struct facet_stop *stop,
                               struct facet_error *err)
{
    assert(g->npanels == panels->npanels);
    size_t most = 0;
    for (size_t n = 0; n < g->npanels; n++) {
        size_t points = g->loop_start[g->panel_loop[n + 1]] -
                        g->loop_start[g->panel_loop[n]];
        most = points > most ? points : most;
    }
    double *xy = malloc((2 * most + 2) * sizeof *xy);
    double *scratch = malloc((4 * most + 4) * sizeof *scratch);
    if (xy == NULL || scratch == NULL) {
        free(xy);
        free(scratch);
        return facet_error_set(err, FACET_EWORK,
                               "out of memory measuring panel widths");
    }
    for (size_t n = 0; n < g->npanels; n++) {
        if (n % STOP_EVERY_PANELS == 0 && facet_stop_requested(stop)) {
            free(xy);
            free(scratch);
            return facet_stop_error(err);
        }
        struct panel *panel = &panels->panels[n];
        double e1[3], e2[3];
        vec3_frame(panel->normal, e1, e2);
        size_t first = g->loop_start[g->panel_loop[n]];
        size_t end = g->loop_start[g->panel_loop[n + 1]];
        for (size_t k = first; k < end; k++) {
            double d[3];
            vec3_sub(g->outline_plane + 3 * k, panel->centroid, d);
            xy[2 * (k - first)] = vec3_dot(d, e1);
            xy[2 * (k - first) + 1] = vec3_dot(d, e2);
        }
        panel->width = polygon_min_width(xy, end - first, scratch);
    }
    free(xy);
    free(scratch);
    return FACET_OK;
}
