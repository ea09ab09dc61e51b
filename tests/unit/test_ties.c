/*
 * test_ties.c: the tie rule of core/search/ties.h on hand-made columns: the
 * tolerance (a billionth of the range or of the largest magnitude), tie
 * classes by single linkage (a chain ties as a whole, a gap over the
 * tolerance splits), infinities, idempotence, and the comparison of
 * normalised numbers.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>

#include "core/search/ties.h"

static void test_tolerance(void **state)
{
    (void)state;
    double range[] = {-3, 1, 7};            /* range 10 over magnitude 7 */
    assert_true(ties_tolerance(range, 3, 1) == 1e-9 * 7 - 1e-9 * -3);
    double costs[] = {1.2e6, 1.0e6, 1.1e6}; /* magnitude 1.2e6 over 2e5 */
    assert_true(ties_tolerance(costs, 3, 1) == 1e-9 * 1.2e6);
    /* Every other value of a 2-column array; infinities do not count. */
    double strided[] = {5, 0, INFINITY, 0, -5, 0};
    assert_true(ties_tolerance(strided, 3, 2) == 1e-9 * 5 - 1e-9 * -5);
    assert_true(ties_tolerance(strided, 0, 2) == 0);
    double none[] = {INFINITY, -INFINITY};
    assert_true(ties_tolerance(none, 2, 1) == 0);
}

static void test_classes(void **state)
{
    (void)state;
    /* 0, 0.6, 1.2 chain (each gap 0.6 <= 1) though 0 and 1.2 are 1.2
     * apart; 2.3 is 1.1 from 1.2 and starts a class; 3.3 joins it. */
    double v[] = {1.2, 3.3, 0.6, 2.3, 0, INFINITY, INFINITY, -INFINITY};
    double out[8];
    assert_int_equal(ties_merge_column(v, 8, 1, 1.0, out, NULL), 0);
    const double expected[] = {0, 2.3, 0, 2.3, 0, INFINITY, INFINITY,
                               -INFINITY};
    for (int k = 0; k < 8; k++)
        assert_true(out[k] == expected[k]);
    /* In place, and again: nothing moves. */
    assert_int_equal(ties_merge_column(v, 8, 1, 1.0, v, NULL), 0);
    for (int k = 0; k < 8; k++)
        assert_true(v[k] == expected[k]);
}

static void test_merge_columns(void **state)
{
    (void)state;
    /* Two objectives of the size of a cost and an area: the costs differ
     * by rounding (9e-10, within 1e-9 of 1.3e6 USD), the areas by 1e-3,
     * over 1e-9 of 900 m^2. */
    double f[] = {1215639.0000000009, 630.3,
                  1215639.0000000018, 630.301,
                  1300000.0, 900.0};
    assert_int_equal(ties_merge(f, 3, 2, f, NULL), 0);
    assert_true(f[0] == f[2]);
    assert_true(f[0] == 1215639.0000000009);
    assert_true(f[1] == 630.3 && f[3] == 630.301);
    double again[6];
    assert_int_equal(ties_merge(f, 3, 2, again, NULL), 0);
    for (int k = 0; k < 6; k++)
        assert_true(again[k] == f[k]);
}

static void test_compare_normalised(void **state)
{
    (void)state;
    assert_int_equal(ties_compare_normalised(0.5, 0.5 + 1e-12), 0);
    assert_int_equal(ties_compare_normalised(0.5, 0.5 + 1e-8), -1);
    assert_int_equal(ties_compare_normalised(0.5 + 1e-8, 0.5), 1);
    assert_int_equal(ties_compare_normalised(INFINITY, INFINITY), 0);
    assert_int_equal(ties_compare_normalised(2.0, INFINITY), -1);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_tolerance),
        cmocka_unit_test(test_classes),
        cmocka_unit_test(test_merge_columns),
        cmocka_unit_test(test_compare_normalised),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
