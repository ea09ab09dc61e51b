/*
 * surface.h: a designer's surface, loaded and checked, ready to panelize.
 *
 * Wraps the two load steps every command repeats (read the OBJ, build the
 * mesh in metres) and collects the warnings a facade engineer should see
 * before trusting any number: units that look wrong, several surfaces in one
 * file with none selected, edges shared by more than two triangles,
 * triangles dropped because their corners were welded together.
 */
#ifndef FACET_SURFACE_H
#define FACET_SURFACE_H

#include "core/fit/sp_fit.h"
#include "core/joint/joint_length.h"
#include "core/surface/curvature.h"
#include "core/surface/mesh.h"
#include "core/obj/obj.h"
#include "core/panel/panel.h"
#include "core/surface/param.h"
#include "core/surface/uv_index.h"

#define SURFACE_MAX_WARNINGS 8

struct surface {
    char *path;                 /* owned copy of the file's path */
    enum mesh_units units;
    struct obj_file obj;        /* the file as read (names, counts);
                                   empty for a project's surface */
    struct mesh mesh;           /* the selected part, in metres */
    int selected;               /* --object or --group was given */
    int nwarnings;
    char warnings[SURFACE_MAX_WARNINGS][320];

    /* What does not depend on the grid, set by surface_prepare and shared
     * by every option evaluated on the surface: */
    int prepared;
    struct parameterization param;  /* the UV the panels follow */
    struct uv_index uv;             /* lookup over param.uv */
    struct curvature curvature;     /* vertex curvature */
    struct panel_prep panels;       /* per-triangle sums every grid adds */
    struct joint_prep joints;       /* the outline and the triangles in
                                       order, for every grid's joints */
    struct fit_points fit;          /* the mesh points in UV, for the
                                       fit of SP panels (sp_fit.h) */
    double facet_sag;               /* how far the facets sag from the
                                       surface the vertices sample (m,
                                       mesh_facet_sag) */
};

/* Refuses s when its size, in the units it was read in, is no building's
 * while another unit gives it one (mesh_units_mistaken): FACET_EINPUT
 * about FACET_SETTING_UNITS, with that unit as the value to give, the
 * message saying both sizes. A front-end asks it when its user did not
 * name the units: units named are read as asked, with the warning. */
int surface_units_check(const struct surface *s, struct facet_error *err);

/* surface_units_check of what (a file, or a building of several: named in
 * the message) whose bounding box's diagonal is diagonal (m, as read in
 * units). */
int surface_units_check_size(const char *what, double diagonal,
                             enum mesh_units units, struct facet_error *err);

/* Loads path with options into *out. Returns FACET_OK, or the loader's or
 * mesh builder's error. The caller releases *out with surface_close, also
 * after a failure. */
int surface_open(const char *path, const struct mesh_options *options,
                 struct surface *out, struct facet_error *err);

/* surface_open, asking stop (stop.h) every few milliseconds of reading and
 * building: FACET_ESTOP when it fires. A command its user can interrupt
 * reads with this one. */
int surface_open_stoppable(const char *path,
                           const struct mesh_options *options,
                           const struct facet_stop *stop,
                           struct surface *out, struct facet_error *err);

/* surface_open of a file already read into *obj, which it takes over
 * (and zeroes). */
int surface_from_obj(const char *path, struct obj_file *obj,
                     const struct mesh_options *options,
                     struct surface *out, struct facet_error *err);

/* Makes *out the surface of a mesh already built (one surface of a
 * project, core/project/project.h): takes *mesh over (and zeroes it),
 * names the surface path in messages (a copy), runs surface_open's checks
 * and warnings, and counts it as selected. out->obj stays empty: the file
 * is its project's, read once. Release *out with surface_close, also after
 * a failure. */
int surface_from_mesh(const char *path, enum mesh_units units,
                      struct mesh *mesh, struct surface *out,
                      struct facet_error *err);

/* Fails with FACET_EINPUT when the surface is several disconnected pieces
 * and none was selected, listing the objects or groups to choose from, so
 * that a panelization never silently mixes two surfaces. */
int surface_require_single(const struct surface *surface,
                           struct facet_error *err);

/* Computes what every panelization of the surface shares: the UV
 * parameterization (param.h: uv, or PARAM_AUTO for the first that
 * applies), its lookup, the vertex curvature, with the
 * normals flipped when flip_normals is set, the sums panels_build_fast
 * starts from (panel_prep_build), the joints' prep and the points SP
 * panels are fitted to (fit_points_build). Refuses a surface of several
 * unselected pieces (surface_require_single). Returns FACET_OK or the first
 * error; surface_close releases what it made. */
int surface_prepare(struct surface *surface, int flip_normals,
                    enum param_method uv, struct facet_error *err);

/* surface_prepare, asking stop (stop.h) between its steps and within the
 * long ones (UV, curvature): FACET_ESTOP when it fires; surface_close
 * releases what was made. */
int surface_prepare_stoppable(struct surface *surface, int flip_normals,
                              enum param_method uv,
                              const struct facet_stop *stop,
                              struct facet_error *err);

/* What surface_prepare does after the UV and the curvature, for a
 * surface whose param and curvature are already set (by surface_prepare,
 * or read back from a prepared building's cache, project_cache.h, made by
 * surface_prepare with the same settings): the UV warning, the UV's
 * lookup, the facets' sag, the panel sums, the joints' prep and the fit
 * points, all functions of the mesh, UV and curvature alone, so the same
 * to the bit as surface_prepare makes them. A surface whose lookup, sag,
 * sums and joints' prep came from the cache too (format 3:
 * surface_prepared_in_cache) gets the UV warning and the fit points only.
 * FACET_ESTOP when stop fires. */
int surface_prepare_rest(struct surface *surface,
                         const struct facet_stop *stop,
                         struct facet_error *err);

/* Whether surface's UV lookup, panel sums and joints' prep are already
 * set (read back from a prepared building's cache), so that
 * surface_prepare_rest does not make them again. */
int surface_prepared_in_cache(const struct surface *surface);

void surface_close(struct surface *surface);

#endif
