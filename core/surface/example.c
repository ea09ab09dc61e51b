/*
 * example.c: the example surfaces, generated. See example.h.
 *
 * Each surface is S(s, t) on the unit square, in metres; the OBJ has one
 * vertex per grid point, vt = (s, t), and two triangles per grid quad, wound
 * so that the normal dS/ds x dS/dt points up or outwards.
 *
 *   plane     x = 20 s, y = 15 t, z = 0
 *   cylinder  angle a = (-60 + 120 s) degrees, radius 10:
 *             x = 10 sin a, y = 30 t, z = 10 cos a          (axis along y)
 *   dome      x = 20 s - 10, y = 20 t - 10,
 *             z = sqrt(400 - x^2 - y^2) - sqrt(200)          (sphere R 20)
 *   hypar     x = 20 s - 10, y = 20 t - 10, z = x y / 20
 *   torus     R 20, r 6, p = 90 s degrees around the axis, q = (-135 +
 *             270 t) degrees around the tube: x = (R + r cos q) cos p,
 *             y = (R + r cos q) sin p, z = r sin q: the outside (K > 0)
 *             and, past the top and bottom of the tube, part of the inside
 *             (K < 0)
 *   wave      x = 30 s, y = 20 t, z = 4 + 1.5 sin(2 pi s) cos(pi t)
 *   roof      x = L s, y = 30 t (L = 39.56), z = 6 + arch(x) + bump(x, y):
 *             flat for x < L/4; arch(x) = 1.5 (1 - cos(2 pi (x - L/4)/16))
 *             on the next 16 m, a single-curved vault (z depends on x
 *             only); bump = 3 exp(-((x - 0.83 L)^2/25 + (y - 15)^2/40)),
 *             faded in by a smoothstep over 0.6 L..0.7 L: double-curved.
 *             About 1,240 m^2, the area of the paper's case study.
 */
#include "core/surface/example.h"

#include "core/surface/example_skin.h"

#include <math.h>
#include <string.h>

#define PI 3.14159265358979323846
#define DEFAULT_RES 140  /* 141^2 = 19,881 vertices */

const char *const example_names[] = {
    "plane", "cylinder", "dome", "hypar", "torus", "wave", "roof", NULL,
};

static const char *const descriptions[] = {
    "a flat 20 m x 15 m rectangle",
    "a barrel vault: radius 10 m, 120 degrees, 30 m long",
    "a spherical cap of radius 20 m over a 20 m x 20 m square",
    "the hyperbolic paraboloid z = xy/20 over 20 m x 20 m",
    "a torus section, R = 20 m, r = 6 m: 90 degrees around the axis, "
    "270 around the tube (outside and part of the inside)",
    "a 30 m x 20 m sine wave roof, amplitude 1.5 m",
    "a free-form roof of about 1,240 m^2: flat, single- and "
    "double-curved regions",
};

static int example_index(const char *name)
{
    for (int i = 0; example_names[i] != NULL; i++)
        if (strcmp(example_names[i], name) == 0)
            return i;
    return -1;
}

const char *example_describe(const char *name)
{
    int i = example_index(name);
    return i < 0 ? NULL : descriptions[i];
}

static double smoothstep(double a, double b, double x)
{
    if (x <= a)
        return 0;
    if (x >= b)
        return 1;
    double f = (x - a) / (b - a);
    return f * f * f * (f * (f * 6 - 15) + 10);
}

int example_point(const char *name, double s, double t, double p[3])
{
    switch (example_index(name)) {
    case 0:
        p[0] = 20 * s;
        p[1] = 15 * t;
        p[2] = 0;
        return 0;
    case 1: {
        double a = (-60 + 120 * s) * PI / 180;
        p[0] = 10 * sin(a);
        p[1] = 30 * t;
        p[2] = 10 * cos(a);
        return 0;
    }
    case 2:
        p[0] = 20 * s - 10;
        p[1] = 20 * t - 10;
        p[2] = sqrt(400 - p[0] * p[0] - p[1] * p[1]) - sqrt(200);
        return 0;
    case 3:
        p[0] = 20 * s - 10;
        p[1] = 20 * t - 10;
        p[2] = p[0] * p[1] / 20;
        return 0;
    case 4: {
        double around = 90 * s * PI / 180, tube = (-135 + 270 * t) * PI / 180;
        p[0] = (20 + 6 * cos(tube)) * cos(around);
        p[1] = (20 + 6 * cos(tube)) * sin(around);
        p[2] = 6 * sin(tube);
        return 0;
    }
    case 5:
        p[0] = 30 * s;
        p[1] = 20 * t;
        p[2] = 4 + 1.5 * sin(2 * PI * s) * cos(PI * t);
        return 0;
    case 6: {
        const double length = 39.56, width = 30, start = length / 4;
        double x = length * s, y = width * t;
        double arch = x >= start && x <= start + 16
                          ? 1.5 * (1 - cos(2 * PI * (x - start) / 16)) : 0;
        double bump = 3 * exp(-((x - 0.83 * length) * (x - 0.83 * length) / 25 +
                                (y - width / 2) * (y - width / 2) / 40)) *
                      smoothstep(0.6 * length, 0.7 * length, x);
        p[0] = x;
        p[1] = y;
        p[2] = 6 + arch + bump;
        return 0;
    }
    default:
        return -1;
    }
}

int example_write(const char *name, int res, FILE *out,
                  struct facet_error *err)
{
    int which = example_index(name);
    if (which < 0) {
        if (strcmp(name, "skin") == 0)
            return skin_write(res, out, err);
        char names[128] = "";
        for (int i = 0; example_names[i] != NULL; i++) {
            strncat(names, i ? ", " : "", sizeof names - strlen(names) - 1);
            strncat(names, example_names[i], sizeof names - strlen(names) - 1);
        }
        strncat(names, " or skin", sizeof names - strlen(names) - 1);
        return facet_error_set(err, FACET_EINPUT,
            "unknown example '%s' (choose %s)", name, names);
    }
    if (res == 0)
        res = DEFAULT_RES;
    if (res < 1 || res > 4096)
        return facet_error_set(err, FACET_EINPUT,
            "resolution %d is out of range (1 to 4096)", res);

    fprintf(out, "# Facet example '%s': %s\n", name, descriptions[which]);
    fprintf(out, "# units: metres; vt = surface parameters (s, t); "
                 "%d x %d quads\n", res, res);
    fprintf(out, "o %s\n", name);
    for (int j = 0; j <= res; j++)
        for (int i = 0; i <= res; i++) {
            double p[3];
            example_point(name, (double)i / res, (double)j / res, p);
            fprintf(out, "v %.9g %.9g %.9g\n", p[0], p[1], p[2]);
        }
    for (int j = 0; j <= res; j++)
        for (int i = 0; i <= res; i++)
            fprintf(out, "vt %.9g %.9g\n", (double)i / res, (double)j / res);
    /* Alternate the diagonal like a chequerboard, so no direction is
     * favoured by the triangulation (the curvature fit sees both). */
    for (int j = 0; j < res; j++)
        for (int i = 0; i < res; i++) {
            int a = j * (res + 1) + i + 1, b = a + 1;
            int c = b + res + 1, d = a + res + 1;
            if ((i + j) % 2 == 0)
                fprintf(out, "f %d/%d %d/%d %d/%d\nf %d/%d %d/%d %d/%d\n",
                        a, a, b, b, c, c, a, a, c, c, d, d);
            else
                fprintf(out, "f %d/%d %d/%d %d/%d\nf %d/%d %d/%d %d/%d\n",
                        a, a, b, b, d, d, b, b, c, c, d, d);
        }
    if (fflush(out) != 0 || ferror(out))
        return facet_error_set(err, FACET_EWORK,
                               "writing the example '%s' failed", name);
    return FACET_OK;
}
