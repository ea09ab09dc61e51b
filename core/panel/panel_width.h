/*
 * panel_width.h: how narrow each panel is, the measure of a sliver.
 *
 * A panel's width is the least distance between two parallel lines that
 * hold its outline between them, measured in its best-fit plane: its
 * outline as panel_geometry.h projects it there (the shape a flat panel is
 * cut to; for a trimmed panel the part inside the surface's outline),
 * the narrowest caliper opening of its convex hull. For a rectangle a x b
 * it is min(a, b); for a parallelogram its lesser height; for a triangle
 * its least altitude. A panel with a notch is as wide as its hull: the
 * width says how narrow a blank the panel is cut from can be, not how
 * thin a part of it is. docs/method.md: "Slivers".
 *
 * Units: m. No allocation kept; no I/O.
 */
#ifndef FACET_PANEL_WIDTH_H
#define FACET_PANEL_WIDTH_H

#include <stddef.h>

#include "core/base/error.h"
#include "core/base/stop.h"
#include "core/panel/panel.h"
#include "core/panel/panel_geometry.h"

/* The least width of the convex hull of the n points xy (n x 2, m):
 * the smallest, over the hull's edges, of the largest distance of a hull
 * point from the edge's line. 0 for fewer than three points or points on
 * one line. scratch holds 2 n + 2 doubles x 2 (caller-owned); xy is
 * reordered. */
double polygon_min_width(double *xy, size_t n, double *scratch);

/* Sets the width (m) of every panel of panels from geometry, which
 * panel_geometry_build made over them: panel->width. Returns FACET_OK,
 * FACET_EWORK when out of memory. */
int panel_widths_set(const struct panel_geometry *geometry,
                     struct panelization *panels, struct facet_error *err);

/* panel_widths_set, asking stop (core/base/stop.h; NULL: never) every few
 * thousand panels: FACET_ESTOP when it fires, the widths then partly set. */
int panel_widths_set_stoppable(const struct panel_geometry *geometry,
                               struct panelization *panels,
                               const struct facet_stop *stop,
                               struct facet_error *err);

#endif
