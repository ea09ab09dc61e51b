/*
 * store_option.c: the options table: committing a batch of evaluated
 * options, reading a run's options back, writing the Pareto analysis, and
 * the sorted, filtered queries of `facet options` and the TUI. See store.h.
 * Which columns an option has, and where its row holds each, is the
 * registry's (quantity.h): the INSERT and SELECT lists and the
 * binding and reading of a row are built from it.
 */
#include "store_internal.h"

#include <assert.h>
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "core/search/ties.h"
#include "filter_sql.h"

/* The SQL of the columns an option_row holds, from the registry
 * (quantity.h) in its order, into sql (size bytes): "number,
 * generation, ..., rank, crowding, knee" for a SELECT, with rank as
 * store_rank_sql (0 until ranked); insert: only the columns written with
 * the option, for an INSERT. Returns how many. */
static int option_columns_sql(char *sql, size_t size, int insert)
{
    size_t len = 0;
    int n = 0;
    sql[0] = '\0';
    for (int k = 0; k < OPTION_QUANTITIES; k++) {
        const struct quantity *c = &option_quantities[k];
        if (c->writer == WRITTEN_AS_KEY ||
            (insert && c->writer != WRITTEN_WITH_OPTION))
            continue;
        /* A gap or kink is read as core holds it, from option_held
         * (quantity_stored); the table's column has it in mm or degrees. */
        char held[320];
        if (!insert && c->stored != STORED_AS_HELD)
            store_held_sql(held, sizeof held, c, "option_held",
                           "h.run = options.run AND h.option = options.number",
                           "options");
        const char *sql_of = !insert && strcmp(c->name, "rank") == 0
                                 ? store_rank_sql
                             : !insert && c->stored != STORED_AS_HELD
                                 ? held : c->name;
        len += (size_t)snprintf(sql + len, size - len, "%s%s",
                                n ? ", " : "", sql_of);
        assert(len < size);
        n++;
    }
    return n;
}

/* Room for the SQL of every column, with room to grow. */
#define OPTION_COLUMNS_SQL 8192

static int is_module_column(const struct quantity *c)
{
    return c->offset == offsetof(struct option_row, module_w) ||
           c->offset == offsetof(struct option_row, module_h) ||
           c->offset == offsetof(struct option_row, modules);
}

/* Binds run to ?1 and row's values of the columns written with the option
 * to ?2.. in the order of option_columns_sql; a single surface's option
 * (project 0) has no module: NULL, whatever its row holds. */
static void option_bind(sqlite3_stmt *s, int64_t run,
                        const struct option_row *o, int project)
{
    int p = 1;
    sqlite3_bind_int64(s, p++, run);
    for (int k = 0; k < OPTION_QUANTITIES; k++) {
        const struct quantity *c = &option_quantities[k];
        if (c->writer != WRITTEN_WITH_OPTION)
            continue;
        const void *field = (const char *)o + c->offset;
        if (!project && is_module_column(c))
            sqlite3_bind_null(s, p++);
        else
            store_bind_quantity(s, p++, c, field);
    }
}

void store_held_sql(char *sql, size_t size, const struct quantity *q,
                    const char *held, const char *match, const char *table)
{
    assert(q->stored != STORED_AS_HELD);
    const char *back = q->stored == STORED_MM ? store_held_from_mm_sql
                                              : store_held_from_deg_sql;
    int n = snprintf(sql, size, "coalesce((SELECT h.%s FROM %s h WHERE %s),"
                     " %s.%s %s)", q->name, held, match, table, q->name,
                     back);
    assert(n > 0 && (size_t)n < size);
    (void)n;
}

int store_held_columns(char *sql, size_t size, int per_surface)
{
    size_t len = 0;
    int n = 0;
    sql[0] = '\0';
    for (int k = 0; k < OPTION_QUANTITIES; k++) {
        const struct quantity *q = &option_quantities[k];
        if (q->stored == STORED_AS_HELD || (per_surface && !q->per_surface))
            continue;
        len += (size_t)snprintf(sql + len, size - len, ", %s", q->name);
        assert(len < size);
        n++;
    }
    return n;
}

void store_bind_held(sqlite3_stmt *s, int p, const struct option_totals *t,
                     int per_surface)
{
    for (int k = 0; k < OPTION_QUANTITIES; k++) {
        const struct quantity *q = &option_quantities[k];
        if (q->stored == STORED_AS_HELD || (per_surface && !q->per_surface))
            continue;
        assert(q->field == FIELD_DOUBLE);
        sqlite3_bind_double(s, p++, *(const double *)quantity_field(q, t));
    }
}

static int step_done(struct store *store, sqlite3_stmt *s, const char *doing,
                     struct facet_error *err);

/* Writes row's held values (option_held) beside the row just written,
 * or again over them (an option measured after it was stored). */
static int held_put(struct store *store, int64_t run,
                    const struct option_row *row, struct facet_error *err)
{
    if (store->held_insert == NULL) {
        char columns[512], sql[1024];
        int values = store_held_columns(columns, sizeof columns, 0);
        int len = snprintf(sql, sizeof sql, "INSERT OR REPLACE INTO"
                           " option_held (run, option%s) VALUES (?1, ?2",
                           columns);
        for (int k = 0; k < values; k++)
            len += snprintf(sql + len, sizeof sql - (size_t)len, ", ?%d",
                            3 + k);
        snprintf(sql + len, sizeof sql - (size_t)len, ")");
        int rc = store_prepare(store, sql, &store->held_insert,
                               "storing options", err);
        if (rc != FACET_OK)
            return rc;
    }
    sqlite3_stmt *s = store->held_insert;
    sqlite3_clear_bindings(s);
    sqlite3_bind_int64(s, 1, run);
    sqlite3_bind_int64(s, 2, row->number);
    store_bind_held(s, 3, &row->totals, 0);
    return step_done(store, s, "storing options", err);
}

void store_bind_quantity(sqlite3_stmt *s, int p, const struct quantity *c,
                         const void *field)
{
    if (c->field == FIELD_DOUBLE)
        /* a gap or kink in the column's mm or degrees (quantity_stored) */
        sqlite3_bind_double(s, p,
                            quantity_stored_of_held(c, *(const double *)field));
    else if (c->field == FIELD_INT)
        sqlite3_bind_int(s, p, *(const int *)field);
    else if (c->field == FIELD_INT64)
        sqlite3_bind_int64(s, p, *(const int64_t *)field);
    else if (*(const size_t *)field == TOTALS_UNKNOWN)
        sqlite3_bind_null(s, p);  /* as it was read */
    else
        sqlite3_bind_int64(s, p, (sqlite3_int64)*(const size_t *)field);
}

void store_read_quantity(sqlite3_stmt *s, int c, const struct quantity *col,
                         void *field)
{
    if (col->field == FIELD_DOUBLE)
        /* NULL: a column added after the option was stored. */
        *(double *)field = store_column_or_nan(s, c);
    else if (col->field == FIELD_INT)
        *(int *)field = sqlite3_column_int(s, c);
    else if (col->field == FIELD_INT64)
        *(int64_t *)field = sqlite3_column_int64(s, c);
    else if (sqlite3_column_type(s, c) == SQLITE_NULL)
        /* a count added after the option was stored: not known, never 0 */
        *(size_t *)field = TOTALS_UNKNOWN;
    else
        *(size_t *)field = (size_t)sqlite3_column_int64(s, c);
}

/* Reads a row of the columns of option_columns_sql (SELECT) starting at
 * result column first. */
static void option_from_row(sqlite3_stmt *s, int first,
                            struct option_row *o)
{
    memset(o, 0, sizeof *o);
    int c = first, crowding = -1;
    for (int k = 0; k < OPTION_QUANTITIES; k++) {
        const struct quantity *col = &option_quantities[k];
        if (col->writer == WRITTEN_AS_KEY)
            continue;
        void *field = (char *)o + col->offset;
        if (col->offset == offsetof(struct option_row, crowding))
            *(double *)field = sqlite3_column_double(s, c);
        else
            store_read_quantity(s, c, col, field);
        if (col->offset == offsetof(struct option_row, crowding))
            crowding = c;
        c++;
    }
    /* Crowding is stored as NULL for +infinity: SQLite has no infinity
     * literal a user could compare against. */
    assert(crowding >= 0);
    if (sqlite3_column_type(s, crowding) == SQLITE_NULL && o->rank > 0)
        o->crowding = INFINITY;
}

/* Runs the statement to completion, for statements without rows. */
static int step_done(struct store *store, sqlite3_stmt *s, const char *doing,
                     struct facet_error *err)
{
    int step = sqlite3_step(s);
    sqlite3_reset(s);
    if (step != SQLITE_DONE)
        return store_fail(store, doing, err);
    return FACET_OK;
}

int store_options_put(struct store *store, int64_t run,
                      const struct option_row *rows, size_t n,
                      struct facet_error *err)
{
    return store_options_put_with(store, run, rows, n, NULL, 0, err);
}

int store_project_options_put(struct store *store, int64_t run,
                              const struct option_row *rows, size_t n,
                              const struct option_surface_row *surfaces,
                              size_t nsurfaces, struct facet_error *err)
{
    assert(surfaces != NULL || n == 0 || nsurfaces == 0);
    static const struct option_surface_row none;
    return store_options_put_with(store, run, rows, n,
                                  surfaces ? surfaces : &none, nsurfaces,
                                  err);
}

int store_options_put_with(struct store *store, int64_t run,
                           const struct option_row *rows, size_t n,
                           const struct option_surface_row *surfaces,
                           size_t nsurfaces, struct facet_error *err)
{
    int rc = FACET_OK;
    if (store->option_insert == NULL) {
        char columns[OPTION_COLUMNS_SQL], sql[2 * OPTION_COLUMNS_SQL];
        int values = option_columns_sql(columns, sizeof columns, 1);
        int len = snprintf(sql, sizeof sql,
                           "INSERT OR IGNORE INTO options (run, %s)"
                           " VALUES (?1", columns);
        for (int k = 2; k <= 1 + values; k++)
            len += snprintf(sql + len, sizeof sql - (size_t)len, ", ?%d", k);
        snprintf(sql + len, sizeof sql - (size_t)len, ")");
        rc = store_prepare(store, sql, &store->option_insert,
                           "storing options", err);
        if (rc != FACET_OK)
            return rc;
    }
    rc = store_exec(store, "BEGIN IMMEDIATE", "storing options", err);
    if (rc != FACET_OK)
        return rc;
    int64_t added = 0;
    for (size_t k = 0; k < n && rc == FACET_OK; k++) {
        sqlite3_clear_bindings(store->option_insert);
        option_bind(store->option_insert, run, &rows[k], surfaces != NULL);
        rc = step_done(store, store->option_insert, "storing options", err);
        int fresh = sqlite3_changes(store->db) > 0;
        added += fresh;
        if (rc == FACET_OK && fresh)
            rc = held_put(store, run, &rows[k], err);
        /* An option already stored keeps the rows it has. */
        if (rc == FACET_OK && fresh && surfaces != NULL && nsurfaces > 0)
            rc = store_option_surfaces_insert(store, run, rows[k].number,
                                              surfaces + k * nsurfaces,
                                              nsurfaces, err);
    }
    sqlite3_stmt *count = NULL;
    if (rc == FACET_OK)
        rc = store_prepare(store,
            "UPDATE runs SET options = options + ?2 WHERE id = ?1", &count,
            "storing options", err);
    if (rc == FACET_OK) {
        sqlite3_bind_int64(count, 1, run);
        sqlite3_bind_int64(count, 2, added);
        rc = step_done(store, count, "storing options", err);
    }
    sqlite3_finalize(count);
    if (rc == FACET_OK)
        rc = store_exec(store, "COMMIT", "storing options", err);
    if (rc != FACET_OK)
        sqlite3_exec(store->db, "ROLLBACK", NULL, NULL, NULL);
    return rc;
}

int store_options_measured(struct store *store, int64_t run,
                           const struct option_row *rows, size_t n,
                           struct facet_error *err)
{
    /* The same columns and binding as the INSERT, so that a value is
     * written the one way whether first or again. */
    char columns[OPTION_COLUMNS_SQL], sql[2 * OPTION_COLUMNS_SQL];
    int values = option_columns_sql(columns, sizeof columns, 1);
    int number = 0;
    for (int k = 0, p = 2; k < OPTION_QUANTITIES; k++) {
        const struct quantity *c = &option_quantities[k];
        if (c->writer != WRITTEN_WITH_OPTION)
            continue;
        if (strcmp(c->name, "number") == 0)
            number = p;
        p++;
    }
    assert(number > 0);
    int len = snprintf(sql, sizeof sql, "UPDATE options SET (%s) = (?2",
                       columns);
    for (int k = 3; k <= 1 + values; k++)
        len += snprintf(sql + len, sizeof sql - (size_t)len, ", ?%d", k);
    snprintf(sql + len, sizeof sql - (size_t)len,
             ") WHERE run = ?1 AND number = ?%d", number);
    sqlite3_stmt *s;
    int rc = store_prepare(store, sql, &s, "storing measured options", err);
    if (rc != FACET_OK)
        return rc;
    rc = store_exec(store, "BEGIN IMMEDIATE", "storing measured options",
                    err);
    for (size_t k = 0; k < n && rc == FACET_OK; k++) {
        sqlite3_clear_bindings(s);
        option_bind(s, run, &rows[k], 0);
        rc = step_done(store, s, "storing measured options", err);
        if (rc == FACET_OK && sqlite3_changes(store->db) > 0)
            rc = held_put(store, run, &rows[k], err);
    }
    sqlite3_finalize(s);
    if (rc == FACET_OK)
        rc = store_exec(store, "COMMIT", "storing measured options", err);
    if (rc != FACET_OK)
        sqlite3_exec(store->db, "ROLLBACK", NULL, NULL, NULL);
    return rc;
}

int store_options_get(struct store *store, int64_t run,
                      struct option_row **rows, size_t *n,
                      struct facet_error *err)
{
    /* Run 0 would mean every run to a query; here it is no run. */
    struct option_query q = {run > 0 ? run : -1, 0, NULL, NULL, 0, 0, 0, 0};
    return store_options_query_rows(store, &q, rows, n, err);
}

int store_option_get(struct store *store, int64_t run, int64_t number,
                     struct option_row *row, struct facet_error *err)
{
    /* Prepared once: the workbench reads every row of a page here. */
    if (store->option_get == NULL) {
        char columns[OPTION_COLUMNS_SQL], sql[OPTION_COLUMNS_SQL + 64];
        option_columns_sql(columns, sizeof columns, 0);
        snprintf(sql, sizeof sql, "SELECT %s FROM options"
                 " WHERE run = ?1 AND number = ?2", columns);
        int rc = store_prepare(store, sql, &store->option_get,
                               "reading an option", err);
        if (rc != FACET_OK)
            return rc;
    }
    sqlite3_stmt *s = store->option_get;
    int rc = FACET_OK;
    sqlite3_bind_int64(s, 1, run);
    sqlite3_bind_int64(s, 2, number);
    int step = sqlite3_step(s);
    if (step == SQLITE_ROW)
        option_from_row(s, 0, row);
    else if (step == SQLITE_DONE)
        rc = facet_error_set(err, FACET_EINPUT,
            "%s: run %lld has no option %lld", store->path, (long long)run,
            (long long)number);
    else
        rc = store_fail(store, "reading an option", err);
    sqlite3_reset(s);  /* holds no read transaction between calls */
    return rc;
}

int store_front_bounds(struct store *store, int64_t run,
                       struct front_bounds *out, struct facet_error *err)
{
    memset(out, 0, sizeof *out);
    sqlite3_stmt *s;
    /* The threshold's bounds compare to a thousandth of a millimetre, the
     * precision options are drawn at. */
    int rc = store_prepare(store,
        "SELECT count(*),"
        " coalesce(sum(o.nu = r.u_min), 0), coalesce(sum(o.nu = r.u_max), 0),"
        " coalesce(sum(o.nv = r.v_min), 0), coalesce(sum(o.nv = r.v_max), 0),"
        " coalesce(sum(abs(o.threshold_mm - r.threshold_min_mm) < 5e-4), 0),"
        " coalesce(sum(abs(o.threshold_mm - r.threshold_max_mm) < 5e-4), 0)"
        " FROM options o JOIN runs r ON r.id = o.run"
        " WHERE o.run = ?1 AND o.rank = 1", &s, "reading the front", err);
    if (rc != FACET_OK)
        return rc;
    sqlite3_bind_int64(s, 1, run);
    if (sqlite3_step(s) == SQLITE_ROW) {
        out->pareto = sqlite3_column_int64(s, 0);
        for (int k = 0; k < FRONT_BOUNDS; k++)
            out->at[k] = sqlite3_column_int64(s, 1 + k);
    } else {
        rc = store_fail(store, "reading the front", err);
    }
    sqlite3_finalize(s);
    return rc;
}

int store_options_set_pareto(struct store *store, int64_t run,
                             const int64_t *numbers, const int *rank,
                             const double *crowding, size_t n, int64_t knee,
                             double hypervolume, struct facet_error *err)
{
    sqlite3_stmt *option = NULL, *summary = NULL;
    int rc = store_exec(store, "BEGIN IMMEDIATE", "storing the front", err);
    if (rc != FACET_OK)
        return rc;
    rc = store_prepare(store,
        "UPDATE options SET rank = ?3, crowding = ?4, knee = ?5"
        " WHERE run = ?1 AND number = ?2", &option, "storing the front",
        err);
    for (size_t k = 0; k < n && rc == FACET_OK; k++) {
        sqlite3_bind_int64(option, 1, run);
        sqlite3_bind_int64(option, 2, numbers[k]);
        sqlite3_bind_int(option, 3, rank[k]);
        store_bind_or_null(option, 4, crowding[k]);
        sqlite3_bind_int(option, 5, numbers[k] == knee);
        rc = step_done(store, option, "storing the front", err);
    }
    if (rc == FACET_OK)
        rc = store_prepare(store,
            "UPDATE runs SET knee = nullif(?2, 0), hypervolume = ?3,"
            " options = (SELECT count(*) FROM options WHERE run = ?1),"
            " pareto_options = (SELECT count(*) FROM options"
            "  WHERE run = ?1 AND rank = 1),"
            " best_cost = (SELECT min(cost) FROM options"
            "  WHERE run = ?1 AND feasible)"
            " WHERE id = ?1", &summary, "storing the front", err);
    if (rc == FACET_OK) {
        sqlite3_bind_int64(summary, 1, run);
        sqlite3_bind_int64(summary, 2, knee);
        store_bind_or_null(summary, 3, hypervolume);
        rc = step_done(store, summary, "storing the front", err);
    }
    sqlite3_finalize(option);
    sqlite3_finalize(summary);
    if (rc == FACET_OK)
        rc = store_exec(store, "COMMIT", "storing the front", err);
    if (rc != FACET_OK)
        sqlite3_exec(store->db, "ROLLBACK", NULL, NULL, NULL);
    return rc;
}

/* --- queries --- */

const char store_rank_sql[] = "ifnull(\"rank\", 0)";

const char store_feasible_sql[] = "(\"feasible\" IS 1)";

const char store_crowding_sql[] =
    "ifnull(\"crowding\", CASE WHEN ifnull(\"rank\", 0) > 0 THEN 1e999"
    " ELSE 0 END)";

/* The column of option_quantities named by the length bytes at name,
 * in any case, or NULL. */
static const struct quantity *sort_column(const char *name,
                                               size_t length)
{
    for (int k = 0; k < OPTION_QUANTITIES; k++)
        if (strlen(option_quantities[k].name) == length &&
            strncasecmp(option_quantities[k].name, name, length) == 0)
            return &option_quantities[k];
    return NULL;
}

/* Appends the ORDER BY list for sort ("cost,dp_area") to sql, after
 * feasibility (the feasible first) with feasible_first and a sort. */
static int order_by(const char *sort, int descending, int feasible_first,
                    char *sql, size_t size, struct facet_error *err)
{
    const char *direction = descending ? " DESC" : "";
    size_t len = strlen(sql);
    const char *p = sort ? sort : "";
    if (feasible_first && *p != '\0')
        len += (size_t)snprintf(sql + len, size - len, "%s DESC, ",
                                store_feasible_sql);
    while (*p != '\0') {
        size_t n = strcspn(p, ",");
        while (n > 0 && p[0] == ' ') {
            p++;
            n--;
        }
        while (n > 0 && p[n - 1] == ' ')
            n--;
        if (n == 0 || sort_column(p, n) == NULL) {
            char hint[960];
            filter_column_hint(p, n, 0, hint, sizeof hint);
            return facet_error_about(err, FACET_SETTING_SORT, FACET_EINPUT,
                "unknown column '%.*s' (%s)", (int)(n < 40 ? n : 40), p,
                hint);
        }
        if (n == 8 && strncasecmp(p, "crowding", 8) == 0)
            len += (size_t)snprintf(sql + len, size - len, "%s%s, ",
                                    store_crowding_sql, direction);
        else
            len += (size_t)snprintf(sql + len, size - len, "\"%.*s\"%s, ",
                                    (int)n, p, direction);
        if (len >= size)
            return facet_error_about(err, FACET_SETTING_SORT, FACET_EINPUT,
                                     "too long");
        p += strcspn(p, ",");
        if (*p == ',')
            p++;
    }
    snprintf(sql + len, size - len, "run%s, number%s", direction, direction);
    return FACET_OK;
}

int store_options_sort_check(const char *sort, struct facet_error *err)
{
    char sql[2048] = "";
    return order_by(sort, 0, 0, sql, sizeof sql, err);
}

/* The sort keys of a query, as option_quantities names, with each
 * key's tie tolerance (core/search/ties.h) over the options of the query's
 * run, or of every run. */
struct sort_keys {
    const char *column[32];
    double tolerance[32];
    size_t n;
};

/* The tolerance of column over run's options (0 = every run's). */
static int column_tolerance(struct store *store, int64_t run,
                            const char *column, double *tolerance,
                            struct facet_error *err)
{
    double ends[2] = {INFINITY, -INFINITY};
    struct run_info *runs = NULL;
    size_t count = 1;
    int rc = FACET_OK;
    if (run == 0)
        rc = store_run_list(store, &runs, &count, err);
    for (size_t k = 0; rc == FACET_OK && k < count; k++) {
        double low, high;
        rc = store_run_column_range(store, runs ? runs[k].id : run, column,
                                    &low, &high, err);
        if (rc == FACET_OK && !isnan(low)) {
            ends[0] = fmin(ends[0], low);
            ends[1] = fmax(ends[1], high);
        }
    }
    free(runs);
    *tolerance = ties_tolerance(ends, 2, 1);
    return rc;
}

static int sort_keys_of(struct store *store, const struct option_query *q,
                        struct sort_keys *keys, struct facet_error *err)
{
    keys->n = 0;
    const char *p = q->sort ? q->sort : "";
    while (*p != '\0') {
        size_t n = strcspn(p, ",");
        const char *name = p;
        while (n > 0 && name[0] == ' ') {
            name++;
            n--;
        }
        while (n > 0 && name[n - 1] == ' ')
            n--;
        const struct quantity *c = sort_column(name, n);
        if (c != NULL && keys->n < 30)
            keys->column[keys->n++] = c->name;
        p += strcspn(p, ",");
        if (*p == ',')
            p++;
    }
    for (size_t k = 0; k < keys->n; k++) {
        keys->tolerance[k] = 0;
        int rc = strcmp(keys->column[k], "run") == 0
                     ? FACET_OK
                     : column_tolerance(store, q->run, keys->column[k],
                                        &keys->tolerance[k], err);
        if (rc != FACET_OK)
            return rc;
    }
    /* Then run and number, exactly, as the SQL order ends. */
    keys->column[keys->n] = "run";
    keys->tolerance[keys->n++] = 0;
    keys->column[keys->n] = "number";
    keys->tolerance[keys->n++] = 0;
    return FACET_OK;
}

/* The rows SQL gave whose first sort key is one tie class so far (each
 * within the tolerance of the one before), waiting to be put in order by
 * the other keys. */
struct tie_group {
    const struct option_query *q;
    const struct sort_keys *keys;
    struct option_row *rows;
    int64_t *run;
    double *values;          /* n x keys->n */
    size_t *order;
    size_t n, capacity;
    int64_t skipped, given;  /* for offset and limit */
    int (*row)(void *context, int64_t run, const struct option_row *option);
    void *context;
    int stopped;
};

/* A value not known (NULL, NaN in the row) is -infinity here: SQLite
 * orders NULL before every number, so the tie classes keep its order, and
 * all the options without the value are one class, ordered by the next
 * keys. */
static double key_value(const struct option_row *o, int64_t run,
                        const char *column)
{
    double value = strcmp(column, "run") == 0
                       ? (double)run : option_quantity_value(o, column);
    return isnan(value) ? -INFINITY : value;
}

/* Hands the group's rows on in the order of their keys with ties. */
static int flush_group(struct tie_group *g)
{
    size_t m = g->keys->n;
    if (ties_order(g->values, g->n, m, g->keys->tolerance,
                   g->q->descending, g->order, NULL) != 0)
        return -1;
    for (size_t k = 0; k < g->n && !g->stopped; k++) {
        size_t i = g->order[k];
        if (g->skipped < g->q->offset) {
            g->skipped++;
            continue;
        }
        if (g->row(g->context, g->run[i], &g->rows[i]) != 0 ||
            (g->q->limit > 0 && ++g->given >= g->q->limit))
            g->stopped = 1;
    }
    g->n = 0;
    return 0;
}

/* Takes one row from SQL (in the order of the exact values). */
static int group_row(struct tie_group *g, int64_t run,
                     const struct option_row *o)
{
    size_t m = g->keys->n;
    double first = key_value(o, run, g->keys->column[0]);
    if (g->n > 0) {
        double last = g->values[(g->n - 1) * m];
        /* feasible first: the infeasible ones start a class of their own */
        int parted = g->q->feasible_first &&
                     (g->rows[g->n - 1].totals.feasible == 1) !=
                         (o->totals.feasible == 1);
        if (parted ||
            !(first == last || (isfinite(first) && isfinite(last) &&
                                fabs(first - last) <= g->keys->tolerance[0])))
            if (flush_group(g) != 0)
                return -1;
    }
    if (g->stopped)
        return 0;
    if (g->n == g->capacity) {
        size_t capacity = g->capacity ? 2 * g->capacity : 64;
        struct option_row *rows = realloc(g->rows, capacity * sizeof *rows);
        if (rows != NULL)
            g->rows = rows;
        int64_t *runs = realloc(g->run, capacity * sizeof *runs);
        if (runs != NULL)
            g->run = runs;
        double *values = realloc(g->values, capacity * m * sizeof *values);
        if (values != NULL)
            g->values = values;
        size_t *order = realloc(g->order, capacity * sizeof *order);
        if (order != NULL)
            g->order = order;
        if (rows == NULL || runs == NULL || values == NULL || order == NULL)
            return -1;
        g->capacity = capacity;
    }
    g->rows[g->n] = *o;
    g->run[g->n] = run;
    for (size_t k = 0; k < m; k++)
        g->values[g->n * m + k] = key_value(o, run, g->keys->column[k]);
    g->n++;
    return 0;
}

int store_options_query(struct store *store, const struct option_query *q,
                        int (*row)(void *context, int64_t run,
                                   const struct option_row *option),
                        void *context, struct facet_error *err)
{
    /* ?1 run (0 = all), ?2 limit, ?3 offset; the filter's from ?4. */
    char *where = NULL;
    if (q->where != NULL && (where = filter_sql(q->where, 4)) == NULL)
        return facet_error_set(err, FACET_EWORK, "out of memory");
    size_t size = OPTION_COLUMNS_SQL + 1024 + (where ? strlen(where) : 0) +
                  (q->sort ? 4 * strlen(q->sort) : 0);
    char *sql = malloc(size);
    if (sql == NULL) {
        free(where);
        return facet_error_set(err, FACET_EWORK, "out of memory");
    }
    char columns[OPTION_COLUMNS_SQL];
    option_columns_sql(columns, sizeof columns, 0);
    snprintf(sql, size, "SELECT run, %s FROM options"
             " WHERE (?1 = 0 OR run = ?1)%s AND (%s) ORDER BY ",
             columns, q->pareto_only ? " AND rank = 1" : "",
             where ? where : "1");
    free(where);
    int rc = order_by(q->sort, q->descending, q->feasible_first, sql, size,
                      err);
    if (rc == FACET_OK)
        snprintf(sql + strlen(sql), size - strlen(sql),
                 " LIMIT ?2 OFFSET ?3");
    /* Sorted by columns, SQL orders by their exact values, and values
     * equal but for rounding (ties.h) come out in the order of their
     * rounding. So the rows come in SQL's order, each tie class of the
     * first key is gathered, and put in order by the keys with ties
     * before it is handed on; limit and offset count after that. */
    struct sort_keys keys;
    struct tie_group group = {.q = q, .keys = &keys, .row = row,
                              .context = context};
    int ties = q->sort != NULL && q->sort[0] != '\0';
    if (rc == FACET_OK && ties)
        rc = sort_keys_of(store, q, &keys, err);
    sqlite3_stmt *s = NULL;
    if (rc == FACET_OK)
        rc = store_prepare(store, sql, &s, "querying options", err);
    free(sql);
    if (rc != FACET_OK)
        return rc;
    sqlite3_bind_int64(s, 1, q->run);
    sqlite3_bind_int64(s, 2, q->limit > 0 && !ties ? q->limit : -1);
    sqlite3_bind_int64(s, 3, q->offset > 0 && !ties ? q->offset : 0);
    if (q->where != NULL)
        for (size_t k = 0; k < filter_param_count(q->where); k++)
            sqlite3_bind_double(s, 4 + (int)k, filter_param(q->where, k));
    int step, out_of_memory = 0;
    struct option_row option;
    while ((step = sqlite3_step(s)) == SQLITE_ROW) {
        option_from_row(s, 1, &option);
        int64_t run = sqlite3_column_int64(s, 0);
        if (ties) {
            out_of_memory = group_row(&group, run, &option) != 0;
            if (out_of_memory || group.stopped) {
                step = SQLITE_DONE;
                break;
            }
        } else if (row(context, run, &option) != 0) {
            step = SQLITE_DONE;
            break;
        }
    }
    if (step != SQLITE_DONE)
        rc = store_fail(store, "querying options", err);
    else if (ties && !out_of_memory && !group.stopped)
        out_of_memory = flush_group(&group) != 0;
    if (rc == FACET_OK && out_of_memory)
        rc = facet_error_set(err, FACET_EWORK, "out of memory (sorting)");
    sqlite3_finalize(s);
    free(group.rows);
    free(group.run);
    free(group.values);
    free(group.order);
    return rc;
}

/* A query's rows, gathered into a growing array. */
struct gathered_rows {
    struct option_row *rows;
    size_t n, capacity;
    int out_of_memory;
};

static int gather_row(void *context, int64_t run, const struct option_row *o)
{
    (void)run;
    struct gathered_rows *g = context;
    if (g->n == g->capacity) {
        size_t capacity = g->capacity ? 2 * g->capacity : 256;
        struct option_row *grown = realloc(g->rows,
                                           capacity * sizeof *grown);
        if (grown == NULL) {
            g->out_of_memory = 1;
            return 1;
        }
        g->rows = grown;
        g->capacity = capacity;
    }
    g->rows[g->n++] = *o;
    return 0;
}

int store_options_query_rows(struct store *store,
                             const struct option_query *q,
                             struct option_row **rows, size_t *n,
                             struct facet_error *err)
{
    struct gathered_rows g = {NULL, 0, 0, 0};
    int rc = store_options_query(store, q, gather_row, &g, err);
    if (rc == FACET_OK && g.out_of_memory)
        rc = facet_error_set(err, FACET_EWORK, "out of memory");
    if (rc != FACET_OK) {
        free(g.rows);
        g.rows = NULL;
        g.n = 0;
    }
    *rows = g.rows;
    *n = g.n;
    return rc;
}
