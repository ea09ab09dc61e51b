/*
 * store_shard.c: what runs record of shards and merges (schema v6), and
 * the copy a merge works on. See store.h.
 */
#include "store_internal.h"

#include <stdio.h>

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
