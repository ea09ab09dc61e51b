/*
 * test_examples.c: the example surfaces are what example.c says they are:
 * one UV-mapped disk each, with the analytic area of their formula.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/surface/example.h"
#include "core/surface/mesh.h"
#include "tests/support/quadrature.h"

#define PI 3.14159265358979323846

static void build(const char *name, int res, struct mesh *mesh)
{
    char *text = NULL;
    size_t size = 0;
    FILE *out = open_memstream(&text, &size);
    struct facet_error err;
    assert_int_equal(example_write(name, res, out, &err), FACET_OK);
    fclose(out);
    struct obj_file obj;
    if (obj_parse(text, size, name, &obj, &err) != FACET_OK)
        fail_msg("%s: %s", name, err.message);
    free(text);
    struct mesh_options options = {UNITS_M, NULL, NULL};
    if (mesh_build(&obj, &options, mesh, &err) != FACET_OK)
        fail_msg("%s: %s", name, err.message);
    obj_free(&obj);
}

static void example_at(const void *data, double s, double t, double p[3])
{
    example_point(data, s, t, p);
}

/* The area of example name by quadrature of its formula, an oracle
 * independent of the triangulation. */
static double example_area(const char *name)
{
    return quadrature_area(example_at, name, 600);
}

static void test_every_example_is_a_disk_with_uv(void **state)
{
    (void)state;
    for (int e = 0; example_names[e] != NULL; e++) {
        struct mesh m;
        build(example_names[e], 0, &m);
        assert_int_equal(m.nvertices, 141 * 141);
        assert_int_equal(m.ntriangles, 2 * 140 * 140);
        assert_true(m.has_uv);
        assert_int_equal(m.ncomponents, 1);
        assert_int_equal(m.nloops, 1);
        assert_int_equal(m.nonmanifold_edges, 0);
        assert_non_null(example_describe(example_names[e]));
        /* Normals point up or outwards: their area-weighted sum has a
         * positive z (every example is a roof seen from above), except the
         * torus section, whose outside faces away from the axis. */
        double sum[3] = {0, 0, 0};
        for (size_t t = 0; t < m.ntriangles; t++)
            for (int k = 0; k < 3; k++)
                sum[k] += m.face_area[t] * m.face_normal[3 * t + k];
        if (strcmp(example_names[e], "torus") == 0)
            assert_true(sum[0] > 0 && sum[1] > 0);
        else
            assert_true(sum[2] > 0);
        mesh_free(&m);
    }
}

static void test_areas(void **state)
{
    (void)state;
    struct mesh m;
    build("plane", 0, &m);
    assert_true(fabs(m.area - 300) < 1e-9 * 300);
    mesh_free(&m);
    build("cylinder", 0, &m);
    double cylinder = 2 * PI * 10 / 3 * 30;
    assert_true(fabs(m.area - cylinder) < 1e-3 * cylinder);
    mesh_free(&m);
    /* The torus section: r (pi/2) (R 3pi/2 + r (sin 135 - sin -135)). */
    build("torus", 0, &m);
    double torus = 6 * PI / 2 * (20 * 1.5 * PI + 6 * 2 * sin(0.75 * PI));
    assert_true(fabs(m.area - torus) < 5e-3 * torus);
    mesh_free(&m);
    const char *others[] = {"dome", "hypar", "wave", "roof"};
    for (int k = 0; k < 4; k++) {
        build(others[k], 0, &m);
        double oracle = example_area(others[k]);
        if (fabs(m.area - oracle) > 5e-3 * oracle)
            fail_msg("%s: mesh area %.4f, quadrature %.4f", others[k], m.area,
                     oracle);
        mesh_free(&m);
    }
    build("roof", 0, &m);
    assert_true(fabs(m.area - 1240) < 0.01 * 1240);
    mesh_free(&m);
}

/* The roof has the three regions the paper's method needs: flat where
 * x < L/4, single-curved (z depends on x only) on the vault, and
 * double-curved on the bump. Checked on the formula by finite differences
 * of the second fundamental form's determinant. */
static void test_roof_regions(void **state)
{
    (void)state;
    const double h = 1e-4;
    double zs[3][3];
    double gauss[3];
    const double where[3][2] = {{0.1, 0.5}, {0.4, 0.3}, {0.83, 0.5}};
    for (int w = 0; w < 3; w++) {
        for (int a = -1; a <= 1; a++)
            for (int b = -1; b <= 1; b++) {
                double p[3];
                example_point("roof", where[w][0] + a * h,
                              where[w][1] + b * h, p);
                zs[a + 1][b + 1] = p[2];
            }
        double zss = (zs[2][1] - 2 * zs[1][1] + zs[0][1]) / (h * h);
        double ztt = (zs[1][2] - 2 * zs[1][1] + zs[1][0]) / (h * h);
        double zst = (zs[2][2] - zs[2][0] - zs[0][2] + zs[0][0]) /
                     (4 * h * h);
        gauss[w] = zss * ztt - zst * zst;
        if (w == 0)
            assert_true(fabs(zss) < 1e-6 && fabs(ztt) < 1e-6);
        if (w == 1)
            assert_true(fabs(zss) > 1 && fabs(ztt) < 1e-6);
    }
    assert_true(fabs(gauss[0]) < 1e-9);
    assert_true(fabs(gauss[1]) < 1e-6);
    assert_true(fabs(gauss[2]) > 1);
}

static void test_errors(void **state)
{
    (void)state;
    struct facet_error err;
    assert_int_equal(example_write("blob", 0, stdout, &err), FACET_EINPUT);
    assert_non_null(strstr(err.message, "blob"));
    assert_non_null(strstr(err.message, "roof"));
    assert_int_equal(example_write("plane", 5000, stdout, &err),
                     FACET_EINPUT);
    assert_int_equal(example_write("plane", -1, stdout, &err), FACET_EINPUT);
    FILE *full = fopen("/dev/full", "w");
    if (full != NULL) {
        assert_int_equal(example_write("plane", 50, full, &err), FACET_EWORK);
        fclose(full);
    }
    double p[3];
    assert_int_equal(example_point("blob", 0, 0, p), -1);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_every_example_is_a_disk_with_uv),
        cmocka_unit_test(test_areas),
        cmocka_unit_test(test_roof_regions),
        cmocka_unit_test(test_errors),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
