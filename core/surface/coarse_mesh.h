/*
 * coarse_mesh.h: telling when a mesh is coarser than its panels.
 *
 * Curvature is estimated for the smooth surface the mesh samples, while a
 * panel's deviation is measured on the mesh itself. When a panel is only a
 * facet or two across, the two part: the curvature says flat, and the
 * deviation measures the fold lines between facets (compas_hypar, an 8 x 8
 * quad hypar at 20 x 35 panels: 488 of 700 FP panels deviate more than
 * 3 mm). Facet then warns, so that a FP panel beyond the threshold is read
 * as what it is: a panel smaller than the design's own facets.
 */
#ifndef FACET_COARSE_MESH_H
#define FACET_COARSE_MESH_H

#include <stddef.h>

#include "core/base/error.h"
#include "core/surface/mesh.h"
#include "core/panel/panel.h"

/* A panel is coarse-meshed when the facets are at least this fraction of
 * its side: fewer than two facets across it. */
#define COARSE_MESH_RATIO 0.5

/* The typical facet of mesh (m): the median over its triangles of
 * sqrt(2 x area), the side of the quad a triangle is half of, into *size;
 * 0 for a mesh without triangles. Returns FACET_OK, or FACET_EWORK when out
 * of memory (*size is then 0). */
int mesh_facet_size(const struct mesh *mesh, double *size,
                    struct facet_error *err);

/* The typical side of p's panels (m): the square root of the median area
 * of the panels that are not trimmed (of all panels when every one is),
 * into *side; 0 for no panels. Returns FACET_OK, or FACET_EWORK when out
 * of memory (*side is then 0). */
int panels_typical_side(const struct panelization *p, double *side,
                        struct facet_error *err);

/* The side (m) of a full panel of an nu x nv grid over a surface of area
 * (m^2) whose UV covers fill (0 to 1) of its UV box: what a run's finest
 * grid gives before it is evaluated. */
double grid_panel_side(double area, double fill, int nu, int nv);

/* Writes into warning (size bytes) one line saying that facets of
 * facet_size are comparable to or larger than panels of panel_side, for the
 * grid named by grid ("20 x 35", "the finest grid 40 x 50"), when
 * facet_size >= COARSE_MESH_RATIO x panel_side. Returns 1 when it wrote the
 * warning, 0 (warning untouched) otherwise. */
int coarse_mesh_warning(double facet_size, double panel_side,
                        const char *grid, char *warning, size_t size);

#endif
