/*
 * panel_split.c: cutting a triangle along grid lines into the pieces of
 * the cells it crosses, and a piece's moments. See panel_internal.h.
 */
#include <assert.h>
#include <math.h>
#include <string.h>

#include "core/panel/panel_internal.h"

static inline void split_push(struct split_vertex *out, int *n,
                              const struct split_vertex *x)
{
    if (*n < SPLIT_MAX)
        out[(*n)++] = *x;
}

void panel_split(const struct split_vertex *in, int count, int axis,
                 double limit, struct split_vertex *low, int *nlow,
                  struct split_vertex *high, int *nhigh)
{
    assert(count >= 0 && count <= SPLIT_MAX && (axis == 0 || axis == 1));
    *nlow = *nhigh = 0;
    for (int k = 0; k < count; k++) {
        const struct split_vertex *p = &in[k];
        const struct split_vertex *q = &in[k + 1 < count ? k + 1 : 0];
        double dp = (axis == 0 ? p->u : p->v) - limit;
        double dq = (axis == 0 ? q->u : q->v) - limit;
        int low_p = dp <= 0, high_p = dp >= 0;
        if (low_p)
            split_push(low, nlow, p);
        if (high_p)
            split_push(high, nhigh, p);
        int cut_low = low_p != (dq <= 0), cut_high = high_p != (dq >= 0);
        if (cut_low || cut_high) {
            double t = dp / (dp - dq);
            struct split_vertex x;
            x.u = p->u + t * (q->u - p->u);
            x.v = p->v + t * (q->v - p->v);
            for (int c = 0; c < 3; c++)
                x.b[c] = p->b[c] + t * (q->b[c] - p->b[c]);
            if (axis == 0)
                x.u = limit;
            else
                x.v = limit;
            if (cut_low)
                split_push(low, nlow, &x);
            if (cut_high)
                split_push(high, nhigh, &x);
        }
    }
}

void panel_piece_moments(const struct panel_prep_triangle *T,
                         const double corner[3][3],
                         const struct split_vertex *piece, int count,
                         struct piece_moments *m_out)
{
    double x[SPLIT_MAX][3];
    for (int k = 0; k < count; k++)
        for (int d = 0; d < 3; d++)
            x[k][d] = piece[k].b[0] * corner[0][d] +
                      piece[k].b[1] * corner[1][d] +
                      piece[k].b[2] * corner[2][d];
    struct piece_moments m;
    memset(&m, 0, sizeof m);
    double fraction = 0;
    const double *b0 = piece[0].b;
    for (int k = 1; k + 1 < count; k++) {
        const double *b1 = piece[k].b, *b2 = piece[k + 1].b;
        double part = fabs((b1[1] - b0[1]) * (b2[2] - b0[2]) -
                           (b2[1] - b0[1]) * (b1[2] - b0[2]));
        fraction += part;
        piece_moments_add_triangle(&m, x[0], x[k], x[k + 1],
                                   part * T->area);
    }
    m.area = fraction * T->area;
    m.uv_area = fraction * T->uv_area;
    for (int d = 0; d < 3; d++)
        m.normal_sum[d] = fraction * T->normal_sum[d];
    *m_out = m;
}


void panel_triangle_corners(const struct panel_prep *prep, uint32_t t,
                            double corner[3][3])
{
    const struct panel_prep_triangle *T = &prep->triangle[t];
    const uint32_t *point = prep->corner + 3 * (size_t)t;
    for (int k = 0; k < 3; k++)
        for (int d = 0; d < 3; d++)
            corner[k][d] = prep->point[point[k]].position[d] -
                           T->centroid[d];
}
