/*
 * dxf_patterns.h: an option's flat patterns (unroll.h) as a DXF drawing,
 * nested on sheets to cut from, with every panel's 3D outline beside.
 *
 * The file is DXF R12 ASCII (AC1009), in millimetres ($INSUNITS 4), read
 * by every CAD program. Layers:
 *   - FP, SP, DP: one closed POLYLINE per outline loop of each panel (one
 *     for an untrimmed panel) on the layer of its type as built, its
 *     pattern as unroll.h lays it flat, seen from the panel's outer face;
 *     a TEXT of its panel id (the schedule's id: 1.., unique across a
 *     building) at the centre of its pattern; a DP panel, not
 *     developable, its outline projected onto its best-fit plane, carries
 *     a second TEXT "DP: not developable" under its id;
 *   - SHEETS: each sheet's frame, sheet_width x sheet_height, the sheets
 *     side by side along x, sheet k at x = k (sheet_width + 200 mm), with
 *     a TEXT "sheet K" under it;
 *   - OUTLINE_3D_FP, OUTLINE_3D_SP, OUTLINE_3D_DP: each panel's outline
 *     in space (a closed 3D POLYLINE per loop), where the panel is.
 * Every polyline of a panel (its pattern's loops and its 3D outline's)
 * carries the panel as XDATA of the application FACET (registered in the
 * APPID table), name and value pairs: 1000 "PanelId", 1000 its id; then,
 * for a planarized option's moved panel (planar_option.h), 1000
 * "CornerDistance_mm", 1040 the largest distance of its corners from the
 * design surface, and 1000 "CornerMoved_mm", 1040 how far they moved
 * (panel_corner_distance, panel_corner_moved, in mm, the shortest text
 * that reads back as the stored double). A panel whose corners were not
 * moved (every classified option's) has neither pair: not measured,
 * never 0. A moved panel's 3D outline is its moved quad
 * (panel_geometry.h), its pattern that quad on its plane.
 * Nesting: each pattern's bounding box (turned a quarter when only so it
 * fits a sheet) is placed by a shelf packer, tallest first (ties by id),
 * 10 mm from the frame and 10 mm from each other, so no two patterns
 * overlap and every one is inside its frame. Nothing is mirrored.
 *
 * The same input gives the same bytes: no date, no handle, no clock.
 */
#ifndef FACET_DXF_PATTERNS_H
#define FACET_DXF_PATTERNS_H

#include <stdio.h>

#include "core/base/error.h"
#include "core/fit/unroll.h"
#include "core/panel/panel.h"
#include "core/panel/panel_geometry.h"

/* The application name of the panels' XDATA. */
#define DXF_APPLICATION "FACET"

/* The gap between a sheet's frame and its patterns, and between two
 * patterns (m). */
#define DXF_MARGIN 0.010

/* One surface of the option: a single surface's option has one. */
struct dxf_surface {
    const char *name;                      /* for messages */
    const struct panelization *panels;
    const struct panel_geometry *geometry; /* built from panels */
    const struct flat_patterns *patterns;  /* of geometry */
    size_t first_id;                       /* the id of its first panel */
};

struct dxf_patterns {
    size_t nsurfaces;
    const struct dxf_surface *surfaces;
    double sheet_width, sheet_height;      /* m, finite, > 2 DXF_MARGIN */
    int sheet_grows;                       /* 1: a sheet too small for the
                                              largest pattern grows, each
                                              side to hold it within the
                                              margins, in whole
                                              DXF_SHEET_STEPs (the frames
                                              drawn are the sheets used);
                                              0: such a pattern is
                                              refused */
};

/* The default sheet (m): 3000 x 1500 mm, a standard sheet of metal. */
#define DXF_SHEET_WIDTH 3.0
#define DXF_SHEET_HEIGHT 1.5
/* The sides a sheet may have (m). */
#define DXF_SHEET_MIN 0.050
#define DXF_SHEET_MAX 100.0
/* What a grown sheet's sides are whole multiples of (m). */
#define DXF_SHEET_STEP 0.100

/* Parses text, "WxH" in mm ("3000x1500"), the sheet size given for the
 * setting what (the caller's name for it), into *width, *height (m).
 * Returns FACET_OK, or FACET_EINPUT with a message that starts with what
 * and says what is wrong (not two numbers, one not finite, out of
 * DXF_SHEET_MIN..DXF_SHEET_MAX); the outputs are untouched on an error. */
int dxf_sheet_parse(const char *text, const char *what, double *width,
                    double *height, struct facet_error *err);

/* Writes x to out. Returns FACET_OK, or FACET_EINPUT before writing
 * anything when a pattern does not fit on a sheet either way round and
 * the sheet does not grow (naming its panel id, surface, cell and size in mm), FACET_EWORK when
 * out of memory. */
int dxf_patterns_write(FILE *out, const struct dxf_patterns *x,
                       struct facet_error *err);

#endif
