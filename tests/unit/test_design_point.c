/*
 * test_design_point.c: the one rule design points are told apart by
 * (optimize.h): the same grid and the same threshold to a thousandth of a
 * millimetre; the order is by grid, then threshold, and the hash agrees
 * with the sameness.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include "core/search/optimize.h"

static void test_same_to_a_micrometre(void **state)
{
    (void)state;
    struct design_point a = {10, 20, 3.0};
    struct design_point b = {10, 20, 3.0004};  /* rounds to 3.000 mm */
    struct design_point c = {10, 20, 3.0006};  /* rounds to 3.001 mm */
    struct design_point d = {10, 21, 3.0};
    struct design_point e = {11, 1, 0.5};
    assert_int_equal(design_point_compare(&a, &b), 0);
    assert_true(design_point_hash(&a) == design_point_hash(&b));
    assert_int_equal(design_point_compare(&a, &c), -1);
    assert_int_equal(design_point_compare(&c, &a), 1);
    assert_int_equal(design_point_compare(&a, &d), -1);
    /* The grid before the threshold: nu first. */
    assert_int_equal(design_point_compare(&d, &e), -1);
    assert_int_equal(design_point_compare(&e, &e), 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_same_to_a_micrometre),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
