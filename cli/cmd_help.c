/*
 * cmd_help.c: `facet help [COMMAND]`, and the same text as a manual page
 * (--man) and as shell completion (--completion SHELL), for make install.
 */
#include <stddef.h>
#include <stdio.h>

#include "args.h"
#include "command.h"
#include "completion.h"
#include "man_page.h"

struct help_args {
    int man;
    const char *completion;
};

static const struct arg_option help_options[] = {
    {"man", 0, ARG_FLAG, offsetof(struct help_args, man), NULL,
     "print this help, of every command, as a manual page (roff): what "
     "make install installs as facet.1", NULL},
    {"completion", 0, ARG_STRING, offsetof(struct help_args, completion),
     "bash", "print the completion script of that shell for the "
     "commands, their flags and the columns of --sort and --where",
     NULL},
    {NULL, 0, ARG_FLAG, 0, NULL, NULL, NULL},
};

static int help_run(int argc, char **argv, struct facet_error *err)
{
    struct help_args a = {0, NULL};
    const struct arg_table table = {help_options, &a};
    const char *name = NULL;
    int count = 0;
    int rc = args_parse(argc, argv, &table, NULL, &name, 1, &count, err);
    if (rc != FACET_OK)
        return rc;
    if ((a.man || a.completion) && count > 0)
        return facet_error_set(err, FACET_EINPUT,
            "help: --man and --completion cover every command: give no "
            "command name");
    if (a.man && a.completion)
        return facet_error_set(err, FACET_EINPUT,
                               "help: give --man or --completion, not both");
    if (a.man) {
        man_page_write(stdout);
        return 0;
    }
    if (a.completion)
        return completion_write(stdout, a.completion, err);
    if (count == 0) {
        command_print_overview(stdout);
        return 0;
    }
    const struct command *cmd = command_find(name);
    if (cmd == NULL)
        return facet_error_set(err, FACET_EINPUT,
            "help: unknown command '%s' (see 'facet --help')", name);
    command_print_usage(cmd, stdout);
    return 0;
}

const struct command cmd_help = {
    .name = "help",
    .usage = "[COMMAND] [--man] [--completion SHELL]",
    .summary = "Show the commands, or one command's usage and options.",
    .before = "",
    .options = help_options,
    .after = "",
    .run = help_run,
};
