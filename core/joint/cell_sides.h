/*
 * cell_sides.h: the surface along every side of a panel grid's cells.
 *
 * Two neighbouring panels meet along the side their UV cells share; a
 * panel's outline is its four sides. This module samples the surface along
 * every cell side of a panelization once, so that the fit of single-curved
 * panels (sp_fit.h) and the gaps and kinks between panels (joint.h) read
 * the same points.
 *
 * Only the sides that need it are sampled (by the panels' classified
 * types): every side of an SP panel (its fit reads them), and every joint
 * between two panels but those between two flat quads and those between
 * two full DP panels (typed DP, not trimmed, every corner on the
 * surface). A side between two flat quads needs only its ends, the
 * panels' corners; two full DP panels both follow the surface, so their
 * gap and kink are 0 wherever they meet (joint.h says both). A side on
 * the grid's edge or next to an empty cell is no joint, and is sampled
 * only for an SP panel.
 *
 * A sampled side s is sampled at CELL_SIDE_SEGMENTS + 1 points evenly spaced in UV,
 * ends included (the cell corners, located as panels_build locates them).
 * A sample is the surface point at that UV by the affine map of the mesh
 * triangle holding it, so the samples lie on the mesh, and the piecewise
 * linear curve through them follows the mesh's own to within the sag of
 * one sample spacing. Where the UV point is off the surface (a trimmed
 * panel's side), the sample is marked off. A side's samples, to the last
 * bit, depend on the side alone, not on which other sides are sampled: a
 * UV point on a mesh edge is placed in the triangle the UV lookup gives
 * (uv_index_locate), whichever triangle a search from the sample before
 * reached first. (On a UV parameterization that folds over itself, where
 * two triangles hold one point well inside both, this cannot hold.)
 *
 * Sides are numbered: the side on the line u = umin + i du between rows j
 * and j + 1 is cell_side_u(sides, i, j), i = 0..nu, j = 0..nv-1; the side
 * on v = vmin + j dv between columns i and i + 1 is cell_side_v(sides, i,
 * j), i = 0..nu-1, j = 0..nv. Sample k of side s lies at fraction k /
 * CELL_SIDE_SEGMENTS from the side's first end (lower v, resp. lower u).
 *
 * Ownership: cell_sides_sample fills a caller-owned struct; every array is
 * allocated by it and released by cell_sides_free.
 */
#ifndef FACET_CELL_SIDES_H
#define FACET_CELL_SIDES_H

#include <stddef.h>
#include <stdint.h>

#include "core/base/error.h"
#include "core/panel/panel.h"
#include "core/surface/curvature.h"
#include "core/surface/mesh.h"
#include "core/surface/uv_index.h"

#define CELL_SIDE_SEGMENTS 8
#define CELL_SIDE_SAMPLES (CELL_SIDE_SEGMENTS + 1)

struct cell_sides {
    int nu, nv;
    size_t nsides;        /* (nu + 1) nv + nu (nv + 1) */
    double *point;        /* nsides x CELL_SIDE_SAMPLES x 3 (m); NaN off
                             the surface */
    double *smooth;       /* the same samples on the smooth surface through
                             the mesh's vertices (m, NaN off the surface):
                             each moved off its facet as Phong tessellation
                             with shape factor 1/2 moves it, by
                             1/2 sum b_i ((p_i - x).n_i) n_i over the
                             triangle's vertices p_i with their surface
                             normals n_i (curvature.h), b the sample's
                             barycentrics. On a
                             quadric with exact normals that is the height
                             of the surface over the facet to second order
                             (a cylinder of R = 7.567 m with facets sagging
                             4.1 mm: within 0.02 mm), so a facet's sag is
                             taken out of what is measured there */
    signed char *middle;  /* nsides: the sample nearest the side's middle
                             that lies on the surface (of samples 1 ..
                             CELL_SIDE_SEGMENTS), or -1 when none does */
    double *normal;       /* nsides x 3: the unit surface normal at that
                             sample: its triangle's corners' surface
                             normals (curvature.h) each carried halfway to
                             it by its shape operator, blended by its
                             barycentrics (second-order exact), on the side
                             of the face normal (the side panel normals are
                             on); NaN without one */
    unsigned char *on;    /* nsides x CELL_SIDE_SAMPLES: 1 on the surface */
    unsigned char *sampled;  /* nsides: 1 when the side was sampled; point,
                                on, middle and normal are unset
                                otherwise (smooth and normal NULL when
                                cell_sides_sample_fits_stoppable did not
                                take them) */
};

static inline size_t cell_side_u(const struct cell_sides *s, int i, int j)
{
    return (size_t)j * (size_t)(s->nu + 1) + (size_t)i;
}

static inline size_t cell_side_v(const struct cell_sides *s, int i, int j)
{
    return (size_t)(s->nu + 1) * (size_t)s->nv +
           (size_t)j * (size_t)s->nu + (size_t)i;
}

/* 1 when panel is built as the planar quad of its four corners: typed FP,
 * not trimmed, every corner on the surface. */
int cell_sides_flat_quad(const struct panel *panel);

/* Samples the sides of panels' grid (classified) over the surface mesh with UV lookup
 * index (the index panels was built over) and vertex normals from
 * curvature. Fills *out (release with cell_sides_free, also after a
 * failure). Returns FACET_OK or FACET_EWORK when out of memory. */
int cell_sides_sample(const struct mesh *mesh, const struct uv_index *index,
                      const struct curvature *curvature,
                      const struct panelization *panels,
                      struct cell_sides *out, struct facet_error *err);

/* Samples every side of panels' grid, whatever the panels' types (as
 * cell_sides_sample otherwise): the sides of a grid classified at several
 * thresholds (sp_fit.h's grid_fits). Each side's samples are those
 * cell_sides_sample gives it, to the bit. */
int cell_sides_sample_every(const struct mesh *mesh,
                            const struct uv_index *index,
                            const struct curvature *curvature,
                            const struct panelization *panels,
                            struct cell_sides *out, struct facet_error *err);

/* The two above, asking stop at every grid line they walk (a fine grid's
 * sides take seconds): also FACET_ESTOP (stop.h), with *out released. */
int cell_sides_sample_stoppable(const struct mesh *mesh,
                                const struct uv_index *index,
                                const struct curvature *curvature,
                                const struct panelization *panels,
                                const struct facet_stop *stop,
                                struct cell_sides *out,
                                struct facet_error *err);
int cell_sides_sample_every_stoppable(const struct mesh *mesh,
                                      const struct uv_index *index,
                                      const struct curvature *curvature,
                                      const struct panelization *panels,
                                      const struct facet_stop *stop,
                                      struct cell_sides *out,
                                      struct facet_error *err);

/* cell_sides_sample_stoppable for a caller that fits the SP panels
 * (sp_fit.h) and measures no joints: only the SP panels' sides are
 * sampled, and of them only what the fits read: point, on and middle,
 * and smooth when smooth is 1 (NULL when 0); normal is NULL. Each side it
 * samples has the samples cell_sides_sample gives it, to the bit (the
 * sides of the other panels, the normals and the unused smooth points are
 * work no fit reads: issue 27's run that measures fits alone). Not for
 * joints_measure. */
int cell_sides_sample_fits_stoppable(const struct mesh *mesh,
                                     const struct uv_index *index,
                                     const struct curvature *curvature,
                                     const struct panelization *panels,
                                     int smooth,
                                     const struct facet_stop *stop,
                                     struct cell_sides *out,
                                     struct facet_error *err);

/* The sides cell_sides_sample samples for panels (classified), into
 * sampled (nsides, as cell_sides numbers them): 1 for a side to sample. */
void cell_sides_mark(const struct panelization *panels,
                     unsigned char *sampled);

void cell_sides_free(struct cell_sides *sides);

#endif
