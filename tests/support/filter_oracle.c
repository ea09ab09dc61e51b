/*
 * filter_oracle.c: SQLite against filter_match. See filter_oracle.h.
 */
#include "filter_oracle.h"

#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "store/filter_sql.h"

enum { NCOLUMNS = OPTION_QUANTITIES };

int oracle_column(const char *name)
{
    for (int k = 0; k < OPTION_QUANTITIES; k++)
        if (strcmp(option_quantities[k].name, name) == 0)
            return k;
    return -1;
}

double oracle_value(void *context, const char *column)
{
    int k = oracle_column(column);
    return k < 0 ? NAN : ((const struct oracle_row *)context)->v[k];
}

static void set(struct oracle_row *r, const char *column, double value)
{
    int k = oracle_column(column);
    if (k >= 0)
        r->v[k] = value;
}

static bool integer_column(int k)
{
    static const char *const integers[] = {
        "number", "generation", "nu", "nv", "panels", "fp_count",
        "sp_count", "dp_count", "feasible", "rank", "knee", "run",
    };
    for (size_t j = 0; j < sizeof integers / sizeof *integers; j++)
        if (strcmp(option_quantities[k].name, integers[j]) == 0)
            return true;
    const char *name = option_quantities[k].name;
    size_t n = strlen(name);
    return n > 6 && strcmp(name + n - 6, "_count") == 0;
}

void oracle_random_rows(struct rng *rng, struct oracle_row *rows, int n)
{
    for (int i = 0; i < n; i++) {
        struct oracle_row *r = &rows[i];
        for (int k = 0; k < NCOLUMNS; k++)
            r->v[k] = 0;
        double nu = 2 + (double)rng_below(rng, 39);
        double nv = 2 + (double)rng_below(rng, 39);
        double fp = (double)rng_below(rng, 200), sp = (double)rng_below(rng, 200);
        double dp = (double)rng_below(rng, 200);
        set(r, "number", i + 1);
        set(r, "generation", (double)rng_below(rng, 10));
        set(r, "nu", nu);
        set(r, "nv", nv);
        set(r, "threshold_mm", 0.5 * (double)(1 + rng_below(rng, 20)));
        set(r, "panels", nu * nv);
        set(r, "fp_count", fp);
        set(r, "sp_count", sp);
        set(r, "dp_count", dp);
        set(r, "fp_area", (double)rng_below(rng, 100000) / 100);
        set(r, "sp_area", (double)rng_below(rng, 100000) / 100);
        set(r, "dp_area", (double)rng_below(rng, 2000));
        set(r, "area", 1000 + (double)rng_below(rng, 500));
        set(r, "cost", 1000 * (double)rng_below(rng, 3000));
        set(r, "fp_cost", 1000 * (double)rng_below(rng, 1000));
        set(r, "sp_cost",
            rng_below(rng, 3) == 0 ? 0 : 500 * (double)rng_below(rng, 100));
        set(r, "dp_cost", 1000 * (double)rng_below(rng, 2000));
        for (int k = 0; k < OPTION_QUANTITIES; k++) {
            const char *c = option_quantities[k].name;
            size_t len = strlen(c);
            if (len > 6 && strcmp(c + len - 6, "_count") == 0 &&
                strcmp(c, "fp_count") && strcmp(c, "sp_count") &&
                strcmp(c, "dp_count"))
                r->v[k] = (double)rng_below(rng, 50);
            else if (len > 5 && strcmp(c + len - 5, "_area") == 0 &&
                     strcmp(c, "fp_area") && strcmp(c, "sp_area") &&
                     strcmp(c, "dp_area"))
                r->v[k] = (double)rng_below(rng, 3000) / 10;
        }
        set(r, "planarity", rng_below(rng, 10) == 0 ? NAN : rng_uniform(rng));
        set(r, "max_deviation",
            rng_below(rng, 10) == 0 ? NAN : rng_uniform(rng) * 0.05);
        set(r, "max_panel_area", 1 + (double)rng_below(rng, 8));
        set(r, "p_dist", rng_uniform(rng));
        set(r, "feasible", rng_below(rng, 4) != 0);
        set(r, "rank", 1 + (double)rng_below(rng, 5));
        set(r, "crowding",
            rng_below(rng, 8) == 0 ? INFINITY : rng_uniform(rng) * 2);
        /* Not ranked yet (a run going on): stored NULL, read as 0, and
         * so is its crowding (see oracle_database). */
        if (rng_below(rng, 10) == 0) {
            set(r, "rank", 0);
            set(r, "crowding", 0);
        }
        set(r, "knee", i == 17 || i == 203);
        set(r, "run", 1 + (double)rng_below(rng, 3));
    }
}

sqlite3 *oracle_database(const struct oracle_row *rows, int n)
{
    sqlite3 *db = NULL;
    if (sqlite3_open(":memory:", &db) != SQLITE_OK) {
        sqlite3_close(db);
        return NULL;
    }
    char create[2048] = "CREATE TABLE options (";
    char insert[1024] = "INSERT INTO options VALUES (";
    for (int k = 0; k < NCOLUMNS; k++) {
        char part[64];
        snprintf(part, sizeof part, "%s\"%s\" %s", k == 0 ? "" : ", ",
                 option_quantities[k].name,
                 integer_column(k) ? "INTEGER" : "REAL");
        strcat(create, part);
        strcat(insert, k == 0 ? "?" : ", ?");
    }
    strcat(create, ")");
    strcat(insert, ")");
    sqlite3_stmt *stmt = NULL;
    if (sqlite3_exec(db, create, NULL, NULL, NULL) != SQLITE_OK ||
        sqlite3_prepare_v2(db, insert, -1, &stmt, NULL) != SQLITE_OK) {
        sqlite3_close(db);
        return NULL;
    }
    for (int i = 0; i < n; i++) {
        for (int k = 0; k < NCOLUMNS; k++) {
            double v = rows[i].v[k];
            /* As the store keeps them: rank NULL until ranked, crowding
             * NULL at a front's ends (infinity) and before ranking. */
            bool unranked = rows[i].v[oracle_column("rank")] == 0;
            const char *name = option_quantities[k].name;
            bool stored_null =
                (strcmp(name, "rank") == 0 && unranked) ||
                (strcmp(name, "crowding") == 0 && (unranked || isinf(v)));
            if (isnan(v) || stored_null)
                sqlite3_bind_null(stmt, k + 1);
            else if (integer_column(k))
                sqlite3_bind_int64(stmt, k + 1, (sqlite3_int64)v);
            else
                sqlite3_bind_double(stmt, k + 1, v);
        }
        if (sqlite3_step(stmt) != SQLITE_DONE) {
            sqlite3_finalize(stmt);
            sqlite3_close(db);
            return NULL;
        }
        sqlite3_reset(stmt);
    }
    sqlite3_finalize(stmt);
    return db;
}

/* Counts the options of db the statement selects into selected[0..n)
 * (by number) and returns how many, or -1 on an SQLite error. */
static int run_query(sqlite3 *db, const char *sql, const struct filter *f,
                     int first_param, bool *selected, int n)
{
    sqlite3_stmt *stmt = NULL;
    if (sqlite3_prepare_v2(db, sql, -1, &stmt, NULL) != SQLITE_OK)
        return -1;
    if (first_param == 3) {
        sqlite3_bind_int(stmt, 1, 0);
        sqlite3_bind_int(stmt, 2, 0);
    }
    int ok = sqlite3_bind_parameter_count(stmt) ==
             (int)filter_param_count(f) + first_param - 1;
    for (size_t k = 0; ok && k < filter_param_count(f); k++)
        ok = sqlite3_bind_double(stmt, first_param + (int)k,
                                 filter_param(f, k)) == SQLITE_OK;
    int count = 0, rc;
    while (ok && (rc = sqlite3_step(stmt)) == SQLITE_ROW) {
        sqlite3_int64 number = sqlite3_column_int64(stmt, 0);
        if (number < 1 || number > n)
            ok = 0;
        else
            selected[number - 1] = true;
        count++;
    }
    if (ok && rc != SQLITE_DONE)
        ok = 0;
    sqlite3_finalize(stmt);
    return ok ? count : -1;
}

int oracle_compare_from(sqlite3 *db, const struct oracle_row *rows, int n,
                        const struct filter *f, int first_param, char *why,
                        size_t size)
{
    bool *selected = calloc((size_t)n + 1, sizeof *selected);
    bool *scanned = calloc((size_t)n + 1, sizeof *scanned);
    char *where = filter_sql(f, first_param);
    char *scan = filter_sql_scan(f, 1);
    int result = -1;
    if (selected == NULL || scanned == NULL || where == NULL ||
        scan == NULL) {
        snprintf(why, size, "out of memory");
        goto done;
    }
    size_t length = strlen(where) + strlen(scan) + 128;
    char *query = malloc(length);
    if (query == NULL) {
        snprintf(why, size, "out of memory");
        goto done;
    }
    if (first_param == 3)
        snprintf(query, length, "SELECT number FROM options WHERE number > "
                 "?1 - ?2 AND (%s)", where);
    else
        snprintf(query, length, "SELECT number FROM options WHERE %s",
                 where);
    int count = run_query(db, query, f, first_param, selected, n);
    if (count < 0) {
        snprintf(why, size, "'%s' gave bad SQL '%s': %s", filter_text(f),
                 query, sqlite3_errmsg(db));
        free(query);
        goto done;
    }
    snprintf(query, length, "SELECT number FROM options WHERE %s", scan);
    int scan_count = run_query(db, query, f, 1, scanned, n);
    free(query);
    int matched = 0;
    for (int i = 0; i < n; i++) {
        bool match = filter_match(f, oracle_value, (void *)&rows[i]) != 0;
        if (match != selected[i]) {
            snprintf(why, size, "'%s' (SQL %s): option %d: SQLite %d, "
                     "filter_match %d", filter_text(f), where, i + 1,
                     selected[i], match);
            goto done;
        }
        if (scanned[i] != selected[i]) {
            snprintf(why, size, "'%s' (SQL for scans %s): option %d: %d, "
                     "the indexed form %d", filter_text(f), scan, i + 1,
                     scanned[i], selected[i]);
            goto done;
        }
        matched += match;
    }
    if (scan_count != count) {
        snprintf(why, size, "'%s': the scan form selects %d, the other %d",
                 filter_text(f), scan_count, count);
        goto done;
    }
    result = matched;
done:
    free(selected);
    free(scanned);
    free(where);
    free(scan);
    return result;
}

int oracle_compare(sqlite3 *db, const struct oracle_row *rows, int n,
                   const struct filter *f, char *why, size_t size)
{
    return oracle_compare_from(db, rows, n, f, 1, why, size);
}
