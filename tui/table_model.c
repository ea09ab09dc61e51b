/*
 * table_model.c: a paged, sorted, filtered view of one run's options. See
 * table_model.h.
 *
 * Nothing here reads the whole run unless the user asks for the end of
 * the table: the count is capped (TABLE_COUNT_CAP) and grows as the user
 * scrolls, a kept selection is located with a capped count, and every
 * page comes by keyset from a row held. Positions are exact except after
 * a deep option was kept across a re-sort (m->estimated): then they are
 * lower bounds, corrected when the window reaches either end.
 */
#include "table_model.h"

#include "format.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int table_model_open(struct table_model *m, struct store *store,
                     int64_t run, struct facet_error *err)
{
    return table_model_open_sorted(m, store, run, NULL, 0, err);
}

/* Checks keys and makes them m's order; m is unchanged on an error. */
static int set_keys(struct table_model *m, const struct browse_key *keys,
                    int n, struct facet_error *err)
{
    if (n < 0 || n > BROWSE_MAX_KEYS)
        return facet_error_set(err, FACET_EINPUT, "sort: at most %d keys",
                               BROWSE_MAX_KEYS);
    for (int k = 0; k < n; k++)
        if (keys[k].column == NULL ||
            isnan(option_quantity_value(&(struct option_row){0},
                                     keys[k].column)))
            return facet_error_set(err, FACET_EINPUT,
                "sort: unknown column '%s'",
                keys[k].column ? keys[k].column : "(none)");
    for (int k = 0; k < n; k++) {
        snprintf(m->key_names[k], sizeof m->key_names[k], "%s",
                 keys[k].column);
        m->browse.keys[k].column = m->key_names[k];
        m->browse.keys[k].descending = keys[k].descending;
    }
    m->browse.nkeys = n;
    return FACET_OK;
}

int table_model_open_sorted(struct table_model *m, struct store *store,
                            int64_t run, const struct browse_key *keys,
                            int n, struct facet_error *err)
{
    memset(m, 0, sizeof *m);
    m->store = store;
    m->browse.run = run;
    int rc = store_run_get(store, run, &m->run, err);
    if (rc != FACET_OK)
        return rc;
    m->project = store_run_is_project(&m->run);
    m->browse.feasible_first = 1;
    rc = set_keys(m, keys, n, err);
    if (rc != FACET_OK)
        return rc;
    m->rows = malloc(TABLE_WINDOW * sizeof *m->rows);
    if (m->rows == NULL)
        return facet_error_set(err, FACET_EWORK, "out of memory");
    return table_model_refresh(m, err);
}

void table_model_close(struct table_model *m)
{
    filter_free(m->filter);
    free(m->rows);
    memset(m, 0, sizeof *m);
}

int table_model_marked(const struct table_model *m, int64_t number)
{
    for (int k = 0; k < m->nmarks; k++)
        if (m->marks[k] == number)
            return 1;
    return 0;
}

int table_model_set_mark(struct table_model *m, int64_t number, int on,
                         struct facet_error *err)
{
    for (int k = 0; k < m->nmarks; k++)
        if (m->marks[k] == number) {
            if (!on) {
                memmove(m->marks + k, m->marks + k + 1,
                        (size_t)(m->nmarks - k - 1) * sizeof m->marks[0]);
                m->nmarks--;
            }
            return FACET_OK;
        }
    if (!on)
        return FACET_OK;
    if (m->nmarks == TABLE_MARKS_MAX)
        return facet_error_set(err, FACET_EINPUT, "at most %d marks",
                               TABLE_MARKS_MAX);
    m->marks[m->nmarks++] = number;
    return FACET_OK;
}

const struct option_row *table_model_row(const struct table_model *m,
                                         int64_t position)
{
    if (position < m->base || position >= m->base + m->nrows)
        return NULL;
    return &m->rows[position - m->base];
}

const struct option_row *table_model_selection(const struct table_model *m)
{
    return table_model_row(m, m->selected);
}

/* Rows a fetch collects, in the order the store delivers them. */
struct batch {
    struct option_row rows[TABLE_PAGE];
    int n;
};

static int collect(void *context, const struct option_row *option)
{
    struct batch *b = context;
    b->rows[b->n++] = *option;
    return b->n >= TABLE_PAGE;
}

/* Replaces the window with batch (reversed when backward), at base. */
static void window_set(struct table_model *m, const struct batch *b,
                       int backward, int64_t base)
{
    for (int k = 0; k < b->n; k++)
        m->rows[k] = b->rows[backward ? b->n - 1 - k : k];
    m->nrows = b->n;
    m->base = base;
    m->at_end = 0;
}

/* Appends batch after the window, dropping rows at the front to fit. */
static void window_append(struct table_model *m, const struct batch *b)
{
    int64_t drop = m->nrows + b->n - TABLE_WINDOW;
    if (drop > 0) {
        memmove(m->rows, m->rows + drop,
                (size_t)(m->nrows - drop) * sizeof *m->rows);
        m->nrows -= drop;
        m->base += drop;
    }
    memcpy(m->rows + m->nrows, b->rows, (size_t)b->n * sizeof *b->rows);
    m->nrows += b->n;
}

/* Prepends batch (delivered nearest first) before the window, dropping
 * rows at the back to fit. With estimated positions, renumbers so that
 * positions stay >= 0, and exact once a short batch shows the start. */
static int64_t window_prepend(struct table_model *m, const struct batch *b)
{
    int64_t shift = 0;
    if (m->base - b->n < 0 || (m->estimated && b->n < TABLE_PAGE))
        shift = b->n - m->base;
    if (b->n < TABLE_PAGE)
        m->estimated = 0;  /* rows[0] will be the first row */
    m->base += shift;
    m->selected += shift;
    m->count += shift;
    if (m->count < m->base + m->nrows)
        m->count = m->base + m->nrows;
    int64_t keep = m->nrows;
    if (keep + b->n > TABLE_WINDOW)
        keep = TABLE_WINDOW - b->n;
    if (keep < m->nrows)
        m->at_end = 0;  /* the last rows held are dropped */
    memmove(m->rows + b->n, m->rows, (size_t)keep * sizeof *m->rows);
    for (int k = 0; k < b->n; k++)
        m->rows[b->n - 1 - k] = b->rows[k];
    m->nrows = keep + b->n;
    m->base -= b->n;
    return shift;
}

_Static_assert(TABLE_PAGE <= BROWSE_TAIL,
               "the count's steps keep a whole last page");

/* The last page as the steps of the count kept it (m->tail, the last
 * first), into b. */
static int tail_page(struct table_model *m, struct batch *b,
                     struct facet_error *err)
{
    for (int k = 0; k < m->tail.n && k < TABLE_PAGE; k++) {
        int rc = store_option_get(m->store, m->browse.run,
                                  m->tail.numbers[k], &b->rows[b->n], err);
        if (rc != FACET_OK)
            return rc;
        b->n++;
    }
    return FACET_OK;
}

int table_model_fetch(struct table_model *m, int64_t from, int64_t n,
                      struct facet_error *err)
{
    if (from < 0)
        from = 0;
    if (from + n > m->count)
        n = m->count - from;
    if (n > TABLE_WINDOW - TABLE_PAGE)
        n = TABLE_WINDOW - TABLE_PAGE;
    if (n <= 0)
        return FACET_OK;
    int64_t end = from + n;
    struct batch *b = malloc(sizeof *b);
    if (b == NULL)
        return facet_error_set(err, FACET_EWORK, "out of memory");
    int rc = FACET_OK;
    if (m->estimated && m->nrows > 0 && m->base < TABLE_PAGE &&
        from < m->base + TABLE_PAGE / 4) {
        /* near an estimated start: read what is really before rows[0] */
        b->n = 0;
        m->fetches++;
        rc = store_browse_page(m->store, &m->browse, &m->rows[0], 1,
                               TABLE_PAGE, collect, b, err);
        if (rc == FACET_OK) {
            int64_t shift = window_prepend(m, b);
            from += shift;
            end += shift;
        }
    }
    while (rc == FACET_OK) {
        int64_t have_end = m->base + m->nrows;
        if (m->nrows > 0 && from >= m->base && end <= have_end)
            break;
        b->n = 0;
        m->fetches++;
        if (m->nrows > 0 && from >= m->base && from <= have_end &&
            have_end < m->count) {
            /* next to the end: the page after the last row held */
            rc = store_browse_page(m->store, &m->browse,
                                   &m->rows[m->nrows - 1], 0, TABLE_PAGE,
                                   collect, b, err);
            if (rc == FACET_OK && b->n < TABLE_PAGE && !m->estimated) {
                /* the end of the table: the count is now known */
                m->count = m->base + m->nrows + b->n;
                m->count_exact = 1;
            }
            if (rc == FACET_OK && b->n == 0)
                break;  /* the table shrank under us */
            if (rc == FACET_OK)
                window_append(m, b);
            if (end > m->count)
                end = m->count;
        } else if (m->nrows > 0 && end <= have_end && end >= m->base &&
                   (m->base > 0 || m->estimated)) {
            /* next to the start: the page before the first row held */
            rc = store_browse_page(m->store, &m->browse, &m->rows[0], 1,
                                   TABLE_PAGE, collect, b, err);
            if (rc == FACET_OK && b->n == 0) {
                if (m->estimated)
                    window_prepend(m, b);  /* rows[0] is the first */
                break;
            }
            if (rc == FACET_OK) {
                int64_t shift = window_prepend(m, b);
                from += shift;
                end += shift;
            }
        } else if (m->count_exact && end > m->count - TABLE_PAGE) {
            /* near the end: the last page, read backwards, or as the
             * count's steps found it */
            rc = m->tail_ready ? tail_page(m, b, err)
                               : store_browse_page(m->store, &m->browse,
                                                   NULL, 1, TABLE_PAGE,
                                                   collect, b, err);
            if (rc == FACET_OK) {
                window_set(m, b, 1, m->count - b->n);
                m->estimated = 0;
                m->at_end = 1;
            }
            if (rc == FACET_OK && (b->n == 0 || from >= m->base))
                break;
        } else {
            /* far from both: by offset, once */
            int64_t start = from - TABLE_PAGE / 4 > 0 ? from - TABLE_PAGE / 4
                                                      : 0;
            rc = store_browse_offset(m->store, &m->browse, start, TABLE_PAGE,
                                     collect, b, err);
            if (rc == FACET_OK) {
                window_set(m, b, 0, start);
                m->estimated = 0;
            }
            if (rc == FACET_OK && b->n == 0)
                break;
        }
    }
    free(b);
    return rc;
}

static int window_around(struct table_model *m, const struct option_row *keep,
                         int64_t position, struct facet_error *err);

/* Counts TABLE_COUNT_CAP options past the last row held, so that the
 * count grows as far as the user scrolls. */
static int count_further(struct table_model *m, struct facet_error *err)
{
    if (m->nrows == 0)
        return table_model_fetch(m, m->count - 1, 1, err);
    int64_t more;
    m->fetches++;
    int rc = store_browse_count_capped(m->store, &m->browse,
                                       &m->rows[m->nrows - 1], 0,
                                       TABLE_COUNT_CAP, &more, err);
    if (rc != FACET_OK)
        return rc;
    if (m->base + m->nrows + more > m->count)
        m->count = m->base + m->nrows + more;
    m->count_exact = more < TABLE_COUNT_CAP && !m->estimated;
    return FACET_OK;
}

/* Makes the window the last page of the table while the count is a lower
 * bound, without counting: read backwards from the end, placed just past
 * the rows known, its positions estimates (lower bounds) until the count
 * is exact (table_model_count_step), then numbered from the count. */
static int window_last(struct table_model *m, struct facet_error *err)
{
    struct batch *b = malloc(sizeof *b);
    if (b == NULL)
        return facet_error_set(err, FACET_EWORK, "out of memory");
    b->n = 0;
    m->fetches++;
    int rc = store_browse_page(m->store, &m->browse, NULL, 1, TABLE_PAGE,
                               collect, b, err);
    if (rc == FACET_OK && b->n > 0) {
        int64_t known = m->count > m->base + m->nrows ? m->count
                                                      : m->base + m->nrows;
        window_set(m, b, 1, known > b->n ? known - b->n : 0);
        m->at_end = 1;
        m->estimated = 1;
        m->count = m->base + m->nrows;
        m->selected = m->count - 1;
    }
    free(b);
    return rc;
}

int table_model_select_last(struct table_model *m, struct facet_error *err)
{
    int rc = FACET_OK;
    /* Without a filter the count is the run's index: exact at once.
     * With one it reads every row: left to the steps between keys. */
    if (!m->count_exact && m->browse.where == NULL &&
        !m->browse.pareto_only)
        rc = table_model_count_exact(m, err);
    if (rc != FACET_OK)
        return rc;
    if (m->count_exact || m->count == 0)
        return table_model_select(m, m->count - 1, err);
    return window_last(m, err);
}

int table_model_select(struct table_model *m, int64_t position,
                       struct facet_error *err)
{
    if (!m->count_exact && m->count > 0 && position >= m->count - 1) {
        if (position == m->count - 1 &&
            position - m->selected > TABLE_PAGE)
            return table_model_select_last(m, err);  /* End, G */
        int rc = count_further(m, err);
        if (rc != FACET_OK)
            return rc;
    }
    if (position >= m->count)
        position = m->count - 1;
    if (position < 0)
        position = 0;
    m->selected = position;
    int rc = table_model_fetch(m, position - 60, 121, err);
    if (m->selected >= m->count)  /* the end came nearer than counted */
        m->selected = m->count > 0 ? m->count - 1 : 0;
    return rc;
}

/* The count is exact and the window holds the last rows: its positions
 * (estimates) become exact, numbered back from the count. */
static void rebase_at_end(struct table_model *m)
{
    int64_t shift = m->count - m->nrows - m->base;
    m->base += shift;
    m->selected += shift;
    m->estimated = 0;
}

int table_model_count_exact(struct table_model *m, struct facet_error *err)
{
    if (m->count_exact)
        return FACET_OK;
    int64_t count;
    m->fetches++;
    int rc = store_browse_count(m->store, &m->browse, &count, err);
    if (rc != FACET_OK)
        return rc;
    m->count = count;
    m->count_exact = 1;
    if (m->estimated && m->at_end && m->nrows > 0) {
        rebase_at_end(m);
    } else if (m->estimated) {
        /* the window's numbering is a guess: start again from the top */
        m->estimated = 0;
        m->nrows = 0;
        m->base = 0;
    }
    return FACET_OK;
}

int table_model_count_step(struct table_model *m, int64_t rows, int *exact,
                           struct facet_error *err)
{
    *exact = m->count_exact;
    if (m->count_exact)
        return FACET_OK;
    int done;
    m->fetches++;
    /* with a filter the steps keep the table's last page too: End is
     * then a page read by number (it would read every row again) */
    int gather = m->browse.where != NULL || m->browse.pareto_only;
    int rc = store_browse_count_step(m->store, &m->browse, rows,
                                     &m->count_from, &m->count_sofar, &done,
                                     gather ? &m->tail : NULL, err);
    if (rc != FACET_OK)
        return rc;
    if (!done) {
        if (m->count_sofar > m->count)
            m->count = m->count_sofar;
        return FACET_OK;
    }
    /* The count is exact now, estimated positions or not: stepping on
     * from the end would add the last slice again at every step (a
     * 6,355-option run counted past ten million). Estimated positions are
     * made exact here too, from the selected option's own position. */
    m->count = m->count_sofar;
    m->count_exact = 1;
    m->count_from = m->count_sofar = 0;
    m->tail_ready = gather && m->tail.n == (m->count < TABLE_PAGE
                                                ? m->count : TABLE_PAGE);
    if (m->estimated && m->at_end && m->nrows > 0) {
        rebase_at_end(m);
    } else if (m->estimated) {
        const struct option_row *selection = table_model_selection(m);
        struct option_row keep;
        int64_t position = 0;
        m->estimated = 0;
        if (selection != NULL) {
            keep = *selection;
            m->fetches++;
            rc = store_browse_position(m->store, &m->browse, &keep,
                                       &position, err);
            m->nrows = 0;
            m->base = 0;
            if (rc == FACET_OK)
                rc = window_around(m, &keep, position, err);
            if (rc != FACET_OK)
                return rc;
            m->selected = position;
        }
    }
    if (m->selected >= m->count)
        m->selected = m->count > 0 ? m->count - 1 : 0;
    *exact = 1;
    return FACET_OK;
}

void table_model_count_text(const struct table_model *m, char *out,
                            size_t size)
{
    char number[32];
    tui_fmt_number(number, sizeof number, (double)m->count, 0, 1);
    snprintf(out, size, "%s%s", number, m->count_exact ? "" : "+");
}

void table_model_position_text(const struct table_model *m, char *out,
                               size_t size)
{
    char row[32], count[40];
    tui_fmt_number(row, sizeof row, (double)(m->selected + 1), 0, 1);
    table_model_count_text(m, count, sizeof count);
    snprintf(out, size, "row %s%s of %s", row, m->estimated ? "+" : "",
             count);
}

/* filter_match's view of an option's columns. */
static double option_value(void *context, const char *column)
{
    return option_quantity_value(context, column);
}

int table_model_shows(const struct table_model *m,
                      const struct option_row *option)
{
    if (m->browse.pareto_only && option->rank != 1)
        return 0;
    return filter_match(m->filter, option_value, (void *)option);
}

/* Fills the window with the pages before and after keep, which is at
 * position: by keyset from a row, so a jump deep into a filtered table
 * costs a page, not an OFFSET scan. */
static int window_around(struct table_model *m, const struct option_row *keep,
                         int64_t position, struct facet_error *err)
{
    struct batch *b = malloc(sizeof *b);
    if (b == NULL)
        return facet_error_set(err, FACET_EWORK, "out of memory");
    b->n = 0;
    m->fetches++;
    int rc = store_browse_page(m->store, &m->browse, keep, 1, TABLE_PAGE,
                               collect, b, err);
    if (rc == FACET_OK) {
        window_set(m, b, 1, position - b->n);
        m->rows[m->nrows++] = *keep;
        b->n = 0;
        m->fetches++;
        rc = store_browse_page(m->store, &m->browse, keep, 0, TABLE_PAGE,
                               collect, b, err);
    }
    if (rc == FACET_OK)
        window_append(m, b);
    else
        m->nrows = 0;
    free(b);
    return rc;
}

/* Counts again with a cap: the count, whether it is exact, and whether
 * the filter passes so few options that they are found first and sorted
 * (option_browse.filter_first). */
static int recount(struct table_model *m, struct facet_error *err)
{
    m->browse.filter_first = 0;
    m->count_from = m->count_sofar = 0;
    m->tail.n = 0;
    m->fetches++;
    int rc = store_browse_count_capped(m->store, &m->browse, NULL, 0,
                                       TABLE_COUNT_CAP, &m->count, err);
    if (rc != FACET_OK)
        return rc;
    m->count_exact = m->count < TABLE_COUNT_CAP;
    m->browse.filter_first = (m->browse.where != NULL ||
                              m->browse.pareto_only) &&
                             m->count_exact &&
                             m->count <= TABLE_FILTER_FIRST;
    return FACET_OK;
}

/* The position of keep (shown by the model) into *position: exact within
 * TABLE_POSITION_CAP rows of the start, else that cap, and the model's
 * positions become estimates. */
static int locate(struct table_model *m, const struct option_row *keep,
                  int64_t *position, struct facet_error *err)
{
    m->fetches++;
    int rc = store_browse_count_capped(m->store, &m->browse, keep, 1,
                                       TABLE_POSITION_CAP, position, err);
    if (rc == FACET_OK && *position >= TABLE_POSITION_CAP)
        m->estimated = 1;
    return rc;
}

/* Fills the window around keep at position and makes the count cover
 * what the window holds. */
static int keep_at(struct table_model *m, const struct option_row *keep,
                   int64_t position, struct facet_error *err)
{
    int rc = window_around(m, keep, position, err);
    if (rc == FACET_OK && m->count < m->base + m->nrows)
        m->count = m->base + m->nrows;
    return rc;
}

/* Counts again (when recount), empties the window, and selects keep (an
 * option) at its new position when the model shows it, else position
 * fallback. */
static int reload(struct table_model *m, const struct option_row *keep,
                  int64_t fallback, int do_recount, struct facet_error *err)
{
    /* the last page kept was of the order before; a count under way
     * starts again, so that its steps keep the new order's */
    m->tail_ready = 0;
    m->tail.n = 0;
    if (!m->count_exact)
        m->count_from = m->count_sofar = 0;
    int rc = do_recount ? recount(m, err) : FACET_OK;
    if (rc != FACET_OK)
        return rc;
    m->nrows = 0;
    m->base = 0;
    m->estimated = 0;
    int64_t position = fallback;
    if (keep != NULL && table_model_shows(m, keep)) {
        rc = locate(m, keep, &position, err);
        if (rc == FACET_OK)
            rc = keep_at(m, keep, position, err);
        if (rc != FACET_OK)
            return rc;
    }
    return table_model_select(m, position, err);
}

int table_model_select_first(struct table_model *m, struct facet_error *err)
{
    m->nrows = 0;
    m->base = 0;
    m->estimated = 0;
    m->selected = 0;
    return table_model_select(m, 0, err);
}

int table_model_select_number(struct table_model *m, int64_t number,
                              int *found, struct facet_error *err)
{
    *found = 0;
    for (int64_t k = 0; k < m->nrows; k++)
        if (m->rows[k].number == number) {
            *found = 1;
            return table_model_select(m, m->base + k, err);
        }
    struct option_row option;
    struct facet_error ignored;
    if (store_option_get(m->store, m->browse.run, number, &option,
                         &ignored) != FACET_OK || !table_model_shows(m,
                                                                  &option))
        return FACET_OK;
    int64_t position;
    m->nrows = 0;
    m->base = 0;
    m->estimated = 0;
    int rc = locate(m, &option, &position, err);
    if (rc == FACET_OK)
        rc = keep_at(m, &option, position, err);
    if (rc != FACET_OK)
        return rc;
    *found = 1;
    return table_model_select(m, position, err);
}

int table_model_refresh(struct table_model *m, struct facet_error *err)
{
    const struct option_row *selection = table_model_selection(m);
    struct option_row keep;
    if (selection != NULL) {
        /* read it again: a live run may have ranked it since */
        struct facet_error ignored;
        if (store_option_get(m->store, m->browse.run, selection->number,
                             &keep, &ignored) != FACET_OK)
            keep = *selection;
    }
    return reload(m, selection ? &keep : NULL, m->selected, 1, err);
}

int table_model_read_run(struct table_model *m, struct facet_error *err)
{
    struct run_info run;
    int rc = store_run_get(m->store, m->browse.run, &run, err);
    if (rc == FACET_OK)
        m->run = run;
    return rc;
}

int table_model_set_filter(struct table_model *m, const char *text,
                           struct facet_error *err)
{
    struct filter *filter;
    int rc = filter_compile(text, &filter, err);
    if (rc != FACET_OK)
        return rc;
    const struct option_row *selection = table_model_selection(m);
    struct option_row keep;
    if (selection)
        keep = *selection;
    struct filter *old = m->filter;
    m->filter = filter;
    m->browse.where = filter_text(filter)[0] ? filter : NULL;
    rc = reload(m, selection ? &keep : NULL, 0, 1, err);
    if (rc != FACET_OK) {
        m->filter = old;
        m->browse.where = old && filter_text(old)[0] ? old : NULL;
        filter_free(filter);
        struct facet_error ignored;
        reload(m, selection ? &keep : NULL, 0, 1, &ignored);
        return rc;
    }
    filter_free(old);
    return FACET_OK;
}

int table_model_set_pareto(struct table_model *m, int on,
                           struct facet_error *err)
{
    const struct option_row *selection = table_model_selection(m);
    struct option_row keep;
    if (selection)
        keep = *selection;
    m->browse.pareto_only = on;
    return reload(m, selection ? &keep : NULL, 0, 1, err);
}

int table_model_set_feasible_first(struct table_model *m, int on,
                                   struct facet_error *err)
{
    const struct option_row *selection = table_model_selection(m);
    struct option_row keep;
    if (selection)
        keep = *selection;
    m->browse.feasible_first = on;
    return reload(m, selection ? &keep : NULL, 0, 0, err);
}

int table_model_set_sort(struct table_model *m, const struct browse_key *keys,
                         int n, struct facet_error *err)
{
    const struct option_row *selection = table_model_selection(m);
    struct option_row keep;
    if (selection)
        keep = *selection;
    int rc = set_keys(m, keys, n, err);
    if (rc != FACET_OK)
        return rc;
    return reload(m, selection ? &keep : NULL, 0, 0, err);
}

int64_t table_model_scroll(int64_t top, int64_t selected, int64_t height,
                           int64_t count)
{
    if (height < 1)
        height = 1;
    if (selected < top)
        top = selected;
    if (selected >= top + height)
        top = selected - height + 1;
    if (top > count - height)
        top = count - height;
    if (top < 0)
        top = 0;
    return top;
}
