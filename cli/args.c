/*
 * args.c: the shared option parser. See args.h.
 */
#include "args.h"

#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/base/numparse.h"
#include "core/base/spelling.h"

/* The tables a command parses against: its own and the shared ones
 * (NULL when none), each ending with a NULL name. */
struct arg_tables {
    const struct arg_option *table[2];
};

static const struct arg_option *find_long(const struct arg_tables *tables,
                                          const char *name, size_t length)
{
    for (int t = 0; t < 2; t++)
        for (const struct arg_option *o = tables->table[t];
             o != NULL && o->name != NULL; o++)
            if (strlen(o->name) == length &&
                memcmp(o->name, name, length) == 0)
                return o;
    return NULL;
}

static const struct arg_option *find_alias(const struct arg_tables *tables,
                                           char alias)
{
    for (int t = 0; t < 2; t++)
        for (const struct arg_option *o = tables->table[t];
             o != NULL && o->name != NULL; o++)
            if (o->alias != 0 && o->alias == alias)
                return o;
    return NULL;
}

/* The error for an unknown --name (length bytes of name), with the
 * nearest flag of the table when one is close. */
static int unknown_long(const char *command,
                        const struct arg_tables *tables, const char *name,
                        size_t length, struct facet_error *err)
{
    const char *names[128];
    size_t n = 0;
    for (int t = 0; t < 2; t++)
        for (const struct arg_option *o = tables->table[t];
             o != NULL && o->name != NULL && n < 128; o++)
            names[n++] = o->name;
    const char *near = spelling_closest(name, length, names, n);
    if (near != NULL)
        return facet_error_set(err, FACET_EINPUT,
            "%s: unknown option '--%.*s' (did you mean --%s?)", command,
            (int)length, name, near);
    return facet_error_set(err, FACET_EINPUT,
        "%s: unknown option '--%.*s' (see 'facet %s --help')", command,
        (int)length, name, command);
}

int args_parse(int argc, char **argv, const struct arg_option *options,
               const char **positional, int max, int *count,
               struct facet_error *err)
{
    return args_parse_shared(argc, argv, options, NULL, positional, max,
                             count, err);
}

int args_parse_shared(int argc, char **argv,
                      const struct arg_option *options,
                      const struct arg_option *shared,
                      const char **positional, int max, int *count,
                      struct facet_error *err)
{
    const struct arg_tables tables = {{options, shared}};
    int only_positional = 0;
    *count = 0;
    for (int i = 1; i < argc; i++) {
        const char *word = argv[i];
        const struct arg_option *option = NULL;
        const char *value = NULL;

        if (!only_positional && strcmp(word, "--") == 0) {
            only_positional = 1;
            continue;
        }
        if (!only_positional && word[0] == '-' && word[1] == '-') {
            const char *name = word + 2;
            const char *equals = strchr(name, '=');
            size_t length = equals ? (size_t)(equals - name) : strlen(name);
            option = find_long(&tables, name, length);
            if (option == NULL)
                return unknown_long(argv[0], &tables, name, length, err);
            if (equals != NULL) {
                if (option->kind == ARG_FLAG)
                    return facet_error_set(err, FACET_EINPUT,
                        "%s: option '--%s' takes no value", argv[0],
                        option->name);
                value = equals + 1;
            }
        } else if (!only_positional && word[0] == '-' && word[1] != '\0' &&
                   word[2] == '\0' && find_alias(&tables, word[1]) != NULL) {
            option = find_alias(&tables, word[1]);
        } else if (!only_positional && word[0] == '-' && word[1] != '\0' &&
                   !(word[1] >= '0' && word[1] <= '9') && word[1] != '.') {
            return facet_error_set(err, FACET_EINPUT,
                "%s: unknown option '%s' (see 'facet %s --help')", argv[0],
                word, argv[0]);
        }

        if (option == NULL) {
            if (*count >= max)
                return facet_error_set(err, FACET_EINPUT,
                    "%s: unexpected argument '%s' (see 'facet %s --help')",
                    argv[0], word, argv[0]);
            positional[(*count)++] = word;
            continue;
        }
        if (option->kind == ARG_FLAG) {
            *option->flag = 1;
            continue;
        }
        if (value == NULL) {
            if (i + 1 >= argc)
                return facet_error_set(err, FACET_EINPUT,
                    "%s: option '--%s' needs a value", argv[0], option->name);
            value = argv[++i];
        }
        *option->value = value;
    }
    return FACET_OK;
}

int args_parse_one(int argc, char **argv, const struct arg_option *options,
                   const struct arg_option *shared, const char **positional,
                   const char *missing, struct facet_error *err)
{
    int count;
    int rc = args_parse_shared(argc, argv, options, shared, positional, 1,
                               &count, err);
    if (rc == FACET_OK && count != 1)
        rc = facet_error_set(err, FACET_EINPUT, "%s", missing);
    return rc;
}

int args_parse_surfaces(int argc, char **argv,
                        const struct arg_option *options,
                        const struct arg_option *shared, const char **files,
                        int *count, struct facet_error *err)
{
    /* Every word is taken, so that too many files is said as such, not
     * as an argument the command does not expect. */
    const char **all = calloc((size_t)argc + 1, sizeof *all);
    if (all == NULL)
        return facet_error_set(err, FACET_EWORK, "out of memory");
    int n = 0;
    int rc = args_parse_shared(argc, argv, options, shared, all, argc, &n,
                               err);
    if (rc == FACET_OK)
        rc = project_files_check((size_t)n, err);
    if (rc == FACET_OK) {
        memcpy(files, all, (size_t)n * sizeof *files);
        *count = n;
    }
    free(all);
    return rc;
}

int args_int(const char *text, long min, long max, const char *what,
             long *out, struct facet_error *err)
{
    const char *stop;
    long long number;
    int rc = numparse_whole(text, text + strlen(text), LLONG_MIN, LLONG_MAX,
                            &number, &stop);
    if (rc == NUMPARSE_SYNTAX || *stop != '\0')
        return facet_error_set(err, FACET_EINPUT,
            "%s: '%s' is not a whole number", what, text);
    if (rc == NUMPARSE_RANGE || number < min || number > max)
        return facet_error_set(err, FACET_EINPUT,
            "%s: %s is out of range (%ld to %ld)", what, text, min, max);
    *out = (long)number;
    return FACET_OK;
}
