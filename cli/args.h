/*
 * args.h: the option parser every subcommand shares.
 *
 * Options are long (--name VALUE, --name=VALUE, or --flag), with an optional
 * one-letter alias (-o VALUE); everything else is positional; "--" ends the
 * options. A command describes its options in a table and gets its values
 * written where the table points.
 */
#ifndef FACET_ARGS_H
#define FACET_ARGS_H

#include "core/base/error.h"
#include "core/project/project.h"

enum arg_kind {
    ARG_FLAG,    /* no value: sets *flag to 1 */
    ARG_STRING   /* one value: sets *value (points into argv) */
};

struct arg_option {
    const char *name;    /* without the leading "--" */
    char alias;          /* one-letter alias after "-", or 0 */
    enum arg_kind kind;
    const char **value;  /* for ARG_STRING */
    int *flag;           /* for ARG_FLAG */
};

/* Parses argv[1..argc) (argv[0] is the command name) against options, which
 * ends with an entry whose name is NULL. Positional arguments are stored in
 * positional[0..max) and counted in *count. Returns FACET_OK or FACET_EINPUT
 * with err naming the unknown option, the missing value or the surplus
 * argument. */
int args_parse(int argc, char **argv, const struct arg_option *options,
               const char **positional, int max, int *count,
               struct facet_error *err);

/* args_parse against two tables at once: the command's own options and
 * shared (NULL: none), a table of flags several commands take (such as
 * classify_flags.h's), each ending with an entry whose name is NULL. Kept
 * apart, neither table is copied into the other at an offset. */
int args_parse_shared(int argc, char **argv,
                      const struct arg_option *options,
                      const struct arg_option *shared,
                      const char **positional, int max, int *count,
                      struct facet_error *err);

/* args_parse_shared for a command of exactly one positional argument
 * (the surface or the database) into *positional; shared as there (NULL:
 * none). Returns FACET_OK, or FACET_EINPUT as args_parse does, or with
 * the one-line reminder missing ("runs: name the result database (facet
 * runs runs.db)") when the argument is not given. */
int args_parse_one(int argc, char **argv, const struct arg_option *options,
                   const struct arg_option *shared, const char **positional,
                   const char *missing, struct facet_error *err);

/* args_parse_shared for a command that names surface files (a project):
 * at most PROJECT_FILES_MAX (core/project/project.h) into files, which
 * has room for as many; more is FACET_EINPUT with project_files_check's
 * message, the same for every command. */
int args_parse_surfaces(int argc, char **argv,
                        const struct arg_option *options,
                        const struct arg_option *shared, const char **files,
                        int *count, struct facet_error *err);

/* Parses text as an integer in [min, max] into *out. what names the value in
 * the error ("--res"). Returns FACET_OK or FACET_EINPUT. (A number that
 * need not be whole: numparse_number, core/base/numparse.h, which the
 * TUI's forms share.) */
int args_int(const char *text, long min, long max, const char *what,
             long *out, struct facet_error *err);

#endif
