/*
 * quadrature.c: a surface's area by quadrature. See quadrature.h.
 */
#include "tests/support/quadrature.h"

#include <math.h>

double quadrature_area(void (*point)(const void *data, double s, double t,
                                     double p[3]),
                       const void *data, int n)
{
    const double h = 1e-6;
    double area = 0;
    for (int j = 0; j < n; j++)
        for (int i = 0; i < n; i++) {
            double s = (i + 0.5) / n, t = (j + 0.5) / n;
            double a[3], b[3], c[3], d[3], ds[3], dt[3];
            point(data, s + h, t, a);
            point(data, s - h, t, b);
            point(data, s, t + h, c);
            point(data, s, t - h, d);
            for (int k = 0; k < 3; k++) {
                ds[k] = (a[k] - b[k]) / (2 * h);
                dt[k] = (c[k] - d[k]) / (2 * h);
            }
            double x = ds[1] * dt[2] - ds[2] * dt[1];
            double y = ds[2] * dt[0] - ds[0] * dt[2];
            double z = ds[0] * dt[1] - ds[1] * dt[0];
            area += sqrt(x * x + y * y + z * z) / ((double)n * n);
        }
    return area;
}
