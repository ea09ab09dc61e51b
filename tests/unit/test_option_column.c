/*
 * test_quantity.c: the registry of an option's columns
 * (core/quantity/quantity.h) against the truth it describes: the options
 * table SQLite creates (pragma_table_info: names, order, types), the
 * fields of struct option_row (written here by hand, field by field), the
 * search's metrics (core/search/metric.h), the values SQLite holds under
 * each column's name after a store, and the rows SQLite counts and
 * orders for a --where and a --sort on every column.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <sqlite3.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "core/search/metric.h"
#include "store/filter.h"
#include "store/store.h"
#include "study/study_export.h"
#include "tests/support/store_fixture.h"

enum { ROWS = 6 };

static char db_path[64];

/* A fresh store with one run, path in db_path. */
static struct store *fresh_store(int64_t *run_id)
{
    snprintf(db_path, sizeof db_path, "/tmp/facet_test_option_column_%d.db",
             (int)getpid());
    store_fixture_remove(db_path);
    struct facet_error err;
    struct store *store;
    assert_int_equal(store_open(db_path, &store, &err), FACET_OK);
    struct run_info run;
    store_fixture_run(&run);
    assert_int_equal(store_run_create(store, &run, &err), FACET_OK);
    *run_id = run.id;
    return store;
}

/* Option k of ROWS: every field a value no other field has. */
static struct option_row option_k(int k)
{
    struct option_row o;
    memset(&o, 0, sizeof o);
    struct option_totals *t = &o.totals;
    o.number = k + 1;
    o.generation = 10 + k;
    o.nu = 20 + k;
    o.nv = 30 + k;
    o.threshold_mm = 1.25 + k;
    t->panels = (size_t)(40 + k);
    for (int j = 0; j < TYPE_COUNT; j++) {
        t->count[j] = (size_t)(50 + 10 * j + k);
        t->area_of[j] = 80.5 + 10 * j + k;
        t->cost_of[j] = 1100.25 + 100 * j + k;
    }
    t->area = 120.75 + k;
    t->cost = 1500.5 + k;
    t->planarity = 0.0625 + k;
    t->max_deviation = 0.003 + 0.001 * k;
    t->max_panel_area = 2.5 + k;
    t->p_dist = 0.0078125 + k;
    t->feasible = k % 2;
    for (int c = 0; c < CLASS_COUNT; c++) {
        t->class_count[c] = (size_t)(200 + 10 * c + k);
        t->class_area[c] = 300.5 + 10 * c + k;
    }
    t->joint_length = 900.125 + k;
    t->moulds_of[TYPE_SP] = (size_t)(7 + k);
    t->moulds_of[TYPE_DP] = (size_t)(11 + k);
    t->moulds = t->moulds_of[TYPE_SP] + t->moulds_of[TYPE_DP];
    t->largest_family = (size_t)(5 + k);
    t->singleton_families = (size_t)(3 + k);
    t->area_cost = 1400.5 + k;
    t->panel_cost = 4000.5 + k;
    t->joint_cost = 9001.25 + k;
    t->mould_cost = 60000.75 + k;
    t->max_gap = 0.0045 + 0.001 * k;   /* m, stored in mm */
    t->mean_gap = 0.001125 + 0.001 * k;
    t->max_kink = 0.05 + 0.01 * k;     /* rad, stored in degrees */
    t->mean_kink = 0.0125 + 0.01 * k;
    t->gaps_over = (size_t)(13 + k);
    t->kinks_over = (size_t)(17 + k);
    t->sp_misfits = (size_t)(19 + k);
    t->sp_fitted = (size_t)(23 + k);
    t->sp_min_radius = 4.375 + k;
    t->min_panel_area = 0.125 + k;
    t->min_panel_width = 0.3125 + k;
    t->slivers = (size_t)(29 + k);
    t->planarized = (k + 1) % 2;
    t->closeness_reached = 0.0046875 + k;
    t->closeness_mean = 0.001953125 + k;
    t->planarity_reached = 0.00048828125 + k;
    t->planar_over = (size_t)(31 + k);
    t->seams = (size_t)(37 + k);
    t->seam_length = 12.5 + k;
    t->seam_max_gap = 0.0015625 + k;
    t->seam_max_kink = 0.015625 + k;
    t->seam_max_crease = 0.78125 + k;
    t->seam_gaps_over = (size_t)(41 + k);
    t->seam_kinks_over = (size_t)(43 + k);
    o.module_w = 1.25 + k;
    o.module_h = 0.75 + k;
    o.modules = (size_t)(2 + k);
    return o;
}

/* The value of column name of o, read from the fields by hand: the truth
 * the registry's offsets and types are held to. */
static double by_hand(const struct option_row *o, const char *name)
{
    const struct option_totals *t = &o->totals;
    const struct {
        const char *name;
        double value;
    } fields[] = {
        {"number", (double)o->number}, {"generation", o->generation},
        {"nu", o->nu}, {"nv", o->nv}, {"threshold_mm", o->threshold_mm},
        {"panels", (double)t->panels},
        {"fp_count", (double)t->count[TYPE_FP]},
        {"sp_count", (double)t->count[TYPE_SP]},
        {"dp_count", (double)t->count[TYPE_DP]},
        {"fp_area", t->area_of[TYPE_FP]}, {"sp_area", t->area_of[TYPE_SP]},
        {"dp_area", t->area_of[TYPE_DP]}, {"area", t->area},
        {"fp_cost", t->cost_of[TYPE_FP]}, {"sp_cost", t->cost_of[TYPE_SP]},
        {"dp_cost", t->cost_of[TYPE_DP]}, {"cost", t->cost},
        {"planarity", t->planarity}, {"max_deviation", t->max_deviation},
        {"max_panel_area", t->max_panel_area}, {"p_dist", t->p_dist},
        {"feasible", t->feasible},
        {"rank", o->rank}, {"crowding", o->crowding}, {"knee", o->knee},
        {"joint_length", t->joint_length}, {"moulds", (double)t->moulds},
        {"sp_moulds", (double)t->moulds_of[TYPE_SP]},
        {"dp_moulds", (double)t->moulds_of[TYPE_DP]},
        {"largest_family", (double)t->largest_family},
        {"single_moulds", (double)t->singleton_families},
        {"area_cost", t->area_cost}, {"panel_cost", t->panel_cost}, {"joint_cost", t->joint_cost},
        {"mould_cost", t->mould_cost},
        /* held in m and rad, the columns in mm and degrees: the
         * plain expressions, written out here as the truth */
        {"max_gap", t->max_gap * 1000}, {"mean_gap", t->mean_gap * 1000},
        {"max_kink", t->max_kink * 180 / M_PI},
        {"mean_kink", t->mean_kink * 180 / M_PI},
        {"gaps_over", (double)t->gaps_over},
        {"kinks_over", (double)t->kinks_over},
        {"sp_misfits", (double)t->sp_misfits},
        {"sp_fitted", (double)t->sp_fitted},
        {"sp_min_radius", t->sp_min_radius},
        {"min_panel_area", t->min_panel_area},
        {"min_panel_width", t->min_panel_width},
        {"slivers", (double)t->slivers},
        {"module_w", o->module_w},
        {"module_h", o->module_h},
        {"modules", (double)o->modules},
        {"planarized", t->planarized},
        {"closeness_reached", t->closeness_reached},
        {"closeness_mean", t->closeness_mean},
        {"planarity_reached", t->planarity_reached},
        {"planar_over", (double)t->planar_over},
        {"seams", (double)t->seams},
        {"seam_length", t->seam_length},
        {"seam_max_gap", t->seam_max_gap * 1000},
        {"seam_max_kink", t->seam_max_kink * 180 / M_PI},
        {"seam_max_crease", t->seam_max_crease * 180 / M_PI},
        {"seam_gaps_over", (double)t->seam_gaps_over},
        {"seam_kinks_over", (double)t->seam_kinks_over},
    };
    for (size_t k = 0; k < sizeof fields / sizeof fields[0]; k++)
        if (strcmp(fields[k].name, name) == 0)
            return fields[k].value;
    for (int c = 0; c < CLASS_COUNT; c++) {
        char count[64], area[64];
        const char *class = panel_class_name((enum panel_class)c);
        snprintf(count, sizeof count, "%s_count", class);
        snprintf(area, sizeof area, "%s_area", class);
        if (strcmp(name, count) == 0)
            return (double)t->class_count[c];
        if (strcmp(name, area) == 0)
            return t->class_area[c];
    }
    fail_msg("no field for column %s", name);
    return NAN;
}

/* The registry is the options table of a freshly created store: the same
 * columns in the same order (run, first in the table, last in the
 * registry), integers and reals alike. */
static void test_registry_is_the_table(void **state)
{
    (void)state;
    int64_t run;
    struct store *store = fresh_store(&run);
    store_close(store);
    sqlite3 *db;
    assert_int_equal(sqlite3_open(db_path, &db), SQLITE_OK);
    sqlite3_stmt *s;
    assert_int_equal(sqlite3_prepare_v2(db,
        "SELECT name, type FROM pragma_table_info('options') ORDER BY cid",
        -1, &s, NULL), SQLITE_OK);
    int n = 0;
    while (sqlite3_step(s) == SQLITE_ROW) {
        const char *name = (const char *)sqlite3_column_text(s, 0);
        const char *type = (const char *)sqlite3_column_text(s, 1);
        /* run is the table's first column and the registry's last */
        int k = n == 0 ? OPTION_QUANTITIES - 1 : n - 1;
        assert_true(k < OPTION_QUANTITIES);
        const struct quantity *c = &option_quantities[k];
        if (strcmp(c->name, name) != 0)
            fail_msg("table column %d is %s, registry row %d is %s", n,
                     name, k, c->name);
        assert_string_equal(type, c->field == FIELD_DOUBLE ? "REAL"
                                                           : "INTEGER");
        n++;
    }
    sqlite3_finalize(s);
    /* option_held (schema v16): run, option, then a column for each row
     * core holds in m or rad and the table in mm or degrees, and no
     * other. */
    assert_int_equal(sqlite3_prepare_v2(db,
        "SELECT name FROM pragma_table_info('option_held') WHERE cid > 1"
        " ORDER BY cid", -1, &s, NULL), SQLITE_OK);
    int held = 0;
    while (sqlite3_step(s) == SQLITE_ROW) {
        const char *name = (const char *)sqlite3_column_text(s, 0);
        const struct quantity *c = quantity_named(name);
        if (c == NULL || c->stored == STORED_AS_HELD)
            fail_msg("option_held holds %s, the registry does not", name);
        held++;
    }
    sqlite3_finalize(s);
    int held_in_si = 0;
    for (int k = 0; k < OPTION_QUANTITIES; k++)
        held_in_si += option_quantities[k].stored != STORED_AS_HELD;
    assert_int_equal(held, held_in_si);
    assert_int_equal(held_in_si, 7);
    sqlite3_close(db);
    if (n != OPTION_QUANTITIES)
        fail_msg("the options table has %d columns, the registry %d: a row"
                 " without its migration (store/schema.c), or a column"
                 " without its row", n, OPTION_QUANTITIES);
    store_fixture_remove(db_path);

    /* Every row says what it needs to be shown and filtered. */
    for (int k = 0; k < OPTION_QUANTITIES; k++) {
        const struct quantity *c = &option_quantities[k];
        assert_ptr_equal(quantity_named(c->name), c);
        assert_non_null(c->label);
        assert_non_null(c->heading);
        assert_non_null(c->unit);
        assert_true(c->scale > 0);
        assert_true(c->decimals >= 0 && c->list_decimals >= 0);
        assert_true((c->example == NULL) == (c->yes_no != 0));
        assert_true((c->field == FIELD_NONE) ==
                    (c->writer == WRITTEN_AS_KEY));
    }
    assert_null(quantity_named("nosuch"));
}

/* Each column reads its own field of an option_row. */
static void test_values_read_the_row(void **state)
{
    (void)state;
    struct option_row o = option_k(3);
    o.rank = 2;
    o.crowding = 0.375;
    o.knee = 1;
    for (int k = 0; k < OPTION_QUANTITIES; k++) {
        const struct quantity *c = &option_quantities[k];
        double v = quantity_value(c, &o);
        if (c->writer == WRITTEN_AS_KEY) {
            assert_true(isnan(v));
            continue;
        }
        if (v != by_hand(&o, c->name))
            fail_msg("%s reads %g, its field holds %g", c->name, v,
                     by_hand(&o, c->name));
        assert_true(v == option_quantity_value(&o, c->name));
    }
    assert_true(isnan(option_quantity_value(&o, "nosuch")));
}

/* The objectives a search may take (core/search/metric.h) are
 * quantities, and an objective's value is its column's: the front a run
 * ranks by is the front the tables show. The names users' scripts give
 * --objectives (the nineteen of every Facet since schema v7) all still
 * parse, and sp_min_radius (schema v10), min_panel_area, min_panel_width
 * and slivers (v12). */
static void test_metrics_are_columns(void **state)
{
    (void)state;
    struct option_row o = option_k(4);
    static const char *const names[] = {
        "cost", "planarity", "dp_area", "fp_area", "sp_area", "panels",
        "fp_count", "sp_count", "dp_count", "max_deviation",
        "max_panel_area", "p_dist", "moulds", "sp_moulds", "dp_moulds",
        "joint_length", "max_gap", "max_kink", "sp_misfits",
        "sp_min_radius", "min_panel_area", "min_panel_width", "slivers"};
    int objectives = 0;
    for (int k = 0; k < OPTION_QUANTITIES; k++)
        objectives += option_quantities[k].objective;
    assert_int_equal(objectives, (int)(sizeof names / sizeof names[0]));
    for (size_t m = 0; m < sizeof names / sizeof names[0]; m++) {
        struct objective parsed[OBJECTIVES_MAX];
        int count;
        struct facet_error err;
        char text[64];
        snprintf(text, sizeof text, "max:%s", names[m]);
        if (objectives_parse(text, "objectives", parsed, &count, &err) !=
            FACET_OK)
            fail_msg("objective %s: %s", names[m], err.message);
        assert_int_equal(count, 1);
        assert_string_equal(parsed[0].quantity->name, names[m]);
        assert_true(objective_value(&o.totals, &parsed[0]) ==
                    -quantity_value(parsed[0].quantity, &o));
    }
    for (int k = 0; k < OPTION_QUANTITIES; k++) {
        const struct quantity *q = &option_quantities[k];
        if (!quantity_in_totals(q))
            continue;
        double a = quantity_of_totals(q, &o.totals);
        double b = quantity_value(q, &o);
        if (!(a == b || (isnan(a) && isnan(b))))
            fail_msg("%s: %g in the totals, %g in the row", q->name, a, b);
    }
}

/* A fresh store with ROWS options of one run, ranked (rank k % 3 + 1,
 * crowding infinite on the first option, the knee on the second): the
 * rows as stored into rows, the run into *run, and SQLite's own handle
 * on the file into *db (unless db is NULL). */
static struct store *ranked_store(int64_t *run, struct option_row rows[ROWS],
                                  sqlite3 **db)
{
    struct store *store = fresh_store(run);
    struct facet_error err;
    int64_t numbers[ROWS];
    int rank[ROWS];
    double crowding[ROWS];
    for (int k = 0; k < ROWS; k++) {
        rows[k] = option_k(k);
        numbers[k] = rows[k].number;
        rows[k].rank = rank[k] = k % 3 + 1;
        rows[k].crowding = crowding[k] = k == 0 ? INFINITY : 0.125 * k;
        rows[k].knee = k == 1;
    }
    /* As a project's options (no surfaces): their module columns are
     * written, which a single surface's are not. */
    assert_int_equal(store_project_options_put(store, *run, rows, ROWS, NULL,
                                               0, &err), FACET_OK);
    assert_int_equal(store_options_set_pareto(store, *run, numbers, rank,
                                              crowding, ROWS, 2, 0.5, &err),
                     FACET_OK);
    if (db != NULL)
        assert_int_equal(sqlite3_open(db_path, db), SQLITE_OK);
    return store;
}

/* What SQLite holds under each column's name is the field of the row
 * stored, and reading the option back gives every field again. */
static void test_store_round_trip(void **state)
{
    (void)state;
    int64_t run;
    struct option_row rows[ROWS];
    sqlite3 *db;
    struct store *store = ranked_store(&run, rows, &db);
    for (int k = 0; k < OPTION_QUANTITIES; k++) {
        const char *name = option_quantities[k].name;
        if (option_quantities[k].writer == WRITTEN_AS_KEY)
            continue;
        char sql[160];
        snprintf(sql, sizeof sql, "SELECT \"%s\" FROM options"
                 " WHERE run = ?1 ORDER BY number", name);
        sqlite3_stmt *s;
        assert_int_equal(sqlite3_prepare_v2(db, sql, -1, &s, NULL),
                         SQLITE_OK);
        sqlite3_bind_int64(s, 1, run);
        for (int r = 0; r < ROWS; r++) {
            assert_int_equal(sqlite3_step(s), SQLITE_ROW);
            double want = by_hand(&rows[r], name);
            /* crowding: NULL stands for infinity (docs/store.md) */
            double got = sqlite3_column_type(s, 0) == SQLITE_NULL
                             ? INFINITY : sqlite3_column_double(s, 0);
            if (got != want)
                fail_msg("option %d: column %s holds %g, the row %g", r + 1,
                         name, got, want);
        }
        sqlite3_finalize(s);
    }
    sqlite3_close(db);
    struct facet_error err;
    for (int r = 0; r < ROWS; r++) {
        struct option_row back;
        assert_int_equal(store_option_get(store, run, r + 1, &back, &err),
                         FACET_OK);
        for (int k = 0; k < OPTION_QUANTITIES; k++)
            if (option_quantities[k].writer != WRITTEN_AS_KEY)
                assert_true(by_hand(&back, option_quantities[k].name) ==
                            by_hand(&rows[r], option_quantities[k].name));
    }
    store_close(store);
    store_fixture_remove(db_path);
}

struct gathered {
    int64_t numbers[ROWS];
    int n;
};

static int gather(void *context, int64_t run, const struct option_row *o)
{
    (void)run;
    struct gathered *g = context;
    if (g->n < ROWS)
        g->numbers[g->n] = o->number;
    g->n++;
    return 0;
}

static int gather_browsed(void *context, const struct option_row *o)
{
    return gather(context, 0, o);
}

/* Every column can be named in a --where and a --sort: the filter
 * compiles, SQLite accepts the query, it passes the options SQLite counts
 * by hand, and the sort puts them in the column's order. */
static void test_every_column_filters_and_sorts(void **state)
{
    (void)state;
    int64_t run;
    struct option_row rows[ROWS];
    sqlite3 *db;
    struct store *store = ranked_store(&run, rows, &db);
    struct facet_error err;
    for (int k = 0; k < OPTION_QUANTITIES; k++) {
        const struct quantity *c = &option_quantities[k];
        /* a value the third option has, so some pass and some do not */
        double middle = c->writer == WRITTEN_AS_KEY
                            ? (double)run : by_hand(&rows[2], c->name);
        char where[128], sql[256];
        if (c->yes_no)
            snprintf(where, sizeof where, "%s", c->name);
        else
            snprintf(where, sizeof where, "%s >= %.17g", c->name, middle);
        struct filter *f;
        if (filter_compile(where, &f, &err) != FACET_OK)
            fail_msg("--where '%s': %s", where, err.message);
        /* crowding: NULL is infinite (docs/store.md) */
        snprintf(sql, sizeof sql, "SELECT count(*) FROM options"
                 " WHERE run = ?1 AND %s%s%s%s",
                 strcmp(c->name, "crowding") == 0 ? "ifnull(crowding, 1e999)"
                                                  : "\"",
                 strcmp(c->name, "crowding") == 0 ? "" : c->name,
                 strcmp(c->name, "crowding") == 0 ? "" : "\"",
                 c->yes_no ? " != 0" : " >= ?2");
        sqlite3_stmt *s;
        assert_int_equal(sqlite3_prepare_v2(db, sql, -1, &s, NULL),
                         SQLITE_OK);
        sqlite3_bind_int64(s, 1, run);
        sqlite3_bind_double(s, 2, middle);
        assert_int_equal(sqlite3_step(s), SQLITE_ROW);
        int want = sqlite3_column_int(s, 0);
        sqlite3_finalize(s);
        assert_true(c->writer == WRITTEN_AS_KEY ||
                    (want > 0 && want < ROWS));

        struct option_query q = {run, 0, f, c->name, 0, 0, 0, 0};
        struct gathered g = {{0}, 0};
        if (store_options_query(store, &q, gather, &g, &err) != FACET_OK)
            fail_msg("--where '%s' --sort %s: %s", where, c->name,
                     err.message);
        if (g.n != want)
            fail_msg("--where '%s': %d options, SQLite counts %d", where,
                     g.n, want);
        assert_int_equal(store_options_sort_check(c->name, &err), FACET_OK);

        /* sorted by the column alone: in its order, every option */
        q.where = NULL;
        g.n = 0;
        assert_int_equal(store_options_query(store, &q, gather, &g, &err),
                         FACET_OK);
        assert_int_equal(g.n, ROWS);
        for (int r = 1; r < ROWS && c->writer != WRITTEN_AS_KEY; r++)
            assert_true(by_hand(&rows[g.numbers[r - 1] - 1], c->name) <=
                        by_hand(&rows[g.numbers[r] - 1], c->name));

        /* the workbench's browse takes it as a key and a filter */
        if (c->writer != WRITTEN_AS_KEY) {
            struct option_browse b;
            memset(&b, 0, sizeof b);
            b.run = run;
            b.where = f;
            b.keys[0] = (struct browse_key){c->name, 1};
            b.nkeys = 1;
            g.n = 0;
            if (store_browse_page(store, &b, NULL, 0, ROWS, gather_browsed,
                                  &g, &err) != FACET_OK)
                fail_msg("browse by %s: %s", c->name, err.message);
            assert_int_equal(g.n, want);
        }
        filter_free(f);
    }
    sqlite3_close(db);
    store_close(store);
    store_fixture_remove(db_path);
}


/* The unit a column is stored in, by docs/store.md's rule (lengths m, areas
 * m^2, money USD, the threshold mm; a name ending in length is a length;
 * a joint's gap mm and kink degrees)
 * read off its name: the test's own
 * reading, not the registry's. */
static const char *stored_unit_by_name(const char *name)
{
    size_t n = strlen(name);
    if (strcmp(name, "threshold_mm") == 0)
        return "mm";
    if (n >= 4 && strcmp(name + n - 4, "cost") == 0)
        return "USD";
    if (n >= 4 && strcmp(name + n - 4, "area") == 0)
        return "m^2";
    if (n >= 6 && strcmp(name + n - 6, "length") == 0)
        return "m";
    if (strcmp(name, "planarity") == 0 || strcmp(name, "max_deviation") == 0)
        return "m";
    if (strcmp(name, "p_dist") == 0)
        return "m^4";
    /* a project's module, its width and height in m (docs/store.md) */
    if (strcmp(name, "module_w") == 0 || strcmp(name, "module_h") == 0)
        return "m";
    /* a radius in m (docs/store.md) */
    if (strcmp(name, "sp_min_radius") == 0)
        return "m";
    /* a panel's width in m, shown in mm (docs/method.md: Slivers) */
    if (strcmp(name, "min_panel_width") == 0)
        return "m";
    /* how far a planarized option's corners ended from the surface, in m
     * (docs/store.md); its planarity a ratio, no unit */
    if (strncmp(name, "closeness_", 10) == 0)
        return "m";
    /* a building's seams (docs/store.md, schema v16): the gap in mm, the
     * kink added and the crease in degrees, as the option's own */
    if (n >= 7 && strcmp(name + n - 7, "_crease") == 0)
        return "deg";
    /* a joint's gap in mm, its kink in degrees (docs/method.md: Panels as
     * built) */
    if (n >= 4 && strcmp(name + n - 4, "_gap") == 0)
        return "mm";
    if (n >= 5 && strcmp(name + n - 5, "_kink") == 0)
        return "deg";
    return "";
}

/* Every column's stored unit is the one its name says, and the one a plot
 * writes on an axis that shows it (the plot draws stored values: a
 * deviation in m, though the tables show it in mm). */
static void test_plot_axis_units(void **state)
{
    (void)state;
    struct option_row rows[ROWS];
    int64_t run;
    struct store *store = ranked_store(&run, rows, NULL);
    char svg_path[80];
    snprintf(svg_path, sizeof svg_path, "/tmp/facet_test_axis_%d.svg",
             (int)getpid());
    for (int k = 0; k < OPTION_QUANTITIES; k++) {
        const struct quantity *c = &option_quantities[k];
        if (c->writer == WRITTEN_AS_KEY)
            continue;
        const char *want = stored_unit_by_name(c->name);
        if (strcmp(c->stored_unit, want) != 0)
            fail_msg("%s is stored in '%s', the registry says '%s'",
                     c->name, want, c->stored_unit);
        if (c->scale == 1 && strcmp(c->unit, c->stored_unit) != 0)
            fail_msg("%s is shown as stored, in '%s' not '%s'", c->name,
                     c->unit, c->stored_unit);
        /* A front's ends have an infinite crowding, which a plot refuses
         * (study_plot: "a non-finite value"). */
        if (strcmp(c->name, "crowding") == 0)
            continue;
        struct plot_request r;
        memset(&r, 0, sizeof r);
        r.runs = &run;
        r.nruns = 1;
        r.x = c->name;
        r.y = "cost";
        r.force = 1;
        struct facet_error err;
        if (study_plot(store, &r, svg_path, &err) != FACET_OK)
            fail_msg("plot of %s: %s", c->name, err.message);
        FILE *f = fopen(svg_path, "r");
        assert_non_null(f);
        static char svg[1 << 20];
        size_t n = fread(svg, 1, sizeof svg - 1, f);
        svg[n] = '\0';
        fclose(f);
        char label[128];
        if (want[0] != '\0')
            snprintf(label, sizeof label, ">%s (%s)<", c->name, want);
        else
            snprintf(label, sizeof label, ">%s<", c->name);
        if (strstr(svg, label) == NULL)
            fail_msg("the plot of %s has no axis %s", c->name, label);
    }
    unlink(svg_path);
    store_close(store);
    store_fixture_remove(db_path);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_registry_is_the_table),
        cmocka_unit_test(test_values_read_the_row),
        cmocka_unit_test(test_metrics_are_columns),
        cmocka_unit_test(test_store_round_trip),
        cmocka_unit_test(test_plot_axis_units),
        cmocka_unit_test(test_every_column_filters_and_sorts),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
