/*
 * command.h: the table of facet subcommands.
 *
 * One subcommand, one file (cli/cmd_NAME.c), one table entry. The usage text
 * printed by `facet --help`, `facet help CMD` and `facet CMD --help` is made
 * from the same entry, its option lines from the very tables the command
 * parses with, so it never drifts from the code.
 */
#ifndef FACET_COMMAND_H
#define FACET_COMMAND_H

#include <stdio.h>

#include "args.h"
#include "core/base/error.h"

struct command {
    const char *name;
    const char *usage;    /* arguments after the name, one line */
    const char *summary;  /* what it does, one line */
    /* Lines before the option lines (its arguments, what it writes), each
     * ending with a newline, or "". */
    const char *before;
    /* The table the command parses its options with (args.h), NULL for
     * none, and the shared one it takes too (classify_flags.h), or NULL:
     * --help names every entry of both, from the tables themselves. */
    const struct arg_option *options;
    const struct arg_option *shared;
    const char *after;    /* lines after them (examples, notes), or "" */
    /* The command whose options the words after "--" are (facet slurm:
     * optimize's, for every shard), or NULL: after "--" only files. The
     * bash completion offers that command's flags there. */
    const struct command *passes_on;
    /* Runs the command on argv[0..argc) (argv[0] is the command's name).
     * Returns the exit code: 0 success, 1 failure while working, 2 bad
     * usage or bad input, with err filled for 1 and 2. */
    int (*run)(int argc, char **argv, struct facet_error *err);
};

/* Checks facet optimize's arguments argv[0..argc) (argv[0] "optimize") as
 * facet optimize would, without opening any file or database: facet slurm
 * refuses the options it would write into its scripts if optimize would
 * refuse them on every node. FACET_OK, or FACET_EINPUT with optimize's
 * own message. */
int optimize_args_check(int argc, char **argv, struct facet_error *err);

/* Every subcommand, NULL-terminated, in the order --help lists them. */
extern const struct command *const command_table[];

/* The entry named name, or NULL. */
const struct command *command_find(const char *name);

/* Prints the usage of one command: name, usage, summary, and under
 * "options:" its before lines, a line per entry of its tables
 * (args_print_help) and its after lines. */
void command_print_usage(const struct command *cmd, FILE *out);

/* Prints the program's usage: every command with its summary. */
void command_print_overview(FILE *out);

/* What Facet does, one paragraph, and what its exit status means, one
 * line: the overview prints them, and the manual page (man_page.h). */
extern const char command_program_summary[];
extern const char command_exit_status[];

extern const struct command cmd_help;
extern const struct command cmd_info;
extern const struct command cmd_example;
extern const struct command cmd_classify;
extern const struct command cmd_planarize;
extern const struct command cmd_curvature;
extern const struct command cmd_optimize;
extern const struct command cmd_merge;
extern const struct command cmd_slurm;
extern const struct command cmd_runs;
extern const struct command cmd_options;
extern const struct command cmd_show;
extern const struct command cmd_tui;
extern const struct command cmd_export;
extern const struct command cmd_plot;
extern const struct command cmd_migrate;

#endif
