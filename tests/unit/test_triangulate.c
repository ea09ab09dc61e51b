/*
 * test_triangulate.c: ear clipping gives n - 2 triangles that tile the
 * polygon (inside it, same winding, areas summing to its area) for convex,
 * L-, U- and comb-shaped polygons in tilted planes, and still n - 2
 * triangles for degenerate ones.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/obj/triangulate.h"

/* Places 2D outline (x, y) pairs into 3D on a tilted plane. */
static double *lift(const double *xy, size_t n)
{
    double *p = calloc(3 * n, sizeof *p);
    for (size_t i = 0; i < n; i++) {
        double x = xy[2 * i], y = xy[2 * i + 1];
        p[3 * i] = 0.8 * x + 0.1 * y + 5;
        p[3 * i + 1] = 0.6 * y - 0.3 * x - 2;
        p[3 * i + 2] = 0.5 * x + 0.7 * y + 1;
    }
    return p;
}

static double signed_area(const double *xy, size_t n)
{
    double a = 0;
    for (size_t i = 0; i < n; i++) {
        size_t j = (i + 1) % n;
        a += xy[2 * i] * xy[2 * j + 1] - xy[2 * j] * xy[2 * i + 1];
    }
    return a / 2;
}

/* Whether point q is strictly inside the 2D polygon (ray crossing). */
static int inside(const double *xy, size_t n, double qx, double qy)
{
    int in = 0;
    for (size_t i = 0, j = n - 1; i < n; j = i++) {
        double xi = xy[2 * i], yi = xy[2 * i + 1];
        double xj = xy[2 * j], yj = xy[2 * j + 1];
        if ((yi > qy) != (yj > qy) &&
            qx < (xj - xi) * (qy - yi) / (yj - yi) + xi)
            in = !in;
    }
    return in;
}

/* Triangulates the outline (in 3D on a tilted plane) and checks that the
 * triangles are n - 2, use every corner number in range, are wound like the
 * polygon, lie inside it and add up to its area. */
static void check_tiles(const double *xy, size_t n)
{
    double *point = lift(xy, n);
    uint32_t *tri = calloc(3 * n, sizeof *tri);  /* n - 2 triangles used */
    struct triangulate_scratch scratch;
    memset(&scratch, 0, sizeof scratch);
    struct facet_error err;
    assert_int_equal(triangulate_polygon(point, n, tri, &scratch, &err),
                     FACET_OK);
    double area = signed_area(xy, n), sum = 0;
    for (size_t t = 0; t < n - 2; t++) {
        double c[6];
        for (int k = 0; k < 3; k++) {
            assert_true(tri[3 * t + k] < n);
            c[2 * k] = xy[2 * tri[3 * t + k]];
            c[2 * k + 1] = xy[2 * tri[3 * t + k] + 1];
        }
        double a = signed_area(c, 3);
        assert_true(a * area >= 0);  /* same winding (or zero area) */
        sum += a;
        if (fabs(a) > 1e-12) {
            double cx = (c[0] + c[2] + c[4]) / 3, cy = (c[1] + c[3] + c[5]) / 3;
            assert_true(inside(xy, n, cx, cy));
        }
    }
    assert_true(fabs(sum - area) <= 1e-9 * fabs(area));
    triangulate_scratch_free(&scratch);
    free(tri);
    free(point);
}

static void test_triangle_and_quads(void **state)
{
    (void)state;
    double square[] = {0, 0, 2, 0, 2, 1, 0, 1};
    check_tiles(square, 4);
    double dart[] = {0, 0, 2, 1, 0, 2, 0.5, 1};  /* reflex corner 3 */
    check_tiles(dart, 4);
    double dart2[] = {0.5, 1, 0, 0, 2, 1, 0, 2};  /* reflex corner 0 */
    check_tiles(dart2, 4);
    double triangle[] = {0, 0, 1, 0, 0, 1};
    check_tiles(triangle, 3);
}

static void test_l_shape(void **state)
{
    (void)state;
    double l[] = {0, 0, 3, 0, 3, 1, 1, 1, 1, 3, 0, 3};
    check_tiles(l, 6);
    double cw[12];  /* the same, clockwise */
    for (int i = 0; i < 6; i++) {
        cw[2 * i] = l[2 * (5 - i)];
        cw[2 * i + 1] = l[2 * (5 - i) + 1];
    }
    check_tiles(cw, 6);
}

static void test_u_shape(void **state)
{
    (void)state;
    double u[] = {0, 0, 3, 0, 3, 3, 2, 3, 2, 1, 1, 1, 1, 3, 0, 3};
    check_tiles(u, 8);
}

static void test_thousand_corner_comb(void **state)
{
    (void)state;
    /* A comb: 250 teeth along the top of a bar, 1000 corners. */
    size_t teeth = 250, n = 4 * teeth;
    double *xy = malloc(sizeof(double) * 2 * n);
    size_t k = 0;
    for (size_t t = 0; t < teeth; t++) {
        double x = (double)t;
        double top = 3 + (double)(t % 7);
        double pts[8] = {x, 1, x + 0.25, top, x + 0.5, top, x + 0.75, 1};
        memcpy(xy + 2 * k, pts, sizeof pts);
        k += 4;
    }
    /* Close the bar underneath by bending the first and last corner down. */
    xy[1] = 0;
    xy[2 * (n - 1) + 1] = 0;
    check_tiles(xy, n);
    free(xy);
}

static void test_thousand_corner_circle(void **state)
{
    (void)state;
    size_t n = 1000;
    double *xy = malloc(sizeof(double) * 2 * n);
    for (size_t i = 0; i < n; i++) {
        double a = 2 * M_PI * (double)i / (double)n;
        double r = i % 2 ? 1.0 : 0.8;  /* a star: every other corner reflex */
        xy[2 * i] = r * cos(a);
        xy[2 * i + 1] = r * sin(a);
    }
    check_tiles(xy, n);
    free(xy);
}

static void test_collinear_corners(void **state)
{
    (void)state;
    /* A square with extra corners along its edges. */
    double square[] = {0, 0, 1, 0, 2, 0, 2, 1, 2, 2, 1, 2, 0, 2, 0, 1};
    check_tiles(square, 8);
    /* An L with a collinear corner at the reflex side. */
    double l[] = {0, 0, 3, 0, 3, 1, 2, 1, 1, 1, 1, 3, 0, 3, 0, 1.5};
    check_tiles(l, 8);
}

static void test_degenerate_gives_n_minus_2(void **state)
{
    (void)state;
    struct triangulate_scratch scratch;
    memset(&scratch, 0, sizeof scratch);
    struct facet_error err;
    /* All corners on one line, all at one point, a bow tie. */
    double line[] = {0, 0, 0, 1, 1, 1, 2, 2, 2, 3, 3, 3, 4, 4, 4};
    double point[15] = {0};
    double bowtie[] = {0, 0, 0, 1, 1, 0, 1, 0, 0, 0, 1, 0, 0.5, 2, 0};
    const double *cases[] = {line, point, bowtie};
    for (int c = 0; c < 3; c++) {
        uint32_t tri[9];
        for (size_t n = 3; n <= 5; n++) {
            memset(tri, 0xff, sizeof tri);
            assert_int_equal(triangulate_polygon(cases[c], n, tri, &scratch,
                                                 &err), FACET_OK);
            for (size_t k = 0; k < 3 * (n - 2); k++)
                assert_true(tri[k] < n);
        }
    }
    triangulate_scratch_free(&scratch);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_triangle_and_quads),
        cmocka_unit_test(test_l_shape),
        cmocka_unit_test(test_u_shape),
        cmocka_unit_test(test_thousand_corner_comb),
        cmocka_unit_test(test_thousand_corner_circle),
        cmocka_unit_test(test_collinear_corners),
        cmocka_unit_test(test_degenerate_gives_n_minus_2),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
