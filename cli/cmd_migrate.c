/*
 * cmd_migrate.c: `facet migrate DB`, an older Facet's database brought to
 * this Facet's schema. The commands that read (runs, options, show,
 * export, plot, the workbench) never change a file's schema: migrating
 * writes into the file and shuts older Facets out of it, so it is asked
 * for by name.
 */
#include <stdio.h>

#include "args.h"
#include "command.h"
#include "shown.h"
#include "store/store.h"

static int migrate_main(int argc, char **argv, struct facet_error *err)
{
    const char *path;
    int rc = args_parse_one(argc, argv, NULL, NULL, &path,
            "migrate: name the result database (facet migrate runs.db)",
            err);
    if (rc != FACET_OK)
        return rc;
    int from = 0;
    if ((rc = store_migrate(path, &from, err)) != FACET_OK)
        return rc;
    int to = store_schema_version();
    if (from == to)
        shown_line(stdout, "%s: already at schema %d; nothing to do", path,
                   to);
    else
        shown_line(stdout, "%s: migrated from schema %d to %d", path, from,
                   to);
    return FACET_OK;
}

const struct command cmd_migrate = {
    .name = "migrate",
    .usage = "DB",
    .summary = "Bring an older Facet's result store to this Facet's "
               "schema.",
    .before = "",
    .options = NULL,
    .after = "The file is written, and no older Facet opens it after: keep "
             "a copy for one.\n"
             "examples:\n"
             "  facet migrate runs.db\n",
    .run = migrate_main,
};
