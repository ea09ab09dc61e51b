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
    const char *uv_method;     /* "vt", "grid", "plane" or "harmonic" */
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

/* Writes the panel schedule a cost plan takes: a header row; one row per
 * panel (id = its row number from 1, i, j, type, class, area m^2,
 * deviation mm, k1, k2 1/m, K 1/m^2, H 1/m, unit price USD/m^2, cost USD,
 * the four cell corners on the surface, m, empty where off it); then a
 * totals row (id "total", class "N panels", the area, the largest
 * deviation among the FP and SP panels, the cost) with the numbers of
 * totals, which `facet show` prints. */
void report_schedule_csv(FILE *out, const struct panelization *panels,
                         const struct option_totals *totals);

#endif
