/*
 * mesh.h: the surface model every later stage works on.
 *
 * A triangle mesh in SI units (metres), built once from an obj_file: the
 * selected object or group, positions scaled by the units factor and welded
 * (OBJ vertices with identical coordinates become one vertex), per-corner UV
 * from vt (which may be split at seams while positions are welded), face
 * normals from the winding, edge adjacency, vertex-to-triangle incidence,
 * boundary loops, connected components, total area and bounding box.
 *
 * Ownership: mesh_build fills a caller-owned struct mesh; mesh_free releases
 * everything in it. The mesh does not point into the obj_file, which may be
 * freed once the mesh is built.
 */
#ifndef FACET_MESH_H
#define FACET_MESH_H

#include <stddef.h>
#include <stdint.h>

#include "core/base/error.h"
#include "core/base/stop.h"
#include "core/obj/obj.h"

#define MESH_NONE UINT32_MAX  /* no neighbour across a boundary edge */

enum mesh_units { UNITS_M, UNITS_CM, UNITS_MM, UNITS_IN, UNITS_FT };

struct mesh_options {
    enum mesh_units units;     /* what one OBJ unit is */
    const char *object;        /* keep only faces of this o name, or NULL */
    const char *group;         /* keep only faces of this g name, or NULL */
};

struct mesh {
    size_t nvertices;
    double *position;          /* #V x 3 vertex positions (m) */
    uint32_t *source_vertex;   /* #V: the first OBJ v index welded into it */

    size_t ntriangles;
    uint32_t *triangle;        /* #T x 3 vertex indices, winding as in file */
    uint32_t *source_face;     /* #T: the OBJ f statement it came from */
    double *face_normal;       /* #T x 3 unit normals from the winding */
    double *face_area;         /* #T triangle areas (m^2) */

    int has_uv;                /* every selected corner had a vt */
    double *uv;                /* #T x 3 x 2 per-corner (u, v), or NULL */
    int has_normals;           /* every selected corner had a vn */
    double *corner_normal;     /* #T x 3 x 3 unit vn per corner, or NULL */

    /* Adjacency: neighbour[3t+k] is the triangle across the edge from
     * corner k to corner (k+1)%3 of triangle t, MESH_NONE on a boundary or
     * non-manifold edge. */
    uint32_t *neighbour;       /* #T x 3 */
    size_t nonmanifold_edges;  /* edges shared by more than two triangles */
    size_t ndegenerate;        /* triangles dropped: corners welded together */

    /* Triangles around each vertex, compressed: the triangles of vertex v
     * are vertex_triangles[vertex_start[v] .. vertex_start[v+1]). */
    uint32_t *vertex_start;    /* #V + 1 */
    uint32_t *vertex_triangles;/* 3 #T */
    unsigned char *on_boundary;/* #V: 1 if the vertex lies on a boundary */

    /* Boundary loops, compressed like vertex_triangles: loop l runs through
     * loop_vertices[loop_start[l] .. loop_start[l+1]) in order. */
    size_t nloops;
    uint32_t *loop_start;      /* nloops + 1 */
    uint32_t *loop_vertices;

    size_t ncomponents;        /* edge-connected pieces */
    uint32_t *component;       /* #T: component of each triangle, 0-based */

    double area;               /* total area (m^2) */
    double bbox_min[3];        /* bounding box (m) */
    double bbox_max[3];
};

/* Metres per OBJ unit for u. */
double mesh_units_scale(enum mesh_units u);

/* Parses "m", "cm", "mm", "in" or "ft" into *out. Returns FACET_OK or
 * FACET_EINPUT with err naming the field what (the caller's name for it)
 * and the bad text. */
int mesh_units_parse(const char *text, const char *what,
                     enum mesh_units *out, struct facet_error *err);

/* The name of u, as mesh_units_parse accepts it. */
const char *mesh_units_name(enum mesh_units u);

/* Builds *out from obj with the options given. Fails with FACET_EINPUT when
 * no triangle is selected (unknown object or group, or an empty file) or a
 * triangle is degenerate beyond repair (all three corners welded into one
 * vertex is skipped, not an error). The caller releases *out with mesh_free,
 * also after a failure. */
int mesh_build(const struct obj_file *obj, const struct mesh_options *options,
               struct mesh *out, struct facet_error *err);

/* mesh_build, asking stop (stop.h) every few milliseconds: FACET_ESTOP
 * when it fires. */
int mesh_build_stoppable(const struct obj_file *obj,
                         const struct mesh_options *options,
                         const struct facet_stop *stop, struct mesh *out,
                         struct facet_error *err);

/* Builds *out, as mesh_build does, from the selected triangles list[0 ..
 * count) of obj (indices into its triangles, in the order the mesh keeps
 * them), with positions in units: how a project builds each of its
 * surfaces from one file read once. FACET_EINPUT when count is 0 or every
 * triangle is degenerate, FACET_ESTOP when stop (or NULL) fires. Release
 * *out with mesh_free, also after a failure. */
int mesh_build_triangles(const struct obj_file *obj, enum mesh_units units,
                         const uint32_t *list, size_t count,
                         const struct facet_stop *stop, struct mesh *out,
                         struct facet_error *err);

/* The sizes a building has, by the diagonal of its bounding box (m): a
 * surface outside them was most likely read in the wrong units (a 50 km
 * roof is a 50 m one in millimetres, a 4 mm facade a 4 m one in
 * metres). The tallest towers and the longest airport roofs stay
 * within the upper bound, a model of a small pavilion at 1:100 within
 * the lower one. */
#define MESH_BUILDING_MIN 0.05
#define MESH_BUILDING_MAX 2000.0

/* The diagonal of mesh's bounding box (m). */
double mesh_diagonal(const struct mesh *mesh);

/* Whether mesh, read in units given, has no building's size while another
 * unit gives it one: returns 1 and sets *better to that unit (of several,
 * the one that puts the diagonal nearest the geometric middle of a
 * building's sizes), else 0: the size is a building's, or no unit mends
 * it (a real 10 km site model), and mesh_units_warning says what it can.
 * The caller refuses the file unless its user named the units. */
int mesh_units_mistaken(const struct mesh *mesh, enum mesh_units given,
                        enum mesh_units *better);

/* mesh_units_mistaken of a bounding box's diagonal (m, as read in given):
 * a building of several surfaces is judged by the box around them all. */
int mesh_units_mistaken_at(double diagonal, enum mesh_units given,
                           enum mesh_units *better);

/* Writes into warning (size bytes) a one-line warning when the bounding box
 * suggests the units are wrong (a 40 km facade is probably millimetres, a
 * 4 mm one probably metres), and returns 1; otherwise returns 0. */
int mesh_units_warning(const struct mesh *mesh, enum mesh_units units,
                       char *warning, size_t size);

void mesh_free(struct mesh *mesh);

#endif
