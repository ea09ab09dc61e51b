/*
 * schema_script.c: a program the build runs (not part of Facet) that
 * writes the C file of store_schemas (store_internal.h): Facet's schema
 * of each version as its migrations leave it, the entries of sqlite_schema
 * (type, name, CREATE statement) in its order. It runs the migrations themselves
 * (store_schema_migrate, schema.c) in an in-memory database, one version
 * at a time, and writes down what SQLite holds after each: the migrations
 * stay the one declaration of the schema, and the Makefile writes the file
 * again whenever schema.c changes. store_schema_check then compares a
 * file with these entries, and builds its expectation from them, instead
 * of replaying every migration, each ALTER TABLE of which makes SQLite
 * parse the whole schema again.
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

/* Writes the entries of store's schema as it is now as the array
 * version_N: each entry of sqlite_schema with SQL of its own (an automatic
 * index has none: SQLite makes it again with its table), in rowid order,
 * then the end (type NULL). */
static int write_entries(FILE *out, struct store *store, int version,
                         struct facet_error *err)
{
    sqlite3_stmt *s;
    int rc = store_prepare(store, "SELECT type, name, sql FROM sqlite_schema"
                           " WHERE sql IS NOT NULL ORDER BY rowid", &s,
                           "reading the schema", err);
    if (rc != FACET_OK)
        return rc;
    fprintf(out, "static const struct store_schema_entry version_%d[] = {\n",
            version);
    int step;
    while ((step = sqlite3_step(s)) == SQLITE_ROW) {
        fputs("    {\n", out);
        for (int col = 0; col < 3; col++) {
            write_literal(out, (const char *)sqlite3_column_text(s, col));
            fputs(",\n", out);
        }
        fputs("    },\n", out);
    }
    fputs("    {NULL, NULL, NULL},\n};\n\n", out);
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
            "(store_internal.h, store_schemas). */\n"
            "#include \"store/store_internal.h\"\n\n");
    for (int version = 0; rc == FACET_OK && version <= STORE_SCHEMA_VERSION;
         version++) {
        if (version > 0)
            rc = store_schema_migrate(&store, version - 1, version, &err);
        if (rc == FACET_OK)
            rc = write_entries(out, &store, version, &err);
    }
    fputs("const struct store_schema_entry *const\n"
          "    store_schemas[STORE_SCHEMA_VERSION + 1] = {\n", out);
    for (int version = 0; version <= STORE_SCHEMA_VERSION; version++)
        fprintf(out, "    version_%d,\n", version);
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
