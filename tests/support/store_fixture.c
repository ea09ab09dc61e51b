/*
 * store_fixture.c: a run for tests. See store_fixture.h.
 */
#include "store_fixture.h"

#include <sqlite3.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

void store_fixture_run(struct run_info *run)
{
    memset(run, 0, sizeof *run);
    snprintf(run->surface_path, sizeof run->surface_path, "x.obj");
    run->units = UNITS_M;
    run->method = METHOD_EXHAUSTIVE;
    run->per_panel = PANEL_EXTREMES;
    snprintf(run->objectives, sizeof run->objectives, "cost");
    run->u_min = run->u_max = run->v_min = run->v_max = 1;
    run->jobs = 1;
}

void store_fixture_remove(const char *path)
{
    char side[1024];
    unlink(path);
    snprintf(side, sizeof side, "%s-wal", path);
    unlink(side);
    snprintf(side, sizeof side, "%s-shm", path);
    unlink(side);
}

int store_fixture_sql_int(const char *path, const char *query,
                          int64_t *value)
{
    sqlite3 *db;
    sqlite3_stmt *s = NULL;
    int ok = sqlite3_open(path, &db) == SQLITE_OK &&
             sqlite3_prepare_v2(db, query, -1, &s, NULL) == SQLITE_OK &&
             sqlite3_step(s) == SQLITE_ROW;
    if (ok)
        *value = sqlite3_column_int64(s, 0);
    sqlite3_finalize(s);
    sqlite3_close(db);
    return ok ? 0 : -1;
}
