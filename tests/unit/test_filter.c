/*
 * test_filter.c: the --where language. Precedence, parentheses, every
 * operator, aliases and case against hand-written truth tables and the text
 * Facet shows back; the exact column of every error message; hostile input
 * (deep nesting, huge text, NaN and infinity, random bytes); and an oracle:
 * SQLite running filter_sql over a table of pseudo-random options (with
 * NULLs and infinities) must select exactly the options filter_match
 * accepts, for hand-picked and randomly generated expressions.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <sqlite3.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/base/rng.h"
#include "store/filter.h"
#include "store/filter_sql.h"
#include "store/store.h"
#include "tests/support/filter_oracle.h"

enum { NCOLUMNS = OPTION_QUANTITIES, NROWS = 400 };

/* ---- helpers ------------------------------------------------------------- */

static int column_index(const char *name)
{
    return oracle_column(name);
}

/* Fails the test when filter_match asks for a name that is not a
 * canonical column: aliases and case must be resolved before. */
static double row_value(void *context, const char *column)
{
    int k = column_index(column);
    if (k < 0)
        fail_msg("filter_match asked for column '%s'", column);
    return ((const struct oracle_row *)context)->v[k];
}

static void set(struct oracle_row *r, const char *column, double value)
{
    int k = column_index(column);
    assert_true(k >= 0);
    r->v[k] = value;
}

static struct oracle_row zero_row(void)
{
    struct oracle_row r;
    for (int k = 0; k < NCOLUMNS; k++)
        r.v[k] = 0;
    return r;
}

static struct filter *compile_ok(const char *text)
{
    struct filter *f = NULL;
    struct facet_error err;
    int rc = filter_compile(text, &f, &err);
    if (rc != FACET_OK)
        fail_msg("'%s' did not compile: %s", text, err.message);
    assert_non_null(f);
    return f;
}

static void expect_text(const char *text, const char *expected)
{
    struct filter *f = compile_ok(text);
    assert_string_equal(filter_text(f), expected);
    filter_free(f);
}

static void expect_error(const char *text, const char *message)
{
    struct filter *f = (struct filter *)&f;  /* must be reset to NULL */
    struct facet_error err;
    int rc = filter_compile(text, &f, &err);
    if (rc != FACET_EINPUT)
        fail_msg("'%s' compiled (rc %d), expected: %s", text, rc, message);
    assert_null(f);
    assert_int_equal(err.code, FACET_EINPUT);
    /* about the filter: each front-end names its own field for it */
    assert_int_equal(err.setting, FACET_SETTING_FILTER);
    assert_string_equal(err.message, message);
}

/* text fails with a one-line message that starts with start and holds
 * part (unless NULL) somewhere after it. */
static void expect_error_parts(const char *text, const char *start,
                               const char *part)
{
    struct filter *f = NULL;
    struct facet_error err;
    assert_int_equal(filter_compile(text, &f, &err), FACET_EINPUT);
    assert_null(f);
    if (strncmp(err.message, start, strlen(start)) != 0 ||
        (part != NULL && strstr(err.message + strlen(start), part) == NULL))
        fail_msg("'%.60s' gave '%s'", text, err.message);
    assert_true(strlen(err.message) < sizeof err.message - 1);
}

static bool matches(const char *text, const struct oracle_row *r)
{
    struct filter *f = compile_ok(text);
    bool result = filter_match(f, row_value, (void *)r) != 0;
    filter_free(f);
    return result;
}

/* ---- the language -------------------------------------------------------- */

static void test_columns_table(void **state)
{
    (void)state;
    const char *expected[] = {
        "number", "generation", "nu", "nv", "threshold_mm", "panels",
        "fp_count", "sp_count", "dp_count", "fp_area", "sp_area", "dp_area",
        "area", "fp_cost", "sp_cost", "dp_cost", "cost", "planarity",
        "max_deviation", "max_panel_area", "p_dist", "feasible",
        "convex_feature_curve_count", "convex_feature_curve_area",
        "saddle_count", "saddle_area", "concave_feature_curve_count",
        "concave_feature_curve_area", "ruled_convex_count",
        "ruled_convex_area", "flat_count", "flat_area", "ruled_concave_count",
        "ruled_concave_area", "convex_round_count", "convex_round_area",
        "concave_round_count", "concave_round_area",
        "rank", "crowding", "knee", "joint_length", "moulds", "sp_moulds",
        "dp_moulds", "largest_family", "single_moulds", "area_cost",
        "panel_cost", "joint_cost", "mould_cost", "max_gap", "mean_gap",
        "max_kink", "mean_kink", "gaps_over", "kinks_over", "sp_misfits",
        "sp_fitted", "module_w", "module_h", "modules", "sp_min_radius",
        "min_panel_area", "min_panel_width", "slivers", "planarized",
        "closeness_reached", "closeness_mean", "planarity_reached",
        "planar_over", "seams", "seam_length", "seam_max_gap",
        "seam_max_kink", "seam_max_crease", "seam_gaps_over",
        "seam_kinks_over", "run",
    };
    for (int k = 0; k < NCOLUMNS; k++)
        assert_string_equal(option_quantities[k].name, expected[k]);

    /* Every column can be compared; only feasible, knee and planarized
     * (yes or no) stand alone. */
    char text[64];
    struct facet_error err;
    for (int k = 0; k < NCOLUMNS; k++) {
        const char *c = option_quantities[k].name;
        snprintf(text, sizeof text, "%s >= 2", c);
        struct filter *f = compile_ok(text);
        char expected_sql[160];
        snprintf(expected_sql, sizeof expected_sql,
                 strcmp(c, "crowding") == 0
                     ? "ifnull(\"%s\", CASE WHEN ifnull(\"rank\", 0) > 0 THEN "
                       "1e999 ELSE 0 END) >= ?1"
                 : strcmp(c, "rank") == 0 ? "ifnull(\"%s\", 0) >= ?1"
                                          : "\"%s\" >= ?1", c);
        char *sql = filter_sql(f, 1);
        assert_string_equal(sql, expected_sql);
        free(sql);
        filter_free(f);
        bool yes_no = strcmp(c, "feasible") == 0 || strcmp(c, "knee") == 0 ||
                      strcmp(c, "planarized") == 0;
        struct filter *g = NULL;
        int rc = filter_compile(c, &g, &err);
        assert_int_equal(rc, yes_no ? FACET_OK : FACET_EINPUT);
        filter_free(g);
    }
}

static void test_empty_matches_everything(void **state)
{
    (void)state;
    const char *texts[] = {"", "   ", " \t\r\n\v\f ", NULL};
    for (size_t k = 0; k < sizeof texts / sizeof *texts; k++) {
        struct filter *f = compile_ok(texts[k]);
        assert_string_equal(filter_text(f), "");
        assert_int_equal(filter_param_count(f), 0);
        char *sql = filter_sql(f, 5);
        assert_string_equal(sql, "1");
        free(sql);
        struct oracle_row r = zero_row();
        r.v[column_index("cost")] = NAN;
        assert_true(filter_match(f, row_value, &r));
        filter_free(f);
    }
    /* NULL is the empty filter everywhere, and freeing it is fine. */
    char *sql = filter_sql(NULL, 1);
    assert_string_equal(sql, "1");
    free(sql);
    assert_string_equal(filter_text(NULL), "");
    assert_int_equal(filter_param_count(NULL), 0);
    assert_true(filter_match(NULL, row_value, NULL));
    filter_free(NULL);
}

/* Every combination of feasible, knee and rank 1 / not rank 1. */
static void truth_table(const char *text, bool (*expected)(bool, bool, bool))
{
    struct filter *f = compile_ok(text);
    for (int bits = 0; bits < 8; bits++) {
        bool a = bits & 1, b = bits & 2, c = bits & 4;
        struct oracle_row r = zero_row();
        set(&r, "feasible", a);
        set(&r, "knee", b);
        set(&r, "rank", c ? 1 : 2);
        bool got = filter_match(f, row_value, &r) != 0;
        if (got != expected(a, b, c))
            fail_msg("'%s' with feasible=%d knee=%d pareto=%d gave %d", text,
                     a, b, c, got);
    }
    filter_free(f);
}

static bool or_of_and(bool a, bool b, bool c) { return a || (b && c); }
static bool and_of_or(bool a, bool b, bool c) { return (a && b) || c; }
static bool not_first(bool a, bool b, bool c) { (void)c; return !a && b; }
static bool not_all(bool a, bool b, bool c) { return !(a || (b && c)); }
static bool grouped(bool a, bool b, bool c) { return (a || b) && c; }
static bool double_not(bool a, bool b, bool c) { (void)b; (void)c; return a; }
static bool mixed(bool a, bool b, bool c) { return (!a && !b) || (a && c); }

static void test_precedence(void **state)
{
    (void)state;
    /* and binds tighter than or, whichever comes first. */
    expect_text("feasible or knee and pareto",
                "feasible or (knee and pareto)");
    expect_text("feasible and knee or pareto",
                "(feasible and knee) or pareto");
    truth_table("feasible or knee and pareto", or_of_and);
    truth_table("feasible and knee or pareto", and_of_or);
    /* not binds tighter than and. */
    expect_text("not feasible and knee", "(not feasible) and knee");
    expect_text("not feasible or knee", "(not feasible) or knee");
    truth_table("not feasible and knee", not_first);
    truth_table("!feasible && knee", not_first);
    truth_table("not not feasible", double_not);
    truth_table("! ! feasible", double_not);
    expect_text("not not feasible", "not not feasible");
    truth_table("not feasible and not knee or feasible and pareto", mixed);
    truth_table("!feasible&&!knee||feasible&&pareto", mixed);
    /* Chains are one level, however long. */
    expect_text("feasible and knee and pareto",
                "feasible and knee and pareto");
    expect_text("cost < 1.5e6 and dp_area <= 900 or pareto",
                "((cost < 1500000) and (dp_area <= 900)) or pareto");
    expect_text("(nu >= 30 or nv = 40) and not feasible",
                "((nu >= 30) or (nv = 40)) and (not feasible)");
}

static void test_parentheses(void **state)
{
    (void)state;
    truth_table("(feasible or knee) and pareto", grouped);
    truth_table("not (feasible or knee and pareto)", not_all);
    truth_table("!(feasible||(knee&&pareto))", not_all);
    truth_table("((((feasible)) or ((knee)) and (pareto)))", or_of_and);
    expect_text("(feasible or knee) and pareto",
                "(feasible or knee) and pareto");
    expect_text("((((cost < 5))))", "cost < 5");
    expect_text("(cost<5)", "cost < 5");
    expect_text("not (cost < 5)", "not (cost < 5)");
    expect_text("feasible and (knee and pareto)",
                "feasible and (knee and pareto)");
    expect_text("(feasible or knee) or (pareto and cost > 1)",
                "(feasible or knee) or (pareto and (cost > 1))");
}

/* Whether text matches options of cost 4, 5 and 6. */
static void expect_against_five(const char *text, bool below, bool equal,
                                bool above)
{
    struct oracle_row r = zero_row();
    set(&r, "cost", 4);
    assert_int_equal(matches(text, &r), below);
    set(&r, "cost", 5);
    assert_int_equal(matches(text, &r), equal);
    set(&r, "cost", 6);
    assert_int_equal(matches(text, &r), above);
}

static void test_every_operator(void **state)
{
    (void)state;
    static const struct {
        const char *op, *shown;
        bool below, equal, above;  /* cost 4, 5, 6 against 5 */
    } ops[] = {
        {"<", "<", 1, 0, 0},   {"<=", "<=", 1, 1, 0}, {">", ">", 0, 0, 1},
        {">=", ">=", 0, 1, 1}, {"=", "=", 0, 1, 0},   {"==", "=", 0, 1, 0},
        {"!=", "!=", 1, 0, 1}, {"<>", "!=", 1, 0, 1},
    };
    char text[64], shown[64];
    for (size_t k = 0; k < sizeof ops / sizeof *ops; k++) {
        for (int spaced = 0; spaced < 2; spaced++) {
            snprintf(text, sizeof text, spaced ? "cost %s 5" : "cost%s5",
                     ops[k].op);
            snprintf(shown, sizeof shown, "cost %s 5", ops[k].shown);
            expect_text(text, shown);
            expect_against_five(text, ops[k].below, ops[k].equal,
                                ops[k].above);
            /* NUMBER OP COLUMN means the same with the sides swapped:
             * 5 < cost is cost > 5. */
            snprintf(text, sizeof text, spaced ? "5 %s cost" : "5%scost",
                     ops[k].op);
            expect_against_five(text, ops[k].above, ops[k].equal,
                                ops[k].below);
        }
    }
    expect_text("5 < cost", "cost > 5");
    expect_text("5 <= cost", "cost >= 5");
    expect_text("5 > cost", "cost < 5");
    expect_text("5 >= cost", "cost <= 5");
    expect_text("5 == cost", "cost = 5");
    expect_text("5 <> cost", "cost != 5");
    /* Yes/no columns may also be compared, like any column. */
    expect_text("feasible = 0", "feasible = 0");
    expect_text("knee != 1", "knee != 1");
}

static void test_aliases_and_case(void **state)
{
    (void)state;
    expect_text("u = 10", "nu = 10");
    expect_text("V >= 3", "nv >= 3");
    expect_text("threshold <= 2.5", "threshold_mm <= 2.5");
    expect_text("THRESHOLD_MM < 1", "threshold_mm < 1");
    expect_text("3 < U", "nu > 3");
    expect_text("COST < 5 AND Not KNEE OR PaReTo",
                "((cost < 5) and (not knee)) or pareto");
    expect_text("Feasible And DP_AREA <= 900 oR fEaSiBlE",
                "(feasible and (dp_area <= 900)) or feasible");
    expect_text("cost < 1.5E6", "cost < 1500000");

    struct oracle_row r = zero_row();
    set(&r, "nu", 10);
    set(&r, "nv", 3);
    set(&r, "threshold_mm", 2.5);
    assert_true(matches("U = 10 and v = 3 and Threshold = 2.5", &r));
    assert_false(matches("u = 3", &r));
    /* row_value fails the test for any name but the canonical one. */
    assert_true(matches("NU = 10 AND Nv = 3 And THRESHOLD = 2.5", &r));
}

static void test_numbers(void **state)
{
    (void)state;
    static const struct {
        const char *text;
        double value;
    } cases[] = {
        {"cost < 1.5e6", 1.5e6},   {"cost < 1.5M", 1.5e6},
        {"cost < 2k", 2000},       {"cost < 2K", 2000},
        {"cost < .5", 0.5},        {"cost < 5.", 5},
        {"cost < -3", -3},         {"cost < +3", 3},
        {"cost < 1e-3", 1e-3},     {"cost < 2.5E+2", 250},
        {"cost < 0.1k", 100},      {"cost < 1.1k", 1100},
        {"cost < 0.3M", 300000},   {"cost < -.25k", -250},
        {"cost < 0", 0},           {"cost < 1e-320", 1e-320},
        {"cost < 1.7976931348623157e308", 1.7976931348623157e308},
        {"cost<-1", -1},           {"cost<>-1", -1},
    };
    for (size_t k = 0; k < sizeof cases / sizeof *cases; k++) {
        struct filter *f = compile_ok(cases[k].text);
        assert_int_equal(filter_param_count(f), 1);
        /* Exactly the double of the same decimal: a suffix shifts the
         * exponent rather than multiplying. */
        if (filter_param(f, 0) != cases[k].value)
            fail_msg("'%s' gave %.17g", cases[k].text, filter_param(f, 0));
        /* And the number shown reads back as the same double. */
        struct filter *g = compile_ok(filter_text(f));
        assert_string_equal(filter_text(g), filter_text(f));
        assert_true(filter_param(g, 0) == cases[k].value);
        filter_free(g);
        filter_free(f);
    }
    expect_text("cost < 1.5M", "cost < 1500000");
    expect_text("cost < 0.1", "cost < 0.1");
    expect_text("cost < 1e20", "cost < 1e+20");
    expect_text("cost < 123456789.123456789", "cost < 123456789.12345679");
}

/* text gives exactly sql from first_param, with these parameter values. */
static void expect_sql(const char *text, int first_param, const char *sql,
                       const double *params, size_t nparams)
{
    struct filter *f = compile_ok(text);
    char *got = filter_sql(f, first_param);
    assert_string_equal(got, sql);
    free(got);
    assert_int_equal(filter_param_count(f), nparams);
    for (size_t k = 0; k < nparams; k++)
        assert_true(filter_param(f, k) == params[k]);
    filter_free(f);
}

static void test_sql_fragment(void **state)
{
    (void)state;
    const double example[] = {1.5e6, 900};
    expect_sql("cost < 1.5e6 and dp_area <= 900 or pareto", 1,
               "(\"cost\" < ?1 AND \"dp_area\" <= ?2) OR "
               "(\"rank\" IS NOT NULL AND \"rank\" = 1)",
               example, 2);
    expect_sql("cost < 1.5e6 and dp_area <= 900 or pareto", 4,
               "(\"cost\" < ?4 AND \"dp_area\" <= ?5) OR "
               "(\"rank\" IS NOT NULL AND \"rank\" = 1)",
               example, 2);

    /* Parameters in the order written, NUMBER OP COLUMN included; yes/no
     * and not as SQL. */
    const double written[] = {7, 2};
    expect_sql("not (7 > U or knee) and !Feasible and run == 2", 2,
               "(NOT (\"nu\" < ?2 OR \"knee\" != 0)) AND "
               "(NOT (\"feasible\" != 0)) AND \"run\" = ?3",
               written, 2);

    /* Nothing the user typed reaches SQL but through parameters. */
    const double typed[] = {1, 99999, 325};
    expect_sql("COST<1 or THRESHOLD >= 99999 or 3.25e2 != V", 1,
               "\"cost\" < ?1 OR \"threshold_mm\" >= ?2 OR \"nv\" != ?3",
               typed, 3);
}

/* ---- errors -------------------------------------------------------------- */

static void test_error_positions(void **state)
{
    (void)state;
    static const struct {
        const char *text, *message;
    } cases[] = {
        {"cost < 1.5e6 and dp_aera <= 900",
         "column 18: unknown column 'dp_aera' (did you mean "
         "dp_area?)"},
        {"cost <", "column 7: expected a number after '<'"},
        {"cost <= feasible",
         "column 9: expected a number after '<='"},
        {"cost < 5 or (knee))", "column 19: unexpected ')'"},
        {")", "column 1: unexpected ')'"},
        {"nu > 2 and (cost < 5",
         "column 21: missing ')' for the '(' at column 12"},
        {"  (cost < 5", "column 12: missing ')' for the '(' at "
                        "column 3"},
        {"((knee)", "column 8: missing ')' for the '(' at column 1"},
        {"cost 5", "column 6: expected a comparison (<, <=, >, >=, "
                   "=, !=) after 'cost'"},
        {"dp_area cost", "column 9: expected a comparison (<, <=, "
                         ">, >=, =, !=) after 'dp_area'"},
        {"cost !< 5", "column 6: expected a comparison (<, <=, >, "
                      ">=, =, !=) after 'cost'"},
        {"5 and knee", "column 3: expected a comparison (<, <=, >, "
                       ">=, =, !=) after '5'"},
        {"not cost", "column 5: 'cost' is not a yes/no column; "
                     "compare it, e.g. cost < 1e6"},
        {"\t\tcost", "column 3: 'cost' is not a yes/no column; "
                     "compare it, e.g. cost < 1e6"},
        {"knee and U or pareto", "column 10: 'U' is not a yes/no "
                                 "column; compare it, e.g. nu < 30"},
        {"pareto = 1", "column 1: 'pareto' is yes/no and cannot be "
                       "compared; write pareto, or compare rank, e.g. rank "
                       "<= 2"},
        {"1 = Pareto", "column 5: 'Pareto' is yes/no and cannot be "
                       "compared; write pareto, or compare rank, e.g. rank "
                       "<= 2"},
        {"5 < 6", "column 5: expected a column after '<'"},
        {"5 <", "column 4: expected a column after '<'"},
        {"cost < 5 adn nu > 3",
         "column 10: unexpected 'adn' (did you mean and?)"},
        {"cost < 5 nu > 3",
         "column 10: unexpected 'nu'; join conditions with and / "
         "or"},
        {"feasible 1",
         "column 10: unexpected '1'; join conditions with and / "
         "or"},
        {"(cost < 5 knee)",
         "column 11: unexpected 'knee'; join conditions with and / "
         "or"},
        {"cost < 5 < 6",
         "column 10: unexpected '<'; compare one column with one "
         "number at a time, e.g. cost > 5 and cost < 10"},
        {"()", "column 2: expected a condition after '(', not ')'"},
        {"cost < 5 and", "column 13: expected a condition after "
                         "'and'"},
        {"knee or or pareto", "column 9: expected a condition after "
                              "'or', not 'or'"},
        {"not", "column 4: expected a condition after 'not'"},
        {"and knee", "column 1: unexpected 'and'; a condition "
                     "starts with a column, a number, not or '('"},
        {"<= 5", "column 1: unexpected '<='; a condition starts "
                 "with a column, a number, not or '('"},
        {"cost & 5", "column 6: '&' is not an operator; write and "
                     "(or &&)"},
        {"knee | pareto", "column 6: '|' is not an operator; write "
                          "or (or ||)"},
        {"cost < 5 # x", "column 10: unexpected '#'"},
        {"cost < 5 and é", "column 14: unexpected character 'é'"},
        {"cöst < 5", "column 2: unexpected character 'ö'"},
        {"cost < 5m", "column 9: 'm' after a number is ambiguous; "
                      "write k (thousand) or M (million)"},
        {"1e6and", "column 1: malformed number '1e6and'"},
        {"cost < 1.2.3", "column 8: malformed number '1.2.3'"},
        {"cost < 5kg", "column 8: malformed number '5kg'"},
        {"cost < 1e3k", "column 8: number '1e3k' has both an "
                        "exponent and a k/M suffix; write one"},
        {"cost < 1e999", "column 8: number '1e999' is out of "
                         "range"},
        {"cost < -1e999", "column 8: number '-1e999' is out of "
                          "range"},
        {"thresold < 3", "column 1: unknown column 'thresold' (did "
                         "you mean threshold?)"},
        {"paerto", "column 1: unknown column 'paerto' (did you "
                   "mean pareto?)"},
        {"knee and 3 < crowdnig", "column 14: unknown column "
                                  "'crowdnig' (did you mean crowding?)"},
    };
    for (size_t k = 0; k < sizeof cases / sizeof *cases; k++)
        expect_error(cases[k].text, cases[k].message);

    /* With nothing near, the message lists the names instead. */
    expect_error("x < 5", "column 1: unknown column 'x' (columns: "
                           "number, generation, nu, nv, threshold_mm, panels, "
                           "{fp,sp,dp}_count, {fp,sp,dp}_area, area, "
                           "{fp,sp,dp,area,panel,joint,mould}_cost, cost, "
                           "planarity, max_deviation, {max,min}_panel_area, "
                           "p_dist, "
                           "feasible, rank, crowding, knee, "
                           "{joint,seam}_length, "
                           "moulds, {sp,dp,single}_moulds, largest_family, "
                           "{max,mean}_gap, {max,mean}_kink, "
                           "{gaps,kinks,planar}_over, sp_misfits, sp_fitted, "
                           "module_w, module_h, modules, sp_min_radius, "
                           "min_panel_width, slivers, planarized, "
                           "{closeness,planarity}_reached, closeness_mean, "
                           "seams, seam_max_gap, seam_max_kink, "
                           "seam_max_crease, seam_gaps_over, "
                           "seam_kinks_over, "
                           "run, u, v, "
                           "threshold, pareto, CLASS_{count,area})");
}

static void test_nan_and_infinity(void **state)
{
    (void)state;
    const char *texts[] = {
        "cost < nan",  "cost < NaN",  "cost < inf",      "cost < -inf",
        "cost < +INF", "nan > cost",  "cost < Infinity", "knee or -nan < 1",
    };
    for (size_t k = 0; k < sizeof texts / sizeof *texts; k++)
        expect_error_parts(texts[k], "column ",
                           "NaN and infinity are not allowed; write a finite "
                           "number");
    expect_error("cost < nan", "column 8: NaN and infinity are not "
                               "allowed; write a finite number");
    expect_error("knee or -nan < 1", "column 9: NaN and infinity "
                                     "are not allowed; write a finite number");
    /* Numbers too large for a double, written or reached with a suffix. */
    char big[400];
    memset(big, '9', 330);
    strcpy(big + 330, "M > cost");
    expect_error_parts(big, "column 1: number '999",
                       "...' is out of range");
    expect_error("cost < 1e308k", "column 8: number '1e308k' has "
                                  "both an exponent and a k/M suffix; write "
                                  "one");
}

/* "((((knee))))" with depth pairs of parentheses. */
static char *nested(int depth, const char *inner)
{
    size_t n = strlen(inner);
    char *text = malloc(2 * (size_t)depth + n + 1);
    memset(text, '(', (size_t)depth);
    memcpy(text + depth, inner, n);
    memset(text + depth + n, ')', (size_t)depth);
    text[2 * depth + n] = '\0';
    return text;
}

/* A filter compiles only when its text does: the text is shown, copied
 * and brushed back. Found by fuzz_where: 35 nots before a comparison were
 * written back as 70 levels of "not (", past the limit. */
static void test_text_compiles_again(void **state)
{
    (void)state;
    static const char *const tails[] = {"knee", "nv = 40", "(nu < 3 or knee)",
                                        "(a", "cost < 5 and pareto"};
    /* Long: "!" is written back as "not ", four times longer. Found by
     * fuzz_where: 2,470 bytes whose text took 4,600. */
    char *wide = malloc(FILTER_MAX_LENGTH + 1);
    assert_non_null(wide);
    wide[0] = '\0';
    while (strlen(wide) + 16 < FILTER_MAX_LENGTH)
        strcat(wide, strlen(wide) ? " and !!nu = 2" : "!!nu = 2");
    struct filter *long_one = NULL;
    struct facet_error long_err;
    if (filter_compile(wide, &long_one, &long_err) == FACET_OK) {
        struct filter *again = NULL;
        if (filter_compile(filter_text(long_one), &again, &long_err) !=
            FACET_OK)
            fail_msg("a %zu-byte filter compiled, its text did not: %s",
                     strlen(wide), long_err.message);
        filter_free(again);
    }
    filter_free(long_one);
    free(wide);
    for (size_t t = 0; t < sizeof tails / sizeof *tails; t++)
        for (int depth = 0; depth <= FILTER_MAX_DEPTH + 2; depth++) {
            char text[1024] = "";
            for (int k = 0; k < depth; k++)
                strcat(text, k % 3 == 2 ? "!" : "not ");
            strcat(text, tails[t]);
            struct filter *f = NULL, *g = NULL;
            struct facet_error err;
            if (filter_compile(text, &f, &err) != FACET_OK)
                continue;
            if (filter_compile(filter_text(f), &g, &err) != FACET_OK)
                fail_msg("'%s' compiled, its text '%s' did not: %s", text,
                         filter_text(f), err.message);
            assert_string_equal(filter_text(g), filter_text(f));
            filter_free(f);
            filter_free(g);
        }
}

/* Every filter that compiles gives SQL that SQLite parses: at the depth
 * limit, the shapes that take most of its parser stack (an or-and chain,
 * a chain of not ( ... ), plain parentheses, their mix) all run against
 * the oracle table. Found by fuzz_where: 48 nots gave SQL SQLite refused
 * ("parser stack overflow"), an or-and chain overflows past 30 levels. */
static void test_deepest_sql_parses(void **state)
{
    (void)state;
    struct rng rng;
    rng_seed(&rng, 3);
    struct oracle_row *rows = malloc(NROWS * sizeof *rows);
    assert_non_null(rows);
    oracle_random_rows(&rng, rows, NROWS);
    sqlite3 *db = oracle_database(rows, NROWS);
    assert_non_null(db);
    for (int shape = 0; shape < 4; shape++) {
        char text[4096] = "";
        int opened = 0, used = 0;
        for (int k = 0;; k++) {
            char part[64];
            int cost = 1;  /* what the parser counts: each ( and not */
            if (shape == 0 || (shape == 3 && k % 2)) {
                snprintf(part, sizeof part, "nu > %d %s (", k,
                         k % 2 ? "or" : "and");
            } else if (shape == 1 || shape == 3) {
                snprintf(part, sizeof part, "not (");
                cost = 2;
            } else {
                snprintf(part, sizeof part, "(");
            }
            if (used + cost > FILTER_MAX_DEPTH)
                break;
            strcat(text, part);
            used += cost;
            opened++;
        }
        strcat(text, "cost < 1e6");
        for (int k = 0; k < opened; k++)
            strcat(text, ")");
        struct filter *f = compile_ok(text);
        char why[1024];
        if (oracle_compare(db, rows, NROWS, f, why, sizeof why) < 0)
            fail_msg("shape %d at depth %d: %s", shape, FILTER_MAX_DEPTH,
                     why);
        filter_free(f);
    }
    sqlite3_close(db);
    free(rows);
}

static void test_hostile_nesting(void **state)
{
    (void)state;
    char expected[128];

    char *text = nested(FILTER_MAX_DEPTH, "knee");
    struct filter *f = compile_ok(text);
    assert_string_equal(filter_text(f), "knee");
    free(text);
    filter_free(f);

    text = nested(FILTER_MAX_DEPTH + 1, "knee");
    snprintf(expected, sizeof expected,
             "column %d: nested too deeply (more than %d "
             "parentheses and nots)",
             FILTER_MAX_DEPTH + 1, FILTER_MAX_DEPTH);
    expect_error(text, expected);
    free(text);

    /* Within the length limit, as deep as it goes: no stack overflow. */
    text = nested(FILTER_MAX_LENGTH / 2 - 2, "knee");
    expect_error(text, expected);
    free(text);
    text = malloc(FILTER_MAX_LENGTH + 1);
    memset(text, '(', FILTER_MAX_LENGTH);
    text[FILTER_MAX_LENGTH] = '\0';
    expect_error(text, expected);
    free(text);

    /* not counts as a level, alone or mixed with parentheses. */
    size_t cap = 8 * FILTER_MAX_LENGTH;
    text = malloc(cap);
    text[0] = '\0';
    for (int k = 0; k < FILTER_MAX_DEPTH; k++)
        strcat(text, "not ");
    strcat(text, "knee");
    f = compile_ok(text);
    filter_free(f);
    text[0] = '\0';
    for (int k = 0; k < FILTER_MAX_DEPTH + 1; k++)
        strcat(text, "!");
    strcat(text, "knee");
    snprintf(expected, sizeof expected,
             "column %d: nested too deeply (more than %d "
             "parentheses and nots)",
             FILTER_MAX_DEPTH + 1, FILTER_MAX_DEPTH);
    expect_error(text, expected);
    text[0] = '\0';
    for (int k = 0; k < 1000; k++)
        strcat(text, "(!");
    expect_error_parts(text, "column ", "nested too deeply");
    free(text);

    /* Long and/or chains are flat, not deep: 300 terms at depth 1 (as
     * long as their text, "(nu < 1) and knee", fits the length limit). */
    text = malloc(cap);
    text[0] = '\0';
    for (int k = 0; k < 300; k++)
        strcat(text, k == 0 ? "knee" : k % 2 ? " or u<1" : "&&knee");
    assert_true(strlen(text) <= FILTER_MAX_LENGTH);
    f = compile_ok(text);
    assert_int_equal(filter_param_count(f), 150);
    struct oracle_row r = zero_row();
    set(&r, "nu", 0);
    assert_true(filter_match(f, row_value, &r));
    char *sql = filter_sql(f, 1);
    assert_non_null(strstr(sql, "?150"));
    free(sql);
    filter_free(f);
    free(text);
}

static void test_hostile_length(void **state)
{
    (void)state;
    char expected[128];
    snprintf(expected, sizeof expected,
             "column %d: the expression is longer than %d bytes",
             FILTER_MAX_LENGTH + 1, FILTER_MAX_LENGTH);

    /* Exactly the limit is fine; one byte more is not. */
    char *text = malloc(4 * FILTER_MAX_LENGTH);
    memset(text, ' ', FILTER_MAX_LENGTH);
    memcpy(text + FILTER_MAX_LENGTH - 8, "cost < 1", 8);
    text[FILTER_MAX_LENGTH] = '\0';
    struct filter *f = compile_ok(text);
    assert_string_equal(filter_text(f), "cost < 1");
    filter_free(f);
    text[FILTER_MAX_LENGTH] = ' ';
    text[FILTER_MAX_LENGTH + 1] = '\0';
    expect_error(text, expected);
    free(text);

    /* A megabyte is refused just the same (and without reading it all). */
    size_t n = 1 << 20;
    text = malloc(n + 1);
    memset(text, 'k', n);
    text[n] = '\0';
    expect_error(text, expected);
    free(text);

    /* A name of thousands of letters is cut short in the message. */
    text = malloc(FILTER_MAX_LENGTH + 1);
    memset(text, 'q', 4000);
    strcpy(text + 4000, " < 1");
    expect_error_parts(text, "column 1: unknown column 'qqq",
                       "...' (columns: number,");
    free(text);

    /* And so is a long number. */
    text = malloc(FILTER_MAX_LENGTH + 1);
    strcpy(text, "cost < ");
    memset(text + 7, '1', 3000);
    strcpy(text + 3007, "x");
    expect_error_parts(text, "column 8: malformed number '111",
                       NULL);
    free(text);

    /* Many digits are still one exact enough number. */
    text = malloc(FILTER_MAX_LENGTH + 1);
    strcpy(text, "cost < 0.");
    memset(text + 9, '0', 3000);
    strcpy(text + 3009, "1e3000");
    f = compile_ok(text);
    assert_true(fabs(filter_param(f, 0) - 0.1) < 1e-16);
    filter_free(f);
    free(text);
}

/* Checks the promises that hold for any text: compile succeeds or fails
 * with a one-line FACET_EINPUT message whose column lies within the text;
 * what compiles shows a text that compiles to itself. */
static void check_any_text(const char *text)
{
    struct filter *f = NULL;
    struct facet_error err;
    int rc = filter_compile(text, &f, &err);
    if (rc != FACET_OK) {
        assert_int_equal(rc, FACET_EINPUT);
        assert_null(f);
        unsigned long column = 0;
        if (sscanf(err.message, "column %lu: ", &column) != 1)
            fail_msg("'%s': bad message '%s'", text, err.message);
        size_t characters = 0;
        for (const char *c = text; *c != '\0'; c++)
            characters += ((unsigned char)*c & 0xC0) != 0x80;
        assert_true(column >= 1 && column <= characters + 1);
        for (const char *c = err.message; *c != '\0'; c++)
            assert_true((unsigned char)*c >= 0x20 && *c != 0x7F);
        return;
    }
    struct filter *g = compile_ok(filter_text(f));
    assert_string_equal(filter_text(g), filter_text(f));
    char *a = filter_sql(f, 1), *b = filter_sql(g, 1);
    assert_string_equal(a, b);
    free(a);
    free(b);
    assert_int_equal(filter_param_count(f), filter_param_count(g));
    for (size_t k = 0; k < filter_param_count(f); k++)
        assert_true(filter_param(f, k) == filter_param(g, k));
    filter_free(g);
    filter_free(f);
}

static void test_garbage_bytes(void **state)
{
    (void)state;
    static const char *const pieces[] = {
        "cost", "knee", "pareto", "u", "(", ")", "<", "<=", ">", "=", "==",
        "!=", "<>", "!", "&&", "||", "and", "or", "not", "5", "1.5e6",
        "2k", "-3", ".", "e", "M", " ", "  ", "\t", "nan", "&", "|", "x",
        "dp_aera", "1e999", "é", "\xff", "\xc3", "\x01", "\"", "'", ";",
        "--", "?1", "\\",
    };
    size_t npieces = sizeof pieces / sizeof *pieces;
    struct rng rng;
    rng_seed(&rng, 2024);
    char text[256];
    for (int round = 0; round < 20000; round++) {
        size_t n = 0;
        if (round % 2 == 0) {
            /* Pieces of the language, shuffled. */
            int count = 1 + (int)rng_below(&rng, 12);
            text[0] = '\0';
            for (int k = 0; k < count; k++) {
                const char *p = pieces[rng_below(&rng, npieces)];
                if (n + strlen(p) + 1 >= sizeof text)
                    break;
                strcpy(text + n, p);
                n += strlen(p);
            }
        } else {
            /* Raw bytes, any of 1..255. */
            n = (size_t)rng_below(&rng, 40);
            for (size_t k = 0; k < n; k++)
                text[k] = (char)(1 + rng_below(&rng, 255));
            text[n] = '\0';
        }
        check_any_text(text);
    }
}

/* ---- three-valued logic -------------------------------------------------- */

static void test_null_is_unknown(void **state)
{
    (void)state;
    struct oracle_row r = zero_row();
    set(&r, "planarity", NAN);
    set(&r, "feasible", 1);
    /* A comparison with NULL is neither true nor false... */
    assert_false(matches("planarity < 1", &r));
    assert_false(matches("not (planarity < 1)", &r));
    assert_false(matches("planarity != 1", &r));
    /* ...until and / or decide without it, as SQL does. */
    assert_true(matches("planarity < 1 or feasible", &r));
    assert_false(matches("planarity < 1 and feasible", &r));
    assert_true(matches("not (planarity < 1 and not feasible)", &r));
    assert_false(matches("not (planarity < 1 or not feasible)", &r));
    set(&r, "feasible", NAN);
    assert_false(matches("feasible", &r));
    assert_false(matches("not feasible", &r));
    set(&r, "rank", NAN);
    assert_false(matches("pareto or not pareto", &r));
    /* Infinity is a value like any other. */
    set(&r, "crowding", INFINITY);
    assert_true(matches("crowding > 1e308", &r));
    assert_false(matches("crowding < 0", &r));
}

/* ---- the SQLite oracle --------------------------------------------------- */

/* Runs text through SQLite and through filter_match (filter_oracle.h)
 * and fails on any option where they differ. The caller's own parameters
 * ?1 and ?2 come first when first_param is 3. Returns how many options
 * matched. */
static int compare_with_sqlite(sqlite3 *db, const struct oracle_row *rows,
                               const char *text, int first_param)
{
    struct filter *f = compile_ok(text);
    char why[1024];
    int count = oracle_compare_from(db, rows, NROWS, f, first_param, why,
                                    sizeof why);
    if (count < 0)
        fail_msg("%s", why);
    filter_free(f);
    return count;
}

/* A random expression over every column, operator, form and spelling. */
static void random_expression(struct rng *rng, int depth, char *out,
                              size_t size)
{
    static const char *const ops[] = {"<", "<=", ">", ">=", "=", "==",
                                      "!=", "<>"};
    static const char *const values[] = {"0", "1", "2", "3", "5", "0.5",
                                         "20", "1e3", "1.5M", "2k", "-1",
                                         "0.25", "100", "1.5e6", "30"};
    static const char *const yes_no[] = {"feasible", "knee", "pareto",
                                         "FEASIBLE", "Pareto"};
    size_t n = strlen(out);
    uint64_t kind = depth >= 3 ? rng_below(rng, 3) : rng_below(rng, 7);
    if (kind == 0) {
        const char *c = option_quantities[rng_below(rng, NCOLUMNS)].name;
        if (strcmp(c, "nu") == 0 && rng_below(rng, 2))
            c = "u";
        if (strcmp(c, "nv") == 0 && rng_below(rng, 2))
            c = "V";
        if (strcmp(c, "threshold_mm") == 0 && rng_below(rng, 2))
            c = "threshold";
        const char *op = ops[rng_below(rng, 8)];
        const char *v = values[rng_below(rng, sizeof values / sizeof *values)];
        if (rng_below(rng, 4) == 0)
            snprintf(out + n, size - n, "%s %s %s", v, op, c);
        else
            snprintf(out + n, size - n, "%s%s%s", c, op, v);
    } else if (kind == 1) {
        snprintf(out + n, size - n, "%s", yes_no[rng_below(rng, 5)]);
    } else if (kind == 2) {
        /* A value that is exactly a row's, so = and != decide. */
        static const char *const exact[] = {"nu = 10", "nv != 7",
                                            "rank = 1", "threshold <= 2.5",
                                            "generation = 3", "run <> 2",
                                            "crowding > 1.9", "knee = 1"};
        snprintf(out + n, size - n, "%s", exact[rng_below(rng, 8)]);
    } else if (kind == 3) {
        strcat(out, rng_below(rng, 2) ? "not " : "!");
        random_expression(rng, depth + 1, out, size);
    } else if (kind == 4) {
        strcat(out, "(");
        random_expression(rng, depth + 1, out, size);
        strcat(out, ")");
    } else {
        int count = 2 + (int)rng_below(rng, 3);
        const char *join = kind == 5 ? (rng_below(rng, 2) ? " and " : "&&")
                                     : (rng_below(rng, 2) ? " OR " : "||");
        for (int k = 0; k < count; k++) {
            if (k > 0)
                strcat(out, join);
            random_expression(rng, depth + 1, out, size);
        }
    }
}

static void test_sqlite_oracle(void **state)
{
    (void)state;
    struct rng rng;
    rng_seed(&rng, 7);
    struct oracle_row *rows = malloc(NROWS * sizeof *rows);
    oracle_random_rows(&rng, rows, NROWS);
    sqlite3 *db = oracle_database(rows, NROWS);
    assert_non_null(db);

    static const char *const texts[] = {
        "cost < 1.5e6 and dp_area <= 900 or pareto",
        "(nu >= 30 or nv = 40) and not feasible",
        "pareto", "not pareto", "feasible", "not feasible", "knee",
        "!knee", "cost < 1.5M", "2k > dp_area", "u = 10", "V <> 7",
        "threshold <= 2.5", "threshold_mm = 3", "planarity < 0.5",
        "not (planarity < 0.5)", "planarity >= 0.5 or planarity < 0.5",
        "not (planarity < 0.5 or max_deviation < 0.01)",
        "not (planarity < 0.5 and max_deviation < 0.01)",
        "crowding > 1e300", "crowding <= 1 or not feasible",
        "rank == 2 or rank = 3 and knee", "not (rank != 1)",
        "rank < 2", "not (rank >= 1)", "not (rank = 0) and not pareto",
        "panels > 400 and panels <= 900", "fp_count > 1",
        "sp_count >= 150", "number <= 100 || number > 300",
        "generation = 3 && run = 2", "area >= 1200 and fp_area < 500",
        "sp_area > 250.5", "max_panel_area = 4 or p_dist < 0.1",
        "!(feasible && (pareto || knee)) && cost < 1e6",
        "((((nu < 20))) and not not (nv < 20))",
        "-1 < dp_count and dp_count < 50",
        "COST >= 2.5e6 OR Not Feasible AND Pareto",
        "", "   ",
    };
    int decided = 0, valid = (int)(sizeof texts / sizeof *texts);
    for (size_t k = 0; k < sizeof texts / sizeof *texts; k++) {
        int count = compare_with_sqlite(db, rows, texts[k], 1);
        assert_int_equal(compare_with_sqlite(db, rows, texts[k], 3), count);
        decided += count > 0 && count < NROWS;
    }
    assert_true(decided >= valid - 6);

    /* Random expressions: the two evaluators agree on every one, and the
     * text shown back selects the same options. */
    char text[4096];
    int nontrivial = 0;
    for (int round = 0; round < 400; round++) {
        text[0] = '\0';
        random_expression(&rng, 0, text, sizeof text);
        int count = compare_with_sqlite(db, rows, text, round % 2 ? 3 : 1);
        struct filter *f = compile_ok(text);
        assert_int_equal(compare_with_sqlite(db, rows, filter_text(f), 1),
                         count);
        filter_free(f);
        nontrivial += count > 0 && count < NROWS;
    }
    assert_true(nontrivial > 100);

    sqlite3_close(db);
    free(rows);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_columns_table),
        cmocka_unit_test(test_empty_matches_everything),
        cmocka_unit_test(test_precedence),
        cmocka_unit_test(test_parentheses),
        cmocka_unit_test(test_every_operator),
        cmocka_unit_test(test_aliases_and_case),
        cmocka_unit_test(test_numbers),
        cmocka_unit_test(test_sql_fragment),
        cmocka_unit_test(test_error_positions),
        cmocka_unit_test(test_nan_and_infinity),
        cmocka_unit_test(test_hostile_nesting),
        cmocka_unit_test(test_text_compiles_again),
        cmocka_unit_test(test_deepest_sql_parses),
        cmocka_unit_test(test_hostile_length),
        cmocka_unit_test(test_garbage_bytes),
        cmocka_unit_test(test_null_is_unknown),
        cmocka_unit_test(test_sqlite_oracle),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
