/*
 * test_tui_model.c: the options table model of `facet tui` against an
 * oracle: every position of a few thousand synthetic options, walked
 * forwards, backwards and by jumps, under mixed-direction sort keys with
 * many ties, filters and Pareto-only, equals a qsort of all rows filtered
 * with filter_match; walking fetches a page at a time; the selection
 * survives a re-sort; a bad filter leaves the model as it was.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "store/filter.h"
#include "store/store.h"
#include "tui/table_model.h"

#define N 2500

static char db_path[80];
static struct option_row all[N];

/* A store with one run of N options: costs with many ties, ranks 1 on
 * every tenth. */
static struct store *make_store(int64_t *run)
{
    snprintf(db_path, sizeof db_path, "/tmp/facet_test_tui_%d.db",
             (int)getpid());
    unlink(db_path);
    struct store *store;
    struct facet_error err;
    assert_int_equal(store_open(db_path, &store, &err), FACET_OK);
    struct run_info info;
    memset(&info, 0, sizeof info);
    snprintf(info.surface_path, sizeof info.surface_path, "synthetic.obj");
    snprintf(info.surface_sha256, sizeof info.surface_sha256, "0");
    info.units = UNITS_M;
    info.method = METHOD_RANDOM;
    info.per_panel = PANEL_EXTREMES;
    snprintf(info.objectives, sizeof info.objectives, "cost,planarity");
    info.u_min = info.v_min = 1;
    info.u_max = info.v_max = 20;
    info.jobs = 1;
    assert_int_equal(store_run_create(store, &info, &err), FACET_OK);
    *run = info.id;
    int64_t numbers[N];
    int rank[N];
    double crowding[N];
    for (int k = 0; k < N; k++) {
        struct option_row *o = &all[k];
        memset(o, 0, sizeof *o);
        o->number = k + 1;
        o->nu = 1 + (k * 7) % 13;
        o->nv = 1 + (k * 11) % 17;
        o->threshold_mm = 1 + k % 3;
        o->totals.cost = 1000.0 * ((k * 7919) % 97);
        o->totals.planarity = ((k * 104729) % 1000) / 1000.0;
        o->totals.area_of[TYPE_DP] = (k % 50) * 2.5;
        o->totals.feasible = k % 4 != 0;
        numbers[k] = k + 1;
        rank[k] = k % 10 == 0 ? 1 : 2 + k % 5;
        crowding[k] = k % 10 == 0 && k % 20 == 0 ? INFINITY : k * 0.01;
        o->rank = rank[k];
        o->crowding = crowding[k];
    }
    assert_int_equal(store_options_put(store, *run, all, N, &err), FACET_OK);
    assert_int_equal(store_options_set_pareto(store, *run, numbers, rank,
                                              crowding, N, 11, 0.5, &err),
                     FACET_OK);
    /* the oracle holds the rows as the store gives them back */
    struct option_row *back;
    size_t n;
    assert_int_equal(store_options_get(store, *run, &back, &n, &err),
                     FACET_OK);
    assert_int_equal(n, N);
    memcpy(all, back, sizeof all);
    free(back);
    assert_true(all[10].knee && all[10].number == 11);
    return store;
}

static void drop_store(struct store *store)
{
    store_close(store);
    unlink(db_path);
    char side[100];
    snprintf(side, sizeof side, "%s-wal", db_path);
    unlink(side);
    snprintf(side, sizeof side, "%s-shm", db_path);
    unlink(side);
}

/* The oracle: rows of all that pass filter/pareto, sorted by keys, the
 * feasible ones first when sorted (keys given) unless oracle_mixed, as
 * the model opens (issue 32 item 19). */
static const struct browse_key *oracle_keys;
static int oracle_nkeys;
static int oracle_mixed;

static int oracle_compare(const void *a, const void *b)
{
    const struct option_row *p = a, *q = b;
    if (!oracle_mixed && oracle_nkeys > 0 &&
        p->totals.feasible != q->totals.feasible)
        return p->totals.feasible ? -1 : 1;
    for (int k = 0; k < oracle_nkeys; k++) {
        double x = option_quantity_value(p, oracle_keys[k].column);
        double y = option_quantity_value(q, oracle_keys[k].column);
        if (x != y)
            return (x < y) != oracle_keys[k].descending ? -1 : 1;
    }
    return p->number < q->number ? -1 : p->number > q->number;
}

static double value_of(void *context, const char *column)
{
    return option_quantity_value(context, column);
}

static size_t oracle(const struct filter *filter, int pareto,
                     const struct browse_key *keys, int nkeys,
                     struct option_row *out)
{
    size_t n = 0;
    for (int k = 0; k < N; k++)
        if ((!pareto || all[k].rank == 1) &&
            filter_match(filter, value_of, &all[k]))
            out[n++] = all[k];
    oracle_keys = keys;
    oracle_nkeys = nkeys;
    qsort(out, n, sizeof *out, oracle_compare);
    return n;
}

/* Walks the model forwards, backwards and by jumps against want. */
static void check_walk(struct table_model *m, const struct option_row *want,
                       size_t n)
{
    struct facet_error err;
    /* The count is exact up to the cap, a lower bound beyond it
     * ("2,000+"), and exact once the walk has reached the end. */
    if (n <= TABLE_COUNT_CAP || m->count_exact) {
        assert_true(m->count_exact);
        assert_int_equal(m->count, (int64_t)n);
    } else {
        assert_true(m->count >= TABLE_COUNT_CAP &&
                    m->count < (int64_t)n);
        char text[32];
        table_model_count_text(m, text, sizeof text);
        assert_non_null(strchr(text, '+'));
    }
    int64_t before = m->fetches;
    for (size_t p = 0; p < n; p++) {
        assert_int_equal(table_model_select(m, (int64_t)p, &err), FACET_OK);
        assert_int_equal(table_model_selection(m)->number, want[p].number);
    }
    /* one page per TABLE_PAGE rows, give or take the first window and
     * the counts that grow as the walk passes the cap */
    assert_true(m->fetches - before <=
                (int64_t)n / TABLE_PAGE + 3 + (int64_t)n / TABLE_COUNT_CAP);
    assert_int_equal(m->count, (int64_t)n);
    assert_true(m->count_exact);
    for (size_t p = n; p-- > 0;) {
        assert_int_equal(table_model_select(m, (int64_t)p, &err), FACET_OK);
        assert_int_equal(table_model_selection(m)->number, want[p].number);
    }
    for (int k = 0; k < 40 && n > 0; k++) {
        size_t p = ((size_t)k * 7907) % n;
        assert_int_equal(table_model_select(m, (int64_t)p, &err), FACET_OK);
        assert_int_equal(table_model_selection(m)->number, want[p].number);
        assert_int_equal(table_model_fetch(m, (int64_t)p, 50, &err),
                         FACET_OK);
        for (size_t q = p; q < p + 50 && q < n; q++)
            assert_int_equal(table_model_row(m, (int64_t)q)->number,
                             want[q].number);
    }
    if (n > 0) {
        assert_int_equal(table_model_select(m, (int64_t)n + 10, &err),
                         FACET_OK);
        assert_int_equal(m->selected, (int64_t)n - 1);
    }
}

static void test_sorts(void **state)
{
    (void)state;
    int64_t run;
    struct store *store = make_store(&run);
    struct table_model m;
    struct facet_error err;
    static struct option_row want[N];
    assert_int_equal(table_model_open(&m, store, run, &err), FACET_OK);
    size_t n = oracle(NULL, 0, NULL, 0, want);
    check_walk(&m, want, n);

    const struct browse_key sorts[][2] = {
        {{"cost", 0}, {"planarity", 1}},
        {{"cost", 1}, {"nu", 0}},
        {{"rank", 0}, {"crowding", 1}},
        {{"threshold_mm", 1}, {"dp_area", 0}},
    };
    for (size_t k = 0; k < sizeof sorts / sizeof sorts[0]; k++) {
        assert_int_equal(table_model_set_sort(&m, sorts[k], 2, &err),
                         FACET_OK);
        n = oracle(NULL, 0, sorts[k], 2, want);
        check_walk(&m, want, n);
    }
    const struct browse_key one = {"planarity", 1};
    assert_int_equal(table_model_set_sort(&m, &one, 1, &err), FACET_OK);
    n = oracle(NULL, 0, &one, 1, want);
    check_walk(&m, want, n);
    /* asked otherwise: the keys alone, feasible or not */
    assert_true(want[0].totals.feasible && !want[n - 1].totals.feasible);
    assert_int_equal(table_model_set_feasible_first(&m, 0, &err), FACET_OK);
    oracle_mixed = 1;
    for (size_t k = 0; k < 2; k++) {
        assert_int_equal(table_model_set_sort(&m, sorts[k], 2, &err),
                         FACET_OK);
        n = oracle(NULL, 0, sorts[k], 2, want);
        check_walk(&m, want, n);
    }
    oracle_mixed = 0;
    table_model_close(&m);
    drop_store(store);
}

/* Opened sorted, as the Options screen opens: the same rows as the
 * oracle's order from the first, the first row selected, and the run read
 * once into the model for the screens on it. */
static void test_open_sorted(void **state)
{
    (void)state;
    int64_t run;
    struct store *store = make_store(&run);
    struct table_model m;
    struct facet_error err;
    static struct option_row want[N];
    const struct browse_key sorts[][2] = {
        {{"cost", 0}, {"planarity", 1}},
        {{"planarity", 1}, {"number", 0}},
    };
    for (size_t k = 0; k < sizeof sorts / sizeof sorts[0]; k++) {
        assert_int_equal(table_model_open_sorted(&m, store, run, sorts[k], 2,
                                                 &err), FACET_OK);
        assert_int_equal(m.run.id, run);
        assert_int_equal(m.run.options, N);
        assert_int_equal(m.selected, 0);
        size_t n = oracle(NULL, 0, sorts[k], 2, want);
        assert_int_equal(table_model_selection(&m)->number, want[0].number);
        check_walk(&m, want, n);
        table_model_close(&m);
    }
    /* an unknown key is refused with its name */
    const struct browse_key bad = {"colour", 0};
    assert_int_equal(table_model_open_sorted(&m, store, run, &bad, 1, &err),
                     FACET_EINPUT);
    assert_non_null(strstr(err.message, "colour"));
    table_model_close(&m);
    drop_store(store);
}

static void test_filters(void **state)
{
    (void)state;
    int64_t run;
    struct store *store = make_store(&run);
    struct table_model m;
    struct facet_error err;
    static struct option_row want[N];
    assert_int_equal(table_model_open(&m, store, run, &err), FACET_OK);
    const struct browse_key keys[2] = {{"cost", 0}, {"number", 1}};
    assert_int_equal(table_model_set_sort(&m, keys, 2, &err), FACET_OK);
    const char *texts[] = {"cost < 50k and nu >= 3",
                           "not feasible or planarity > 0.9",
                           "dp_area = 0", "cost > 1e9", ""};
    for (size_t k = 0; k < sizeof texts / sizeof texts[0]; k++) {
        assert_int_equal(table_model_set_filter(&m, texts[k], &err),
                         FACET_OK);
        struct filter *f;
        assert_int_equal(filter_compile(texts[k], &f, &err), FACET_OK);
        size_t n = oracle(f, 0, keys, 2, want);
        check_walk(&m, want, n);
        assert_int_equal(table_model_set_pareto(&m, 1, &err), FACET_OK);
        n = oracle(f, 1, keys, 2, want);
        check_walk(&m, want, n);
        assert_int_equal(table_model_set_pareto(&m, 0, &err), FACET_OK);
        filter_free(f);
    }
    /* a bad filter names the column and changes nothing */
    assert_int_equal(table_model_set_filter(&m, "cost < 5", &err), FACET_OK);
    int64_t count = m.count;
    assert_int_equal(table_model_set_filter(&m, "cost < 5 and dp_aera > 1",
                                            &err), FACET_EINPUT);
    assert_non_null(strstr(err.message, "column 14"));
    assert_non_null(strstr(err.message, "dp_area"));
    assert_int_equal(m.count, count);
    assert_string_equal(filter_text(m.filter), "cost < 5");
    table_model_close(&m);
    drop_store(store);
}

static void test_selection(void **state)
{
    (void)state;
    int64_t run;
    struct store *store = make_store(&run);
    struct table_model m;
    struct facet_error err;
    assert_int_equal(table_model_open(&m, store, run, &err), FACET_OK);
    int found;
    assert_int_equal(table_model_select_number(&m, 1234, &found, &err),
                     FACET_OK);
    assert_true(found);
    assert_int_equal(table_model_selection(&m)->number, 1234);
    const struct browse_key keys[2] = {{"cost", 1}, {"planarity", 0}};
    assert_int_equal(table_model_set_sort(&m, keys, 2, &err), FACET_OK);
    assert_int_equal(table_model_selection(&m)->number, 1234);
    static struct option_row want[N];
    oracle(NULL, 0, keys, 2, want);
    /* Within the position cap the row number is exact; deeper, the
     * option is placed at the cap and numbered from there. */
    size_t place = 0;
    while (want[place].number != 1234)
        place++;
    if (place < TABLE_POSITION_CAP)
        assert_int_equal(m.selected, (int64_t)place);
    else
        assert_int_equal(m.selected, TABLE_POSITION_CAP);
    /* the knee (11, rank 1) stays selected with Pareto only */
    assert_int_equal(table_model_select_number(&m, 11, &found, &err),
                     FACET_OK);
    assert_int_equal(table_model_set_pareto(&m, 1, &err), FACET_OK);
    assert_int_equal(table_model_selection(&m)->number, 11);
    assert_true(table_model_selection(&m)->knee);
    /* a hidden option is not found, and the selection stays */
    assert_int_equal(table_model_select_number(&m, 12, &found, &err),
                     FACET_OK);
    assert_false(found);
    assert_int_equal(table_model_selection(&m)->number, 11);
    /* unknown sort keys are refused */
    const struct browse_key bad = {"nosuch", 0};
    assert_int_equal(table_model_set_sort(&m, &bad, 1, &err), FACET_EINPUT);
    assert_non_null(strstr(err.message, "nosuch"));
    table_model_close(&m);
    drop_store(store);
}

static void test_store_browse(void **state)
{
    (void)state;
    int64_t run;
    struct store *store = make_store(&run);
    struct facet_error err;
    struct option_browse b = {run, 0, NULL, {{"cost", 0}}, 1, 0, 0, 0};
    double lo, hi;
    assert_int_equal(store_browse_range(store, &b, "cost", &lo, &hi, &err),
                     FACET_OK);
    assert_true(lo == 0 && hi == 96000);
    assert_int_equal(store_browse_range(store, &b, "run", &lo, &hi, &err),
                     FACET_EINPUT);
    int64_t count;
    b.pareto_only = 1;
    assert_int_equal(store_browse_count(store, &b, &count, &err), FACET_OK);
    assert_int_equal(count, N / 10);
    b.pareto_only = 0;
    int64_t position;
    assert_int_equal(store_browse_position(store, &b, &all[0], &position,
                                           &err), FACET_OK);
    /* option 1 has cost 0: before it, only cost-0 options numbered lower */
    assert_int_equal(position, 0);
    table_model_scroll(0, 0, 10, 100);
    drop_store(store);
}

/* A count stepped to its end while positions are estimated (a deep option
 * kept across a re-sort, as a live run's refresh does) is the run's count
 * and stays it: the steps used to add the last slice again each time
 * (a 6,355-option run showed "10,377,715+ shown", climbing). The selection
 * keeps its option, now at its exact position (the oracle's). */
static void test_count_step_stops(void **state)
{
    (void)state;
    int64_t run;
    struct store *store = make_store(&run);
    struct table_model m;
    struct facet_error err;
    assert_int_equal(table_model_open(&m, store, run, &err), FACET_OK);
    const struct browse_key keys[1] = {{"cost", 1}};
    static struct option_row want[N];
    oracle(NULL, 0, keys, 1, want);
    /* an option beyond the position cap in the new order */
    int64_t deep = want[N - 100].number;
    int found;
    assert_int_equal(table_model_select_number(&m, deep, &found, &err),
                     FACET_OK);
    assert_true(found);
    assert_int_equal(table_model_set_sort(&m, keys, 1, &err), FACET_OK);
    assert_true(m.estimated);
    assert_false(m.count_exact);
    int done = 0, steps = 0;
    while (!done && steps < 100) {
        assert_int_equal(table_model_count_step(&m, 300, &done, &err),
                         FACET_OK);
        steps++;
    }
    assert_int_equal(done, 1);
    assert_int_equal(m.count, N);
    for (int k = 0; k < 20; k++) {
        done = 0;
        assert_int_equal(table_model_count_step(&m, 300, &done, &err),
                         FACET_OK);
        assert_int_equal(done, 1);
        assert_int_equal(m.count, N);
    }
    char text[32];
    table_model_count_text(&m, text, sizeof text);
    assert_string_equal(text, "2,500");
    assert_int_equal(table_model_selection(&m)->number, deep);
    assert_int_equal(m.selected, N - 100);
    table_model_position_text(&m, text, sizeof text);
    assert_string_equal(text, "row 2,401 of 2,500");
    /* and the rows around it are the oracle's */
    for (int64_t p = N - 150; p < N; p++) {
        assert_int_equal(table_model_select(&m, p, &err), FACET_OK);
        assert_int_equal(table_model_selection(&m)->number, want[p].number);
    }
    table_model_close(&m);
    drop_store(store);
}

/* End on a filter that passes more options than the count's cap: the
 * last page is read without counting (the oracle's last rows, positions
 * lower bounds, "+" shown), walking up from it gives the oracle's rows,
 * and once the steps have counted, every position is the oracle's. Without
 * a filter End counts exactly at once. Counted by the steps first, End
 * reads the last page they kept, in any order of keys. */
static void test_end_before_count(void **state)
{
    (void)state;
    int64_t run;
    struct store *store = make_store(&run);
    struct table_model m;
    struct facet_error err;
    assert_int_equal(table_model_open(&m, store, run, &err), FACET_OK);
    const struct browse_key keys[2] = {{"cost", 1}, {"planarity", 0}};
    assert_int_equal(table_model_set_sort(&m, keys, 2, &err), FACET_OK);
    assert_int_equal(table_model_select_last(&m, &err), FACET_OK);
    assert_true(m.count_exact);
    assert_int_equal(m.selected, N - 1);

    const char *text = "planarity > 0.05";
    struct filter *f;
    assert_int_equal(filter_compile(text, &f, &err), FACET_OK);
    static struct option_row want[N];
    size_t n = oracle(f, 0, keys, 2, want);
    assert_true(n > TABLE_COUNT_CAP);
    assert_int_equal(table_model_set_filter(&m, text, &err), FACET_OK);
    assert_false(m.count_exact);
    assert_int_equal(table_model_select(&m, m.count - 1, &err), FACET_OK);
    assert_false(m.count_exact);
    assert_true(m.estimated);
    assert_int_equal(m.selected, m.count - 1);
    assert_int_equal(table_model_selection(&m)->number, want[n - 1].number);
    char words[64];
    table_model_position_text(&m, words, sizeof words);
    assert_non_null(strstr(words, "+ of "));
    table_model_count_text(&m, words, sizeof words);
    assert_non_null(strchr(words, '+'));
    int64_t last = m.selected;
    for (int64_t back = 0; back < 450; back++) {
        assert_int_equal(table_model_select(&m, last - back, &err),
                         FACET_OK);
        assert_int_equal(table_model_selection(&m)->number,
                         want[n - 1 - (size_t)back].number);
    }
    int done = 0, steps = 0;
    while (!done && steps++ < 100)
        assert_int_equal(table_model_count_step(&m, 300, &done, &err),
                         FACET_OK);
    assert_int_equal(done, 1);
    assert_int_equal(m.count, (int64_t)n);
    assert_false(m.estimated);
    assert_int_equal(table_model_selection(&m)->number, want[n - 450].number);
    assert_int_equal(m.selected, (int64_t)n - 450);
    for (int64_t p = (int64_t)n - 1; p >= (int64_t)n - 700; p--) {
        assert_int_equal(table_model_select(&m, p, &err), FACET_OK);
        assert_int_equal(table_model_selection(&m)->number, want[p].number);
    }

    /* Counted first by the steps, which keep the last page: End reads
     * it by number (one fetch), the oracle's rows; after a re-sort the
     * page kept is of the old order and is not used. */
    const struct browse_key other[1] = {{"planarity", 1}};
    for (int sort = 0; sort < 2; sort++) {
        if (sort)
            assert_int_equal(table_model_set_sort(&m, other, 1, &err),
                             FACET_OK);
        assert_int_equal(table_model_set_filter(&m, text, &err), FACET_OK);
        assert_int_equal(table_model_select(&m, 0, &err), FACET_OK);
        n = oracle(f, 0, sort ? other : keys, sort ? 1 : 2, want);
        done = 0;
        steps = 0;
        while (!done && steps++ < 100)
            assert_int_equal(table_model_count_step(&m, 700, &done, &err),
                             FACET_OK);
        assert_true(m.tail_ready);
        int64_t fetches = m.fetches;
        assert_int_equal(table_model_select(&m, m.count - 1, &err),
                         FACET_OK);
        assert_int_equal(m.fetches - fetches, 1);
        for (int64_t p = (int64_t)n - 1; p >= (int64_t)n - 500; p--) {
            assert_int_equal(table_model_select(&m, p, &err), FACET_OK);
            assert_int_equal(table_model_selection(&m)->number,
                             want[p].number);
        }
    }
    assert_int_equal(table_model_set_sort(&m, keys, 2, &err), FACET_OK);
    assert_false(m.tail_ready);
    n = oracle(f, 0, keys, 2, want);
    assert_int_equal(table_model_select(&m, m.count - 1, &err), FACET_OK);
    assert_int_equal(table_model_selection(&m)->number, want[n - 1].number);
    filter_free(f);
    table_model_close(&m);
    drop_store(store);
}

static int gather(void *context, const struct option_row *option)
{
    struct option_row **at = context;
    *(*at)++ = *option;
    return 0;
}

/* A filtered page read by a scan of the run (what a page whose walk runs
 * too long falls back to) is the page the walk gives, forward and
 * backward, from either end and from rows in the middle. */
static void test_page_by_scan(void **state)
{
    (void)state;
    int64_t run;
    struct store *store = make_store(&run);
    struct facet_error err;
    struct filter *f;
    assert_int_equal(filter_compile("cost < 50k and nu >= 3", &f, &err),
                     FACET_OK);
    struct option_browse walk = {run, 0, f, {{"cost", 1}, {"nv", 0}}, 2, 0,
                                 1, 0};
    struct option_browse scan = walk;
    scan.filter_first = BROWSE_SCAN;
    static struct option_row want[N];
    size_t n = oracle(f, 0, walk.keys, 2, want);
    assert_true(n > 400);
    static struct option_row a[N], b[N];
    const struct option_row *from[] = {NULL, &want[0], &want[n / 2],
                                       &want[n - 1]};
    for (size_t k = 0; k < sizeof from / sizeof from[0]; k++)
        for (int backward = 0; backward < 2; backward++) {
            struct option_row *at = a, *bt = b;
            assert_int_equal(store_browse_page(store, &walk, from[k],
                                               backward, 150, gather, &at,
                                               &err), FACET_OK);
            assert_int_equal(store_browse_page(store, &scan, from[k],
                                               backward, 150, gather, &bt,
                                               &err), FACET_OK);
            assert_int_equal(at - a, bt - b);
            for (struct option_row *p = a, *q = b; p < at; p++, q++)
                assert_int_equal(p->number, q->number);
        }
    filter_free(f);
    drop_store(store);
}

/* A new sort shows its top: after a re-sort kept an option deeper than
 * the position cap (positions estimated), selecting the first row gives
 * the order's first option at position 0 and exact positions after it
 * (the oracle's). */
static void test_select_first(void **state)
{
    (void)state;
    int64_t run;
    struct store *store = make_store(&run);
    struct table_model m;
    struct facet_error err;
    assert_int_equal(table_model_open(&m, store, run, &err), FACET_OK);
    const struct browse_key keys[2] = {{"planarity", 1}, {"cost", 0}};
    static struct option_row want[N];
    oracle(NULL, 0, keys, 2, want);
    int found;
    assert_int_equal(table_model_select_number(&m, want[N - 10].number,
                                               &found, &err), FACET_OK);
    assert_int_equal(table_model_set_sort(&m, keys, 2, &err), FACET_OK);
    assert_true(m.estimated);
    assert_int_equal(table_model_select_first(&m, &err), FACET_OK);
    assert_false(m.estimated);
    assert_int_equal(m.selected, 0);
    for (int64_t p = 0; p < 450; p++) {
        assert_int_equal(table_model_select(&m, p, &err), FACET_OK);
        assert_int_equal(table_model_selection(&m)->number, want[p].number);
    }
    table_model_close(&m);
    drop_store(store);
}

static void test_scroll(void **state)
{
    (void)state;
    assert_int_equal(table_model_scroll(0, 5, 10, 100), 0);
    assert_int_equal(table_model_scroll(0, 10, 10, 100), 1);
    assert_int_equal(table_model_scroll(50, 40, 10, 100), 40);
    assert_int_equal(table_model_scroll(95, 99, 10, 100), 90);
    assert_int_equal(table_model_scroll(0, 0, 10, 3), 0);
    assert_int_equal(table_model_scroll(7, 0, 0, 3), 0);
}

/* Marks: the 65th is refused with a message and leaves the 64 as they
 * were; marking twice keeps one mark; unmarking makes room again. */
static void test_marks_full(void **state)
{
    (void)state;
    struct table_model m;
    memset(&m, 0, sizeof m);
    struct facet_error err;
    for (int64_t k = 1; k <= TABLE_MARKS_MAX; k++)
        assert_int_equal(table_model_set_mark(&m, k, 1, &err), FACET_OK);
    assert_int_equal(table_model_set_mark(&m, 1, 1, &err), FACET_OK);
    assert_int_equal(m.nmarks, TABLE_MARKS_MAX);
    facet_error_clear(&err);
    assert_int_equal(table_model_set_mark(&m, 1000, 1, &err), FACET_EINPUT);
    assert_int_equal(err.code, FACET_EINPUT);
    char want[64];
    snprintf(want, sizeof want, "at most %d marks", TABLE_MARKS_MAX);
    assert_string_equal(err.message, want);
    assert_false(table_model_marked(&m, 1000));
    assert_int_equal(m.nmarks, TABLE_MARKS_MAX);
    assert_int_equal(table_model_set_mark(&m, 7, 0, &err), FACET_OK);
    assert_false(table_model_marked(&m, 7));
    assert_int_equal(table_model_set_mark(&m, 1000, 1, &err), FACET_OK);
    assert_true(table_model_marked(&m, 1000));
    assert_int_equal(m.nmarks, TABLE_MARKS_MAX);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_sorts),
        cmocka_unit_test(test_open_sorted),
        cmocka_unit_test(test_filters),
        cmocka_unit_test(test_selection),
        cmocka_unit_test(test_store_browse),
        cmocka_unit_test(test_scroll),
        cmocka_unit_test(test_count_step_stops),
        cmocka_unit_test(test_select_first),
        cmocka_unit_test(test_end_before_count),
        cmocka_unit_test(test_page_by_scan),
        cmocka_unit_test(test_marks_full),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
