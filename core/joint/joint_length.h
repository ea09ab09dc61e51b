/*
 * joint_length.h: the total length of the joints of a panelization.
 *
 * What a contractor prices per metre (gaskets, sealant) is every line
 * where a panel edge lies, each counted once:
 *
 *   joint length = sum over the interior grid lines (u = umin + i du,
 *                  i = 1..nu-1, and v = vmin + j dv, j = 1..nv-1) of the
 *                  length on the surface of the part the surface reaches
 *                + the length of the surface's outline.
 *
 * So an interior side shared by two panels counts once, at its length on
 * the surface; a trimmed panel's side counts at its real (cut) length;
 * and a panel side on the outline counts once, as outline. "On the
 * surface" is on the mesh: a grid line is followed through every triangle
 * it crosses, by the triangle's affine map from UV to 3D (the map panels
 * are built with), so a curved line is measured as the polyline of its
 * crossings, short of the smooth curve by the mesh's chord error.
 *
 * The outline is every mesh edge on a boundary, plus every edge along a
 * UV seam (where the two triangles beside it give its ends different UV,
 * so panels meet there too), each once. A grid line that runs exactly
 * along an outline edge counts only as outline. An edge shared by more
 * than two triangles (non-manifold) counts once for each.
 *
 * For a plane rectangle W x H with its UV along its sides, nu x nv:
 *   (nu - 1) H + (nv - 1) W + 2 (W + H).
 */
#ifndef FACET_JOINT_LENGTH_H
#define FACET_JOINT_LENGTH_H

#include <stdint.h>

#include "core/base/error.h"
#include "core/base/stop.h"
#include "core/panel/panel.h"
#include "core/surface/mesh.h"
#include "core/surface/uv_index.h"

/* A triangle as a grid line along one axis takes it: its corners'
 * coordinates along the axis, its vertices, and which of its edges lie on
 * the outline. */
struct joint_triangle {
    double x[3];          /* corner k's u (v) */
    uint32_t vertex[3];   /* corner k's mesh vertex */
    uint32_t outline;     /* bit k: edge k (corner k to k + 1) counts in
                             the outline */
};

/* What does not depend on the grid, computed once per surface: the
 * outline, and the triangles in order along each UV axis, so that a grid
 * line visits only the triangles it may cross, read in that order from
 * one array (about 40 bytes a triangle per axis). */
struct joint_prep {
    double outline;        /* the outline's length (m) */
    size_t ntriangles;
    uint32_t *order[2];    /* #T: triangles by their least u (v) */
    double *least[2];      /* #T: that least coordinate, in that order */
    struct joint_triangle *triangle[2];  /* #T: those triangles, in that
                                            order */
    double reach[2];       /* the largest extent of a triangle along u (v),
                              widened by rounding */
};

/* Fills *out (caller-owned, released with joint_prep_free, also after a
 * failure) for mesh with UV lookup index. Returns FACET_OK or FACET_EWORK
 * when out of memory. */
int joint_prep_build(const struct mesh *mesh, const struct uv_index *index,
                     struct joint_prep *out, struct facet_error *err);

void joint_prep_free(struct joint_prep *prep);

/* The joint length (m) of the grid of panels (its nu, nv and UV box),
 * built over mesh and index (for a prepared surface s: &s->mesh, &s->uv,
 * &s->joints). Takes O(log #T) per grid line plus the triangles the lines
 * cross, and no memory. */
double joint_length(const struct joint_prep *prep, const struct mesh *mesh,
                    const struct uv_index *index,
                    const struct panelization *panels);

/* The crossings of the grid lines many grids share, measured once: the
 * grids of a design space cut the UV box along far fewer lines than they
 * have (the paper's 336 grids, 23,700 lines, along 1,116 distinct ones).
 * Each line keeps the lengths joint_length adds for it, in the order it
 * adds them, so that the sum over a grid's lines is joint_length's to the
 * bit. */
struct joint_lines {
    double box[4];        /* the UV box (umin, vmin, umax, vmax) of the
                             grids the lines are of */
    size_t nline[2];      /* distinct lines along u (v) */
    double *line[2];      /* their coordinates, ascending */
    size_t *start[2];     /* nline + 1: line k's lengths are */
    size_t *count[2];     /* nline: length[start[k] .. start[k] +
                             count[k]) */
    double *length[2];    /* (m), the nonzero ones (a zero adds nothing) */
};

/* Measures the lines of the grids over the UV box of index whose side
 * along u is one of side[0][0..nsides[0]) and along v one of side[1][0..
 * nsides[1]), on up to jobs threads, into *out (caller-owned, released
 * with joint_lines_free, also after a failure). Returns FACET_OK or
 * FACET_EWORK when out of memory. */
int joint_lines_build(const struct joint_prep *prep, const struct mesh *mesh,
                      const struct uv_index *index, const int *const side[2],
                      const size_t nsides[2], int jobs,
                      struct joint_lines *out, struct facet_error *err);

void joint_lines_free(struct joint_lines *lines);

/* joint_length, to the bit, taking the lines lines holds from it (lines
 * NULL: none) and measuring the others. */
double joint_length_lines(const struct joint_lines *lines,
                          const struct joint_prep *prep,
                          const struct mesh *mesh,
                          const struct uv_index *index,
                          const struct panelization *panels);

/* joint_length_lines, asking stop at every grid line it measures (a fine
 * grid's lines take seconds): FACET_OK with the length in *length, or
 * FACET_ESTOP (stop.h) with *length untouched. */
int joint_length_lines_stoppable(const struct joint_lines *lines,
                                 const struct joint_prep *prep,
                                 const struct mesh *mesh,
                                 const struct uv_index *index,
                                 const struct panelization *panels,
                                 const struct facet_stop *stop,
                                 double *length, struct facet_error *err);

/* joint_length the plain way, for tests: every grid line against every
 * triangle, in prep's order (the order the sum is taken in), from the mesh
 * and index themselves. Equal to joint_length to the bit. */
double joint_length_plain(const struct joint_prep *prep,
                          const struct mesh *mesh,
                          const struct uv_index *index,
                          const struct panelization *panels);

/* The outline part alone (m): boundary and UV-seam edges, each once. */
double joint_outline_length(const struct mesh *mesh,
                            const struct uv_index *index);

#endif
