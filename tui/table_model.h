/*
 * table_model.h: the options of one run as a table that a screen scrolls:
 * filter, Pareto-only, sort keys, a count, a selected position, and a
 * window of cached rows around what is shown. Rows come from the store a
 * page at a time (store_browse_*), never all at once, so a run of a
 * million options opens, sorts, filters and scrolls at page speed. No
 * curses here: the table, scatter and compare screens share one model,
 * which is how their selection and filter stay linked.
 */
#ifndef FACET_TUI_TABLE_MODEL_H
#define FACET_TUI_TABLE_MODEL_H

#include <stddef.h>
#include <stdint.h>

#include "store/filter.h"
#include "store/store.h"

/* Rows the window holds at most, and rows one fetch adds. */
#define TABLE_WINDOW 600
#define TABLE_PAGE 200

/* A count stops here until it is needed exactly ("2,000+"); a selected
 * option deeper than TABLE_POSITION_CAP rows in a new order is placed at
 * that row (positions become estimates: lower bounds); a filter that
 * passes at most TABLE_FILTER_FIRST options is read by the filter's own
 * index or a scan and sorted, not by walking the order's index. */
#define TABLE_COUNT_CAP 2000
/* Options one step of a count looks at, one step a tick while no key
 * comes (table_model_count_step): about 50 ms a step, counting and
 * keeping the last page of a filter, so a key waits no longer. */
#define TABLE_COUNT_STEP 100000
#define TABLE_POSITION_CAP 2000
#define TABLE_FILTER_FIRST 2000

/* Options a table can hold marked (for Compare and export). */
#define TABLE_MARKS_MAX 64

struct table_model {
    struct store *store;          /* borrowed */
    struct option_browse browse;  /* run, Pareto-only, filter, keys */
    struct run_info run;          /* the run, read by table_model_open and
                                     again only by table_model_read_run:
                                     the screens on this model take it
                                     from here, never from the store */
    int project;                  /* the run is a building's: its options'
                                     module and grids are the project's
                                     (store_run_is_project) */
    struct filter *filter;        /* owned; browse.where points to it */
    char key_names[BROWSE_MAX_KEYS][32];  /* browse.keys[k].column */
    int64_t count;                /* options the browse sees; when
                                     count_exact is 0, a lower bound that
                                     grows as the table is scrolled */
    int count_exact;              /* count is the exact count */
    int estimated;                /* positions are lower bounds (a deep
                                     option kept across a re-sort, or the
                                     last page read before the count) */
    int at_end;                   /* rows[nrows - 1] is the table's last
                                     row */
    int64_t count_from, count_sofar;  /* table_model_count_step's place */
    struct browse_tail tail;      /* with a filter, the last page as the
                                     count's steps find it */
    int tail_ready;               /* tail is the table's last page */
    int64_t selected;             /* position of the selected row, or 0 */
    int64_t base;                 /* position of rows[0] */
    struct option_row *rows;      /* rows[0..nrows): window */
    int64_t nrows;
    int64_t fetches;              /* store queries made (tests, bench) */
    int64_t marks[TABLE_MARKS_MAX];  /* marked option numbers, in the
                                        order marked: the table's and the
                                        scatter's, one set */
    int nmarks;
};

/* Opens the model on run of store (by number, no filter) with the
 * selection on the first row. Release with table_model_close. */
int table_model_open(struct table_model *m, struct store *store,
                     int64_t run, struct facet_error *err);
/* The same, sorted by keys (n of them, as table_model_set_sort takes
 * them; 0: by number) from the start: the first row of that order is
 * selected, and no option is looked for in it, where opening by number
 * and then sorting keeps option 1 selected and counts the options before
 * it in the new order (300 ms on 300,000 options). */
int table_model_open_sorted(struct table_model *m, struct store *store,
                            int64_t run, const struct browse_key *keys,
                            int n, struct facet_error *err);
void table_model_close(struct table_model *m);

/* The row at position, when the window holds it; NULL otherwise (call
 * table_model_fetch first). */
const struct option_row *table_model_row(const struct table_model *m,
                                         int64_t position);

/* The selected row, or NULL when the table is empty. */
const struct option_row *table_model_selection(const struct table_model *m);

/* Makes the window hold positions [from, from + n) (clamped to the
 * table), by keyset pages next to what it holds, else from either end,
 * else by offset. */
int table_model_fetch(struct table_model *m, int64_t from, int64_t n,
                      struct facet_error *err);

/* Moves the selection to position (clamped) and fetches around it. While
 * the count is a lower bound, a position at or past the last row known
 * counts further (TABLE_COUNT_CAP more), except a far jump to exactly
 * count - 1 (the last row: End, G), which is table_model_select_last. */
int table_model_select(struct table_model *m, int64_t position,
                       struct facet_error *err);

/* Selects the last row (End, G). Without a filter the count is made exact
 * first (the run's index, 35 ms a million options). With one, counting
 * reads every row: the last page is read by itself instead, placed after
 * the rows known with positions that are lower bounds ("row 2,200+ of
 * 2,200+"), numbered exactly from the count when the steps between keys
 * (table_model_count_step) or table_model_count_exact finish it. */
int table_model_select_last(struct table_model *m, struct facet_error *err);

/* Selects the first row of the order, exactly: the window is read again
 * from the start (positions kept as estimates are dropped), as a new
 * sort shows its top. */
int table_model_select_first(struct table_model *m, struct facet_error *err);

/* Moves the selection to option number when the table shows it; *found
 * tells whether it does (the selection stays otherwise). */
int table_model_select_number(struct table_model *m, int64_t number,
                              int *found, struct facet_error *err);

/* Replaces the filter with text compiled by filter_compile. A bad text is
 * FACET_EINPUT with filter_compile's message and leaves the model as it
 * was. The selected option stays selected when the new filter shows it. */
int table_model_set_filter(struct table_model *m, const char *text,
                           struct facet_error *err);

/* Shows only rank 1 (on) or every option (off); keeps the selection as
 * set_filter does. */
int table_model_set_pareto(struct table_model *m, int on,
                           struct facet_error *err);

/* Sorted (keys given), puts every feasible option before every other
 * one (on, as the model opens: the ranks do so too) or sorts by the keys
 * alone (off); keeps the selection as set_filter does. */
int table_model_set_feasible_first(struct table_model *m, int on,
                                   struct facet_error *err);

/* Sorts by keys[0..n) (then number); keeps the selected option selected.
 * Unknown columns are FACET_EINPUT and leave the model as it was. */
int table_model_set_sort(struct table_model *m, const struct browse_key *keys,
                         int n, struct facet_error *err);

/* Counts again and refetches (options were added by a live run, or
 * ranks written), keeping the selected option selected. */
int table_model_refresh(struct table_model *m, struct facet_error *err);

/* Reads m->run again from the store (a live run's status, counts, knee);
 * on an error m->run is as it was. */
int table_model_read_run(struct table_model *m, struct facet_error *err);

/* The count as a table shows it: "1,234" or, while it is a lower bound,
 * "2,000+". */
void table_model_count_text(const struct table_model *m, char *out,
                            size_t size);

/* Where the selection is, as a table shows it: "row 12 of 336", "row 12
 * of 2,000+" while the count is a lower bound, "row 2,001+ of 9,000" while
 * positions are (after a re-sort kept a deep option). */
void table_model_position_text(const struct table_model *m, char *out,
                               size_t size);

/* Counts exactly now (reads every option of the run with a filter, the
 * run's index without one). */
int table_model_count_exact(struct table_model *m, struct facet_error *err);

/* One bounded step of an exact count (at most rows options looked at),
 * for a screen to call between keystrokes: *exact becomes 1 when the
 * count is exact (then every later step says so at once, and estimated
 * positions have been made exact), 0 when more steps are needed. Returns
 * FACET_OK, or FACET_E* with err filled (*exact is then 0). */
int table_model_count_step(struct table_model *m, int64_t rows, int *exact,
                           struct facet_error *err);

/* Whether option number is marked. */
int table_model_marked(const struct table_model *m, int64_t number);

/* Marks option number (on non-zero) or unmarks it. Returns FACET_OK, or
 * FACET_EINPUT ("at most TABLE_MARKS_MAX marks") when the marks are full
 * and it could not be marked. */
int table_model_set_mark(struct table_model *m, int64_t number, int on,
                         struct facet_error *err);

/* Whether option passes the model's filter and Pareto-only setting. */
int table_model_shows(const struct table_model *m,
                      const struct option_row *option);

/* The first row to show so that the selection is visible in a view of
 * height rows that showed top before: the view scrolls only as far as it
 * must. */
int64_t table_model_scroll(int64_t top, int64_t selected, int64_t height,
                           int64_t count);

#endif
