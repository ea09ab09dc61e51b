/*
 * format.h: how the workbench writes numbers: fixed decimals, thousands
 * separators, durations, and the option columns of its tables with their
 * titles, units and widths. Pure text, no curses: the unit tests pin it.
 */
#ifndef FACET_TUI_FORMAT_H
#define FACET_TUI_FORMAT_H

#include <stddef.h>

#include "store/store.h"

/* value with decimals places and thousands separators ("1,551,317.25");
 * "-" for NaN, "inf"/"-inf" for infinities. */
void tui_fmt_number(char *out, size_t size, double value, int decimals,
                    int thousands);

/* A duration in seconds as "0.05 s", "12.3 s", "4m05s", "2h03m". */
void tui_fmt_elapsed(char *out, size_t size, double seconds);

/* An ISO 8601 UTC time "2026-11-25T01:30:00Z" as "2026-11-25 01:30". */
void tui_fmt_started(char *out, size_t size, const char *iso);

/* How a column of an options table shows. */
enum tui_column_kind { COLUMN_NUMBER, COLUMN_YESNO, COLUMN_PARETO };

struct tui_column {
    const char *column;   /* store_option_columns name it shows and sorts */
    const char *title;    /* header, line 1 */
    const char *unit;     /* header, line 2 ("" for none) */
    int width;            /* characters, right-aligned */
    int decimals;
    int thousands;        /* 1,000 separators */
    enum tui_column_kind kind;
    double scale;         /* shown = stored x scale: a deviation is
                             stored in m and shown in mm (1000), as the
                             threshold it is held to; 1 otherwise */
};

/* The options table's columns: first the ones it shows by default, in
 * order (No., Pareto mark, planarity, DP area, cost, FP area, SP area, U,
 * V, threshold, feasibility, rank: 80 characters), then the ones the
 * column chooser can add (area, panels, DP panels, largest panel, max
 * deviation, P_dist, crowding, generation). */
extern const struct tui_column tui_option_columns[];
extern const int tui_option_column_count;
extern const int tui_option_column_default_count;

/* Every metric of an option with its label, unit and format (the detail
 * pane, compare and the scatter's axes). */
extern const struct tui_column tui_metric_columns[];
extern const int tui_metric_column_count;

/* The column of tui_metric_columns named column, or NULL. */
const struct tui_column *tui_metric_column(const char *column);

/* The cell text of option for c, right-aligned in c->width characters
 * (ASCII only, so width is the display width). pareto_glyph is written
 * for rank 1 in a COLUMN_PARETO cell and is the caller's to place. */
void tui_fmt_cell(char *out, size_t size, const struct tui_column *c,
                  const struct option_row *option);

/* value (as stored, in the store's unit) as column c formats it, in the
 * column's unit (times c->scale), not padded. */
void tui_fmt_value(char *out, size_t size, const struct tui_column *c,
                   double value);

#endif
