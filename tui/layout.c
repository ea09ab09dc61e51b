/*
 * layout.c: titles, the function-key bar, the help page and click targets
 * fitted to the screen. See layout.h.
 */
#include "layout.h"

#include <stdio.h>
#include <string.h>

int tui_text_width(const char *text)
{
    int n = 0;
    for (const unsigned char *p = (const unsigned char *)text; *p; p++)
        if ((*p & 0xc0) != 0x80)
            n++;
    return n;
}

static int fields_width(const struct tui_field *fields, const int *keep,
                        int n)
{
    int w = 0, first = 1;
    for (int k = 0; k < n; k++) {
        if (!keep[k])
            continue;
        if (!first)
            w += tui_text_width(fields[k].sep);
        w += tui_text_width(fields[k].text);
        first = 0;
    }
    return w;
}

int tui_fit_fields(char *out, size_t size, int width,
                   const struct tui_field *fields, int n)
{
    int keep[32];
    if (n > 32)
        n = 32;
    for (int k = 0; k < n; k++)
        keep[k] = fields[k].text != NULL && fields[k].text[0] != '\0';
    while (fields_width(fields, keep, n) > width) {
        int worst = -1;
        for (int k = 0; k < n; k++)
            if (keep[k] && fields[k].drop > 0 &&
                (worst < 0 || fields[k].drop >= fields[worst].drop))
                worst = k;
        if (worst < 0)
            break;
        keep[worst] = 0;
    }
    size_t len = 0;
    int first = 1;
    out[0] = '\0';
    for (int k = 0; k < n && len < size; k++) {
        if (!keep[k])
            continue;
        len += (size_t)snprintf(out + len, size - len, "%s%s",
                                first ? "" : fields[k].sep, fields[k].text);
        first = 0;
    }
    return tui_text_width(out);
}

/* The bar's width with labels at most cap columns, each padded to pad. */
static int bar_width(const char *const labels[10], int cap, int pad,
                     int x[10], int label_width[10])
{
    int at = 0;
    for (int k = 0; k < 10; k++) {
        x[k] = -1;
        label_width[k] = 0;
        if (labels[k] == NULL || labels[k][0] == '\0')
            continue;
        int w = tui_text_width(labels[k]);
        if (w > cap)
            w = cap;
        if (w < pad)
            w = pad;
        x[k] = at;
        label_width[k] = w;
        at += (k == 9 ? 3 : 2) + w + 1;
    }
    return at > 0 ? at - 1 : 0;  /* no blank needed after the last */
}

int tui_fkey_layout(const char *const labels[10], int width, int x[10],
                    int label_width[10])
{
    int w = bar_width(labels, 8, 6, x, label_width);
    if (w <= width)
        return w;
    for (int cap = 8; cap >= 1; cap--) {
        w = bar_width(labels, cap, 0, x, label_width);
        if (w <= width)
            return w;
    }
    return w;
}

int tui_fkey_at(const int x_of[10], const int label_width[10], int x)
{
    for (int k = 0; k < 10; k++)
        if (x_of[k] >= 0 && x >= x_of[k] &&
            x < x_of[k] + (k == 9 ? 3 : 2) + label_width[k])
            return k + 1;
    return 0;
}

void tui_help_layout(int lines, int height, int width, int entry_width,
                     int top, struct tui_help_page *out)
{
    int per_page = height - 3;  /* title, blank, and a line for "more" */
    if (per_page < 1)
        per_page = 1;
    int columns = 1;
    if (lines > per_page && width >= 2 * entry_width + 3)
        columns = 2;
    int shown = per_page * columns;
    int max_top = lines > shown ? lines - shown : 0;
    if (top > max_top)
        top = max_top;
    if (top < 0)
        top = 0;
    out->columns = columns;
    out->per_page = per_page;
    out->top = top;
    out->pages = (lines + shown - 1) / (shown > 0 ? shown : 1);
}

int tui_column_at(const int *widths, int n, int x)
{
    int at = 0;
    for (int k = 0; k < n; k++) {
        if (x >= at && x < at + widths[k])
            return k;
        at += widths[k] + 1;
    }
    return -1;
}
