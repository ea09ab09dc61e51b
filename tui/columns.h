/*
 * columns.h: which columns of the options table show, and in what order
 * (the column chooser), as a list of tui_option_columns indexes with a
 * shown flag each. The workbench keeps one for the session (app.h), so
 * every options table opened after a change shows the same columns. No
 * curses here.
 */
#ifndef FACET_TUI_COLUMNS_H
#define FACET_TUI_COLUMNS_H

#define TUI_COLUMNS_MAX 32

struct tui_column_set {
    int n;                          /* = tui_option_column_count */
    int order[TUI_COLUMNS_MAX];     /* tui_option_columns indexes */
    unsigned char shown[TUI_COLUMNS_MAX];  /* shown[k]: order[k] shows */
};

/* Every column in tui_option_columns order, the first
 * tui_option_column_default_count shown. */
void tui_columns_default(struct tui_column_set *set);

/* Writes the tui_option_columns indexes of the shown columns, in order,
 * into out (room for TUI_COLUMNS_MAX) and returns how many. */
int tui_columns_visible(const struct tui_column_set *set, int *out);

/* Shows or hides the column at position (0..n-1) of the order. Hiding
 * the last shown column is refused: returns -1, else 0. */
int tui_columns_toggle(struct tui_column_set *set, int position);

/* Moves the column at position by delta places (clamped to the list) and
 * returns its new position. */
int tui_columns_move(struct tui_column_set *set, int position, int delta);

/* Characters the shown columns take with one blank between them. */
int tui_columns_width(const struct tui_column_set *set);

#endif
