/*
 * svg.h: the little SVG writing the exported pictures share.
 *
 * A document with a viewBox in pixels, numbers at a fixed precision with
 * trailing zeros dropped (so files are small and diff well), text escaped
 * for XML (markup characters as entities; control characters and invalid
 * UTF-8, which XML cannot hold, as '?'), a few shapes, and the colours the
 * pictures and the OBJ materials give panel types and classes.
 *
 * Attribute strings passed to the shape functions (attributes) are written
 * as they are: callers pass constant markup such as `class="axis"`, never
 * user text. Text content goes through svg_text or svg_escape.
 *
 * Nothing here allocates; errors are left on the stream for the caller's
 * ferror / outfile_commit.
 */
#ifndef FACET_SVG_H
#define FACET_SVG_H

#include <stddef.h>
#include <stdio.h>

#include "core/panel/panel.h"

struct svg {
    FILE *out;
    int precision;   /* digits after the decimal point for numbers */
};

/* Starts a document of width x height pixels (viewBox 0 0 width height)
 * on out, numbers with precision digits (0..9) after the point. */
void svg_begin(struct svg *svg, FILE *out, double width, double height,
               int precision);

/* Ends the document (and a trailing newline). */
void svg_end(struct svg *svg);

/* Writes x into text (size bytes) with precision digits after the point,
 * trailing zeros and a trailing point dropped, "-0" written as "0", and a
 * non-finite x as "0" (SVG has no NaN). */
void svg_format_number(char *text, size_t size, double x, int precision);


/* Writes x as svg_format_number does at the document's precision. */
void svg_number(struct svg *svg, double x);

/* Writes ` name="x"` (number at the document's precision). */
void svg_attribute(struct svg *svg, const char *name, double x);

/* Writes text escaped for XML content or attribute values. */
void svg_escape(FILE *out, const char *text);

/* <text x y attributes>printf-formatted text, escaped</text>. */
void svg_text(struct svg *svg, double x, double y, const char *attributes,
              const char *format, ...) __attribute__((format(printf, 5, 6)));

/* <rect x y width height attributes/>. */
void svg_rect(struct svg *svg, double x, double y, double width,
              double height, const char *attributes);

/* <line x1 y1 x2 y2 attributes/>. */
void svg_line(struct svg *svg, double x1, double y1, double x2, double y2,
              const char *attributes);

/* Writes "x,y" (as in points= and path data). */
void svg_point(struct svg *svg, double x, double y);

/* "#rrggbb" of a panel type (FP blue, SP yellow, DP vermillion) and of a
 * class (eight distinct colours: flat in FP's blue, ruled convex in SP's
 * yellow, convex round in DP's vermillion), from Okabe and Ito's palette,
 * which colour-blind readers tell apart. */
const char *svg_type_colour(enum panel_type type);
const char *svg_class_colour(enum panel_class class);

#endif
