/*
 * panel_lattice.h: the panels of every grid of a design space from one
 * division of the surface.
 *
 * The grids nu x nv of a design space (nu in u_lo..u_hi, nv in
 * v_lo..v_hi) cut the UV box along a few hundred distinct lines: the
 * paper's space, 336 grids, along 506 lines in u and 610 in v. The lattice
 * clips the surface once along all of them into fine cells and keeps:
 *   - each fine cell's area and moments, and their running (prefix) sums
 *     in extended precision, so that a grid's cell is four lookups;
 *   - the points a panel's deviation, curvature and outline are sampled
 *     at, filed by the line they lie on: a grid visits the mesh points,
 *     the cut points of its own lines and the crossings of its own lines.
 * A grid then costs a few times a pass over the mesh points instead of a
 * clipping of every triangle that crosses one of its lines. The panels are
 * panels_build_fast's (PANEL_EXTREMES) to rounding, tested against
 * panels_build.
 *
 * A lattice costs about 500 bytes per line crossing, and some more per
 * mesh point and per cut of a line by a mesh edge (the paper's space on a
 * 100,000-triangle surface: 310,000 crossings, 150 MB); it is built only
 * up to PANEL_LATTICE_MAX_NODES crossings.
 */
#ifndef FACET_PANEL_LATTICE_H
#define FACET_PANEL_LATTICE_H

#include "core/base/error.h"
#include "core/base/stop.h"
#include "core/panel/panel.h"

#define PANEL_LATTICE_MAX_NODES 600000

struct panel_lattice;

/* Builds the lattice of prep's surface for the grids nu in u_lo..u_hi by
 * nv in v_lo..v_hi, on up to jobs threads, into *out (caller-owned,
 * released with panel_lattice_free; it borrows prep, which must outlive
 * it). *out is NULL, with FACET_OK, when the lattice would exceed
 * PANEL_LATTICE_MAX_NODES line crossings. Returns FACET_OK, FACET_EINPUT
 * for sides outside 1..PANEL_MAX_GRID or a UV box without extent,
 * FACET_EWORK when out of memory. */
int panel_lattice_build(const struct panel_prep *prep, int u_lo, int u_hi,
                        int v_lo, int v_hi, int jobs,
                        struct panel_lattice **out, struct facet_error *err);

/* panel_lattice_build, asking stop (core/base/stop.h) while it divides
 * the triangles, the longest of its steps (seconds on ten million
 * triangles): FACET_ESTOP when it fires, *out NULL. */
int panel_lattice_build_stoppable(const struct panel_prep *prep, int u_lo,
                                  int u_hi, int v_lo, int v_hi, int jobs,
                                  const struct facet_stop *stop,
                                  struct panel_lattice **out,
                                  struct facet_error *err);

/* The memory the lattice holds (bytes). */
size_t panel_lattice_bytes(const struct panel_lattice *lattice);

/* Whether grid nu x nv is one of the lattice's. */
int panel_lattice_has(const struct panel_lattice *lattice, int nu, int nv);

/* panels_build_fast(prep, PANEL_EXTREMES, nu, nv, out) from the lattice:
 * the same panels, to rounding. Same returns; FACET_EINPUT also for a grid
 * that is not the lattice's. */
int panels_build_lattice(const struct panel_lattice *lattice, int nu,
                         int nv, struct panelization *out,
                         struct facet_error *err);

/* panels_build_lattice, asking stop (NULL: never) between its passes over
 * the cells: FACET_ESTOP when it fires. */
int panels_build_lattice_stoppable(const struct panel_lattice *lattice,
                                   int nu, int nv,
                                   const struct facet_stop *stop,
                                   struct panelization *out,
                                   struct facet_error *err);

void panel_lattice_free(struct panel_lattice *lattice);

#endif
