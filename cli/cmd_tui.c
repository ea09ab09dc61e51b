/*
 * cmd_tui.c: `facet tui [DB] [SURFACE.obj]`, the terminal workbench
 * (tui/tui.h). The command line says which file is the database and which
 * the surface; tui_run is told both.
 */
#include <stddef.h>
#include <string.h>
#include <strings.h>

#include "command.h"
#include "tui/tui.h"
#include "args.h"

/* The syntax's one rule for a lone argument: a name ending in .obj is a
 * surface (`facet tui roof.obj`), anything else a database. */
static int names_obj(const char *path)
{
    size_t n = strlen(path);
    return n > 4 && strcasecmp(path + n - 4, ".obj") == 0;
}

/* The options as given (pointing into argv), NULL when absent. */
struct tui_args {
    const char *db, *surface;
};

static const struct arg_option tui_options[] = {
    {"db", 0, ARG_STRING, offsetof(struct tui_args, db), "FILE",
     "the same as DB", NULL},
    {"surface", 0, ARG_STRING, offsetof(struct tui_args, surface), "FILE",
     "the same as SURFACE.obj, whatever the file's name", NULL},
    {NULL, 0, ARG_FLAG, 0, NULL, NULL, NULL},
};

static int tui_main(int argc, char **argv, struct facet_error *err)
{
    struct tui_args a = {NULL, NULL};
    const struct arg_table own = {tui_options, &a};
    const char *path[2] = {NULL, NULL};
    int count;
    int rc = args_parse(argc, argv, &own, NULL, path, 2, &count, err);
    if (rc != FACET_OK)
        return rc;
    const char *db = a.db, *surface = a.surface;
    const char *given_db = NULL, *given_surface = NULL;
    if (count == 2) {
        given_db = path[0];
        given_surface = path[1];
    } else if (count == 1 && names_obj(path[0])) {
        given_surface = path[0];
    } else if (count == 1) {
        given_db = path[0];
    }
    if ((db && given_db) || (surface && given_surface))
        return facet_error_set(err, FACET_EINPUT,
            "tui: the database or the surface is named twice (facet tui "
            "[DB] [SURFACE.obj], or --db FILE --surface FILE)");
    if (db == NULL)
        db = given_db ? given_db : "facet.db";
    if (surface == NULL)
        surface = given_surface;
    return tui_run(db, surface, err);
}

const struct command cmd_tui = {
    .name = "tui",
    .usage = "[DB] [SURFACE.obj]\n"
             "   or: facet tui [--db FILE] [--surface FILE]",
    .summary = "The terminal workbench: browse, filter, compare and start "
               "runs.",
    .before =
        "  DB                  the result store (default facet.db here;\n"
        "                      a missing one is created after a y/n)\n"
        "  SURFACE.obj         open the New run form for this surface;\n"
        "                      alone, a name ending in .obj is the surface\n"
        "                      (into facet.db)\n",
    .options = tui_options,
    .after = "",
    .run = tui_main,
};
