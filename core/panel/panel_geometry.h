/*
 * panel_geometry.h: the surface patch of every panel, as plain arrays.
 *
 * panel.h measures panels without keeping their shape; exports (OBJ, SVG)
 * need the shape itself. For a panelization built by panels_build on a
 * mesh and a UV index, this module keeps:
 *
 *   - the pieces: each mesh triangle clipped to a panel's UV cell, exactly
 *     the pieces panels_build measured (panels_walk_pieces), as convex
 *     polygons with 3D positions and UV; their areas add up to the panel's
 *     area;
 *   - the outline: the boundary of each panel's patch as closed loops. For
 *     an untrimmed panel that is one loop through its four cell corners
 *     and the points where the cell's border crosses mesh edges, in order;
 *     for a trimmed one, the boundary of the clipped region (which may be
 *     several loops: two lobes in one cell, or a hole);
 *   - the outline projected onto the panel's best-fit plane (panel->centroid,
 *     panel->normal), the shape a flat (FP) panel is cut to.
 *
 * A panel of a planarized option whose corners were moved (planar_option.h:
 * corner_moved known, untrimmed, four corners; panel_geometry_is_moved) is
 * its moved quad, not the design surface's patch: four vertices at its
 * corners (panel->corner) with its cell's corners' UV, two triangle
 * pieces (cut along the diagonal whose triangles face the same way, so
 * that a quad with a reflex corner is cut through it and their areas add
 * up to the quad's) and one loop through the four, wound as the surface
 * faces; so every file drawn from the geometry (OBJ, DXF, IFC) draws what
 * is built, where it is.
 *
 * Vertices are shared within a panel (pieces of neighbouring triangles meet
 * at the same vertex, merged when their UV agree to within rounding,
 * 1e-9 of a cell, and so do their positions, to 1e-9 of the panel's
 * diameter) and never between panels, so each panel's arrays stand
 * alone. A piece thinner than that in both UV and space (a triangle corner
 * a hair off a cell line) collapses and is dropped, with an area of at
 * most about 1e-9 of the panel's; a piece the UV squeezes to a point but
 * space does not (far inside a harmonic map) is kept. Loops and pieces keep the mesh's winding, so a polygon written
 * from them faces the same way as the surface.
 *
 * Ownership: panel_geometry_build fills a caller-owned struct; every array
 * in it is allocated by the build and released by panel_geometry_free. It
 * does not point into the mesh, the index or the panelization.
 */
#ifndef FACET_PANEL_GEOMETRY_H
#define FACET_PANEL_GEOMETRY_H

#include <stddef.h>
#include <stdint.h>

#include "core/base/error.h"
#include "core/base/stop.h"
#include "core/surface/mesh.h"
#include "core/panel/panel.h"
#include "core/surface/uv_index.h"

struct panel_geometry {
    size_t npanels;             /* as the panelization; panel n of the
                                   geometry is panels->panels[n] */

    /* Vertices, panel by panel: */
    size_t nvertices;
    double *position;           /* #V x 3 on the surface (m) */
    double *uv;                 /* #V x 2 in the UV the panels follow */
    size_t *panel_vertex;       /* npanels + 1: panel n's vertices are
                                   [panel_vertex[n], panel_vertex[n+1]) */

    /* Pieces: convex polygons of at most PANEL_PIECE_MAX corners. */
    size_t npieces;
    size_t *panel_piece;        /* npanels + 1: panel n's pieces are
                                   [panel_piece[n], panel_piece[n+1]) */
    size_t *piece_start;        /* npieces + 1: piece p's corners are
                                   corner[piece_start[p] .. [p+1]) */
    size_t *corner;             /* vertex indices (into position, uv) */
    uint32_t *piece_triangle;   /* npieces: the mesh triangle it was cut
                                   from; PANEL_GEOMETRY_NO_TRIANGLE for a
                                   moved quad, cut from none */

    /* Outline: closed loops of vertex indices (the last joins the first). */
    size_t nloops;
    size_t *panel_loop;         /* npanels + 1: panel n's loops are
                                   [panel_loop[n], panel_loop[n+1]) */
    size_t *loop_start;         /* nloops + 1: loop l's points are
                                   outline[loop_start[l] .. [l+1]) */
    size_t *outline;            /* vertex indices, in order along the
                                   boundary */
    double *outline_plane;      /* loop_start[nloops] x 3: each outline
                                   point projected onto its panel's
                                   best-fit plane (m) */
};

/* Builds the geometry of panels, which panels_build made from mesh and
 * index (for a prepared surface s: &s->mesh, &s->uv).
 *   mesh    the surface (m)
 *   index   the UV lookup the panels follow (its per-corner UV, #T x 3 x 2)
 *   panels  the panelization; its centroids and normals give the planes
 * Fills *out (caller-owned; release with panel_geometry_free, also after a
 * failure). Returns FACET_OK, FACET_EINPUT when panels was not built over
 * index's UV box, FACET_EWORK when out of memory. */
int panel_geometry_build(const struct mesh *mesh,
                         const struct uv_index *index,
                         const struct panelization *panels,
                         struct panel_geometry *out,
                         struct facet_error *err);

/* panel_geometry_build, asking stop (core/base/stop.h; NULL: never)
 * between its walks over the triangles and every few thousand panels:
 * FACET_ESTOP when it fires (*out released with panel_geometry_free). */
int panel_geometry_build_stoppable(const struct mesh *mesh,
                                   const struct uv_index *index,
                                   const struct panelization *panels,
                                   const struct facet_stop *stop,
                                   struct panel_geometry *out,
                                   struct facet_error *err);

void panel_geometry_free(struct panel_geometry *geometry);

/* A moved quad's piece_triangle. */
#define PANEL_GEOMETRY_NO_TRIANGLE UINT32_MAX

/* Whether panel n of panels is drawn as its moved quad (above): a
 * planarized option's full panel, its corner move known. */
int panel_geometry_is_moved(const struct panelization *panels, size_t n);

/* x (m) projected onto panel's best-fit plane (through panel->centroid,
 * normal panel->normal) into out (m); out may not alias x. */
void panel_geometry_project(const struct panel *panel, const double x[3],
                            double out[3]);

/* The 3D area of piece p (m^2). */
double panel_geometry_piece_area(const struct panel_geometry *geometry,
                                 size_t p);

/* The area enclosed by loop l of the projected outline, measured in its
 * panel's plane with normal (unit) (m^2): positive when the loop winds
 * counter-clockwise seen from the normal's side, as an outer boundary of a
 * surface facing that side does. */
double panel_geometry_loop_area(const struct panel_geometry *geometry,
                                size_t l, const double normal[3]);

#endif
