/*
 * cmd_show.c: `facet show DB --run N --option M`, one stored option: its
 * variables, totals and panel map, computing and storing its panels first
 * when they are not stored yet.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "args.h"
#include "command.h"
#include "option_text.h"
#include "text_table.h"
#include "core/out/report.h"
#include "core/base/text.h"
#include "study/study.h"
#include "study/study_export.h"

/* A project option's surfaces, a row each: its grid, panels by type, cost,
 * the moulds it starts and those its panels use, and its worst deviation,
 * gap and kink. */
static void show_surfaces(const struct study_option *o)
{
    static const struct text_column heads[] = {
        {"surface", "", 8, 1, 0, 0},
        {"grid", "", 9, 0, 0, 0},
        {"panels", "", 7, 0, 9, 0},
        {"FP", "", 6, 0, 5, 0},
        {"SP", "", 6, 0, 5, 0},
        {"DP", "", 6, 0, 5, 0},
        {"cost", "USD", 13, 0, 8, 0},
        {"moulds", "started", 8, 0, 6, 0},
        {"moulds", "used", 7, 0, 6, 0},
        {"max dev", "mm", 8, 0, 7, 0},
        {"max gap", "mm", 8, 0, 4, 0},
        {"max kink", "deg", 9, 0, 4, 0},
    };
    enum { COLUMNS = sizeof heads / sizeof *heads };
    struct text_column column[COLUMNS];
    memcpy(column, heads, sizeof heads);
    for (size_t i = 0; i < o->nsurfaces; i++) {
        int len = (int)strlen(o->surfaces[i].name);
        if (len > column[0].width)
            column[0].width = len < 40 ? len : 40;
    }
    struct text_table t = {column, COLUMNS, {0}, 0, 0};
    text_table_fit(&t, text_table_width(stdout, 0));
    printf("\n");
    text_table_head(stdout, &t);
    for (size_t i = 0; i < o->nsurfaces; i++) {
        const struct option_surface_row *r = &o->surface_rows[i];
        const struct option_totals *s = &r->totals;
        char text[COLUMNS][64], name[256];
        const char *cell[COLUMNS];
        text_for_terminal(o->surfaces[i].name, name, sizeof name);
        snprintf(text[0], sizeof text[0], "%.40s", name);
        snprintf(text[1], sizeof text[1], "%d x %d", r->nu, r->nv);
        snprintf(text[2], sizeof text[2], "%zu", s->panels);
        snprintf(text[3], sizeof text[3], "%zu", s->count[TYPE_FP]);
        snprintf(text[4], sizeof text[4], "%zu", s->count[TYPE_SP]);
        snprintf(text[5], sizeof text[5], "%zu", s->count[TYPE_DP]);
        store_number_text(text[6], sizeof text[6], s->cost, 0, 1);
        snprintf(text[7], sizeof text[7], "%zu", s->moulds);
        snprintf(text[8], sizeof text[8], "%lld", (long long)r->moulds_used);
        store_number_text(text[9], sizeof text[9], s->max_deviation * 1000,
                          2, 0);
        store_number_text(text[10], sizeof text[10], s->max_gap_mm, 2, 0);
        store_number_text(text[11], sizeof text[11], s->max_kink_deg, 2, 0);
        for (int k = 0; k < COLUMNS; k++)
            cell[k] = text[k];
        text_table_row(stdout, &t, cell);
    }
    text_table_foot(stdout, &t);
}

static int show_main(int argc, char **argv, struct facet_error *err)
{
    const char *run = NULL, *option = NULL, *surface = NULL;
    int json = 0;
    const struct arg_option options[] = {
        {"run", 0, ARG_STRING, &run, NULL},
        {"option", 0, ARG_STRING, &option, NULL},
        {"json", 0, ARG_FLAG, NULL, &json},
        {"surface", 0, ARG_STRING, &surface, NULL},
        {NULL, 0, ARG_FLAG, NULL, NULL},
    };
    const char *path;
    const char *missing =
        "show: give the database, the run and the option (facet show "
        "runs.db --run 1 --option 12)";
    int rc = args_parse_one(argc, argv, options, NULL, &path, missing, err);
    if (rc != FACET_OK)
        return rc;
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
                printf("%-16s %d x %d (%zu panels)\n", "grid", o.row.nu,
                       o.row.nv, o.totals.panels);
            }
            printf("%-16s %g mm\n", "threshold", o.row.threshold_mm);
            printf("%-16s %d%s\n", "Pareto rank", o.row.rank,
                   o.row.rank == 0 ? " (not ranked yet)" : "");
            option_text_totals(stdout, &o.totals, &o.classify);
            if (o.nsurfaces > 0)
                show_surfaces(&o);
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
    .options =
        "  --run N             the run\n"
        "  --option M          the option's number in the run\n"
        "  --json              the option as facet classify --json writes "
        "it\n"
        "  --surface FILE      the run's surface has moved: record its new\n"
        "                      place (its SHA-256 must be the run's)\n",
    .run = show_main,
};
