/*
 * param.c: choosing the UV: vt, structured grid, plane projection or
 * harmonic map. See param.h.
 */
#include "core/surface/param.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/surface/param_chart.h"
#include "core/surface/param_grid.h"
#include "core/surface/param_harmonic.h"
#include "core/base/sym3.h"

static const char *const method_names[] = {"auto", "vt", "grid", "plane",
                                           "harmonic"};

const char *param_method_name(enum param_method method)
{
    return method >= PARAM_AUTO && method <= PARAM_HARMONIC
               ? method_names[method] : "?";
}

int param_method_parse(const char *text, enum param_method *out)
{
    for (int m = PARAM_AUTO; m <= PARAM_HARMONIC; m++)
        if (strcmp(text, method_names[m]) == 0) {
            *out = (enum param_method)m;
            return 0;
        }
    return -1;
}

void param_free(struct parameterization *param)
{
    free(param->uv);
    memset(param, 0, sizeof *param);
}

static int folds(const struct uv_report *report)
{
    return report->flipped > 0 || report->overlapping > 0;
}

/* Per-corner UV from per-vertex (u, v). */
static double *corners_from_vertices(const struct mesh *mesh,
                                     const double *vertex_uv)
{
    double *uv = malloc(sizeof(double) * 6 * (mesh->ntriangles ? mesh->ntriangles : 1));
    if (uv == NULL)
        return NULL;
    for (size_t t = 0; t < mesh->ntriangles; t++)
        for (int k = 0; k < 3; k++) {
            uint32_t v = mesh->triangle[3 * t + k];
            uv[6 * t + 2 * k] = vertex_uv[2 * v];
            uv[6 * t + 2 * k + 1] = vertex_uv[2 * v + 1];
        }
    return uv;
}

/* Projects every vertex onto the least-squares plane of the vertices, u
 * along the direction of largest spread, v across it. */
static double *plane_projection(const struct mesh *mesh)
{
    size_t n = mesh->nvertices;
    double mean[3] = {0, 0, 0}, covariance[9] = {0};
    for (size_t v = 0; v < n; v++)
        for (int x = 0; x < 3; x++)
            mean[x] += mesh->position[3 * v + x] / (double)n;
    for (size_t v = 0; v < n; v++)
        for (int r = 0; r < 3; r++)
            for (int q = 0; q < 3; q++)
                covariance[3 * r + q] +=
                    (mesh->position[3 * v + r] - mean[r]) *
                    (mesh->position[3 * v + q] - mean[q]);
    double value[3], axis[3][3];
    sym3_eigen(covariance, value, axis);

    /* Keep the winding: v = normal x u with the normal on the side of the
     * faces' normals, so a surface seen from its front maps unmirrored. */
    double normal_sum[3] = {0, 0, 0};
    for (size_t t = 0; t < mesh->ntriangles; t++)
        for (int x = 0; x < 3; x++)
            normal_sum[x] += mesh->face_area[t] * mesh->face_normal[3 * t + x];
    double *normal = axis[0], *u_axis = axis[2], v_axis[3];
    if (normal[0] * normal_sum[0] + normal[1] * normal_sum[1] +
        normal[2] * normal_sum[2] < 0)
        for (int x = 0; x < 3; x++)
            normal[x] = -normal[x];
    v_axis[0] = normal[1] * u_axis[2] - normal[2] * u_axis[1];
    v_axis[1] = normal[2] * u_axis[0] - normal[0] * u_axis[2];
    v_axis[2] = normal[0] * u_axis[1] - normal[1] * u_axis[0];

    double *vertex_uv = malloc(sizeof(double) * 2 * (n ? n : 1));
    if (vertex_uv == NULL)
        return NULL;
    for (size_t v = 0; v < n; v++) {
        double d[3];
        for (int x = 0; x < 3; x++)
            d[x] = mesh->position[3 * v + x] - mean[x];
        vertex_uv[2 * v] = d[0] * u_axis[0] + d[1] * u_axis[1] +
                           d[2] * u_axis[2];
        vertex_uv[2 * v + 1] = d[0] * v_axis[0] + d[1] * v_axis[1] +
                               d[2] * v_axis[2];
    }
    return vertex_uv;
}

/* Sets out->uv from per-vertex UV (which it frees) and checks it. */
static int take_vertex_uv(const struct mesh *mesh, double *vertex_uv,
                          const struct facet_stop *stop,
                          struct parameterization *out,
                          struct facet_error *err)
{
    free(out->uv);
    out->uv = corners_from_vertices(mesh, vertex_uv);
    free(vertex_uv);
    if (out->uv == NULL)
        return facet_error_set(err, FACET_EWORK, "out of memory (UV)");
    return uv_check_stoppable(out->uv, mesh->ntriangles, stop, &out->report,
                              err);
}

/* The file's vt: refused when they fold or form several charts. */
static int try_vt(const struct mesh *mesh, const char *name,
                  const struct facet_stop *stop,
                  struct parameterization *out, struct facet_error *err)
{
    if (!mesh->has_uv)
        return facet_error_set(err, FACET_EINPUT,
            "%s has no texture coordinates (vt) on every corner to take "
            "the UV from", name);
    out->uv = malloc(sizeof(double) * 6 * (mesh->ntriangles ? mesh->ntriangles : 1));
    if (out->uv == NULL)
        return facet_error_set(err, FACET_EWORK, "out of memory (UV)");
    memcpy(out->uv, mesh->uv, sizeof(double) * 6 * mesh->ntriangles);
    int rc = uv_check_stoppable(out->uv, mesh->ntriangles, stop,
                                &out->report, err);
    if (rc == FACET_OK)
        rc = facet_stop_check(stop, err);
    if (rc != FACET_OK)
        return rc;
    if (folds(&out->report))
        return facet_error_about(err, FACET_SETTING_OBJECT, FACET_EINPUT,
            "%s: the texture coordinates fold (%zu flipped, %zu "
            "overlapping UV triangles); re-export the surface with its "
            "surface parameters as UV, or select one object", name,
            out->report.flipped,
            out->report.overlapping);
    struct uv_chart chart[3];
    size_t found;
    rc = param_charts(mesh, out->uv, chart, 3, &found, err);
    if (rc != FACET_OK)
        return rc;
    long charts = (long)found;
    if (charts > 1) {
        char list[240];
        size_t used = 0;
        for (long c = 0; c < charts && c < 3; c++)
            used += (size_t)snprintf(list + used, sizeof list - used,
                "%s%zu triangles in u %.3g..%.3g, v %.3g..%.3g",
                c ? "; " : "", chart[c].triangles, chart[c].umin,
                chart[c].umax, chart[c].vmin, chart[c].vmax);
        return facet_error_about(err, FACET_SETTING_CHART, FACET_EINPUT,
            "%s: the texture coordinates form %ld separate UV charts "
            "(%s%s), and a panel must not hold pieces of two: export one "
            "chart per object and select its object or group, or "
            "re-parameterize a disk-like surface with the harmonic UV",
            name, charts, list, charts > 3 ? "; ..." : "");
    }
    snprintf(out->reason, sizeof out->reason,
             "the file's texture coordinates, one chart");
    return FACET_OK;
}

static int try_grid(const struct mesh *mesh, const char *name,
                    const struct facet_stop *stop,
                    struct parameterization *out, char *why, size_t size,
                    struct facet_error *err)
{
    double *vertex_uv;
    int paired;
    int rc = param_grid(mesh, &vertex_uv, &out->grid_nu, &out->grid_nv,
                        &paired, why, size);
    if (rc == FACET_EWORK)
        return facet_error_set(err, FACET_EWORK, "out of memory (UV)");
    if (rc != FACET_OK)
        return facet_error_set(err, FACET_EINPUT,
            "%s is not a structured quad grid: %s", name, why);
    if ((rc = facet_stop_check(stop, err)) != FACET_OK) {
        free(vertex_uv);
        return rc;
    }
    rc = take_vertex_uv(mesh, vertex_uv, stop, out, err);
    if (rc != FACET_OK)
        return rc;
    if (folds(&out->report) || out->report.degenerate > 0)
        return facet_error_set(err, FACET_EINPUT,
            "%s: the quad grid's (i, j) folds (%zu flipped, %zu overlapping, "
            "%zu degenerate triangles)", name, out->report.flipped,
            out->report.overlapping, out->report.degenerate);
    snprintf(out->reason, sizeof out->reason, "%d x %d quads, structured%s",
             out->grid_nu, out->grid_nv,
             paired ? ", paired from the file's triangles" : "");
    return FACET_OK;
}

/* The plane projection; refused when it folds or squashes a triangle,
 * with what it did in why. */
static int try_plane(const struct mesh *mesh, const char *name,
                     const struct facet_stop *stop,
                     struct parameterization *out, char *why, size_t size,
                     struct facet_error *err)
{
    double *vertex_uv = plane_projection(mesh);
    if (vertex_uv == NULL)
        return facet_error_set(err, FACET_EWORK, "out of memory (UV)");
    int rc = take_vertex_uv(mesh, vertex_uv, stop, out, err);
    if (rc != FACET_OK)
        return rc;
    const struct uv_report *r = &out->report;
    if (!folds(r) && r->degenerate == 0) {
        snprintf(out->reason, sizeof out->reason,
                 "the projection onto the least-squares plane folds nothing");
        return FACET_OK;
    }
    if (folds(r))
        snprintf(why, size, "the plane projection folds %zu triangles "
                 "(%zu overlapping pairs)", r->flipped, r->overlapping);
    else
        snprintf(why, size, "the plane projection squashes %zu triangles",
                 r->degenerate);
    return facet_error_set(err, FACET_EINPUT, "%s: %s", name, why);
}

static int try_harmonic(const struct mesh *mesh, const char *name,
                        const struct facet_stop *stop,
                        struct parameterization *out, char *why, size_t size,
                        struct facet_error *err)
{
    double *vertex_uv;
    int rc = param_harmonic(mesh, stop, &vertex_uv, &out->holes, why, size);
    if (rc == FACET_EWORK)
        return facet_error_set(err, FACET_EWORK, "out of memory (UV)");
    if (rc == FACET_ESTOP)
        return facet_stop_error(err);
    if (rc != FACET_OK)
        return facet_error_set(err, FACET_EINPUT,
            "%s: no harmonic map: %s", name, why);
    rc = take_vertex_uv(mesh, vertex_uv, stop, out, err);
    if (rc != FACET_OK)
        return rc;
    if (folds(&out->report)) {
        snprintf(why, size, "the harmonic parameterization folds (%zu "
                 "flipped, %zu overlapping triangles)", out->report.flipped,
                 out->report.overlapping);
        return facet_error_set(err, FACET_EINPUT, "%s: %s", name, why);
    }
    if (out->holes > 0)
        snprintf(out->reason, sizeof out->reason,
                 "mean-value map, %zu holes capped", out->holes);
    else
        snprintf(out->reason, sizeof out->reason, "mean-value map");
    return FACET_OK;
}

/* Appends text to the reason, after what came before. */
static void explain(struct parameterization *out, const char *text)
{
    size_t used = strlen(out->reason);
    snprintf(out->reason + used, sizeof out->reason - used, "%s%s",
             used ? "; " : "", text);
}

int param_choose(const struct mesh *mesh, enum param_method want,
                 const char *name, struct parameterization *out,
                 struct facet_error *err)
{
    return param_choose_stoppable(mesh, want, name, NULL, out, err);
}

int param_choose_stoppable(const struct mesh *mesh, enum param_method want,
                           const char *name, const struct facet_stop *stop,
                           struct parameterization *out,
                           struct facet_error *err)
{
    memset(out, 0, sizeof *out);
    char why[200] = "";
    out->method = want;
    switch (want) {
    case PARAM_VT:
        return try_vt(mesh, name, stop, out, err);
    case PARAM_GRID:
        return try_grid(mesh, name, stop, out, why, sizeof why, err);
    case PARAM_PLANE:
        return try_plane(mesh, name, stop, out, why, sizeof why, err);
    case PARAM_HARMONIC:
        return try_harmonic(mesh, name, stop, out, why, sizeof why, err);
    default:
        break;
    }

    /* vt, when the file has it, is the designer's: taken or refused, never
     * replaced by a map of Facet's own. */
    if (mesh->has_uv) {
        out->method = PARAM_VT;
        return try_vt(mesh, name, stop, out, err);
    }
    out->method = PARAM_GRID;
    int rc = try_grid(mesh, name, stop, out, why, sizeof why, err);
    if (rc != FACET_EINPUT)
        return rc;
    char not_grid[240];
    snprintf(not_grid, sizeof not_grid, "no vt; not a structured quad grid: "
             "%s", why);

    out->method = PARAM_PLANE;
    out->reason[0] = '\0';
    if ((rc = facet_stop_check(stop, err)) != FACET_OK)
        return rc;
    rc = try_plane(mesh, name, stop, out, why, sizeof why, err);
    if (rc == FACET_OK) {
        char plane[sizeof out->reason];
        snprintf(plane, sizeof plane, "%s", out->reason);
        snprintf(out->reason, sizeof out->reason, "%s", not_grid);
        explain(out, plane);
    }
    if (rc != FACET_EINPUT)
        return rc;
    char plane_fails[200];
    snprintf(plane_fails, sizeof plane_fails, "%s", why);

    free(out->uv);
    out->uv = NULL;
    memset(&out->report, 0, sizeof out->report);
    out->method = PARAM_HARMONIC;
    if ((rc = facet_stop_check(stop, err)) != FACET_OK)
        return rc;
    rc = try_harmonic(mesh, name, stop, out, why, sizeof why, err);
    if (rc == FACET_OK) {
        char harmonic[sizeof out->reason];
        snprintf(harmonic, sizeof harmonic, "%s", out->reason);
        snprintf(out->reason, sizeof out->reason, "%s", not_grid);
        explain(out, plane_fails);
        explain(out, harmonic);
        return FACET_OK;
    }
    if (rc != FACET_EINPUT)
        return rc;
    return facet_error_set(err, FACET_EINPUT,
        "%s has no texture coordinates, is not a structured quad grid, "
        "%s, and has no harmonic map: %s; export it with texture "
        "coordinates (its surface parameters as vt, e.g. Rhino's mesh "
        "export with texture coordinates)", name, plane_fails, why);
}
