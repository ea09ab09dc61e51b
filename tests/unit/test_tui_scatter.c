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

/* The next smaller step of the 1-2-5 series. */
static double smaller_step(double d)
{
    double e = pow(10, floor(log10(d) + 1e-9)), m = d / e;
    return m > 4 ? 2 * e : m > 1.5 ? e : 0.5 * e;
}

/* How many multiples of d lie in [min, max], counted one by one. */
static int multiples(double min, double max, double d)
{
    int n = 0;
    for (double t = floor(min / d) - 1; t * d <= max + d; t++) {
        double v = t * d;
        if (v >= min - fabs(d) * 1e-9 && v <= max + fabs(d) * 1e-9)
            n++;
    }
    return n;
}

static void test_ticks(void **state)
{
    (void)state;
    double ticks[16], step;
    /* the demo's cost axis: 1,045,215 .. 1,316,466 in at most 6 ticks */
    int n = scatter_ticks(1045215, 1316466, 6, ticks, &step);
    assert_int_equal(n, 6);
    assert_true(step == 50000);
    assert_true(ticks[0] == 1050000 && ticks[5] == 1300000);
    assert_int_equal(scatter_ticks(3, 3, 5, ticks, &step), 1);
    assert_true(ticks[0] == 3 && step == 0);
    assert_int_equal(scatter_ticks(NAN, 3, 5, ticks, &step), 0);
    srand(7);
    for (int k = 0; k < 3000; k++) {
        double a = (rand() / (double)RAND_MAX - 0.3) *
                   pow(10, rand() % 12 - 5);
        double b = a + rand() / (double)RAND_MAX * pow(10, rand() % 10 - 4);
        int max = 1 + rand() % 15;
        n = scatter_ticks(a, b, max, ticks, &step);
        if (!(b > a))
            continue;
        assert_true(n >= 0 && n <= max);
        /* a step of the 1-2-5 series */
        double e = pow(10, floor(log10(step) + 1e-9)), m = step / e;
        assert_true(fabs(m - 1) < 1e-9 || fabs(m - 2) < 1e-9 ||
                    fabs(m - 5) < 1e-9);
        /* every multiple in the range, once, ascending */
        assert_int_equal(n, multiples(a, b, step));
        for (int t = 0; t < n; t++) {
            /* rounding of a multiple far from 0: a few ulps of it */
            double tol = step * 1e-6 + fabs(ticks[t]) * 1e-12;
            assert_true(ticks[t] >= a - tol && ticks[t] <= b + tol);
            assert_true(fabs(ticks[t] - round(ticks[t] / step) * step) < tol);
            if (t > 0)
                assert_true(fabs(ticks[t] - ticks[t - 1] - step) < tol);
        }
        /* the smallest such step: the next smaller gives too many */
        assert_true(multiples(a, b, smaller_step(step)) > max);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_ticks),
        cmocka_unit_test(test_cells),
        cmocka_unit_test(test_front),
        cmocka_unit_test(test_steps),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
