/*
 * args.c: the shared option parser. See args.h.
 */
#include "args.h"

#include <assert.h>
#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/base/numparse.h"
#include "core/base/spelling.h"

/* The tables a command parses against: its own and the shared one
 * (either NULL when none). */
struct arg_tables {
    const struct arg_table *table[2];
};

/* The entry of the tables named name (length bytes), and in *values the
 * struct its value goes into; NULL when none is. */
static const struct arg_option *find_long(const struct arg_tables *tables,
                                          const char *name, size_t length,
                                          void **values)
{
    for (int t = 0; t < 2; t++)
        for (const struct arg_option *o = tables->table[t]
                                              ? tables->table[t]->options
                                              : NULL;
             o != NULL && o->name != NULL; o++)
            if (strlen(o->name) == length &&
                memcmp(o->name, name, length) == 0) {
                *values = tables->table[t]->values;
                return o;
            }
    return NULL;
}

static const struct arg_option *find_alias(const struct arg_tables *tables,
                                           char alias, void **values)
{
    for (int t = 0; t < 2; t++)
        for (const struct arg_option *o = tables->table[t]
                                              ? tables->table[t]->options
                                              : NULL;
             o != NULL && o->name != NULL; o++)
            if (o->alias != 0 && o->alias == alias) {
                *values = tables->table[t]->values;
                return o;
            }
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
        for (const struct arg_option *o = tables->table[t]
                                              ? tables->table[t]->options
                                              : NULL;
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

/* The unknown options of one command line, each once, in the order
 * given: all of them are named in one error, so that a user (and
 * tests/e2e/help.sh, which asks the binary about many flags in one call)
 * learns every one at once. */
#define UNKNOWN_MAX 64
struct unknowns {
    const char *word[UNKNOWN_MAX];   /* into argv */
    size_t length[UNKNOWN_MAX];      /* of word's name, before any '=' */
    int count;
    int more;                        /* past UNKNOWN_MAX */
};

static void unknown_add(struct unknowns *u, const char *word, size_t length)
{
    for (int k = 0; k < u->count; k++)
        if (u->length[k] == length && memcmp(u->word[k], word, length) == 0)
            return;
    if (u->count == UNKNOWN_MAX) {
        u->more++;
        return;
    }
    u->word[u->count] = word;
    u->length[u->count++] = length;
}

/* The one error for the unknown options u, of command: one as
 * unknown_long says it; several named in a list that fits one message,
 * the rest counted ("and 3 more"). */
static int unknowns_error(const char *command, const struct arg_tables *tables,
                          const struct unknowns *u, struct facet_error *err)
{
    assert(u->count > 0);
    if (u->count == 1 && u->more == 0) {
        if (u->word[0][1] == '-')
            return unknown_long(command, tables, u->word[0] + 2,
                                u->length[0] - 2, err);
        return facet_error_set(err, FACET_EINPUT,
            "%s: unknown option '%.*s' (see 'facet %s --help')", command,
            (int)u->length[0], u->word[0], command);
    }
    char list[sizeof err->message];
    size_t used = 0;
    int named = 0;
    /* Room for the command, the words around the list and "and N more". */
    size_t room = sizeof list - 2 * strlen(command) - 64;
    for (; named < u->count; named++) {
        size_t need = u->length[named] + 4;   /* '', and ", " */
        if (used + need >= room)
            break;
        used += (size_t)snprintf(list + used, sizeof list - used, "%s'%.*s'",
                                 named ? ", " : "", (int)u->length[named],
                                 u->word[named]);
    }
    int rest = u->count - named + u->more;
    if (rest > 0)
        return facet_error_set(err, FACET_EINPUT,
            "%s: unknown options %s and %d more (see 'facet %s --help')",
            command, list, rest, command);
    return facet_error_set(err, FACET_EINPUT,
        "%s: unknown options %s (see 'facet %s --help')", command, list,
        command);
}

/* Writes value (ARG_STRING), appends it (ARG_LIST) or 1 (ARG_FLAG) into
 * option's field of values, where its table's offset says. FACET_EINPUT
 * when an ARG_LIST is full. */
static int store_value(const char *command, const struct arg_option *option,
                       void *values, const char *value,
                       struct facet_error *err)
{
    assert(values != NULL);
    char *field = (char *)values + option->offset;
    if (option->kind == ARG_FLAG) {
        *(int *)(void *)field = 1;
    } else if (option->kind == ARG_LIST) {
        struct arg_list *list = (struct arg_list *)(void *)field;
        if (list->count >= ARG_LIST_MAX)
            return facet_error_set(err, FACET_EINPUT,
                "%s: option '--%s' is given more than %d times", command,
                option->name, ARG_LIST_MAX);
        list->item[list->count++] = value;
    } else {
        *(const char **)(void *)field = value;
    }
    return FACET_OK;
}

int args_parse(int argc, char **argv, const struct arg_table *own,
               const struct arg_table *shared, const char **positional,
               int max, int *count, struct facet_error *err)
{
    const struct arg_tables tables = {{own, shared}};
    struct unknowns unknown;
    unknown.count = unknown.more = 0;
    /* The first error that is not an unknown option: said only when no
     * option is unknown, for an unknown option can explain it (a value
     * taken as an argument). The line is read to its end either way. */
    struct facet_error first;
    facet_error_clear(&first);
    int only_positional = 0;
    *count = 0;
    for (int i = 1; i < argc; i++) {
        const char *word = argv[i];
        const struct arg_option *option = NULL;
        void *values = NULL;
        const char *value = NULL;

        if (!only_positional && strcmp(word, "--") == 0) {
            only_positional = 1;
            continue;
        }
        if (!only_positional && word[0] == '-' && word[1] == '-') {
            const char *name = word + 2;
            const char *equals = strchr(name, '=');
            size_t length = equals ? (size_t)(equals - name) : strlen(name);
            option = find_long(&tables, name, length, &values);
            if (option == NULL) {
                unknown_add(&unknown, word, length + 2);
                continue;
            }
            if (equals != NULL) {
                if (option->kind == ARG_FLAG) {
                    if (first.code == FACET_OK)
                        facet_error_set(&first, FACET_EINPUT,
                            "%s: option '--%s' takes no value", argv[0],
                            option->name);
                    continue;
                }
                value = equals + 1;
            }
        } else if (!only_positional && word[0] == '-' && word[1] != '\0' &&
                   word[2] == '\0' &&
                   find_alias(&tables, word[1], &values) != NULL) {
            option = find_alias(&tables, word[1], &values);
        } else if (!only_positional && word[0] == '-' && word[1] != '\0' &&
                   !(word[1] >= '0' && word[1] <= '9') && word[1] != '.') {
            unknown_add(&unknown, word, strlen(word));
            continue;
        }

        if (option == NULL) {
            if (*count < max)
                positional[(*count)++] = word;
            else if (first.code == FACET_OK)
                facet_error_set(&first, FACET_EINPUT,
                    "%s: unexpected argument '%s' (see 'facet %s --help')",
                    argv[0], word, argv[0]);
            continue;
        }
        if (option->kind != ARG_FLAG && value == NULL) {
            if (i + 1 >= argc) {
                if (first.code == FACET_OK)
                    facet_error_set(&first, FACET_EINPUT,
                        "%s: option '--%s' needs a value", argv[0],
                        option->name);
                continue;
            }
            value = argv[++i];
        }
        if (first.code == FACET_OK)
            store_value(argv[0], option, values, value, &first);
    }
    if (unknown.count > 0)
        return unknowns_error(argv[0], &tables, &unknown, err);
    if (first.code != FACET_OK)
        return facet_error_set(err, first.code, "%s", first.message);
    return FACET_OK;
}

int args_parse_one(int argc, char **argv, const struct arg_table *own,
                   const struct arg_table *shared, const char **positional,
                   const char *missing, struct facet_error *err)
{
    int count;
    int rc = args_parse(argc, argv, own, shared, positional, 1, &count, err);
    if (rc == FACET_OK && count != 1)
        rc = facet_error_set(err, FACET_EINPUT, "%s", missing);
    return rc;
}

int args_parse_surfaces(int argc, char **argv, const struct arg_table *own,
                        const struct arg_table *shared, const char **files,
                        int *count, struct facet_error *err)
{
    /* Every word is taken, so that too many files is said as such, not
     * as an argument the command does not expect. */
    const char **all = calloc((size_t)argc + 1, sizeof *all);
    if (all == NULL)
        return facet_error_set(err, FACET_EWORK, "out of memory");
    int n = 0;
    int rc = args_parse(argc, argv, own, shared, all, argc, &n, err);
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

/* Columns of the help: the option from 3, its text from HELP_COLUMN + 1,
 * no line past HELP_WIDTH. */
#define HELP_COLUMN 22
#define HELP_WIDTH 78

/* Appends "--name VALUE[, -a VALUE]" of o to the size bytes of left. */
static void append_names(char *left, size_t size, const struct arg_option *o)
{
    size_t n = strlen(left);
    const char *value = o->kind != ARG_FLAG ? o->value : NULL;
    snprintf(left + n, size - n, "%s--%s%s%s", n > 2 ? ", " : "", o->name,
             value ? " " : "", value ? value : "");
    n = strlen(left);
    if (o->alias != 0)
        snprintf(left + n, size - n, ", -%c%s%s", o->alias,
                 value ? " " : "", value ? value : "");
}

void args_print_wrapped(FILE *out, const char *text, int at, int indent)
{
    int column = at;
    for (const char *p = text; *p != '\0';) {
        while (*p == ' ')
            p++;
        size_t word = strcspn(p, " ");
        if (word == 0)
            break;
        if (column > indent &&
            column + 1 + (int)word > HELP_WIDTH) {
            fputc('\n', out);
            column = 0;
        }
        if (column < indent) {
            fprintf(out, "%*s", indent - column, "");
            column = indent;
        } else if (column > 0) {
            fputc(' ', out);
            column++;
        }
        fwrite(p, 1, word, out);
        column += (int)word;
        p += word;
    }
    fputc('\n', out);
}

void args_print_help(FILE *out, const struct arg_option *options)
{
    for (const struct arg_option *o = options; o->name != NULL; o++) {
        /* an entry without help is a spelling of the one before it */
        assert(o->help != NULL || o != options);
        assert(o->kind == ARG_FLAG || o->value != NULL);
        if (o->help == NULL)
            continue;
        char left[256] = "  ";
        append_names(left, sizeof left, o);
        for (const struct arg_option *other = o + 1;
             other->name != NULL && other->help == NULL; other++)
            append_names(left, sizeof left, other);
        char text[1024], shown[256] = "";
        if (o->default_text != NULL)
            o->default_text(shown, sizeof shown);
        snprintf(text, sizeof text, "%s%s%s%s", o->help,
                 shown[0] ? " (default " : "", shown, shown[0] ? ")" : "");
        fputs(left, out);
        int at = (int)strlen(left);
        if (at >= HELP_COLUMN) {
            fputc('\n', out);
            at = 0;
        }
        args_print_wrapped(out, text, at, HELP_COLUMN);
    }
}
