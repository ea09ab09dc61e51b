/*
 * joint.c: gaps and kinks between neighbouring panels. See joint.h.
 */
#include "core/joint/joint.h"

#include <assert.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/base/vec3.h"
#include "core/panel/panel_geometry.h"

/* One panel's side of a joint: which of its corners are the side's first
 * and last ends. */
struct joint_side {
    const struct panel *panel;
    const struct built_panel *built;
    int first, last;              /* indices into panel->corner */
    double end[2][3];             /* those corners projected (FP quad) */
    int quad;                     /* FP with a full quad */
};

static void side_init(struct joint_side *s, const struct panel *panel,
                      const struct built_panel *built, int first, int last)
{
    s->panel = panel;
    s->built = built;
    s->first = first;
    s->last = last;
    s->quad = built->type == TYPE_FP && cell_sides_flat_quad(panel);
    if (s->quad) {
        panel_geometry_project(panel, panel->corner[first], s->end[0]);
        panel_geometry_project(panel, panel->corner[last], s->end[1]);
    }
}

void joint_place(const struct panel *panel, const struct built_panel *built,
                 const double x[3], double out[3])
{
    if (built->fitted)
        developable_nearest(&built->fit, x, out, NULL);
    else if (built->type == TYPE_FP)
        panel_geometry_project(panel, x, out);
    else
        memcpy(out, x, 3 * sizeof *out);
}

void joint_normal(const struct panel *panel, const struct built_panel *built,
                  const double x[3], const double surface_normal[3],
                  double out[3])
{
    if (built->fitted) {
        developable_nearest(&built->fit, x, NULL, out);
        if (vec3_dot(out, surface_normal) < 0)
            for (int k = 0; k < 3; k++)
                out[k] = -out[k];
    } else if (built->type == TYPE_FP) {
        memcpy(out, panel->normal, 3 * sizeof *out);
    } else {
        memcpy(out, surface_normal, 3 * sizeof *out);
    }
}

/* The place of surface point x on the side's panel as built. */
static void place_of(const struct joint_side *s, const double x[3],
                     double out[3])
{
    if (s->quad && !s->built->fitted) {
        double d[3], q[3];
        vec3_sub(s->end[1], s->end[0], d);
        vec3_sub(x, s->end[0], q);
        double length2 = vec3_dot(d, d);
        double f = length2 > 0 ? vec3_dot(q, d) / length2 : 0;
        f = f < 0 ? 0 : f > 1 ? 1 : f;
        for (int k = 0; k < 3; k++)
            out[k] = s->end[0][k] + f * d[k];
    } else {
        joint_place(s->panel, s->built, x, out);
    }
}

/* The side's panel normal at surface point x, whose surface normal is
 * surface_normal. */
static void normal_of(const struct joint_side *s, const double x[3],
                      const double surface_normal[3], double out[3])
{
    joint_normal(s->panel, s->built, x, surface_normal, out);
}

/* Raises *gap to distance when that is larger: fmax(*gap, distance)
 * without the library call, for a gap that starts at 0 and distances that
 * are square roots (never -0; a NaN leaves the gap, as fmax does). */
static void widen(double *gap, double distance)
{
    if (distance > *gap)
        *gap = distance;
}

/* Measures one joint on side of sides between a and b; returns 0 when the
 * surface does not reach the side. A side between two full DP panels is
 * not sampled: both follow the surface, so the places of every point of
 * it, and its normals, are the same on both (gap and kink 0, as sampled
 * they come out exactly). A side between two flat quads is
 * measured at its ends: the places of a point of it on the two quads' edges
 * differ by an affine function of the point, whose largest value on the
 * side's curve departs from its largest at the ends by at most the curve's
 * sag times the angle between the two edges (micrometres). */
static int measure(const struct cell_sides *sides, size_t side,
                   const struct joint_side *a, const struct joint_side *b,
                   struct joint_edge *edge)
{
    edge->side = side;
    edge->gap = 0;
    if (!sides->sampled[side] && !a->quad) {
        /* Two full DP panels (cell_sides.h): both follow the surface. */
        assert(!b->quad && a->built->type == TYPE_DP &&
               b->built->type == TYPE_DP);
        edge->kink = 0;
        return 1;
    }
    if (!sides->sampled[side]) {
        assert(a->quad && b->quad);
        const double *end[2] = {a->panel->corner[a->first],
                                a->panel->corner[a->last]};
        for (int e = 0; e < 2; e++) {
            double pa[3], pb[3];
            place_of(a, end[e], pa);
            place_of(b, end[e], pb);
            widen(&edge->gap, vec3_distance(pa, pb));
        }
        edge->kink = vec3_angle(a->panel->normal, b->panel->normal);
        return 1;
    }
    int any = 0;
    for (int k = 0; k < CELL_SIDE_SAMPLES; k++) {
        size_t at = side * CELL_SIDE_SAMPLES + (size_t)k;
        if (!sides->on[at])
            continue;
        any = 1;
        double pa[3], pb[3];
        place_of(a, sides->point + 3 * at, pa);
        place_of(b, sides->point + 3 * at, pb);
        widen(&edge->gap, vec3_distance(pa, pb));
    }
    int middle = sides->middle[side];
    if (!any || middle < 0)
        return 0;
    const double *x = sides->point + 3 * (side * CELL_SIDE_SAMPLES +
                                          (size_t)middle);
    double na[3], nb[3];
    normal_of(a, x, sides->normal + 3 * side, na);
    normal_of(b, x, sides->normal + 3 * side, nb);
    edge->kink = vec3_angle(na, nb);
    return 1;
}

int joints_measure(const struct panelization *panels,
                   const struct built_option *built,
                   const struct cell_sides *sides, double max_gap,
                   double max_kink, struct joints *out,
                   struct facet_error *err)
{
    return joints_measure_stoppable(panels, built, sides, max_gap, max_kink,
                                    NULL, out, err);
}

int joints_measure_stoppable(const struct panelization *panels,
                             const struct built_option *built,
                             const struct cell_sides *sides, double max_gap,
                             double max_kink, const struct facet_stop *stop,
                             struct joints *out, struct facet_error *err)
{
    memset(out, 0, sizeof *out);
    int nu = panels->nu, nv = panels->nv;
    size_t most = (size_t)(nu - 1) * (size_t)nv +
                  (size_t)nu * (size_t)(nv - 1);
    out->npanels = panels->npanels;
    out->edges = malloc((most + 1) * sizeof *out->edges);
    out->worst_gap = calloc(panels->npanels + 1, sizeof *out->worst_gap);
    out->worst_kink = calloc(panels->npanels + 1, sizeof *out->worst_kink);
    if (out->edges == NULL || out->worst_gap == NULL ||
        out->worst_kink == NULL) {
        joints_free(out);
        return facet_error_set(err, FACET_EWORK,
                               "out of memory for %zu joints", most);
    }
    /* Corners 0..3 of a panel are (i,j), (i+1,j), (i+1,j+1), (i,j+1). */
    for (int j = 0; j < nv; j++) {
        int rc = facet_stop_check(stop, err);
        if (rc != FACET_OK) {
            joints_free(out);
            return rc;
        }
        for (int i = 0; i < nu; i++) {
            int32_t here = panels->cell_panel[j * nu + i];
            if (here < 0)
                continue;
            int32_t left = i > 0 ? panels->cell_panel[j * nu + i - 1] : -1;
            int32_t below = j > 0 ? panels->cell_panel[(j - 1) * nu + i] : -1;
            struct joint_side a, b;
            struct joint_edge *edge = &out->edges[out->nedges];
            if (left >= 0) {
                side_init(&a, &panels->panels[left], &built->panels[left], 1,
                          2);
                side_init(&b, &panels->panels[here], &built->panels[here], 0,
                          3);
                edge->panel[0] = (uint32_t)left;
                edge->panel[1] = (uint32_t)here;
                if (measure(sides, cell_side_u(sides, i, j), &a, &b, edge))
                    edge = &out->edges[++out->nedges];
            }
            if (below >= 0) {
                side_init(&a, &panels->panels[below], &built->panels[below],
                          3, 2);
                side_init(&b, &panels->panels[here], &built->panels[here], 0,
                          1);
                edge->panel[0] = (uint32_t)below;
                edge->panel[1] = (uint32_t)here;
                if (measure(sides, cell_side_v(sides, i, j), &a, &b, edge))
                    ++out->nedges;
            }
        }
    }
    for (size_t e = 0; e < out->nedges; e++) {
        const struct joint_edge *edge = &out->edges[e];
        out->max_gap = fmax(out->max_gap, edge->gap);
        out->max_kink = fmax(out->max_kink, edge->kink);
        out->mean_gap += edge->gap;
        out->mean_kink += edge->kink;
        out->gaps_over += edge->gap > max_gap;
        out->kinks_over += edge->kink > max_kink;
        for (int s = 0; s < 2; s++) {
            uint32_t p = edge->panel[s];
            out->worst_gap[p] = fmax(out->worst_gap[p], edge->gap);
            out->worst_kink[p] = fmax(out->worst_kink[p], edge->kink);
        }
    }
    if (out->nedges > 0) {
        out->mean_gap /= (double)out->nedges;
        out->mean_kink /= (double)out->nedges;
    }
    return FACET_OK;
}

void joints_free(struct joints *joints)
{
    free(joints->edges);
    free(joints->worst_gap);
    free(joints->worst_kink);
    memset(joints, 0, sizeof *joints);
}
