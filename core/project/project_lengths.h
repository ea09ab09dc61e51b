/*
 * project_lengths.h: how long a surface is along its u and along its v.
 *
 * A surface's u length Lu is the mean length of its iso-lines v = const
 * (the curves along which u runs), over the v range of its UV:
 *
 *   Lu = (1 / (vmax - vmin)) * integral over the UV domain of |dS/du|,
 *
 * and Lv likewise with u and v swapped. On a rectangular UV domain that is
 * exactly the mean length of the iso-lines; on a trimmed one, the lines
 * are cut by the trim. It does not depend on how the UV is scaled (vt in
 * [0,1] or in metres give the same lengths): a module w metres wide fits
 * about Lu / w times along u (module.h).
 *
 * On a triangle mesh with per-corner UV, dS/du is constant on each
 * triangle: with edges e1, e2 (m) and their UV differences d1, d2,
 * |dS/du| times the triangle's UV area is |e1 d2v - e2 d1v| / 2. A
 * triangle with no extent in UV adds nothing.
 */
#ifndef FACET_PROJECT_LENGTHS_H
#define FACET_PROJECT_LENGTHS_H

#include "core/surface/mesh.h"

/* Lu and Lv (m) of mesh with per-corner UV uv (#T x 3 x 2) into *lu and
 * *lv; both 0 when the UV has no extent along u or along v. */
void surface_uv_lengths(const struct mesh *mesh, const double *uv,
                        double *lu, double *lv);

#endif
