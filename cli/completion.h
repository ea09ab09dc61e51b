/*
 * completion.h: the shell completion script for facet.
 *
 * Made from the tables facet itself reads: the command table (command.h)
 * for the commands, each command's option tables (args.h) for its flags
 * and which of them take a value, the option quantities
 * (core/quantity/quantity.h) for the column names --sort, --where,
 * --objectives and plot's axes take, and the --where language's own words
 * (store/filter.h). So what it offers is what facet takes, and a flag or
 * column added to a table is offered without another edit. `facet help
 * --completion bash` prints it; `make install` installs it where
 * bash-completion looks (share/bash-completion/completions/facet).
 */
#ifndef FACET_COMPLETION_H
#define FACET_COMPLETION_H

#include <stdio.h>

#include "core/base/error.h"

/* Writes the completion script for shell (only "bash" so far) to out:
 * a function _facet for `complete -F`, which completes
 *   - the first word: the commands, --help, --version;
 *   - a word that starts with '-': the command's flags and --help;
 *   - the value of --sort or --objectives (a comma list), plot's --x,
 *     --y, --size: the column names; of --where: the last name of the
 *     expression, from the columns and the language's words;
 *   - the value of a flag whose value is a folder: folders;
 *   - anything else: file names (complete -o default).
 * Returns FACET_OK, or FACET_EINPUT naming the shell it does not know. */
int completion_write(FILE *out, const char *shell, struct facet_error *err);

#endif
