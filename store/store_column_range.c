/*
 * store_column_range.c: the extent of one option column over a whole run,
 * read from the ends of the column's index (the parallel coordinates'
 * axes, beside the browsing of store_browse.c).
 * See store.h.
 */
#include "store_internal.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* The value at one end of column's order over run's options (NULLs left
 * out) into *value, NaN when there is none. column is checked by the
 * caller. */
static int column_end(struct store *store, int64_t run, const char *column,
                      int descending, double *value, struct facet_error *err)
{
    char sql[256];
    snprintf(sql, sizeof sql,
             "SELECT \"%s\" FROM options WHERE run = ?1 AND \"%s\" IS NOT "
             "NULL ORDER BY \"%s\" %s LIMIT 1", column, column, column,
             descending ? "DESC" : "ASC");
    sqlite3_stmt *stmt;
    int rc = store_prepare(store, sql, &stmt, "measuring options", err);
    if (rc != FACET_OK)
        return rc;
    sqlite3_bind_int64(stmt, 1, run);
    *value = NAN;
    int step = sqlite3_step(stmt);
    if (step == SQLITE_ROW)
        *value = sqlite3_column_double(stmt, 0);
    sqlite3_finalize(stmt);
    if (step != SQLITE_ROW && step != SQLITE_DONE)
        return store_fail(store, "measuring options", err);
    return FACET_OK;
}

int store_run_column_range(struct store *store, int64_t run,
                           const char *column, double *min, double *max,
                           struct facet_error *err)
{
    *min = *max = NAN;
    int known = 0;
    for (int k = 0; k < OPTION_QUANTITIES; k++)
        if (strcmp(option_quantities[k].name, "run") != 0 &&
            strcmp(option_quantities[k].name, column) == 0)
            known = 1;
    if (!known)
        return facet_error_set(err, FACET_EINPUT, "unknown column '%s'",
                               column);
    int rc = column_end(store, run, column, 0, min, err);
    if (rc == FACET_OK)
        rc = column_end(store, run, column, 1, max, err);
    return rc;
}
