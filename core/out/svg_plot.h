/*
 * svg_plot.h: a scatter plot of a run's design options, as SVG.
 *
 * The paper's Figure 13 by default: planarity (m) across, cost (USD) up,
 * bubble size by DP area (m^2). Each option is one <circle class="option">
 * (class "option pareto" for rank 1, drawn solid; others pale) with data-
 * attributes and a <title> tooltip; nothing else in the picture is a
 * <circle>, so counting them counts options. Per series (a run, with its
 * own colour and label), the Pareto front (its rank 1 options sorted by x)
 * is one <polyline class="front">, and the knee option is marked by a
 * <path class="knee">.
 *
 * Axes have "nice" ticks (steps of 1, 2 or 5 x 10^k) and labels with
 * units; their ranges are padded so that every point, and every bubble
 * but the very largest at an extreme, lies inside. The <g class="axes">
 * element carries data-x-min, data-x-max, data-y-min, data-y-max (full
 * precision) for scripts and tests.
 *
 * The plot borrows every array it is given; nothing is kept after a call.
 */
#ifndef FACET_SVG_PLOT_H
#define FACET_SVG_PLOT_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "core/base/error.h"

struct svg_plot_series {
    const char *label;    /* legend text (a run's name), or NULL */
    const char *colour;   /* "#rrggbb", or NULL for the next default */
    size_t n;             /* options */
    const double *x;      /* n values across, in x_unit */
    const double *y;      /* n values up, in y_unit */
    const double *size;   /* n bubble values >= 0 in size_unit (bubble
                             area grows with them), or NULL: equal dots */
    const int *rank;      /* n Pareto ranks (1 = on the front), or NULL:
                             no front drawn, nothing highlighted */
    size_t knee;          /* index of the knee option, or SIZE_MAX */
};

struct svg_plot {
    const char *title;                   /* or NULL for "Design options" */
    const char *x_name, *x_unit;         /* "planarity", "m" */
    const char *y_name, *y_unit;         /* "cost", "USD" */
    const char *size_name, *size_unit;   /* "DP area", "m^2" */
    const struct svg_plot_series *series;
    size_t nseries;
    double width, height;                /* page (px) */
};

/* An axis: its range and ticks. */
struct svg_axis {
    double min, max;   /* the range, multiples of step */
    double step;       /* tick spacing: 1, 2 or 5 x 10^k */
    int decimals;      /* digits after the point tick labels need */
};

/* Figure 13's axes (planarity m, cost USD, DP area m^2), no series,
 * 800 x 560 px. */
void svg_plot_defaults(struct svg_plot *plot);

/* The nice axis over values in [lo, hi]: the range is first widened by
 * pad (a fraction of hi - lo, or of |lo|, or 1, when they are equal) on
 * each side, then rounded out to a step of 1, 2 or 5 x 10^k giving about
 * ticks intervals. So min < lo and hi < max whenever pad > 0, except that
 * values none of which is negative get min 0 at the least (no negative
 * planarity or cost on a page). lo and hi must be finite. */
void svg_plot_axis(double lo, double hi, double pad, int ticks,
                   struct svg_axis *axis);

/* Writes the plot to out. Returns FACET_OK, or FACET_EINPUT, before
 * writing anything, for a series without x or y, a non-finite value, a
 * negative size, a knee past n, or a colour that is not "#rrggbb" (the
 * message names the series and the option). */
int svg_plot_write(FILE *out, const struct svg_plot *plot,
                   struct facet_error *err);

/* svg_plot_write to path through path.partial and rename. Returns as
 * svg_plot_write, and FACET_EINPUT when path exists and force is 0 or it
 * cannot be created (message naming path), FACET_EWORK when writing
 * fails. */
int svg_plot_save(const char *path, int force, const struct svg_plot *plot,
                  struct facet_error *err);

#endif
