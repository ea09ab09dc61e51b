/*
 * filter_sql.h: a compiled --where filter as SQL, for store/ only.
 *
 * The store (store_browse.c, store_option.c) appends the fragment to its own WHERE clause and binds the
 * filter's numbers as parameters; no text the user typed reaches SQL (the
 * column names come from option_quantities, the numbers are bound).
 * A column that is NULL makes a comparison unknown, with SQL's usual
 * three-valued logic; filter_match (filter.h) gives the same answers.
 */
#ifndef FACET_FILTER_SQL_H
#define FACET_FILTER_SQL_H

#include <stddef.h>

#include "store/filter.h"

/* The WHERE fragment, e.g. "(\"cost\" < ?1 AND \"dp_area\" <= ?2) OR
 * (\"rank\" IS NOT NULL AND \"rank\" = 1)", over the columns of the
 * options table, which are named exactly as in option_quantities.
 * Parameters are numbered from first_param (>= 1, so the caller can bind
 * its own parameters first); every number of the user's text is a
 * parameter, never pasted. "1" for the empty filter (or NULL). Malloc'ed,
 * the caller frees; NULL when out of memory. */
char *filter_sql(const struct filter *filter, int first_param);

/* filter_sql with every column written +"column", which keeps SQLite from
 * walking an index for the filter: for counting the rows of a run through
 * its primary key. A filter that many options pass costs a read of each
 * of its rows through an index (5 s for 420,000 of a million), and 0.2 s
 * by a scan of the run. */
char *filter_sql_scan(const struct filter *filter, int first_param);

/* How many parameters the fragment has (0 for the empty filter). */
size_t filter_param_count(const struct filter *filter);

/* The value to bind to parameter first_param + k, k < filter_param_count. */
double filter_param(const struct filter *filter, size_t k);

/* What to say of word (n bytes), which names no option column, into out
 * (size bytes): "did you mean cost?" for a near name (with pareto and
 * the filter's aliases when in_filter), else the columns, the per-class
 * ones by their pattern so that the list fits one line ("columns:
 * number, ..., CLASS_{count,area}"). */
void filter_column_hint(const char *word, size_t n, int in_filter,
                        char *out, size_t size);

#endif
