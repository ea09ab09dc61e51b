/*
 * unroll.c: panels laid flat. See unroll.h.
 */
#include "core/fit/unroll.h"

#include <assert.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/base/vec3.h"

#define QUARTER_TURN 1.57079632679489661923

/* e1 across normal, along `along` where it has a part across normal, and
 * e2 = normal x e1: a right-handed frame of the plane seen from normal. */
static void plane_frame(const double normal[3], const double along[3],
                        double e1[3], double e2[3])
{
    int have = 0;
    if (along != NULL) {
        double a = vec3_dot(along, normal);
        for (int k = 0; k < 3; k++)
            e1[k] = along[k] - a * normal[k];
        have = vec3_normalize(e1);
    }
    if (!have) {
        /* The axis least along normal, made normal to it. */
        int k = 0;
        for (int x = 1; x < 3; x++)
            if (fabs(normal[x]) < fabs(normal[k]))
                k = x;
        double pick[3] = {0, 0, 0};
        pick[k] = 1;
        vec3_cross(pick, normal, e1);
        vec3_normalize(e1);
    }
    vec3_cross(normal, e1, e2);
}

void unroll_plane(const double origin[3], const double normal[3],
                  const double along[3], const double *points, size_t n,
                  double *out)
{
    double e1[3], e2[3];
    plane_frame(normal, along, e1, e2);
    for (size_t k = 0; k < n; k++) {
        double q[3];
        vec3_sub(points + 3 * k, origin, q);
        out[2 * k] = vec3_dot(q, e1);
        out[2 * k + 1] = vec3_dot(q, e2);
    }
}

void unroll_developable(const struct developable *d, const double *points,
                        size_t n, const double facing[3], double *out)
{
    if (n == 0)
        return;
    /* theta's zero: the direction from the axis to the points' mean. */
    double mean[3] = {0, 0, 0};
    for (size_t k = 0; k < n; k++)
        for (int c = 0; c < 3; c++)
            mean[c] += points[3 * k + c] / (double)n;
    double foot[3], a[3], apex[3];
    double alpha = developable_describe(d, mean, foot, a, apex);
    int cone = isfinite(apex[0]);
    double e1[3], e2[3];
    vec3_sub(mean, foot, e1);
    if (!vec3_normalize(e1))
        plane_frame(a, NULL, e1, e2);
    vec3_cross(a, e1, e2);
    /* The pattern's own frame is seen from outside a cylinder (e_theta x
     * a is the outward normal) and from inside a cone ((ruling) x e_theta
     * is the inward normal): mirrored when facing says the other side. */
    double outward[3];
    developable_nearest(d, mean, NULL, outward);
    double seen = vec3_dot(outward, facing != NULL ? facing : outward);
    double flip = (cone ? -seen : seen) < 0 ? -1 : 1;
    double sin_alpha = sin(alpha);
    for (size_t k = 0; k < n; k++) {
        double p[3], q[3];
        developable_nearest(d, points + 3 * k, p, NULL);
        vec3_sub(p, cone ? apex : foot, q);
        double h = vec3_dot(q, a);
        double r[3];
        for (int c = 0; c < 3; c++)
            r[c] = q[c] - h * a[c];
        double theta = atan2(vec3_dot(r, e2), vec3_dot(r, e1));
        if (cone) {
            double s = vec3_length(q);
            double phi = theta * sin_alpha;
            out[2 * k] = flip * s * cos(phi);
            out[2 * k + 1] = s * sin(phi);
        } else {
            out[2 * k] = flip * d->radius * theta;
            out[2 * k + 1] = h;
        }
    }
}

double unroll_polygon_area(const double *points, size_t n)
{
    /* The shoelace formula about the first point, which keeps the
     * products small far from the origin. */
    double sum = 0;
    for (size_t k = 1; k + 1 < n; k++) {
        double ax = points[2 * k] - points[0];
        double ay = points[2 * k + 1] - points[1];
        double bx = points[2 * (k + 1)] - points[0];
        double by = points[2 * (k + 1) + 1] - points[1];
        sum += ax * by - ay * bx;
    }
    return sum / 2;
}

/* The points' order by x, then y (qsort cannot carry the points: an
 * insertion of indices, the hull's points few hundred at most). */
static void sort_points(const double *p, size_t n, size_t *order)
{
    for (size_t k = 0; k < n; k++) {
        size_t m = k;
        while (m > 0) {
            const double *a = p + 2 * order[m - 1], *b = p + 2 * k;
            if (a[0] < b[0] || (a[0] == b[0] && a[1] <= b[1]))
                break;
            order[m] = order[m - 1];
            m--;
        }
        order[m] = k;
    }
}

static double cross3(const double *o, const double *a, const double *b)
{
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

double unroll_least_box_turn(const double *points, size_t n,
                             double *hull, size_t *order)
{
    if (n < 3)
        return 0;
    /* Andrew's monotone chain: the hull counter-clockwise into hull. */
    sort_points(points, n, order);
    size_t h = 0;
    for (size_t k = 0; k < n; k++) {
        const double *p = points + 2 * order[k];
        while (h >= 2 && cross3(hull + 2 * (h - 2), hull + 2 * (h - 1), p) <= 0)
            h--;
        hull[2 * h] = p[0];
        hull[2 * h + 1] = p[1];
        h++;
    }
    size_t lower = h + 1;
    for (size_t k = n - 1; k-- > 0;) {
        const double *p = points + 2 * order[k];
        while (h >= lower &&
               cross3(hull + 2 * (h - 2), hull + 2 * (h - 1), p) <= 0)
            h--;
        hull[2 * h] = p[0];
        hull[2 * h + 1] = p[1];
        h++;
    }
    h--;  /* the last is the first again */
    if (h < 3)
        return 0;
    double best = INFINITY, turn = 0, wide = 0, tall = 0;
    for (size_t e = 0; e < h; e++) {
        const double *a = hull + 2 * e, *b = hull + 2 * ((e + 1) % h);
        double dx = b[0] - a[0], dy = b[1] - a[1];
        double length = hypot(dx, dy);
        if (!(length > 0))
            continue;
        double c = dx / length, s = dy / length;
        /* Along the edge (u) and across it (v). */
        double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
        for (size_t k = 0; k < h; k++) {
            double x = hull[2 * k], y = hull[2 * k + 1];
            double u = x * c + y * s, v = -x * s + y * c;
            lo[0] = fmin(lo[0], u);
            hi[0] = fmax(hi[0], u);
            lo[1] = fmin(lo[1], v);
            hi[1] = fmax(hi[1], v);
        }
        double area = (hi[0] - lo[0]) * (hi[1] - lo[1]);
        if (area < best) {
            best = area;
            turn = -atan2(s, c);  /* turns the edge onto +x */
            wide = hi[0] - lo[0];
            tall = hi[1] - lo[1];
        }
    }
    if (tall > wide)
        turn += turn > 0 ? -QUARTER_TURN : QUARTER_TURN;
    return isfinite(best) ? turn : 0;
}

void flat_patterns_free(struct flat_patterns *f)
{
    free(f->flat);
    free(f->developed);
    free(f->area);
    memset(f, 0, sizeof *f);
}

int flat_patterns_build(const struct panel_geometry *g,
                        const struct panelization *panels,
                        const struct built_panel *fit,
                        struct flat_patterns *out, struct facet_error *err)
{
    memset(out, 0, sizeof *out);
    assert(g->npanels == panels->npanels);
    out->npanels = g->npanels;
    out->npoints = g->loop_start[g->nloops];
    out->flat = malloc((out->npoints ? out->npoints : 1) * 2 *
                       sizeof *out->flat);
    out->developed = malloc((g->npanels ? g->npanels : 1) *
                            sizeof *out->developed);
    out->area = malloc((g->npanels ? g->npanels : 1) * sizeof *out->area);
    /* One panel's outline positions at a time, gathered for the fit. */
    size_t most = 0;
    for (size_t n = 0; n < g->npanels; n++) {
        size_t count = g->loop_start[g->panel_loop[n + 1]] -
                       g->loop_start[g->panel_loop[n]];
        if (count > most)
            most = count;
    }
    double *gathered = malloc((most ? most : 1) * 3 * sizeof *gathered);
    if (!out->flat || !out->developed || !out->area || !gathered) {
        free(gathered);
        return facet_error_set(err, FACET_EWORK, "out of memory");
    }
    int rc = FACET_OK;
    for (size_t n = 0; n < g->npanels && rc == FACET_OK; n++) {
        const struct panel *p = &panels->panels[n];
        size_t first = g->loop_start[g->panel_loop[n]];
        size_t count = g->loop_start[g->panel_loop[n + 1]] - first;
        double *flat = out->flat + 2 * first;
        if (p->built == TYPE_SP) {
            if (fit == NULL || !fit[n].fitted) {
                rc = facet_error_set(err, FACET_EINPUT, "panel (%d, %d) is "
                                     "built SP but has no fitted cylinder "
                                     "or cone to unroll", p->i, p->j);
                break;
            }
            for (size_t k = 0; k < count; k++)
                memcpy(gathered + 3 * k,
                       g->position + 3 * g->outline[first + k],
                       3 * sizeof *gathered);
            unroll_developable(&fit[n].fit, gathered, count, p->normal,
                               flat);
            out->developed[n] = TYPE_SP;
        } else {
            double along[3];
            int sided = p->ncorners == 4;
            for (int k = 0; k < 3; k++)
                along[k] = p->corner[1][k] - p->corner[0][k];
            unroll_plane(p->centroid, p->normal, sided ? along : NULL,
                         g->outline_plane + 3 * first, count, flat);
            out->developed[n] = p->built == TYPE_FP ? TYPE_FP : TYPE_DP;
        }
        double area = 0;
        for (size_t l = g->panel_loop[n]; l < g->panel_loop[n + 1]; l++)
            area += unroll_polygon_area(out->flat + 2 * g->loop_start[l],
                                        g->loop_start[l + 1] -
                                            g->loop_start[l]);
        out->area[n] = area;
    }
    free(gathered);
    return rc;
}
