/*
 * store_browse.c: browsing one run's options a page at a time, for the
 * TUI: keyset pages in any order of columns with mixed directions, counts,
 * positions, ranges and plot samples. See store.h ("browsing one run").
 *
 * Pages are chosen by keyset (the rows after the last one shown), never by
 * a large OFFSET, so the SQLite indexes on (run, cost), (run, planarity),
 * (run, dp_area) and (run, rank, number) serve a million options at page
 * speed; a leading range term on the first key lets the planner seek.
 * Each query selects option numbers only; the rows themselves are read
 * with store_option_get, so this file has no second copy of the options
 * table's column list. Not here: writing options (store_option.c).
 */
#include "store_internal.h"

#include <assert.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "filter_sql.h"

/* Parameters: ?1 run, ?2 limit, ?3 offset or stride, ?4.. key values
 * (BROWSE_MAX_KEYS + number), the filter's from FILTER_FIRST. */
#define KEY_FIRST 4
#define FILTER_FIRST (KEY_FIRST + BROWSE_MAX_KEYS + 1)

/* The SQL expression that orders by column, or NULL when column is not a
 * sortable option column. The expressions give what an option_row read
 * by store_option_get holds, so keyset values compare alike: rank is NULL
 * until a run is ranked (0 in a row); crowding is NULL at a front's ends,
 * infinity in a row of a ranked option (1e999 is SQLite's infinity, equal
 * to a bound INFINITY) and 0 in an unranked one. */
static const char *key_expr(const char *column)
{
    static const char *const special[][2] = {
        {"rank", store_rank_sql},
        {"crowding", store_crowding_sql},
    };
    for (size_t k = 0; k < sizeof special / sizeof special[0]; k++)
        if (strcmp(column, special[k][0]) == 0)
            return special[k][1];
    for (int k = 0; k < OPTION_QUANTITIES; k++)
        if (strcmp(option_quantities[k].name, "run") != 0 &&
            strcmp(option_quantities[k].name, column) == 0)
            return "";  /* a plain column: key_sql quotes it */
    return NULL;
}

/* Writes the expression of column into out ("\"cost\"" or a special).
 * With filter_first, a plain column is written "+\"cost\"": the unary
 * plus keeps SQLite from walking the column's index for the order, so it
 * finds the filter's rows first (by the filter's index, or a scan) and
 * sorts them. */
static void key_sql(const struct option_browse *b, const char *column,
                    char *out, size_t size)
{
    const char *expr = key_expr(column);
    if (expr != NULL && expr[0] != '\0')
        snprintf(out, size, "%s", expr);
    else
        snprintf(out, size, "%s\"%s\"", b->filter_first ? "+" : "",
                 column);
}

/* The value of column of option as the key expression sees it. */
static double key_value(const struct option_row *option, const char *column)
{
    return option_quantity_value(option, column);
}

/* A growing SQL string; a failed append leaves failed set. */
struct sql_text {
    char *text;
    size_t length, capacity;
    int failed;
};

static void sql_add(struct sql_text *s, const char *fmt, ...)
    __attribute__((format(printf, 2, 3)));

static void sql_add(struct sql_text *s, const char *fmt, ...)
{
    if (s->failed)
        return;
    for (;;) {
        va_list ap;
        va_start(ap, fmt);
        int n = vsnprintf(s->text ? s->text + s->length : NULL,
                          s->text ? s->capacity - s->length : 0, fmt, ap);
        va_end(ap);
        if (n < 0) {
            s->failed = 1;
            return;
        }
        if (s->text != NULL && s->length + (size_t)n < s->capacity) {
            s->length += (size_t)n;
            return;
        }
        size_t capacity = 2 * (s->capacity + (size_t)n) + 256;
        char *grown = realloc(s->text, capacity);
        if (grown == NULL) {
            s->failed = 1;
            return;
        }
        s->text = grown;
        s->capacity = capacity;
    }
}

/* Checks b's keys; FACET_EINPUT names an unknown column. */
static int check_keys(const struct option_browse *b, struct facet_error *err)
{
    if (b->nkeys < 0 || b->nkeys > BROWSE_MAX_KEYS)
        return facet_error_set(err, FACET_EINPUT,
                               "sort: at most %d keys", BROWSE_MAX_KEYS);
    for (int k = 0; k < b->nkeys; k++)
        if (b->keys[k].column == NULL || key_expr(b->keys[k].column) == NULL)
            return facet_error_set(err, FACET_EINPUT,
                "sort: unknown column '%s'",
                b->keys[k].column ? b->keys[k].column : "(none)");
    return FACET_OK;
}

/* Appends "FROM options WHERE run = ?1 [AND rank = 1] AND (filter)"; with
 * filter_first, the filter goes into "number IN (SELECT ...)", which
 * SQLite evaluates first, by the filter's best index or a scan, so the
 * page is then read by primary key and sorted (see key_sql). With scan,
 * the filter is written for a read of the run's rows by the primary key
 * (filter_sql_scan): the form of a count that may run into every option
 * of a run, where filter_first has nothing to add. */
static void add_from(struct sql_text *s, const struct option_browse *b,
                     int scan)
{
    int filter_first = b->filter_first && !scan;
    sql_add(s, " FROM options WHERE run = ?1");
    if (b->feasible_part != 0)
        sql_add(s, " AND %s%s", b->feasible_part > 0 ? "" : "NOT ",
                store_feasible_sql);
    if (filter_first)
        sql_add(s, " AND number IN (SELECT number FROM options"
                   " WHERE run = ?1");
    if (b->pareto_only)
        sql_add(s, " AND rank = 1");
    if (b->where != NULL) {
        char *fragment = scan ? filter_sql_scan(b->where, FILTER_FIRST)
                              : filter_sql(b->where, FILTER_FIRST);
        if (fragment == NULL) {
            s->failed = 1;
            return;
        }
        sql_add(s, " AND (%s)", fragment);
        free(fragment);
    }
    if (filter_first)
        sql_add(s, ")");
}

/* Whether b's order leads with feasibility (the feasible first): a
 * feasible_first browse with keys, not one of its parts. */
static int feasible_leads(const struct option_browse *b)
{
    return b->feasible_first && b->nkeys > 0 && b->feasible_part == 0;
}

/* The part of b's options that are feasible (part 1) or not (-1), each
 * in the order of b's keys: a feasible_first browse is its part 1, then
 * its part -1. */
static struct option_browse browse_part(const struct option_browse *b,
                                        int part)
{
    struct option_browse p = *b;
    p.feasible_first = 0;
    p.feasible_part = part;
    return p;
}

/* The part an option belongs to. */
static int part_of(const struct option_row *option)
{
    return option->totals.feasible == 1 ? 1 : -1;
}

/* Appends " AND <row comes after the keyset row>" (before, when
 * backward): a lexicographic comparison over the keys and number, with a
 * leading range term on the first key that an index can seek by. A key
 * the keyset row has no value of (NULL in the file, NaN in the row: a
 * column added after an older Facet stored the option) compares by IS
 * NULL: NULL sorts before every value, so after it come the rows with a
 * value and the NULL rows later by the next keys (a NULL never compares
 * with ?). */
static void add_keyset(struct sql_text *s, const struct option_browse *b,
                       const struct option_row *keyset, int backward)
{
    char expr[160];
    /* A feasible-first order is walked part by part (store_browse_page),
     * each part by its keys alone. */
    assert(!feasible_leads(b));
    sql_add(s, " AND ");
    if (b->nkeys > 0 && !isnan(key_value(keyset, b->keys[0].column))) {
        int greater = !b->keys[0].descending != !!backward;
        key_sql(b, b->keys[0].column, expr, sizeof expr);
        sql_add(s, "%s %s ?%d AND ", expr, greater ? ">=" : "<=",
                KEY_FIRST);
    }
    for (int k = 0; k <= b->nkeys; k++) {
        int greater = k < b->nkeys ? !b->keys[k].descending != !!backward
                                   : !backward;
        if (k < b->nkeys)
            key_sql(b, b->keys[k].column, expr, sizeof expr);
        else
            snprintf(expr, sizeof expr, "%snumber",
                     b->filter_first ? "+" : "");
        int no_value = k < b->nkeys &&
                       isnan(key_value(keyset, b->keys[k].column));
        if (no_value && greater)
            sql_add(s, "(%s IS NOT NULL OR (%s IS NULL AND ", expr, expr);
        else if (no_value)
            sql_add(s, "(0 OR (%s IS NULL AND ", expr);
        else if (k < b->nkeys)
            sql_add(s, "(%s %s ?%d OR (%s = ?%d AND ", expr,
                    greater ? ">" : "<", KEY_FIRST + k, expr, KEY_FIRST + k);
        else
            sql_add(s, "%s %s ?%d", expr, greater ? ">" : "<",
                    KEY_FIRST + k);
    }
    for (int k = 0; k < b->nkeys; k++)
        sql_add(s, "))");
}

/* Appends " ORDER BY keys, number" (every direction reversed when
 * backward), after feasibility when it leads (a tail's sort of the rows
 * it read; a page reads part by part). */
static void add_order(struct sql_text *s, const struct option_browse *b,
                      int backward)
{
    char expr[160];
    sql_add(s, " ORDER BY ");
    if (feasible_leads(b))
        sql_add(s, "%s %s, ", store_feasible_sql, backward ? "ASC" : "DESC");
    for (int k = 0; k < b->nkeys; k++) {
        key_sql(b, b->keys[k].column, expr, sizeof expr);
        sql_add(s, "%s %s, ", expr,
                !b->keys[k].descending != !!backward ? "ASC" : "DESC");
    }
    sql_add(s, "%snumber %s", b->filter_first ? "+" : "",
            backward ? "DESC" : "ASC");
}

/* Prepares s's text and binds run, the filter's numbers and, when keyset
 * is given, its key values. */
static int prepare(struct store *store, struct sql_text *s,
                   const struct option_browse *b,
                   const struct option_row *keyset, sqlite3_stmt **stmt,
                   const char *doing, struct facet_error *err)
{
    *stmt = NULL;
    if (s->failed) {
        free(s->text);
        return facet_error_set(err, FACET_EWORK, "out of memory");
    }
    int rc = store_prepare(store, s->text, stmt, doing, err);
    free(s->text);
    s->text = NULL;
    if (rc != FACET_OK)
        return rc;
    sqlite3_bind_int64(*stmt, 1, b->run);
    if (keyset != NULL) {
        for (int k = 0; k < b->nkeys; k++)
            sqlite3_bind_double(*stmt, KEY_FIRST + k,
                                key_value(keyset, b->keys[k].column));
        sqlite3_bind_int64(*stmt, KEY_FIRST + b->nkeys, keyset->number);
    }
    if (b->where != NULL)
        for (size_t k = 0; k < filter_param_count(b->where); k++)
            sqlite3_bind_double(*stmt, FILTER_FIRST + (int)k,
                                filter_param(b->where, k));
    return FACET_OK;
}

/* What collect_numbers returns when a progress handler interrupted its
 * statement (no FACET_E* code: err is not filled). */
#define WALK_INTERRUPTED (-1)

/* Steps stmt (rows of one column, an option number), collecting at most
 * limit numbers into *numbers (malloc'ed, *n of them), and finalizes it.
 * WALK_INTERRUPTED (err untouched) when a progress handler stopped it. */
static int collect_numbers(struct store *store, sqlite3_stmt *stmt,
                           int64_t limit, int64_t **numbers, size_t *n,
                           const char *doing, struct facet_error *err)
{
    *numbers = NULL;
    *n = 0;
    size_t capacity = 0;
    int rc = FACET_OK, step;
    while ((step = sqlite3_step(stmt)) == SQLITE_ROW) {
        if (*n == capacity) {
            capacity = capacity ? 2 * capacity : 64;
            int64_t *grown = realloc(*numbers, capacity * sizeof *grown);
            if (grown == NULL) {
                rc = facet_error_set(err, FACET_EWORK, "out of memory");
                break;
            }
            *numbers = grown;
        }
        (*numbers)[(*n)++] = sqlite3_column_int64(stmt, 0);
        if (limit > 0 && (int64_t)*n >= limit) {
            step = SQLITE_DONE;
            break;
        }
    }
    if (rc == FACET_OK && step == SQLITE_INTERRUPT)
        rc = WALK_INTERRUPTED;
    else if (rc == FACET_OK && step != SQLITE_DONE)
        rc = store_fail(store, doing, err);
    sqlite3_finalize(stmt);
    if (rc != FACET_OK) {
        free(*numbers);
        *numbers = NULL;
        *n = 0;
    }
    return rc;
}

/* Reads options numbers[0..n) of b's run and hands each to row, in one
 * read transaction (one snapshot, one lock); stops when row returns
 * non-zero. */
static int deliver_numbers(struct store *store,
                           const struct option_browse *b,
                           const int64_t *numbers, size_t n,
                           int (*row)(void *, const struct option_row *),
                           void *context, struct facet_error *err)
{
    int own = n > 1 && sqlite3_get_autocommit(store->db) &&
              sqlite3_exec(store->db, "BEGIN", NULL, NULL, NULL) == SQLITE_OK;
    struct option_row option;
    int rc = FACET_OK;
    for (size_t k = 0; k < n && rc == FACET_OK; k++) {
        rc = store_option_get(store, b->run, numbers[k], &option, err);
        if (rc == FACET_OK && row(context, &option) != 0)
            break;
    }
    if (own)
        sqlite3_exec(store->db, "COMMIT", NULL, NULL, NULL);
    return rc;
}

/* Steps stmt (rows of one column, an option number), collecting at most
 * limit numbers, then reads each option and hands it to row. */
static int deliver(struct store *store, const struct option_browse *b,
                   sqlite3_stmt *stmt, int64_t limit,
                   int (*row)(void *, const struct option_row *),
                   void *context, const char *doing, struct facet_error *err)
{
    int64_t *numbers;
    size_t n;
    int rc = collect_numbers(store, stmt, limit, &numbers, &n, doing, err);
    if (rc == WALK_INTERRUPTED)
        rc = store_fail(store, doing, err);
    if (rc == FACET_OK)
        rc = deliver_numbers(store, b, numbers, n, row, context, err);
    free(numbers);
    return rc;
}

/* Prepares select, the options of b after `after` (all of them when it
 * is NULL) in b's order or against it (backward), ordered so when ordered
 * is set, then end (" LIMIT ?2 ..."); binds ?2 to limit (no limit for
 * <= 0). The paging and counting queries differ only in these. */
static int prepare_after(struct store *store, const struct option_browse *b,
                         const struct option_row *after, int backward,
                         const char *select, int ordered, const char *end,
                         int64_t limit, sqlite3_stmt **stmt,
                         const char *doing, struct facet_error *err)
{
    int rc = check_keys(b, err);
    if (rc != FACET_OK)
        return rc;
    struct sql_text s = {0};
    sql_add(&s, "%s", select);
    /* filter_first with a scan: the run's rows read by number, the
     * filter over each, the page sorted out of them (page_by_scan) */
    add_from(&s, b, b->filter_first == BROWSE_SCAN);
    if (after != NULL)
        add_keyset(&s, b, after, backward);
    if (ordered)
        add_order(&s, b, backward);
    sql_add(&s, "%s", end);
    rc = prepare(store, &s, b, after, stmt, doing, err);
    if (rc == FACET_OK)
        sqlite3_bind_int64(*stmt, 2, limit > 0 ? limit : -1);
    return rc;
}

/* How long a filtered page may walk the order's index before it is read
 * by a scan instead (seconds). */
#define WALK_BUDGET 0.02

static double monotonic_seconds(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + (double)t.tv_nsec * 1e-9;
}

/* SQLite's progress handler: interrupts the statement once its budget
 * (the monotonic second it ends at) is spent. */
static int walk_spent(void *context)
{
    return monotonic_seconds() > *(const double *)context;
}

/* store_browse_page of a browse whose order does not lead with
 * feasibility (one part of one that does). */
static int page_plain(struct store *store, const struct option_browse *b,
                      const struct option_row *after, int backward,
                      int64_t limit,
                      int (*row)(void *context,
                                 const struct option_row *option),
                      void *context, struct facet_error *err)
{
    sqlite3_stmt *stmt;
    int rc = prepare_after(store, b, after, backward, "SELECT number", 1,
                           " LIMIT ?2", limit, &stmt, "browsing options",
                           err);
    if (rc != FACET_OK)
        return rc;
    /* A filter walks the order's index and looks each row up: cheap when
     * its rows come soon, seconds when it fails a long stretch of the
     * order (the end of 'cost < 1.2e6 and dp_area < 200' by cost: 388,000
     * rows looked up for 200, 3 s). The walk gets WALK_BUDGET; past it the
     * page is taken from one read of the run's rows and sorted (0.3 s a
     * million options). Both give the same rows in the same order. */
    int filtered = (b->where != NULL || b->pareto_only ||
                    b->feasible_part != 0) && !b->filter_first;
    if (!filtered)
        return deliver(store, b, stmt, limit, row, context,
                       "browsing options", err);
    double until = monotonic_seconds() + WALK_BUDGET;
    sqlite3_progress_handler(store->db, 1000, walk_spent, &until);
    int64_t *numbers = NULL;
    size_t n = 0;
    rc = collect_numbers(store, stmt, limit, &numbers, &n,
                         "browsing options", err);
    sqlite3_progress_handler(store->db, 0, NULL, NULL);
    if (rc == WALK_INTERRUPTED) {
        struct option_browse scan = *b;
        scan.filter_first = BROWSE_SCAN;
        rc = prepare_after(store, &scan, after, backward, "SELECT number", 1,
                           " LIMIT ?2", limit, &stmt, "browsing options",
                           err);
        if (rc == FACET_OK)
            rc = collect_numbers(store, stmt, limit, &numbers, &n,
                                 "browsing options", err);
    }
    if (rc == FACET_OK)
        rc = deliver_numbers(store, b, numbers, n, row, context, err);
    free(numbers);
    return rc;
}

/* The rows a feasible_first browse's parts hand on, counted, so that the
 * next part gives what the first did not. */
struct part_rows {
    int (*row)(void *context, const struct option_row *option);
    void *context;
    int64_t n;
    int stopped;
};

static int part_row(void *context, const struct option_row *option)
{
    struct part_rows *p = context;
    p->n++;
    p->stopped = p->row(p->context, option) != 0;
    return p->stopped;
}

/* Whether a part's rows leave room for more under limit (<= 0: none). */
static int part_room(const struct part_rows *p, int64_t limit)
{
    return !p->stopped && (limit <= 0 || p->n < limit);
}

/* The parts of a feasible_first browse in the order a walk meets them
 * (forward: the feasible first; backward: the others first), and the
 * first of them that holds the rows after `after` (NULL: the first). */
static int parts_from(const struct option_row *after, int backward,
                      int part[2])
{
    part[0] = backward ? -1 : 1;
    part[1] = -part[0];
    return after != NULL && part_of(after) != part[0];
}

/* Feasibility leads the order, and no index has it: a page is read part
 * by part, each the order of the keys over one part, seeking by its
 * first key's index as a browse without feasibility does. */
int store_browse_page(struct store *store, const struct option_browse *b,
                      const struct option_row *after, int backward,
                      int64_t limit,
                      int (*row)(void *context,
                                 const struct option_row *option),
                      void *context, struct facet_error *err)
{
    if (!feasible_leads(b))
        return page_plain(store, b, after, backward, limit, row, context,
                          err);
    int rc = check_keys(b, err);
    int part[2];
    int from = parts_from(after, backward, part);
    struct part_rows p = {row, context, 0, 0};
    for (int k = from; rc == FACET_OK && k < 2 && part_room(&p, limit);
         k++) {
        struct option_browse one = browse_part(b, part[k]);
        rc = page_plain(store, &one, k == from ? after : NULL, backward,
                        limit > 0 ? limit - p.n : limit, part_row, &p, err);
    }
    return rc;
}

/* store_browse_offset of a browse whose order does not lead with
 * feasibility. */
static int offset_plain(struct store *store, const struct option_browse *b,
                        int64_t offset, int64_t limit,
                        int (*row)(void *context,
                                   const struct option_row *option),
                        void *context, struct facet_error *err)
{
    sqlite3_stmt *stmt;
    int rc = prepare_after(store, b, NULL, 0, "SELECT number", 1,
                           " LIMIT ?2 OFFSET ?3", limit, &stmt,
                           "browsing options", err);
    if (rc != FACET_OK)
        return rc;
    sqlite3_bind_int64(stmt, 3, offset > 0 ? offset : 0);
    return deliver(store, b, stmt, limit, row, context, "browsing options",
                   err);
}

int store_browse_offset(struct store *store, const struct option_browse *b,
                        int64_t offset, int64_t limit,
                        int (*row)(void *context,
                                   const struct option_row *option),
                        void *context, struct facet_error *err)
{
    if (!feasible_leads(b))
        return offset_plain(store, b, offset, limit, row, context, err);
    struct option_browse feasible = browse_part(b, 1);
    struct option_browse others = browse_part(b, -1);
    int64_t n = 0;
    int rc = check_keys(b, err);
    /* From the top, the other part starts at its own top whatever the
     * feasible part holds: no count of it (a scan, since no index has
     * feasibility: 50 to 100 ms on 300,000 options, each time a table
     * opens). Deeper, the count says which part the offset falls in. */
    if (rc == FACET_OK && offset > 0)
        rc = store_browse_count(store, &feasible, &n, err);
    else
        n = INT64_MAX;
    struct part_rows p = {row, context, 0, 0};
    if (rc == FACET_OK && offset < n)
        rc = offset_plain(store, &feasible, offset, limit, part_row, &p,
                          err);
    if (rc == FACET_OK && part_room(&p, limit))
        rc = offset_plain(store, &others, offset < n ? 0 : offset - n,
                          limit > 0 ? limit - p.n : limit, part_row, &p,
                          err);
    return rc;
}

/* Runs a query of one integer or two reals into the outputs given. */
static int single_row(struct store *store, sqlite3_stmt *stmt,
                      int64_t *count, double *a, double *z,
                      const char *doing, struct facet_error *err)
{
    int rc = FACET_OK;
    int step = sqlite3_step(stmt);
    if (step == SQLITE_ROW) {
        if (count != NULL)
            *count = sqlite3_column_int64(stmt, 0);
        if (a != NULL)
            *a = sqlite3_column_type(stmt, 0) == SQLITE_NULL
                     ? NAN : sqlite3_column_double(stmt, 0);
        if (z != NULL)
            *z = sqlite3_column_type(stmt, 1) == SQLITE_NULL
                     ? NAN : sqlite3_column_double(stmt, 1);
    } else {
        rc = store_fail(store, doing, err);
    }
    sqlite3_finalize(stmt);
    return rc;
}

int store_browse_count(struct store *store, const struct option_browse *b,
                       int64_t *count, struct facet_error *err)
{
    *count = 0;
    struct sql_text s = {0};
    sql_add(&s, "SELECT count(*)");
    add_from(&s, b, 1);
    sqlite3_stmt *stmt;
    int rc = prepare(store, &s, b, NULL, &stmt, "counting options", err);
    if (rc != FACET_OK)
        return rc;
    return single_row(store, stmt, count, NULL, NULL, "counting options",
                      err);
}

/* store_browse_count_capped of a browse whose order does not lead with
 * feasibility. */
static int capped_plain(struct store *store, const struct option_browse *b,
                        const struct option_row *after, int backward,
                        int64_t cap, int64_t *count, struct facet_error *err)
{
    *count = 0;
    sqlite3_stmt *stmt;
    int rc = prepare_after(store, b, after, backward,
                           "SELECT count(*) FROM (SELECT 1", 0, " LIMIT ?2)",
                           cap, &stmt, "counting options", err);
    if (rc != FACET_OK)
        return rc;
    return single_row(store, stmt, count, NULL, NULL, "counting options",
                      err);
}

int store_browse_count_capped(struct store *store,
                              const struct option_browse *b,
                              const struct option_row *after, int backward,
                              int64_t cap, int64_t *count,
                              struct facet_error *err)
{
    if (!feasible_leads(b))
        return capped_plain(store, b, after, backward, cap, count, err);
    *count = 0;
    int rc = check_keys(b, err);
    int part[2];
    int from = parts_from(after, backward, part);
    for (int k = from; rc == FACET_OK && k < 2 && (cap <= 0 || *count < cap);
         k++) {
        struct option_browse one = browse_part(b, part[k]);
        int64_t n = 0;
        rc = capped_plain(store, &one, k == from ? after : NULL, backward,
                          cap > 0 ? cap - *count : cap, &n, err);
        *count += n;
    }
    return rc;
}

/* Merges into tail the last options of b's order among the slice of
 * numbers after from (up to end, unless last): the slice's own last
 * BROWSE_TAIL (its rows read by number, the filter over each, the few
 * kept in order), then those and the tail's by their keys, by number. */
static int tail_step(struct store *store, const struct option_browse *b,
                     int64_t from, int64_t end, int last,
                     struct browse_tail *tail, struct facet_error *err)
{
    struct option_browse scan = *b;
    scan.filter_first = BROWSE_SCAN;
    struct sql_text s = {0};
    sql_add(&s, "SELECT number");
    add_from(&s, &scan, 1);
    sql_add(&s, " AND number > ?3%s", last ? "" : " AND number <= ?2");
    add_order(&s, &scan, 1);
    sql_add(&s, " LIMIT %d", BROWSE_TAIL);
    sqlite3_stmt *stmt;
    int rc = prepare(store, &s, &scan, NULL, &stmt, "counting options", err);
    if (rc != FACET_OK)
        return rc;
    sqlite3_bind_int64(stmt, 3, from);
    if (!last)
        sqlite3_bind_int64(stmt, 2, end);
    int64_t *slice;
    size_t n;
    rc = collect_numbers(store, stmt, BROWSE_TAIL, &slice, &n,
                         "counting options", err);
    if (rc == WALK_INTERRUPTED)
        rc = store_fail(store, "counting options", err);
    if (rc != FACET_OK || n == 0) {
        free(slice);
        return rc;
    }
    /* the slice's and the tail's, in order: every one passes b already */
    struct option_browse plain = scan;
    plain.where = NULL;
    plain.pareto_only = 0;
    struct sql_text m = {0};
    sql_add(&m, "SELECT number FROM options WHERE run = ?1 AND number IN (");
    for (size_t k = 0; k < n; k++)
        sql_add(&m, "%s%lld", k ? ", " : "", (long long)slice[k]);
    for (int k = 0; k < tail->n; k++)
        sql_add(&m, ", %lld", (long long)tail->numbers[k]);
    sql_add(&m, ")");
    add_order(&m, &plain, 1);
    sql_add(&m, " LIMIT %d", BROWSE_TAIL);
    free(slice);
    rc = prepare(store, &m, &plain, NULL, &stmt, "counting options", err);
    if (rc != FACET_OK)
        return rc;
    int64_t *merged;
    rc = collect_numbers(store, stmt, BROWSE_TAIL, &merged, &n,
                         "counting options", err);
    if (rc == WALK_INTERRUPTED)
        rc = store_fail(store, "counting options", err);
    if (rc == FACET_OK) {
        /* None when a damaged file's numbers do not read back as they
         * were found (merged is then NULL, which memcpy may not take). */
        if (n > 0)
            memcpy(tail->numbers, merged, n * sizeof *merged);
        tail->n = (int)n;
    }
    free(merged);
    return rc;
}

int store_browse_count_step(struct store *store,
                            const struct option_browse *b, int64_t rows,
                            int64_t *from, int64_t *count, int *done,
                            struct browse_tail *tail,
                            struct facet_error *err)
{
    *done = 0;
    /* Where the slice ends: the rows-th number after *from, or none when
     * the slice holds every option left. */
    int64_t end = 0;
    int last = rows <= 0;
    sqlite3_stmt *stmt;
    int rc;
    if (!last) {
        rc = store_prepare(store, "SELECT number FROM options WHERE run = ?1"
                           " AND number > ?3 ORDER BY number LIMIT 1"
                           " OFFSET ?2 - 1", &stmt, "counting options", err);
        if (rc != FACET_OK)
            return rc;
        sqlite3_bind_int64(stmt, 1, b->run);
        sqlite3_bind_int64(stmt, 2, rows);
        sqlite3_bind_int64(stmt, 3, *from);
        int step = sqlite3_step(stmt);
        if (step == SQLITE_ROW)
            end = sqlite3_column_int64(stmt, 0);
        else if (step == SQLITE_DONE)
            last = 1;
        else
            rc = store_fail(store, "counting options", err);
        sqlite3_finalize(stmt);
        if (rc != FACET_OK)
            return rc;
    }
    /* The slice by number (the primary key, read in order), the filter
     * over its rows: ?3 the number to start after, ?2 the last one. */
    struct sql_text s = {0};
    sql_add(&s, "SELECT count(*)");
    add_from(&s, b, 1);
    sql_add(&s, " AND number > ?3%s", last ? "" : " AND number <= ?2");
    rc = prepare(store, &s, b, NULL, &stmt, "counting options", err);
    if (rc != FACET_OK)
        return rc;
    sqlite3_bind_int64(stmt, 3, *from);
    if (!last)
        sqlite3_bind_int64(stmt, 2, end);
    int64_t seen = 0;
    rc = single_row(store, stmt, &seen, NULL, NULL, "counting options", err);
    if (rc == FACET_OK && tail != NULL && seen > 0)
        rc = tail_step(store, b, *from, end, last, tail, err);
    if (rc != FACET_OK)
        return rc;
    *count += seen;
    if (last)
        *done = 1;
    else
        *from = end;
    return FACET_OK;
}

int store_browse_position(struct store *store,
                          const struct option_browse *b,
                          const struct option_row *option,
                          int64_t *position, struct facet_error *err)
{
    *position = 0;
    int rc = check_keys(b, err);
    if (rc != FACET_OK)
        return rc;
    if (feasible_leads(b)) {
        /* its place in its part, after every feasible one if it is not */
        struct option_browse own = browse_part(b, part_of(option));
        rc = store_browse_position(store, &own, option, position, err);
        int64_t before = 0;
        struct option_browse feasible = browse_part(b, 1);
        if (rc == FACET_OK && part_of(option) < 0)
            rc = store_browse_count(store, &feasible, &before, err);
        *position += before;
        return rc;
    }
    struct sql_text s = {0};
    sql_add(&s, "SELECT count(*)");
    add_from(&s, b, 0);
    add_keyset(&s, b, option, 1);
    sqlite3_stmt *stmt;
    rc = prepare(store, &s, b, option, &stmt, "locating an option", err);
    if (rc != FACET_OK)
        return rc;
    return single_row(store, stmt, position, NULL, NULL,
                      "locating an option", err);
}

int store_browse_range(struct store *store, const struct option_browse *b,
                       const char *column, double *min, double *max,
                       struct facet_error *err)
{
    *min = *max = NAN;
    if (column == NULL || key_expr(column) == NULL)
        return facet_error_set(err, FACET_EINPUT, "unknown column '%s'",
                               column ? column : "(none)");
    char expr[160];
    struct option_browse plain = *b;
    plain.filter_first = 0;
    key_sql(&plain, column, expr, sizeof expr);
    struct sql_text s = {0};
    sql_add(&s, "SELECT min(%s), max(%s)", expr, expr);
    add_from(&s, b, 0);
    sqlite3_stmt *stmt;
    int rc = prepare(store, &s, b, NULL, &stmt, "measuring options", err);
    if (rc != FACET_OK)
        return rc;
    return single_row(store, stmt, NULL, min, max, "measuring options", err);
}

int store_browse_sample(struct store *store, const struct option_browse *b,
                        int64_t stride, int64_t limit,
                        int (*row)(void *context,
                                   const struct option_row *option),
                        void *context, struct facet_error *err)
{
    struct sql_text s = {0};
    sql_add(&s, "SELECT number");
    add_from(&s, b, 0);
    sql_add(&s, " AND (?3 <= 1 OR number %% ?3 = 0 OR rank = 1)"
                " ORDER BY number LIMIT ?2");
    sqlite3_stmt *stmt;
    int rc = prepare(store, &s, b, NULL, &stmt, "sampling options", err);
    if (rc != FACET_OK)
        return rc;
    sqlite3_bind_int64(stmt, 2, limit > 0 ? limit : -1);
    sqlite3_bind_int64(stmt, 3, stride);
    return deliver(store, b, stmt, limit, row, context, "sampling options",
                   err);
}

/* --- statistics and frequency tables (the Statistics screen) --- */

int store_browse_stats(struct store *store, const struct option_browse *b,
                       const char *const *columns, int n,
                       struct column_stats *out, struct facet_error *err)
{
    struct option_browse plain = *b;
    plain.filter_first = 0;  /* an aggregate reads every row it passes */
    char expr[160];
    struct sql_text s = {0};
    sql_add(&s, "SELECT count(*)");
    for (int k = 0; k < n; k++) {
        out[k].count = 0;
        out[k].min = out[k].median = out[k].max = out[k].mean = NAN;
        if (columns[k] == NULL || key_expr(columns[k]) == NULL) {
            free(s.text);
            return facet_error_set(err, FACET_EINPUT, "unknown column '%s'",
                                   columns[k] ? columns[k] : "(none)");
        }
        key_sql(&plain, columns[k], expr, sizeof expr);
        sql_add(&s, ", count(%s), min(%s), max(%s), avg(%s)", expr, expr,
                expr, expr);
    }
    add_from(&s, &plain, 1);
    sqlite3_stmt *stmt;
    int rc = prepare(store, &s, &plain, NULL, &stmt, "measuring options",
                     err);
    if (rc != FACET_OK)
        return rc;
    int step = sqlite3_step(stmt);
    if (step == SQLITE_ROW)
        for (int k = 0; k < n; k++) {
            out[k].count = sqlite3_column_int64(stmt, 1 + 4 * k);
            out[k].min = store_column_or_nan(stmt, 2 + 4 * k);
            out[k].max = store_column_or_nan(stmt, 3 + 4 * k);
            out[k].mean = store_column_or_nan(stmt, 4 + 4 * k);
        }
    else
        rc = store_fail(store, "measuring options", err);
    sqlite3_finalize(stmt);
    return rc;
}

static int ascending(const void *x, const void *y)
{
    double a = *(const double *)x, b = *(const double *)y;
    return a < b ? -1 : a > b;
}

int store_browse_medians(struct store *store, const struct option_browse *b,
                         const char *const *columns, int n,
                         struct column_stats *out, struct facet_error *err)
{
    struct option_browse plain = *b;
    plain.filter_first = 0;
    char expr[160];
    struct sql_text s = {0};
    sql_add(&s, "SELECT 0");
    double **value = calloc((size_t)(n > 0 ? n : 1), sizeof *value);
    int64_t *got = calloc((size_t)(n > 0 ? n : 1), sizeof *got);
    int rc = value == NULL || got == NULL
                 ? facet_error_set(err, FACET_EWORK, "out of memory")
                 : FACET_OK;
    for (int k = 0; rc == FACET_OK && k < n; k++) {
        out[k].median = NAN;
        if (columns[k] == NULL || key_expr(columns[k]) == NULL)
            rc = facet_error_set(err, FACET_EINPUT, "unknown column '%s'",
                                 columns[k] ? columns[k] : "(none)");
        else if (out[k].count > STORE_MEDIANS_AT_ONCE)
            rc = facet_error_set(err, FACET_EINPUT,
                                 "%lld values of '%s': more than %d to "
                                 "hold at once", (long long)out[k].count,
                                 columns[k], STORE_MEDIANS_AT_ONCE);
        else if (out[k].count > 0 &&
                 (value[k] = malloc((size_t)out[k].count *
                                    sizeof *value[k])) == NULL)
            rc = facet_error_set(err, FACET_EWORK, "out of memory");
        if (rc == FACET_OK) {
            key_sql(&plain, columns[k], expr, sizeof expr);
            sql_add(&s, ", %s", expr);
        }
    }
    sqlite3_stmt *stmt = NULL;
    if (rc == FACET_OK) {
        add_from(&s, &plain, 1);
        rc = prepare(store, &s, &plain, NULL, &stmt, "measuring options",
                     err);
    } else {
        free(s.text);
    }
    int step = SQLITE_DONE;
    while (rc == FACET_OK && (step = sqlite3_step(stmt)) == SQLITE_ROW)
        for (int k = 0; k < n; k++) {
            if (sqlite3_column_type(stmt, 1 + k) == SQLITE_NULL)
                continue;
            /* The counts come from one read and this is another: a
             * writer between them (a working run) adds rows. */
            if (got[k] < out[k].count)
                value[k][got[k]] = sqlite3_column_double(stmt, 1 + k);
            got[k]++;
        }
    if (rc == FACET_OK && step != SQLITE_DONE)
        rc = store_fail(store, "measuring options", err);
    sqlite3_finalize(stmt);
    for (int k = 0; rc == FACET_OK && k < n; k++) {
        int64_t count = got[k] < out[k].count ? got[k] : out[k].count;
        if (count <= 0)
            continue;
        qsort(value[k], (size_t)count, sizeof *value[k], ascending);
        /* As store_browse_median sums its one or two middle values. */
        out[k].median = count % 2 ? 0 + value[k][count / 2]
                                  : (0 + value[k][count / 2 - 1] +
                                     value[k][count / 2]) / 2;
    }
    for (int k = 0; value != NULL && k < n; k++)
        free(value[k]);
    free(value);
    free(got);
    return rc;
}

int store_browse_median(struct store *store, const struct option_browse *b,
                        const char *column, int64_t count, double *median,
                        struct facet_error *err)
{
    *median = NAN;
    if (column == NULL || key_expr(column) == NULL)
        return facet_error_set(err, FACET_EINPUT, "unknown column '%s'",
                               column ? column : "(none)");
    if (count <= 0)
        return FACET_OK;
    /* Without a filter the column's own index holds the values in order
     * (no row is looked up); with one, every row would be looked up from
     * the index, so the rows are read in the table's order and sorted:
     * the unary plus of filter_first keeps the planner off the index. */
    struct option_browse order = *b;
    order.filter_first = b->where != NULL || b->pareto_only;
    char expr[160];
    key_sql(&order, column, expr, sizeof expr);
    struct sql_text m = {0};
    sql_add(&m, "SELECT %s", expr);
    order.filter_first = 0;
    add_from(&m, &order, 1);
    sql_add(&m, " AND %s IS NOT NULL ORDER BY %s LIMIT ?2 OFFSET ?3", expr,
            expr);
    sqlite3_stmt *stmt;
    int rc = prepare(store, &m, &order, NULL, &stmt, "measuring options",
                     err);
    if (rc != FACET_OK)
        return rc;
    sqlite3_bind_int64(stmt, 2, count % 2 ? 1 : 2);
    sqlite3_bind_int64(stmt, 3, (count - 1) / 2);
    double sum = 0;
    int got = 0, step;
    while ((step = sqlite3_step(stmt)) == SQLITE_ROW) {
        sum += sqlite3_column_double(stmt, 0);
        got++;
    }
    if (step != SQLITE_DONE)
        rc = store_fail(store, "measuring options", err);
    else if (got > 0)
        *median = got == 2 ? sum / 2 : sum;
    sqlite3_finalize(stmt);
    return rc;
}

int store_browse_groups(struct store *store, const struct option_browse *b,
                        const char *column, double bin,
                        struct option_group **groups, size_t *n,
                        struct facet_error *err)
{
    *groups = NULL;
    *n = 0;
    if (column == NULL || key_expr(column) == NULL)
        return facet_error_set(err, FACET_EINPUT, "unknown column '%s'",
                               column ? column : "(none)");
    struct option_browse plain = *b;
    /* "+column": read the rows in the table's order and sort them, not
     * walk the column's index and look every row up (2.3 s against 0.8 s
     * on a million options) */
    plain.filter_first = 1;
    char expr[160], group[600];
    key_sql(&plain, column, expr, sizeof expr);
    plain.filter_first = 0;
    /* floor without SQLite's optional math functions: CAST truncates
     * toward zero, one less below it */
    if (bin > 0)
        snprintf(group, sizeof group, "((CAST(%s / ?2 AS INTEGER) - (%s / ?2"
                 " < CAST(%s / ?2 AS INTEGER))) * ?2)", expr, expr, expr);
    else
        snprintf(group, sizeof group, "%s", expr);
    struct sql_text s = {0};
    sql_add(&s, "SELECT %s AS g, count(*), sum(%s = 1), sum(feasible <> 0),"
                " min(cost), min(planarity), min(dp_area)", group,
            store_rank_sql);
    add_from(&s, &plain, 1);
    sql_add(&s, " AND %s IS NOT NULL GROUP BY g ORDER BY g", expr);
    sqlite3_stmt *stmt;
    int rc = prepare(store, &s, &plain, NULL, &stmt, "counting options",
                     err);
    if (rc != FACET_OK)
        return rc;
    if (bin > 0)
        sqlite3_bind_double(stmt, 2, bin);
    size_t capacity = 0;
    int step;
    while ((step = sqlite3_step(stmt)) == SQLITE_ROW) {
        if (*n == capacity) {
            capacity = capacity ? 2 * capacity : 32;
            struct option_group *grown = realloc(*groups,
                                                 capacity * sizeof **groups);
            if (grown == NULL) {
                rc = facet_error_set(err, FACET_EWORK, "out of memory");
                break;
            }
            *groups = grown;
        }
        struct option_group *g = &(*groups)[(*n)++];
        g->value = sqlite3_column_double(stmt, 0);
        g->options = sqlite3_column_int64(stmt, 1);
        g->pareto = sqlite3_column_int64(stmt, 2);
        g->feasible = sqlite3_column_int64(stmt, 3);
        g->min_cost = store_column_or_nan(stmt, 4);
        g->min_planarity = store_column_or_nan(stmt, 5);
        g->min_dp_area = store_column_or_nan(stmt, 6);
    }
    if (rc == FACET_OK && step != SQLITE_DONE)
        rc = store_fail(store, "counting options", err);
    sqlite3_finalize(stmt);
    if (rc != FACET_OK) {
        free(*groups);
        *groups = NULL;
        *n = 0;
    }
    return rc;
}

int store_browse_classes(struct store *store, const struct option_browse *b,
                         struct class_frequency out[CLASS_COUNT],
                         struct facet_error *err)
{
    struct option_browse plain = *b;
    plain.filter_first = 0;
    struct sql_text s = {0};
    sql_add(&s, "SELECT count(*)");
    for (int c = 0; c < CLASS_COUNT; c++) {
        const char *name = panel_class_name((enum panel_class)c);
        sql_add(&s, ", sum(\"%s_count\" > 0), sum(\"%s_count\"),"
                    " sum(\"%s_area\")", name, name, name);
        out[c].options = out[c].panels = 0;
        out[c].area = 0;
    }
    add_from(&s, &plain, 1);
    sqlite3_stmt *stmt;
    int rc = prepare(store, &s, &plain, NULL, &stmt, "counting options",
                     err);
    if (rc != FACET_OK)
        return rc;
    if (sqlite3_step(stmt) == SQLITE_ROW)
        for (int c = 0; c < CLASS_COUNT; c++) {
            out[c].options = sqlite3_column_int64(stmt, 1 + 3 * c);
            out[c].panels = sqlite3_column_int64(stmt, 2 + 3 * c);
            out[c].area = sqlite3_column_double(stmt, 3 + 3 * c);
        }
    else
        rc = store_fail(store, "counting options", err);
    sqlite3_finalize(stmt);
    return rc;
}
