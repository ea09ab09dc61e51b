/*
 * param_chart.h: the charts of a UV map.
 *
 * A chart is a connected piece of the surface over which the UV is
 * continuous: triangles joined across edges whose two ends have the same
 * (u, v) on both sides (to 1e-9 of the UV box). A texture atlas (a closed
 * model cut at seams and laid out in pieces) has several; a NURBS face's
 * parameters have one. A panel of a grid over the UV box must never hold
 * pieces of two charts, which lie side by side in UV but apart on the
 * surface.
 */
#ifndef FACET_PARAM_CHART_H
#define FACET_PARAM_CHART_H

#include <stddef.h>

#include "core/base/error.h"
#include "core/surface/mesh.h"

struct uv_chart {
    size_t triangles;
    double umin, vmin, umax, vmax;   /* its UV box */
};

/* Finds the charts of the per-corner UV map uv (#T x 3 x 2) over mesh:
 * their number into *count and the largest (most triangles first) into
 * chart[0 .. min(max, *count)). Returns FACET_OK, or FACET_EWORK when out
 * of memory (*count is then 0). */
int param_charts(const struct mesh *mesh, const double *uv,
                 struct uv_chart *chart, size_t max, size_t *count,
                 struct facet_error *err);

#endif
