/*
 * cmd_export.c: `facet export DB --run N --option M`, a chosen option out
 * of Facet: OBJ + MTL for Rhino or Blender, a CSV panel schedule for the
 * cost plan, JSON, and an SVG panel map for the design review. Every file
 * is checked before any work (refused when it exists, unless --force) and
 * written through FILE.partial.
 */
#include <stdio.h>
#include <string.h>

#include "args.h"
#include "command.h"
#include "core/export_obj.h"
#include "core/outfile.h"
#include "core/report.h"
#include "core/svg_map.h"
#include "store/study.h"

struct export_paths {
    const char *obj, *csv, *json, *svg;
};

enum export_file { FILE_OBJ, FILE_MTL, FILE_CSV, FILE_JSON, FILE_SVG,
                   FILE_COUNT };

static int export_main(int argc, char **argv, struct facet_error *err)
{
    const char *run = NULL, *option = NULL, *view = NULL, *colour = NULL;
    struct export_paths out = {NULL, NULL, NULL, NULL};
    int force = 0, triangles = 0;
    const struct arg_option options[] = {
        {"run", 0, ARG_STRING, &run, NULL},
        {"option", 0, ARG_STRING, &option, NULL},
        {"obj", 0, ARG_STRING, &out.obj, NULL},
        {"csv", 0, ARG_STRING, &out.csv, NULL},
        {"json", 0, ARG_STRING, &out.json, NULL},
        {"svg", 0, ARG_STRING, &out.svg, NULL},
        {"view", 0, ARG_STRING, &view, NULL},
        {"colour", 0, ARG_STRING, &colour, NULL},
        {"color", 0, ARG_STRING, &colour, NULL},
        {"triangles", 0, ARG_FLAG, NULL, &triangles},
        {"force", 'f', ARG_FLAG, NULL, &force},
        {NULL, 0, ARG_FLAG, NULL, NULL},
    };
    const char *path[1];
    int count;
    int rc = args_parse(argc, argv, options, path, 1, &count, err);
    if (rc != FACET_OK)
        return rc;
    if (count != 1 || run == NULL || option == NULL)
        return facet_error_set(err, FACET_EINPUT,
            "export: give the database, the run and the option (facet "
            "export runs.db --run 1 --option 12 --obj knee.obj)");
    if (!out.obj && !out.csv && !out.json && !out.svg)
        return facet_error_set(err, FACET_EINPUT,
            "export: say what to write: --obj, --csv, --json and/or --svg");
    long run_id, number;
    if ((rc = args_int(run, 1, 1L << 62, "--run", &run_id, err)) ||
        (rc = args_int(option, 1, 1L << 62, "--option", &number, err)))
        return rc;
    struct svg_map_options map;
    svg_map_defaults(&map);
    if (view && (rc = svg_map_view_parse(view, &map.view, err)))
        return rc;
    if (colour && (rc = svg_map_colouring_parse(colour, &map.colour_by,
                                                 err)))
        return rc;
    map.triangles = triangles;
    /* Every file is opened (as FILE.partial) before any work and
     * renamed into place only when all are written, so that an export
     * that fails leaves no file behind, new or old. */
    char mtl[4096] = "";
    if (out.obj && (rc = export_obj_mtl_path(out.obj, mtl, sizeof mtl, err)))
        return rc;
    const char *target[FILE_COUNT] = {out.obj, out.obj ? mtl : NULL,
                                      out.csv, out.json, out.svg};
    for (int k = 0; k < FILE_COUNT; k++)
        if (target[k] && (rc = outfile_check(target[k], force, err)))
            return rc;
    struct outfile file[FILE_COUNT];
    int open[FILE_COUNT] = {0};
    for (int k = 0; k < FILE_COUNT && rc == FACET_OK; k++)
        if (target[k]) {
            rc = outfile_open(&file[k], target[k], force, err);
            open[k] = rc == FACET_OK;
        }
    if (rc != FACET_OK) {
        for (int k = 0; k < FILE_COUNT; k++)
            if (open[k])
                outfile_abort(&file[k]);
        return rc;
    }

    struct store *store;
    if ((rc = store_open(path[0], &store, err)) != FACET_OK)
        return rc;
    struct run_info info;
    struct option_row row;
    struct optimize_settings settings;
    struct mesh_options mesh;
    struct surface surface;
    struct panelization panels;
    struct option_totals totals;
    struct panel_geometry geometry;
    int flip, have_surface = 0, have_geometry = 0;
    memset(&panels, 0, sizeof panels);
    memset(&surface, 0, sizeof surface);
    rc = store_run_get(store, run_id, &info, err);
    if (rc == FACET_OK)
        rc = store_option_get(store, run_id, number, &row, err);
    if (rc == FACET_OK)
        rc = study_settings(&info, &settings, &mesh, &flip, err);
    /* The geometry of the panels needs the surface itself. */
    if (rc == FACET_OK && (out.obj || out.svg)) {
        rc = study_open_surface(&info, &surface, err);
        have_surface = 1;
    }
    if (rc == FACET_OK)
        rc = study_option_panels(store, &info, have_surface ? &surface
                                                            : NULL,
                                 number, &panels, &totals, err);
    if (rc == FACET_OK && (out.obj || out.svg)) {
        rc = panel_geometry_build(&surface.mesh, &surface.uv, &panels,
                                  &geometry, err);
        have_geometry = rc == FACET_OK;
    }
    struct classify_options classify = settings.base.classify;
    classify.threshold = row.threshold_mm / 1000;
    if (rc == FACET_OK && out.obj) {
        /* mtllib is relative to the OBJ: the MTL's own name. */
        const char *slash = strrchr(mtl, '/');
        export_obj_write(file[FILE_OBJ].out, slash ? slash + 1 : mtl,
                         &geometry, &panels);
        export_obj_write_mtl(file[FILE_MTL].out);
    }
    if (rc == FACET_OK && out.csv)
        report_schedule_csv(file[FILE_CSV].out, &panels, &totals);
    if (rc == FACET_OK && out.json) {
        struct report_source source = {info.surface_path, info.units,
                                       info.surface_area,
                                       (size_t)info.triangles,
                                       info.uv_method, info.per_panel};
        report_json(file[FILE_JSON].out, &source, &classify, &panels,
                    &totals);
    }
    if (rc == FACET_OK && out.svg) {
        char title[256];
        snprintf(title, sizeof title, "Run %lld, option %lld: %d x %d, "
                 "%g mm", (long long)run_id, (long long)number, row.nu,
                 row.nv, row.threshold_mm);
        map.title = title;
        svg_map_write(file[FILE_SVG].out, &geometry, &panels, &totals,
                      &map);
    }
    /* The MTL before the OBJ: an OBJ never names a missing MTL. */
    static const int order[FILE_COUNT] = {FILE_MTL, FILE_OBJ, FILE_CSV,
                                          FILE_JSON, FILE_SVG};
    for (int k = 0; k < FILE_COUNT; k++) {
        int f = order[k];
        if (!open[f])
            continue;
        if (rc == FACET_OK)
            rc = outfile_commit(&file[f], err);
        else
            outfile_abort(&file[f]);
        if (rc == FACET_OK)
            printf("wrote %s\n", target[f]);
    }
    if (have_geometry)
        panel_geometry_free(&geometry);
    panelization_free(&panels);
    if (have_surface)
        surface_close(&surface);
    store_close(store);
    return rc;
}

const struct command cmd_export = {
    .name = "export",
    .usage = "DB --run N --option M [--obj FILE.obj] [--csv FILE.csv]\n"
             "       [--json FILE.json] [--svg FILE.svg] [--view "
             "uv|top|front|side]\n"
             "       [--colour type|class] [--triangles] [--force]",
    .summary = "Export one option: OBJ + MTL, CSV panel schedule, JSON, "
               "SVG panel map.",
    .options =
        "  --run N, --option M the option (see facet options)\n"
        "  --obj FILE.obj      every panel a group panel_I_J: FP panels as\n"
        "                      planar polygons on their best-fit plane, SP\n"
        "                      and DP as the surface patch; FILE.mtl beside\n"
        "  --csv FILE.csv      the panel schedule with a totals row\n"
        "  --json FILE.json    the option as facet classify --json\n"
        "  --svg FILE.svg      the panel map with legend and title block\n"
        "  --view V            the map in uv (default), or projected: top,\n"
        "                      front, side\n"
        "  --colour C          panels coloured by type (default) or class\n"
        "  --triangles         draw each panel's triangles, not its outline\n"
        "  --force, -f         overwrite existing files\n",
    .run = export_main,
};
