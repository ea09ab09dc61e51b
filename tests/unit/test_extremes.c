/*
 * test_extremes.c: larger and smaller (extremes.h) against the C library's
 * fmax and fmin themselves, bit for bit, on the pairs where an inline
 * comparison most easily differs from them: signed zeros both ways, a NaN
 * on either side or both, infinities, subnormals and equal values, and on
 * a million random pairs drawn from every bit pattern.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <float.h>
#include <math.h>
#include <string.h>

#include "core/base/extremes.h"

static uint64_t bits_of(double x)
{
    uint64_t b;
    memcpy(&b, &x, sizeof b);
    return b;
}

/* The library's answers; volatile so that gcc calls the library rather
 * than folding the call with its own idea of fmax. */
static double library_max(double a, double b)
{
    volatile double x = a, y = b;
    return fmax(x, y);
}

static double library_min(double a, double b)
{
    volatile double x = a, y = b;
    return fmin(x, y);
}

static void check_pair(double a, double b)
{
    /* A NaN's payload is not compared: any NaN is a NaN. */
    double want = library_max(a, b), got = larger(a, b);
    if (isnan(want))
        assert_true(isnan(got));
    else
        assert_int_equal(bits_of(got), bits_of(want));
    want = library_min(a, b);
    got = smaller(a, b);
    if (isnan(want))
        assert_true(isnan(got));
    else
        assert_int_equal(bits_of(got), bits_of(want));
}

static void test_special_values(void **state)
{
    (void)state;
    const double value[] = {0.0, -0.0, 1.0, -1.0, NAN, -NAN, INFINITY,
                            -INFINITY, DBL_MIN, -DBL_MIN, DBL_TRUE_MIN,
                            -DBL_TRUE_MIN, DBL_MAX, -DBL_MAX, 1e-300,
                            0.1, 0.30000000000000004};
    size_t n = sizeof value / sizeof value[0];
    for (size_t i = 0; i < n; i++)
        for (size_t j = 0; j < n; j++)
            check_pair(value[i], value[j]);
    /* the cases that tell a plain a > b ? a : b from the library */
    assert_int_equal(bits_of(larger(0.0, -0.0)), bits_of(fmax(0.0, -0.0)));
    assert_int_equal(bits_of(larger(-0.0, 0.0)), bits_of(library_max(-0.0, 0.0)));
    assert_true(larger(NAN, 2.0) == 2.0);
    assert_true(smaller(2.0, NAN) == 2.0);
}

static void test_random_bit_patterns(void **state)
{
    (void)state;
    uint64_t s = 0x9e3779b97f4a7c15u;
    for (int k = 0; k < 1000000; k++) {
        uint64_t x[2];
        for (int i = 0; i < 2; i++) {
            s ^= s << 13;
            s ^= s >> 7;
            s ^= s << 17;
            x[i] = s;
        }
        double a, b;
        memcpy(&a, &x[0], sizeof a);
        memcpy(&b, &x[1], sizeof b);
        /* Facet never makes a signalling NaN; quiet it as arithmetic
         * would. */
        if (isnan(a))
            a = NAN;
        if (isnan(b))
            b = NAN;
        check_pair(a, b);
        check_pair(a, a);
        check_pair(b, -b);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_special_values),
        cmocka_unit_test(test_random_bit_patterns),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
