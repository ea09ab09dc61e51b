/*
 * format.h: how the workbench writes numbers: fixed decimals, thousands
 * separators, durations, and which option columns its tables show, in
 * what width (the columns' titles, units and formats are the registry's:
 * core/quantity/quantity.h). Pure text, no curses: the unit tests pin it.
 */
#ifndef FACET_TUI_FORMAT_H
#define FACET_TUI_FORMAT_H

#include <stddef.h>

#include "core/quantity/quantity.h"
#include "store/store.h"

/* value with decimals places and thousands separators ("1,551,317.25");
 * "-" for NaN, "inf"/"-inf" for infinities: quantity_number_text. */
void tui_fmt_number(char *out, size_t size, double value, int decimals,
                    int thousands);

/* A duration in seconds as "0.05 s", "12.3 s", "4m05s", "2h03m". */
void tui_fmt_elapsed(char *out, size_t size, double seconds);

/* An ISO 8601 UTC time "2026-11-25T01:30:00Z" as "2026-11-25 01:30". */
void tui_fmt_started(char *out, size_t size, const char *iso);

/* A column of the options list: a column of the registry
 * (core/quantity/quantity.h), which says its heading, unit and format, in
 * width characters; or the Pareto mark. */
struct tui_column {
    const char *column;   /* option_quantities name it shows and sorts */
    int width;            /* characters, right-aligned */
    int pareto_mark;      /* 1: rank 1 as a glyph the caller draws ("P") */
};

/* The options list's columns: first the ones it shows by default, in
 * order (No., Pareto mark, planarity, DP area, cost, FP area, SP area, U,
 * V, threshold, feasibility, rank: 80 characters), then the ones the
 * column chooser can add (area, panels, DP panels, largest panel, max
 * deviation, P_dist, crowding, generation). */
extern const struct tui_column tui_option_columns[];
extern const int tui_option_column_count;
extern const int tui_option_column_default_count;

/* c's registry column. */
const struct quantity *tui_column_of(const struct tui_column *c);

/* The header of c: its registry heading ("P" for the mark), and unit. */
const char *tui_column_title(const struct tui_column *c);
const char *tui_column_unit(const struct tui_column *c);

/* The metrics of an option the detail pane and compare list, in order:
 * names of option_quantities. */
extern const char *const tui_metric_columns[];
extern const int tui_metric_column_count;

/* The cell text of option for c, right-aligned in c->width characters
 * (ASCII only, so width is the display width), with the column's
 * list_decimals; an unranked rank is "-". The mark column is blank: the
 * caller draws its glyph for rank 1. */
/* The column shown in c's place for option: c itself, but for a
 * project's option the module (module_w, module_h) where nu and nv stand,
 * since they index the run's module range, a count of nothing on the
 * building. */
const struct quantity *tui_shown_column(const struct quantity *c,
                                             const struct option_row *option);

void tui_fmt_cell(char *out, size_t size, const struct tui_column *c,
                  const struct option_row *option);

/* The cost of totals as a sum whose shown terms add up to the shown
 * total, in at most width characters: by panel type and the terms beyond
 * area ("cost 2,675,520 USD = FP 270,401 + SP 314,018 + DP 616,566 +
 * panels 28,800 + joints 65,456 + moulds 1,380,000"), or else with the
 * area's types as one term ("= area 1,200,985 + panels ..."), or else
 * the cost alone ("cost 2,675,520 USD"). A term that is 0 or not measured
 * adds nothing and is left out. Each term is rounded to the dollar so
 * that the terms add up to the rounded total: down, and then up by a
 * dollar for the terms with the largest remainders (largest remainder
 * rounding), so that no term shown is a dollar off its value or more. */
void tui_fmt_cost_sum(char *out, size_t size, const struct option_totals *t,
                      int width);

/* Which limits of run an infeasible option's totals t break, in short
 * words into out: "panel 2.05 m^2 > 1.92 m^2 limit, 3 gaps > 2 mm
 * limit"; "over a limit" when the totals do not say which. */
void tui_fmt_violation(char *out, size_t size, const struct option_totals *t,
                       const struct run_info *run);

/* A crowding distance in words where it has no number: "boundary" for
 * an end of a front (infinite); NULL when the number says it. */
const char *tui_crowding_words(double crowding);

/* fields[0 .. n) joined by " | " into out, in at most width display
 * characters (UTF-8 counted as characters): whole fields dropped from the
 * end until the rest fits, so that no number loses its unit and no word
 * is cut; only the first field, a title, is cut when even it alone is too
 * wide. */
void tui_fmt_fields(char *out, size_t size, int width,
                    const char *const *fields, int n);

/* tui_fmt_fields with other separators: lead between fields[0] and
 * fields[1], sep between the rest ("16 panels: FP 4, SP 0, DP 12"). */
void tui_fmt_list(char *out, size_t size, int width,
                  const char *const *fields, int n, const char *lead,
                  const char *sep);

/* option's design grid in words: "37 x 49" panels, or a project's module
 * "module 2.40 x 1.80 m" (its nu and nv only index the module range). */
void tui_fmt_grid(char *out, size_t size, const struct option_row *option);

/* value (as stored, in the store's unit) as column c shows it on its own
 * (quantity_text with c->decimals), not padded. */
void tui_fmt_value(char *out, size_t size, const struct quantity *c,
                   double value);

#endif
