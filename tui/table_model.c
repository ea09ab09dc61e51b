/*
 * table_model.c: a paged, sorted, filtered view of one run's options. See
 * table_model.h.
 */
#include "table_model.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int table_model_open(struct table_model *m, struct store *store,
                     int64_t run, struct facet_error *err)
{
    memset(m, 0, sizeof *m);
    m->store = store;
    m->browse.run = run;
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
 * rows at the back to fit. */
static void window_prepend(struct table_model *m, const struct batch *b)
{
    int64_t keep = m->nrows;
    if (keep + b->n > TABLE_WINDOW)
        keep = TABLE_WINDOW - b->n;
    memmove(m->rows + b->n, m->rows, (size_t)keep * sizeof *m->rows);
    for (int k = 0; k < b->n; k++)
        m->rows[b->n - 1 - k] = b->rows[k];
    m->nrows = keep + b->n;
    m->base -= b->n;
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
            if (rc == FACET_OK && b->n == 0)
                break;  /* the table shrank under us */
            if (rc == FACET_OK)
                window_append(m, b);
        } else if (m->nrows > 0 && end <= have_end && end >= m->base &&
                   m->base > 0) {
            /* next to the start: the page before the first row held */
            rc = store_browse_page(m->store, &m->browse, &m->rows[0], 1,
                                   TABLE_PAGE, collect, b, err);
            if (rc == FACET_OK && b->n == 0)
                break;
            if (rc == FACET_OK)
                window_prepend(m, b);
        } else if (end > m->count - TABLE_PAGE) {
            /* near the end: the last page, read backwards */
            rc = store_browse_page(m->store, &m->browse, NULL, 1,
                                   TABLE_PAGE, collect, b, err);
            if (rc == FACET_OK)
                window_set(m, b, 1, m->count - b->n);
            if (rc == FACET_OK && (b->n == 0 || from >= m->base))
                break;
        } else {
            /* far from both: by offset, once */
            int64_t start = from - TABLE_PAGE / 4 > 0 ? from - TABLE_PAGE / 4
                                                      : 0;
            rc = store_browse_offset(m->store, &m->browse, start, TABLE_PAGE,
                                     collect, b, err);
            if (rc == FACET_OK)
                window_set(m, b, 0, start);
            if (rc == FACET_OK && b->n == 0)
                break;
        }
    }
    free(b);
    return rc;
}

int table_model_select(struct table_model *m, int64_t position,
                       struct facet_error *err)
{
    if (position >= m->count)
        position = m->count - 1;
    if (position < 0)
        position = 0;
    m->selected = position;
    return table_model_fetch(m, position - 60, 121, err);
}

/* filter_match's view of an option's columns. */
static double option_value(void *context, const char *column)
{
    return store_option_value(context, column);
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

/* Counts again, empties the window, and selects keep (an option) at its
 * new position when the model shows it, else position fallback. */
static int reload(struct table_model *m, const struct option_row *keep,
                  int64_t fallback, int recount, struct facet_error *err)
{
    int rc = recount ? store_browse_count(m->store, &m->browse, &m->count,
                                          err)
                     : FACET_OK;
    if (rc != FACET_OK)
        return rc;
    m->nrows = 0;
    m->base = 0;
    int64_t position = fallback;
    if (keep != NULL && table_model_shows(m, keep)) {
        rc = store_browse_position(m->store, &m->browse, keep, &position,
                                   err);
        if (rc != FACET_OK)
            return rc;
        rc = window_around(m, keep, position, err);
        if (rc != FACET_OK)
            return rc;
    }
    return table_model_select(m, position, err);
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
    int rc = store_browse_position(m->store, &m->browse, &option, &position,
                                   err);
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

int table_model_set_sort(struct table_model *m, const struct browse_key *keys,
                         int n, struct facet_error *err)
{
    if (n < 0 || n > BROWSE_MAX_KEYS)
        return facet_error_set(err, FACET_EINPUT, "sort: at most %d keys",
                               BROWSE_MAX_KEYS);
    for (int k = 0; k < n; k++)
        if (keys[k].column == NULL ||
            isnan(store_option_value(&(struct option_row){0},
                                     keys[k].column)))
            return facet_error_set(err, FACET_EINPUT,
                "sort: unknown column '%s'",
                keys[k].column ? keys[k].column : "(none)");
    const struct option_row *selection = table_model_selection(m);
    struct option_row keep;
    if (selection)
        keep = *selection;
    for (int k = 0; k < n; k++) {
        snprintf(m->key_names[k], sizeof m->key_names[k], "%s",
                 keys[k].column);
        m->browse.keys[k].column = m->key_names[k];
        m->browse.keys[k].descending = keys[k].descending;
    }
    m->browse.nkeys = n;
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
