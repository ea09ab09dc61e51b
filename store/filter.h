/*
 * filter.h: the --where expression language over option columns.
 *
 *   cost < 1.5e6 and dp_area <= 900 or pareto
 *   (nu >= 30 or nv = 40) and not feasible
 *
 * Grammar: or-expressions of and-expressions of [not] terms; a term is a
 * comparison COLUMN OP NUMBER (OP one of < <= > >= = == != <>), a bare
 * boolean column (pareto, feasible, knee), or a parenthesised expression.
 * Keywords are case-insensitive. The same parser serves `facet options
 * --where` and the TUI's filter line. A compiled filter becomes a SQL WHERE
 * fragment with every number bound as a parameter: the user's text is never
 * pasted into SQL. A bad expression is FACET_EINPUT with a message that
 * points at the column (1-based character position) of the mistake.
 */
#ifndef FACET_FILTER_H
#define FACET_FILTER_H

#include "core/error.h"

struct filter;

/* Compiles text into *out (caller-owned, released with filter_free).
 * Returns FACET_OK or FACET_EINPUT ("--where: column 12: unknown column
 * 'dp_aera' (did you mean dp_area?)"). */
int filter_compile(const char *text, struct filter **out,
                   struct facet_error *err);
void filter_free(struct filter *filter);

/* The expression as Facet understood it, fully parenthesised (for
 * messages and the TUI's status line). */
const char *filter_text(const struct filter *filter);

#endif
