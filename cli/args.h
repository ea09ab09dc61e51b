/*
 * args.h: the option parser every subcommand shares, and the option lines
 * of its --help.
 *
 * Options are long (--name VALUE, --name=VALUE, or --flag), with an optional
 * one-letter alias (-o VALUE); everything else is positional; "--" ends the
 * options. A command describes its options in one static table, which
 * both the parser and the help read (command.h), so that a flag it takes
 * cannot be missing from its --help: each entry says where its value goes
 * in the command's struct of values (an offset), and how --help names
 * and explains it.
 */
#ifndef FACET_ARGS_H
#define FACET_ARGS_H

#include <stddef.h>
#include <stdio.h>

#include "core/base/error.h"
#include "core/project/project.h"

enum arg_kind {
    ARG_FLAG,    /* no value: sets its int field to 1 */
    ARG_STRING,  /* one value: sets its const char * field (into argv) */
    ARG_LIST     /* a value each time it is given: appends it to its
                    struct arg_list field (--sbatch LINE --sbatch LINE) */
};

/* The values of an ARG_LIST option, in the order given (into argv). */
#define ARG_LIST_MAX 32
struct arg_list {
    const char *item[ARG_LIST_MAX];
    int count;
};

struct arg_option {
    const char *name;    /* without the leading "--"; NULL ends a table */
    char alias;          /* one-letter alias after "-", or 0 */
    enum arg_kind kind;
    size_t offset;       /* offsetof its field in the values struct: an
                            int for ARG_FLAG, a const char * for
                            ARG_STRING, a struct arg_list for ARG_LIST */
    /* ARG_STRING, ARG_LIST: its value in the help ("FILE"); a fixed set
     * of words is written as them, '|' between ("yes|no"), which the
     * bash completion offers (completion.h). */
    const char *value;
    const char *help;    /* what it does, one paragraph (args_print_help
                            wraps it); NULL: another spelling of the entry
                            before it, named on that entry's line */
    /* NULL, or writes the default the help line ends with, " (default
     * X)", from the defaults the command takes (study_request_defaults,
     * option_params_defaults), so that the help never drifts from them. */
    void (*default_text)(char *out, size_t size);
};

/* A table of options, ending with a NULL name, and the values struct its
 * offsets point into, which the parse fills. */
struct arg_table {
    const struct arg_option *options;
    void *values;
};

/* Parses argv[1..argc) (argv[0] is the command name) against own and
 * shared (NULL: none), a table of flags several commands take (such as
 * classify_flags.h's), writing each option's value into its table's
 * values. Positional arguments are stored in positional[0..max) and
 * counted in *count. Returns FACET_OK or FACET_EINPUT with err naming
 * every unknown option of the line, each once (one: with the nearest
 * known one; so many that one line cannot hold them: the first ones and
 * "and N more"), else the first of: a missing value, an ARG_LIST option
 * given more than ARG_LIST_MAX times, the surplus argument. An unknown
 * option takes no value: the word after it is read as usual. */
int args_parse(int argc, char **argv, const struct arg_table *own,
               const struct arg_table *shared, const char **positional,
               int max, int *count, struct facet_error *err);

/* args_parse for a command of exactly one positional argument (the
 * surface or the database) into *positional. Returns FACET_OK, or
 * FACET_EINPUT as args_parse does, or with the one-line reminder missing
 * ("runs: name the result database (facet runs runs.db)") when the
 * argument is not given. */
int args_parse_one(int argc, char **argv, const struct arg_table *own,
                   const struct arg_table *shared, const char **positional,
                   const char *missing, struct facet_error *err);

/* args_parse for a command that names surface files (a project): at most
 * PROJECT_FILES_MAX (core/project/project.h) into files, which has room
 * for as many; more is FACET_EINPUT with project_files_check's message,
 * the same for every command. */
int args_parse_surfaces(int argc, char **argv, const struct arg_table *own,
                        const struct arg_table *shared, const char **files,
                        int *count, struct facet_error *err);

/* Prints text word by word, wrapped at 78 columns, its first line going
 * on from column at (already written), every line after it from column
 * indent; pads the first to indent when at is short of it. */
void args_print_wrapped(FILE *out, const char *text, int at, int indent);

/* Prints one line (or more, wrapped at 78 columns) per entry of options
 * for --help: "  --name VALUE, -a VALUE" and, from column 23, its help and
 * default; the other spellings of an entry on its line. */
void args_print_help(FILE *out, const struct arg_option *options);

/* Parses text as an integer in [min, max] into *out. what names the value in
 * the error ("--res"). Returns FACET_OK or FACET_EINPUT. (A number that
 * need not be whole: numparse_number, core/base/numparse.h, which the
 * TUI's forms share.) */
int args_int(const char *text, long min, long max, const char *what,
             long *out, struct facet_error *err);

#endif
