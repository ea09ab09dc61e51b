/*
 * schema_script.c: a program the build runs (not part of Facet) that
 * writes the C file of store_schema_scripts (store_internal.h): Facet's
 * schema of each version as its migrations leave it, the CREATE statements
 * of sqlite_schema in its order. It runs the migrations themselves
 * (store_schema_migrate, schema.c) in an in-memory database, one version
 * at a time, and writes down what SQLite holds after each: the migrations
 * stay the one declaration of the schema, and the Makefile writes the file
 * again whenever schema.c changes. store_schema_check then builds a file's
 * expectation from one script instead of replaying every migration, each
 * ALTER TABLE of which makes SQLite parse the whole schema again.
 *
 *   schema_script OUT.c      (status 0, or 1 with a line on stderr)
 */
#include "store/store_internal.h"

#include <stdio.h>
#include <string.h>

/* Writes text as C string literals, a line of source per 64 characters
 * or so, escaping what C needs escaped. */
static void write_literal(FILE *out, const char *text)
{
    size_t n = strlen(text);
    size_t at = 0;
    do {
        fputs("    \"", out);
        size_t line = 0;
        for (; at < n && line < 64; at++, line++) {
            unsigned char c = (unsigned char)text[at];
            if (c == '"' || c == '\\')
                fprintf(out, "\\%c", c);
            else if (c < 32 || c > 126)
                fprintf(out, "\\%03o", c);
            else
                fputc(c, out);
        }
        fputs(at < n ? "\"\n" : "\"", out);
    } while (at < n);
}

/* Writes the script of store's schema as it is now: each entry of
 * sqlite_schema with SQL of its own (an automatic index has none: SQLite
 * makes it again with its table), in rowid order, ';' after each. */
static int write_script(FILE *out, struct store *store,
                        struct facet_error *err)
{
    sqlite3_stmt *s;
    int rc = store_prepare(store, "SELECT sql FROM sqlite_schema WHERE sql"
                           " IS NOT NULL ORDER BY rowid", &s,
                           "reading the schema", err);
    if (rc != FACET_OK)
        return rc;
    int entries = 0, step;
    while ((step = sqlite3_step(s)) == SQLITE_ROW) {
        const char *sql = (const char *)sqlite3_column_text(s, 0);
        if (entries++ > 0)
            fputc('\n', out);
        write_literal(out, sql);
        fputs(" \";\"", out);
    }
    if (entries == 0)
        fputs("    \"\"", out);
    if (step != SQLITE_DONE)
        rc = store_fail(store, "reading the schema", err);
    sqlite3_finalize(s);
    return rc;
}

int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: schema_script OUT.c\n");
        return 1;
    }
    FILE *out = fopen(argv[1], "w");
    if (out == NULL) {
        perror(argv[1]);
        return 1;
    }
    char name[] = "(Facet's own schema)";
    struct store store = {.path = name};
    struct facet_error err = {0};
    int rc = FACET_OK;
    if (sqlite3_open_v2(":memory:", &store.db, SQLITE_OPEN_READWRITE,
                        NULL) != SQLITE_OK)
        rc = facet_error_set(&err, FACET_EWORK, "out of memory");
    fprintf(out, "/* Written by store/tool/schema_script.c from the "
            "migrations of store/schema.c\n * at build time: do not edit "
            "(store_internal.h, store_schema_scripts). */\n"
            "#include \"store/store_internal.h\"\n\n"
            "const char *const store_schema_scripts[STORE_SCHEMA_VERSION"
            " + 1] = {\n");
    for (int version = 0; rc == FACET_OK && version <= STORE_SCHEMA_VERSION;
         version++) {
        if (version > 0)
            rc = store_schema_migrate(&store, version - 1, version, &err);
        fprintf(out, "    /* version %d */\n", version);
        if (rc == FACET_OK)
            rc = write_script(out, &store, &err);
        fputs(",\n", out);
    }
    fputs("};\n", out);
    sqlite3_close(store.db);
    if (fclose(out) != 0 && rc == FACET_OK)
        rc = facet_error_set(&err, FACET_EWORK, "%s: cannot write",
                             argv[1]);
    if (rc != FACET_OK) {
        fprintf(stderr, "schema_script: %s\n", err.message);
        remove(argv[1]);
        return 1;
    }
    return 0;
}
