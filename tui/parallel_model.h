/*
 * parallel_model.h: the arithmetic of the parallel coordinates view,
 * without curses: its axes (the design variables and the metrics), a
 * value's place on an axis, brushes (a [lo, hi] range per axis) and their
 * text in the --where language, which is how a brush becomes the filter
 * the table and the scatter share, the reverse (a filter read back into
 * brushes), and a canvas of braille dots that polylines are drawn on.
 */
#ifndef FACET_TUI_PARALLEL_MODEL_H
#define FACET_TUI_PARALLEL_MODEL_H

#include <stddef.h>

#include "core/base/error.h"

/* One vertical axis: a column of the registry (core/quantity/quantity.h),
 * titled with its heading and unit; a column held as an integer (the grid
 * sides) is brushed in whole numbers. */
struct pc_axis {
    const char *column;   /* option_quantities name */
};

/* U, V, threshold, planarity, DP area, cost, FP area, SP area. */
#define PC_AXES 8
extern const struct pc_axis pc_axes[PC_AXES];

/* Steps an edge crosses an axis's range in. */
#define PC_STEPS 20

struct pc_brush {
    int active;          /* the axis filters */
    double lo, hi;       /* lo <= hi */
    int lo_open, hi_open;  /* the edge itself excluded: a filter's strict
                              "cost < 2M" read back; an edge moved or
                              typed includes itself */
};

/* The axes' ranges, their brushes and what else the filter says. */
struct pc_state {
    double min[PC_AXES], max[PC_AXES];  /* NaN when no option has one */
    struct pc_brush brush[PC_AXES];
    char base[1024];     /* the filter's other conjuncts, "" for none */
    int project;         /* a project run's options: its module (metres)
                            where U and V stand (pc_axis_column) */
};

/* The column axis shows: pc_axes[axis]'s, or a project's module in place
 * of nu and nv, which only index its module range. */
const char *pc_axis_column(const struct pc_state *st, int axis);

/* The dot row (0 at the top, dots - 1 at the bottom) of value on an axis
 * from min (bottom) to max (top); -1 for a value that is not finite. A
 * range without extent puts every value in the middle; values outside
 * the range are clamped. */
int pc_axis_dot(double value, double min, double max, int dots);

/* The step an edge of axis moves by: 1/PC_STEPS of its range (at least 1
 * on an integer axis; 1 when the range has no extent). */
double pc_step(const struct pc_state *st, int axis);

/* Moves the low (edge 0) or high (edge 1) edge of axis's brush by steps
 * steps (negative: down), starting from the full range when the axis has
 * no brush; edges stay in [min, max] and lo <= hi; an edge is rounded
 * outward to a short decimal. A brush that covers the whole range
 * becomes inactive. */
void pc_brush_move(struct pc_state *st, int axis, int edge, int steps);

/* Sets axis's brush to [lo, hi] (swapped when backwards); clears it when
 * it covers the whole range. */
void pc_brush_set(struct pc_state *st, int axis, double lo, double hi);

/* Reads "LO:HI", "LO..HI" or "LO HI" (numbers with an optional k or M
 * suffix; either side may be empty for the axis's end) into *lo, *hi.
 * Returns FACET_OK, or FACET_EINPUT for text that is none of these ("range:
 * 'TEXT' is not LO:HI" with examples). */
int pc_parse_range(const char *text, double min, double max, double *lo,
                   double *hi, struct facet_error *err);

/* The filter that base and the brushes make, in the --where language:
 * "cost >= 1100000 and cost <= 1200000" (an edge at its axis's end is
 * left out), into out (size bytes); "" when nothing filters. Returns
 * FACET_OK, or FACET_EINPUT ("the filter is too long") when it does not
 * fit in size. */
int pc_filter_text(const struct pc_state *st, char *out, size_t size,
                   struct facet_error *err);

/* Reads filter (filter_text's canonical form, "" for none) back into the
 * brushes and base: every top-level "COLUMN >= N" or "COLUMN <= N" on an
 * axis becomes a brush edge, the rest base. Needs min and max set. */
void pc_from_filter(struct pc_state *st, const char *filter);

/* A canvas of width x height character cells, each 2 x 4 braille dots.
 * Every cell keeps the dots of the highest level drawn on it (a higher
 * level replaces a lower one, so the lines drawn later at a higher level
 * are on top) and the slope of the last segment at that level (for
 * ASCII terminals). */
struct pc_canvas {
    int width, height;
    unsigned char *dots;    /* braille bits (U+2800 + bits) per cell */
    unsigned char *level;   /* 0 = empty */
    unsigned char *slope;   /* '-', '/', '\\' or '|' */
};

/* Allocates a clear canvas. Returns FACET_OK, FACET_EINPUT for a side
 * below 1 cell, FACET_EWORK when out of memory. Release with
 * pc_canvas_free, also after a failure. */
int pc_canvas_init(struct pc_canvas *c, int width, int height,
                   struct facet_error *err);
void pc_canvas_free(struct pc_canvas *c);

/* Draws a line between dots (x0, y0) and (x1, y1) (x in 0..2 width - 1,
 * y in 0..4 height - 1; dots outside are skipped) at level (1..255). */
void pc_canvas_line(struct pc_canvas *c, int x0, int y0, int x1, int y1,
                    int level);

/* The UTF-8 braille character of bits (3 bytes and a NUL). */
void pc_braille(unsigned bits, char out[4]);

#endif
