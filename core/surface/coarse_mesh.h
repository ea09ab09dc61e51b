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
 *
 * The other way a mesh falls short of its design is facets that sag: a
 * facet's chord lies off the surface its vertices sample by about
 * s^2 k / 8 (s the facet's side, k the surface's curvature along it).
 * When that is a fair part of the flatness threshold t, what is measured
 * on the facets (the fit of a single-curved panel, sp_fit.h) measures the
 * mesh's folds as much as the panel's shape (a strip of 4.1 mm sag on a
 * cylinder of R = 7.567 m: every panel a misfit, "best cylinder 3.8 mm",
 * at t = 3 mm). Facet then warns, and measures those fits against the
 * smooth surface through the vertices instead (cell_sides.h).
 */
#ifndef FACET_COARSE_MESH_H
#define FACET_COARSE_MESH_H

#include <stddef.h>

#include "core/base/error.h"
#include "core/surface/curvature.h"
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

/* The facets sag more than this fraction of t: warned, and single-curved
 * panels measured against the smooth surface. A quarter: a deviation
 * measured on the facets is then off by up to a quarter of t, about what
 * separates a panel that fits from one that does not in a design (and
 * four times the sag of a fine mesh at the usual 3 mm: 0.2 mm). */
#define FACET_SAG_FRACTION 0.25

/* 1 when facets sagging sag (m) are more than FACET_SAG_FRACTION of
 * threshold t (m): warned, and SP panels measured on the smooth surface. */
int facet_sag_matters(double sag, double threshold);

/* How far the facets of mesh sag from the surface its vertices sample (m):
 * each edge's chord sag, length^2 |k_n| / 8 with k_n the normal curvature
 * along the edge (curvature's shape operator, the larger at its two ends),
 * a triangle's the largest of its edges', and the mesh's the median of
 * its triangles' (the typical facet, as mesh_facet_size), into *sag; 0
 * for a mesh without triangles. The paper's roof at 224 x 224 quads: 0.23
 * mm (under a quarter of t = 1 mm; its 90th percentile is 0.87 mm, in
 * its tight valley); the strip above 4.1 mm; compas_hypar 22 mm. Returns FACET_OK, or FACET_EWORK when out
 * of memory (*sag is then 0). */
int mesh_facet_sag(const struct mesh *mesh, const struct curvature *curvature,
                   double *sag, struct facet_error *err);

/* Writes into warning (size bytes) one line saying that facets sagging
 * sag (m) are a fair part of threshold t (m), named by what ("t = 3 mm",
 * "the smallest threshold of the space, t = 1 mm"), when
 * facet_sag_matters. Returns 1 when it wrote the warning, 0 (warning
 * untouched) otherwise. */
int facet_sag_warning(double sag, double threshold, const char *what,
                      char *warning, size_t size);

#endif
