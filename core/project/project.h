/*
 * project.h: a whole building's skin, as a list of surfaces.
 *
 * A project is one OBJ file with many objects or groups, or several OBJ
 * files; each surface keeps its own UV. In each file the surfaces are:
 *
 *   - its objects (o NAME), when it names any;
 *   - else its groups (g NAME), when it names any;
 *   - else the whole file, one surface named after the file (its base
 *     name without ".obj").
 *
 * Surfaces come in file order, then in the order of their first statement.
 * Each is a struct surface (core/surface/surface.h) built from the file
 * read once: its mesh in metres, then, after project_prepare, its UV, the
 * curvature and the sums every panel grid starts from, as for a single
 * surface. Its u and v lengths (project_lengths.h) come with the UV.
 *
 * Refused, with one line "FILE:LINE: object 'NAME': what":
 *   - a face outside any object (or group) in a file that names them;
 *   - an object (group) with no faces;
 *   - a name used for two separate runs of faces in one file (Rhino does
 *     not keep names unique: two faces named alike would silently become
 *     one surface), or by two files of the project;
 *   - a face without vt in a file whose faces carry vt (per-face UV): the
 *     file's UV would be half its own and half computed.
 * A file without any vt is allowed; its surfaces' UV is computed (grid,
 * plane, harmonic: param.h).
 *
 * Memory: a file is held once, while its surfaces' meshes are built, and
 * freed before the next file is read; a project keeps only its surfaces'
 * meshes and what preparing them adds (the skin example, 2M triangles:
 * see tests/bench/bench_project.c for the peak).
 *
 * Ownership: project_open fills a caller-owned struct project;
 * project_close releases everything in it, also after a failure.
 */
#ifndef FACET_PROJECT_H
#define FACET_PROJECT_H

#include <stddef.h>

#include "core/base/error.h"
#include "core/obj/obj.h"
#include "core/surface/mesh.h"
#include "core/surface/param.h"
#include "core/surface/surface.h"

/* What names a file's surfaces. */
enum project_key { PROJECT_FILE, PROJECT_OBJECT, PROJECT_GROUP };

struct project_surface {
    char *name;              /* owned: the o or g name, or the file's */
    const char *file;        /* the project's copy of its file's path */
    enum project_key key;    /* what the name is */
    size_t face;             /* the f statement (0-based, in its file)
                                of its first face */
    struct surface surface;  /* its mesh; prepared by project_prepare.
                                surface.path reads "FILE: object NAME" */
    double u_length;         /* m, set by project_prepare */
    double v_length;
};

/* The most OBJ files one project is read from. A building of more surfaces
 * names them as objects (or groups) inside fewer files, where there is no
 * limit; the file list is hashed, stored with every run and written into
 * every Slurm script, so it stays short. */
#define PROJECT_FILES_MAX 256

/* FACET_OK when npaths files may make one project, else FACET_EINPUT
 * saying how many were named and what the limit is. project_open asks it;
 * commands ask it before they read any file. */
int project_files_check(size_t npaths, struct facet_error *err);

struct project_seams;

struct project {
    size_t nfiles;
    char **files;            /* owned copies of the paths */
    size_t nsurfaces;
    struct project_surface *surfaces;  /* owned, nsurfaces */
    size_t ntriangles;       /* sum over the surfaces' meshes */
    double area;             /* m^2, sum over the surfaces */
    struct project_seams *seams;  /* owned: where its surfaces meet, once
                                     project_seams_keep found them
                                     (project_seams.h); NULL before, and
                                     then no option measures seams */
    /* The prepared building's cache it was read from (project_cache.h),
     * mapped: its surfaces' mesh, UV and curvature arrays lie in these
     * bytes, which project_close unmaps (project_cache_release) rather
     * than free the arrays one by one. NULL when read from its files. */
    unsigned char *cache_bytes;
    size_t cache_size;
};

/* Reads the files paths[0 .. npaths) (npaths >= 1), whose coordinates are
 * in units, into *out as the list of their surfaces. Returns FACET_OK, or
 * FACET_EINPUT for a file the OBJ reader refuses or a case listed above,
 * FACET_EWORK when out of memory, with err naming the file, the line and
 * the surface. */
int project_open(const char *const *paths, size_t npaths,
                 enum mesh_units units, struct project *out,
                 struct facet_error *err);

/* project_open, asking stop (stop.h) every few milliseconds of reading
 * and building: FACET_ESTOP when it fires (release *out with
 * project_close). */
int project_open_stoppable(const char *const *paths, size_t npaths,
                           enum mesh_units units,
                           const struct facet_stop *stop,
                           struct project *out, struct facet_error *err);

/* project_open of one file already read into *obj, which it takes over
 * and frees (a command that read the file to see whether it is a project,
 * project_count_named, does not read it again). */
int project_from_obj(const char *path, struct obj_file *obj,
                     enum mesh_units units, struct project *out,
                     struct facet_error *err);

/* How many surfaces a file names: its named objects, or without any, its
 * named groups; 0 when it names none (the file is one surface). */
size_t project_count_named(const struct obj_file *obj);

/* Prepares every surface (surface_prepare: its UV by method, curvature,
 * panel sums) and sets its u and v lengths. Returns FACET_OK or the first
 * surface's error, which names it. */
int project_prepare(struct project *project, int flip_normals,
                    enum param_method method, struct facet_error *err);

/* project_prepare, asking stop (surface_prepare_stoppable): FACET_ESTOP
 * when it fires. */
int project_prepare_stoppable(struct project *project, int flip_normals,
                              enum param_method method,
                              const struct facet_stop *stop,
                              struct facet_error *err);

/* project_prepare for a project whose surfaces' UV and curvature are
 * already set (read back from its cache, project_cache.h): the rest of
 * surface_prepare on each (surface_prepare_rest) and the u and v lengths,
 * the same to the bit as project_prepare makes them. */
int project_prepare_rest_stoppable(struct project *project,
                                   const struct facet_stop *stop,
                                   struct facet_error *err);

/* surface_units_check of the building as a whole: the box around every
 * surface, in the units the project was read in, so that a building in
 * millimetres read as metres is refused as one file is (a face of it may
 * alone be of a plausible size). A front-end asks it when its user did not
 * name the units. */
int project_units_check(const struct project *project,
                        struct facet_error *err);

/* The surface named name, or NULL. */
const struct project_surface *project_find(const struct project *project,
                                           const char *name);

/* "object", "group" or "file". */
const char *project_key_name(enum project_key key);

void project_close(struct project *project);

#endif
