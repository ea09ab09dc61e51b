/*
 * svg_map.h: the panel map of an evaluated option, as an SVG picture.
 *
 * Panels are drawn in UV (the default: u to the right, v up, the grid's
 * UV box framed) or projected in 3D: top = XY seen from above (+z), front
 * = XZ seen from -y, side = YZ seen from +x. A panel is its patch outline
 * (panel_geometry.h; several loops and holes drawn even-odd) or its
 * clipped triangles filled; in 3D, panels are painted far to near by
 * their centroids, so the near side of a vault hides the far one.
 *
 * Panels are coloured by type (FP, SP, DP) or by class (the paper's eight
 * classes), colours from svg.h's palette. A title block gives the grid,
 * the cost (USD) and the DP area (m^2); a legend the count and area (m^2)
 * of every type or class.
 *
 * The worst joints are drawn over the panels as thick magenta lines, one
 * <line class="worst-joint"> each with data-i, data-j (a panel it
 * bounds), data-side (panel.h's worst_gap_side) and data-gap-mm: of
 * every panel's worst joint (panel->worst_gap_side, the one joint per
 * panel the store keeps), the worst_joints largest gaps and those above
 * max_gap_mm, each joint once; the legend says which.
 *
 * Every panel is exactly one <path> element, with class="panel TYPE" and
 * data-i, data-j, data-type and data-class attributes (and a <title>
 * tooltip), so that scripts and tests can find and count them; nothing
 * else in the picture has data-i.
 */
#ifndef FACET_SVG_MAP_H
#define FACET_SVG_MAP_H

#include <stdio.h>

#include "core/classify/classify.h"
#include "core/base/error.h"
#include "core/panel/panel.h"
#include "core/panel/panel_geometry.h"

enum svg_map_view { SVG_MAP_UV, SVG_MAP_TOP, SVG_MAP_FRONT, SVG_MAP_SIDE };

enum svg_map_colouring { SVG_MAP_BY_TYPE, SVG_MAP_BY_CLASS };

struct svg_map_options {
    enum svg_map_view view;
    enum svg_map_colouring colour_by;
    int triangles;        /* fill each panel's triangles, not its outline */
    const char *title;    /* first line of the title block (the surface's
                             name, say), or NULL for "Facet panel map" */
    double size;          /* the drawing's longer side (px) */
    int worst_joints;     /* draw the joints of the N largest gaps, thick
                             (0: none) */
    double max_gap_mm;    /* and every panel's worst joint over this gap
                             limit (mm; 0 for none) */
};

/* UV view, by type, outlines, no title, 720 px, the 10 worst joints. */
void svg_map_defaults(struct svg_map_options *options);

/* "uv", "top", "front" or "side" into *out. Returns FACET_OK or
 * FACET_EINPUT naming the text and the valid names. */
int svg_map_view_parse(const char *text, enum svg_map_view *out,
                       struct facet_error *err);

/* "type" or "class" into *out. Returns FACET_OK or FACET_EINPUT. */
int svg_map_colouring_parse(const char *text, enum svg_map_colouring *out,
                            struct facet_error *err);

/* Writes the map of panels (classified: types and classes set), whose
 * geometry is g and totals are totals, to out. Errors are left on the
 * stream. */
void svg_map_write(FILE *out, const struct panel_geometry *g,
                   const struct panelization *panels,
                   const struct option_totals *totals,
                   const struct svg_map_options *options);

/* svg_map_write to path through path.partial and rename. Returns FACET_OK,
 * FACET_EINPUT when path exists and force is 0 or it cannot be created
 * (message naming path), FACET_EWORK when writing fails. */
int svg_map_save(const char *path, int force, const struct panel_geometry *g,
                 const struct panelization *panels,
                 const struct option_totals *totals,
                 const struct svg_map_options *options,
                 struct facet_error *err);

#endif
