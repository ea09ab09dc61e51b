/*
 * filter_oracle.h: SQLite as the oracle of the --where language, shared by
 * test_filter (random expressions) and fuzz_where (the fuzzer's inputs).
 *
 * A table of pseudo-random options, stored as the store keeps them (rank
 * NULL until ranked, crowding NULL at a front's ends and before ranking,
 * NaN metrics as NULL), is filtered twice: by SQLite through filter_sql
 * (and its scan form) and by Facet's own evaluator, filter_match. They
 * must select the same options.
 *
 * Test support, not part of Facet: tests/ links it, the binary does not.
 */
#ifndef FACET_FILTER_ORACLE_H
#define FACET_FILTER_ORACLE_H

#include <sqlite3.h>
#include <stddef.h>

#include "core/base/rng.h"
#include "store/filter.h"
#include "store/store.h"

/* An option as the value callback sees it: one double per column of
 * option_quantities, NaN for NULL. */
struct oracle_row {
    double v[OPTION_QUANTITIES];
};

/* The index of a column of option_quantities, or -1. */
int oracle_column(const char *name);

/* The value callback of filter_match over a struct oracle_row (context):
 * NaN for a name that is not a column (callers that must catch those
 * check oracle_column themselves). */
double oracle_value(void *context, const char *column);

/* Fills rows[0..n) with pseudo-random options whose values repeat often
 * enough for = and != to matter, with NULLs in a few metrics, infinite
 * crowding, unranked options, two knees, three runs. */
void oracle_random_rows(struct rng *rng, struct oracle_row *rows, int n);

/* An in-memory database with an options table of rows[0..n), as the
 * store keeps them. NULL when SQLite fails. Close with sqlite3_close. */
sqlite3 *oracle_database(const struct oracle_row *rows, int n);

/* Runs filter f through SQLite (WHERE and the scan form) and through
 * filter_match over rows[0..n) of db. Returns the number of options
 * matched, or -1 with why (size bytes) saying where they differ. */
int oracle_compare(sqlite3 *db, const struct oracle_row *rows, int n,
                   const struct filter *f, char *why, size_t size);

/* oracle_compare with the filter's parameters numbered from first_param:
 * 1, or 3 behind a WHERE of the caller's own (?1 and ?2, both 0). */
int oracle_compare_from(sqlite3 *db, const struct oracle_row *rows, int n,
                        const struct filter *f, int first_param, char *why,
                        size_t size);

#endif
