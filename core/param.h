/*
 * param.h: the UV parameterization panels follow.
 *
 * In order of preference (DESIGN.md):
 *   1. the file's vt, what a CAD export of a NURBS face carries; refused when
 *      it folds (flipped or overlapping UV triangles);
 *   2. without vt, projection onto the surface's least-squares plane, when
 *      that projection folds no triangle;
 *   3. otherwise a harmonic (mean-value) parameterization of a disk-like
 *      patch: the boundary goes to a rectangle when it has four clear
 *      corners, to a circle otherwise, and the inside follows Floater's
 *      mean-value weights, which never fold for a convex boundary;
 *   4. otherwise an error that says how to export with texture coordinates.
 */
#ifndef FACET_PARAM_H
#define FACET_PARAM_H

#include "error.h"
#include "mesh.h"
#include "uv_index.h"

enum param_method { PARAM_VT, PARAM_PLANE, PARAM_HARMONIC };

struct parameterization {
    enum param_method method;
    double *uv;                /* #T x 3 x 2 per-corner (u, v), owned */
    struct uv_report report;   /* what uv_check found in uv */
};

/* Chooses and computes the parameterization of mesh. name is the surface's
 * file name, for messages. Returns FACET_OK, FACET_EINPUT when the UV folds
 * or the surface cannot be parameterized (with what to do), FACET_EWORK when
 * out of memory. Release *out with param_free, also after a failure. */
int param_choose(const struct mesh *mesh, const char *name,
                 struct parameterization *out, struct facet_error *err);

/* "vt", "plane" or "harmonic". */
const char *param_method_name(enum param_method method);

void param_free(struct parameterization *param);

#endif
