/*
 * param.h: the UV parameterization panels follow.
 *
 * In order of preference:
 *   1. vt: the file's texture coordinates, what a CAD export of a NURBS
 *      face carries; refused when they fold (flipped or overlapping UV
 *      triangles) or form several charts (a texture atlas: a panel would
 *      hold pieces of two);
 *   2. grid: without vt, a structured quad grid's own (i, j)
 *      (param_grid.h), so an NU x NV grid of panels on an NU x NV quad
 *      mesh is one panel per quad;
 *   3. plane: the projection onto the surface's least-squares plane, when
 *      it folds no triangle and squashes none;
 *   4. harmonic: the mean-value map of a disk, holes capped
 *      (param_harmonic.h);
 *   5. otherwise an error that says how to export with texture coordinates.
 * Any one of them can be asked for instead; it is then refused, with what
 * stops it, when it cannot apply.
 */
#ifndef FACET_PARAM_H
#define FACET_PARAM_H

#include "core/base/error.h"
#include "core/base/stop.h"
#include "core/surface/mesh.h"
#include "core/surface/uv_index.h"

/* PARAM_AUTO (0, what a zeroed request asks for) takes the order above. */
enum param_method {
    PARAM_AUTO = 0, PARAM_VT, PARAM_GRID, PARAM_PLANE, PARAM_HARMONIC
};

struct parameterization {
    enum param_method method;  /* the one taken (never PARAM_AUTO) */
    double *uv;                /* #T x 3 x 2 per-corner (u, v), owned */
    struct uv_report report;   /* what uv_check found in uv */
    char reason[320];          /* why it was taken, for a designer: "30 x
                                  36 quads, structured", "the plane
                                  projection folds 12 triangles", ... */
    int grid_nu, grid_nv;      /* PARAM_GRID: quads along u and v */
    size_t holes;              /* PARAM_HARMONIC: holes capped */
};

/* Computes the parameterization of mesh: the one asked for, or with
 * PARAM_AUTO the first that applies in the order above. name is the
 * surface's file name, for messages. Returns FACET_OK, FACET_EINPUT when
 * the method asked for cannot apply or none can (the message says why and
 * what to do), FACET_EWORK when out of memory. Release *out with
 * param_free, also after a failure. */
int param_choose(const struct mesh *mesh, enum param_method want,
                 const char *name, struct parameterization *out,
                 struct facet_error *err);

/* param_choose, asking stop (stop.h) between its steps and at every
 * iteration of the harmonic solve: FACET_ESTOP when it fires. */
int param_choose_stoppable(const struct mesh *mesh, enum param_method want,
                           const char *name, const struct facet_stop *stop,
                           struct parameterization *out,
                           struct facet_error *err);

/* "auto", "vt", "grid", "plane" or "harmonic". */
const char *param_method_name(enum param_method method);

/* Parses a name param_method_name gives ("auto" included) into *out.
 * Returns 0, or -1 for an unknown name. */
int param_method_parse(const char *text, enum param_method *out);

void param_free(struct parameterization *param);

#endif
