/*
 * project_lengths.c: a surface's u and v lengths. See project_lengths.h.
 */
#include "core/project/project_lengths.h"

#include <math.h>

#include "core/base/vec3.h"

void surface_uv_lengths(const struct mesh *mesh, const double *uv,
                        double *lu, double *lv)
{
    double umin = INFINITY, umax = -INFINITY;
    double vmin = INFINITY, vmax = -INFINITY;
    double along_u = 0, along_v = 0;
    for (size_t t = 0; t < mesh->ntriangles; t++) {
        const uint32_t *corner = mesh->triangle + 3 * t;
        const double *q = uv + 6 * t;
        for (int k = 0; k < 3; k++) {
            umin = fmin(umin, q[2 * k]);
            umax = fmax(umax, q[2 * k]);
            vmin = fmin(vmin, q[2 * k + 1]);
            vmax = fmax(vmax, q[2 * k + 1]);
        }
        const double *p0 = mesh->position + 3 * (size_t)corner[0];
        const double *p1 = mesh->position + 3 * (size_t)corner[1];
        const double *p2 = mesh->position + 3 * (size_t)corner[2];
        double e1[3], e2[3];
        vec3_sub(p1, p0, e1);
        vec3_sub(p2, p0, e2);
        double d1u = q[2] - q[0], d1v = q[3] - q[1];
        double d2u = q[4] - q[0], d2v = q[5] - q[1];
        /* dS/du |det| = e1 d2v - e2 d1v; dS/dv |det| = e2 d1u - e1 d2u */
        double su[3], sv[3];
        for (int x = 0; x < 3; x++) {
            su[x] = e1[x] * d2v - e2[x] * d1v;
            sv[x] = e2[x] * d1u - e1[x] * d2u;
        }
        along_u += 0.5 * vec3_length(su);
        along_v += 0.5 * vec3_length(sv);
    }
    *lu = vmax > vmin ? along_u / (vmax - vmin) : 0;
    *lv = umax > umin ? along_v / (umax - umin) : 0;
}
