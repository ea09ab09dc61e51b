/*
 * numparse.c: the decimal number parser of the OBJ loader, and the
 * single-number parser of the CLI and the forms. See numparse.h.
 *
 * The digits are gathered into a 64-bit integer mantissa (at most 19
 * significant digits; later digits only move the decimal exponent) and the
 * value is mantissa x 10^exponent. When the mantissa fits in 53 bits and the
 * exponent is at most 22 in size, both factors are exact doubles and one
 * IEEE multiplication or division rounds the result correctly. Otherwise the
 * product is formed in long double (64-bit significand on x86-64), whose
 * extra precision keeps the error far below half a double ulp before the
 * final rounding, so the result is within one ulp of the correctly rounded
 * value. On a platform where long double is just double the slow path can be
 * off by a few ulps; the fast path is exact everywhere.
 */
#include "core/base/numparse.h"

#include <math.h>
#include <stdint.h>
#include <string.h>

#define MAX_MANTISSA_DIGITS 19
#define EXPONENT_CAP 100000  /* larger written exponents saturate here */

/* 10^k for k = 0..22: every one is exactly representable in a double. */
static const double exact_power_of_ten[23] = {
    1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11,
    1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22,
};

/* 10^(2^k) for k = 0..9, correctly rounded to long double by the compiler. */
static const long double binary_power_of_ten[10] = {
    1e1L, 1e2L, 1e4L, 1e8L, 1e16L, 1e32L, 1e64L, 1e128L, 1e256L, 1e512L,
};

static int is_digit(char c)
{
    return c >= '0' && c <= '9';
}

/* Number of decimal digits of m (at most 20). */
static long significant_digits(uint64_t m)
{
    long n = 0;
    for (; m != 0; m /= 10)
        n++;
    return n;
}

/* 10^k for 0 <= k < 1024 in long double, from at most ten exact-ish
 * factors. */
static long double power_of_ten(long k)
{
    long double result = 1.0L;
    for (int bit = 0; k != 0; bit++, k >>= 1)
        if (k & 1)
            result *= binary_power_of_ten[bit];
    return result;
}

int numparse_double(const char *text, const char *end, double *value,
                    const char **stop)
{
    const char *p = text;
    int negative = 0;
    if (p < end && (*p == '-' || *p == '+')) {
        negative = *p == '-';
        p++;
    }

    /* Most numbers have at most 19 digits in all: read them in one sweep
     * and fall back to the careful digit loop below only when longer. */
    const char *digits = p;
    uint64_t mantissa = 0;
    long exponent = 0;        /* value = mantissa x 10^exponent */
    int any_digit = 0;
    int truncated = 0;        /* a nonzero digit did not fit in mantissa */
    for (; p < end && is_digit(*p); p++)
        mantissa = mantissa * 10 + (uint64_t)(*p - '0');
    long nwritten = p - digits;
    if (p < end && *p == '.') {
        const char *fraction = ++p;
        for (; p < end && is_digit(*p); p++)
            mantissa = mantissa * 10 + (uint64_t)(*p - '0');
        exponent = -(long)(p - fraction);
        nwritten += p - fraction;
    }
    any_digit = nwritten > 0;
    if (nwritten > MAX_MANTISSA_DIGITS) {
        int ndigits = 0;      /* significant digits kept in mantissa */
        p = digits;
        mantissa = 0;
        exponent = 0;
        for (; p < end && is_digit(*p); p++) {
            int d = *p - '0';
            any_digit = 1;
            if (mantissa == 0 && d == 0)
                continue;
            if (ndigits < MAX_MANTISSA_DIGITS) {
                mantissa = mantissa * 10 + (uint64_t)d;
                ndigits++;
            } else {
                if (exponent < EXPONENT_CAP)
                    exponent++;
                truncated |= d != 0;
            }
        }
        if (p < end && *p == '.') {
            p++;
            for (; p < end && is_digit(*p); p++) {
                int d = *p - '0';
                any_digit = 1;
                if (mantissa == 0 && d == 0) {
                    if (exponent > -EXPONENT_CAP)
                        exponent--;
                } else if (ndigits < MAX_MANTISSA_DIGITS) {
                    mantissa = mantissa * 10 + (uint64_t)d;
                    ndigits++;
                    exponent--;
                } else {
                    truncated |= d != 0;
                }
            }
        }
    }
    if (!any_digit)
        return NUMPARSE_SYNTAX;

    /* An exponent needs at least one digit; like strtod, "1e" or "1e+" is
     * the number 1 followed by other text. */
    if (p < end && (*p == 'e' || *p == 'E')) {
        const char *q = p + 1;
        int exponent_negative = 0;
        if (q < end && (*q == '-' || *q == '+')) {
            exponent_negative = *q == '-';
            q++;
        }
        if (q < end && is_digit(*q)) {
            long written = 0;
            for (; q < end && is_digit(*q); q++)
                if (written < EXPONENT_CAP)
                    written = written * 10 + (*q - '0');
            exponent += exponent_negative ? -written : written;
            p = q;
        }
    }
    *stop = p;

    double result;
    if (mantissa == 0) {
        result = 0.0;
    } else if (!truncated && mantissa <= ((uint64_t)1 << 53) &&
               exponent >= -22 && exponent <= 22) {
        result = (double)mantissa;
        if (exponent < 0)
            result /= exact_power_of_ten[-exponent];
        else
            result *= exact_power_of_ten[exponent];
    } else if (exponent + significant_digits(mantissa) > 310) {
        return NUMPARSE_RANGE;  /* at least 10^309 > DBL_MAX */
    } else if (exponent + significant_digits(mantissa) < -330) {
        result = 0.0;           /* below half the smallest subnormal */
    } else {
        long double scaled = (long double)mantissa;
        if (exponent < 0)
            scaled /= power_of_ten(-exponent);
        else
            scaled *= power_of_ten(exponent);
        result = (double)scaled;
        if (isinf(result))
            return NUMPARSE_RANGE;
    }
    *value = negative ? -result : result;
    return NUMPARSE_OK;
}

int numparse_whole(const char *text, const char *end, long long min,
                   long long max, long long *value, const char **stop)
{
    const char *p = text;
    int negative = 0;
    if (p < end && *p == '-' && min < 0) {
        negative = 1;
        p++;
    }
    if (p == end || *p < '0' || *p > '9')
        return NUMPARSE_SYNTAX;
    /* Accumulated as a magnitude, stopping at the bound: the digits that
     * follow only make it larger. */
    unsigned long long limit = negative ? (unsigned long long)(-(min + 1)) + 1
                                        : (unsigned long long)(max < 0 ? 0
                                                                       : max);
    unsigned long long n = 0;
    int over = 0;
    for (; p < end && *p >= '0' && *p <= '9'; p++) {
        unsigned digit = (unsigned)(*p - '0');
        if (!over && n > (limit - digit) / 10)
            over = 1;
        if (!over)
            n = n * 10 + digit;
    }
    *stop = p;
    if (over)
        return NUMPARSE_RANGE;
    long long v = negative ? (n == 0 ? 0 : -(long long)(n - 1) - 1)
                           : (long long)n;
    if (v < min || v > max)
        return NUMPARSE_RANGE;
    *value = v;
    return NUMPARSE_OK;
}

int numparse_text(const char *text, double *value)
{
    const char *end = text + strlen(text), *stop;
    int rc = numparse_double(text, end, value, &stop);
    if (rc == NUMPARSE_OK && stop != end)
        return NUMPARSE_SYNTAX;
    return rc;
}

int numparse_number(const char *text, double min, double max,
                    const char *what, double *out, struct facet_error *err)
{
    /* Decimal as written: 0x10, nan and inf are not numbers here. */
    double number;
    int rc = numparse_text(text, &number);
    if (rc == NUMPARSE_SYNTAX)
        return facet_error_set(err, FACET_EINPUT,
            "%s: '%s' is not a number", what, text);
    /* The text as given, not %g of it: 1000000000.5 is not 1e+09. */
    if (rc == NUMPARSE_RANGE || !(number >= min && number <= max))
        return facet_error_set(err, FACET_EINPUT,
            "%s: %s is out of range (%g to %g)", what, text, min, max);
    *out = number;
    return FACET_OK;
}
