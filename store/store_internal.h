/*
 * store_internal.h: what the store's own files share (internal to store/): the
 * open database and the helpers that turn SQLite's result codes into
 * Facet's one-line errors. Nothing outside store/ includes this header.
 */
#ifndef FACET_STORE_INTERNAL_H
#define FACET_STORE_INTERNAL_H

#include <sqlite3.h>

#include "store.h"

/* The schema this Facet writes (PRAGMA user_version) and the
 * application_id that marks a file as Facet's: "FCET". */
#define STORE_SCHEMA_VERSION 16
#define STORE_APPLICATION_ID 0x46434554

struct store {
    sqlite3 *db;
    char *path;                 /* owned copy, for messages */
    sqlite3_stmt *option_insert;/* prepared once, reused by every batch */
    sqlite3_stmt *held_insert;  /* its option_held row, likewise */
    sqlite3_stmt *option_get;   /* store_option_get's, prepared once */
    int read_only;              /* opened by store_open_read */
};

/* Whether the process that wrote a run is gone (same host, no such
 * pid): a run left "running" by it reads as interrupted. */
int store_run_writer_gone(int64_t pid, const char *host);

/* The SQL that reads the crowding column as an option_row holds it:
 * NULL at a front's ends, where it is infinite, reads as +infinity
 * (SQLite's 1e999) in a ranked option and as 0 in one not ranked yet.
 * Sorting, filtering and paging all compare crowding through it. */
extern const char store_crowding_sql[];

/* The SQL that reads the rank column as an option_row holds it: NULL
 * until the run is ranked, read as 0. */
extern const char store_rank_sql[];

/* The SQL that is 1 for a feasible option and 0 for any other (an
 * infeasible one, or one not measured yet: NULL), as an option_row's
 * totals.feasible reads: the leading key of a feasible-first order,
 * descending. */
extern const char store_feasible_sql[];

/* Fills err from the connection's last error: "FILE: what (while DOING)".
 * A corrupt or non-database file is FACET_EINPUT (the user can act on it),
 * anything else FACET_EWORK. Returns the code. */
int store_fail(struct store *store, const char *doing,
               struct facet_error *err);

/* Runs sql (no parameters, no rows wanted). */
int store_exec(struct store *store, const char *sql, const char *doing,
               struct facet_error *err);

/* The one integer sql (a pragma, a count) gives, into *value; reading
 * no row fills err. */
int store_pragma_int(struct store *store, const char *sql, int *value,
                     struct facet_error *err);

/* Prepares sql; on failure fills err. */
int store_prepare(struct store *store, const char *sql, sqlite3_stmt **out,
                  const char *doing, struct facet_error *err);

/* Binds value to parameter col, or NULL when it is not finite (SQL has
 * no NaN or infinity). */
void store_bind_or_null(sqlite3_stmt *stmt, int col, double value);

/* Column col of the current row, NaN when it is NULL. */
double store_column_or_nan(sqlite3_stmt *stmt, int col);

struct quantity;

/* Binds the value of quantity q held at field (its type q->field) to
 * parameter col: a double as is (NaN, not measured, is NULL), or in mm
 * or degrees for a gap or kink (quantity_stored), a count of
 * TOTALS_UNKNOWN as NULL. */
void store_bind_quantity(sqlite3_stmt *stmt, int col, const struct quantity *q,
                         const void *field);

/* The names of the quantities option_held keeps as core holds them (m,
 * rad: quantity.h's quantity_stored), each after ", ", into sql (size
 * bytes); per_surface: only those option_surface_held keeps. Returns how
 * many. store_bind_held binds t's values of them to parameters p... */
int store_held_columns(char *sql, size_t size, int per_surface);
void store_bind_held(sqlite3_stmt *stmt, int p,
                     const struct option_totals *t, int per_surface);

/* The SELECT expression of quantity q (kept in mm or degrees, with its
 * value as core holds it in held: option_held or option_surface_held,
 * whose row is the one where match holds, e.g. "h.run = options.run AND
 * h.option = options.number") into sql (size bytes): the held value, or
 * where that row is missing (deleted in sqlite3's shell, whose foreign
 * keys are off) the column of table converted back, the nearest double
 * to it rather than a 'not measured' beside a number the column has. */
void store_held_sql(char *sql, size_t size, const struct quantity *q,
                    const char *held, const char *match, const char *table);
/* Its SQL from mm and from degrees (schema.c, beside v16's migration). */
extern const char store_held_from_mm_sql[];
extern const char store_held_from_deg_sql[];

/* Reads result column col into field as q holds it: NULL is NaN for a
 * double and TOTALS_UNKNOWN for a count (not measured, or a column added
 * after the row was stored; never 0). */
void store_read_quantity(sqlite3_stmt *stmt, int col, const struct quantity *q,
                         void *field);

/* Brings a database at schema version `from` (0 = empty) up to `to`,
 * one migration at a time, each in its own transaction. */
int store_schema_migrate(struct store *store, int from, int to,
                         struct facet_error *err);

/* One entry of Facet's schema, as sqlite_schema holds it. */
struct store_schema_entry {
    const char *type;           /* "table", "index" or "view" */
    const char *name;
    const char *sql;            /* its CREATE statement */
};

/* Facet's schema of each version (0 .. STORE_SCHEMA_VERSION) as
 * store_schema_migrate leaves an empty database at it: the entries of
 * sqlite_schema (but the automatic indexes, which SQLite makes with their
 * tables) in its order, ending with one whose type is NULL. Their SQL run
 * in order on an empty database makes the same sqlite_schema. Written at
 * build time by store/tool/schema_script.c, which runs the migrations
 * ($(BUILD)/store/schema_script.c); test_store_schema compares each with
 * a replay of the migrations. */
extern const struct store_schema_entry *const
    store_schemas[STORE_SCHEMA_VERSION + 1];

/* Checks that what store's file holds besides data is Facet's schema of
 * version (0 .. STORE_SCHEMA_VERSION), as store_schema_migrate makes it:
 * no trigger, no view but Facet's own word for word, no virtual table,
 * and each of Facet's tables an ordinary table with its columns (name,
 * type, NOT NULL, default, key, in order), foreign keys and kind.
 * Indexes and other ordinary tables are let be. FACET_EINPUT with a
 * one-line message naming the file and the first difference; nothing is
 * written. The expectation is store_schemas[version]. (schema_check.c) */
int store_schema_check(struct store *store, int version,
                       struct facet_error *err);

/* The shard columns of runs (store_shard.c), read after the cost
 * columns by store_shard_from_row from result column col on. */
#define STORE_SHARD_COLUMNS \
    "coalesce(shard_index, 0), coalesce(shard_count, 0)," \
    " coalesce(shards_merged, 0)"
void store_shard_from_row(sqlite3_stmt *stmt, int col, struct run_info *run);

/* store_options_put, and with surfaces (not NULL: a project run's
 * options, nsurfaces rows each) store_project_options_put. */
int store_options_put_with(struct store *store, int64_t run,
                           const struct option_row *rows, size_t n,
                           const struct option_surface_row *surfaces,
                           size_t nsurfaces, struct facet_error *err);

/* Inserts the n surface rows of option number of run (store_project.c),
 * inside the caller's transaction. */
int store_option_surfaces_insert(struct store *store, int64_t run,
                                 int64_t number,
                                 const struct option_surface_row *rows,
                                 size_t n, struct facet_error *err);

/* The module range columns of runs (schema v8), read after the shard
 * columns by store_module_from_row from result column col on. */
#define STORE_MODULE_COLUMNS \
    "module_w_min, module_w_max, module_w_step, module_h_min," \
    " module_h_max, module_h_step"
void store_module_from_row(sqlite3_stmt *stmt, int col,
                           struct run_info *run);
/* Writes run's module range to its row. */
int store_run_set_module(struct store *store, const struct run_info *run,
                         struct facet_error *err);

/* The current UTC time as ISO 8601 ("2026-11-25T01:30:00Z"). */
void store_now(char out[32]);

#endif
