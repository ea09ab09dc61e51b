/*
 * seam_joints.c: gaps and kinks where two surfaces meet. See
 * seam_joints.h.
 */
#include "core/project/seam_joints.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/base/vec3.h"
#include "core/fit/sp_fit.h"
#include "core/joint/joint.h"

/* The cell index along one UV axis of value x in a grid of count cells
 * over [lo, hi], the last cell keeping its far side. */
static int cell_along(double x, double lo, double hi, int count)
{
    double f = (x - lo) / (hi - lo) * count;
    int i = (int)floor(f);
    return i < 0 ? 0 : i >= count ? count - 1 : i;
}

/* The panel of side s whose cell holds point x of triangle t (x on the
 * triangle: its UV by the triangle's affine map), or -1. A point on a
 * cell side whose cell has no panel takes the neighbour's that has. */
static int32_t panel_at(const struct seam_side *s, uint32_t t,
                        const double x[3])
{
    const uint32_t *tri = s->mesh->triangle + 3 * (size_t)t;
    const double *p0 = s->mesh->position + 3 * (size_t)tri[0];
    const double *p1 = s->mesh->position + 3 * (size_t)tri[1];
    const double *p2 = s->mesh->position + 3 * (size_t)tri[2];
    double e1[3], e2[3], r[3];
    vec3_sub(p1, p0, e1);
    vec3_sub(p2, p0, e2);
    vec3_sub(x, p0, r);
    double d11 = vec3_dot(e1, e1), d12 = vec3_dot(e1, e2);
    double d22 = vec3_dot(e2, e2), r1 = vec3_dot(r, e1), r2 = vec3_dot(r, e2);
    double det = d11 * d22 - d12 * d12;
    if (!(det > 0))
        return -1;
    double b1 = (d22 * r1 - d12 * r2) / det;
    double b2 = (d11 * r2 - d12 * r1) / det;
    double b0 = 1 - b1 - b2;
    const double *uv = s->uv->uv + 6 * (size_t)t;
    double u = b0 * uv[0] + b1 * uv[2] + b2 * uv[4];
    double v = b0 * uv[1] + b1 * uv[3] + b2 * uv[5];
    const struct panelization *p = s->panels;
    int i = cell_along(u, p->umin, p->umax, p->nu);
    int j = cell_along(v, p->vmin, p->vmax, p->nv);
    for (int dj = 0; dj >= -1; dj--)
        for (int di = 0; di >= -1; di--) {
            int ci = i + di, cj = j + dj;
            if (ci < 0 || cj < 0)
                continue;
            int32_t k = p->cell_panel[(size_t)cj * (size_t)p->nu +
                                      (size_t)ci];
            if (k >= 0)
                return k;
        }
    return -1;
}

/* The panel as built, from what the panel holds (its fit when built SP). */
static void built_of(const struct panel *panel, struct built_panel *out)
{
    memset(out, 0, sizeof *out);
    if (panel->built == TYPE_SP &&
        built_panel_of_fit(&panel->sp_fit, panel->sp_deviation, out) == 0)
        return;
    out->type = panel->built;
    out->fitted = 0;
}

/* Panel's normal as built at x, on the side of surface normal n. */
static void built_normal(const struct panel *panel,
                         const struct built_panel *built, const double x[3],
                         const double n[3], double out[3])
{
    joint_normal(panel, built, x, n, out);
    if (vec3_dot(out, n) < 0)
        for (int k = 0; k < 3; k++)
            out[k] = -out[k];
}

static int by_panels(const void *x, const void *y)
{
    const struct seam_joint *a = x, *b = y;
    if (a->panel_a != b->panel_a)
        return a->panel_a < b->panel_a ? -1 : 1;
    return a->panel_b < b->panel_b ? -1 : a->panel_b > b->panel_b;
}

int seam_joints_list(const struct seam *seam, const struct seam_side *a,
                     const struct seam_side *b, struct seam_joint **out,
                     size_t *njoints, struct facet_error *err)
{
    *out = NULL;
    *njoints = 0;
    /* Each sample first a joint of its own, then merged by pair. */
    struct seam_joint *sample =
        malloc((seam->npoints ? seam->npoints : 1) * sizeof *sample);
    if (sample == NULL)
        return facet_error_set(err, FACET_EWORK,
                               "out of memory measuring a seam");
    size_t n = 0;
    for (size_t k = 0; k < seam->npoints; k++) {
        const struct seam_point *x = &seam->points[k];
        int32_t pa = panel_at(a, x->triangle_a, x->at);
        int32_t pb = panel_at(b, x->triangle_b, x->across);
        if (pa < 0 || pb < 0)
            continue;
        const struct panel *panel_a = &a->panels->panels[pa];
        const struct panel *panel_b = &b->panels->panels[pb];
        struct built_panel built_a, built_b;
        built_of(panel_a, &built_a);
        built_of(panel_b, &built_b);
        double place_a[3], place_b[3], normal_a[3], normal_b[3];
        joint_place(panel_a, &built_a, x->at, place_a);
        joint_place(panel_b, &built_b, x->across, place_b);
        built_normal(panel_a, &built_a, x->at, x->normal_a, normal_a);
        built_normal(panel_b, &built_b, x->across, x->normal_b, normal_b);
        struct seam_joint *s = &sample[n++];
        s->panel_a = pa;
        s->panel_b = pb;
        s->gap = vec3_distance(place_a, place_b);
        s->kink = vec3_angle(normal_a, normal_b);
        s->added = fabs(s->kink - x->crease);
        s->crease = x->crease;
    }
    qsort(sample, n, sizeof *sample, by_panels);
    /* Each run of one pair of panels becomes its joint, in place. */
    size_t joints = 0;
    for (size_t k = 0; k < n;) {
        struct seam_joint j = sample[k];
        size_t end = k + 1;
        while (end < n && by_panels(&sample[end], &sample[k]) == 0) {
            j.gap = fmax(j.gap, sample[end].gap);
            j.kink = fmax(j.kink, sample[end].kink);
            j.added = fmax(j.added, sample[end].added);
            j.crease = fmax(j.crease, sample[end].crease);
            end++;
        }
        sample[joints++] = j;
        k = end;
    }
    if (joints == 0) {
        free(sample);
        return FACET_OK;
    }
    *out = sample;
    *njoints = joints;
    return FACET_OK;
}

int seam_joints_measure(const struct seam *seam, const struct seam_side *a,
                        const struct seam_side *b, double max_gap,
                        double max_kink, struct seam_joints *out,
                        struct facet_error *err)
{
    memset(out, 0, sizeof *out);
    for (size_t k = 0; k < seam->npoints; k++)
        out->max_crease = fmax(out->max_crease, seam->points[k].crease);
    struct seam_joint *joint;
    size_t n;
    int rc = seam_joints_list(seam, a, b, &joint, &n, err);
    if (rc != FACET_OK)
        return rc;
    double gaps = 0, added = 0;
    for (size_t k = 0; k < n; k++) {
        const struct seam_joint *j = &joint[k];
        out->njoints++;
        out->max_gap = fmax(out->max_gap, j->gap);
        out->max_kink = fmax(out->max_kink, j->kink);
        out->max_added = fmax(out->max_added, j->added);
        out->gaps_over += j->gap > max_gap;
        out->kinks_over += j->added > max_kink;
        gaps += j->gap;
        added += j->added;
    }
    if (out->njoints > 0) {
        out->mean_gap = gaps / (double)out->njoints;
        out->mean_added = added / (double)out->njoints;
    }
    free(joint);
    return FACET_OK;
}
