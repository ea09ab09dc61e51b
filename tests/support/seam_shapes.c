/*
 * seam_shapes.c: see seam_shapes.h.
 */
#include "tests/support/seam_shapes.h"

#include <math.h>

#define PI 3.14159265358979323846

void seam_plane_a(const void *shape, double s, double t, double p[3])
{
    (void)shape;
    p[0] = 2 * s;
    p[1] = t;
    p[2] = 0;
}

void seam_plane_b(const void *shape, double s, double t, double p[3])
{
    const struct hinge *h = shape;
    if (h->reversed)
        t = 1 - t;
    p[0] = 2 + h->apart + h->width * s * cos(h->angle);
    p[1] = t;
    p[2] = h->width * s * sin(h->angle);
}

void seam_half_cylinder(const void *shape, double s, double t, double p[3])
{
    const struct half *h = shape;
    double a = h->from + PI * s;
    p[0] = 3 * cos(a), p[1] = 3 * sin(a), p[2] = 4 * t;
}
