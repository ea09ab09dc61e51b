/*
 * export_obj.h: an evaluated option as Wavefront OBJ + MTL, for CAD.
 *
 * The panels of each type make one object, `o FP`, `o SP`, `o DP` (CAD
 * layers, Blender collections), and within it every panel is its own
 * group, `g panel_I_J`, with `usemtl FP`, `SP` or `DP`; an SP or DP panel
 * is also in the group of its mould family, `g panel_I_J mould_K` (K as
 * mould.h numbers them, 0-based), so that a mould's panels select together:
 *   - an FP panel is what is cut from flat stock, planar: a full cell is
 *     the quad of its four cell corners projected onto its best-fit plane;
 *     a trimmed cell is its outline projected onto that plane, without the
 *     points that lie on a straight edge between their neighbours (to
 *     1e-9 of its diameter), so a fan of it holds no zero-area triangle.
 *     A trimmed FP panel whose outline is not one loop (two lobes in one
 *     cell, or a hole) is written as its pieces projected onto that plane
 *     instead, still planar, since an OBJ face cannot hold a hole;
 *   - an SP or DP panel is its surface patch: the clipped triangles
 *     (convex polygons), vertices shared within the panel where they are
 *     the same point, never between panels, so each group stands alone.
 * Every vertex carries its vt, the surface's UV at that point (the file's
 * vt when it had them), so textures still map; `vn` is not written (faces
 * keep the surface's winding). Lengths are metres. `mtllib NAME.mtl`
 * names the MTL written beside the OBJ: materials FP, SP and DP with the
 * Kd colours of svg.h's palette.
 *
 * Note that an FP polygon's area is its projection's, not the surface's:
 * for an outline, smaller by the cosine of the angle between surface and
 * plane, which for a panel within the flatness threshold is a few parts
 * in 10^5; for a full cell's quad, that of straight edges between the
 * corners, within 1e-3 of the surface's either way.
 */
#ifndef FACET_EXPORT_OBJ_H
#define FACET_EXPORT_OBJ_H

#include <stddef.h>
#include <stdio.h>

#include "core/base/error.h"
#include "core/panel/panel.h"
#include "core/panel/panel_geometry.h"

/* Writes the OBJ text of panels (classified: types set) with geometry g
 * (built from the same panelization) to out, referencing mtl_name (a file
 * name, written as given) with mtllib. Errors are left on the stream. */
void export_obj_write(FILE *out, const char *mtl_name,
                      const struct panel_geometry *g,
                      const struct panelization *panels);

/* Writes the MTL text: materials FP, SP and DP. */
void export_obj_write_mtl(FILE *out);

/* The MTL path that goes with OBJ path: path less a final ".obj" (any
 * case), plus ".mtl", into mtl (size bytes). Returns FACET_OK or
 * FACET_EINPUT when it does not fit. */
int export_obj_mtl_path(const char *path, char *mtl, size_t size,
                        struct facet_error *err);

/* Writes path and its MTL (export_obj_mtl_path), each through
 * FILE.partial and rename, so a failure leaves neither half-written.
 * Refuses with FACET_EINPUT, before creating anything, when either exists
 * and force is 0 ("PATH exists (pass --force to overwrite it)"); FACET_EINPUT
 * when a file cannot be created ("cannot write PATH: reason"), FACET_EWORK
 * when writing fails. */
int export_obj_save(const char *path, int force,
                    const struct panel_geometry *g,
                    const struct panelization *panels,
                    struct facet_error *err);

#endif
