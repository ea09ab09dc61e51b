/*
 * cmd_tui.c: `facet tui [DB | SURFACE.obj]`, the terminal workbench
 * (tui/tui.h).
 */
#include "command.h"
#include "tui/tui.h"
#include "args.h"

static int tui_main(int argc, char **argv, struct facet_error *err)
{
    const struct arg_option options[] = {
        {NULL, 0, ARG_FLAG, NULL, NULL},
    };
    const char *path[1] = {NULL};
    int count;
    int rc = args_parse(argc, argv, options, path, 1, &count, err);
    if (rc != FACET_OK)
        return rc;
    return tui_run(count == 1 ? path[0] : NULL, err);
}

const struct command cmd_tui = {
    .name = "tui",
    .usage = "[DB | SURFACE.obj]",
    .summary = "The terminal workbench: browse, filter, compare and start "
               "runs.",
    .options =
        "  DB                  the result store (default facet.db here;\n"
        "                      a missing one is created after a y/n)\n"
        "  SURFACE.obj         open the New run form for this surface\n"
        "                      (into facet.db)\n",
    .run = tui_main,
};
