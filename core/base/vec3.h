/*
 * vec3.h: the few 3-vector operations the geometry code shares.
 *
 * Vectors are plain double[3] (m, or unitless for directions). Inline so
 * that inner loops pay nothing for the call.
 */
#ifndef FACET_VEC3_H
#define FACET_VEC3_H

#include <math.h>

static inline double vec3_dot(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* out = a x b; out may not alias a or b. */
static inline void vec3_cross(const double a[3], const double b[3],
                              double out[3])
{
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

/* out = a - b. */
static inline void vec3_sub(const double a[3], const double b[3],
                            double out[3])
{
    out[0] = a[0] - b[0];
    out[1] = a[1] - b[1];
    out[2] = a[2] - b[2];
}

static inline double vec3_length(const double a[3])
{
    return sqrt(vec3_dot(a, a));
}

static inline double vec3_distance(const double a[3], const double b[3])
{
    double d[3];
    vec3_sub(a, b, d);
    return vec3_length(d);
}

/* Scales v to unit length in place; returns 0 (leaving v alone) when its
 * length is zero or not finite, 1 otherwise. */
static inline int vec3_normalize(double v[3])
{
    double length = vec3_length(v);
    if (!(length > 0) || !isfinite(length))
        return 0;
    v[0] /= length;
    v[1] /= length;
    v[2] /= length;
    return 1;
}

/* The angle between a and b (rad, 0..pi): atan2 of the sine and cosine
 * keeps small angles exact, where acos of a cosine near 1 does not. */
static inline double vec3_angle(const double a[3], const double b[3])
{
    double cross[3];
    vec3_cross(a, b, cross);
    return atan2(vec3_length(cross), vec3_dot(a, b));
}

/* Two unit vectors e1, e2 that with the unit vector n make a right-handed
 * orthonormal frame (e1 x e2 = n): e1 across n from the axis n leans on
 * least, so the same n always gives the same frame. */
static inline void vec3_frame(const double n[3], double e1[3], double e2[3])
{
    double pick[3] = {0, 0, 0};
    int k = 0;
    for (int x = 1; x < 3; x++)
        if (fabs(n[x]) < fabs(n[k]))
            k = x;
    pick[k] = 1;
    vec3_cross(n, pick, e1);
    vec3_normalize(e1);
    vec3_cross(n, e1, e2);
}

#endif
