/*
 * mould_sample.h: the shape of a panel as a fixed set of surface points.
 *
 * Two panels share a mould when one, moved rigidly, lies on the other
 * (mould.h). To compare shapes cheaply and by corresponding points, each
 * untrimmed panel is sampled at the same places of its UV cell: a
 * MOULD_SIDE x MOULD_SIDE lattice at cell fractions 0, 1/4, 1/2, 3/4, 1 in
 * u and in v, its four corners being the panel's own corners
 * (panel->corner). Each point is the surface point at that UV, found as
 * panels_build finds the corners: the mesh triangle whose UV holds it
 * (uv_index_locate) and that triangle's affine map (panel_piece_point).
 *
 * The lattice is square and symmetric, so each of the 8 ways of laying a
 * quad onto another (4 turns x 2 corner orders) maps sample indices onto
 * sample indices (mould_fit.h).
 *
 * A trimmed panel is not sampled: its outline is a cut through the cell,
 * which the lattice does not see, so two trimmed panels with the same
 * lattice points may still need different blanks. mould.h gives each
 * trimmed panel a family of its own.
 */
#ifndef FACET_MOULD_SAMPLE_H
#define FACET_MOULD_SAMPLE_H

#include <stddef.h>

#include "core/base/stop.h"
#include "core/panel/panel.h"
#include "core/surface/mesh.h"
#include "core/surface/uv_index.h"

#define MOULD_SIDE 5                            /* lattice points a side */
#define MOULD_SAMPLES (MOULD_SIDE * MOULD_SIDE) /* points a panel */

/* The sample index of lattice point (a, b), a along u, b along v, each
 * 0..MOULD_SIDE-1: at cell fraction (a, b) / (MOULD_SIDE - 1). */
static inline int mould_sample_index(int a, int b)
{
    return b * MOULD_SIDE + a;
}

/* Samples panel n of panels, built over mesh and index (for a prepared
 * surface s: &s->mesh, &s->uv), into out (m): out[mould_sample_index(a,
 * b)] is the surface point at the cell's fraction (a, b) / (MOULD_SIDE -
 * 1). Returns 1, or 0 (out undefined) for a trimmed panel, one with a
 * corner off the surface, or one with a lattice point the surface does not
 * reach. */
int mould_sample_panel(const struct mesh *mesh, const struct uv_index *index,
                       const struct panelization *panels, size_t n,
                       double out[MOULD_SAMPLES][3]);

/* Samples every panel n of panels with want[n] set into out[n] as
 * mould_sample_panel(mesh, index, panels, n, out[n]) does, to the bit, and
 * sets sampled[n] to what it returns (0 where want[n] is not set). The
 * samples on a side two cells share are at the same UV, so they are
 * located once, a band of cells at a time along v: a grid takes about 15
 * lookups a panel instead of 21. Asks stop (NULL: never) at every band.
 * Returns FACET_OK, FACET_EWORK when out of memory, or FACET_ESTOP when
 * stop asked (the caller says so: no message is set here). */
int mould_sample_grid(const struct mesh *mesh, const struct uv_index *index,
                      const struct panelization *panels,
                      const unsigned char *want,
                      double (*out)[MOULD_SAMPLES][3],
                      unsigned char *sampled,
                      const struct facet_stop *stop);

#endif
