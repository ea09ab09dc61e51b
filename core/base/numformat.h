/*
 * numformat.h: numbers as a facade engineer reads them in tables, labels
 * and schedules: "1,551,317.25", the one formatter of grouped numbers for
 * the CLI, the TUI and the SVG writers; and numbers as a program reads
 * them back: the shortest text that parses to the same double, the one
 * form of every double in --json and --csv output.
 */
#ifndef FACET_NUMFORMAT_H
#define FACET_NUMFORMAT_H

#include <stddef.h>

/* Writes value with decimals places and its thousands grouped by commas
 * into out (size bytes, always terminated): 1481515.2 with 0 decimals is
 * "1,481,515". A value that rounds to zero has no minus sign; NaN is "-",
 * infinities "inf" and "-inf". */
void number_grouped(char *out, size_t size, double value, int decimals);

/* The longest text number_exact writes, with its terminator. */
#define NUMBER_EXACT_SIZE 32

/* Writes the finite value as the shortest of %.15g, %.16g and %.17g that
 * reads back (strtod) as the same double, bit for bit, with '.' as the
 * decimal point whatever LC_NUMERIC says: 0.1 is "0.1", 0.1 + 0.2
 * "0.30000000000000004". -0 is "-0". Non-finite values are written as
 * "nan", "inf" or "-inf"; callers whose format has no such words (JSON)
 * test isfinite first. */
void number_exact(char out[NUMBER_EXACT_SIZE], double value);

#endif
