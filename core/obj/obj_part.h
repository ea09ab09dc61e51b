/*
 * obj_part.h: one piece of an OBJ file, parsed on its own.
 *
 * Internal to the OBJ reader (obj.c), not part of the library's API. obj.c
 * cuts the file text into parts at line boundaries; each part is parsed by
 * obj_part_parse, possibly on its own thread, into arrays of its own. Until
 * the parts before it are known, a part cannot resolve negative indices,
 * check indices or see the positions its faces use, so it keeps its faces
 * as written (corners resolved as far as it can) and obj_part_emit writes
 * their triangles into the merged obj_file later, once obj.c has set the
 * part's bases and name maps (see "set by the merge" below).
 *
 * Line numbers here are part-local: 0 is the part's first line.
 */
#ifndef FACET_OBJ_PART_H
#define FACET_OBJ_PART_H

#include <stddef.h>
#include <stdint.h>

#include "core/base/error.h"
#include "core/obj/obj.h"
#include "core/obj/obj_table.h"
#include "core/obj/triangulate.h"

#define OBJ_INHERITED UINT32_MAX  /* name id: current where the part starts */

/* Flags in obj_part.relative: which indices of a corner were negative and
 * resolved against the part's own count (so the part's base must be added). */
enum { OBJ_RELATIVE_V = 1, OBJ_RELATIVE_VT = 2, OBJ_RELATIVE_VN = 4 };

/* One f statement as written. */
struct obj_part_face {
    uint32_t ncorners;  /* at least 3 */
    uint32_t line;      /* part-local line of the statement */
};

/* From face first_face on, these names are current (part-local ids into
 * the part's tables, or OBJ_INHERITED). */
struct obj_part_state {
    size_t first_face;
    uint32_t object, group, material;
};

/* A negative index that reaches before the part's first element: resolved
 * (or found to be an error) by the merge. */
struct obj_part_before {
    size_t corner;    /* its slot in obj_part.corner */
    size_t line;      /* part-local */
    uint64_t value;   /* as written, without the '-' */
    size_t count;     /* elements of that kind the part had read before */
    int which;        /* 0 = v, 1 = vt, 2 = vn */
};

/* The first thing wrong in a part; formatted as "NAME:LINE: what". */
struct obj_part_error {
    int code;         /* FACET_OK, FACET_EINPUT or FACET_EWORK */
    size_t line;      /* part-local */
    char what[400];
};

struct obj_part {
    size_t nvertices;
    double *position;          /* nvertices x 3 */
    double *color;             /* nvertices x 3, or NULL if no colour */
    size_t ncolors;
    size_t vertex_capacity;
    size_t ntexcoords;
    double *texcoord;          /* ntexcoords x 2 */
    size_t texcoord_capacity;
    size_t nnormals;
    double *normal;            /* nnormals x 3 */
    size_t normal_capacity;

    size_t nfaces;
    struct obj_part_face *face;
    size_t face_capacity;
    size_t ntriangles;         /* sum of ncorners - 2 */
    size_t ncorners;
    struct obj_corner *corner; /* ncorners, face after face */
    size_t corner_capacity;
    uint8_t *relative;         /* ncorners OBJ_RELATIVE_* flags, or NULL */
    struct obj_part_before *before;
    size_t nbefore;
    size_t before_capacity;

    struct obj_part_state *state;  /* nstates, by first_face */
    size_t nstates;
    size_t state_capacity;
    struct obj_names objects, groups, materials;
    uint32_t object, group, material;  /* current ids */
    struct obj_name *mtllibs;
    size_t nmtllibs;
    size_t mtllib_capacity;

    size_t line;               /* newlines read: the part's line count */
    size_t nstatements;
    size_t nskipped;
    int unterminated;          /* the text ends without a newline */
    char *text;                /* a name being read */
    size_t text_capacity;
    struct obj_part_error error;

    /* Set by the merge before obj_part_emit. */
    size_t line_base;          /* file line of the part's first line */
    size_t vertex_base, texcoord_base, normal_base;  /* elements before */
    size_t face_base, triangle_base;
    const uint32_t *object_map;   /* part-local id -> merged id */
    const uint32_t *group_map;
    const uint32_t *material_map;
    uint32_t inherited_object, inherited_group, inherited_material;
};

/* Per-thread working memory of obj_part_emit; zero it before first use and
 * release it with obj_emitter_free. */
struct obj_emitter {
    double *point;
    size_t point_capacity;
    uint32_t *local;
    size_t local_capacity;
    struct triangulate_scratch scratch;
};

/* Zeroes *part and makes every current name OBJ_INHERITED. */
void obj_part_init(struct obj_part *part);

/* Frees everything the part still owns and zeroes it. */
void obj_part_free(struct obj_part *part);

/* Parses the text [text, end), which starts at the start of a line and
 * ends at the end of one (just after its newline) or of the file, into the
 * part. Stops at the first error. Returns FACET_OK, or the error code with
 * part->error set. Allocates only as arrays grow and per new name. */
int obj_part_parse(struct obj_part *part, const char *text, const char *end);

/* Writes the triangles of faces [first, end) of the part into obj, whose
 * counts are the merged totals and whose positions and per-triangle arrays
 * are allocated (positions filled). Indices are checked against the totals.
 * Returns FACET_OK, or the code of the first face in error with *error set.
 * Different face ranges may be written by different threads at once. */
int obj_part_emit(struct obj_part *part, size_t first, size_t end,
                  struct obj_file *obj, struct obj_emitter *emitter,
                  struct obj_part_error *error);

void obj_emitter_free(struct obj_emitter *emitter);

#endif
