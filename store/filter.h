/*
 * filter.h: the --where expression language over option columns.
 *
 *   cost < 1.5e6 and dp_area <= 900 or pareto
 *   (nu >= 30 or nv = 40) and not feasible
 *
 * Grammar: or-expressions of and-expressions of [not] terms; a term is a
 * comparison COLUMN OP NUMBER (OP one of < <= > >= = == != <>) or NUMBER
 * OP COLUMN, a bare boolean column (pareto, feasible, knee), or a
 * parenthesised expression. Keywords and column names are case-insensitive;
 * && || ! are and, or, not; u, v and threshold are nu, nv and threshold_mm;
 * pareto is rank = 1. A number is decimal with an optional exponent (1.5e6)
 * or a k/M suffix (1.5M); NaN and infinity are not numbers here. The same
 * parser serves `facet options --where` and the TUI's filter line. A
 * compiled filter becomes a SQL WHERE fragment with every number bound as
 * a parameter (filter_sql.h): the user's text is never pasted into SQL. A bad expression is FACET_EINPUT with a message that
 * points at the column (1-based character position) of the mistake.
 */
#ifndef FACET_FILTER_H
#define FACET_FILTER_H

#include <stddef.h>

#include "core/base/error.h"

struct filter;

/* Limits that keep hostile text from costing much: longer text, or more
 * nested parentheses and nots, is FACET_EINPUT. */
enum {
    FILTER_MAX_LENGTH = 4096,  /* bytes of text */
    FILTER_MAX_DEPTH = 24      /* '(' and 'not' open at once: the SQL
                                  of any filter that deep still fits
                                  SQLite's parser stack (an or-and chain
                                  overflows it past 30 levels) */
};

/* Compiles text into *out (caller-owned, released with filter_free).
 * Empty or all-blank text (or NULL) compiles to a filter matching every
 * option. Returns FACET_OK; FACET_EINPUT ("column 12: unknown column
 * 'dp_aera' (did you mean dp_area?)", about FACET_SETTING_FILTER: each
 * front-end says which of its fields it is), the column being the 1-based
 * character (UTF-8 code point) position of the mistake; or FACET_EWORK
 * when out of memory. *out is NULL on failure. */
int filter_compile(const char *text, struct filter **out,
                   struct facet_error *err);
void filter_free(struct filter *filter);  /* NULL is fine */

/* The expression as Facet understood it, fully parenthesised, with
 * canonical lowercase column names, aliases resolved and every comparison
 * written COLUMN OP NUMBER (for messages and the TUI's status line):
 * "((cost < 1500000) and (dp_area <= 900)) or pareto". "" for the empty
 * filter. Owned by the filter. Compiling it again gives the same filter. */
const char *filter_text(const struct filter *filter);

/* Whether an option with these column values matches. value(context,
 * column) returns the value of the named column of option_quantities
 * (lowercase, as in store.h) as a double, booleans 0/1. A NaN value stands
 * for SQL NULL and is unknown, exactly as in the SQL of filter_sql.h: a
 * comparison with it is unknown, not unknown is unknown, and an option
 * matches only when the whole expression is true. A NULL filter matches
 * everything. */
int filter_match(const struct filter *filter,
                 double (*value)(void *context, const char *column),
                 void *context);

/* The k-th word the language knows besides the columns of
 * option_quantities (its other names for columns, pareto, and, or, not),
 * for k from 0; NULL past the last. What a shell's completion offers
 * (cli/completion.h). */
const char *filter_word(size_t k);

#endif
