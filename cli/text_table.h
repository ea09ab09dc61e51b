/*
 * text_table.h: the human tables of the CLI (runs, options, a run's
 * Table 2), fitted to the terminal.
 *
 * A table is a list of columns, each with a heading, a unit line, a width,
 * an alignment and a rank: when the table is wider than the terminal, the
 * columns of the lowest rank go first, and the last column, when it is
 * the elastic kind (a name or a path), is cut to what is left, with "...".
 * --wide prints every column in full. Output that is not a terminal (a
 * pipe, a file) is not cut unless COLUMNS says how wide it is.
 */
#ifndef FACET_TEXT_TABLE_H
#define FACET_TEXT_TABLE_H

#include <stdio.h>

#define TEXT_TABLE_MAX_COLUMNS 24

struct text_column {
    const char *head;     /* heading */
    const char *unit;     /* second heading line ("m^2"), or "" */
    int width;            /* characters (the elastic column: its least) */
    int left;             /* 1: left-aligned; else right-aligned */
    int rank;             /* higher stays longer; 0: never dropped */
    int elastic;          /* the last column only: cut, never dropped */
};

struct text_table {
    const struct text_column *column;
    int ncolumns;
    int shown[TEXT_TABLE_MAX_COLUMNS];  /* set by text_table_fit */
    int elastic_width;                  /* what the elastic column gets,
                                           0 for no limit */
    int dropped;                        /* columns left out */
};

/* The width to fit: the terminal's (stdout a terminal), else COLUMNS when
 * set, else 0 (no limit); 0 too when wide is set. */
int text_table_width(FILE *out, int wide);

/* Chooses the columns of t (ncolumns <= TEXT_TABLE_MAX_COLUMNS) that fit
 * width (0: all). */
void text_table_fit(struct text_table *t, int width);

/* The two heading lines. */
void text_table_head(FILE *out, const struct text_table *t);

/* One row of cells, one per column (shown or not). */
void text_table_row(FILE *out, const struct text_table *t,
                    const char *const *cell);

/* "(2 columns left out: --wide shows them)" when some were, else nothing. */
void text_table_foot(FILE *out, const struct text_table *t);

/* Writes text, broken at spaces into lines of at most width characters
 * (0: one line), the lines after the first indented by two. */
void text_wrap(FILE *out, const char *text, int width);

#endif
