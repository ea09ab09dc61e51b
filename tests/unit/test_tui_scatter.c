/*
 * test_tui_scatter.c: the scatter plot's arithmetic: values to cells
 * (clamped, flat ranges, NaN), glyph levels, the two-metric Pareto front
 * against a brute-force oracle, and the cursor stepping from point to
 * point.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdlib.h>

#include "tui/scatter_model.h"

static void test_cells(void **state)
{
    (void)state;
    assert_int_equal(scatter_cell(0, 0, 10, 10), 0);
    assert_int_equal(scatter_cell(10, 0, 10, 10), 9);
    assert_int_equal(scatter_cell(4.99, 0, 10, 10), 4);
    assert_int_equal(scatter_cell(5, 0, 10, 10), 5);
    assert_int_equal(scatter_cell(-3, 0, 10, 10), 0);   /* clamped */
    assert_int_equal(scatter_cell(30, 0, 10, 10), 9);
    assert_int_equal(scatter_cell(7, 7, 7, 10), 5);     /* flat range */
    assert_int_equal(scatter_cell(NAN, 0, 10, 10), -1);
    assert_int_equal(scatter_cell(INFINITY, 0, 10, 10), -1);
    assert_int_equal(scatter_level(0, 0, 1, 3), 0);
    assert_int_equal(scatter_level(0.5, 0, 1, 3), 1);
    assert_int_equal(scatter_level(1, 0, 1, 3), 2);
    assert_int_equal(scatter_level(5, 5, 5, 3), 0);
    assert_int_equal(scatter_level(NAN, 0, 1, 3), 0);
}

static void test_front(void **state)
{
    (void)state;
    enum { N = 400 };
    struct scatter_point p[N];
    srand(7);
    for (int k = 0; k < N; k++) {
        p[k].number = k + 1;
        p[k].x = rand() % 50;
        p[k].y = rand() % 50;
        p[k].z = 0;
        p[k].rank = 2;
    }
    p[3].x = NAN;
    size_t front[N];
    size_t n = scatter_front(p, N, front);
    /* oracle: not beaten on both (ties: the lowest index), finite */
    size_t want = 0;
    for (int a = 0; a < N; a++) {
        if (!isfinite(p[a].x))
            continue;
        int beaten = 0;
        for (int b = 0; b < N && !beaten; b++)
            if (b != a && isfinite(p[b].x) &&
                ((p[b].x <= p[a].x && p[b].y <= p[a].y &&
                  (p[b].x < p[a].x || p[b].y < p[a].y)) ||
                 (p[b].x == p[a].x && p[b].y == p[a].y && b < a)))
                beaten = 1;
        if (!beaten) {
            assert_true(want < n);
            assert_int_equal(front[want], a);
            want++;
        }
    }
    assert_int_equal(n, want);
    for (size_t k = 1; k < n; k++) {
        assert_true(p[front[k]].x > p[front[k - 1]].x);
        assert_true(p[front[k]].y < p[front[k - 1]].y);
    }
}

static void test_steps(void **state)
{
    (void)state;
    /* a 3 x 3 lattice: index = 3 * row + column, x = column, y = row */
    struct scatter_point p[9];
    for (int k = 0; k < 9; k++)
        p[k] = (struct scatter_point){k + 1, k % 3, k / 3, 0, 2};
    assert_int_equal(scatter_step(p, 9, 4, 1, 0), 5);
    assert_int_equal(scatter_step(p, 9, 4, -1, 0), 3);
    assert_int_equal(scatter_step(p, 9, 4, 0, 1), 7);
    assert_int_equal(scatter_step(p, 9, 4, 0, -1), 1);
    assert_int_equal(scatter_step(p, 9, 5, 1, 0), 5);   /* edge: stays */
    assert_int_equal(scatter_step(p, 9, 0, 0, -1), 0);
    assert_int_equal(scatter_step(p, 9, 0, 0, 0), 0);
    /* two points at one place: right goes to the later one, left back */
    struct scatter_point twin[2] = {{1, 1, 1, 0, 1}, {2, 1, 1, 0, 1}};
    assert_int_equal(scatter_step(twin, 2, 0, 1, 0), 1);
    assert_int_equal(scatter_step(twin, 2, 1, -1, 0), 0);
    assert_int_equal(scatter_step(twin, 2, 1, 1, 0), 1);
    double lo, hi;
    scatter_range(p, 9, 0, &lo, &hi);
    assert_true(lo == 0 && hi == 2);
    scatter_range(p, 0, 1, &lo, &hi);
    assert_true(isnan(lo) && isnan(hi));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_cells),
        cmocka_unit_test(test_front),
        cmocka_unit_test(test_steps),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
