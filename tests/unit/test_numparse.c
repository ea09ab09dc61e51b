/*
 * test_numparse.c: the OBJ number parser against strtod: exact for short
 * decimals, within one ulp on a million random strings of many shapes, and
 * strict about what is not a number; the single-number parser of the CLI
 * and the forms: strtod's value for what it takes, its range and finite
 * values only, and every message naming the field it was given.
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

#include "core/base/numparse.h"

static int parse(const char *text, double *value, const char **stop)
{
    return numparse_double(text, text + strlen(text), value, stop);
}

/* Distance in ulps between two finite doubles of the same sign. */
static uint64_t ulps_apart(double a, double b)
{
    if (a == b)
        return 0;
    int64_t ia, ib;
    memcpy(&ia, &a, sizeof ia);
    memcpy(&ib, &b, sizeof ib);
    if ((ia < 0) != (ib < 0))
        return UINT64_MAX;
    return ia > ib ? (uint64_t)(ia - ib) : (uint64_t)(ib - ia);
}

static void test_short_decimals_exact(void **state)
{
    (void)state;
    const char *cases[] = {
        "0", "-0", "1", "-1", "0.1", "0.5", "3.14159", "-20.000000",
        "1e10", "1E-5", "+7.25", ".5", "5.", "123456.789012", "1e22",
        "9007199254740992", "0.000001", "-0.000000", "2.5e-3", "42",
        "1.7976931348623157e308", "4.9406564584124654e-324",
        "2.2250738585072014e-308", "1e-320", "1e23",
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        double value;
        const char *stop;
        assert_int_equal(parse(cases[i], &value, &stop), NUMPARSE_OK);
        assert_ptr_equal(stop, cases[i] + strlen(cases[i]));
        double want = strtod(cases[i], NULL);
        assert_true(value == want);
        assert_int_equal(signbit(value) != 0, signbit(want) != 0);
    }
}

static void test_stops_at_end_pointer(void **state)
{
    (void)state;
    const char *text = "12345";
    double value;
    const char *stop;
    assert_int_equal(numparse_double(text, text + 3, &value, &stop),
                     NUMPARSE_OK);
    assert_true(value == 123.0);
    assert_ptr_equal(stop, text + 3);
    assert_int_equal(parse("1.5/2", &value, &stop), NUMPARSE_OK);
    assert_int_equal(*stop, '/');
    assert_int_equal(parse("2e", &value, &stop), NUMPARSE_OK);
    assert_true(value == 2.0);
    assert_int_equal(*stop, 'e');
}

static void test_rejects(void **state)
{
    (void)state;
    const char *syntax[] = {"", "-", "+", ".", "nan", "NaN", "inf",
                            "-infinity", "abc", "e5", ".e1", "0x10"};
    for (size_t i = 0; i < sizeof syntax / sizeof syntax[0]; i++) {
        double value;
        const char *stop;
        int rc = parse(syntax[i], &value, &stop);
        if (strcmp(syntax[i], "0x10") == 0) {  /* the number 0, then x */
            assert_int_equal(rc, NUMPARSE_OK);
            assert_int_equal(*stop, 'x');
        } else {
            assert_int_equal(rc, NUMPARSE_SYNTAX);
        }
    }
    const char *range[] = {"1e309", "-1.8e308", "1e100000000000",
                           "99999999999999999999999e300"};
    for (size_t i = 0; i < sizeof range / sizeof range[0]; i++) {
        double value;
        const char *stop;
        assert_int_equal(parse(range[i], &value, &stop), NUMPARSE_RANGE);
    }
    double value;
    const char *stop;
    assert_int_equal(parse("1e-100000000000", &value, &stop), NUMPARSE_OK);
    assert_true(value == 0.0);
}

static uint64_t next_random(uint64_t *s)
{
    *s ^= *s << 13;
    *s ^= *s >> 7;
    *s ^= *s << 17;
    return *s;
}

/* A random decimal string of one of several shapes. */
static void random_number(uint64_t *s, char *out, size_t size)
{
    char digits[64];
    int shape = (int)(next_random(s) % 8);
    int ndigits = 1 + (int)(next_random(s) % (shape == 3 ? 40 : 17));
    for (int i = 0; i < ndigits; i++)
        digits[i] = (char)('0' + next_random(s) % 10);
    digits[ndigits] = '\0';
    const char *sign = next_random(s) % 2 ? "-" : "";
    int point = (int)(next_random(s) % (size_t)(ndigits + 1));
    int e;
    switch (shape) {
    case 0: /* integer */
        snprintf(out, size, "%s%s", sign, digits);
        break;
    case 1: /* fixed point, CAD style */
    case 3: /* long mantissa */
        snprintf(out, size, "%s%.*s.%s", sign, point, digits, digits + point);
        break;
    case 2: /* small exponent */
        e = (int)(next_random(s) % 45) - 22;
        snprintf(out, size, "%s%.*s.%se%d", sign, point, digits,
                 digits + point, e);
        break;
    case 4: /* huge exponent, near overflow */
        e = 280 + (int)(next_random(s) % 28);
        snprintf(out, size, "%s%c.%se%d", sign, digits[0], digits + 1, e);
        break;
    case 5: /* tiny exponent, subnormals */
        e = -340 + (int)(next_random(s) % 40);
        snprintf(out, size, "%s%c.%se%d", sign, digits[0], digits + 1, e);
        break;
    case 6: /* any exponent */
        e = (int)(next_random(s) % 600) - 300;
        snprintf(out, size, "%s0.%sE%+d", sign, digits, e);
        break;
    default: /* a printed double, round trip */
        {
            double x;
            uint64_t bits = next_random(s);
            memcpy(&x, &bits, sizeof x);
            if (!isfinite(x))
                x = 1.5;
            snprintf(out, size, "%.17g", x);
        }
        break;
    }
}

static void test_million_random_within_one_ulp(void **state)
{
    (void)state;
    uint64_t s = 0x9e3779b97f4a7c15u;
    size_t exact = 0, total = 0;
    for (int i = 0; i < 1000000; i++) {
        char text[128];
        random_number(&s, text, sizeof text);
        double want = strtod(text, NULL);
        double value;
        const char *stop;
        int rc = parse(text, &value, &stop);
        if (isinf(want)) {
            assert_int_equal(rc, NUMPARSE_RANGE);
            continue;
        }
        if (rc != NUMPARSE_OK || ulps_apart(value, want) > 1)
            fail_msg("\"%s\": got %.17g, strtod %.17g", text, value, want);
        assert_ptr_equal(stop, text + strlen(text));
        exact += value == want;
        total++;
    }
    /* Off-by-one results are rare: only where the slow path rounds twice. */
    assert_true(exact * 1000 >= total * 999);
}

/* What numparse_number takes is strtod's number, whatever the field's
 * name; the bounds themselves are inside the range. */
static void test_number_takes(void **state)
{
    (void)state;
    const char *cases[] = {"0", "3.5", "1e9", "0.001", "-0", "7.", ".25",
                           "999999999.5", "1E3"};
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        double value = -1;
        struct facet_error err;
        assert_int_equal(numparse_number(cases[i], 0, 1e9, "Panel cost",
                                         &value, &err), FACET_OK);
        assert_true(value == strtod(cases[i], NULL));
    }
    double value;
    struct facet_error err;
    assert_int_equal(numparse_number("-2.5", -2.5, -2.5, "x", &value, &err),
                     FACET_OK);
    assert_true(value == -2.5);
}

/* Everything numparse_number refuses: not a number (words, blanks, a
 * trailing unit, hexadecimal, nan, inf, several numbers), a number
 * outside the range, one too large for a double. Each message starts with
 * the field's name as given, quotes or states the value, and *out is
 * left as it was. */
static void test_number_refuses(void **state)
{
    (void)state;
    static const struct {
        const char *text, *says;
    } cases[] = {
        {"", "'' is not a number"},
        {"abc", "'abc' is not a number"},
        {" 5", "' 5' is not a number"},
        {"5 ", "'5 ' is not a number"},
        {"5mm", "'5mm' is not a number"},
        {"0x10", "'0x10' is not a number"},
        {"nan", "'nan' is not a number"},
        {"inf", "'inf' is not a number"},
        {"-infinity", "'-infinity' is not a number"},
        {"1,2", "'1,2' is not a number"},
        {"-5", "-5 is out of range (0 to 1e+09)"},
        {"1000000000.5", "1000000000.5 is out of range (0 to 1e+09)"},
        {"1e999", "1e999 is out of range (0 to 1e+09)"},
        {"-1e999", "-1e999 is out of range (0 to 1e+09)"},
    };
    const char *const names[] = {"Joint cost USD/m", "--joint-cost"};
    for (size_t n = 0; n < 2; n++)
        for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
            double value = 42;
            struct facet_error err;
            int rc = numparse_number(cases[i].text, 0, 1e9, names[n],
                                     &value, &err);
            char want[200];
            snprintf(want, sizeof want, "%s: %s", names[n], cases[i].says);
            if (rc != FACET_EINPUT || strcmp(err.message, want) != 0)
                fail_msg("\"%s\": rc %d, \"%s\", want \"%s\"",
                         cases[i].text, rc, err.message, want);
            assert_int_equal(err.code, FACET_EINPUT);
            assert_true(value == 42);
        }
    /* Subnormal and tiny numbers are numbers: refused by range alone. */
    double value = 42;
    struct facet_error err;
    assert_int_equal(numparse_number("1e-400", 1e-9, 1, "Max panel m^2",
                                     &value, &err), FACET_EINPUT);
    assert_string_equal(err.message,
                        "Max panel m^2: 1e-400 is out of range (1e-09 to 1)");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_short_decimals_exact),
        cmocka_unit_test(test_stops_at_end_pointer),
        cmocka_unit_test(test_rejects),
        cmocka_unit_test(test_million_random_within_one_ulp),
        cmocka_unit_test(test_number_takes),
        cmocka_unit_test(test_number_refuses),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
