/*
 * param_grid.h: the UV of a structured quad grid, what a CAD "mesh from
 * surface" export without vt is.
 *
 * A structured grid is a mesh of quads (OBJ faces of four corners, each
 * triangulated into two triangles, or, in a file of triangles only, pairs
 * of triangles that share their longest edge) whose vertices can be numbered (i, j),
 * 0 <= i <= NU, 0 <= j <= NV, so that every quad is a cell (i..i+1,
 * j..j+1): a disk with four corners (vertices of one quad), every other
 * boundary vertex in two quads and every inside vertex in four. Its UV is
 * (i, j) scaled by the mean length of the quads' edges along i and along j,
 * so the UV box is NU x NV cells and an NU x NV panel grid gives one panel
 * per quad. u runs along the rows of the file's vertex order (the way a
 * CAD export writes them), and the map keeps the faces' winding.
 */
#ifndef FACET_PARAM_GRID_H
#define FACET_PARAM_GRID_H

#include <stddef.h>

#include "core/surface/mesh.h"

/* Finds the grid of mesh. Returns FACET_OK with *vertex_uv (#V x 2,
 * malloc'ed, the caller's to free), the quads along u and v in *nu, *nv
 * and *paired set when the quads were paired from a file's triangles;
 * FACET_EINPUT when mesh is not a structured quad grid, with why
 * (size bytes) saying what breaks it; FACET_EWORK when out of memory. */
int param_grid(const struct mesh *mesh, double **vertex_uv, int *nu, int *nv,
               int *paired, char *why, size_t size);

#endif
