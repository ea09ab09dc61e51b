/*
 * cmd_help.c: `facet help [COMMAND]`.
 */
#include <stdio.h>

#include "command.h"

static int help_run(int argc, char **argv, struct facet_error *err)
{
    if (argc < 2) {
        command_print_overview(stdout);
        return 0;
    }
    if (argc > 2)
        return facet_error_set(err, FACET_EINPUT,
                               "help: give one command name");
    const struct command *cmd = command_find(argv[1]);
    if (cmd == NULL)
        return facet_error_set(err, FACET_EINPUT,
            "help: unknown command '%s' (see 'facet --help')", argv[1]);
    command_print_usage(cmd, stdout);
    return 0;
}

const struct command cmd_help = {
    .name = "help",
    .usage = "[COMMAND]",
    .summary = "Show the commands, or one command's usage and options.",
    .before = "",
    .after = "",
    .run = help_run,
};
