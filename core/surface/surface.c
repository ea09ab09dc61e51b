/*
 * surface.c: loading a surface and collecting its warnings. See surface.h.
 */
#include "core/surface/surface.h"

#include <assert.h>
#include <math.h>

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/base/units.h"
#include "core/surface/coarse_mesh.h"

static void warn(struct surface *surface, const char *fmt, ...)
    __attribute__((format(printf, 2, 3)));

static void warn(struct surface *surface, const char *fmt, ...)
{
    if (surface->nwarnings >= SURFACE_MAX_WARNINGS)
        return;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(surface->warnings[surface->nwarnings++],
              sizeof surface->warnings[0], fmt, ap);
    va_end(ap);
}

/* Refuses a surface whose coordinates are so far from the origin, for the
 * size of its facets, that doubles cannot hold its shape: a double keeps
 * 16 digits, so at 7e14 m a point is known to 0.1 m and a 1 m panel's
 * area to a few percent. Facet's sums promise 1e-9 of a panel's scale;
 * past a ratio of 1e9 between the farthest coordinate and the typical
 * facet (UTM northings of 5e6 m with 5 mm facets are well within), the
 * rounding of positions alone comes near it. */
static int check_precision(const struct surface *s, struct facet_error *err)
{
    const struct mesh *m = &s->mesh;
    if (m->ntriangles == 0)
        return FACET_OK;
    double far = 0;
    for (int k = 0; k < 3; k++)
        far = fmax(far, fmax(fabs(m->bbox_min[k]), fabs(m->bbox_max[k])));
    /* The median facet is no smaller than the smallest: when even that
     * one is fine, the median (a sort of every facet, a tenth of a
     * second on the skin, at every read of it or its cache) is not
     * needed to say so. */
    double least = INFINITY;
    for (size_t t = 0; t < m->ntriangles; t++)
        least = fmin(least, m->face_area[t]);
    double smallest = sqrt(2 * least);
    if (smallest > 0 && far <= 1e9 * smallest)
        return FACET_OK;
    double facet;
    int rc = mesh_facet_size(m, &facet, err);
    if (rc != FACET_OK)
        return rc;
    if (!(facet > 0) || far <= 1e9 * facet)
        return FACET_OK;
    return facet_error_set(err, FACET_EINPUT,
        "%s: coordinates reach %.3g m, %.3g times the facets' size (%.3g "
        "m): at that distance from the origin doubles keep the points to "
        "%.2g m, too coarse for panels; move the surface near the origin "
        "(subtract the site's offset) and export again", s->path, far,
        far / facet, facet, far * 0x1p-52);
}

/* The checks and warnings of a mesh, however it was selected. */
static int check_mesh(struct surface *out, struct facet_error *err)
{
    int rc = check_precision(out, err);
    if (rc != FACET_OK)
        return rc;
    char text[256];
    if (mesh_units_warning(&out->mesh, out->units, text, sizeof text))
        warn(out, "%s", text);
    if (out->mesh.nonmanifold_edges > 0)
        warn(out, "%zu edges are shared by more than two triangles "
             "(non-manifold)", out->mesh.nonmanifold_edges);
    if (out->mesh.ndegenerate > 0)
        warn(out, "%zu triangles dropped: their corners weld into fewer "
             "than three vertices", out->mesh.ndegenerate);
    return FACET_OK;
}

/* A length (m) as a designer reads it at its size: km, m or mm. */
static void length_text(double metres, char *out, size_t size)
{
    if (metres >= 1000)
        snprintf(out, size, "%.1f km", units_km(metres));
    else if (metres >= 1)
        snprintf(out, size, "%.1f m", metres);
    else
        snprintf(out, size, "%.1f mm", units_mm(metres));
}

int surface_units_check(const struct surface *s, struct facet_error *err)
{
    return surface_units_check_size(s->path, mesh_diagonal(&s->mesh),
                                    s->units, err);
}

int surface_units_check_size(const char *what, double diagonal,
                             enum mesh_units units, struct facet_error *err)
{
    enum mesh_units better;
    if (!mesh_units_mistaken_at(diagonal, units, &better))
        return FACET_OK;
    char as_read[32], as_better[32];
    length_text(diagonal, as_read, sizeof as_read);
    length_text(diagonal / mesh_units_scale(units) * mesh_units_scale(better),
                as_better, sizeof as_better);
    return facet_error_about_value(err, FACET_SETTING_UNITS,
        mesh_units_name(better), FACET_EINPUT,
        "%s is %s across in %s, no building's size; in %s it is %s",
        what, as_read, mesh_units_name(units), mesh_units_name(better),
        as_better);
}

int surface_from_mesh(const char *path, enum mesh_units units,
                      struct mesh *mesh, struct surface *out,
                      struct facet_error *err)
{
    memset(out, 0, sizeof *out);
    out->units = units;
    out->selected = 1;
    out->mesh = *mesh;
    memset(mesh, 0, sizeof *mesh);
    out->path = strdup(path);
    if (out->path == NULL)
        return facet_error_set(err, FACET_EWORK, "out of memory");
    return check_mesh(out, err);
}

static int from_obj(const char *path, struct obj_file *obj,
                    const struct mesh_options *options,
                    const struct facet_stop *stop, struct surface *out,
                    struct facet_error *err);

int surface_open(const char *path, const struct mesh_options *options,
                 struct surface *out, struct facet_error *err)
{
    return surface_open_stoppable(path, options, NULL, out, err);
}

int surface_open_stoppable(const char *path,
                           const struct mesh_options *options,
                           const struct facet_stop *stop,
                           struct surface *out, struct facet_error *err)
{
    struct obj_file obj;
    int rc = obj_load_stoppable(path, stop, &obj, err);
    if (rc != FACET_OK) {
        obj_free(&obj);
        memset(out, 0, sizeof *out);
        return rc;
    }
    return from_obj(path, &obj, options, stop, out, err);
}

int surface_from_obj(const char *path, struct obj_file *obj,
                     const struct mesh_options *options,
                     struct surface *out, struct facet_error *err)
{
    return from_obj(path, obj, options, NULL, out, err);
}

static int from_obj(const char *path, struct obj_file *obj,
                    const struct mesh_options *options,
                    const struct facet_stop *stop, struct surface *out,
                    struct facet_error *err)
{
    memset(out, 0, sizeof *out);
    out->obj = *obj;
    memset(obj, 0, sizeof *obj);
    out->units = options->units;
    out->selected = options->object != NULL || options->group != NULL;
    out->path = strdup(path);
    if (out->path == NULL)
        return facet_error_set(err, FACET_EWORK, "out of memory");
    int rc = mesh_build_stoppable(&out->obj, options, stop, &out->mesh, err);
    if (rc == FACET_ESTOP)
        return rc;
    if (rc != FACET_OK) {
        /* mesh errors do not know the file name; add it. */
        char message[sizeof err->message];
        snprintf(message, sizeof message, "%s", err->message);
        return facet_error_set(err, rc, "%s: %s", path, message);
    }

    if ((rc = check_mesh(out, err)) != FACET_OK)
        return rc;
    if (!out->selected && out->mesh.ncomponents > 1) {
        char names[200];
        if (out->obj.nobjects > 2) {
            obj_names_list(out->obj.objects, out->obj.nobjects, names,
                       sizeof names);
            warn(out, "the file holds %zu separate surfaces; objects: %s "
                 "(select one by its object name)",
                 out->mesh.ncomponents, names);
        } else if (out->obj.ngroups > 2) {
            obj_names_list(out->obj.groups, out->obj.ngroups, names,
                       sizeof names);
            warn(out, "the file holds %zu separate surfaces; groups: %s "
                 "(select one by its group name)",
                 out->mesh.ncomponents, names);
        } else {
            warn(out, "the file holds %zu separate surfaces in one object "
                 "(export the surface to panelize on its own)",
                 out->mesh.ncomponents);
        }
    }
    return FACET_OK;
}

int surface_require_single(const struct surface *surface,
                           struct facet_error *err)
{
    if (surface->mesh.ncomponents <= 1 || surface->selected)
        return FACET_OK;
    char names[200];
    if (surface->obj.nobjects > 2) {
        obj_names_list(surface->obj.objects, surface->obj.nobjects, names,
                   sizeof names);
        return facet_error_about(err, FACET_SETTING_OBJECT, FACET_EINPUT,
            "%s holds %zu separate surfaces (objects: %s); select one "
            "object", surface->path, surface->mesh.ncomponents, names);
    }
    if (surface->obj.ngroups > 2) {
        obj_names_list(surface->obj.groups, surface->obj.ngroups, names,
                   sizeof names);
        return facet_error_about(err, FACET_SETTING_GROUP, FACET_EINPUT,
            "%s holds %zu separate surfaces (groups: %s); select one group",
            surface->path, surface->mesh.ncomponents, names);
    }
    return facet_error_set(err, FACET_EINPUT,
        "%s holds %zu separate surfaces in one object; export the surface "
        "to panelize on its own", surface->path, surface->mesh.ncomponents);
}

static int prepare_rest(struct surface *surface, int cached,
                        const struct facet_stop *stop,
                        struct facet_error *err);

int surface_prepare(struct surface *surface, int flip_normals,
                    enum param_method uv, struct facet_error *err)
{
    return surface_prepare_stoppable(surface, flip_normals, uv, NULL, err);
}

int surface_prepare_stoppable(struct surface *surface, int flip_normals,
                              enum param_method uv,
                              const struct facet_stop *stop,
                              struct facet_error *err)
{
    int rc = surface_require_single(surface, err);
    if (rc != FACET_OK)
        return rc;
    rc = param_choose_stoppable(&surface->mesh, uv, surface->path, stop,
                                &surface->param, err);
    if (rc != FACET_OK)
        return rc;
    /* Each step takes up to a second or two on ten million triangles;
     * the stop is asked between them (and within the curvature, the
     * longest). The curvature reads the mesh alone, so it may come
     * before the UV's lookup: the same numbers either way. */
    if ((rc = facet_stop_check(stop, err)) == FACET_OK)
        rc = curvature_at_vertices_stoppable(&surface->mesh, flip_normals,
                                             stop, &surface->curvature, err);
    if (rc != FACET_OK)
        return rc;
    return prepare_rest(surface, 0, stop, err);
}

int surface_prepare_rest(struct surface *surface,
                         const struct facet_stop *stop,
                         struct facet_error *err)
{
    return prepare_rest(surface, surface_prepared_in_cache(surface), stop,
                        err);
}

/* surface_prepare_rest; cached: the lookup, sag, sums and joints' prep
 * came with the surface (its cache read them, and checked them). */
static int prepare_rest(struct surface *surface, int cached,
                        const struct facet_stop *stop,
                        struct facet_error *err)
{
    assert(surface->param.uv != NULL && surface->curvature.k1 != NULL);
    if (surface->param.report.degenerate > 0)
        warn(surface, "%zu triangles have no extent in UV and add no area "
             "to any panel", surface->param.report.degenerate);
    int rc = facet_stop_check(stop, err);
    /* A surface read back from its cache comes with its lookup, sag,
     * panel sums and joints' prep: only the fit points, cheap, are made. */
    if (rc == FACET_OK && !cached)
        rc = uv_index_build(surface->param.uv, surface->mesh.ntriangles,
                            &surface->uv, err);
    if (rc == FACET_OK && !cached)
        rc = mesh_facet_sag(&surface->mesh, &surface->curvature,
                            &surface->facet_sag, err);
    if (rc == FACET_OK && !cached &&
        (rc = facet_stop_check(stop, err)) == FACET_OK)
        rc = panel_prep_build(&surface->mesh, &surface->uv,
                              &surface->curvature, &surface->panels, err);
    if (rc == FACET_OK && !cached &&
        (rc = facet_stop_check(stop, err)) == FACET_OK)
        rc = joint_prep_build(&surface->mesh, &surface->uv, &surface->joints,
                              err);
    /* the triangles' curvature extremes are not kept in the cache: one
     * pass over the curvature it holds */
    if (rc == FACET_OK && cached && surface->panels.curvature_range == NULL)
        rc = panel_prep_add_ranges(&surface->panels, err);
    if (rc == FACET_OK && (rc = facet_stop_check(stop, err)) == FACET_OK)
        rc = fit_points_build(&surface->panels, &surface->fit, err);
    if (rc != FACET_OK)
        return rc;
    surface->prepared = 1;
    return FACET_OK;
}

int surface_prepared_in_cache(const struct surface *surface)
{
    return surface->uv.cell_start != NULL && surface->panels.triangle != NULL &&
           surface->joints.order[0] != NULL;
}

void surface_close(struct surface *surface)
{
    panel_prep_free(&surface->panels);
    joint_prep_free(&surface->joints);
    fit_points_free(&surface->fit);
    uv_index_free(&surface->uv);
    param_free(&surface->param);
    curvature_free(&surface->curvature);
    free(surface->path);
    obj_free(&surface->obj);
    mesh_free(&surface->mesh);
    memset(surface, 0, sizeof *surface);
}
