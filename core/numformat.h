/*
 * numformat.h: numbers as a facade engineer reads them in tables, labels
 * and schedules: "1,551,317.25". The one formatter of grouped numbers for
 * the CLI, the TUI and the SVG writers.
 */
#ifndef FACET_NUMFORMAT_H
#define FACET_NUMFORMAT_H

#include <stddef.h>

/* Writes value with decimals places and its thousands grouped by commas
 * into out (size bytes, always terminated): 1481515.2 with 0 decimals is
 * "1,481,515". A value that rounds to zero has no minus sign; NaN is "-",
 * infinities "inf" and "-inf". */
void number_grouped(char *out, size_t size, double value, int decimals);

#endif
