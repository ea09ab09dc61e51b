/*
 * export_obj.h: an evaluated option as Wavefront OBJ + MTL, for CAD.
 *
 * Every panel is its own group, `g panel_I_J`, with `usemtl FP`, `SP` or
 * `DP`:
 *   - an FP panel is what is cut from flat stock: one planar polygon, its
 *     outline projected onto its best-fit plane (panel_geometry.h). A
 *     trimmed FP panel whose outline is not one loop (two lobes in one
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
 * smaller by the cosine of the angle between surface and plane, which for
 * a panel within the flatness threshold is a few parts in 10^5.
 */
#ifndef FACET_EXPORT_OBJ_H
#define FACET_EXPORT_OBJ_H

#include <stddef.h>
#include <stdio.h>

#include "error.h"
#include "panel.h"
#include "panel_geometry.h"

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
