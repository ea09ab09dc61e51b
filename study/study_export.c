/*
 * study_export.c: options and runs out as files. See study_export.h.
 */
#include "study_export.h"

#include <assert.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <time.h>

#include "core/surface/coarse_mesh.h"
#include "core/base/units.h"
#include "core/out/dxf_patterns.h"
#include "core/out/export_obj.h"
#include "core/out/option_csv.h"
#include "core/out/outfile.h"
#include "core/panel/panel_geometry.h"
#include "core/project/project_seams.h"
#include "core/out/report.h"
#include "core/out/svg_plot.h"
#include "core/out/ifc_model.h"
#include "core/out/xlsx_schedule.h"
#include "core/fit/sp_fit.h"
#include "core/fit/unroll.h"
#include "core/joint/cell_sides.h"
#include "study.h"
#include "study_internal.h"

/* Opens every wanted file as FILE.partial; on failure none is left. */
static int open_all(const char *const target[EXPORT_FILES], int force,
                    struct outfile file[EXPORT_FILES],
                    int open[EXPORT_FILES], struct facet_error *err)
{
    int rc = FACET_OK;
    for (int k = 0; k < EXPORT_FILES; k++)
        if (target[k] && (rc = outfile_check(target[k], force, err)))
            return rc;
    for (int k = 0; k < EXPORT_FILES && rc == FACET_OK; k++)
        if (target[k]) {
            rc = outfile_open(&file[k], target[k], force, err);
            open[k] = rc == FACET_OK;
        }
    if (rc != FACET_OK)
        for (int k = 0; k < EXPORT_FILES; k++)
            if (open[k]) {
                outfile_abort(&file[k]);
                open[k] = 0;
            }
    return rc;
}

int study_option_load(struct store *store, int64_t run, int64_t number,
                      int geometry, struct study_option *p,
                      struct facet_error *err)
{
    memset(p, 0, sizeof *p);
    struct optimize_settings settings;
    struct mesh_options mesh;
    int flip;
    int rc = store_run_get(store, run, &p->run, err);
    if (rc == FACET_OK)
        rc = store_option_get(store, run, number, &p->row, err);
    if (rc == FACET_OK)
        rc = study_settings(&p->run, &settings, &mesh, &flip, err);
    if (rc != FACET_OK)
        return rc;
    p->classify = option_params_at(&settings.base, p->row.nu, p->row.nv,
                                   p->row.threshold_mm).classify;
    if (store_run_is_project(&p->run) && !geometry) {
        size_t nrows = 0;
        p->totals = p->row.totals;
        rc = store_surfaces_get(store, run, &p->surfaces, &p->nsurfaces, err);
        if (rc == FACET_OK)
            rc = store_option_surfaces_get(store, run, number,
                                           &p->surface_rows, &nrows, err);
        if (rc == FACET_OK && nrows != p->nsurfaces)
            rc = facet_error_set(err, FACET_EINPUT,
                "run %lld option %lld: %zu surface rows for %zu surfaces",
                (long long)run, (long long)number, nrows, p->nsurfaces);
        return rc;
    }
    if (geometry) {
        rc = study_open_surface(store, &p->run, &p->surface, err);
        p->have_surface = 1;
    }
    if (rc == FACET_OK)
        rc = study_option_panels(store, &p->run,
                                 p->have_surface ? &p->surface : NULL,
                                 number, &p->panels, &p->totals, err);
    if (rc == FACET_OK && geometry) {
        rc = panel_geometry_build(&p->surface.mesh, &p->surface.uv,
                                  &p->panels, &p->geometry, err);
        p->have_geometry = rc == FACET_OK;
    }
    return rc;
}

int study_option_building(struct store *store, struct study_option *p,
                          const struct study_project_view *view,
                          const struct project_option *building,
                          const struct study_hooks *hooks,
                          struct facet_error *err)
{
    assert(store_run_is_project(&p->run) && p->view == NULL);
    assert(building == NULL || view != NULL);
    int rc = FACET_OK;
    if (view == NULL) {
        rc = study_project_view_open(store, &p->run, hooks, &p->own_view,
                                     err);
        p->have_view = 1;
        view = &p->own_view;
    }
    p->view = view;
    if (rc == FACET_OK && building == NULL) {
        rc = study_project_view_option(store, view, p->row.number,
                                       &p->own_building, err);
        p->have_building = 1;
        building = &p->own_building;
    }
    p->building = building;
    if (rc != FACET_OK)
        return rc;
    const struct project_option *b = p->building;
    if (b->nsurfaces != p->nsurfaces)
        return facet_error_set(err, FACET_EINPUT,
            "run %lld option %lld: its building has %zu surfaces, the run "
            "recorded %zu", (long long)p->run.id, (long long)p->row.number,
            b->nsurfaces, p->nsurfaces);
    for (size_t s = 0; s < b->nsurfaces; s++)
        if (b->surfaces[s].panels.npanels != p->surface_rows[s].totals.panels)
            return facet_error_set(err, FACET_EINPUT,
                "run %lld option %lld: surface %s evaluates to %zu panels, "
                "the run stored %zu: its files or Facet have changed since",
                (long long)p->run.id, (long long)p->row.number,
                p->surfaces[s].name, b->surfaces[s].panels.npanels,
                p->surface_rows[s].totals.panels);
    if (b->totals.panels != p->row.totals.panels)
        return facet_error_set(err, FACET_EINPUT,
            "run %lld option %lld: its building evaluates to %zu panels, "
            "the run stored %zu", (long long)p->run.id,
            (long long)p->row.number, b->totals.panels,
            p->row.totals.panels);
    return FACET_OK;
}

void study_option_free(struct study_option *p)
{
    if (p->have_building)
        project_option_free(&p->own_building);
    if (p->have_view)
        study_project_view_close(&p->own_view);
    if (p->have_geometry)
        panel_geometry_free(&p->geometry);
    for (size_t s = 0; s < p->building_geometry_built; s++)
        panel_geometry_free(&p->building_geometry[s]);
    free(p->building_geometry);
    panelization_free(&p->panels);
    if (p->have_surface)
        surface_close(&p->surface);
    free(p->surfaces);
    free(p->surface_rows);
    memset(p, 0, sizeof *p);
}

void study_option_source(const struct study_option *p,
                         struct report_source *out)
{
    const struct run_info *r = &p->run;
    *out = (struct report_source){
        r->surface_path, store_run_setting_text(r, RUN_SETTING_UNITS),
        r->surface_area, (size_t)r->triangles,
        store_run_setting_text(r, RUN_SETTING_UV_METHOD),
        store_run_setting_text(r, RUN_SETTING_PER_PANEL)};
}

/* The base name of path, less ".obj": a single surface's name. */
static void surface_name(const char *path, char *out, size_t size)
{
    const char *slash = strrchr(path, '/');
    const char *base = slash ? slash + 1 : path;
    size_t n = strlen(base);
    if (n > size - 1)
        n = size - 1;
    memcpy(out, base, n);
    out[n] = '\0';
    if (n > 4 && strcasecmp(out + n - 4, ".obj") == 0)
        out[n - 4] = '\0';
}

/* Surface s of the option p as the files show it: a building's surface s,
 * or a single surface (s = 0) named after its file. name points into p
 * or into single (size bytes, the caller's); the rest is borrowed from p. */
struct export_surface {
    const char *name;
    const struct panelization *panels;
    const struct option_totals *totals;
    size_t moulds_used;            /* a building's surface's; 0 alone */
    const struct surface *surface; /* the mesh it was evaluated on; NULL
                                      for a single surface opened without
                                      geometry */
};

static struct export_surface export_surface(const struct study_option *p,
                                            size_t s, char *single,
                                            size_t size)
{
    if (p->building != NULL) {
        assert(s < p->building->nsurfaces);
        return (struct export_surface){
            p->surfaces[s].name, &p->building->surfaces[s].panels,
            &p->building->surfaces[s].totals,
            p->building->surfaces[s].moulds_used,
            &p->view->project.surfaces[s].surface};
    }
    assert(s == 0);
    surface_name(p->run.surface_path, single, size);
    return (struct export_surface){single, &p->panels, &p->totals, 0,
                                   p->have_surface ? &p->surface : NULL};
}

/* The surfaces the option p's files show: a building's, or 1. */
static size_t export_surfaces(const struct study_option *p)
{
    return p->building != NULL ? p->building->nsurfaces : 1;
}

/* The number every file gives surface s's first panel: a building's
 * panels are numbered from 1 on across its surfaces in the run's order,
 * so that the schedules, the seams and the drawings name a panel alike. */
static size_t first_panel_id(const struct study_option *p, size_t s)
{
    size_t id = 1;
    for (size_t k = 0; k < s; k++)
        id += p->building->surfaces[k].panels.npanels;
    return id;
}

/* Each panel's fitted cylinder or cone, the one exporters share: into
 * fit (npanels). A panel built SP on a fit the evaluation kept
 * (panel.h's sp_fit) is built on that one; only when some panel built SP
 * has none (a run that typed SP panels by class, a store older than
 * schema v13) are the fits made again over surface as the evaluation
 * makes them (cell sides, then built_option_fit at the panels'
 * threshold), kept for those panels where the panel is built SP on it.
 * Every other panel gets fitted 0 and NaN numbers: no number that
 * belongs to another build. surface may be NULL when no fit is made
 * again. */
static int sp_fits(const struct surface *surface,
                   const struct panelization *panels, double threshold,
                   struct built_panel *fit, struct facet_error *err)
{
    static const struct built_panel none = {
        .type = TYPE_FP, .fitted = 0, .misfit = 0,
        .fit = {DEVELOPABLE_CYLINDER, {NAN, NAN, NAN}, {NAN, NAN, NAN}, NAN,
                NAN},
        .sp_deviation = NAN, .best_cylinder = NAN, .best_cone = NAN,
        .bending_radius = NAN};
    for (size_t k = 0; k < panels->npanels; k++)
        fit[k] = none;
    size_t unfitted = 0;
    for (size_t k = 0; k < panels->npanels; k++) {
        const struct panel *p = &panels->panels[k];
        if (p->type == TYPE_SP && p->built == TYPE_SP &&
            built_panel_of_fit(&p->sp_fit, p->sp_deviation, &fit[k]) != 0)
            unfitted++;
    }
    if (unfitted == 0)
        return FACET_OK;
    if (surface == NULL)
        return facet_error_set(err, FACET_EINPUT,
                               "%zu SP panels have no fit stored, and the "
                               "surface is not open to fit them", unfitted);
    struct cell_sides sides;
    struct built_option built;
    memset(&built, 0, sizeof built);
    int rc = cell_sides_sample(&surface->mesh, &surface->uv,
                               &surface->curvature, panels, &sides, err);
    if (rc == FACET_OK)
        rc = built_option_fit(&surface->mesh, &surface->fit, panels, &sides,
                              threshold,
                              facet_sag_matters(surface->facet_sag,
                                                threshold),
                              &built, err);
    for (size_t k = 0; rc == FACET_OK && k < panels->npanels; k++) {
        const struct built_panel *b = &built.panels[k];
        if (b->fitted && b->type == TYPE_SP &&
            panels->panels[k].built == TYPE_SP && !fit[k].fitted)
            fit[k] = *b;
    }
    built_option_free(&built);
    cell_sides_free(&sides);
    return rc;
}

/* Releases what option_fits made (n: its surfaces); fit may be NULL. */
static void free_fits(struct built_panel **fit, size_t n)
{
    for (size_t s = 0; fit && s < n; s++)
        free(fit[s]);
    free(fit);
}

/* Every surface's fits (sp_fits) of p, a single surface's or a
 * building's: into *out, one array per surface (release with free_fits;
 * NULL after a failure). */
static int option_fits(const struct study_option *p,
                       struct built_panel ***out, struct facet_error *err)
{
    size_t n = export_surfaces(p);
    struct built_panel **fit = calloc(n, sizeof *fit);
    int rc = fit ? FACET_OK
        : facet_error_set(err, FACET_EWORK, "out of memory");
    for (size_t s = 0; rc == FACET_OK && s < n; s++) {
        char single[256];
        struct export_surface e = export_surface(p, s, single, sizeof single);
        fit[s] = malloc((e.panels->npanels ? e.panels->npanels : 1) *
                        sizeof *fit[s]);
        if (fit[s] == NULL)
            rc = facet_error_set(err, FACET_EWORK, "out of memory");
        else
            rc = sp_fits(e.surface, e.panels, p->classify.threshold, fit[s],
                         err);
    }
    if (rc != FACET_OK) {
        free_fits(fit, n);
        fit = NULL;
    }
    *out = fit;
    return rc;
}

/* The run's start as a time: the workbook's date, so that an option
 * exported twice is the same file. */
static time_t run_started(const struct run_info *run)
{
    struct tm t;
    memset(&t, 0, sizeof t);
    if (sscanf(run->started, "%d-%d-%dT%d:%d:%d", &t.tm_year, &t.tm_mon,
               &t.tm_mday, &t.tm_hour, &t.tm_min, &t.tm_sec) != 6)
        return 0;
    t.tm_year -= 1900;
    t.tm_mon -= 1;
    return timegm(&t);
}

/* The seam joints of building option p (project_option_seam_joints). */
static int option_seam_joints(const struct study_option *p,
                              struct building_seam_joint **joints, size_t *n,
                              struct facet_error *err)
{
    return project_option_seam_joints(&p->view->project, p->building,
                                      joints, n, err);
}

/* The option p as a workbook (xlsx_schedule.h) into out, its SP
 * panels' fits fit (option_fits). */
static int write_xlsx(FILE *out, const struct study_option *p,
                      struct built_panel *const *fit,
                      struct facet_error *err)
{
    int building = p->building != NULL;
    size_t n = export_surfaces(p);
    struct xlsx_surface *surfaces = calloc(n, sizeof *surfaces);
    char single[256];
    if (surfaces == NULL)
        return facet_error_set(err, FACET_EWORK, "out of memory");
    for (size_t s = 0; s < n; s++) {
        struct export_surface e = export_surface(p, s, single, sizeof single);
        surfaces[s] = (struct xlsx_surface){e.name, e.panels, fit[s],
                                            e.totals, e.moulds_used};
    }
    char title[128];
    snprintf(title, sizeof title, "Facet panel schedule: run %lld, "
             "option %lld", (long long)p->run.id, (long long)p->row.number);
    struct xlsx_schedule x = {
        title, run_started(&p->run), building, n, surfaces,
        building ? &p->building->totals : &p->totals, &p->classify, NULL, 0};
    /* A building whose run found its seams gets its seams sheet, empty
     * when no panels meet along them. */
    static const struct building_seam_joint no_joints[1];
    struct building_seam_joint *joints = NULL;
    int rc = FACET_OK;
    if (building && p->view->project.seams != NULL) {
        rc = option_seam_joints(p, &joints, &x.nseam_joints, err);
        x.seam_joints = joints != NULL ? joints : no_joints;
    }
    if (rc == FACET_OK)
        rc = xlsx_schedule_write(out, &x, err);
    free(joints);
    free(surfaces);
    return rc;
}

/* Builds every surface's panel patches of p's building (a single
 * surface's are p->geometry), once for every file that draws them. */
static int building_geometry(struct study_option *p, struct facet_error *err)
{
    assert(p->building != NULL && p->building_geometry == NULL);
    size_t n = p->building->nsurfaces;
    p->building_geometry = calloc(n ? n : 1, sizeof *p->building_geometry);
    if (p->building_geometry == NULL)
        return facet_error_set(err, FACET_EWORK, "out of memory");
    int rc = FACET_OK;
    for (size_t s = 0; rc == FACET_OK && s < n; s++) {
        const struct surface *surface = &p->view->project.surfaces[s].surface;
        rc = panel_geometry_build(&surface->mesh, &surface->uv,
                                  &p->building->surfaces[s].panels,
                                  &p->building_geometry[s], err);
        p->building_geometry_built = s + 1;  /* freed also after a failure */
    }
    return rc;
}

/* The panel patches of surface s of p (0 for a single surface). */
static const struct panel_geometry *geometry_of(const struct study_option *p,
                                                size_t s)
{
    if (p->building == NULL) {
        assert(s == 0 && p->have_geometry);
        return &p->geometry;
    }
    assert(s < p->building_geometry_built);
    return &p->building_geometry[s];
}

/* The option p's flat patterns (unroll.h) as DXF (dxf_patterns.h) into
 * out, its SP panels developed on their fits fit (option_fits), on
 * sheets of width x height (m). A building's surfaces each get their
 * panels' geometry built here; a single surface's is p's. */
static int write_dxf(FILE *out, const struct study_option *p,
                     struct built_panel *const *fit, double width,
                     double height, int grows, struct facet_error *err)
{
    size_t n = export_surfaces(p);
    struct flat_patterns *patterns = calloc(n, sizeof *patterns);
    struct dxf_surface *surfaces = calloc(n, sizeof *surfaces);
    char single[256];
    int rc = patterns && surfaces ? FACET_OK
        : facet_error_set(err, FACET_EWORK, "out of memory");
    size_t laid = 0;
    for (size_t s = 0; rc == FACET_OK && s < n; s++) {
        struct export_surface e = export_surface(p, s, single, sizeof single);
        const struct panel_geometry *g = geometry_of(p, s);
        rc = flat_patterns_build(g, e.panels, fit[s], &patterns[s], err);
        laid = s + 1;
        surfaces[s] = (struct dxf_surface){e.name, e.panels, g, &patterns[s],
                                           first_panel_id(p, s)};
    }
    if (rc == FACET_OK) {
        struct dxf_patterns x = {n, surfaces, width, height, grows};
        rc = dxf_patterns_write(out, &x, err);
    }
    for (size_t s = 0; s < laid; s++)
        flat_patterns_free(&patterns[s]);
    free(patterns);
    free(surfaces);
    return rc;
}

/* The option p as an IFC4 model (ifc_model.h) into out. */
static int write_ifc(FILE *out, const struct study_option *p,
                     struct facet_error *err)
{
    size_t n = export_surfaces(p);
    struct ifc_surface *surfaces = calloc(n, sizeof *surfaces);
    char single[256];
    int rc = surfaces ? FACET_OK
        : facet_error_set(err, FACET_EWORK, "out of memory");
    for (size_t s = 0; rc == FACET_OK && s < n; s++) {
        struct export_surface e = export_surface(p, s, single, sizeof single);
        surfaces[s] = (struct ifc_surface){e.name, e.panels, geometry_of(p, s)};
    }
    if (rc == FACET_OK) {
        char title[128], key[256];
        snprintf(title, sizeof title, "Facet run %lld, option %lld",
                 (long long)p->run.id, (long long)p->row.number);
        /* The run's start and surface with its number: two stores' run 1
         * are not one model's objects. */
        snprintf(key, sizeof key, "facet run %lld started %s surface %s "
                 "option %lld", (long long)p->run.id, p->run.started,
                 p->run.surface_sha256, (long long)p->row.number);
        struct ifc_model m = {title, key, run_started(&p->run),
                              "Facet " FACET_VERSION, n, surfaces};
        rc = ifc_model_write(out, &m, err);
    }
    free(surfaces);
    return rc;
}

/* A building's schedule: one header, then every surface's panels in
 * the run's order, ids running on across them; its totals the
 * building's. */
static void write_building_csv(const struct study_option *p, FILE *csv,
                               FILE *totals)
{
    const struct project_option *b = p->building;
    report_csv_header(csv, 1);
    for (size_t s = 0; s < b->nsurfaces; s++)
        report_csv_rows(csv, &b->surfaces[s].panels, p->surfaces[s].name,
                        first_panel_id(p, s));
    if (totals != NULL)
        report_totals_csv(totals, &b->totals);
}

/* A building's seams schedule (report_seams_csv): every seam joint of
 * its option, the panels numbered as in its panel schedule. */
static int write_seams_csv(const struct study_option *p, FILE *out,
                           struct facet_error *err)
{
    size_t n = p->building->nsurfaces;
    const char **names = malloc((n ? n : 1) * sizeof *names);
    size_t *first = malloc((n ? n : 1) * sizeof *first);
    int rc = FACET_OK;
    if (names == NULL || first == NULL)
        rc = facet_error_set(err, FACET_EWORK, "out of memory");
    for (size_t s = 0; rc == FACET_OK && s < n; s++) {
        names[s] = p->surfaces[s].name;
        first[s] = first_panel_id(p, s);
    }
    struct building_seam_joint *joints = NULL;
    size_t njoints = 0;
    if (rc == FACET_OK)
        rc = option_seam_joints(p, &joints, &njoints, err);
    if (rc == FACET_OK)
        report_seams_csv(out, joints, njoints, names, first);
    free(joints);
    free(first);
    free(names);
    return rc;
}

/* Tells hooks the export's next stage; FACET_ESTOP when a stop is asked
 * for. */
static int export_stage(const struct study_hooks *hooks, const char *what,
                        struct facet_error *err)
{
    study_stage(hooks, what);
    struct facet_stop stop = study_stop(hooks);
    return facet_stop_check(&stop, err);
}

int study_export(struct store *store, int64_t run, int64_t number,
                 struct export_request *r, struct facet_error *err)
{
    memset(r->written, 0, sizeof r->written);
    r->refused_building = 0;
    if (!r->obj && !r->csv && !r->json && !r->svg && !r->xlsx && !r->dxf &&
        !r->ifc)
        return facet_error_set(err, FACET_EINPUT,
            "export: say what to write: OBJ, CSV, XLSX, JSON, SVG, DXF "
            "and/or IFC");
    double sheet_width = r->sheet_width ? r->sheet_width : DXF_SHEET_WIDTH;
    double sheet_height = r->sheet_height ? r->sheet_height
                                          : DXF_SHEET_HEIGHT;
    if (r->dxf && !(sheet_width >= DXF_SHEET_MIN &&
                    sheet_width <= DXF_SHEET_MAX &&
                    sheet_height >= DXF_SHEET_MIN &&
                    sheet_height <= DXF_SHEET_MAX))
        return facet_error_set(err, FACET_EINPUT,
            "export: a sheet of %g x %g mm: each side must be %g to %g mm",
            units_mm(sheet_width), units_mm(sheet_height),
            units_mm(DXF_SHEET_MIN), units_mm(DXF_SHEET_MAX));
    char mtl[4096] = "", totals[4096] = "", seams[4096] = "";
    int rc;
    if (r->obj && outfile_is_stream(r->obj))
        return facet_error_set(err, FACET_EINPUT,
            "export: %s: an OBJ needs its MTL beside it; give a file",
            r->obj);
    if (r->obj && (rc = export_obj_mtl_path(r->obj, mtl, sizeof mtl, err)))
        return rc;
    /* A schedule piped out goes alone: its totals have no place beside a
     * stream. */
    int totals_file = r->csv && !outfile_is_stream(r->csv);
    if (totals_file && (rc = outfile_sibling(r->csv, ".csv", "-totals.csv",
                                             totals, sizeof totals, err)))
        return rc;
    int to_stdout = (r->csv && strcmp(r->csv, "-") == 0) +
                    (r->xlsx && strcmp(r->xlsx, "-") == 0) +
                    (r->json && strcmp(r->json, "-") == 0) +
                    (r->svg && strcmp(r->svg, "-") == 0) +
                    (r->dxf && strcmp(r->dxf, "-") == 0) +
                    (r->ifc && strcmp(r->ifc, "-") == 0);
    if (to_stdout > 1)
        return facet_error_set(err, FACET_EINPUT,
            "export: one file at most to standard output (-)");
    /* A building's option: its schedule, every surface's panels in one,
     * its totals and, when its run found its seams, the seams schedule;
     * the other formats are refused before any file is made rather than
     * written empty. */
    struct run_info info;
    if ((rc = store_run_get(store, run, &info, err)))
        return rc;
    int building = store_run_is_project(&info);
    int seams_file = building && totals_file && info.weld_mm > 0;
    if (seams_file && (rc = outfile_sibling(r->csv, ".csv", "-seams.csv",
                                            seams, sizeof seams, err)))
        return rc;
    const char *target[EXPORT_FILES] = {r->obj, r->obj ? mtl : NULL, r->csv,
                                        totals_file ? totals : NULL, r->json,
                                        r->svg, r->xlsx, r->dxf, r->ifc,
                                        seams_file ? seams : NULL};
    if (building && (r->obj || r->json || r->svg)) {
        r->refused_building = 1;
        return facet_error_set(err, FACET_EINPUT,
            "run %lld is a building of several surfaces: an OBJ, JSON or "
            "SVG of its option is not written yet, only its panel schedule "
            "(CSV, XLSX), flat patterns (DXF) and IFC model",
            (long long)run);
    }
    struct outfile file[EXPORT_FILES];
    int open[EXPORT_FILES] = {0};
    if ((rc = open_all(target, r->force, file, open, err)))
        return rc;

    struct study_option p;
    rc = study_option_load(store, run, number,
                           r->obj || r->svg ||
                               ((r->xlsx || r->dxf || r->ifc) &&
                                !building),
                           &p, err);
    if (rc == FACET_OK && building)
        rc = study_option_building(store, &p, r->view, r->building,
                                   r->hooks, err);
    if (rc == FACET_OK && building && r->csv)
        write_building_csv(&p, file[EXPORT_CSV].out,
                           totals_file ? file[EXPORT_TOTALS].out : NULL);
    if (rc == FACET_OK && seams_file)
        rc = write_seams_csv(&p, file[EXPORT_SEAMS].out, err);
    if (rc == FACET_OK && r->obj) {
        /* mtllib is relative to the OBJ: the MTL's own name. */
        const char *slash = strrchr(mtl, '/');
        export_obj_write(file[EXPORT_OBJ].out, slash ? slash + 1 : mtl,
                         &p.geometry, &p.panels);
        export_obj_write_mtl(file[EXPORT_MTL].out);
    }
    if (rc == FACET_OK && r->csv && !building) {
        report_csv(file[EXPORT_CSV].out, &p.panels);
        if (totals_file)
            report_totals_csv(file[EXPORT_TOTALS].out, &p.totals);
    }
    if (rc == FACET_OK && r->json) {
        struct report_source source;
        study_option_source(&p, &source);
        report_json(file[EXPORT_JSON].out, &source, &p.classify, &p.panels,
                    &p.totals);
    }
    if (rc == FACET_OK && r->svg) {
        char title[256];
        snprintf(title, sizeof title, "Run %lld, option %lld: %d x %d, "
                 "%g mm", (long long)run, (long long)number, p.row.nu,
                 p.row.nv, p.row.threshold_mm);
        struct svg_map_options map = r->map;
        map.title = title;
        /* The run's gap limit: every panel's worst joint over it drawn. */
        if (isfinite(p.run.max_gap_mm))
            map.max_gap_mm = p.run.max_gap_mm;
        svg_map_write(file[EXPORT_SVG].out, &p.geometry, &p.panels,
                      &p.totals, &map);
    }
    /* The SP fits, made once for every format that shows them. Each of
     * these takes seconds on a big building: each says so, and a stop
     * asked for between them leaves no file. */
    struct built_panel **fit = NULL;
    if (rc == FACET_OK && (r->xlsx || r->dxf) &&
        (rc = export_stage(r->hooks, "taking the SP panels' fits", err)) ==
            FACET_OK)
        rc = option_fits(&p, &fit, err);
    if (rc == FACET_OK && building && (r->dxf || r->ifc) &&
        (rc = export_stage(r->hooks, "building the panels' surface patches",
                           err)) ==
            FACET_OK)
        rc = building_geometry(&p, err);
    if (rc == FACET_OK && r->xlsx &&
        (rc = export_stage(r->hooks, "writing the XLSX schedule", err)) ==
            FACET_OK)
        rc = write_xlsx(file[EXPORT_XLSX].out, &p, fit, err);
    if (rc == FACET_OK && r->dxf &&
        (rc = export_stage(r->hooks, "laying out the flat patterns (DXF)",
                           err)) == FACET_OK)
        rc = write_dxf(file[EXPORT_DXF].out, &p, fit, sheet_width,
                       sheet_height, r->sheet_grows, err);
    if (rc == FACET_OK && r->ifc &&
        (rc = export_stage(r->hooks, "writing the IFC model", err)) ==
            FACET_OK)
        rc = write_ifc(file[EXPORT_IFC].out, &p, err);
    free_fits(fit, p.building != NULL ? p.building->nsurfaces : 1);
    /* The MTL before the OBJ: an OBJ never names a missing MTL. */
    static const int order[EXPORT_FILES] = {EXPORT_MTL, EXPORT_OBJ,
                                            EXPORT_CSV, EXPORT_TOTALS,
                                            EXPORT_JSON, EXPORT_SVG,
                                            EXPORT_XLSX, EXPORT_DXF,
                                            EXPORT_IFC, EXPORT_SEAMS};
    int n = 0;
    for (int k = 0; k < EXPORT_FILES; k++) {
        int f = order[k];
        if (!open[f])
            continue;
        if (rc == FACET_OK)
            rc = outfile_commit(&file[f], err);
        else
            outfile_abort(&file[f]);
        if (rc == FACET_OK)
            snprintf(r->written[n++], sizeof r->written[0], "%s",
                     target[f]);
    }
    study_option_free(&p);
    return rc;
}

const char *study_column_unit(const char *column)
{
    const struct quantity *c = quantity_named(column);
    return c != NULL ? c->stored_unit : "";
}

static int check_column(const char *what, const char *column,
                        struct facet_error *err)
{
    for (int k = 0; k < OPTION_QUANTITIES; k++)
        if (strcmp(option_quantities[k].name, column) == 0 &&
            strcmp(column, "run") != 0)
            return FACET_OK;
    return facet_error_set(err, FACET_EINPUT,
        "%s: '%s' is not an option column (e.g. cost, planarity, dp_area, "
        "fp_area, nu, threshold_mm)", what, column);
}

/* One run's points, owned. */
struct run_points {
    struct option_row *rows;
    size_t n;
    double *x, *y, *size;
    int *rank;
    char label[160];
};

static int load_points(struct store *store, int64_t run,
                       const struct plot_request *r, struct run_points *p,
                       struct svg_plot_series *series,
                       struct facet_error *err)
{
    struct run_info info;
    int rc = store_run_get(store, run, &info, err);
    struct option_query q = {run, r->pareto_only, r->where, NULL, 0, 0, 0, 0};
    if (rc == FACET_OK)
        rc = r->where || r->pareto_only
                 ? store_options_query_rows(store, &q, &p->rows, &p->n, err)
                 : store_options_get(store, run, &p->rows, &p->n, err);
    if (rc != FACET_OK)
        return rc;
    if (p->n == 0)
        return facet_error_set(err, FACET_EINPUT, "run %lld has no options "
                               "to plot%s", (long long)run,
                               r->where || r->pareto_only
                                   ? " (the filter passes none)" : "");
    p->x = malloc(p->n * sizeof *p->x);
    p->y = malloc(p->n * sizeof *p->y);
    p->size = malloc(p->n * sizeof *p->size);
    p->rank = malloc(p->n * sizeof *p->rank);
    if (!p->x || !p->y || !p->size || !p->rank)
        return facet_error_set(err, FACET_EWORK, "out of memory");
    size_t knee = SIZE_MAX;
    for (size_t k = 0; k < p->n; k++) {
        p->x[k] = option_quantity_value(&p->rows[k], r->x);
        p->y[k] = option_quantity_value(&p->rows[k], r->y);
        p->size[k] = r->size
            ? fmax(0, option_quantity_value(&p->rows[k], r->size)) : 0;
        p->rank[k] = p->rows[k].rank;
        if (p->rows[k].knee)
            knee = k;
    }
    /* The legend has three lines of about 22 characters for it. */
    if (info.name[0])
        snprintf(p->label, sizeof p->label, "run %lld %.48s%s",
                 (long long)run, info.name,
                 strlen(info.name) > 48 ? "..." : "");
    else
        snprintf(p->label, sizeof p->label, "run %lld (%s)", (long long)run,
                 store_run_setting_text(&info, RUN_SETTING_METHOD));
    *series = (struct svg_plot_series){p->label, NULL, p->n, p->x, p->y,
                                       r->size ? p->size : NULL, p->rank,
                                       knee};
    return FACET_OK;
}

int study_plot(struct store *store, const struct plot_request *r,
               const char *path, struct facet_error *err)
{
    int rc;
    if (r->nruns < 1 || r->nruns > PLOT_MAX_RUNS)
        return facet_error_set(err, FACET_EINPUT,
            "plot: 1 to %d runs in one plot", PLOT_MAX_RUNS);
    static const char *const plain[3] = {"x", "y", "size"};
    const char *const *name = r->axis_names ? r->axis_names : plain;
    if ((rc = check_column(name[0], r->x, err)) ||
        (rc = check_column(name[1], r->y, err)) ||
        (r->size && (rc = check_column(name[2], r->size, err))) ||
        (rc = outfile_check(path, r->force, err)))
        return rc;
    struct run_points points[PLOT_MAX_RUNS];
    struct svg_plot_series series[PLOT_MAX_RUNS];
    memset(points, 0, sizeof points);
    for (int k = 0; k < r->nruns && rc == FACET_OK; k++)
        rc = load_points(store, r->runs[k], r, &points[k], &series[k], err);
    if (rc == FACET_OK) {
        struct svg_plot plot;
        svg_plot_defaults(&plot);
        plot.title = r->title;
        plot.x_name = r->x;
        plot.x_unit = study_column_unit(r->x);
        plot.y_name = r->y;
        plot.y_unit = study_column_unit(r->y);
        plot.size_name = r->size;
        plot.size_unit = r->size ? study_column_unit(r->size) : NULL;
        plot.series = series;
        plot.nseries = (size_t)r->nruns;
        rc = svg_plot_save(path, r->force, &plot, err);
    }
    for (int k = 0; k < r->nruns; k++) {
        free(points[k].rows);
        free(points[k].x);
        free(points[k].y);
        free(points[k].size);
        free(points[k].rank);
    }
    return rc;
}

int study_export_options_csv(struct store *store, int64_t run,
                             const int64_t *numbers, size_t n,
                             const char *path, int force,
                             struct facet_error *err)
{
    struct option_row *rows = malloc((n ? n : 1) * sizeof *rows);
    if (rows == NULL)
        return facet_error_set(err, FACET_EWORK, "out of memory");
    int rc = FACET_OK;
    for (size_t k = 0; k < n && rc == FACET_OK; k++)
        rc = store_option_get(store, run, numbers[k], &rows[k], err);
    struct outfile f;
    if (rc == FACET_OK)
        rc = outfile_open(&f, path, force, err);
    if (rc != FACET_OK) {
        free(rows);
        return rc;
    }
    /* facet options --csv's layout: every quantity once */
    option_csv_header(f.out);
    for (size_t k = 0; k < n; k++)
        option_csv_row(f.out, run, &rows[k]);
    free(rows);
    return outfile_commit(&f, err);
}
