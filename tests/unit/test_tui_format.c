/*
 * test_tui_format.c: how `facet tui` writes numbers (thousands, decimals,
 * NaN and infinity, durations, times) and the cells of its options table
 * (right-aligned in their width, yes/no, unranked rank).
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

#include "tui/format.h"

static void check_number(double v, int decimals, int thousands,
                         const char *want)
{
    char out[64];
    tui_fmt_number(out, sizeof out, v, decimals, thousands);
    assert_string_equal(out, want);
}

/* The dollars of the numbers in text after "= ", summed, and the total
 * before it: what a reader adds up. */
static void sum_of(const char *text, double *total, double *sum)
{
    *total = *sum = 0;
    const char *eq = strstr(text, " = ");
    char digits[32];
    size_t n = 0;
    for (const char *c = text + 5; *c && c != eq; c++)
        if (*c >= '0' && *c <= '9' && n + 1 < sizeof digits)
            digits[n++] = *c;
    digits[n] = '\0';
    *total = atof(digits);
    if (eq == NULL)
        return;
    for (const char *c = eq; *c;) {
        while (*c && !(*c >= '0' && *c <= '9'))
            c++;
        n = 0;
        while (*c && ((*c >= '0' && *c <= '9') || *c == ','))
            if (*c++ != ',' && n + 1 < sizeof digits)
                digits[n++] = c[-1];
        digits[n] = '\0';
        *sum += atof(digits);
    }
}

/* Issue 32 item 1: the detail pane's cost at 80 columns left out the
 * terms beyond area, so its sum did not add up. The truth: the terms as
 * a reader adds them, against the total, at every width. */
static void test_cost_sum(void **state)
{
    (void)state;
    struct option_totals t;
    memset(&t, 0, sizeof t);
    /* the option: area by type, then panels, joints and moulds;
     * remainders chosen so that plain rounding of each term is a dollar
     * short of the rounded total */
    t.cost_of[TYPE_FP] = 270401.3;
    t.cost_of[TYPE_SP] = 314018.4;
    t.cost_of[TYPE_DP] = 616566.45;
    t.area_cost = t.cost_of[TYPE_FP] + t.cost_of[TYPE_SP] +
                  t.cost_of[TYPE_DP];
    t.panel_cost = 28800;
    t.joint_cost = 65456.2;
    t.mould_cost = 1380000;
    t.cost = t.area_cost + t.panel_cost + t.joint_cost + t.mould_cost;
    char out[200];
    int forms = 0;
    char last[200] = "";
    for (int width = 10; width <= 160; width++) {
        tui_fmt_cost_sum(out, sizeof out, &t, width);
        double total, sum;
        sum_of(out, &total, &sum);
        assert_true(total == rint(t.cost));  /* printf's rounding */
        if (strstr(out, " = ") != NULL) {
            assert_true((int)strlen(out) <= width);
            assert_true(sum == total);  /* the shown terms add up */
        }
        if (strcmp(out, last) != 0) {
            forms++;
            snprintf(last, sizeof last, "%s", out);
        }
    }
    assert_int_equal(forms, 3);  /* the cost alone, by area, by type */
    tui_fmt_cost_sum(out, sizeof out, &t, 160);
    assert_string_equal(out, "cost 2,675,242 USD = FP 270,401 + SP 314,018 + "
                        "DP 616,567 + panels 28,800 + joints 65,456 + "
                        "moulds 1,380,000");
    tui_fmt_cost_sum(out, sizeof out, &t, 90);
    assert_string_equal(out, "cost 2,675,242 USD = area 1,200,986 + panels "
                        "28,800 + joints 65,456 + moulds 1,380,000");
    /* the paper's model: area alone, the types always shown, no zero
     * term beyond them */
    memset(&t, 0, sizeof t);
    t.cost_of[TYPE_FP] = 1000;
    t.cost_of[TYPE_DP] = 2000.5;
    t.area_cost = t.cost = 3000.5;
    t.joint_cost = NAN;  /* not measured */
    tui_fmt_cost_sum(out, sizeof out, &t, 80);
    assert_string_equal(out, "cost 3,000 USD = FP 1,000 + SP 0 + DP 2,000");
}

/* Issue 32 item 2: a header cut at the screen's edge read "t 4.00 m" for
 * 4.00 mm. Fields are dropped whole instead, at every width, and only a
 * title alone is ever cut. The truth: at each width, the line is the
 * longest prefix of whole fields that fits. */
static void test_fields(void **state)
{
    (void)state;
    const char *fields[4] = {" Map: option 61 of run 1",
                             "surface 1 of 4: façade (15 x 12)", "t 4.00 mm",
                             "by type"};
    char out[256];
    for (int width = 1; width <= 100; width++) {
        tui_fmt_fields(out, sizeof out, width, fields, 4);
        /* the longest prefix of whole fields within width, by hand */
        char want[256] = "";
        for (int kept = 4; kept >= 1; kept--) {
            want[0] = '\0';
            for (int k = 0; k < kept; k++) {
                strcat(want, k ? " | " : "");
                strcat(want, fields[k]);
            }
            size_t chars = 0;
            for (const char *c = want; *c; c++)
                chars += (*c & 0xC0) != 0x80;
            if ((int)chars <= width)
                break;
            if (kept == 1) {
                assert_true(width < 24);
                want[width] = '\0';  /* the title is ASCII */
            }
        }
        assert_string_equal(out, want);
        /* never a threshold without its millimetres */
        const char *t = strstr(out, "t 4.00");
        assert_true(t == NULL || strncmp(t, "t 4.00 mm", 9) == 0);
    }
    tui_fmt_fields(out, sizeof out, 81, fields, 4);
    assert_string_equal(out, " Map: option 61 of run 1 | surface 1 of 4: "
                        "façade (15 x 12) | t 4.00 mm | by type");
    tui_fmt_fields(out, sizeof out, 80, fields, 4);
    assert_string_equal(out, " Map: option 61 of run 1 | surface 1 of 4: "
                        "façade (15 x 12) | t 4.00 mm");
    tui_fmt_fields(out, sizeof out, 70, fields, 4);
    assert_string_equal(out, " Map: option 61 of run 1 | surface 1 of 4: "
                        "façade (15 x 12)");
}

/* Issue 32 item 4: the detail pane's "FP 702 425.2" read as one number.
 * Each type's count and area, each area with its unit, and a line too
 * long for the pane drops whole types, never the end of a number. */
static void test_list(void **state)
{
    (void)state;
    const char *fields[4] = {"12,345 panels, 14,234.5 m^2",
                             "FP 1,234 (4,567.8 m^2)",
                             "SP 2,345 (5,678.9 m^2)",
                             "DP 8,766 (3,987.8 m^2)"};
    char out[256];
    tui_fmt_list(out, sizeof out, 99, fields, 4, ": ", ", ");
    assert_string_equal(out, "12,345 panels, 14,234.5 m^2: FP 1,234 "
                        "(4,567.8 m^2), SP 2,345 (5,678.9 m^2), DP 8,766 "
                        "(3,987.8 m^2)");
    tui_fmt_list(out, sizeof out, 98, fields, 4, ": ", ", ");
    assert_string_equal(out, "12,345 panels, 14,234.5 m^2: FP 1,234 "
                        "(4,567.8 m^2), SP 2,345 (5,678.9 m^2)");
    tui_fmt_list(out, sizeof out, 51, fields, 4, ": ", ", ");
    assert_string_equal(out, "12,345 panels, 14,234.5 m^2: FP 1,234 "
                        "(4,567.8 m^2)");
    tui_fmt_list(out, sizeof out, 50, fields, 4, ": ", ", ");
    assert_string_equal(out, "12,345 panels, 14,234.5 m^2");
}

static void test_numbers(void **state)
{
    (void)state;
    check_number(1551317.4, 0, 1, "1,551,317");
    check_number(1551317.25, 2, 1, "1,551,317.25");
    check_number(999, 0, 1, "999");
    check_number(1000, 0, 1, "1,000");
    check_number(-1234567.5, 1, 1, "-1,234,567.5");
    check_number(-999.5, 0, 1, "-1,000");  /* rounding carries a digit */
    check_number(0, 3, 1, "0.000");
    check_number(2.52174, 3, 0, "2.522");
    check_number(123456, 0, 0, "123456");
    check_number(NAN, 2, 1, "-");
    check_number(INFINITY, 2, 1, "inf");
    check_number(-INFINITY, 0, 0, "-inf");
    char tiny[4];
    tui_fmt_number(tiny, sizeof tiny, 1234567, 0, 1);
    assert_string_equal(tiny, "1,2");  /* truncated, still terminated */
}

static void test_times(void **state)
{
    (void)state;
    char out[32];
    tui_fmt_elapsed(out, sizeof out, 0.05);
    assert_string_equal(out, "0.05 s");
    tui_fmt_elapsed(out, sizeof out, 12.34);
    assert_string_equal(out, "12.3 s");
    tui_fmt_elapsed(out, sizeof out, 245);
    assert_string_equal(out, "4m05s");
    tui_fmt_elapsed(out, sizeof out, 7380);
    assert_string_equal(out, "2h03m");
    tui_fmt_elapsed(out, sizeof out, NAN);
    assert_string_equal(out, "-");
    tui_fmt_started(out, sizeof out, "2026-11-25T01:30:59Z");
    assert_string_equal(out, "2026-11-25 01:30");
    tui_fmt_started(out, sizeof out, "");
    assert_string_equal(out, "-");
}

static void test_cells(void **state)
{
    (void)state;
    struct option_row o;
    memset(&o, 0, sizeof o);
    o.number = 73;
    o.totals.cost = 1551317.2;
    o.totals.planarity = 2.52174;
    o.totals.feasible = 0;
    o.threshold_mm = 2;
    int total = 0;
    for (int c = 0; c < tui_option_column_count; c++) {
        const struct tui_column *col = &tui_option_columns[c];
        char cell[64];
        tui_fmt_cell(cell, sizeof cell, col, &o);
        assert_int_equal((int)strlen(cell), col->width);  /* aligned */
        const char *title = tui_column_title(col);
        assert_true(col->width >= (int)strlen(title));
        assert_true(col->width >= (int)strlen(tui_column_unit(col)));
        if (strcmp(title, "cost") == 0)
            assert_string_equal(cell, " 1,551,317");
        if (strcmp(title, "planarity") == 0)
            assert_string_equal(cell, "    2.522");
        if (strcmp(title, "ok") == 0)
            assert_string_equal(cell, " no");
        if (strcmp(title, "rank") == 0)
            assert_string_equal(cell, "   -");  /* not ranked yet */
        if (strcmp(title, "t") == 0)
            assert_string_equal(cell, " 2.00");
        if (col->pareto_mark)
            assert_string_equal(cell, " ");  /* the caller draws it */
        if (c < tui_option_column_default_count)
            total += col->width + 1;
        /* every column the chooser offers is a store column */
        assert_false(isnan(option_quantity_value(&o, col->column)));
    }
    assert_true(total - 1 <= 80);  /* the default table fits 80 columns */
    /* every metric the tables show is a store column */
    for (int c = 0; c < tui_metric_column_count; c++)
        assert_non_null(quantity_named(tui_metric_columns[c]));
    /* on its own a value has the registry's decimals and unit scale */
    char out[64];
    o.totals.max_deviation = 0.03758;
    tui_fmt_value(out, sizeof out, quantity_named("max_deviation"),
                  o.totals.max_deviation);
    assert_string_equal(out, "37.58");
    tui_fmt_value(out, sizeof out, quantity_named("planarity"),
                  o.totals.planarity);
    assert_string_equal(out, "2.5217");
    tui_fmt_value(out, sizeof out, quantity_named("knee"), 1);
    assert_string_equal(out, "yes");
}

/* Why an infeasible option is: each limit classify_broken_limits names,
 * with the option's figure and the run's limit, in its order; a limit
 * not measured is not named. Worked by hand. */
static void test_violation(void **state)
{
    (void)state;
    struct run_info run;
    memset(&run, 0, sizeof run);
    run.max_panel_area = 1.92;
    run.min_panel_width = 0.3;
    run.max_gap_mm = 2;
    run.max_kink_deg = 5;
    struct option_totals t;
    memset(&t, 0, sizeof t);
    t.max_panel_area = 2.05;
    t.gaps_over = 3;
    t.kinks_over = TOTALS_UNKNOWN;
    char out[200];
    tui_fmt_violation(out, sizeof out, &t, &run);
    assert_string_equal(out, "panel 2.05 m^2 > 1.92 m^2 limit, "
                             "3 gaps > 2 mm limit");
    t.max_panel_area = 1.5;
    t.slivers = 1;
    t.gaps_over = 0;
    t.kinks_over = 2;
    tui_fmt_violation(out, sizeof out, &t, &run);
    assert_string_equal(out, "1 sliver < 0.30 m limit, 2 kinks > 5 deg limit");
    t.slivers = 0;
    t.kinks_over = 0;
    tui_fmt_violation(out, sizeof out, &t, &run);
    assert_string_equal(out, "over a limit");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_numbers),
        cmocka_unit_test(test_cost_sum),
        cmocka_unit_test(test_fields),
        cmocka_unit_test(test_violation),
        cmocka_unit_test(test_list),
        cmocka_unit_test(test_times),
        cmocka_unit_test(test_cells),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
