/*
 * store_project.c: what a project run adds to the store (schema v8): the
 * run's module range, its surfaces, and each option's rows per surface.
 * See store.h.
 */
#include "store_internal.h"

#include <assert.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/base/text.h"
#include "core/quantity/quantity.h"

int store_run_is_project(const struct run_info *run)
{
    return run->module_w_step > 0;
}

void store_module_from_row(sqlite3_stmt *stmt, int col, struct run_info *run)
{
    run->module_w_min = store_column_or_nan(stmt, col++);
    run->module_w_max = store_column_or_nan(stmt, col++);
    run->module_w_step = store_column_or_nan(stmt, col++);
    run->module_h_min = store_column_or_nan(stmt, col++);
    run->module_h_max = store_column_or_nan(stmt, col++);
    run->module_h_step = store_column_or_nan(stmt, col++);
}

int store_run_set_module(struct store *store, const struct run_info *run,
                         struct facet_error *err)
{
    int project = store_run_is_project(run);
    sqlite3_stmt *s;
    int rc = store_prepare(store,
        "UPDATE runs SET module_w_min = ?2, module_w_max = ?3,"
        " module_w_step = ?4, module_h_min = ?5, module_h_max = ?6,"
        " module_h_step = ?7 WHERE id = ?1", &s, "creating a run", err);
    if (rc != FACET_OK)
        return rc;
    sqlite3_bind_int64(s, 1, run->id);
    const double value[6] = {run->module_w_min, run->module_w_max,
                             run->module_w_step, run->module_h_min,
                             run->module_h_max, run->module_h_step};
    for (int k = 0; k < 6; k++)
        store_bind_or_null(s, 2 + k, project ? value[k] : NAN);
    if (sqlite3_step(s) != SQLITE_DONE)
        rc = store_fail(store, "creating a run", err);
    sqlite3_finalize(s);
    return rc;
}

int store_surfaces_put(struct store *store, int64_t run,
                       const struct surface_row *rows, size_t n,
                       struct facet_error *err)
{
    const char *doing = "storing a project's surfaces";
    int rc = store_exec(store, "BEGIN IMMEDIATE", doing, err);
    if (rc != FACET_OK)
        return rc;
    sqlite3_stmt *s = NULL;
    rc = store_prepare(store,
        "INSERT INTO surfaces (run, surface, name, file, file_sha256,"
        " triangles, area, u_length, v_length, uv_method, grid_nu, grid_nv)"
        " VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10, ?11, ?12)", &s, doing, err);
    for (size_t k = 0; rc == FACET_OK && k < n; k++) {
        const struct surface_row *r = &rows[k];
        sqlite3_reset(s);
        sqlite3_bind_int64(s, 1, run);
        sqlite3_bind_int64(s, 2, (int64_t)k);
        sqlite3_bind_text(s, 3, r->name, -1, SQLITE_TRANSIENT);
        sqlite3_bind_text(s, 4, r->file, -1, SQLITE_TRANSIENT);
        sqlite3_bind_text(s, 5, r->file_sha256, -1, SQLITE_TRANSIENT);
        sqlite3_bind_int64(s, 6, r->triangles);
        sqlite3_bind_double(s, 7, r->area);
        sqlite3_bind_double(s, 8, r->u_length);
        sqlite3_bind_double(s, 9, r->v_length);
        sqlite3_bind_text(s, 10, param_method_name(r->uv_method), -1,
                          SQLITE_STATIC);
        if (r->grid_nu > 0) {
            sqlite3_bind_int(s, 11, r->grid_nu);
            sqlite3_bind_int(s, 12, r->grid_nv);
        } else {
            sqlite3_bind_null(s, 11);
            sqlite3_bind_null(s, 12);
        }
        if (sqlite3_step(s) != SQLITE_DONE)
            rc = store_fail(store, doing, err);
    }
    sqlite3_finalize(s);
    if (rc == FACET_OK)
        rc = store_exec(store, "COMMIT", doing, err);
    if (rc != FACET_OK)
        sqlite3_exec(store->db, "ROLLBACK", NULL, NULL, NULL);
    return rc;
}

static void copy_text(char *to, size_t size, sqlite3_stmt *stmt, int col)
{
    const unsigned char *text = sqlite3_column_text(stmt, col);
    snprintf(to, size, "%s", text ? (const char *)text : "");
}

int store_surfaces_get(struct store *store, int64_t run,
                       struct surface_row **rows, size_t *n,
                       struct facet_error *err)
{
    const char *doing = "reading a project's surfaces";
    *rows = NULL;
    *n = 0;
    sqlite3_stmt *s;
    int rc = store_prepare(store,
        "SELECT name, file, file_sha256, triangles, area, u_length,"
        " v_length, uv_method, coalesce(grid_nu, 0), coalesce(grid_nv, 0)"
        " FROM surfaces WHERE run = ?1"
        " ORDER BY surface", &s, doing, err);
    if (rc != FACET_OK)
        return rc;
    sqlite3_bind_int64(s, 1, run);
    size_t capacity = 0;
    int step;
    while ((step = sqlite3_step(s)) == SQLITE_ROW) {
        if (*n == capacity) {
            capacity = capacity ? 2 * capacity : 16;
            struct surface_row *grown = realloc(*rows,
                                                capacity * sizeof *grown);
            if (grown == NULL) {
                rc = facet_error_set(err, FACET_EWORK, "out of memory");
                break;
            }
            *rows = grown;
        }
        struct surface_row *r = &(*rows)[(*n)++];
        memset(r, 0, sizeof *r);
        copy_text(r->name, sizeof r->name, s, 0);
        copy_text(r->file, sizeof r->file, s, 1);
        copy_text(r->file_sha256, sizeof r->file_sha256, s, 2);
        r->triangles = sqlite3_column_int64(s, 3);
        r->area = sqlite3_column_double(s, 4);
        r->u_length = sqlite3_column_double(s, 5);
        r->v_length = sqlite3_column_double(s, 6);
        r->grid_nu = sqlite3_column_int(s, 8);
        r->grid_nv = sqlite3_column_int(s, 9);
        const unsigned char *uv = sqlite3_column_text(s, 7);
        if (uv == NULL ||
            param_method_parse((const char *)uv, &r->uv_method) != 0) {
            /* The file's own text, made one line (error.h). */
            char shown[64];
            text_for_terminal(uv ? (const char *)uv : "", shown,
                              sizeof shown);
            rc = facet_error_set(err, FACET_EINPUT,
                "run %lld: surfaces.uv_method holds '%s', which this Facet "
                "does not know", (long long)run, shown);
        }
        if (rc != FACET_OK)
            break;
    }
    if (rc == FACET_OK && step != SQLITE_DONE && step != SQLITE_ROW)
        rc = store_fail(store, doing, err);
    sqlite3_finalize(s);
    if (rc != FACET_OK) {
        free(*rows);
        *rows = NULL;
        *n = 0;
    }
    return rc;
}

/* The columns of option_surfaces after (run, option, surface) into sql
 * (size bytes): the row's own (nu, nv, moulds_used, joints), then every
 * quantity kept per surface (quantity.h's per_surface), in the registry's
 * order, as surface_bind writes and surface_from_row reads them; to
 * select, a gap or kink as core holds it, from option_surface_held
 * (quantity.h's quantity_stored). Returns how many. */
static int surface_columns_sql(char *sql, size_t size, int select)
{
    size_t len = (size_t)snprintf(sql, size, "nu, nv, moulds_used, joints");
    int n = 4;
    for (int k = 0; k < OPTION_QUANTITIES; k++) {
        const struct quantity *q = &option_quantities[k];
        if (!q->per_surface)
            continue;
        assert(quantity_in_totals(q));
        if (select && q->stored != STORED_AS_HELD) {
            char held[400];
            store_held_sql(held, sizeof held, q, "option_surface_held",
                           "h.run = option_surfaces.run"
                           " AND h.option = option_surfaces.option"
                           " AND h.surface = option_surfaces.surface",
                           "option_surfaces");
            len += (size_t)snprintf(sql + len, size - len, ", %s", held);
        } else
            len += (size_t)snprintf(sql + len, size - len, ", %s", q->name);
        assert(len < size);
        n++;
    }
    return n;
}

#define SURFACE_COLUMNS_SQL 4096

int store_option_surfaces_insert(struct store *store, int64_t run,
                                 int64_t number,
                                 const struct option_surface_row *rows,
                                 size_t n, struct facet_error *err)
{
    const char *doing = "storing an option's surfaces";
    char columns[SURFACE_COLUMNS_SQL], sql[SURFACE_COLUMNS_SQL + 1024];
    int values = surface_columns_sql(columns, sizeof columns, 0);
    int len = snprintf(sql, sizeof sql,
                       "INSERT INTO option_surfaces (run, option, surface, "
                       "%s) VALUES (?1, ?2, ?3", columns);
    for (int k = 0; k < values; k++)
        len += snprintf(sql + len, sizeof sql - (size_t)len, ", ?%d", 4 + k);
    snprintf(sql + len, sizeof sql - (size_t)len, ")");
    sqlite3_stmt *s, *held = NULL;
    int rc = store_prepare(store, sql, &s, doing, err);
    /* ... and its gaps and kinks as core holds them (quantity_stored) */
    values = store_held_columns(columns, sizeof columns, 1);
    /* Over any left by rows deleted without their foreign keys (sqlite3's
     * shell has them off): a resume writes the option's surfaces again. */
    len = snprintf(sql, sizeof sql, "INSERT OR REPLACE INTO"
                   " option_surface_held (run, option, surface%s)"
                   " VALUES (?1, ?2, ?3", columns);
    for (int k = 0; k < values; k++)
        len += snprintf(sql + len, sizeof sql - (size_t)len, ", ?%d", 4 + k);
    snprintf(sql + len, sizeof sql - (size_t)len, ")");
    if (rc == FACET_OK)
        rc = store_prepare(store, sql, &held, doing, err);
    for (size_t i = 0; rc == FACET_OK && i < n; i++) {
        const struct option_surface_row *r = &rows[i];
        sqlite3_reset(s);
        int p = 1;
        sqlite3_bind_int64(s, p++, run);
        sqlite3_bind_int64(s, p++, number);
        sqlite3_bind_int64(s, p++, (int64_t)i);
        sqlite3_bind_int(s, p++, r->nu);
        sqlite3_bind_int(s, p++, r->nv);
        sqlite3_bind_int64(s, p++, r->moulds_used);
        sqlite3_bind_int64(s, p++, r->joints);
        for (int k = 0; k < OPTION_QUANTITIES; k++)
            if (option_quantities[k].per_surface)
                store_bind_quantity(s, p++, &option_quantities[k],
                                    quantity_field(&option_quantities[k],
                                                   &r->totals));
        if (sqlite3_step(s) != SQLITE_DONE) {
            rc = store_fail(store, doing, err);
            break;
        }
        sqlite3_reset(held);
        sqlite3_bind_int64(held, 1, run);
        sqlite3_bind_int64(held, 2, number);
        sqlite3_bind_int64(held, 3, (int64_t)i);
        store_bind_held(held, 4, &r->totals, 1);
        if (sqlite3_step(held) != SQLITE_DONE)
            rc = store_fail(store, doing, err);
    }
    sqlite3_finalize(s);
    sqlite3_finalize(held);
    return rc;
}

int store_option_surfaces_get(struct store *store, int64_t run,
                              int64_t number,
                              struct option_surface_row **rows, size_t *n,
                              struct facet_error *err)
{
    const char *doing = "reading an option's surfaces";
    *rows = NULL;
    *n = 0;
    sqlite3_stmt *s;
    char columns[SURFACE_COLUMNS_SQL], sql[SURFACE_COLUMNS_SQL + 256];
    surface_columns_sql(columns, sizeof columns, 1);
    snprintf(sql, sizeof sql, "SELECT %s FROM option_surfaces"
             " WHERE run = ?1 AND option = ?2 ORDER BY surface", columns);
    int rc = store_prepare(store, sql, &s, doing, err);
    if (rc != FACET_OK)
        return rc;
    sqlite3_bind_int64(s, 1, run);
    sqlite3_bind_int64(s, 2, number);
    size_t capacity = 0;
    int step;
    while ((step = sqlite3_step(s)) == SQLITE_ROW) {
        if (*n == capacity) {
            capacity = capacity ? 2 * capacity : 16;
            struct option_surface_row *grown =
                realloc(*rows, capacity * sizeof *grown);
            if (grown == NULL) {
                rc = facet_error_set(err, FACET_EWORK, "out of memory");
                break;
            }
            *rows = grown;
        }
        struct option_surface_row *r = &(*rows)[(*n)++];
        memset(r, 0, sizeof *r);
        int c = 0;
        r->nu = sqlite3_column_int(s, c++);
        r->nv = sqlite3_column_int(s, c++);
        r->moulds_used = sqlite3_column_int64(s, c++);
        r->joints = sqlite3_column_int64(s, c++);
        for (int k = 0; k < OPTION_QUANTITIES; k++)
            if (option_quantities[k].per_surface)
                store_read_quantity(s, c++, &option_quantities[k],
                                    quantity_field_to_set(
                                        &option_quantities[k], &r->totals));
    }
    if (rc == FACET_OK && step != SQLITE_DONE)
        rc = store_fail(store, doing, err);
    sqlite3_finalize(s);
    if (rc != FACET_OK) {
        free(*rows);
        *rows = NULL;
        *n = 0;
    }
    return rc;
}
