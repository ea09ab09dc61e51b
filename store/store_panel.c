/*
 * store_panel.c: the panels of the options a designer looks at (the
 * panel_sets and panels tables). See store.h.
 */
#include "store_internal.h"
#include "core/base/units.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static const char *const sp_surface_name[] = {NULL, "cylinder", "cone"};

/* Binds fit into the 13 columns from c (sp_surface .. sp_half_angle, the
 * half-angle in degrees as worst_kink, then sp_bending_radius); returns
 * the next column. */
static int bind_sp_fit(sqlite3_stmt *s, int c, const struct panel_sp_fit *fit)
{
    if (fit->shape == PANEL_SP_NONE) {
        for (int k = 0; k < 13; k++)
            sqlite3_bind_null(s, c++);
        return c;
    }
    sqlite3_bind_text(s, c++, sp_surface_name[fit->shape], -1,
                      SQLITE_STATIC);
    for (int d = 0; d < 3; d++)
        store_bind_or_null(s, c++, fit->axis_point[d]);
    for (int d = 0; d < 3; d++)
        store_bind_or_null(s, c++, fit->direction[d]);
    store_bind_or_null(s, c++, fit->radius);
    for (int d = 0; d < 3; d++)
        store_bind_or_null(s, c++, fit->apex[d]);
    store_bind_or_null(s, c++, units_deg(fit->half_angle));
    store_bind_or_null(s, c++, fit->bending_radius);
    return c;
}

/* The fit bind_sp_fit stored, from column c; returns the next column. A
 * panel stored before schema v11, or not built on a fit: shape NONE;
 * before v13: no bending radius (NaN). */
static int read_sp_fit(sqlite3_stmt *s, int c, struct panel_sp_fit *fit)
{
    const char *name = (const char *)sqlite3_column_text(s, c++);
    fit->shape = PANEL_SP_NONE;
    for (int k = PANEL_SP_CYLINDER; name != NULL && k <= PANEL_SP_CONE; k++)
        if (strcmp(name, sp_surface_name[k]) == 0)
            fit->shape = (enum panel_sp_shape)k;
    for (int d = 0; d < 3; d++)
        fit->axis_point[d] = store_column_or_nan(s, c++);
    for (int d = 0; d < 3; d++)
        fit->direction[d] = store_column_or_nan(s, c++);
    fit->radius = store_column_or_nan(s, c++);
    for (int d = 0; d < 3; d++)
        fit->apex[d] = store_column_or_nan(s, c++);
    fit->half_angle = units_rad_of_deg(store_column_or_nan(s, c++));
    fit->bending_radius = store_column_or_nan(s, c++);
    return c;
}

int store_panels_put(struct store *store, int64_t run, int64_t option,
                     const struct panelization *p, struct facet_error *err)
{
    return store_panels_put_stoppable(store, run, option, p, NULL, err);
}

/* Panels written between two questions to the stop: a million panels
 * take seconds to write. */
#define PANELS_BETWEEN_STOPS 4096

int store_panels_put_stoppable(struct store *store, int64_t run,
                               int64_t option, const struct panelization *p,
                               const struct facet_stop *stop,
                               struct facet_error *err)
{
    sqlite3_stmt *set = NULL, *panel = NULL;
    int rc = store_exec(store, "BEGIN IMMEDIATE", "storing panels", err);
    if (rc != FACET_OK)
        return rc;
    /* Replacing the set cascades to its old panels. */
    rc = store_prepare(store,
        "INSERT OR REPLACE INTO panel_sets (run, option, nu, nv, umin, vmin,"
        " umax, vmax, stored) VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9)",
        &set, "storing panels", err);
    if (rc == FACET_OK) {
        char now[32];
        store_now(now);
        sqlite3_bind_int64(set, 1, run);
        sqlite3_bind_int64(set, 2, option);
        sqlite3_bind_int(set, 3, p->nu);
        sqlite3_bind_int(set, 4, p->nv);
        sqlite3_bind_double(set, 5, p->umin);
        sqlite3_bind_double(set, 6, p->vmin);
        sqlite3_bind_double(set, 7, p->umax);
        sqlite3_bind_double(set, 8, p->vmax);
        sqlite3_bind_text(set, 9, now, -1, SQLITE_TRANSIENT);
        if (sqlite3_step(set) != SQLITE_DONE)
            rc = store_fail(store, "storing panels", err);
    }
    if (rc == FACET_OK)
        rc = store_prepare(store,
            "INSERT INTO panels (run, option, i, j, class, type, area,"
            " uv_area, deviation, k1, k2, K, H, eps, p_dist, diameter,"
            " trimmed, corner_planarity, price, cost, centroid_x,"
            " centroid_y, centroid_z, normal_x, normal_y, normal_z,"
            " c0_x, c0_y, c0_z, c1_x, c1_y, c1_z, c2_x, c2_y, c2_z,"
            " c3_x, c3_y, c3_z, mould_family, built_type, sp_deviation,"
            " worst_gap, worst_gap_side, worst_kink, best_cylinder,"
            " best_cone, misfit_reason, sp_surface, sp_axis_x, sp_axis_y,"
            " sp_axis_z, sp_direction_x, sp_direction_y, sp_direction_z,"
            " sp_radius, sp_apex_x, sp_apex_y, sp_apex_z, sp_half_angle,"
            " sp_bending_radius, corner_distance, corner_moved)"
            " VALUES (?1, ?2, ?3, ?4, ?5,"
            " ?6, ?7, ?8, ?9, ?10, ?11, ?12, ?13, ?14, ?15, ?16, ?17, ?18,"
            " ?19, ?20, ?21, ?22, ?23, ?24, ?25, ?26, ?27, ?28, ?29, ?30,"
            " ?31, ?32, ?33, ?34, ?35, ?36, ?37, ?38, ?39, ?40, ?41, ?42,"
            " ?43, ?44, ?45, ?46, ?47, ?48, ?49, ?50, ?51, ?52, ?53, ?54,"
            " ?55, ?56, ?57, ?58, ?59, ?60, ?61, ?62)", &panel,
            "storing panels",
            err);
    for (size_t k = 0; k < p->npanels && rc == FACET_OK; k++) {
        if (k % PANELS_BETWEEN_STOPS == 0 &&
            (rc = facet_stop_check(stop, err)) != FACET_OK)
            break;
        const struct panel *x = &p->panels[k];
        int c = 1;
        sqlite3_bind_int64(panel, c++, run);
        sqlite3_bind_int64(panel, c++, option);
        sqlite3_bind_int(panel, c++, x->i);
        sqlite3_bind_int(panel, c++, x->j);
        sqlite3_bind_text(panel, c++, panel_class_name(x->class), -1,
                          SQLITE_STATIC);
        sqlite3_bind_text(panel, c++, panel_type_name(x->type), -1,
                          SQLITE_STATIC);
        sqlite3_bind_double(panel, c++, x->area);
        sqlite3_bind_double(panel, c++, x->uv_area);
        sqlite3_bind_double(panel, c++, x->deviation);
        sqlite3_bind_double(panel, c++, x->k1);
        sqlite3_bind_double(panel, c++, x->k2);
        sqlite3_bind_double(panel, c++, x->K);
        sqlite3_bind_double(panel, c++, x->H);
        sqlite3_bind_double(panel, c++, x->curvature_tol);
        sqlite3_bind_double(panel, c++, x->p_dist);
        sqlite3_bind_double(panel, c++, x->diameter);
        sqlite3_bind_int(panel, c++, x->trimmed);
        store_bind_or_null(panel, c++, x->corner_planarity);
        sqlite3_bind_double(panel, c++, x->price);
        sqlite3_bind_double(panel, c++, x->cost);
        for (int d = 0; d < 3; d++)
            store_bind_or_null(panel, c++, x->centroid[d]);
        for (int d = 0; d < 3; d++)
            store_bind_or_null(panel, c++, x->normal[d]);
        for (int corner = 0; corner < 4; corner++)
            for (int d = 0; d < 3; d++)
                store_bind_or_null(panel, c++, x->corner[corner][d]);
        if (x->mould >= 0)
            sqlite3_bind_int(panel, c++, x->mould);
        else
            sqlite3_bind_null(panel, c++);
        sqlite3_bind_text(panel, c++, panel_type_name(x->built), -1,
                          SQLITE_STATIC);
        store_bind_or_null(panel, c++, x->sp_deviation);
        store_bind_or_null(panel, c++, units_mm(x->worst_gap));
        if (x->worst_gap_side >= 0)
            sqlite3_bind_int(panel, c++, x->worst_gap_side);
        else
            sqlite3_bind_null(panel, c++);
        store_bind_or_null(panel, c++, units_deg(x->worst_kink));
        store_bind_or_null(panel, c++, x->best_cylinder);
        store_bind_or_null(panel, c++, x->best_cone);
        char reason[200];
        classify_misfit_reason(p, k, reason, sizeof reason);
        if (reason[0] != '\0')
            sqlite3_bind_text(panel, c++, reason, -1, SQLITE_TRANSIENT);
        else
            sqlite3_bind_null(panel, c++);
        c = bind_sp_fit(panel, c, &x->sp_fit);
        /* NULL for a classified option's panels (never 0: not moved is
         * not measured as a move of 0). */
        store_bind_or_null(panel, c++, panel_corner_distance(p, k));
        store_bind_or_null(panel, c++, panel_corner_moved(p, k));
        if (sqlite3_step(panel) != SQLITE_DONE)
            rc = store_fail(store, "storing panels", err);
        sqlite3_reset(panel);
    }
    sqlite3_finalize(set);
    sqlite3_finalize(panel);
    if (rc == FACET_OK)
        rc = store_exec(store, "COMMIT", "storing panels", err);
    if (rc != FACET_OK)
        sqlite3_exec(store->db, "ROLLBACK", NULL, NULL, NULL);
    return rc;
}

int store_panels_exist(struct store *store, int64_t run, int64_t option,
                       int *stored, struct facet_error *err)
{
    *stored = 0;
    sqlite3_stmt *s;
    int rc = store_prepare(store, "SELECT 1 FROM panel_sets WHERE run = ?1"
                           " AND option = ?2", &s, "reading panels", err);
    if (rc != FACET_OK)
        return rc;
    sqlite3_bind_int64(s, 1, run);
    sqlite3_bind_int64(s, 2, option);
    int step = sqlite3_step(s);
    sqlite3_finalize(s);
    if (step == SQLITE_ROW)
        *stored = 1;
    else if (step != SQLITE_DONE)
        return store_fail(store, "reading panels", err);
    return FACET_OK;
}

/* The enum value whose name is text, or -1. */
static int class_of(const char *text)
{
    for (int c = 0; c < CLASS_COUNT; c++)
        if (strcmp(panel_class_name((enum panel_class)c), text) == 0)
            return c;
    return -1;
}

static int type_of(const char *text)
{
    for (int t = 0; t < TYPE_COUNT; t++)
        if (strcmp(panel_type_name((enum panel_type)t), text) == 0)
            return t;
    return -1;
}

/* A planarized option's corner distance and move of panel n, from column
 * c: the arrays made at its first panel that has them (a classified
 * option's panels have none: the arrays stay NULL). */
static int read_corner_moves(sqlite3_stmt *s, int c, struct panelization *p,
                             size_t n, struct facet_error *err)
{
    double distance = store_column_or_nan(s, c);
    double moved = store_column_or_nan(s, c + 1);
    if (p->corner_moved == NULL && (isnan(distance) && isnan(moved)))
        return FACET_OK;
    if (p->corner_moved == NULL) {
        size_t m = p->npanels ? p->npanels : 1;
        p->corner_distance = malloc(m * sizeof *p->corner_distance);
        p->corner_moved = malloc(m * sizeof *p->corner_moved);
        if (p->corner_distance == NULL || p->corner_moved == NULL)
            return facet_error_set(err, FACET_EWORK,
                                   "out of memory (panels)");
        for (size_t k = 0; k < m; k++)
            p->corner_distance[k] = p->corner_moved[k] = NAN;
    }
    p->corner_distance[n] = distance;
    p->corner_moved[n] = moved;
    return FACET_OK;
}

int store_panels_get(struct store *store, int64_t run, int64_t option,
                     struct panelization *p, struct facet_error *err)
{
    memset(p, 0, sizeof *p);
    sqlite3_stmt *s;
    int rc = store_prepare(store, "SELECT nu, nv, umin, vmin, umax, vmax,"
                           " (SELECT count(*) FROM panels WHERE run = ?1 AND"
                           " option = ?2), (SELECT threshold_mm FROM options"
                           " WHERE run = ?1 AND number = ?2)"
                           " FROM panel_sets WHERE run = ?1 AND"
                           " option = ?2", &s, "reading panels", err);
    if (rc != FACET_OK)
        return rc;
    sqlite3_bind_int64(s, 1, run);
    sqlite3_bind_int64(s, 2, option);
    int step = sqlite3_step(s);
    if (step == SQLITE_ROW) {
        p->nu = sqlite3_column_int(s, 0);
        p->nv = sqlite3_column_int(s, 1);
        p->umin = sqlite3_column_double(s, 2);
        p->vmin = sqlite3_column_double(s, 3);
        p->umax = sqlite3_column_double(s, 4);
        p->vmax = sqlite3_column_double(s, 5);
        p->npanels = (size_t)sqlite3_column_int64(s, 6);
        p->threshold = units_m_of_mm(store_column_or_nan(s, 7));
    }
    sqlite3_finalize(s);
    if (step == SQLITE_DONE)
        return facet_error_set(err, FACET_EINPUT,
            "%s: run %lld option %lld has no stored panels", store->path,
            (long long)run, (long long)option);
    if (step != SQLITE_ROW)
        return store_fail(store, "reading panels", err);
    if (p->nu < 1 || p->nv < 1 || p->nu > PANEL_MAX_GRID ||
        p->nv > PANEL_MAX_GRID ||
        p->npanels > (size_t)p->nu * (size_t)p->nv)
        return facet_error_set(err, FACET_EINPUT,
            "%s: run %lld option %lld: stored grid %dx%d is damaged",
            store->path, (long long)run, (long long)option, p->nu, p->nv);
    size_t cells = (size_t)p->nu * (size_t)p->nv;
    p->panels = calloc(p->npanels ? p->npanels : 1, sizeof *p->panels);
    p->cell_panel = malloc(cells * sizeof *p->cell_panel);
    if (p->panels == NULL || p->cell_panel == NULL)
        return facet_error_set(err, FACET_EWORK, "out of memory (panels)");
    for (size_t k = 0; k < cells; k++)
        p->cell_panel[k] = -1;
    rc = store_prepare(store,
        "SELECT i, j, class, type, area, uv_area, deviation, k1, k2, K, H,"
        " eps, p_dist, diameter, trimmed, corner_planarity, price, cost,"
        " centroid_x, centroid_y, centroid_z, normal_x, normal_y, normal_z,"
        " c0_x, c0_y, c0_z, c1_x, c1_y, c1_z, c2_x, c2_y, c2_z,"
        " c3_x, c3_y, c3_z, coalesce(mould_family, -1),"
        " coalesce(built_type, type), sp_deviation, worst_gap,"
        " coalesce(worst_gap_side, -1), worst_kink,"
        " best_cylinder, best_cone, misfit_reason IS NOT NULL, sp_surface,"
        " sp_axis_x, sp_axis_y, sp_axis_z, sp_direction_x, sp_direction_y,"
        " sp_direction_z, sp_radius, sp_apex_x, sp_apex_y, sp_apex_z,"
        " sp_half_angle, sp_bending_radius, corner_distance, corner_moved"
        " FROM panels"
        " WHERE run = ?1 AND option = ?2"
        " ORDER BY j, i", &s, "reading panels", err);
    if (rc != FACET_OK)
        return rc;
    sqlite3_bind_int64(s, 1, run);
    sqlite3_bind_int64(s, 2, option);
    size_t n = 0;
    while (rc == FACET_OK && (step = sqlite3_step(s)) == SQLITE_ROW &&
           n < p->npanels) {
        struct panel *x = &p->panels[n];
        int c = 0;
        x->i = sqlite3_column_int(s, c++);
        x->j = sqlite3_column_int(s, c++);
        int class = class_of((const char *)sqlite3_column_text(s, c++));
        int type = type_of((const char *)sqlite3_column_text(s, c++));
        if (class < 0 || type < 0 || x->i < 0 || x->j < 0 ||
            x->i >= p->nu || x->j >= p->nv) {
            rc = facet_error_set(err, FACET_EINPUT,
                "%s: run %lld option %lld: stored panel %d,%d is damaged",
                store->path, (long long)run, (long long)option, x->i, x->j);
            break;
        }
        x->class = (enum panel_class)class;
        x->type = (enum panel_type)type;
        x->area = sqlite3_column_double(s, c++);
        x->uv_area = sqlite3_column_double(s, c++);
        x->deviation = sqlite3_column_double(s, c++);
        x->k1 = sqlite3_column_double(s, c++);
        x->k2 = sqlite3_column_double(s, c++);
        x->K = sqlite3_column_double(s, c++);
        x->H = sqlite3_column_double(s, c++);
        x->curvature_tol = sqlite3_column_double(s, c++);
        x->p_dist = sqlite3_column_double(s, c++);
        x->diameter = sqlite3_column_double(s, c++);
        x->trimmed = sqlite3_column_int(s, c++);
        x->corner_planarity = store_column_or_nan(s, c++);
        x->price = sqlite3_column_double(s, c++);
        x->cost = sqlite3_column_double(s, c++);
        for (int d = 0; d < 3; d++)
            x->centroid[d] = store_column_or_nan(s, c++);
        for (int d = 0; d < 3; d++)
            x->normal[d] = store_column_or_nan(s, c++);
        x->ncorners = 0;
        for (int corner = 0; corner < 4; corner++) {
            for (int d = 0; d < 3; d++)
                x->corner[corner][d] = store_column_or_nan(s, c++);
            x->ncorners += isfinite(x->corner[corner][0]);
        }
        x->mould = sqlite3_column_int(s, c++);
        /* Panels stored before schema v7 were never built: their built
         * type is their type, and their gaps and fits unknown (NaN). */
        int built = type_of((const char *)sqlite3_column_text(s, c++));
        x->built = built < 0 ? x->type : (enum panel_type)built;
        x->sp_deviation = store_column_or_nan(s, c++);
        x->worst_gap = units_m_of_mm(store_column_or_nan(s, c++));
        x->worst_gap_side = sqlite3_column_int(s, c++);
        if (x->worst_gap_side < -1 || x->worst_gap_side > 3)
            x->worst_gap_side = -1;
        x->worst_kink = units_rad_of_deg(store_column_or_nan(s, c++));
        x->width = NAN;  /* not stored per panel: the option's least is */
        x->best_cylinder = store_column_or_nan(s, c++);
        x->best_cone = store_column_or_nan(s, c++);
        x->misfit = sqlite3_column_int(s, c++);
        c = read_sp_fit(s, c, &x->sp_fit);
        rc = read_corner_moves(s, c, p, n, err);
        p->cell_panel[(size_t)x->j * (size_t)p->nu + (size_t)x->i] = (int)n;
        n++;
    }
    if (rc == FACET_OK && step != SQLITE_DONE && step != SQLITE_ROW)
        rc = store_fail(store, "reading panels", err);
    sqlite3_finalize(s);
    return rc;
}
