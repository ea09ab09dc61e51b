/*
 * seam.h: where two surfaces of a building meet.
 *
 * A facade's worst joints are at the seams between its faces: a ridge, a
 * corner, a flat field meeting a curved band (issue 31). Two surfaces meet
 * along a seam where their boundaries coincide within a welding tolerance
 * w the user can set:
 *
 *   a boundary edge of surface a is on the seam with surface b when every
 *   sample of it (its ends, and points at most `spacing` apart between
 *   them) lies within w of b's boundary (the nearest point of any of b's
 *   boundary edges).
 *
 * The boundary edges are the mesh's edges with no triangle across
 * (mesh.h's neighbour MESH_NONE). A seam is seen from a: its samples are
 * on a's boundary, each with the nearest point of b's boundary across it.
 * Measured from b the samples differ, not the seam's length beyond w.
 *
 * The crease. At each sample the design's own angle between the two
 * surfaces: the angle between their unit normals there, each the
 * curvature fit's surface normal at the boundary edge's two vertices
 * (curvature.h) interpolated along the edge. So two faces of one smooth
 * surface have no crease (a cylinder cut along a ruling: 0, not the
 * facets' angle), and two walls of a box meet at 90 degrees. Faces wound
 * the opposite way (one's normals inward) are read consistently: two
 * consistently wound faces run their shared edge in opposite directions,
 * so where a's edge and b's run the same way, b's normal is turned over
 * first. The crease is what the design holds, never a fabrication
 * defect: a kink the panels add at a seam is measured against it.
 *
 * Units: metres and radians. Pure computation; the caller owns every
 * struct, and releases a seam with seam_free.
 */
#ifndef FACET_SEAM_H
#define FACET_SEAM_H

#include <stddef.h>
#include <stdint.h>

#include "core/base/error.h"
#include "core/surface/curvature.h"
#include "core/surface/mesh.h"

/* The welding tolerance when the user gives none: 1 mm, far above the
 * rounding of coordinates written by CAD (micrometres) and below any
 * joint a facade is built with (10 mm and more). */
#define SEAM_WELD_DEFAULT 0.001

/* The range a user's welding tolerance is taken in (m): above 0, as
 * coordinates computed apart never meet exactly, and up to 100 mm, beyond
 * which boundaries a joint apart would count as one seam. */
#define SEAM_WELD_MIN 1e-9
#define SEAM_WELD_MAX 0.1

/* Parses all of text, a welding tolerance in mm the user gave for the
 * setting what (a flag, a form's label), into *weld in m: a number from
 * SEAM_WELD_MIN to SEAM_WELD_MAX, as numparse_number reads it. The one
 * reading of a welding tolerance: `facet optimize --weld` and the
 * workbench's New run form. Returns FACET_OK, or FACET_EINPUT with a
 * message that starts with what; *weld is untouched on an error. */
int seam_weld_parse(const char *text, const char *what, double *weld,
                    struct facet_error *err);

struct seam_point {
    double at[3];           /* on a's boundary (m) */
    double across[3];       /* the nearest point of b's boundary (m) */
    uint32_t triangle_a;    /* the boundary triangles they lie on */
    uint32_t triangle_b;
    double normal_a[3];     /* a's unit surface normal at `at` */
    double normal_b[3];     /* b's at `across`, turned over when b is wound
                               the other way: on the side of normal_a */
    double crease;          /* the design's angle between a and b (rad) */
};

struct seam {
    size_t npoints;
    struct seam_point *points;  /* along a's seam edges, edge by edge */
    size_t nedges;              /* a's boundary edges on the seam */
    double length;              /* their length (m) */
    double max_crease;          /* over the points (rad); 0 when none */
    double max_apart;           /* the largest |at - across| (m) */
};

/* Finds the seam of surface a (mesh, its curvature) with surface b within
 * weld (m, >= 0), sampling a's boundary edges at most spacing (m, > 0)
 * apart, into *out (npoints 0 when the two do not meet). Returns FACET_OK,
 * FACET_EINPUT for a weld or spacing out of range, FACET_EWORK when out
 * of memory (*out then empty). */
int seam_find(const struct mesh *a, const struct curvature *curvature_a,
              const struct mesh *b, const struct curvature *curvature_b,
              double weld, double spacing, struct seam *out,
              struct facet_error *err);

void seam_free(struct seam *seam);

#endif
