/*
 * report.h: writing an evaluated option as JSON or as a CSV panel schedule.
 *
 * The JSON is the format of `facet classify --json` (keys in README.md);
 * the CSV has one row per panel and a header row, for a spreadsheet. Units:
 * lengths m, areas m^2, curvatures 1/m (K 1/m^2), money USD.
 */
#ifndef FACET_REPORT_H
#define FACET_REPORT_H

#include <stdio.h>

#include "classify.h"
#include "panel.h"

/* What the option was computed from. */
struct report_source {
    const char *file;          /* the surface's path */
    const char *units;         /* as given: m, cm, mm, in, ft */
    double area;               /* mesh area (m^2) */
    size_t triangles;
    const char *uv_method;     /* "vt", "plane" or "harmonic" */
    const char *per_panel;     /* "extremes" or "mean" */
};

/* Writes one JSON object: surface, grid, threshold_mm, curvature_tol,
 * prices, panels, totals. */
void report_json(FILE *out, const struct report_source *source,
                 const struct classify_options *options,
                 const struct panelization *panels,
                 const struct option_totals *totals);

/* Writes the panel schedule: a header row, then one row per panel. */
void report_csv(FILE *out, const struct panelization *panels);

#endif
