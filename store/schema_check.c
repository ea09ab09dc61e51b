/*
 * schema_check.c: whether a file's schema is the one Facet's own
 * migrations make (store_schema_check, store_internal.h). The expectation
 * is not listed here: it is the entries of sqlite_schema the build wrote
 * down by running the same migrations (schema.c, store_schemas). A file
 * whose entries are Facet's word for word passes at once; any other is
 * compared with the expectation built in a private in-memory database,
 * through SQLite's own description of both (sqlite_schema and the table
 * pragmas), which names the first difference. Replaying the migrations
 * for every file instead cost each process that opened one 16 migrations,
 * each ALTER TABLE of which has SQLite parse the whole schema again:
 * nearly all of `facet runs`.
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
 * one line of text. The table list is asked for the table alone: listing
 * every table works out the columns of every view. */
static const char table_sql[] =
    "SELECT (SELECT group_concat(k, '; ') FROM (SELECT \"table\" || '('"
    " || coalesce(\"to\", '') || ') ' || \"from\" || ' ' || on_update"
    " || ' ' || on_delete AS k FROM pragma_foreign_key_list(?1)"
    " ORDER BY id, seq)), (SELECT wr || ' ' || strict FROM"
    " pragma_table_list(?1) WHERE schema = 'main' AND name = ?1)";

/* The entry of sqlite_schema named ?1 (any case, as SQLite resolves
 * names): its type and SQL. */
static const char entry_sql[] =
    "SELECT coalesce(type, ''), coalesce(sql, '') FROM sqlite_schema"
    " WHERE name = ?1 COLLATE NOCASE";

/* The entries of sqlite_schema of type ?1, in order. */
static const char entries_sql[] =
    "SELECT coalesce(type, ''), coalesce(name, ''), coalesce(tbl_name, ''),"
    " coalesce(sql, '') FROM sqlite_schema WHERE type = ?1 ORDER BY rowid";

/* The first index on table ?1 on an expression or with a WHERE. */
static const char index_sql[] =
    "SELECT il.name FROM pragma_index_list(?1) AS il WHERE il.partial OR"
    " EXISTS (SELECT 1 FROM pragma_index_xinfo(il.name) WHERE cid = -2)"
    " LIMIT 1";

/* One database the check reads (the file, or the expectation) and the
 * statements it runs on it, each prepared once and run again for every
 * table: preparing was most of the cost of these short queries. */
struct reader {
    struct store *store;
    sqlite3_stmt *columns;      /* column_sql */
    sqlite3_stmt *table;        /* table_sql */
    sqlite3_stmt *entry;        /* entry_sql */
    sqlite3_stmt *entries;      /* entries_sql */
    sqlite3_stmt *index;        /* index_sql */
};

/* *slot, prepared from sql on reader's database the first time and reset
 * after, with ?1 bound to text. */
static int reader_statement(struct reader *reader, sqlite3_stmt **slot,
                            const char *sql, const char *text,
                            struct facet_error *err)
{
    if (*slot == NULL) {
        int rc = store_prepare(reader->store, sql, slot,
                               "checking the schema", err);
        if (rc != FACET_OK)
            return rc;
    } else {
        sqlite3_reset(*slot);
    }
    sqlite3_bind_text(*slot, 1, text, -1, SQLITE_TRANSIENT);
    return FACET_OK;
}

static void reader_close(struct reader *reader)
{
    sqlite3_finalize(reader->columns);
    sqlite3_finalize(reader->table);
    sqlite3_finalize(reader->entry);
    sqlite3_finalize(reader->entries);
    sqlite3_finalize(reader->index);
}

/* Reads the columns of table (at most most of them) into cols, *n. */
static int read_columns(struct reader *reader, const char *table,
                        struct column_text *cols, int most, int *n,
                        struct facet_error *err)
{
    int rc = reader_statement(reader, &reader->columns, column_sql, table,
                              err);
    if (rc != FACET_OK)
        return rc;
    sqlite3_stmt *s = reader->columns;
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
        rc = store_fail(reader->store, "checking the schema", err);
    sqlite3_reset(s);
    return rc;
}

/* The keys and kind of table as one line into out (table_sql). */
static int read_table(struct reader *reader, const char *table, char *out,
                      size_t size, struct facet_error *err)
{
    int rc = reader_statement(reader, &reader->table, table_sql, table, err);
    if (rc != FACET_OK)
        return rc;
    sqlite3_stmt *s = reader->table;
    if (sqlite3_step(s) == SQLITE_ROW) {
        const char *keys = (const char *)sqlite3_column_text(s, 0);
        const char *kind = (const char *)sqlite3_column_text(s, 1);
        snprintf(out, size, "%s | %s", keys ? keys : "",
                 kind ? kind : "");
    } else {
        rc = store_fail(reader->store, "checking the schema", err);
    }
    sqlite3_reset(s);
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

/* Looks up the entry of reader's schema named name (any case, as SQLite
 * resolves names): its type into type ("" when none) and its SQL into
 * *sql (malloc'ed; NULL when none). */
static int schema_entry(struct reader *reader, const char *name, char *type,
                        size_t type_size, char **sql,
                        struct facet_error *err)
{
    int rc = reader_statement(reader, &reader->entry, entry_sql, name, err);
    if (rc != FACET_OK)
        return rc;
    sqlite3_stmt *s = reader->entry;
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
    sqlite3_reset(s);
    return rc;
}

/* An index of the user's own on one of Facet's tables is let be, as
 * long as Facet's writes run none of its SQL: an index on an expression
 * or with a WHERE (Facet makes neither) is refused. */
static int check_indexes(struct reader *file, const char *table,
                         struct facet_error *err)
{
    struct store *store = file->store;
    int rc = reader_statement(file, &file->index, index_sql, table, err);
    if (rc != FACET_OK)
        return rc;
    sqlite3_stmt *s = file->index;
    int step = sqlite3_step(s);
    if (step == SQLITE_ROW)
        rc = facet_error_set(err, FACET_EINPUT,
            "%s: holds index '%.60s' on %s, on an expression or with a "
            "WHERE, which Facet never makes: the file's own SQL is not run; "
            "the file is not opened", store->path,
            (const char *)sqlite3_column_text(s, 0), table);
    else if (step != SQLITE_DONE)
        rc = store_fail(store, "checking the schema", err);
    sqlite3_reset(s);
    return rc;
}

/* The most columns a table of Facet's has, with room to spare: a table
 * wider than this is not Facet's anyway. */
#define COLUMNS_MOST 256

/* Compares Facet's table name (of the schema at version) in the file
 * with its twin in expected. */
static int check_table(struct reader *file, struct reader *expected,
                       const char *name, int version,
                       struct facet_error *err)
{
    const char *path = file->store->path;
    struct column_text *want = calloc(2 * COLUMNS_MOST, sizeof *want);
    if (want == NULL)
        return facet_error_set(err, FACET_EWORK, "out of memory");
    struct column_text *have = want + COLUMNS_MOST;
    int nwant = 0, nhave = 0;
    int rc = read_columns(expected, name, want, COLUMNS_MOST, &nwant, err);
    if (rc == FACET_OK)
        rc = read_columns(file, name, have, COLUMNS_MOST, &nhave, err);
    for (int k = 0; rc == FACET_OK && k < nwant; k++) {
        int at = find_column(have, nhave, want[k].name);
        if (at < 0)
            rc = facet_error_set(err, FACET_EINPUT,
                "%s: table %s has no column %s, which Facet's schema %d "
                "has: the file was altered; it is not opened", path,
                name, want[k].name, version);
        else if (strcmp(have[at].text, want[k].text) != 0)
            rc = facet_error_set(err, FACET_EINPUT,
                "%s: column %s.%s is '%.80s' where Facet's schema %d has "
                "'%.80s': the file was altered; it is not opened",
                path, name, want[k].name, have[at].text, version,
                want[k].text);
        else if (at != k)
            rc = facet_error_set(err, FACET_EINPUT,
                "%s: the columns of table %s are not in the order of "
                "Facet's schema %d (%s is column %d, not %d): the file was "
                "altered; it is not opened", path, name, version,
                want[k].name, at + 1, k + 1);
    }
    if (rc == FACET_OK && nhave != nwant)
        rc = facet_error_set(err, FACET_EINPUT,
            "%s: table %s has a column %.60s that Facet's schema %d has "
            "not: the file was altered; it is not opened", path, name,
            nhave > nwant ? have[nwant].name : "?", version);
    free(want);
    char want_keys[1024], have_keys[1024];
    if (rc == FACET_OK)
        rc = read_table(expected, name, want_keys, sizeof want_keys, err);
    if (rc == FACET_OK)
        rc = read_table(file, name, have_keys, sizeof have_keys, err);
    if (rc == FACET_OK && strcmp(want_keys, have_keys) != 0)
        rc = facet_error_set(err, FACET_EINPUT,
            "%s: table %s's keys or kind (%.120s) are not those of Facet's "
            "schema %d (%.120s): the file was altered; it is not opened",
            path, name, have_keys, version, want_keys);
    /* What the pragmas do not show (a CHECK, a collation, a generated
     * column's expression) is in the declaration: Facet's own is the
     * text its migrations leave (an ALTER TABLE adds to it, and a DROP
     * COLUMN takes it back out, word for word). */
    char type[16];
    char *want_sql = NULL, *have_sql = NULL;
    if (rc == FACET_OK)
        rc = schema_entry(expected, name, type, sizeof type, &want_sql, err);
    if (rc == FACET_OK)
        rc = schema_entry(file, name, type, sizeof type, &have_sql, err);
    if (rc == FACET_OK && (want_sql == NULL || have_sql == NULL ||
                           strcmp(want_sql, have_sql) != 0))
        rc = facet_error_set(err, FACET_EINPUT,
            "%s: table %s is not declared as Facet's schema %d declares it "
            "(a constraint, collation or generated column of the file's "
            "own): the file was altered; it is not opened", path,
            name, version);
    free(want_sql);
    free(have_sql);
    if (rc == FACET_OK)
        rc = check_indexes(file, name, err);
    return rc;
}

/* Checks one entry of the file's sqlite_schema, of a type that is never
 * Facet's or must be Facet's word for word: a trigger is never Facet's, a
 * view must be one of Facet's as Facet wrote it, and a virtual table is
 * never Facet's. Indexes and the user's own ordinary tables are let be:
 * SQLite runs no SQL of theirs on a read, and a write runs only innocuous
 * functions (trusted_schema off). */
static int check_entry(struct reader *file, struct reader *expected,
                       const char *type, const char *name, const char *on,
                       const char *sql, struct facet_error *err)
{
    const char *path = file->store->path;
    if (strcmp(type, "trigger") == 0)
        return facet_error_set(err, FACET_EINPUT,
            "%s: holds trigger '%.60s' on %.60s, which Facet never makes: "
            "the file's own SQL is not run; the file is not opened",
            path, name, on);
    if (strcmp(type, "table") == 0 &&
        sqlite3_strnicmp(sql, "CREATE VIRTUAL", 14) == 0)
        return facet_error_set(err, FACET_EINPUT,
            "%s: holds virtual table '%.60s', which Facet never makes: the "
            "file is not opened", path, name);
    if (strcmp(type, "view") != 0)
        return FACET_OK;
    char want_type[16];
    char *want_sql = NULL;
    int rc = schema_entry(expected, name, want_type, sizeof want_type,
                          &want_sql, err);
    if (rc == FACET_OK && strcmp(want_type, "table") == 0)
        rc = facet_error_set(err, FACET_EINPUT,
            "%s: '%.60s' is a view where Facet keeps a table: the file was "
            "altered; it is not opened", path, name);
    else if (rc == FACET_OK && (strcmp(want_type, "view") != 0 ||
                                strcmp(want_sql, sql) != 0))
        rc = facet_error_set(err, FACET_EINPUT,
            "%s: holds view '%.60s', which is not Facet's: the file's own "
            "SQL is not run; the file is not opened", path, name);
    free(want_sql);
    return rc;
}

/* check_entry on every entry of the file's schema of type. */
static int check_entries(struct reader *file, struct reader *expected,
                         const char *type, struct facet_error *err)
{
    int rc = reader_statement(file, &file->entries, entries_sql, type, err);
    if (rc != FACET_OK)
        return rc;
    sqlite3_stmt *s = file->entries;
    int step = SQLITE_DONE;
    while (rc == FACET_OK && (step = sqlite3_step(s)) == SQLITE_ROW)
        rc = check_entry(file, expected,
                         (const char *)sqlite3_column_text(s, 0),
                         (const char *)sqlite3_column_text(s, 1),
                         (const char *)sqlite3_column_text(s, 2),
                         (const char *)sqlite3_column_text(s, 3), err);
    if (rc == FACET_OK && step != SQLITE_DONE)
        rc = store_fail(file->store, "checking the schema", err);
    sqlite3_reset(s);
    return rc;
}

/* Each of Facet's tables (those of expected) is in the file as an
 * ordinary table (a view of its name is check_entry's to name) with its
 * columns, keys and kind. */
static int check_tables(struct reader *file, struct reader *expected,
                        int version, struct facet_error *err)
{
    int rc = reader_statement(expected, &expected->entries, entries_sql,
                              "table", err);
    if (rc != FACET_OK)
        return rc;
    sqlite3_stmt *s = expected->entries;
    while (rc == FACET_OK && sqlite3_step(s) == SQLITE_ROW) {
        const char *name = (const char *)sqlite3_column_text(s, 1);
        char type[16];
        char *sql = NULL;
        rc = schema_entry(file, name, type, sizeof type, &sql, err);
        if (rc != FACET_OK)
            break;
        int found = sql != NULL;
        free(sql);
        if (found && strcmp(type, "view") == 0)
            rc = facet_error_set(err, FACET_EINPUT,
                "%s: '%s' is a view where Facet keeps a table: the file was "
                "altered; it is not opened", file->store->path, name);
        else if (!found)
            rc = facet_error_set(err, FACET_EINPUT,
                "%s: table %s of Facet's schema %d is missing: the file was "
                "altered or damaged; it is not opened", file->store->path,
                name, version);
        else
            rc = check_table(file, expected, name, version, err);
    }
    sqlite3_reset(s);
    return rc;
}

/* Triggers first (the SQL a file would run on its own), then virtual
 * tables, Facet's tables and last the views. */
static int compare(struct reader *file, struct reader *expected,
                   int version, struct facet_error *err)
{
    int rc = check_entries(file, expected, "trigger", err);
    if (rc == FACET_OK)
        rc = check_entries(file, expected, "table", err);
    if (rc == FACET_OK)
        rc = check_tables(file, expected, version, err);
    if (rc == FACET_OK)
        rc = check_entries(file, expected, "view", err);
    return rc;
}

/* Whether the file's schema is Facet's of version word for word, which
 * the comparison would pass: each of Facet's tables is there once, under
 * its name, declared in the very text Facet's migrations leave (so its
 * columns, keys and kind, which SQLite reads from that text alone, are
 * Facet's too); every view and index is Facet's own, text for text, or an
 * automatic index (made from a table's declaration); and whatever else
 * there is, is an ordinary table (the user's own, let be). Anything else,
 * or an error, is 0: the comparison then finds what differs, or that
 * nothing that matters does (an index of the user's own). */
static int declared_as_facets(struct store *store, int version)
{
    const struct store_schema_entry *want = store_schemas[version];
    int nwant = 0;
    while (want[nwant].type != NULL)
        nwant++;
    char *seen = calloc((size_t)nwant + 1, 1);
    sqlite3_stmt *s = NULL;
    if (seen == NULL ||
        sqlite3_prepare_v2(store->db, "SELECT coalesce(type, ''),"
                           " coalesce(name, ''), sql FROM sqlite_schema",
                           -1, &s, NULL) != SQLITE_OK) {
        free(seen);
        return 0;
    }
    int same = 1, step;
    while (same && (step = sqlite3_step(s)) == SQLITE_ROW) {
        const char *type = (const char *)sqlite3_column_text(s, 0);
        const char *name = (const char *)sqlite3_column_text(s, 1);
        const char *sql = (const char *)sqlite3_column_text(s, 2);
        int k = 0;
        while (k < nwant && sqlite3_stricmp(want[k].name, name) != 0)
            k++;
        if (sql == NULL)
            same = strcmp(type, "index") == 0;
        else if (k < nwant)
            same = !seen[k] && strcmp(type, want[k].type) == 0 &&
                   strcmp(name, want[k].name) == 0 &&
                   strcmp(sql, want[k].sql) == 0;
        else
            same = strcmp(type, "table") == 0 &&
                   sqlite3_strnicmp(sql, "CREATE TABLE", 12) == 0;
        if (k < nwant)
            seen[k] = 1;
    }
    if (same && step != SQLITE_DONE)
        same = 0;
    sqlite3_finalize(s);
    for (int k = 0; same && k < nwant; k++)
        if (strcmp(want[k].type, "table") == 0 && !seen[k])
            same = 0;
    free(seen);
    return same;
}

/* Builds Facet's schema of version in built, from its entries. */
static int build(struct store *built, int version, struct facet_error *err)
{
    int rc = store_exec(built, "BEGIN", "building the schema", err);
    for (const struct store_schema_entry *e = store_schemas[version];
         rc == FACET_OK && e->type != NULL; e++)
        rc = store_exec(built, e->sql, "building the schema", err);
    if (rc == FACET_OK)
        rc = store_exec(built, "COMMIT", "building the schema", err);
    return rc;
}

int store_schema_check(struct store *store, int version,
                       struct facet_error *err)
{
    assert(version >= 0 && version <= STORE_SCHEMA_VERSION);
    if (declared_as_facets(store, version))
        return FACET_OK;
    char name[] = "(Facet's own schema)";
    struct store built = {.path = name};
    if (sqlite3_open_v2(":memory:", &built.db, SQLITE_OPEN_READWRITE,
                        NULL) != SQLITE_OK) {
        sqlite3_close(built.db);
        return facet_error_set(err, FACET_EWORK, "out of memory");
    }
    int rc = build(&built, version, err);
    struct reader file = {.store = store}, expected = {.store = &built};
    if (rc == FACET_OK)
        rc = compare(&file, &expected, version, err);
    reader_close(&file);
    reader_close(&expected);
    sqlite3_close(built.db);
    return rc;
}
