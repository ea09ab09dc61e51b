/*
 * obj.h: reading Wavefront OBJ files.
 *
 * The loader reads what a CAD or DCC export holds: v (with optional w and
 * vertex colours), vt, vn, f in every index form (v, v/vt, v//vn, v/vt/vn),
 * negative (relative) indices, polygons of any size, o/g names, usemtl and
 * mtllib (recorded, not read), comments, CRLF, tabs and '\' continuations.
 * s, l, p and statements it does not know are skipped.
 *
 * Polygons are triangulated by ear clipping in the polygon's own plane, so a
 * non-convex planar polygon comes out right. Coordinates are kept exactly as
 * written (no unit conversion; that is mesh.h's job).
 *
 * The file is read with read() (not mapped): whole when it is up to 1 GiB,
 * else in 64 MiB windows. The text is cut at line boundaries into parts
 * parsed on up to one thread per core (a small file stays on the calling
 * thread), then merged in file order; no allocation per line. Every error
 * names the file, the line and what is wrong, the first in file order.
 */
#ifndef FACET_OBJ_H
#define FACET_OBJ_H

#include <stddef.h>
#include <stdint.h>

#include "core/base/error.h"
#include "core/base/stop.h"

#define OBJ_NONE UINT32_MAX  /* an absent vt or vn index */

/* One corner of a triangle: 0-based indices into the file's arrays. */
struct obj_corner {
    uint32_t v;   /* position index */
    uint32_t vt;  /* texcoord index, or OBJ_NONE */
    uint32_t vn;  /* normal index, or OBJ_NONE */
};

/* A name from an o, g or usemtl statement. */
struct obj_name {
    char *text;   /* owned, NUL-terminated, trimmed */
};

struct obj_file {
    size_t nvertices;
    double *position;      /* nvertices x 3, as written (x, y, z) */
    double *color;         /* nvertices x 3 vertex colours, or NULL if none */
    size_t ncolors;        /* vertices that carried a colour */

    size_t ntexcoords;
    double *texcoord;      /* ntexcoords x 2 (u, v); w is dropped */

    size_t nnormals;
    double *normal;        /* nnormals x 3, as written (not normalised) */

    size_t nfaces;         /* f statements in the file */
    size_t ntriangles;     /* after triangulation */
    struct obj_corner *corner;  /* ntriangles x 3 */
    uint32_t *triangle_face;    /* ntriangles: the f statement (0-based) */
    uint32_t *triangle_object;  /* ntriangles: index into objects */
    uint32_t *triangle_group;   /* ntriangles: index into groups */
    uint32_t *triangle_material;/* ntriangles: index into materials */

    /* Name tables. Index 0 of objects and groups is the unnamed default
     * ("" : faces before any o or g statement); index 0 of materials is ""
     * (no usemtl). Later entries are distinct names in order of first use. */
    size_t nobjects;
    struct obj_name *objects;
    size_t ngroups;
    struct obj_name *groups;
    size_t nmaterials;
    struct obj_name *materials;
    size_t nmtllibs;
    struct obj_name *mtllibs;  /* mtllib file names, as written */

    size_t nlines;             /* physical lines read */
    size_t nskipped;           /* statements skipped (s, l, p, unknown) */
};

/* Loads the OBJ file at path into *out (which the caller owns and must
 * release with obj_free, also after a failure). Returns FACET_OK, or
 * FACET_EINPUT for a missing, unreadable, empty, binary or malformed file,
 * FACET_EWORK for out of memory or an I/O error, with err naming the
 * file, the line and what is wrong. */
int obj_load(const char *path, struct obj_file *out, struct facet_error *err);

/* obj_load, asking stop (stop.h) every few milliseconds of reading and
 * parsing: FACET_ESTOP when it fires, *out then to be released as after
 * any failure. */
int obj_load_stoppable(const char *path, const struct facet_stop *stop,
                       struct obj_file *out, struct facet_error *err);

/* Parses an OBJ held in memory. name is used in error messages only. The
 * text need not be NUL-terminated. Ownership as obj_load. */
int obj_parse(const char *text, size_t length, const char *name,
              struct obj_file *out, struct facet_error *err);

/* Frees everything obj_load or obj_parse allocated and zeroes *obj. */
void obj_free(struct obj_file *obj);

/* Writes the names of a table, skipping the unnamed entry 0, into text
 * (size bytes) as "a, b, c", ending in "..." when they do not fit. */
void obj_names_list(const struct obj_name *names, size_t count, char *text,
                    size_t size);

#endif
