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

/* The options as given (pointing into argv), the defaults or 0 when
 * absent. */
struct plot_args {
    const char *run, *runs, *output, *x, *y, *size, *title;
    int force, no_size;
};

static const struct arg_option plot_options[] = {
    {"run", 0, ARG_STRING, offsetof(struct plot_args, run), "N",
     "the run to plot", NULL},
    {"runs", 0, ARG_STRING, offsetof(struct plot_args, runs), "N,M",
     "several runs overlaid, one colour each", NULL},
    {"x", 0, ARG_STRING, offsetof(struct plot_args, x), "METRIC",
     "across (default planarity, m)", NULL},
    {"y", 0, ARG_STRING, offsetof(struct plot_args, y), "METRIC",
     "up (default cost, USD)", NULL},
    {"size", 0, ARG_STRING, offsetof(struct plot_args, size), "METRIC",
     "bubble size (default dp_area, m^2)", NULL},
    {"no-size", 0, ARG_FLAG, offsetof(struct plot_args, no_size), NULL,
     "equal dots", NULL},
    {"title", 0, ARG_STRING, offsetof(struct plot_args, title), "TEXT",
     "the plot's title", NULL},
    {"output", 'o', ARG_STRING, offsetof(struct plot_args, output), "FILE",
     "the SVG to write", NULL},
    {"force", 'f', ARG_FLAG, offsetof(struct plot_args, force), NULL,
     "overwrite an existing file", NULL},
    {NULL, 0, ARG_FLAG, 0, NULL, NULL, NULL},
};

static int plot_main(int argc, char **argv, struct facet_error *err)
{
    struct plot_args a = {NULL, NULL, NULL, "planarity", "cost", "dp_area",
                          NULL, 0, 0};
    const struct arg_table own = {plot_options, &a};
    const char *path;
    const char *missing =
        "plot: give the database, --run N (or --runs N,M) and -o "
        "FILE.svg";
    int rc = args_parse_one(argc, argv, &own, NULL, &path, missing, err);
    if (rc != FACET_OK)
        return rc;
    const char *run = a.run, *runs = a.runs, *output = a.output;
    const char *x = a.x, *y = a.y, *size = a.size, *title = a.title;
    int force = a.force, no_size = a.no_size;
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
    .usage = "DB --run N [--runs N,M] [--x METRIC] [--y METRIC]\n"
             "       [--size METRIC] [--no-size] [--title TEXT] -o FILE.svg "
             "[--force]",
    .summary = "Plot a run's options as SVG: Pareto front, knee, bubbles.",
    .before = "",
    .options = plot_options,
    .after = "",
    .run = plot_main,
};
