/*
 * completion.c: the bash completion script, from facet's own tables.
 */
#include "completion.h"

#include <string.h>

#include "args.h"
#include "command.h"
#include "core/quantity/quantity.h"
#include "store/filter.h"

/* What a flag's value is, by the word its help names it with (the value
 * of its arg_option): a list of columns, one column, a --where
 * expression, a folder, one of a fixed set of words ("yes|no": "choice",
 * the words offered); any other value ("value") is offered file names,
 * as a word that is no flag's value is. */
static const struct {
    const char *value;
    const char *kind;
} value_kinds[] = {
    {"KEYS", "columns"},
    {"LIST", "columns"},
    {"METRIC", "column"},
    {"EXPR", "expression"},
    {"DIR", "folder"},
    {"FOLDER", "folder"},
};

static const char *value_kind(const struct arg_option *o)
{
    if (o->kind == ARG_FLAG)
        return NULL;
    if (strchr(o->value, '|') != NULL)
        return "choice";
    for (size_t k = 0; k < sizeof value_kinds / sizeof *value_kinds; k++)
        if (strcmp(o->value, value_kinds[k].value) == 0)
            return value_kinds[k].kind;
    return "value";
}

/* Every spelling of every entry of options, space-separated. */
static void write_flags(FILE *out, const struct arg_option *options)
{
    for (const struct arg_option *o = options; o && o->name != NULL; o++) {
        fprintf(out, " --%s", o->name);
        if (o->alias != 0)
            fprintf(out, " -%c", o->alias);
    }
}

/* A case arm per flag of options that takes a value: "CMD --flag)". */
static void write_values(FILE *out, const char *command,
                         const struct arg_option *options)
{
    for (const struct arg_option *o = options; o && o->name != NULL; o++) {
        const char *kind = value_kind(o);
        if (kind == NULL)
            continue;
        fprintf(out, "    '%s --%s'", command, o->name);
        if (o->alias != 0)
            fprintf(out, " | '%s -%c'", command, o->alias);
        if (strcmp(kind, "choice") == 0) {
            /* "choice WORD WORD...": the words of "yes|no" */
            fputs(") echo 'choice ", out);
            for (const char *c = o->value; *c != '\0'; c++)
                fputc(*c == '|' ? ' ' : *c, out);
            fputs("' ;;\n", out);
        } else {
            fprintf(out, ") echo %s ;;\n", kind);
        }
    }
}

/* The shell function: what is offered, given the command (the first
 * word), the flag before the word (or before its '=') and the word. */
static const char completion_function[] =
    "_facet() {\n"
    "    local cur=${COMP_WORDS[COMP_CWORD]} cmd=${COMP_WORDS[1]}\n"
    "    local at=$((COMP_CWORD - 1)) kind=none word head\n"
    "    local i\n"
    "    COMPREPLY=()\n"
    "    if [ \"$COMP_CWORD\" -le 1 ]; then\n"
    "        COMPREPLY=($(compgen -W \"$_facet_commands --help --version\""
    " -- \"$cur\"))\n"
    "        return 0\n"
    "    fi\n"
    "    # --flag=VALUE: bash splits it at '='\n"
    "    if [ \"$cur\" = \"=\" ]; then\n"
    "        cur=\n"
    "    elif [ \"${COMP_WORDS[at]}\" = \"=\" ]; then\n"
    "        at=$((at - 1))\n"
    "    fi\n"
    "    # after \"--\": the options of the command they are passed on to\n"
    "    for ((i = 2; i < COMP_CWORD; i++)); do\n"
    "        if [ \"${COMP_WORDS[i]}\" = -- ]; then\n"
    "            cmd=$(_facet_passes_on \"$cmd\")\n"
    "            break\n"
    "        fi\n"
    "    done\n"
    "    [ \"$at\" -ge 2 ] && kind=$(_facet_value \"$cmd\""
    " \"${COMP_WORDS[at]}\")\n"
    "    case ${kind%% *} in\n"
    "    choice)\n"
    "        COMPREPLY=($(compgen -W \"${kind#choice }\" -- \"$cur\")) ;;\n"
    "    columns)\n"
    "        word=${cur##*,}\n"
    "        head=${cur%\"$word\"}\n"
    "        COMPREPLY=($(compgen -P \"$head\" -W \"$_facet_columns\""
    " -- \"$word\")) ;;\n"
    "    column)\n"
    "        COMPREPLY=($(compgen -W \"$_facet_columns\" -- \"$cur\")) ;;\n"
    "    expression)\n"
    "        word=${cur##*[!A-Za-z0-9_]}\n"
    "        head=${cur%\"$word\"}\n"
    "        # one reply a line: the expression before holds blanks\n"
    "        mapfile -t COMPREPLY < <(compgen -P \"$head\""
    " -W \"$_facet_columns $_facet_where_words\" -- \"$word\") ;;\n"
    "    folder)\n"
    "        COMPREPLY=($(compgen -d -- \"$cur\")) ;;\n"
    "    value) ;;\n"
    "    *)\n"
    "        if [[ $cur == -* ]]; then\n"
    "            COMPREPLY=($(compgen -W \"$(_facet_flags \"$cmd\") --help\""
    " -- \"$cur\"))\n"
    "        elif [ \"$cmd\" = help ]; then\n"
    "            COMPREPLY=($(compgen -W \"$_facet_commands\" -- \"$cur\"))\n"
    "        fi ;;\n"
    "    esac\n"
    "    return 0\n"
    "}\n"
    "complete -o default -F _facet facet\n";

static void write_bash(FILE *out)
{
    fputs("# bash completion for facet(1), written by `facet help "
          "--completion bash`\n# from the tables that facet --help prints "
          "and --sort and --where read.\n\n", out);
    fputs("_facet_commands='", out);
    for (int i = 0; command_table[i] != NULL; i++)
        fprintf(out, "%s%s", i ? " " : "", command_table[i]->name);
    fputs("'\n_facet_columns='", out);
    for (int k = 0; k < OPTION_QUANTITIES; k++)
        fprintf(out, "%s%s", k ? " " : "", option_quantities[k].name);
    fputs("'\n_facet_where_words='", out);
    for (size_t k = 0; filter_word(k) != NULL; k++)
        fprintf(out, "%s%s", k ? " " : "", filter_word(k));
    fputs("'\n\n# _facet_flags COMMAND: its flags\n"
          "_facet_flags() {\n    case $1 in\n", out);
    for (int i = 0; command_table[i] != NULL; i++) {
        const struct command *cmd = command_table[i];
        fprintf(out, "    %s) echo '", cmd->name);
        write_flags(out, cmd->options);
        write_flags(out, cmd->shared);
        fputs(" ' ;;\n", out);
    }
    fputs("    esac\n}\n\n"
          "# _facet_value COMMAND FLAG: what FLAG's value is (columns, "
          "column,\n# expression, folder, value), none for a flag without "
          "one\n"
          "_facet_value() {\n    case \"$1 $2\" in\n", out);
    for (int i = 0; command_table[i] != NULL; i++) {
        write_values(out, command_table[i]->name, command_table[i]->options);
        write_values(out, command_table[i]->name, command_table[i]->shared);
    }
    fputs("    *) echo none ;;\n    esac\n}\n\n"
          "# _facet_passes_on COMMAND: the command whose options follow "
          "\"--\" in it\n"
          "_facet_passes_on() {\n    case $1 in\n", out);
    for (int i = 0; command_table[i] != NULL; i++)
        if (command_table[i]->passes_on != NULL)
            fprintf(out, "    %s) echo %s ;;\n", command_table[i]->name,
                    command_table[i]->passes_on->name);
    fputs("    esac\n}\n\n", out);
    fputs(completion_function, out);
}

int completion_write(FILE *out, const char *shell, struct facet_error *err)
{
    if (strcmp(shell, "bash") != 0)
        return facet_error_set(err, FACET_EINPUT,
            "help: --completion: no completion for '%s' (bash is the one "
            "there is)", shell);
    write_bash(out);
    return FACET_OK;
}
