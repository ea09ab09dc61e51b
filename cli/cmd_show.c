/*
 * cmd_show.c: `facet show DB --run N --option M`, one stored option: its
 * variables, totals and panel map, computing and storing its panels first
 * when they are not stored yet.
 */
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include "args.h"
#include "command.h"
#include "core/base/numformat.h"
#include "option_text.h"
#include "surface_table.h"
#include "core/out/report.h"
#include "core/base/text.h"
#include "study/study.h"
#include "study/study_export.h"

/* The options as given (pointing into argv), NULL or 0 when absent. */
struct show_args {
    const char *run, *option, *surface;
    int json;
};

static const struct arg_option show_options[] = {
    {"run", 0, ARG_STRING, offsetof(struct show_args, run), "N", "the run",
     NULL},
    {"option", 0, ARG_STRING, offsetof(struct show_args, option), "M",
     "the option's number in the run", NULL},
    {"json", 0, ARG_FLAG, offsetof(struct show_args, json), NULL,
     "the option as facet classify --json writes it", NULL},
    {"surface", 0, ARG_STRING, offsetof(struct show_args, surface), "FILE",
     "the run's surface has moved: record its new place (its SHA-256 must "
     "be the run's)", NULL},
    {NULL, 0, ARG_FLAG, 0, NULL, NULL, NULL},
};

static int show_main(int argc, char **argv, struct facet_error *err)
{
    struct show_args a = {NULL, NULL, NULL, 0};
    const struct arg_table own = {show_options, &a};
    const char *path;
    const char *missing =
        "show: give the database, the run and the option (facet show "
        "runs.db --run 1 --option 12)";
    int rc = args_parse_one(argc, argv, &own, NULL, &path, missing, err);
    if (rc != FACET_OK)
        return rc;
    const char *run = a.run, *option = a.option, *surface = a.surface;
    int json = a.json;
    if (run == NULL || option == NULL)
        return facet_error_set(err, FACET_EINPUT, "%s", missing);
    long run_id, number;
    if ((rc = args_int(run, 1, 1L << 62, "--run", &run_id, err)) ||
        (rc = args_int(option, 1, 1L << 62, "--option", &number, err)))
        return rc;
    struct store *store;
    if ((rc = store_open_existing(path, &store, err)) != FACET_OK)
        return rc;
    struct study_option o;
    memset(&o, 0, sizeof o);
    if (surface != NULL)
        rc = study_repoint_surface(store, run_id, surface, err);
    if (rc == FACET_OK)
        rc = study_option_load(store, run_id, number, 0, &o, err);
    if (rc == FACET_OK && json && o.nsurfaces > 0)
        rc = facet_error_set(err, FACET_EINPUT,
            "show --json: run %ld is a project; its option's rows per "
            "surface are in the store's option_surfaces table", run_id);
    if (rc == FACET_OK) {
        if (json) {
            struct report_source source;
            study_option_source(&o, &source);
            report_json(stdout, &source, &o.classify, &o.panels, &o.totals);
        } else {
            printf("%-16s run %lld option %lld%s%s\n", "option",
                   (long long)run_id, (long long)number,
                   o.row.rank == 1 ? " (Pareto-optimal)" : "",
                   o.row.knee ? " (the knee)" : "");
            char shown[sizeof o.run.surface_path];
            text_for_terminal(o.run.surface_path, shown, sizeof shown);
            printf("%-16s %s (%s)\n", "surface", shown,
                   store_run_setting_text(&o.run, RUN_SETTING_UNITS));
            if (o.nsurfaces > 0) {
                printf("%-16s %zu surfaces, %lld triangles, %.3f m^2\n",
                       "project", o.nsurfaces, (long long)o.run.triangles,
                       o.run.surface_area);
                printf("%-16s %.2f m x %.2f m (%zu panels; %zu module%s "
                       "of the range give%s these grids)\n", "module",
                       o.row.module_w, o.row.module_h, o.totals.panels,
                       o.row.modules, o.row.modules == 1 ? "" : "s",
                       o.row.modules == 1 ? "s" : "");
            } else {
                char panels[40];
                number_grouped(panels, sizeof panels, (double)o.totals.panels,
                               0);
                printf("%-16s %d x %d (%s panels)\n", "grid", o.row.nu,
                       o.row.nv, panels);
            }
            printf("%-16s %g mm\n", "threshold", o.row.threshold_mm);
            printf("%-16s %d%s\n", "Pareto rank", o.row.rank,
                   o.row.rank == 0 ? " (not ranked yet)" : "");
            option_text_kind(stdout, &o.totals, &o.panels,
                             o.run.planarize_closeness_mm);
            option_text_totals(stdout, &o.totals, &o.classify);
            if (o.nsurfaces > 0) {
                printf("\n");
                surface_table_print(stdout, o.surfaces, o.surface_rows,
                                    o.nsurfaces);
            }
            else
                option_text_map(stdout, &o.panels);
        }
    }
    study_option_free(&o);
    store_close(store);
    return rc;
}

const struct command cmd_show = {
    .name = "show",
    .usage = "DB --run N --option M [--json] [--surface FILE]",
    .summary = "Show one stored option: totals and panel map.",
    .before = "",
    .options = show_options,
    .after = "",
    .run = show_main,
};
