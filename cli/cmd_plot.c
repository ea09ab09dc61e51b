/*
 * cmd_plot.c: `facet plot DB --run N -o FILE.svg`, a run's options as the
 * paper's Figure 13: total planarity against cost, bubble size by DP area,
 * the Pareto front drawn and the knee marked; --runs overlays runs.
 */
#include <stdio.h>
#include <string.h>

#include "args.h"
#include "command.h"
#include "shown.h"
#include "study/study_export.h"

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
    const char *path;
    const char *missing =
        "plot: give the database, --run N (or --runs N,M) and -o "
        "FILE.svg";
    int rc = args_parse_one(argc, argv, options, NULL, &path, missing, err);
    if (rc != FACET_OK)
        return rc;
    if ((run == NULL) == (runs == NULL) || output == NULL)
        return facet_error_set(err, FACET_EINPUT, "%s", missing);
    if (no_size)
        size = NULL;
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
    static const char *const flags[3] = {"--x", "--y", "--size"};
    struct plot_request request = {ids, nruns, x, y, size, title, force,
                                   NULL, 0, flags};
    struct store *store;
    if ((rc = store_open_read(path, &store, err)) != FACET_OK)
        return rc;
    rc = study_plot(store, &request, output, err);
    if (rc == FACET_OK)
        shown_line(stdout, "wrote %s", output);
    store_close(store);
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
