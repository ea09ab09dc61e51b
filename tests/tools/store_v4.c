/*
 * store_v4.c: takes a Facet result store back to schema version 4, as a
 * Facet before the cost model left it (STORE_FIXTURE_UNDO_V5), or with 7
 * to version 7, as a Facet before projects left it (STORE_FIXTURE_UNDO_V8),
 * for the end-to-end tests of a run an older Facet stored: the next Facet
 * that opens it migrates it, and the new columns of its options are NULL.
 *
 *   store_v4 DB [7]
 *
 * Exits 0, or 2 with SQLite's message on stderr.
 */
#include <sqlite3.h>
#include <stdio.h>
#include <string.h>

#include "tests/support/store_fixture.h"

int main(int argc, char **argv)
{
    int to7 = argc == 3 && strcmp(argv[2], "7") == 0;
    if (argc != 2 && !to7) {
        fprintf(stderr, "usage: store_v4 DB [7]\n");
        return 2;
    }
    sqlite3 *db;
    char *message = NULL;
    int rc = sqlite3_open_v2(argv[1], &db, SQLITE_OPEN_READWRITE, NULL);
    if (rc == SQLITE_OK)
        rc = sqlite3_exec(db, to7 ? STORE_FIXTURE_UNDO_V8
                                    "PRAGMA user_version = 7;"
                                  : STORE_FIXTURE_UNDO_V5
                                    "PRAGMA user_version = 4;",
                          NULL, NULL, &message);
    if (rc != SQLITE_OK)
        fprintf(stderr, "store_v4: %s: %s\n", argv[1],
                message ? message : sqlite3_errmsg(db));
    sqlite3_free(message);
    sqlite3_close(db);
    return rc == SQLITE_OK ? 0 : 2;
}
