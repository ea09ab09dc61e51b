/*
 * store_shard.c: what runs record of shards and merges (schema v6), and
 * the copy a merge works on. See store.h.
 */
#include "store_internal.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/base/text.h"

void store_shard_from_row(sqlite3_stmt *stmt, int col, struct run_info *run)
{
    run->shard_index = sqlite3_column_int(stmt, col++);
    run->shard_count = sqlite3_column_int(stmt, col++);
    run->shards_merged = sqlite3_column_int(stmt, col++);
}

int store_run_incomplete(const struct run_info *run)
{
    return run->shard_index == 0 && run->shard_count > 0 &&
           run->shards_merged < run->shard_count;
}

const char *store_run_status_text(const struct run_info *run, char *text,
                                  size_t size)
{
    if (store_run_incomplete(run))
        snprintf(text, size, "incomplete");
    else if (run->shard_index > 0)
        snprintf(text, size, "%s %d/%d", run_status_name(run->status),
                 run->shard_index, run->shard_count);
    else
        snprintf(text, size, "%s", run_status_name(run->status));
    return text;
}

static void bind_positive_or_null(sqlite3_stmt *stmt, int col, int value)
{
    if (value > 0)
        sqlite3_bind_int(stmt, col, value);
    else
        sqlite3_bind_null(stmt, col);
}

/* The grid counts of an option (panels along u and v, or a project's
 * module indices) lie in 0..SHARD_GRID_MOST. */
#define SHARD_GRID_MOST 100000

/* Appends to sql (size bytes, *used of them taken) a WHEN clause naming
 * column when it holds what its declared type (REAL or INTEGER) and its
 * meaning cannot: another type (text 'NaN' reads as 0.0), NULL where
 * Facet writes a value, a value beyond the finite, a negative count, area,
 * cost or length, a grid out of bounds. 0 when sql is too small. */
static int add_column_test(char *sql, size_t size, size_t *used,
                           const char *column, const char *type, int notnull)
{
    const char *kinds = strcmp(type, "REAL") == 0 ? "'real', 'integer'"
                                                   : "'integer'";
    char range[200] = "";
    if (strcmp(column, "number") == 0)
        snprintf(range, sizeof range, " OR \"number\" < 1");
    else if (strcmp(column, "nu") == 0 || strcmp(column, "nv") == 0)
        snprintf(range, sizeof range, " OR \"%s\" < 0 OR \"%s\" > %d",
                 column, column, SHARD_GRID_MOST);
    else if (strstr(column, "count") || strstr(column, "area") ||
             strstr(column, "cost") || strstr(column, "length") ||
             strcmp(column, "panels") == 0 ||
             strcmp(column, "threshold_mm") == 0 ||
             strcmp(column, "planarity") == 0 ||
             strcmp(column, "max_deviation") == 0)
        snprintf(range, sizeof range, " OR \"%s\" < 0", column);
    char null_test[160] = "";
    if (notnull)
        snprintf(null_test, sizeof null_test, "\"%s\" IS NULL OR ",
                 column);
    int n = snprintf(sql + *used, size - *used,
        " WHEN %s(\"%s\" IS NOT NULL AND (typeof(\"%s\") NOT IN (%s) OR "
        "abs(\"%s\") > 1.7976931348623157e308%s)) THEN '%s'",
        null_test, column, column, kinds, column, range, column);
    if (n < 0 || (size_t)n >= size - *used)
        return 0;
    *used += (size_t)n;
    return 1;
}

/* Names into column (size bytes) the first column of option number's row
 * of run that holds what it cannot, "" when none: one scan of the run. */
static int first_bad_value(struct store *store, int64_t run,
                           int64_t *number, char *column, size_t size,
                           struct facet_error *err)
{
    column[0] = '\0';
    /* The shard's own table describes Facet's declared one: the open
     * compared it with the schema Facet's migrations build
     * (store_schema_check), types and NOT NULL included, so a table
     * rebuilt without NOT NULL to hide a NULL was refused before this. */
    sqlite3_stmt *info;
    int rc = store_prepare(store, "SELECT name, upper(type), \"notnull\""
                           " FROM pragma_table_info('options')"
                           " WHERE name <> 'run'", &info,
                           "checking a shard", err);
    if (rc != FACET_OK)
        return rc;
    size_t most = 64 * 1024, used = 0;
    char *sql = malloc(most);
    if (sql == NULL) {
        sqlite3_finalize(info);
        return facet_error_set(err, FACET_EWORK, "out of memory");
    }
    used = (size_t)snprintf(sql, most, "SELECT number, CASE");
    int fits = 1, step;
    while (fits && (step = sqlite3_step(info)) == SQLITE_ROW)
        fits = add_column_test(sql, most, &used,
                               (const char *)sqlite3_column_text(info, 0),
                               (const char *)sqlite3_column_text(info, 1),
                               sqlite3_column_int(info, 2));
    sqlite3_finalize(info);
    /* The clauses are of Facet's own schema: a table too wide for them
     * is not Facet's. */
    if (fits && (size_t)snprintf(sql + used, most - used,
                                 " END AS bad FROM options WHERE run = ?1"
                                 " AND bad IS NOT NULL LIMIT 1") <
                    most - used) {
        sqlite3_stmt *s;
        rc = store_prepare(store, sql, &s, "checking a shard", err);
        if (rc == FACET_OK) {
            sqlite3_bind_int64(s, 1, run);
            step = sqlite3_step(s);
            if (step == SQLITE_ROW) {
                *number = sqlite3_column_int64(s, 0);
                snprintf(column, size, "%s",
                         (const char *)sqlite3_column_text(s, 1));
            } else if (step != SQLITE_DONE) {
                rc = store_fail(store, "checking a shard", err);
            }
            sqlite3_finalize(s);
        }
    } else {
        rc = facet_error_set(err, FACET_EINPUT, "%s: its options table is "
                             "not Facet's", store->path);
    }
    free(sql);
    return rc;
}

int store_shard_check(struct store *store, const struct run_info *run,
                      struct facet_error *err)
{
    if (run->shard_index < 1 || run->shard_count < 1 ||
        run->shard_index > run->shard_count)
        return facet_error_set(err, FACET_EINPUT,
            "%s: shard %d of %d is no shard of a run (I/N with 1 <= I <= N):"
            " the file was altered; make the shard again", store->path,
            run->shard_index, run->shard_count);
    int64_t held = -1;
    sqlite3_stmt *count;
    int rc = store_prepare(store, "SELECT count(*) FROM options WHERE run = ?1",
                           &count, "checking a shard", err);
    if (rc != FACET_OK)
        return rc;
    sqlite3_bind_int64(count, 1, run->id);
    if (sqlite3_step(count) == SQLITE_ROW)
        held = sqlite3_column_int64(count, 0);
    else
        rc = store_fail(store, "checking a shard", err);
    sqlite3_finalize(count);
    if (rc == FACET_OK && held != run->options)
        rc = facet_error_set(err, FACET_EINPUT,
            "%s: shard %d/%d holds %lld options, and its run recorded %lld:"
            " the file was altered; make the shard again", store->path,
            run->shard_index, run->shard_count, (long long)held,
            (long long)run->options);
    int64_t number = 0;
    char column[64];
    if (rc == FACET_OK)
        rc = first_bad_value(store, run->id, &number, column, sizeof column,
                             err);
    if (rc == FACET_OK && column[0] != '\0') {
        char value[64] = "?";
        sqlite3_stmt *s;
        char sql[200];
        snprintf(sql, sizeof sql, "SELECT substr(quote(\"%s\"), 1, 40) FROM"
                 " options WHERE run = ?1 AND number = ?2", column);
        if (store_prepare(store, sql, &s, "checking a shard", err) ==
            FACET_OK) {
            sqlite3_bind_int64(s, 1, run->id);
            sqlite3_bind_int64(s, 2, number);
            if (sqlite3_step(s) == SQLITE_ROW)
                text_for_terminal((const char *)sqlite3_column_text(s, 0),
                                  value, sizeof value);
            sqlite3_finalize(s);
        }
        rc = facet_error_set(err, FACET_EINPUT,
            "%s: shard %d/%d, option %lld: %s is %s, which Facet never "
            "writes there: the file was altered; make the shard again",
            store->path, run->shard_index, run->shard_count,
            (long long)number, column, value);
    }
    return rc;
}

int store_run_set_shard(struct store *store, const struct run_info *run,
                        struct facet_error *err)
{
    sqlite3_stmt *s;
    int rc = store_prepare(store,
        "UPDATE runs SET shard_index = ?2, shard_count = ?3,"
        " shards_merged = ?4, warnings = ?5 WHERE id = ?1", &s,
        "recording a run's shards", err);
    if (rc != FACET_OK)
        return rc;
    sqlite3_bind_int64(s, 1, run->id);
    bind_positive_or_null(s, 2, run->shard_index);
    bind_positive_or_null(s, 3, run->shard_count);
    bind_positive_or_null(s, 4, run->shards_merged);
    sqlite3_bind_text(s, 5, run->warnings, -1, SQLITE_TRANSIENT);
    if (sqlite3_step(s) != SQLITE_DONE)
        rc = store_fail(store, "recording a run's shards", err);
    sqlite3_finalize(s);
    return rc;
}

int store_run_clear_options(struct store *store, int64_t run,
                            struct facet_error *err)
{
    sqlite3_stmt *s;
    int rc = store_prepare(store, "DELETE FROM options WHERE run = ?1", &s,
                           "emptying a run", err);
    if (rc != FACET_OK)
        return rc;
    sqlite3_bind_int64(s, 1, run);
    if (sqlite3_step(s) != SQLITE_DONE)
        rc = store_fail(store, "emptying a run", err);
    sqlite3_finalize(s);
    return rc;
}

int store_copy(struct store *store, const char *path,
               struct facet_error *err)
{
    sqlite3_stmt *s;
    int rc = store_prepare(store, "VACUUM INTO ?1", &s, "copying", err);
    if (rc != FACET_OK)
        return rc;
    sqlite3_bind_text(s, 1, path, -1, SQLITE_TRANSIENT);
    if (sqlite3_step(s) != SQLITE_DONE)
        rc = store_fail(store, "copying", err);
    sqlite3_finalize(s);
    return rc;
}
