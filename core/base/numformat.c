/*
 * numformat.c: grouped numbers. See numformat.h.
 */
#include "core/base/numformat.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void number_grouped(char *out, size_t size, double value, int decimals)
{
    if (size == 0)
        return;
    if (isnan(value)) {
        snprintf(out, size, "-");
        return;
    }
    if (isinf(value)) {
        snprintf(out, size, value > 0 ? "inf" : "-inf");
        return;
    }
    char plain[400];
    int n = snprintf(plain, sizeof plain, "%.*f", decimals, value);
    if (n < 0 || (size_t)n >= sizeof plain) {
        snprintf(out, size, "%.6g", value);
        return;
    }
    const char *digits = plain + (plain[0] == '-');
    size_t whole = strcspn(digits, ".");
    char grouped[560];
    size_t g = 0;
    if (plain[0] == '-' && strspn(digits, "0.") != strlen(digits))
        grouped[g++] = '-';  /* no "-0" for a tiny negative number */
    for (size_t k = 0; k < whole; k++) {
        if (k > 0 && (whole - k) % 3 == 0)
            grouped[g++] = ',';
        grouped[g++] = digits[k];
    }
    snprintf(grouped + g, sizeof grouped - g, "%s", digits + whole);
    snprintf(out, size, "%s", grouped);
}

void number_exact(char out[NUMBER_EXACT_SIZE], double value)
{
    if (!isfinite(value)) {
        snprintf(out, NUMBER_EXACT_SIZE, "%s",
                 isnan(value) ? "nan" : value > 0 ? "inf" : "-inf");
        return;
    }
    /* strtod reads in the same locale as snprintf writes, so the check is
     * made before the decimal point becomes '.'. %.17g always reads back. */
    for (int precision = 15; precision <= 17; precision++) {
        snprintf(out, NUMBER_EXACT_SIZE, "%.*g", precision, value);
        if (precision == 17 || strtod(out, NULL) == value)
            break;
    }
    for (char *c = out; *c != '\0'; c++)
        if ((*c < '0' || *c > '9') && *c != 'e' && *c != '-' && *c != '+')
            *c = '.';
}
