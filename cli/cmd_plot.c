/*
 * cmd_plot.c: `facet plot DB --run N -o FILE.svg`, a run's options as the
 * paper's Figure 13: total planarity against cost, bubble size by DP area,
 * the Pareto front drawn and the knee marked; --runs overlays runs.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "command.h"
#include "core/outfile.h"
#include "core/svg_plot.h"
#include "store/store.h"

#define PLOT_MAX_RUNS 8

/* The unit a column is in, for the axis label. */
static const char *column_unit(const char *column)
{
    static const char *const unit[][2] = {
        {"cost", "USD"}, {"planarity", "m"}, {"max_deviation", "m"},
        {"fp_area", "m^2"}, {"sp_area", "m^2"}, {"dp_area", "m^2"},
        {"area", "m^2"}, {"max_panel_area", "m^2"}, {"p_dist", "m^4"},
        {"threshold_mm", "mm"},
    };
    for (size_t k = 0; k < sizeof unit / sizeof *unit; k++)
        if (strcmp(unit[k][0], column) == 0)
            return unit[k][1];
    return "";
}

static int check_column(const char *what, const char *column,
                        struct facet_error *err)
{
    for (int k = 0; store_option_columns[k] != NULL; k++)
        if (strcmp(store_option_columns[k], column) == 0 &&
            strcmp(column, "run") != 0)
            return FACET_OK;
    return facet_error_set(err, FACET_EINPUT,
        "%s: '%s' is not an option column (e.g. cost, planarity, dp_area, "
        "fp_area, nu, threshold_mm)", what, column);
}

/* One run's points. */
struct run_points {
    struct option_row *rows;
    size_t n;
    double *x, *y, *size;
    int *rank;
    char label[160];
};

static int load_run(struct store *store, int64_t run, const char *x,
                    const char *y, const char *size, struct run_points *p,
                    struct svg_plot_series *series, struct facet_error *err)
{
    struct run_info info;
    int rc = store_run_get(store, run, &info, err);
    if (rc == FACET_OK)
        rc = store_options_get(store, run, &p->rows, &p->n, err);
    if (rc != FACET_OK)
        return rc;
    if (p->n == 0)
        return facet_error_set(err, FACET_EINPUT, "run %lld has no options "
                               "to plot", (long long)run);
    p->x = malloc(p->n * sizeof *p->x);
    p->y = malloc(p->n * sizeof *p->y);
    p->size = malloc(p->n * sizeof *p->size);
    p->rank = malloc(p->n * sizeof *p->rank);
    if (!p->x || !p->y || !p->size || !p->rank)
        return facet_error_set(err, FACET_EWORK, "out of memory");
    size_t knee = SIZE_MAX;
    for (size_t k = 0; k < p->n; k++) {
        p->x[k] = store_option_value(&p->rows[k], x);
        p->y[k] = store_option_value(&p->rows[k], y);
        p->size[k] = size ? fmax(0, store_option_value(&p->rows[k], size))
                          : 0;
        p->rank[k] = p->rows[k].rank;
        if (p->rows[k].knee)
            knee = k;
    }
    snprintf(p->label, sizeof p->label, "run %lld%s%s (%s)",
             (long long)run, info.name[0] ? " " : "", info.name,
             info.method);
    *series = (struct svg_plot_series){p->label, NULL, p->n, p->x, p->y,
                                       size ? p->size : NULL, p->rank, knee};
    return FACET_OK;
}

static int plot_main(int argc, char **argv, struct facet_error *err)
{
    const char *run = NULL, *runs = NULL, *output = NULL;
    const char *x = "planarity", *y = "cost", *size = "dp_area";
    const char *title = NULL;
    int force = 0, no_size = 0;
    const struct arg_option options[] = {
        {"run", 0, ARG_STRING, &run, NULL},
        {"runs", 0, ARG_STRING, &runs, NULL},
        {"x", 0, ARG_STRING, &x, NULL},
        {"y", 0, ARG_STRING, &y, NULL},
        {"size", 0, ARG_STRING, &size, NULL},
        {"no-size", 0, ARG_FLAG, NULL, &no_size},
        {"title", 0, ARG_STRING, &title, NULL},
        {"output", 'o', ARG_STRING, &output, NULL},
        {"force", 'f', ARG_FLAG, NULL, &force},
        {NULL, 0, ARG_FLAG, NULL, NULL},
    };
    const char *path[1];
    int count;
    int rc = args_parse(argc, argv, options, path, 1, &count, err);
    if (rc != FACET_OK)
        return rc;
    if (count != 1 || (run == NULL) == (runs == NULL) || output == NULL)
        return facet_error_set(err, FACET_EINPUT,
            "plot: give the database, --run N (or --runs N,M) and -o "
            "FILE.svg");
    if (no_size)
        size = NULL;
    if ((rc = check_column("--x", x, err)) ||
        (rc = check_column("--y", y, err)) ||
        (size && (rc = check_column("--size", size, err))))
        return rc;
    int64_t ids[PLOT_MAX_RUNS];
    int nruns = 0;
    char list[256];
    snprintf(list, sizeof list, "%s", run ? run : runs);
    char *rest = list, *field;
    while ((field = strsep(&rest, ",")) != NULL) {
        long id;
        if (nruns == PLOT_MAX_RUNS)
            return facet_error_set(err, FACET_EINPUT,
                "--runs: at most %d runs in one plot", PLOT_MAX_RUNS);
        if ((rc = args_int(field, 1, 1L << 62, run ? "--run" : "--runs",
                           &id, err)))
            return rc;
        ids[nruns++] = id;
    }
    if ((rc = outfile_check(output, force, err)))
        return rc;

    struct store *store;
    if ((rc = store_open(path[0], &store, err)) != FACET_OK)
        return rc;
    struct run_points points[PLOT_MAX_RUNS];
    struct svg_plot_series series[PLOT_MAX_RUNS];
    memset(points, 0, sizeof points);
    for (int k = 0; k < nruns && rc == FACET_OK; k++)
        rc = load_run(store, ids[k], x, y, size, &points[k], &series[k],
                      err);
    store_close(store);
    if (rc == FACET_OK) {
        struct svg_plot plot;
        svg_plot_defaults(&plot);
        plot.title = title;
        plot.x_name = x;
        plot.x_unit = column_unit(x);
        plot.y_name = y;
        plot.y_unit = column_unit(y);
        plot.size_name = size;
        plot.size_unit = size ? column_unit(size) : NULL;
        plot.series = series;
        plot.nseries = (size_t)nruns;
        rc = svg_plot_save(output, force, &plot, err);
        if (rc == FACET_OK)
            printf("wrote %s\n", output);
    }
    for (int k = 0; k < nruns; k++) {
        free(points[k].rows);
        free(points[k].x);
        free(points[k].y);
        free(points[k].size);
        free(points[k].rank);
    }
    return rc;
}

const struct command cmd_plot = {
    .name = "plot",
    .usage = "DB --run N [--runs N,M] [--x METRIC] [--y METRIC] "
             "[--size METRIC]\n"
             "       [--no-size] [--title TEXT] -o FILE.svg [--force]",
    .summary = "Plot a run's options as SVG: Pareto front, knee, bubbles.",
    .options =
        "  --run N             the run to plot\n"
        "  --runs N,M          several runs overlaid, one colour each\n"
        "  --x METRIC          across (default planarity, m)\n"
        "  --y METRIC          up (default cost, USD)\n"
        "  --size METRIC       bubble size (default dp_area, m^2)\n"
        "  --no-size           equal dots\n"
        "  --title TEXT        the plot's title\n"
        "  -o, --output FILE   the SVG to write\n"
        "  --force, -f         overwrite an existing file\n",
    .run = plot_main,
};
