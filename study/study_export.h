/*
 * study_export.h: a stored option or run out of Facet, as files: what
 * `facet export`, `facet plot` and the TUI's export keys all do.
 *
 * An option goes out as OBJ + MTL (core/out/export_obj.h), a CSV panel
 * schedule and JSON (core/out/report.h), an XLSX panel schedule
 * (core/out/xlsx_schedule.h: its workbook dated the run's start, so the
 * same option gives the same bytes) and an SVG panel map
 * (core/out/svg_map.h), the flat patterns as DXF (core/fit/unroll.h,
 * core/out/dxf_patterns.h), an IFC4 model (core/out/ifc_model.h: dated the
 * run's start, its GlobalIds derived from the option, so the same option
 * gives the same bytes too); a run as an SVG scatter (core/out/svg_plot.h). Every
 * file is opened (as FILE.partial) before any work and renamed into place
 * only when all of them are written, so an export that fails leaves no file
 * behind, new or old; an existing file is refused unless force is set.
 */
#ifndef FACET_STUDY_EXPORT_H
#define FACET_STUDY_EXPORT_H

#include "core/panel/panel_geometry.h"
#include "core/out/report.h"
#include "core/surface/surface.h"
#include "core/out/svg_map.h"
#include "store/store.h"
#include "study/study_project_view.h"

/* A stored option with what showing or exporting it needs. */
struct study_option {
    struct run_info run;
    struct option_row row;
    struct classify_options classify;  /* the run's, at the option's
                                          threshold */
    struct panelization panels;
    struct option_totals totals;
    /* With geometry only (the surface file is opened for it): */
    struct surface surface;
    struct panel_geometry geometry;
    int have_surface, have_geometry;
    /* A project run's option (store_run_is_project): no panels (not kept
     * yet; totals are the row's), its surfaces and their rows instead,
     * nsurfaces each (malloc'ed); NULL, 0 otherwise. */
    struct surface_row *surfaces;
    struct option_surface_row *surface_rows;
    size_t nsurfaces;
    /* A project run's option evaluated over its building
     * (study_option_building): the prepared building, and every surface's
     * panels, the building's totals and mould families; NULL before.
     * Borrowed when the caller had them (the workbench's map), else the
     * option's own (own_view, own_building, released by study_option_free
     * when have_view, have_building). */
    const struct study_project_view *view;
    const struct project_option *building;
    struct study_project_view own_view;
    struct project_option own_building;
    int have_view, have_building;
    /* The building's panels' surface patches, surface by surface, built
     * once for every file that draws them (malloc'ed, released by
     * study_option_free); NULL until then. */
    struct panel_geometry *building_geometry;
    size_t building_geometry_built;
};

/* Reads option number of run into *out (caller-owned, released with
 * study_option_free, also after a failure): its run, row and classify
 * settings, its panels (computed and stored first when not stored), and
 * with geometry set the panels' surface patches too. Of a project run,
 * its surfaces and their rows instead of panels; geometry is then
 * refused (FACET_EINPUT). */
int study_option_load(struct store *store, int64_t run, int64_t number,
                      int geometry, struct study_option *out,
                      struct facet_error *err);
void study_option_free(struct study_option *option);

/* Of a project run's option loaded by study_option_load: its building
 * and the option evaluated over it, into option->view and
 * option->building. view is the run's building already prepared
 * (borrowed: it must outlive option), or NULL to open it again
 * (study_project_view_open: its files, checked by SHA-256); building is
 * the option already evaluated over view (borrowed likewise; only with
 * view), or NULL to evaluate it with the run's settings and the option's
 * stored grids. Either way the building's panels must be as many as the
 * option's row says, surface by surface and in all, or FACET_EINPUT: a
 * schedule that does not add up to the option shown is never written.
 * hooks (may be NULL) hears the stage. */
int study_option_building(struct store *store, struct study_option *option,
                          const struct study_project_view *view,
                          const struct project_option *building,
                          const struct study_hooks *hooks,
                          struct facet_error *err);

/* What report_json writes about the option's surface. */
void study_option_source(const struct study_option *option,
                         struct report_source *out);

enum export_file { EXPORT_OBJ, EXPORT_MTL, EXPORT_CSV, EXPORT_TOTALS,
                   EXPORT_JSON, EXPORT_SVG, EXPORT_XLSX, EXPORT_DXF,
                   EXPORT_IFC, EXPORT_SEAMS,
                   EXPORT_FILES };

struct export_request {
    const char *obj, *csv, *json, *svg;   /* paths; NULL: not wanted */
    const char *xlsx;                     /* the schedule as a workbook
                                             (core/out/xlsx_schedule.h) */
    const char *dxf;                      /* the flat patterns, nested on
                                             sheets, and the 3D outlines
                                             (core/out/dxf_patterns.h) */
    double sheet_width, sheet_height;     /* the DXF's sheets (m); 0:
                                             DXF_SHEET_WIDTH x _HEIGHT */
    int sheet_grows;                      /* 1: sheets grow to hold the
                                             largest pattern (dxf_patterns.h)
                                             rather than refuse it */
    const char *ifc;                      /* the IFC4 model
                                             (core/out/ifc_model.h) */
    int force;                            /* overwrite existing files */
    /* A building's option already open (the workbench's map), borrowed;
     * NULL: study_export opens the building and evaluates the option
     * again (study_option_building). building only with view. */
    const struct study_project_view *view;
    const struct project_option *building;
    const struct study_hooks *hooks;      /* hears the stage of long
                                             work; NULL: nothing told */
    struct svg_map_options map;           /* view and colouring of the SVG */
    /* Set by study_export: 1 when it refused a format a building's option
     * is not written in (the refusal's caller may say where its numbers
     * are instead), else 0. */
    int refused_building;
    /* Set by study_export: the paths written, in the order written (the
     * MTL is obj's name with .mtl, the CSV's totals csv's name less .csv
     * with -totals.csv, a building's seams schedule with -seams.csv: a
     * run that found its seams, schema v15), "" for those not wanted. */
    char written[EXPORT_FILES][4096];
};

/* Writes the files request asks for of option number of run. Of a
 * building's option (a project run) the CSV and XLSX schedules, the DXF
 * of every surface's patterns and the IFC model, every surface's panels
 * (study_option_building), ids running on across them, the geometry built
 * surface by surface; the others are refused
 * (FACET_EINPUT) before any file is made. Panels not
 * stored yet are computed and stored first (study_option_panels); the OBJ
 * and the SVG need the surface file, which must be unchanged. Returns
 * FACET_OK, FACET_EINPUT (no such run or option, a file that exists, a
 * path that cannot be written, no file asked for, a sheet size out of
 * range, a pattern no sheet holds) or FACET_EWORK. */
int study_export(struct store *store, int64_t run, int64_t number,
                 struct export_request *request, struct facet_error *err);

/* What a scatter of runs shows: option columns (option_quantities) */
struct plot_request {
    const int64_t *runs;    /* the runs to overlay, one colour each */
    int nruns;              /* 1 to PLOT_MAX_RUNS */
    const char *x, *y;      /* columns across and up */
    const char *size;       /* bubble size column, or NULL for dots */
    const char *title;      /* or NULL */
    int force;
    const struct filter *where;  /* the options of each run to plot; NULL:
                                    every one */
    int pareto_only;        /* rank 1 only */
    const char *const *axis_names;  /* how the caller's user names x, y
                                       and size, for the message of an
                                       unknown column (the CLI's "--x");
                                       NULL: "x", "y", "size" */
};

#define PLOT_MAX_RUNS 8

/* Writes the scatter of the request's runs to path: one circle per
 * option, Pareto options highlighted and joined by the front, the knee
 * marked, axes with units. FACET_EINPUT for an unknown run or column, a
 * run without options, a path that exists or cannot be written. */
int study_plot(struct store *store, const struct plot_request *request,
               const char *path, struct facet_error *err);

/* Writes options numbers[0..n) of run to path as CSV, one row each in
 * the order given, with a header: run, then every option column of
 * option_quantities, the cost per type (fp_cost, sp_cost, dp_cost)
 * and the count and area per class (CLASS_count, CLASS_area), as the
 * options table holds them (crowding empty where infinite). A path that
 * exists is refused unless force. FACET_EINPUT for an unknown option. */
int study_export_options_csv(struct store *store, int64_t run,
                             const int64_t *numbers, size_t n,
                             const char *path, int force,
                             struct facet_error *err);

/* The unit an option column is stored and plotted in (the registry's
 * stored_unit: "USD", "m", "m^2", "mm", "" for counts and unknown names). */
const char *study_column_unit(const char *column);

#endif
