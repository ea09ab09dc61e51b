/*
 * schema_check.c: whether a file's schema is the one Facet's own
 * migrations make (store_schema_check, store_internal.h). The expectation
 * is not listed here: it is built in a private in-memory database from
 * the script of the file's version, which the build wrote by running the
 * same migrations (schema.c, store_schema_scripts), and the two are
 * compared through SQLite's own description of them (sqlite_schema and
 * the table pragmas). Replaying the migrations here instead cost every
 * process that opens a file 16 migrations, each ALTER TABLE of which has
 * SQLite parse the whole schema again: nearly all of `facet runs`.
 */
#include "store_internal.h"

#include <assert.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* One column as a line of text: its name, then its type and every
 * property the table pragmas give (NOT NULL, default, key, hidden or
 * generated), so that two columns compare as two strings. */
struct column_text {
    char name[64];
    char text[200];
};

/* What one column is, from a row of pragma_table_xinfo. */
static const char column_sql[] =
    "SELECT name, type || CASE WHEN \"notnull\" THEN ' NOT NULL' ELSE ''"
    " END || coalesce(' DEFAULT ' || dflt_value, '')"
    " || CASE WHEN pk THEN ' KEY ' || pk ELSE '' END"
    " || CASE hidden WHEN 0 THEN '' ELSE ' HIDDEN ' || hidden END"
    " FROM pragma_table_xinfo(?1) ORDER BY cid";

/* The keys it refers by, and the table's kind (WITHOUT ROWID, STRICT):
 * one line of text. */
static const char table_sql[] =
    "SELECT (SELECT group_concat(k, '; ') FROM (SELECT \"table\" || '('"
    " || coalesce(\"to\", '') || ') ' || \"from\" || ' ' || on_update"
    " || ' ' || on_delete AS k FROM pragma_foreign_key_list(?1)"
    " ORDER BY id, seq)), (SELECT wr || ' ' || strict FROM pragma_table_list"
    " WHERE schema = 'main' AND name = ?1)";

/* Reads the columns of table (at most most of them) into cols, *n. */
static int read_columns(struct store *store, const char *table,
                        struct column_text *cols, int most, int *n,
                        struct facet_error *err)
{
    sqlite3_stmt *s;
    int rc = store_prepare(store, column_sql, &s, "checking the schema",
                           err);
    if (rc != FACET_OK)
        return rc;
    sqlite3_bind_text(s, 1, table, -1, SQLITE_TRANSIENT);
    int step = SQLITE_DONE;
    *n = 0;
    while ((step = sqlite3_step(s)) == SQLITE_ROW && *n < most) {
        const char *name = (const char *)sqlite3_column_text(s, 0);
        const char *text = (const char *)sqlite3_column_text(s, 1);
        snprintf(cols[*n].name, sizeof cols[*n].name, "%s",
                 name ? name : "");
        snprintf(cols[*n].text, sizeof cols[*n].text, "%s",
                 text ? text : "");
        (*n)++;
    }
    if (step != SQLITE_ROW && step != SQLITE_DONE)
        rc = store_fail(store, "checking the schema", err);
    sqlite3_finalize(s);
    return rc;
}

/* The keys and kind of table as one line into out (table_sql). */
static int read_table(struct store *store, const char *table, char *out,
                      size_t size, struct facet_error *err)
{
    sqlite3_stmt *s;
    int rc = store_prepare(store, table_sql, &s, "checking the schema", err);
    if (rc != FACET_OK)
        return rc;
    sqlite3_bind_text(s, 1, table, -1, SQLITE_TRANSIENT);
    if (sqlite3_step(s) == SQLITE_ROW) {
        const char *keys = (const char *)sqlite3_column_text(s, 0);
        const char *kind = (const char *)sqlite3_column_text(s, 1);
        snprintf(out, size, "%s | %s", keys ? keys : "",
                 kind ? kind : "");
    } else {
        rc = store_fail(store, "checking the schema", err);
    }
    sqlite3_finalize(s);
    return rc;
}

/* The index of the column named name in cols[0..n), or -1. */
static int find_column(const struct column_text *cols, int n,
                       const char *name)
{
    for (int k = 0; k < n; k++)
        if (sqlite3_stricmp(cols[k].name, name) == 0)
            return k;
    return -1;
}

/* Looks up the entry of store's schema named name (any case, as SQLite
 * resolves names): its type into type ("" when none) and its SQL into
 * *sql (malloc'ed; NULL when none). */
static int schema_entry(struct store *store, const char *name, char *type,
                        size_t type_size, char **sql,
                        struct facet_error *err)
{
    sqlite3_stmt *s;
    int rc = store_prepare(store, "SELECT type, coalesce(sql, '') FROM"
                           " sqlite_schema WHERE name = ?1 COLLATE NOCASE",
                           &s, "checking the schema", err);
    if (rc != FACET_OK)
        return rc;
    sqlite3_bind_text(s, 1, name, -1, SQLITE_TRANSIENT);
    type[0] = '\0';
    *sql = NULL;
    if (sqlite3_step(s) == SQLITE_ROW) {
        const char *kind = (const char *)sqlite3_column_text(s, 0);
        snprintf(type, type_size, "%s", kind ? kind : "");
        const char *text = (const char *)sqlite3_column_text(s, 1);
        *sql = strdup(text ? text : "");
        if (*sql == NULL)
            rc = facet_error_set(err, FACET_EWORK, "out of memory");
    }
    sqlite3_finalize(s);
    return rc;
}

/* An index of the user's own on one of Facet's tables is let be, as
 * long as Facet's writes run none of its SQL: an index on an expression
 * or with a WHERE (Facet makes neither) is refused. */
static int check_indexes(struct store *store, const char *table,
                         struct facet_error *err)
{
    sqlite3_stmt *s;
    int rc = store_prepare(store, "SELECT il.name FROM pragma_index_list(?1)"
                           " AS il WHERE il.partial OR EXISTS (SELECT 1 FROM"
                           " pragma_index_xinfo(il.name) WHERE cid = -2)"
                           " LIMIT 1", &s, "checking the schema", err);
    if (rc != FACET_OK)
        return rc;
    sqlite3_bind_text(s, 1, table, -1, SQLITE_TRANSIENT);
    int step = sqlite3_step(s);
    if (step == SQLITE_ROW)
        rc = facet_error_set(err, FACET_EINPUT,
            "%s: holds index '%.60s' on %s, on an expression or with a "
            "WHERE, which Facet never makes: the file's own SQL is not run; "
            "the file is not opened", store->path,
            (const char *)sqlite3_column_text(s, 0), table);
    else if (step != SQLITE_DONE)
        rc = store_fail(store, "checking the schema", err);
    sqlite3_finalize(s);
    return rc;
}

/* The most columns a table of Facet's has, with room to spare: a table
 * wider than this is not Facet's anyway. */
#define COLUMNS_MOST 256

/* Compares Facet's table name (of the schema at version) in the file
 * with its twin in expected. */
static int check_table(struct store *store, struct store *expected,
                       const char *name, int version,
                       struct facet_error *err)
{
    struct column_text *want = calloc(2 * COLUMNS_MOST, sizeof *want);
    if (want == NULL)
        return facet_error_set(err, FACET_EWORK, "out of memory");
    struct column_text *have = want + COLUMNS_MOST;
    int nwant = 0, nhave = 0;
    int rc = read_columns(expected, name, want, COLUMNS_MOST, &nwant, err);
    if (rc == FACET_OK)
        rc = read_columns(store, name, have, COLUMNS_MOST, &nhave, err);
    for (int k = 0; rc == FACET_OK && k < nwant; k++) {
        int at = find_column(have, nhave, want[k].name);
        if (at < 0)
            rc = facet_error_set(err, FACET_EINPUT,
                "%s: table %s has no column %s, which Facet's schema %d "
                "has: the file was altered; it is not opened", store->path,
                name, want[k].name, version);
        else if (strcmp(have[at].text, want[k].text) != 0)
            rc = facet_error_set(err, FACET_EINPUT,
                "%s: column %s.%s is '%.80s' where Facet's schema %d has "
                "'%.80s': the file was altered; it is not opened",
                store->path, name, want[k].name, have[at].text, version,
                want[k].text);
        else if (at != k)
            rc = facet_error_set(err, FACET_EINPUT,
                "%s: the columns of table %s are not in the order of "
                "Facet's schema %d (%s is column %d, not %d): the file was "
                "altered; it is not opened", store->path, name, version,
                want[k].name, at + 1, k + 1);
    }
    if (rc == FACET_OK && nhave != nwant)
        rc = facet_error_set(err, FACET_EINPUT,
            "%s: table %s has a column %.60s that Facet's schema %d has "
            "not: the file was altered; it is not opened", store->path, name,
            nhave > nwant ? have[nwant].name : "?", version);
    free(want);
    char want_keys[1024], have_keys[1024];
    if (rc == FACET_OK)
        rc = read_table(expected, name, want_keys, sizeof want_keys, err);
    if (rc == FACET_OK)
        rc = read_table(store, name, have_keys, sizeof have_keys, err);
    if (rc == FACET_OK && strcmp(want_keys, have_keys) != 0)
        rc = facet_error_set(err, FACET_EINPUT,
            "%s: table %s's keys or kind (%.120s) are not those of Facet's "
            "schema %d (%.120s): the file was altered; it is not opened",
            store->path, name, have_keys, version, want_keys);
    /* What the pragmas do not show (a CHECK, a collation, a generated
     * column's expression) is in the declaration: Facet's own is the
     * text its migrations leave (an ALTER TABLE adds to it, and a DROP
     * COLUMN takes it back out, word for word). */
    char type[16];
    char *want_sql = NULL, *have_sql = NULL;
    if (rc == FACET_OK)
        rc = schema_entry(expected, name, type, sizeof type, &want_sql, err);
    if (rc == FACET_OK)
        rc = schema_entry(store, name, type, sizeof type, &have_sql, err);
    if (rc == FACET_OK && (want_sql == NULL || have_sql == NULL ||
                           strcmp(want_sql, have_sql) != 0))
        rc = facet_error_set(err, FACET_EINPUT,
            "%s: table %s is not declared as Facet's schema %d declares it "
            "(a constraint, collation or generated column of the file's "
            "own): the file was altered; it is not opened", store->path,
            name, version);
    free(want_sql);
    free(have_sql);
    if (rc == FACET_OK)
        rc = check_indexes(store, name, err);
    return rc;
}

/* Checks one entry of the file's sqlite_schema, of a type that is never
 * Facet's or must be Facet's word for word: a trigger is never Facet's, a
 * view must be one of Facet's as Facet wrote it, and a virtual table is
 * never Facet's. Indexes and the user's own ordinary tables are let be:
 * SQLite runs no SQL of theirs on a read, and a write runs only innocuous
 * functions (trusted_schema off). */
static int check_entry(struct store *store, struct store *expected,
                       const char *type, const char *name, const char *on,
                       const char *sql, struct facet_error *err)
{
    if (strcmp(type, "trigger") == 0)
        return facet_error_set(err, FACET_EINPUT,
            "%s: holds trigger '%.60s' on %.60s, which Facet never makes: "
            "the file's own SQL is not run; the file is not opened",
            store->path, name, on);
    if (strcmp(type, "table") == 0 &&
        sqlite3_strnicmp(sql, "CREATE VIRTUAL", 14) == 0)
        return facet_error_set(err, FACET_EINPUT,
            "%s: holds virtual table '%.60s', which Facet never makes: the "
            "file is not opened", store->path, name);
    if (strcmp(type, "view") != 0)
        return FACET_OK;
    char want_type[16];
    char *want_sql = NULL;
    int rc = schema_entry(expected, name, want_type, sizeof want_type,
                          &want_sql, err);
    if (rc == FACET_OK && strcmp(want_type, "table") == 0)
        rc = facet_error_set(err, FACET_EINPUT,
            "%s: '%.60s' is a view where Facet keeps a table: the file was "
            "altered; it is not opened", store->path, name);
    else if (rc == FACET_OK && (strcmp(want_type, "view") != 0 ||
                                strcmp(want_sql, sql) != 0))
        rc = facet_error_set(err, FACET_EINPUT,
            "%s: holds view '%.60s', which is not Facet's: the file's own "
            "SQL is not run; the file is not opened", store->path, name);
    free(want_sql);
    return rc;
}

/* check_entry on every entry of the file's schema for which the SQL
 * condition where holds. */
static int check_entries(struct store *store, struct store *expected,
                         const char *where, struct facet_error *err)
{
    char sql[300];
    snprintf(sql, sizeof sql, "SELECT coalesce(type, ''), coalesce(name, ''),"
             " coalesce(tbl_name, ''), coalesce(sql, '') FROM sqlite_schema"
             " WHERE %s ORDER BY rowid", where);
    sqlite3_stmt *s;
    int rc = store_prepare(store, sql, &s, "checking the schema", err);
    if (rc != FACET_OK)
        return rc;
    int step = SQLITE_DONE;
    while (rc == FACET_OK && (step = sqlite3_step(s)) == SQLITE_ROW)
        rc = check_entry(store, expected,
                         (const char *)sqlite3_column_text(s, 0),
                         (const char *)sqlite3_column_text(s, 1),
                         (const char *)sqlite3_column_text(s, 2),
                         (const char *)sqlite3_column_text(s, 3), err);
    if (rc == FACET_OK && step != SQLITE_DONE)
        rc = store_fail(store, "checking the schema", err);
    sqlite3_finalize(s);
    return rc;
}

/* Each of Facet's tables (those of expected) is in the file as an
 * ordinary table (a view of its name is check_entry's to name) with its
 * columns, keys and kind. */
static int check_tables(struct store *store, struct store *expected,
                        int version, struct facet_error *err)
{
    sqlite3_stmt *s;
    int rc = store_prepare(expected, "SELECT name FROM sqlite_schema"
                           " WHERE type = 'table' ORDER BY rowid", &s,
                           "checking the schema", err);
    if (rc != FACET_OK)
        return rc;
    while (rc == FACET_OK && sqlite3_step(s) == SQLITE_ROW) {
        const char *name = (const char *)sqlite3_column_text(s, 0);
        sqlite3_stmt *find;
        rc = store_prepare(store, "SELECT coalesce(type, '') FROM"
                           " sqlite_schema WHERE name = ?1 COLLATE NOCASE", &find,
                           "checking the schema", err);
        if (rc != FACET_OK)
            break;
        sqlite3_bind_text(find, 1, name, -1, SQLITE_TRANSIENT);
        int found = sqlite3_step(find) == SQLITE_ROW;
        int view = found &&
            strcmp((const char *)sqlite3_column_text(find, 0), "view") == 0;
        sqlite3_finalize(find);
        if (view)
            rc = facet_error_set(err, FACET_EINPUT,
                "%s: '%s' is a view where Facet keeps a table: the file was "
                "altered; it is not opened", store->path, name);
        else if (!found)
            rc = facet_error_set(err, FACET_EINPUT,
                "%s: table %s of Facet's schema %d is missing: the file was "
                "altered or damaged; it is not opened", store->path, name,
                version);
        else
            rc = check_table(store, expected, name, version, err);
    }
    sqlite3_finalize(s);
    return rc;
}

/* Triggers first (the SQL a file would run on its own), then virtual
 * tables, Facet's tables and last the views. */
static int compare(struct store *store, struct store *expected, int version,
                   struct facet_error *err)
{
    int rc = check_entries(store, expected, "type = 'trigger'", err);
    if (rc == FACET_OK)
        rc = check_entries(store, expected, "type = 'table'", err);
    if (rc == FACET_OK)
        rc = check_tables(store, expected, version, err);
    if (rc == FACET_OK)
        rc = check_entries(store, expected, "type = 'view'", err);
    return rc;
}

int store_schema_check(struct store *store, int version,
                       struct facet_error *err)
{
    assert(version >= 0 && version <= STORE_SCHEMA_VERSION);
    char name[] = "(Facet's own schema)";
    struct store expected = {.path = name};
    if (sqlite3_open_v2(":memory:", &expected.db, SQLITE_OPEN_READWRITE,
                        NULL) != SQLITE_OK) {
        sqlite3_close(expected.db);
        return facet_error_set(err, FACET_EWORK, "out of memory");
    }
    int rc = store_exec(&expected, "BEGIN", "building the schema", err);
    if (rc == FACET_OK)
        rc = store_exec(&expected, store_schema_scripts[version],
                        "building the schema", err);
    if (rc == FACET_OK)
        rc = store_exec(&expected, "COMMIT", "building the schema", err);
    if (rc == FACET_OK)
        rc = compare(store, &expected, version, err);
    sqlite3_close(expected.db);
    return rc;
}
