/*
 * test_unroll.c: flat patterns (unroll.h) against the closed forms of the
 * developments. A cylinder panel theta0..theta1 x h0..h1 of radius R is
 * the rectangle R (theta1 - theta0) x (h1 - h0); a cone panel s0..s1 x
 * theta0..theta1 (s the slant distance from the apex, half-angle a) is
 * the annular sector of radii s0, s1 and angle (theta1 - theta0) sin a.
 * The outlines are sampled along their sides, put off the surface by up
 * to 2 mm (the development projects them first), on axes that are not
 * the coordinate axes, and the cone once more with its axis and slope
 * given with the other sign (the same cone).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdlib.h>

#include "core/base/vec3.h"
#include "core/fit/developable.h"
#include "core/fit/unroll.h"

#define SIDE 16   /* samples per side of an outline */
#define POINTS (4 * SIDE)

static void assert_relative(double got, double want, double rel)
{
    if (!(fabs(got - want) <= rel * fabs(want))) {
        print_error("got %.17g, want %.17g (relative %.3g > %.3g)\n", got,
                    want, fabs(got - want) / fabs(want), rel);
        fail();
    }
}

/* A unit axis not along any coordinate axis, and two unit vectors across
 * it: a right-handed frame (e1, e2, axis). */
static void tilted_frame(double axis[3], double e1[3], double e2[3])
{
    axis[0] = 0.3;
    axis[1] = -0.5;
    axis[2] = 0.81;
    vec3_normalize(axis);
    double pick[3] = {1, 0, 0};
    vec3_cross(axis, pick, e1);
    vec3_normalize(e1);
    vec3_cross(axis, e1, e2);
}

/* The outline of the panel u0..u1 x v0..v1 of a surface at(u, v),
 * counter-clockwise in (u, v): SIDE points along each side, corners
 * once, in points[POINTS][3]; uv of each into uv[POINTS][2]. */
typedef void (*surface_at)(double u, double v, double off, double x[3]);

static void outline(surface_at at, double u0, double u1, double v0,
                    double v1, double *points, double *uv)
{
    for (int k = 0; k < POINTS; k++) {
        int side = k / SIDE;
        double t = (double)(k % SIDE) / SIDE;
        double u = side == 0 ? u0 + t * (u1 - u0)
                 : side == 1 ? u1
                 : side == 2 ? u1 - t * (u1 - u0) : u0;
        double v = side == 0 ? v0
                 : side == 1 ? v0 + t * (v1 - v0)
                 : side == 2 ? v1 : v1 - t * (v1 - v0);
        /* Off the surface by up to 2 mm, either way. */
        double off = 0.002 * sin(7.0 * k);
        at(u, v, off, points + 3 * k);
        uv[2 * k] = u;
        uv[2 * k + 1] = v;
    }
}

static double flat_distance(const double *flat, int a, int b)
{
    return hypot(flat[2 * a] - flat[2 * b], flat[2 * a + 1] - flat[2 * b + 1]);
}

/* ---- The cylinder: R = 3.7 m about a tilted axis through (1, 2, 3). */
#define CYL_R 3.7
static const double cyl_base[3] = {1, 2, 3};

static void cylinder_at(double theta, double h, double off, double x[3])
{
    double a[3], e1[3], e2[3];
    tilted_frame(a, e1, e2);
    for (int k = 0; k < 3; k++)
        x[k] = cyl_base[k] + h * a[k] +
               (CYL_R + off) * (cos(theta) * e1[k] + sin(theta) * e2[k]);
}

static struct developable the_cylinder(void)
{
    struct developable d = {DEVELOPABLE_CYLINDER, {0}, {1, 2, 3}, CYL_R, 0};
    double e1[3], e2[3];
    tilted_frame(d.axis, e1, e2);
    return d;
}

static void test_cylinder_is_its_rectangle(void **state)
{
    (void)state;
    struct developable d = the_cylinder();
    double t0 = 0.4, t1 = 1.3, h0 = -0.7, h1 = 1.8;
    double points[POINTS * 3], uv[POINTS * 2], flat[POINTS * 2];
    outline(cylinder_at, t0, t1, h0, h1, points, uv);
    /* Seen from outside (the normal away from the axis). */
    double outward[3];
    developable_nearest(&d, points + 3 * (SIDE / 2), NULL, outward);
    unroll_developable(&d, points, POINTS, outward, flat);
    double width = CYL_R * (t1 - t0), height = h1 - h0;
    /* (theta, h) counter-clockwise seen from outside: a positive area. */
    assert_relative(unroll_polygon_area(flat, POINTS), width * height, 1e-9);
    int corner[4] = {0, SIDE, 2 * SIDE, 3 * SIDE};
    assert_relative(flat_distance(flat, corner[0], corner[1]), width, 1e-9);
    assert_relative(flat_distance(flat, corner[1], corner[2]), height, 1e-9);
    assert_relative(flat_distance(flat, corner[2], corner[3]), width, 1e-9);
    assert_relative(flat_distance(flat, corner[3], corner[0]), height, 1e-9);
    assert_relative(flat_distance(flat, corner[0], corner[2]),
                    hypot(width, height), 1e-9);
    /* Every edge of the outline keeps its length on the surface: R
     * dtheta around (the arc, longer than its chord in space), dh
     * along a ruling (the chord itself). */
    for (int k = 0; k < POINTS; k++) {
        int next = (k + 1) % POINTS;
        double du = uv[2 * next] - uv[2 * k], dv = uv[2 * next + 1] -
                                                    uv[2 * k + 1];
        double on_surface = hypot(CYL_R * du, dv);
        assert_relative(flat_distance(flat, k, next), on_surface, 1e-9);
        double a[3], b[3];
        cylinder_at(uv[2 * k], uv[2 * k + 1], 0, a);
        cylinder_at(uv[2 * next], uv[2 * next + 1], 0, b);
        assert_true(flat_distance(flat, k, next) >=
                    vec3_distance(a, b) * (1 - 1e-12));
        if (du == 0)
            assert_relative(flat_distance(flat, k, next),
                            vec3_distance(a, b), 1e-9);
    }
    /* Seen from inside, the same pattern mirrored: the area's sign turns,
     * its lengths stay. */
    double inward[3] = {-outward[0], -outward[1], -outward[2]};
    double mirrored[POINTS * 2];
    unroll_developable(&d, points, POINTS, inward, mirrored);
    assert_relative(unroll_polygon_area(mirrored, POINTS), -width * height,
                    1e-9);
    /* The same cylinder given with its axis the other way. */
    struct developable turned = d;
    for (int k = 0; k < 3; k++)
        turned.axis[k] = -d.axis[k];
    unroll_developable(&turned, points, POINTS, outward, mirrored);
    assert_relative(unroll_polygon_area(mirrored, POINTS), width * height,
                    1e-9);
}

/* ---- The cone: half-angle 30 deg, apex (-2, 1, 4), axis tilted. */
#define CONE_ALPHA (30 * M_PI / 180)
static const double cone_apex[3] = {-2, 1, 4};

static void cone_at(double theta, double s, double off, double x[3])
{
    double a[3], e1[3], e2[3];
    tilted_frame(a, e1, e2);
    double ca = cos(CONE_ALPHA), sa = sin(CONE_ALPHA);
    for (int k = 0; k < 3; k++) {
        double radial = cos(theta) * e1[k] + sin(theta) * e2[k];
        double ruling = ca * a[k] + sa * radial;
        double normal = ca * radial - sa * a[k];  /* away from the axis */
        x[k] = cone_apex[k] + s * ruling + off * normal;
    }
}

/* The cone as a fit gives it: a base 5 m up the axis, the radius there,
 * the slope; sign -1 gives the axis and slope the other way. */
static struct developable the_cone(int sign)
{
    struct developable d;
    double e1[3], e2[3];
    d.shape = DEVELOPABLE_CONE;
    tilted_frame(d.axis, e1, e2);
    for (int k = 0; k < 3; k++)
        d.base[k] = cone_apex[k] + 5 * d.axis[k];
    d.radius = 5 * tan(CONE_ALPHA);
    d.slope = sign * tan(CONE_ALPHA);
    for (int k = 0; k < 3; k++)
        d.axis[k] *= sign;
    return d;
}

static void check_cone(int sign)
{
    struct developable d = the_cone(sign);
    double axis_point[3], direction[3], apex[3];
    double alpha = developable_describe(&d, cone_apex, axis_point,
                                        direction, apex);
    assert_relative(alpha, CONE_ALPHA, 1e-12);
    for (int k = 0; k < 3; k++)
        assert_true(fabs(apex[k] - cone_apex[k]) < 1e-12);
    double t0 = -0.6, t1 = 1.1, s0 = 3, s1 = 10;
    double points[POINTS * 3], uv[POINTS * 2], flat[POINTS * 2];
    outline(cone_at, t0, t1, s0, s1, points, uv);
    double outward[3];
    developable_nearest(&d, points + 3 * (SIDE / 2), NULL, outward);
    unroll_developable(&d, points, POINTS, outward, flat);
    double dphi = (t1 - t0) * sin(CONE_ALPHA);
    /* The sector's polygon: SIDE chords on each arc, each subtending
     * dphi / SIDE at the apex. */
    double area = (s1 * s1 - s0 * s0) / 2 * SIDE * sin(dphi / SIDE);
    /* The pattern is seen from outside: the loop, counter-clockwise in
     * (theta, s), winds there as it winds seen from outside in space,
     * the sign of (dX/dtheta x dX/ds) . outward. */
    double n[3], du[3], dv[3], p[3], q[3], r[3];
    cone_at(t0, s0, 0, p);
    cone_at(t1, s0, 0, q);
    cone_at(t0, s1, 0, r);
    vec3_sub(q, p, du);
    vec3_sub(r, p, dv);
    vec3_cross(du, dv, n);
    double sign_seen = vec3_dot(n, outward) > 0 ? 1 : -1;
    assert_relative(unroll_polygon_area(flat, POINTS), sign_seen * area,
                    1e-9);
    /* Every point at its slant distance from the apex, which the
     * development puts at the origin. */
    for (int k = 0; k < POINTS; k++)
        assert_relative(hypot(flat[2 * k], flat[2 * k + 1]), uv[2 * k + 1],
                        1e-9);
    /* The sector's angle: between its two straight sides. */
    double a0 = atan2(flat[1], flat[0]);                 /* (t0, s0) */
    double a1 = atan2(flat[2 * SIDE + 1], flat[2 * SIDE]);  /* (t1, s0) */
    double angle = fabs(remainder(a1 - a0, 2 * M_PI));
    assert_relative(angle, dphi, 1e-9);
    /* Every edge: a ruling keeps its length in space; an arc's chord in
     * the pattern is 2 s sin(dphi / 2), over the chord in space. */
    for (int k = 0; k < POINTS; k++) {
        int next = (k + 1) % POINTS;
        double dt = uv[2 * next] - uv[2 * k];
        double s = uv[2 * k + 1];
        double a[3], b[3];
        cone_at(uv[2 * k], uv[2 * k + 1], 0, a);
        cone_at(uv[2 * next], uv[2 * next + 1], 0, b);
        double want = dt == 0 ? vec3_distance(a, b)
                              : 2 * s * sin(fabs(dt) * sin(CONE_ALPHA) / 2);
        assert_relative(flat_distance(flat, k, next), want, 1e-9);
        assert_true(flat_distance(flat, k, next) >=
                    vec3_distance(a, b) * (1 - 1e-12));
    }
}

static void test_cone_is_its_annular_sector(void **state)
{
    (void)state;
    check_cone(1);
}

static void test_cone_given_the_other_way_is_the_same(void **state)
{
    (void)state;
    check_cone(-1);
}

/* A plane panel: its pattern is congruent to it. */
static void test_plane_keeps_every_distance(void **state)
{
    (void)state;
    double normal[3], e1[3], e2[3];
    tilted_frame(normal, e1, e2);
    double origin[3] = {4, -1, 2};
    double points[5 * 3], flat[5 * 2];
    static const double xy[5][2] = {{0, 0}, {2, 0.1}, {2.5, 1.5},
                                    {0.7, 1.9}, {-0.3, 0.8}};
    for (int k = 0; k < 5; k++)
        for (int c = 0; c < 3; c++)
            points[3 * k + c] = origin[c] + xy[k][0] * e1[c] +
                                xy[k][1] * e2[c];
    double along[3] = {1, 1, 1};
    unroll_plane(origin, normal, along, points, 5, flat);
    for (int a = 0; a < 5; a++)
        for (int b = a + 1; b < 5; b++)
            assert_relative(flat_distance(flat, a, b),
                            hypot(xy[a][0] - xy[b][0], xy[a][1] - xy[b][1]),
                            1e-12);
    /* (e1, e2, normal) is right-handed: counter-clockwise stays so. */
    assert_relative(unroll_polygon_area(flat, 5),
                    unroll_polygon_area(&xy[0][0], 5), 1e-12);
}

/* What a schedule says of a fit: a cylinder's axis pointed one way
 * whichever sign the fit gave it. */
static void test_describe_cylinder(void **state)
{
    (void)state;
    struct developable d = the_cylinder();
    double x[3], foot[3], direction[3], apex[3], other[3];
    cylinder_at(0.5, 1.0, 0, x);
    assert_true(developable_describe(&d, x, foot, direction, apex) == 0);
    assert_true(isnan(apex[0]));
    assert_relative(vec3_distance(x, foot), CYL_R, 1e-12);
    for (int k = 0; k < 3; k++)
        d.axis[k] = -d.axis[k];
    developable_describe(&d, x, foot, other, apex);
    for (int k = 0; k < 3; k++)
        assert_true(fabs(other[k] - direction[k]) < 1e-15);
}

/* A 3 x 1 rectangle turned by 0.4 rad, with points along its sides and
 * inside: turned back into its 3 x 1 box, landscape. */
static void test_least_box_turns_a_rectangle_back(void **state)
{
    (void)state;
    double points[24 * 2], hull[4 * 24 + 2];
    size_t order[24];
    double a = 0.4, c = cos(a), s = sin(a);
    static const double xy[12][2] = {{0, 0}, {1, 0}, {2, 0}, {3, 0},
                                     {3, 0.5}, {3, 1}, {2, 1}, {1, 1},
                                     {0, 1}, {0, 0.5}, {1.5, 0.5},
                                     {2.5, 0.2}};
    for (int k = 0; k < 12; k++) {
        points[2 * k] = 7 + c * xy[k][0] - s * xy[k][1];
        points[2 * k + 1] = -2 + s * xy[k][0] + c * xy[k][1];
    }
    double turn = unroll_least_box_turn(points, 12, hull, order);
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (int k = 0; k < 12; k++) {
        double x = cos(turn) * points[2 * k] - sin(turn) * points[2 * k + 1];
        double y = sin(turn) * points[2 * k] + cos(turn) * points[2 * k + 1];
        lo[0] = fmin(lo[0], x);
        hi[0] = fmax(hi[0], x);
        lo[1] = fmin(lo[1], y);
        hi[1] = fmax(hi[1], y);
    }
    assert_relative(hi[0] - lo[0], 3, 1e-12);
    assert_relative(hi[1] - lo[1], 1, 1e-12);
    /* Tall, it is laid landscape: the same box. */
    for (int k = 0; k < 12; k++) {
        double x = points[2 * k], y = points[2 * k + 1];
        points[2 * k] = -y;
        points[2 * k + 1] = x;
    }
    turn = unroll_least_box_turn(points, 12, hull, order);
    double w = 0, h = 0;
    lo[0] = lo[1] = INFINITY;
    hi[0] = hi[1] = -INFINITY;
    for (int k = 0; k < 12; k++) {
        double x = cos(turn) * points[2 * k] - sin(turn) * points[2 * k + 1];
        double y = sin(turn) * points[2 * k] + cos(turn) * points[2 * k + 1];
        lo[0] = fmin(lo[0], x);
        hi[0] = fmax(hi[0], x);
        lo[1] = fmin(lo[1], y);
        hi[1] = fmax(hi[1], y);
    }
    w = hi[0] - lo[0];
    h = hi[1] - lo[1];
    assert_relative(w, 3, 1e-12);
    assert_relative(h, 1, 1e-12);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_cylinder_is_its_rectangle),
        cmocka_unit_test(test_cone_is_its_annular_sector),
        cmocka_unit_test(test_cone_given_the_other_way_is_the_same),
        cmocka_unit_test(test_plane_keeps_every_distance),
        cmocka_unit_test(test_describe_cylinder),
        cmocka_unit_test(test_least_box_turns_a_rectangle_back),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
