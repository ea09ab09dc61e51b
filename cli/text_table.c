/*
 * text_table.c: fitting a table to the terminal. See text_table.h.
 */
#include "text_table.h"

#include <stdlib.h>
#include <string.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include "shown.h"

int text_table_width(FILE *out, int wide)
{
    if (wide)
        return 0;
    struct winsize size;
    if (isatty(fileno(out)) && ioctl(fileno(out), TIOCGWINSZ, &size) == 0 &&
        size.ws_col > 0)
        return size.ws_col;
    const char *columns = getenv("COLUMNS");
    if (columns != NULL && atoi(columns) > 0)
        return atoi(columns);
    return 0;
}

/* The width of the shown columns, one space between each. */
static int shown_width(const struct text_table *t)
{
    int width = 0, n = 0;
    for (int k = 0; k < t->ncolumns; k++)
        if (t->shown[k]) {
            width += t->column[k].width;
            n++;
        }
    return width + (n > 0 ? n - 1 : 0);
}

void text_table_fit(struct text_table *t, int width)
{
    for (int k = 0; k < t->ncolumns; k++)
        t->shown[k] = 1;
    t->dropped = 0;
    t->elastic_width = 0;
    if (width <= 0)
        return;
    /* Drop the lowest-ranked column, the rightmost of equals, until the
     * table fits or only unrankable columns are left. */
    while (shown_width(t) > width) {
        int worst = -1;
        for (int k = 0; k < t->ncolumns; k++)
            if (t->shown[k] && t->column[k].rank > 0 &&
                !t->column[k].elastic &&
                (worst < 0 || t->column[k].rank <= t->column[worst].rank))
                worst = k;
        if (worst < 0)
            break;
        t->shown[worst] = 0;
        t->dropped++;
    }
    const struct text_column *last = &t->column[t->ncolumns - 1];
    if (last->elastic) {
        int room = width - shown_width(t) + last->width;
        t->elastic_width = room > last->width ? room : last->width;
    }
}

/* Writes text in a cell of width (cut to it when cut is set). */
static void cell_out(FILE *out, const char *text, int width, int left,
                     int cut, int last)
{
    int length = (int)strlen(text);
    if (cut && length > width) {
        if (width > 3)
            fprintf(out, "%.*s...", width - 3, text);
        else
            fprintf(out, "%.*s", width, text);
        return;
    }
    if (left && last)
        fputs(text, out);  /* no trailing blanks */
    else if (left)
        fprintf(out, "%-*s", width, text);
    else
        fprintf(out, "%*s", width, text);
}

static void line_out(FILE *out, const struct text_table *t,
                     const char *const *cell)
{
    /* Into memory first, so the line ends without trailing blanks. */
    char *text = NULL;
    size_t length = 0;
    FILE *line = open_memstream(&text, &length);
    if (line == NULL)
        return;
    int first = 1;
    for (int k = 0; k < t->ncolumns; k++) {
        if (!t->shown[k])
            continue;
        if (!first)
            fputc(' ', line);
        first = 0;
        const struct text_column *c = &t->column[k];
        int elastic = c->elastic && k == t->ncolumns - 1;
        int width = elastic && t->elastic_width > 0 ? t->elastic_width
                                                    : c->width;
        cell_out(line, cell[k], width, c->left,
                 elastic && t->elastic_width > 0, k == t->ncolumns - 1);
    }
    fclose(line);
    while (length > 0 && text[length - 1] == ' ')
        length--;
    /* Cells hold stored names, paths and times: shown, not obeyed. A cut
     * inside a character shows as '?' too. */
    text[length] = '\0';
    shown_text(out, text);
    fputc('\n', out);
    free(text);
}

void text_table_head(FILE *out, const struct text_table *t)
{
    const char *head[TEXT_TABLE_MAX_COLUMNS] = {0};
    const char *unit[TEXT_TABLE_MAX_COLUMNS] = {0};
    int units = 0;
    for (int k = 0; k < t->ncolumns && k < TEXT_TABLE_MAX_COLUMNS; k++) {
        head[k] = t->column[k].head;
        unit[k] = t->column[k].unit;
        units |= t->shown[k] && unit[k][0] != '\0';
    }
    line_out(out, t, head);
    if (units)
        line_out(out, t, unit);
}

void text_table_row(FILE *out, const struct text_table *t,
                    const char *const *cell)
{
    line_out(out, t, cell);
}

void text_table_foot(FILE *out, const struct text_table *t)
{
    if (t->dropped > 0)
        fprintf(out, "(%d column%s left out to fit %s; --wide shows every "
                "column)\n", t->dropped, t->dropped == 1 ? "" : "s",
                "the terminal");
}

void text_wrap(FILE *out, const char *text, int width)
{
    /* Each line cleaned (shown.h): the text can quote a stored warning,
     * and a newline in it would forge a line. */
    const char *line = text;
    int room = width;
    while (width > 20 && (int)strlen(line) > room) {
        const char *cut = line + room;
        while (cut > line && *cut != ' ')
            cut--;
        if (cut == line)  /* one word longer than the line: keep it whole */
            cut = strchr(line + room, ' ');
        if (cut == NULL)
            break;
        shown_line(out, "%.*s", (int)(cut - line), line);
        fputs("  ", out);
        line = cut + 1;
        room = width - 2;
    }
    shown_line(out, "%s", line);
}
