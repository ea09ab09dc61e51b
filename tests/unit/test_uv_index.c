/*
 * test_uv_index.c: the UV bucket grid finds the right triangle, and the UV
 * check counts folds exactly (shared edges and corners are not overlaps).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/surface/uv_index.h"

/* n x n unit-square grid split into 2 n^2 counter-clockwise triangles. */
static double *grid_uv(int n, size_t *ntriangles)
{
    double *uv = malloc(sizeof(double) * 12 * n * n);
    size_t t = 0;
    for (int j = 0; j < n; j++)
        for (int i = 0; i < n; i++) {
            double u0 = (double)i / n, u1 = (double)(i + 1) / n;
            double v0 = (double)j / n, v1 = (double)(j + 1) / n;
            double a[6] = {u0, v0, u1, v0, u1, v1};
            double b[6] = {u0, v0, u1, v1, u0, v1};
            memcpy(uv + 6 * t++, a, sizeof a);
            memcpy(uv + 6 * t++, b, sizeof b);
        }
    *ntriangles = t;
    return uv;
}

static void test_locate_every_point(void **state)
{
    (void)state;
    size_t n;
    double *uv = grid_uv(37, &n);
    struct uv_index index;
    struct facet_error err;
    assert_int_equal(uv_index_build(uv, n, &index, &err), FACET_OK);
    srand(7);
    for (int k = 0; k < 20000; k++) {
        double u = rand() / (double)RAND_MAX, v = rand() / (double)RAND_MAX;
        double b[3];
        uint32_t t = uv_index_locate(&index, u, v, 0, b);
        assert_true(t != UINT32_MAX);
        const double *c = uv + 6 * (size_t)t;
        double pu = b[0] * c[0] + b[1] * c[2] + b[2] * c[4];
        double pv = b[0] * c[1] + b[1] * c[3] + b[2] * c[5];
        assert_true(fabs(pu - u) < 1e-12 && fabs(pv - v) < 1e-12);
        assert_true(b[0] >= -1e-12 && b[1] >= -1e-12 && b[2] >= -1e-12);
    }
    double b[3];
    assert_int_equal(uv_index_locate(&index, 1.5, 0.5, 0, b), UINT32_MAX);
    assert_int_equal(uv_index_locate(&index, -0.01, 0.5, 0, b), UINT32_MAX);
    uv_index_free(&index);
    free(uv);
}

static void test_grid_is_valid(void **state)
{
    (void)state;
    size_t n;
    double *uv = grid_uv(50, &n);
    struct uv_report report;
    struct facet_error err;
    assert_int_equal(uv_check(uv, n, &report, &err), FACET_OK);
    assert_int_equal(report.flipped, 0);
    assert_int_equal(report.overlapping, 0);
    assert_int_equal(report.degenerate, 0);
    assert_true(fabs(report.uv_area - 1.0) < 1e-12);
    free(uv);
}

static void test_fold_is_found(void **state)
{
    (void)state;
    size_t n;
    double *uv = grid_uv(10, &n);
    /* Pull one interior grid corner across its neighbours: the triangles
     * around it flip and overlap their neighbours. */
    for (size_t k = 0; k < 3 * n; k++)
        if (fabs(uv[2 * k] - 0.5) < 1e-9 && fabs(uv[2 * k + 1] - 0.5) < 1e-9)
            uv[2 * k] = 0.75;
    struct uv_report report;
    struct facet_error err;
    assert_int_equal(uv_check(uv, n, &report, &err), FACET_OK);
    assert_true(report.flipped > 0);
    assert_true(report.overlapping > 0);
    free(uv);
}

static void test_two_overlapping_triangles(void **state)
{
    (void)state;
    double uv[12] = {0, 0, 1, 0, 0, 1, 0.2, 0.2, 1.2, 0.2, 0.2, 1.2};
    struct uv_report report;
    struct facet_error err;
    assert_int_equal(uv_check(uv, 2, &report, &err), FACET_OK);
    assert_int_equal(report.overlapping, 1);
    assert_int_equal(report.flipped, 0);
    /* Touching at one corner only is not an overlap. */
    double touch[12] = {0, 0, 1, 0, 0, 1, 1, 0, 2, 0, 2, 1};
    assert_int_equal(uv_check(touch, 2, &report, &err), FACET_OK);
    assert_int_equal(report.overlapping, 0);
}

static void test_degenerate_and_nan(void **state)
{
    (void)state;
    double uv[12] = {0, 0, 1, 0, 0, 1, 0, 0, 0.5, 0, 1, 0};
    struct uv_report report;
    struct facet_error err;
    assert_int_equal(uv_check(uv, 2, &report, &err), FACET_OK);
    assert_int_equal(report.degenerate, 1);
    uv[3] = NAN;
    assert_int_equal(uv_check(uv, 2, &report, &err), FACET_EINPUT);
    assert_non_null(strstr(err.message, "triangle 1"));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_locate_every_point),
        cmocka_unit_test(test_grid_is_valid),
        cmocka_unit_test(test_fold_is_found),
        cmocka_unit_test(test_two_overlapping_triangles),
        cmocka_unit_test(test_degenerate_and_nan),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
