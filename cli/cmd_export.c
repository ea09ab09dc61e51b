/*
 * cmd_export.c: `facet export DB --run N --option M`, a chosen option out
 * of Facet: OBJ + MTL for Rhino or Blender, a CSV panel schedule for the
 * cost plan, an IFC4 model for BIM, JSON, an SVG panel map for the
 * design review, and the flat patterns as DXF for the cutter. Every file
 * is checked before any work (refused when it exists, unless --force) and
 * written through FILE.partial.
 */
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "args.h"
#include "command.h"
#include "progress.h"
#include "shown.h"
#include "signals.h"
#include "study/study.h"
#include "study/study_export.h"
#include "core/out/dxf_patterns.h"

/* Whether path is standard output: "-", or the file stdout is open on
 * (/dev/stdout, a pipe's /proc/self/fd/1). */
static int is_stdout(const char *path)
{
    if (strcmp(path, "-") == 0)
        return 1;
    struct stat a, b;
    return stat(path, &a) == 0 && fstat(STDOUT_FILENO, &b) == 0 &&
           a.st_dev == b.st_dev && a.st_ino == b.st_ino;
}

/* study_export's refusal of a format a building's option is not written
 * in, with the command that shows its numbers surface by surface. */
static int building_refusal(const char *path, long run, long number,
                            struct facet_error *err)
{
    char said[sizeof err->message];
    snprintf(said, sizeof said, "%s", err->message);
    return facet_error_set(err, err->code,
                           "export: %s; its totals surface by surface: "
                           "facet show %s --run %ld --option %ld",
                           said, path, run, number);
}

/* The options as given (pointing into argv), NULL or 0 when absent; the
 * files to write go straight into the request. */
struct export_args {
    const char *run, *option, *view, *colour, *surface, *sheet;
    int triangles;
    struct export_request request;
};

static const struct arg_option export_options[] = {
    {"run", 0, ARG_STRING, offsetof(struct export_args, run), "N",
     "the run (see facet runs)", NULL},
    {"option", 0, ARG_STRING, offsetof(struct export_args, option), "M",
     "the option's number in the run (see facet options)", NULL},
    {"obj", 0, ARG_STRING, offsetof(struct export_args, request.obj),
     "FILE.obj", "every panel a group panel_I_J: FP panels as planar "
     "polygons on their best-fit plane, SP and DP as the surface patch; "
     "FILE.mtl beside", NULL},
    {"csv", 0, ARG_STRING, offsetof(struct export_args, request.csv),
     "FILE.csv", "the panel schedule, a row per panel; its totals in FILE-totals.csv beside it (and a building's seam joints, a row each, in FILE-seams.csv)", NULL},
    {"xlsx", 0, ARG_STRING, offsetof(struct export_args, request.xlsx),
     "FILE.xlsx", "the panel schedule as a workbook: sheets of panels, "
     "moulds, surfaces (a building) and totals", NULL},
    {"ifc", 0, ARG_STRING, offsetof(struct export_args, request.ifc),
     "FILE.ifc", "an IFC4 model: a curtain wall per surface, a plate per "
     "panel with its body and its schedule's values", NULL},
    {"json", 0, ARG_STRING, offsetof(struct export_args, request.json),
     "FILE.json", "the option as facet classify --json", NULL},
    {"svg", 0, ARG_STRING, offsetof(struct export_args, request.svg),
     "FILE.svg", "the panel map with legend and title block", NULL},
    {"dxf", 0, ARG_STRING, offsetof(struct export_args, request.dxf),
     "FILE.dxf", "the flat patterns to cut, in mm: FP in their plane, SP "
     "unrolled on their fitted cylinder or cone, DP projected (not "
     "developable), each labelled with its panel id and nested on sheets; "
     "the 3D outlines on their own layers", NULL},
    {"sheet", 0, ARG_STRING, offsetof(struct export_args, sheet), "WxH",
     "the DXF's sheet in mm (default 3000x1500)", NULL},
    {"view", 0, ARG_STRING, offsetof(struct export_args, view),
     "uv|top|front|side",
     "the map in uv (default), or projected: top, front, side", NULL},
    {"colour", 0, ARG_STRING, offsetof(struct export_args, colour),
     "type|class",
     "panels coloured by type (default) or class", NULL},
    {"color", 0, ARG_STRING, offsetof(struct export_args, colour),
     "type|class",
     NULL, NULL},
    {"triangles", 0, ARG_FLAG, offsetof(struct export_args, triangles), NULL,
     "draw each panel's triangles, not its outline", NULL},
    {"surface", 0, ARG_STRING, offsetof(struct export_args, surface), "FILE",
     "the run's surface has moved: record its new place (its SHA-256 must "
     "be the run's)", NULL},
    {"force", 'f', ARG_FLAG, offsetof(struct export_args, request.force),
     NULL, "overwrite existing files", NULL},
    {NULL, 0, ARG_FLAG, 0, NULL, NULL, NULL},
};

static int export_main(int argc, char **argv, struct facet_error *err)
{
    struct export_args a;
    memset(&a, 0, sizeof a);
    const struct arg_table own = {export_options, &a};
    const char *path;
    const char *missing =
        "export: give the database, the run and the option (facet "
        "export runs.db --run 1 --option 12 --obj knee.obj)";
    int rc = args_parse_one(argc, argv, &own, NULL, &path, missing, err);
    if (rc != FACET_OK)
        return rc;
    const char *run = a.run, *option = a.option, *view = a.view;
    const char *colour = a.colour, *surface = a.surface;
    int triangles = a.triangles;
    struct export_request request = a.request;
    if (run == NULL || option == NULL)
        return facet_error_set(err, FACET_EINPUT, "%s", missing);
    if (!request.obj && !request.csv && !request.json && !request.svg &&
        !request.xlsx && !request.dxf && !request.ifc)
        return facet_error_set(err, FACET_EINPUT,
            "export: say what to write: --obj, --csv, --xlsx, --dxf, --ifc, "
            "--json and/or --svg");
    if (a.sheet && !request.dxf)
        return facet_error_set(err, FACET_EINPUT,
            "export: --sheet is the size of the --dxf's sheets; give --dxf");
    if (a.sheet && (rc = dxf_sheet_parse(a.sheet, "--sheet",
                                         &request.sheet_width,
                                         &request.sheet_height, err)))
        return rc;
    long run_id, number;
    if ((rc = args_int(run, 1, 1L << 62, "--run", &run_id, err)) ||
        (rc = args_int(option, 1, 1L << 62, "--option", &number, err)))
        return rc;
    svg_map_defaults(&request.map);
    if (view && (rc = svg_map_view_parse(view, &request.map.view, err)))
        return rc;
    if (colour && (rc = svg_map_colouring_parse(colour,
                                                 &request.map.colour_by,
                                                 err)))
        return rc;
    request.map.triangles = triangles;
    struct store *store;
    if ((rc = store_open_existing(path, &store, err)) != FACET_OK)
        return rc;
    if (surface != NULL)
        rc = study_repoint_surface(store, run_id, surface, err);
    /* A building's files are read and prepared again, seconds on a big
     * one: say so on a terminal, and let Ctrl-C stop it with no file
     * written. */
    struct study_hooks hooks = {NULL, progress_show_stage, NULL,
                                signals_stop_hook, NULL,
                                progress_show_warning, NULL};
    request.hooks = &hooks;
    signals_catch_stop();
    if (rc == FACET_OK)
        rc = study_export(store, run_id, number, &request, err);
    if (rc != FACET_OK && request.refused_building)
        rc = building_refusal(path, run_id, number, err);
    /* What was written is said on stdout, unless a file went there. */
    FILE *say = stdout;
    for (int k = 0; k < EXPORT_FILES; k++)
        if (request.written[k][0] && is_stdout(request.written[k]))
            say = stderr;
    for (int k = 0; rc == FACET_OK && k < EXPORT_FILES; k++)
        if (request.written[k][0])
            shown_line(say, "wrote %s", request.written[k]);
    store_close(store);
    if (rc == FACET_ESTOP) {
        shown_line(stderr, "facet: export interrupted; no file written");
        return signals_stop_status();
    }
    return rc;
}

const struct command cmd_export = {
    .name = "export",
    .usage = "DB --run N --option M [--obj FILE.obj] [--csv FILE.csv]\n"
             "       [--xlsx FILE.xlsx] [--dxf FILE.dxf [--sheet WxH]]\n"
             "       [--ifc FILE.ifc]\n"
             "       [--json FILE.json] [--svg FILE.svg] [--view "
             "uv|top|front|side]\n"
             "       [--colour type|class] [--triangles] [--surface FILE] "
             "[--force]",
    .summary = "Export one option: OBJ + MTL, CSV or XLSX panel schedule, "
               "JSON, SVG panel map, DXF flat patterns, IFC4 model.",
    .before = "",
    .options = export_options,
    .after = "",
    .run = export_main,
};
