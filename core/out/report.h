/*
 * report.h: writing an evaluated option as JSON or as a CSV panel schedule.
 *
 * The JSON is the format of `facet classify --json` (keys in docs/manual.md);
 * the CSV has one row per panel and a header row, for a spreadsheet. Units:
 * lengths m, areas m^2, curvatures 1/m (K 1/m^2), money USD.
 */
#ifndef FACET_REPORT_H
#define FACET_REPORT_H

#include <stdio.h>

#include "core/classify/classify.h"
#include "core/panel/panel.h"

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

/* Writes the panel schedule, the one layout of `facet classify --csv` and
 * `facet export --csv`: a header row, then one row per panel: id (its row
 * number from 1), i, j, class, type, area_m2, deviation_m, k1, k2 (1/m),
 * K (1/m^2), H, eps (1/m), p_dist_m4, diameter_m, trimmed (0/1),
 * corner_planarity_m, price_usd_m2, cost_usd, and the four cell corners
 * on the surface c0_x_m ... c3_z_m (empty where off it, as
 * corner_planarity_m is unless all four are on it), mould_family (the
 * panel's mould, mould.h; empty for an FP panel, which needs none),
 * built_type (FP, SP or DP as built: DP for an SP misfit), sp_deviation_m
 * (from its fitted cylinder or cone; empty unless classed SP),
 * worst_gap_mm and worst_kink_deg (the largest at its joints, joint.h),
 * misfit_reason (quoted; empty unless a misfit), corner_distance_m and
 * corner_moved_m (a planarized option's, panel.h; empty for a classified
 * option's). One unit per column,
 * named in its header; every number reads back exactly. */
void report_csv(FILE *out, const struct panelization *panels);

/* The schedule in two parts, for a building's: the header row, with a
 * surface column after id when with_surface; then panels' rows, numbered
 * from first_id, each naming surface (CSV-quoted where it must be) when
 * it is not NULL. A building's schedule is one header and every
 * surface's rows in turn, ids running on across the surfaces so that
 * each is unique in the building. */
void report_csv_header(FILE *out, int with_surface);
void report_csv_rows(FILE *out, const struct panelization *panels,
                     const char *surface, size_t first_id);

/* The seams schedule of a building's option, `facet export --csv`'s
 * NAME-seams.csv: a header row, then one row per seam joint (a pair of
 * panels of two surfaces meeting along a seam, project_seams.h's
 * project_seams_joints, seam by seam): seam (its number from 1),
 * surface_a, panel_a, surface_b, panel_b (the panels' ids in the
 * building's schedule: first_id[i] is surface i's first, names[i] its
 * name), gap_mm, kink_deg (the panels' own angle), crease_deg (the
 * design's own angle between the surfaces there) and added_kink_deg (what
 * the panels add to it: what --max-kink holds at a seam), each the
 * largest over the joint's samples. */
struct building_seam_joint;
void report_seams_csv(FILE *out, const struct building_seam_joint *joints,
                      size_t n, const char *const *names,
                      const size_t *first_id);

/* Writes the option's totals as a CSV of its own (a header row and one
 * row: panels, counts, areas and costs per type, cost, planarity, largest
 * deviation, largest panel, P_dist, feasible, then the joint length, the
 * mould families, the cost term by term, the gaps (mm) and kinks
 * (degrees) and the SP misfits and fitted panels, the columns in that
 * order first; then every other quantity of the totals in the quantity
 * table's order: per-class counts and areas, the smallest panel and
 * slivers, a planarized option's closeness, a building's seams (seams ..
 * seam_kinks_over, m and rad)), each column named as quantity_csv_name
 * names it, in the unit it is stored in, empty where not known (NULL: a
 * single surface's seams), the numbers `facet show` prints, so that a
 * schedule holds panels only. */
void report_totals_csv(FILE *out, const struct option_totals *totals);

#endif
