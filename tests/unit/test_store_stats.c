/*
 * test_store_stats.c: the Statistics screen's SQL (store_browse_stats,
 * store_browse_median, store_browse_groups, store_browse_classes) against a brute force over
 * every row read back with store_options_get, filtered with filter_match:
 * count, min, median (odd and even counts), max and mean of columns; the
 * options, Pareto options, feasible options and least cost, planarity and
 * DP area per value and per bin; per class, the options with a panel of
 * it and the panels and area summed; under filters and Pareto-only.
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

#define N 1999

static char db_path[80];
static struct option_row all[N];

static struct store *make_store(int64_t *run)
{
    snprintf(db_path, sizeof db_path, "/tmp/facet_test_stats_%d.db",
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
    info.method = METHOD_NSGA2;
    info.per_panel = PANEL_EXTREMES;
    snprintf(info.objectives, sizeof info.objectives, "cost,planarity");
    info.u_min = info.v_min = 1;
    info.u_max = info.v_max = 20;
    info.jobs = 1;
    assert_int_equal(store_run_create(store, &info, &err), FACET_OK);
    *run = info.id;
    static int64_t numbers[N];
    static int rank[N];
    static double crowding[N];
    srand(11);
    for (int k = 0; k < N; k++) {
        struct option_row *o = &all[k];
        memset(o, 0, sizeof *o);
        o->number = k + 1;
        o->generation = k / 100;
        o->nu = 1 + rand() % 13;
        o->nv = 1 + rand() % 17;
        o->threshold_mm = (rand() % 4000) / 1000.0;
        o->totals.cost = 1000.0 * (rand() % 97);   /* many ties */
        o->totals.planarity = (rand() % 100000) / 1000.0;
        o->totals.area_of[TYPE_DP] = (rand() % 50) * 2.5;
        o->totals.feasible = rand() % 4 != 0;
        for (int c = 0; c < CLASS_COUNT; c++) {
            o->totals.class_count[c] = rand() % 3 == 0 ? 0
                                       : (size_t)(rand() % 40);
            o->totals.class_area[c] = o->totals.class_count[c] * 0.75;
        }
        numbers[k] = k + 1;
        rank[k] = k % 10 == 0 ? 1 : 2 + k % 5;
        crowding[k] = k * 0.01;
    }
    assert_int_equal(store_options_put(store, *run, all, N, &err), FACET_OK);
    assert_int_equal(store_options_set_pareto(store, *run, numbers, rank,
                                              crowding, N, 11, 0.5, &err),
                     FACET_OK);
    struct option_row *back;
    size_t n;
    assert_int_equal(store_options_get(store, *run, &back, &n, &err),
                     FACET_OK);
    assert_int_equal(n, N);
    memcpy(all, back, sizeof all);
    free(back);
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

static double row_value(void *context, const char *column)
{
    return option_quantity_value(context, column);
}

/* The rows a browse with filter f (NULL: all) and pareto sees. */
static int passes(const struct filter *f, int pareto,
                  const struct option_row *o)
{
    if (pareto && o->rank != 1)
        return 0;
    return filter_match(f, row_value, (void *)o);
}

static int by_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

static int close_to(double a, double b)
{
    if (isnan(a) || isnan(b))
        return isnan(a) && isnan(b);
    return fabs(a - b) <= 1e-9 * (1 + fabs(a) + fabs(b));
}

static void check_browse(struct store *store, int64_t run, const char *text,
                         int pareto)
{
    struct facet_error err;
    struct filter *f = NULL;
    if (text)
        assert_int_equal(filter_compile(text, &f, &err), FACET_OK);
    struct option_browse b;
    memset(&b, 0, sizeof b);
    b.run = run;
    b.pareto_only = pareto;
    b.where = f;
    static const char *const columns[] = {"cost", "planarity", "dp_area",
                                          "nu", "threshold_mm", "rank",
                                          "generation"};
    enum { C = sizeof columns / sizeof columns[0] };
    struct column_stats got[C];
    assert_int_equal(store_browse_stats(store, &b, columns, C, got, &err),
                     FACET_OK);
    for (int c = 0; c < C; c++) {
        assert_true(isnan(got[c].median));  /* left to store_browse_median */
        assert_int_equal(store_browse_median(store, &b, columns[c],
                                             got[c].count, &got[c].median,
                                             &err), FACET_OK);
    }
    /* All at once, from one read: each the same, to the bit, as the
     * column's own median. */
    struct column_stats once[C];
    memcpy(once, got, sizeof once);
    assert_int_equal(store_browse_medians(store, &b, columns, C, once, &err),
                     FACET_OK);
    for (int c = 0; c < C; c++)
        assert_memory_equal(&once[c].median, &got[c].median,
                            sizeof once[c].median);
    static double values[N];
    for (int c = 0; c < C; c++) {
        int n = 0;
        double sum = 0;
        for (int k = 0; k < N; k++)
            if (passes(f, pareto, &all[k])) {
                values[n] = option_quantity_value(&all[k], columns[c]);
                sum += values[n++];
            }
        qsort(values, (size_t)n, sizeof values[0], by_double);
        assert_int_equal(got[c].count, n);
        if (n == 0) {
            assert_true(isnan(got[c].min) && isnan(got[c].median));
            continue;
        }
        double median = n % 2 ? values[n / 2]
                              : (values[n / 2 - 1] + values[n / 2]) / 2;
        assert_true(close_to(got[c].min, values[0]));
        assert_true(close_to(got[c].max, values[n - 1]));
        assert_true(close_to(got[c].median, median));
        assert_true(close_to(got[c].mean, sum / n));
    }
    /* groups: by nu exactly, and by threshold in 0.5 mm bins */
    for (int pass = 0; pass < 2; pass++) {
        const char *column = pass ? "threshold_mm" : "nu";
        double bin = pass ? 0.5 : 0;
        struct option_group *groups;
        size_t ng;
        assert_int_equal(store_browse_groups(store, &b, column, bin,
                                             &groups, &ng, &err), FACET_OK);
        int64_t total = 0;
        for (size_t g = 0; g < ng; g++) {
            if (g > 0)
                assert_true(groups[g].value > groups[g - 1].value);
            int64_t options = 0, paretos = 0, feasible = 0;
            double cost = NAN, planarity = NAN, dp = NAN;
            for (int k = 0; k < N; k++) {
                if (!passes(f, pareto, &all[k]))
                    continue;
                double v = option_quantity_value(&all[k], column);
                double key = bin > 0 ? floor(v / bin) * bin : v;
                if (!close_to(key, groups[g].value))
                    continue;
                options++;
                paretos += all[k].rank == 1;
                feasible += all[k].totals.feasible != 0;
                cost = isnan(cost) ? all[k].totals.cost
                                   : fmin(cost, all[k].totals.cost);
                planarity = isnan(planarity)
                                ? all[k].totals.planarity
                                : fmin(planarity, all[k].totals.planarity);
                double d = all[k].totals.area_of[TYPE_DP];
                dp = isnan(dp) ? d : fmin(dp, d);
            }
            assert_int_equal(groups[g].options, options);
            assert_int_equal(groups[g].pareto, paretos);
            assert_int_equal(groups[g].feasible, feasible);
            assert_true(close_to(groups[g].min_cost, cost));
            assert_true(close_to(groups[g].min_planarity, planarity));
            assert_true(close_to(groups[g].min_dp_area, dp));
            total += options;
        }
        assert_int_equal(total, got[0].count);
        free(groups);
    }
    struct class_frequency classes[CLASS_COUNT];
    assert_int_equal(store_browse_classes(store, &b, classes, &err),
                     FACET_OK);
    for (int c = 0; c < CLASS_COUNT; c++) {
        int64_t options = 0, panels = 0;
        double area = 0;
        for (int k = 0; k < N; k++)
            if (passes(f, pareto, &all[k])) {
                options += all[k].totals.class_count[c] > 0;
                panels += (int64_t)all[k].totals.class_count[c];
                area += all[k].totals.class_area[c];
            }
        assert_int_equal(classes[c].options, options);
        assert_int_equal(classes[c].panels, panels);
        assert_true(close_to(classes[c].area, area));
    }
    filter_free(f);
}

static void test_stats(void **state)
{
    (void)state;
    int64_t run;
    struct store *store = make_store(&run);
    check_browse(store, run, NULL, 0);
    check_browse(store, run, NULL, 1);
    check_browse(store, run, "cost < 40000 and nu >= 5", 0);
    check_browse(store, run, "planarity > 50 or feasible", 1);
    check_browse(store, run, "cost < 0", 0);  /* none */
    const char *bad[] = {"nosuch"};
    struct column_stats out[1];
    struct facet_error err;
    struct option_browse b;
    memset(&b, 0, sizeof b);
    b.run = run;
    assert_int_equal(store_browse_stats(store, &b, bad, 1, out, &err),
                     FACET_EINPUT);
    drop_store(store);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_stats),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
