/*
 * example_skin.h: the generated example building skin, `facet example skin`.
 *
 * A 180 m tower whose plan is a rounded rectangle (100 m x 60 m, corner
 * radius 18 m), cut by a grid of seams into 20 columns around x 9 rows of
 * 20 m = 180 faces, each written as its own `o` with its own vertices and
 * its own vt, as Rhino exports a polysurface's faces:
 *
 *   rows 0-1 (z < 40 m), the podium: a vertical extrusion of the plan, so
 *     the faces on the straight sides are flat and those on the corner
 *     arcs single-curved (cylinders);
 *   rows 2-8: the plan scaled by a bulge s(z) = 1 + 0.12 sin^2(pi (z -
 *     40) / 140): the straight sides become single-curved (a profile
 *     extruded horizontally), the corners double-curved;
 *   rows 6-8 (z > 120 m): also twisted about the vertical axis by
 *     0.35 smoothstep((z - 120) / 60) rad: every face double-curved.
 *
 * Columns: each long side (64 m straight) 4 columns of 16 m, each short
 * side (24 m) 2 of 12 m, each corner arc (28.27 m) 2 columns. Faces are
 * named skin_rRR_cCC (row from the bottom; column counter-clockwise from
 * the south end of the short east side, x = +50 m). Every face is res x res quads
 * (default 75: 2,025,000 triangles), split along alternating diagonals.
 *
 * Seams are watertight: a vertex on a seam is computed once from its
 * global grid indices, so both faces write the same text for it. vt is
 * the face's own (s, t) in [0,1]^2, except on the podium's flat faces,
 * whose vt is in metres along the face (as Rhino gives a planar face),
 * (0,0) at the face's lower-left corner. Normals point outwards. Positions
 * are written to the micrometre, vt to 1e-9.
 *
 * Deterministic: the same res gives the same bytes.
 */
#ifndef FACET_EXAMPLE_SKIN_H
#define FACET_EXAMPLE_SKIN_H

#include <stdio.h>

#include "core/base/error.h"

#define SKIN_ROWS 9
#define SKIN_COLUMNS 20
#define SKIN_FACES (SKIN_ROWS * SKIN_COLUMNS)
#define SKIN_DEFAULT_RES 75
#define SKIN_MAX_RES 1024

/* What a face is by construction: its Gaussian curvature's kind. */
enum skin_kind { SKIN_FLAT, SKIN_SINGLE, SKIN_DOUBLE };

/* Face f (0..SKIN_FACES-1, row-major from the bottom: f = row * 20 +
 * column) at its own parameters (s, t) in [0,1]^2 into p (m): s runs
 * counter-clockwise around the tower, t upwards. */
void skin_point(int face, double s, double t, double p[3]);

/* The kind of face f, and whether its vt is in metres (1) or [0,1] (0). */
enum skin_kind skin_face_kind(int face);
int skin_face_vt_metres(int face);

/* The name of face f ("skin_r03_c12") into name (size bytes). */
void skin_face_name(int face, char *name, size_t size);

/* Writes the skin as OBJ to out, res x res quads per face (0: the
 * default). FACET_EINPUT for res outside 1..SKIN_MAX_RES, FACET_EWORK for
 * a write error. Streams: memory does not grow with res. */
int skin_write(int res, FILE *out, struct facet_error *err);

#endif
