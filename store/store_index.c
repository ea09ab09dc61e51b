/*
 * store_index.c: the options table's indexes by metric, dropped while a
 * run stores many options and built again, from the whole table at once,
 * when it ends. See store.h ("a run of many options").
 *
 * Why: each of these indexes takes an option at a place its metric
 * chooses, so every option stored touches thirteen B-trees at random
 * pages, and every commit writes all those pages to the WAL: a million
 * options went in at about 5,000 a second, an eighth the rate of the
 * table alone. CREATE INDEX sorts the table's keys and writes each index
 * once, in order. The index by rank stays: a run stores its options
 * unranked (rank NULL), in number order, so it only appends.
 *
 * A run's file always ends with its indexes: the writer that dropped them
 * builds them when its run ends, however it ends (done, stopped, failed);
 * a writer killed before leaves its run "running" with a writer that is
 * gone, and the next writer to open the file (store_open) builds them
 * when it marks that run interrupted. While they are missing every query
 * gives the same rows, the planner reading the table instead.
 */
#include "store_internal.h"

#include <stdio.h>

/* The indexes by metric of the current schema (schema.c creates them,
 * version by version; test_store checks that this list is every index of
 * the options table but options_by_rank). */
static const struct {
    const char *name;
    const char *columns;
} metric_indexes[] = {
    {"options_by_cost", "run, cost"},
    {"options_by_planarity", "run, planarity"},
    {"options_by_dp_area", "run, dp_area"},
    {"options_by_fp_area", "run, fp_area"},
    {"options_by_sp_area", "run, sp_area"},
    {"options_by_nu", "run, nu"},
    {"options_by_nv", "run, nv"},
    {"options_by_threshold", "run, threshold_mm"},
    {"options_by_moulds", "run, moulds"},
    {"options_by_joint_length", "run, joint_length"},
    {"options_by_max_gap", "run, max_gap"},
    {"options_by_max_kink", "run, max_kink"},
    {"options_by_sp_misfits", "run, sp_misfits"},
};

#define METRIC_INDEXES (sizeof metric_indexes / sizeof metric_indexes[0])

const char *store_metric_index_name(size_t k)
{
    return k < METRIC_INDEXES ? metric_indexes[k].name : NULL;
}

/* One integer from sql (no parameters but ?1 = number, when given). */
static int query_int(struct store *store, const char *sql, int64_t number,
                     int64_t *value, const char *doing,
                     struct facet_error *err)
{
    sqlite3_stmt *stmt;
    int rc = store_prepare(store, sql, &stmt, doing, err);
    if (rc != FACET_OK)
        return rc;
    sqlite3_bind_int64(stmt, 1, number);
    if (sqlite3_step(stmt) == SQLITE_ROW)
        *value = sqlite3_column_int64(stmt, 0);
    else
        rc = store_fail(store, doing, err);
    sqlite3_finalize(stmt);
    return rc;
}

/* How many of the indexes by metric the file has. */
static int indexes_present(struct store *store, int64_t *present,
                           struct facet_error *err)
{
    char sql[1024];
    size_t len = (size_t)snprintf(sql, sizeof sql,
        "SELECT count(*) FROM sqlite_schema WHERE type = 'index'"
        " AND tbl_name = 'options' AND name IN (");
    for (size_t k = 0; k < METRIC_INDEXES; k++)
        len += (size_t)snprintf(sql + len, sizeof sql - len, "%s'%s'",
                                k ? ", " : "", metric_indexes[k].name);
    snprintf(sql + len, sizeof sql - len, ")");
    return query_int(store, sql, 0, present, "reading the schema", err);
}

int store_indexes_defer(struct store *store, int64_t rows, int *deferred,
                        struct facet_error *err)
{
    *deferred = 0;
    if (rows < STORE_BULK_ROWS || store->read_only)
        return FACET_OK;
    /* Building them again reads the whole table: worth it only when the
     * run brings at least as many options as the file holds. */
    int64_t held = 0;
    int rc = query_int(store, "SELECT coalesce(sum(options), 0) FROM runs",
                       0, &held, "reading runs", err);
    if (rc != FACET_OK || held > rows)
        return rc;
    rc = store_exec(store, "BEGIN IMMEDIATE", "dropping indexes", err);
    for (size_t k = 0; k < METRIC_INDEXES && rc == FACET_OK; k++) {
        char sql[128];
        snprintf(sql, sizeof sql, "DROP INDEX IF EXISTS %s",
                 metric_indexes[k].name);
        rc = store_exec(store, sql, "dropping indexes", err);
    }
    if (rc == FACET_OK)
        rc = store_exec(store, "COMMIT", "dropping indexes", err);
    if (rc != FACET_OK) {
        sqlite3_exec(store->db, "ROLLBACK", NULL, NULL, NULL);
        return rc;
    }
    *deferred = 1;
    return FACET_OK;
}

int store_indexes_build(struct store *store, int64_t writing_run,
                        int *built, struct facet_error *err)
{
    if (built != NULL)
        *built = 0;
    if (store->read_only)
        return FACET_OK;
    int64_t present = 0;
    int rc = indexes_present(store, &present, err);
    if (rc != FACET_OK || present == (int64_t)METRIC_INDEXES)
        return rc;
    int live = 0;
    /* Another run's writer, still there (this process's own connections
     * included), may be storing many options with the indexes dropped,
     * and builds them when it ends. */
    struct run_info other;
    rc = store_run_live_writer(store, writing_run, &other, &live, err);
    if (rc != FACET_OK || live)
        return rc;
    /* One transaction each: the write lock is held for one sort at a
     * time (a second a million options), shorter than the busy timeout
     * of a writer or reader waiting for it. */
    for (size_t k = 0; k < METRIC_INDEXES && rc == FACET_OK; k++) {
        char sql[160];
        snprintf(sql, sizeof sql,
                 "CREATE INDEX IF NOT EXISTS %s ON options(%s)",
                 metric_indexes[k].name, metric_indexes[k].columns);
        rc = store_exec(store, sql, "building indexes", err);
    }
    if (rc == FACET_OK && built != NULL)
        *built = 1;
    return rc;
}
