/*
 * command.c: the subcommand table and the usage text made from it.
 */
#include "command.h"

#include "args.h"

#include <string.h>

const struct command *const command_table[] = {
    &cmd_info,
    &cmd_classify,
    &cmd_planarize,
    &cmd_curvature,
    &cmd_optimize,
    &cmd_merge,
    &cmd_slurm,
    &cmd_runs,
    &cmd_options,
    &cmd_show,
    &cmd_tui,
    &cmd_export,
    &cmd_plot,
    &cmd_migrate,
    &cmd_example,
    &cmd_help,
    NULL
};

const struct command *command_find(const char *name)
{
    for (int i = 0; command_table[i] != NULL; i++)
        if (strcmp(command_table[i]->name, name) == 0)
            return command_table[i];
    return NULL;
}

void command_print_usage(const struct command *cmd, FILE *out)
{
    fprintf(out, "usage: facet %s %s\n\n", cmd->name, cmd->usage);
    args_print_wrapped(out, cmd->summary, 0, 0);
    if (cmd->before[0] == '\0' && cmd->options == NULL &&
        cmd->shared == NULL && cmd->after[0] == '\0')
        return;
    fprintf(out, "\noptions:\n%s", cmd->before);
    if (cmd->options != NULL)
        args_print_help(out, cmd->options);
    if (cmd->shared != NULL)
        args_print_help(out, cmd->shared);
    fputs(cmd->after, out);
}

const char command_program_summary[] =
    "Facet rationalizes free-form surfaces: it divides a surface into a UV "
    "grid of panels, classifies them flat, single- or double-curved, and "
    "prices the result.";

const char command_exit_status[] =
    "0 success, 1 failure while working, 2 bad usage or bad input.";

void command_print_overview(FILE *out)
{
    fputs("usage: facet COMMAND [ARGS]\n\n", out);
    args_print_wrapped(out, command_program_summary, 0, 0);
    fputs("\ncommands:\n", out);
    for (int i = 0; command_table[i] != NULL; i++) {
        int at = fprintf(out, "  %-10s", command_table[i]->name);
        args_print_wrapped(out, command_table[i]->summary, at, at + 1);
    }
    fprintf(out, "\n'facet help COMMAND' or 'facet COMMAND --help' tells "
            "more.\nExit status: %s\n", command_exit_status);
}
