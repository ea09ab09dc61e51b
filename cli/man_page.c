/*
 * man_page.c: facet(1) in roff, from the tables --help prints.
 */
#include "man_page.h"

#include <string.h>

#include "args.h"
#include "command.h"

/* Writes the n bytes at text as roff text: '\' and '-' escaped, and a
 * line that would start with a control character ('.' or '\'') guarded
 * with \&. at_line_start: whether out is at the start of a line. */
static void roff_bytes(FILE *out, const char *text, size_t n,
                       int at_line_start)
{
    for (size_t i = 0; i < n; i++) {
        char c = text[i];
        if (at_line_start && (c == '.' || c == '\''))
            fputs("\\&", out);
        if (c == '\\')
            fputs("\\e", out);
        else if (c == '-')
            fputs("\\-", out);
        else
            fputc(c, out);
        at_line_start = c == '\n';
    }
}

static void roff_text(FILE *out, const char *text)
{
    roff_bytes(out, text, strlen(text), 1);
}

/* Lines already laid out for a terminal (a usage's second line, the
 * arguments before the options, the examples after them), kept as they
 * are: no filling, no adjusting. */
static void roff_lines(FILE *out, const char *lines)
{
    if (lines[0] == '\0')
        return;
    fputs(".PP\n.nf\n", out);
    roff_text(out, lines);
    if (lines[strlen(lines) - 1] != '\n')
        fputc('\n', out);
    fputs(".fi\n", out);
}

/* One spelling of an option, as args_print_help writes it ("--name
 * VALUE, -a VALUE"), bold names and italic values. */
static void roff_option_names(FILE *out, const struct arg_option *o,
                              int first)
{
    const char *value = o->kind != ARG_FLAG ? o->value : NULL;
    fputs(first ? "\\fB" : ", \\fB", out);
    roff_text(out, "--");
    roff_text(out, o->name);
    fputs("\\fR", out);
    if (value != NULL) {
        fputs(" \\fI", out);
        roff_text(out, value);
        fputs("\\fR", out);
    }
    if (o->alias != 0) {
        fprintf(out, ", \\fB\\-%c\\fR", o->alias);
        if (value != NULL) {
            fputs(" \\fI", out);
            roff_text(out, value);
            fputs("\\fR", out);
        }
    }
}

/* A tagged paragraph per entry of options, as args_print_help prints a
 * line per entry: its spellings, then its help and default. */
static void roff_options(FILE *out, const struct arg_option *options)
{
    for (const struct arg_option *o = options; o->name != NULL; o++) {
        if (o->help == NULL)
            continue;
        fputs(".TP\n", out);
        roff_option_names(out, o, 1);
        for (const struct arg_option *other = o + 1;
             other->name != NULL && other->help == NULL; other++)
            roff_option_names(out, other, 0);
        fputc('\n', out);
        roff_text(out, o->help);
        if (o->default_text != NULL) {
            char shown[256] = "";
            o->default_text(shown, sizeof shown);
            if (shown[0] != '\0') {
                roff_text(out, " (default ");
                roff_text(out, shown);
                fputc(')', out);
            }
        }
        fputc('\n', out);
    }
}

static void roff_command(FILE *out, const struct command *cmd)
{
    fputs(".SS ", out);
    roff_text(out, cmd->name);
    fputs("\n.nf\n\\fBfacet ", out);
    roff_text(out, cmd->name);
    fputs("\\fR ", out);
    roff_bytes(out, cmd->usage, strlen(cmd->usage), 0);
    fputs("\n.fi\n.PP\n", out);
    roff_text(out, cmd->summary);
    fputc('\n', out);
    roff_lines(out, cmd->before);
    if (cmd->options != NULL || cmd->shared != NULL)
        fputs(".PP\nOptions:\n", out);
    if (cmd->options != NULL)
        roff_options(out, cmd->options);
    if (cmd->shared != NULL)
        roff_options(out, cmd->shared);
    roff_lines(out, cmd->after);
}

void man_page_write(FILE *out)
{
    fputs(".\\\" facet(1), written by `facet help --man` from the tables "
          "that --help prints.\n", out);
    fputs(".TH FACET 1 \"\" \"facet " FACET_VERSION "\" \"User Commands\"\n"
          /* no hyphenation, no adjusting: a flag or a column name in
           * the text reads as typed */
          ".nh\n.ad l\n"
          ".SH NAME\n"
          "facet \\- rationalize free\\-form surfaces into flat, single\\- "
          "and double\\-curved panels\n"
          ".SH SYNOPSIS\n"
          ".B facet\n.I COMMAND\n.RI [ ARGS ]\n.br\n"
          ".B facet\n.I COMMAND\n.B \\-\\-help\n.br\n"
          ".B facet help\n.RI [ COMMAND ]\n.br\n"
          ".B facet \\-\\-version\n"
          ".SH DESCRIPTION\n", out);
    roff_text(out, command_program_summary);
    fputs("\n.PP\nThe commands, each with its usage and options:\n", out);
    for (int i = 0; command_table[i] != NULL; i++) {
        fputs(".TP\n.B ", out);
        roff_text(out, command_table[i]->name);
        fputc('\n', out);
        roff_text(out, command_table[i]->summary);
        fputc('\n', out);
    }
    fputs(".SH COMMANDS\n", out);
    for (int i = 0; command_table[i] != NULL; i++)
        roff_command(out, command_table[i]);
    fputs(".SH EXIT STATUS\n", out);
    roff_text(out, command_exit_status);
    fputs("\nEvery error is one line on standard error.\n"
          ".SH SEE ALSO\n"
          "\\fBsqlite3\\fR(1), which reads the result store as it is. "
          "Facet's README.md and docs/manual.md, beside its sources.\n",
          out);
}
