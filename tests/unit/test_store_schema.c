/*
 * test_store_schema.c: the schema a file is held to (store_schema_check).
 * Its expectation is the entries of sqlite_schema the build writes down by
 * running the migrations (store_schemas, store/tool/schema_script.c):
 * each version's are, in SQLite's own words (sqlite_schema), those the
 * migrations make, and their SQL run makes the same schema, so a stale
 * file fails here; and a file
 * whose schema differs from the migrations' by one column, one type, one
 * default, one NOT NULL, one key, one index, one constraint, a trigger or
 * a view is still refused in one line naming it, at the current version
 * and at an older one, while a file as Facet made it, or with an index and
 * a table of the user's own, opens.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <sqlite3.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "store/store_internal.h"
#include "tests/support/store_fixture.h"

/* sqlite_schema of db, every entry (the automatic indexes too) in rowid
 * order, one "type|name|table|sql" line each, into out (malloc'ed). */
static char *schema_text(sqlite3 *db)
{
    sqlite3_stmt *s;
    assert_int_equal(sqlite3_prepare_v2(db,
        "SELECT type || '|' || name || '|' || tbl_name || '|' ||"
        " coalesce(sql, '-') FROM sqlite_schema ORDER BY rowid", -1, &s,
        NULL), SQLITE_OK);
    size_t size = 1, used = 0;
    char *out = calloc(1, size);
    assert_non_null(out);
    while (sqlite3_step(s) == SQLITE_ROW) {
        const char *line = (const char *)sqlite3_column_text(s, 0);
        size_t n = strlen(line);
        out = realloc(out, size + n + 1);
        assert_non_null(out);
        size += n + 1;
        memcpy(out + used, line, n);
        out[used + n] = '\n';
        used += n + 1;
        out[used] = '\0';
    }
    sqlite3_finalize(s);
    return out;
}

/* A new in-memory database in *store, for the store's own functions. */
static void memory_store(struct store *store)
{
    static char name[] = "(test)";
    memset(store, 0, sizeof *store);
    store->path = name;
    assert_int_equal(sqlite3_open_v2(":memory:", &store->db,
                                     SQLITE_OPEN_READWRITE, NULL),
                     SQLITE_OK);
}

/* Runs the SQL of entries (store_schemas) on db. */
static void run_entries(sqlite3 *db, const struct store_schema_entry *e,
                        int version)
{
    for (; e->type != NULL; e++) {
        char *said = NULL;
        if (sqlite3_exec(db, e->sql, NULL, NULL, &said) != SQLITE_OK)
            fail_msg("version %d: %s fails: %s", version, e->sql, said);
    }
}

/* Each version's entries are, in order and word for word, the entries
 * with SQL that replaying the migrations from an empty database up to
 * that version leaves in sqlite_schema; and their SQL run on an empty
 * database makes that sqlite_schema whole (its automatic indexes too). */
static void test_entries_are_the_migrations(void **state)
{
    (void)state;
    for (int version = 0; version <= STORE_SCHEMA_VERSION; version++) {
        struct store replay, script;
        struct facet_error err = {0};
        memory_store(&replay);
        memory_store(&script);
        assert_int_equal(store_schema_migrate(&replay, 0, version, &err),
                         FACET_OK);
        sqlite3_stmt *s;
        assert_int_equal(sqlite3_prepare_v2(replay.db, "SELECT type, name,"
            " sql FROM sqlite_schema WHERE sql IS NOT NULL ORDER BY rowid",
            -1, &s, NULL), SQLITE_OK);
        const struct store_schema_entry *e = store_schemas[version];
        for (; sqlite3_step(s) == SQLITE_ROW; e++) {
            const char *sql = (const char *)sqlite3_column_text(s, 2);
            if (e->type == NULL)
                fail_msg("version %d: no entry for %s", version, sql);
            assert_string_equal(e->type, sqlite3_column_text(s, 0));
            assert_string_equal(e->name, sqlite3_column_text(s, 1));
            assert_string_equal(e->sql, sql);
        }
        if (e->type != NULL)
            fail_msg("version %d: %s is none of the migrations'", version,
                     e->sql);
        sqlite3_finalize(s);
        run_entries(script.db, store_schemas[version], version);
        char *want = schema_text(replay.db);
        char *have = schema_text(script.db);
        if (strcmp(want, have) != 0)
            fail_msg("version %d: the migrations make\n%s\nthe entries "
                     "make\n%s", version, want, have);
        /* Not empty but at 0: the comparison compared something. */
        assert_true(version == 0 || strstr(want, "table|runs|") != NULL);
        free(want);
        free(have);
        sqlite3_close(replay.db);
        sqlite3_close(script.db);
    }
}

static char older_db[96], template_db[96], work_db[96];

/* The file a new Facet database is: made once by store_open (the
 * migrations on a file), copied for each case. */
static int make_template(void **state)
{
    (void)state;
    snprintf(template_db, sizeof template_db,
             "/tmp/facet_test_schema_%d.db", (int)getpid());
    snprintf(work_db, sizeof work_db, "/tmp/facet_test_schema_%d_work.db",
             (int)getpid());
    snprintf(older_db, sizeof older_db, "/tmp/facet_test_schema_%d_v8.db",
             (int)getpid());
    store_fixture_remove(template_db);
    struct store *store;
    struct facet_error err = {0};
    if (store_open(template_db, &store, &err) != FACET_OK)
        return -1;
    store_close(store);
    return 0;
}

static int remove_files(void **state)
{
    (void)state;
    store_fixture_remove(template_db);
    store_fixture_remove(work_db);
    store_fixture_remove(older_db);
    return 0;
}

/* Copies file from to to (and no side file: store_close left the WAL
 * empty). */
static void copy_file(const char *from, const char *to)
{
    store_fixture_remove(to);
    FILE *in = fopen(from, "rb");
    FILE *out = fopen(to, "wb");
    assert_non_null(in);
    assert_non_null(out);
    char buffer[65536];
    size_t n;
    while ((n = fread(buffer, 1, sizeof buffer, in)) > 0)
        assert_int_equal(fwrite(buffer, 1, n, out), n);
    fclose(in);
    assert_int_equal(fclose(out), 0);
}

/* Runs sql on the file at path with SQLite alone (as a user's sqlite3
 * would, writable_schema allowed). */
static void alter(const char *path, const char *sql)
{
    sqlite3 *db;
    assert_int_equal(sqlite3_open(path, &db), SQLITE_OK);
    char *said = NULL;
    if (sqlite3_exec(db, sql, NULL, NULL, &said) != SQLITE_OK)
        fail_msg("%s: %s", sql, said);
    sqlite3_close(db);
}

/* The file at path, of Facet's schema version, is refused by a reader
 * and by a writer, with FACET_EINPUT and one line holding words (its %d,
 * if any: version). */
static void refused(const char *path, int version, const char *pattern)
{
    char words[300];
    snprintf(words, sizeof words, pattern, version);
    struct store *store = NULL;
    struct facet_error err = {0};
    int rc = store_open_read(path, &store, &err);
    if (rc == FACET_OK)
        store_close(store);
    if (rc != FACET_EINPUT || strstr(err.message, words) == NULL ||
        strchr(err.message, '\n') != NULL)
        fail_msg("reading: %d '%s', not refused with '%s'", rc, err.message,
                 words);
    memset(&err, 0, sizeof err);
    rc = store_open(path, &store, &err);
    if (rc == FACET_OK)
        store_close(store);
    if (rc != FACET_EINPUT || strstr(err.message, words) == NULL)
        fail_msg("writing: %d '%s', not refused with '%s'", rc, err.message,
                 words);
}

/* One way a file's schema differs from Facet's, and the words its
 * refusal says. */
struct case_ {
    const char *what;
    const char *sql;
    const char *words;
};

/* writable_schema: a declaration changed in place, as a user's sqlite3
 * can (replace() on one table's SQL). */
#define EDIT(table, from, to) \
    "PRAGMA writable_schema = ON; UPDATE sqlite_schema SET sql =" \
    " replace(sql, '" from "', '" to "') WHERE name = '" table "';"

static const struct case_ current_cases[] = {
    {"a column added", "ALTER TABLE runs ADD COLUMN extra REAL;",
     "table runs has a column extra that Facet's schema %d has not"},
    {"a column dropped", "ALTER TABLE options DROP COLUMN knee;",
     "table options has no column knee, which Facet's schema %d has"},
    {"a column's type", EDIT("options", " cost REAL NOT NULL,",
                             " cost TEXT NOT NULL,"),
     "column options.cost is 'TEXT NOT NULL' where Facet's schema %d has "
     "'REAL NOT NULL'"},
    {"a column's default", EDIT("runs", "DEFAULT ''front''",
                                "DEFAULT ''knee''"),
     "column runs.store_panels is 'TEXT NOT NULL DEFAULT 'knee''"},
    {"a default added", EDIT("options", " cost REAL NOT NULL,",
                             " cost REAL NOT NULL DEFAULT 0,"),
     "column options.cost is 'REAL NOT NULL DEFAULT 0'"},
    {"NOT NULL dropped", EDIT("options", " cost REAL NOT NULL,",
                              " cost REAL,"),
     "column options.cost is 'REAL' where Facet's schema %d has 'REAL NOT "
     "NULL'"},
    {"the primary key's order", EDIT("panel_sets", "PRIMARY KEY (run, option)",
                                     "PRIMARY KEY (option, run)"),
     "column panel_sets.run is 'INTEGER NOT NULL KEY 2'"},
    {"a rowid alias no more", EDIT("runs", " id INTEGER PRIMARY KEY,",
                                   " id INTEGER,"),
     "column runs.id is 'INTEGER'"},
    {"a foreign key's action", EDIT("options", "ON DELETE CASCADE",
                                    "ON DELETE SET NULL"),
     "table options's keys or kind"},
    {"a foreign key's table", EDIT("option_held", "REFERENCES options",
                                   "REFERENCES runs"),
     "table option_held's keys or kind"},
    {"WITHOUT ROWID dropped", EDIT("surfaces", ") WITHOUT ROWID", ")"),
     "table surfaces's keys or kind"},
    {"a CHECK of its own", EDIT("options", " cost REAL NOT NULL,",
                                " cost REAL NOT NULL CHECK (cost >= 0),"),
     "table options is not declared as Facet's schema %d declares it"},
    {"a collation of its own", EDIT("runs", " name TEXT NOT NULL",
                                    " name TEXT COLLATE NOCASE NOT NULL"),
     "table runs is not declared as Facet's schema %d declares it"},
    {"the columns in another order",
     EDIT("panel_sets", " nu INTEGER NOT NULL, nv INTEGER NOT NULL,",
          " nv INTEGER NOT NULL, nu INTEGER NOT NULL,"),
     "the columns of table panel_sets are not in the order"},
    {"an index on an expression",
     "CREATE INDEX spin ON panels(abs(area));",
     "holds index 'spin' on panels, on an expression or with a WHERE"},
    {"a partial index",
     "CREATE INDEX some ON options(run, cost) WHERE cost > 0;",
     "holds index 'some' on options, on an expression or with a WHERE"},
    {"Facet's index made again on an expression",
     "DROP INDEX options_by_cost; CREATE INDEX options_by_cost ON"
     " options(run, abs(cost));",
     "holds index 'options_by_cost' on options, on an expression"},
    {"an index on an expression, said to be another table's",
     "CREATE TABLE notes (text TEXT); CREATE INDEX spin ON"
     " panels(abs(area)); PRAGMA writable_schema = ON; UPDATE sqlite_schema"
     " SET tbl_name = 'notes' WHERE name = 'spin';",
     "malformed database schema (spin)"},
    {"a virtual table of its own",
     "CREATE VIRTUAL TABLE mine USING fts4(text);",
     "holds virtual table 'mine'"},
    {"a table missing", "DROP TABLE option_surface_held;",
     "table option_surface_held of Facet's schema %d is missing"},
    {"a table become a view",
     "ALTER TABLE surfaces RENAME TO kept; CREATE VIEW surfaces AS"
     " SELECT * FROM kept;",
     "'surfaces' is a view where Facet keeps a table"},
    {"a trigger", "CREATE TRIGGER forge AFTER INSERT ON runs BEGIN"
     " DELETE FROM options; END;",
     "holds trigger 'forge' on runs"},
    {"a view redefined", "DROP VIEW pareto; CREATE VIEW pareto AS"
     " SELECT * FROM options;",
     "holds view 'pareto', which is not Facet's"},
    {"a view of its own", "CREATE VIEW mine AS SELECT 1;",
     "holds view 'mine', which is not Facet's"},
};

/* A current file differing from the migrations' schema by any one of
 * current_cases is refused, naming the difference; the file as made, and
 * one with an index and a table of the user's own, open. */
static void test_altered_current_refused(void **state)
{
    (void)state;
    struct store *store;
    struct facet_error err = {0};
    copy_file(template_db, work_db);
    assert_int_equal(store_open_read(work_db, &store, &err), FACET_OK);
    store_close(store);
    alter(work_db, "CREATE INDEX mine ON options(cost, nu);"
          " CREATE TABLE notes (text TEXT);");
    assert_int_equal(store_open_read(work_db, &store, &err), FACET_OK);
    store_close(store);
    for (size_t k = 0; k < sizeof current_cases / sizeof current_cases[0];
         k++) {
        copy_file(template_db, work_db);
        alter(work_db, current_cases[k].sql);
        print_message("%s\n", current_cases[k].what);
        refused(work_db, STORE_SCHEMA_VERSION, current_cases[k].words);
    }
}

/* A file of an older version (8: projects, before the fits) is held to
 * that version's script: as the migrations left it, it passes the check
 * (and is then refused by a reader only for being older, and migrated by
 * store_migrate); a default changed, a column added or a key changed is
 * refused naming schema 8. */
static void test_altered_older_refused(void **state)
{
    (void)state;
    static const struct case_ cases[] = {
        {"a column's default", EDIT("runs", "DEFAULT ''front''",
                                    "DEFAULT ''none''"),
         "column runs.store_panels is 'TEXT NOT NULL DEFAULT 'none'' "
         "where Facet's schema %d has"},
        {"a column of a later version", "ALTER TABLE options ADD COLUMN"
         " sp_min_radius REAL;",
         "table options has a column sp_min_radius that Facet's schema %d "
         "has not"},
        {"a foreign key's action", EDIT("surfaces", "ON DELETE CASCADE",
                                        "ON DELETE RESTRICT"),
         "table surfaces's keys or kind"},
        {"an index on an expression",
         "CREATE INDEX spin ON options(abs(cost));",
         "holds index 'spin' on options"},
    };
    struct store older;
    struct facet_error err = {0};
    for (size_t k = 0; k <= sizeof cases / sizeof cases[0]; k++) {
        store_fixture_remove(older_db);
        memset(&older, 0, sizeof older);
        older.path = older_db;
        assert_int_equal(sqlite3_open(older_db, &older.db), SQLITE_OK);
        assert_int_equal(store_schema_migrate(&older, 0, 8, &err), FACET_OK);
        sqlite3_close(older.db);
        struct store *store = NULL;
        if (k == sizeof cases / sizeof cases[0]) {
            /* As made: past the check, refused as older, migrated. */
            assert_int_equal(store_open_read(older_db, &store, &err),
                             FACET_EINPUT);
            assert_non_null(strstr(err.message, "written by an older Facet"
                                   " (schema 8;"));
            int from = 0;
            assert_int_equal(store_migrate(older_db, &from, &err), FACET_OK);
            assert_int_equal(from, 8);
            assert_int_equal(store_open_read(older_db, &store, &err),
                             FACET_OK);
            store_close(store);
            continue;
        }
        alter(older_db, cases[k].sql);
        print_message("schema 8: %s\n", cases[k].what);
        refused(older_db, 8, cases[k].words);
    }
}

/* A new file (store_open) holds the schema the migrations make from
 * an empty database, word for word, stamped as Facet's at the current
 * version: Facet creates it from the entries in one step. */
static void test_new_file_is_the_migrations(void **state)
{
    (void)state;
    sqlite3 *file;
    struct store replay;
    struct facet_error err = {0};
    assert_int_equal(sqlite3_open_v2(template_db, &file,
                                     SQLITE_OPEN_READONLY, NULL), SQLITE_OK);
    memory_store(&replay);
    assert_int_equal(store_schema_migrate(&replay, 0, STORE_SCHEMA_VERSION,
                                          &err), FACET_OK);
    char *want = schema_text(replay.db);
    char *have = schema_text(file);
    assert_string_equal(have, want);
    free(want);
    free(have);
    sqlite3_stmt *s;
    assert_int_equal(sqlite3_prepare_v2(file, "SELECT (SELECT user_version"
        " FROM pragma_user_version), (SELECT application_id FROM"
        " pragma_application_id)", -1, &s, NULL), SQLITE_OK);
    assert_int_equal(sqlite3_step(s), SQLITE_ROW);
    assert_int_equal(sqlite3_column_int(s, 0), STORE_SCHEMA_VERSION);
    assert_int_equal(sqlite3_column_int(s, 1), 0x46434554);  /* "FCET" */
    sqlite3_finalize(s);
    sqlite3_close(file);
    sqlite3_close(replay.db);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_entries_are_the_migrations),
        cmocka_unit_test(test_new_file_is_the_migrations),
        cmocka_unit_test(test_altered_current_refused),
        cmocka_unit_test(test_altered_older_refused),
    };
    return cmocka_run_group_tests(tests, make_template, remove_files);
}
