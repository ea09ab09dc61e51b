/*
 * quad.c: a quad's planarity as the distance between its diagonals
 * (quad.h).
 */
#include "quad.h"

#include <math.h>

#include "core/base/vec3.h"

double quad_planarity(const double c[4][3])
{
    double d1[3], d2[3], w[3], n[3];
    vec3_sub(c[2], c[0], d1);
    vec3_sub(c[3], c[1], d2);
    vec3_sub(c[1], c[0], w);
    vec3_cross(d1, d2, n);
    double length = sqrt(vec3_dot(n, n));
    return length > 0 ? fabs(vec3_dot(w, n)) / length : 0;
}

double quad_diagonal(const double c[4][3])
{
    return fmax(vec3_distance(c[0], c[2]), vec3_distance(c[1], c[3]));
}
