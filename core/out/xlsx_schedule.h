/*
 * xlsx_schedule.h: an option's panel schedule as an XLSX workbook, the
 * spreadsheet a facade contractor prices and orders from
 * (libxlsxwriter).
 *
 * Sheets, each with one header row (frozen) naming its unit, a column
 * width a person can read, and every number a number cell with a number
 * format (never text); a value not known (NaN) is an empty cell:
 *   - panels: one row per panel, in surface order then the panelization's
 *     (j then i): id (1.., unique in the building, as the CSV's), surface,
 *     column i, row j, type as classed, type as built, class, area (m^2),
 *     in-plane bounding size of its corners (m; empty for a trimmed
 *     panel, whose outline is not its corners), centroid (m), unit normal,
 *     the four cell corners (m), deviation (mm), a planarized option's
 *     corner distance and move (mm, panel.h), SP bending radius (m,
 *     where fitted), the fitted surface of a panel built SP (cylinder or
 *     cone; its axis point, the foot of the panel's centroid on the axis,
 *     m; its axis direction, unit, from the apex towards the panel for a
 *     cone, largest component positive for a cylinder; a cylinder's
 *     radius, m; a cone's apex, m, and half-angle, deg; the largest
 *     distance of the panel's samples from it, mm: sp_fit.h), empty for
 *     any other panel, worst gap (mm) and kink (deg), mould family (as the
 *     CSV's mould_family, 0-based; empty for none), price (USD/m^2), cost
 *     (USD);
 *   - moulds: one row per mould family, in family order: family, type
 *     (SP: a bending jig, DP: a mould), members, representative (the
 *     panel id of its first member), cost (USD, the run's mould cost of
 *     the type);
 *   - surfaces (a building's option only): one row per surface, its grid
 *     and its totals;
 *   - seams (a building's option whose run found its seams): one row per
 *     panel joint along a seam between two surfaces, as the seams CSV's
 *     (report.h): seam (1..), each side's surface and panel id, gap (mm),
 *     kink, the design's crease there and the kink the panels add to it
 *     (deg);
 *   - totals: one row per quantity of the option's totals
 *     (core/quantity/quantity.h: name, label, value as shown, unit), the
 *     numbers facet show prints.
 *
 * The workbook is made byte for byte from its input: its creation date is
 * the given one, never the clock, so the same option written twice is the
 * same file.
 *
 * libxlsxwriter writes to a named file, and a zip file is written with
 * seeks; so the workbook is written to a temporary file (in $TMPDIR, else
 * /tmp) which is then copied into out and removed. out may be a stream.
 */
#ifndef FACET_XLSX_SCHEDULE_H
#define FACET_XLSX_SCHEDULE_H

#include <stdio.h>
#include <time.h>

#include "core/base/error.h"
#include "core/classify/classify.h"
#include "core/fit/sp_fit.h"
#include "core/panel/panel.h"
#include "core/project/project_seams.h"

/* One surface of the option: a single surface's option has one. */
struct xlsx_surface {
    const char *name;                    /* the surface's name */
    const struct panelization *panels;   /* classified, evaluated */
    const struct built_panel *sp_fit;    /* npanels: each panel's fitted
                                            cylinder or cone where
                                            fitted, else fitted 0 (empty
                                            cells); NULL: none known */
    /* A building's surface (xlsx_schedule.building): */
    const struct option_totals *totals;  /* its totals (project_option.h) */
    size_t moulds_used;                  /* families its panels use */
};

struct xlsx_schedule {
    const char *title;                   /* "run 1, option 5": the
                                            workbook's title */
    time_t created;                      /* its creation date */
    int building;                        /* 1: a building's option (a
                                            surfaces sheet) */
    size_t nsurfaces;
    const struct xlsx_surface *surfaces; /* nsurfaces */
    const struct option_totals *totals;  /* the option's */
    const struct classify_options *classify;  /* its prices */
    /* A building's seam joints (project_seams_joints), whose a and b index
     * surfaces; NULL: no seams sheet (a single surface, a run that found
     * no seams). */
    const struct building_seam_joint *seam_joints;
    size_t nseam_joints;
};

/* Writes s as a workbook to out. Returns FACET_OK, FACET_EINPUT for more
 * panels than a sheet has rows (1,048,575 after the header), or
 * FACET_EWORK naming
 * what failed (the temporary file, libxlsxwriter's error, a short copy);
 * out then holds a part of the file and the caller discards it
 * (outfile_abort). */
int xlsx_schedule_write(FILE *out, const struct xlsx_schedule *s,
                        struct facet_error *err);

#endif
