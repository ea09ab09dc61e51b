/*
 * layout.h: what fits on the screen, worked out without curses so that
 * the unit tests pin it: a title of fields that drops the least needed
 * ones rather than cutting a number ("knee 3" for knee 324), the
 * function-key bar with a blank after every label, the help overlay's
 * page, and which table column or row a mouse click falls on. Widths are
 * in columns, one per UTF-8 code point (as tui_put counts them).
 */
#ifndef FACET_TUI_LAYOUT_H
#define FACET_TUI_LAYOUT_H

#include <stddef.h>

/* The columns text takes: its UTF-8 code points. */
int tui_text_width(const char *text);

/* One field of a title: sep (" | ", " ", or "" for the first) then text.
 * drop: 0 never dropped; a larger number is dropped earlier. */
struct tui_field {
    const char *sep;
    const char *text;
    int drop;
};

/* Joins fields[0..n) into out, leaving out whole fields, the highest
 * drop first (the later of equals first), until the rest fits width. A
 * title whose undroppable fields do not fit is written whole, to be cut
 * at the screen's edge. Returns the width of out. */
int tui_fit_fields(char *out, size_t size, int width,
                   const struct tui_field *fields, int n);

/* The function-key bar: labels[k] is F(k+1)'s, NULL or "" for a key the
 * screen does not use (not drawn). Each used key takes "Fn", its label
 * and one blank (htop's bar, with the labels apart): labels padded to six
 * columns when that fits width, else at their own length (at most 8),
 * else cut to the longest length that fits. x[k] is where "Fn" starts (-1: not drawn)
 * and label_width[k] the columns of the label field. Returns the columns
 * the bar takes. */
int tui_fkey_layout(const char *const labels[10], int width, int x[10],
                    int label_width[10]);

/* The function key (1..10) whose field holds column x of the bar laid out
 * by tui_fkey_layout, or 0. */
int tui_fkey_at(const int x_of[10], const int label_width[10], int x);

/* The help overlay: lines of text in a box of height rows (title and a
 * blank included) and width columns. columns (1 or 2) side by side when
 * the screen is wide enough to hold two of entry_width and the lines do
 * not fit one; per_page lines shown at once (per column); top clamped so
 * the last page is full. */
struct tui_help_page {
    int columns, per_page, top, pages;
};
void tui_help_layout(int lines, int height, int width, int entry_width,
                     int top, struct tui_help_page *out);

/* The index of the table column under screen column x, for columns of
 * widths[0..n) drawn from column 0 with one blank between them, or -1
 * (a blank, or past the last). */
int tui_column_at(const int *widths, int n, int x);

#endif
