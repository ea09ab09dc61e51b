/*
 * test_tui_layout.c: what fits on the screen of `facet tui` (layout.h):
 * a title drops whole fields, the least needed first, and never cuts a
 * number (at 80 columns the Options title showed "knee 3" for knee 324);
 * the function-key bar keeps a blank after every label at every width
 * where it fits (the labels ran together: "F3FilterF4ParetoF5Plot") and a
 * click finds the key it lands on; the help page fits the box; a click
 * finds the table column under it. Each is checked against a brute-force
 * oracle over many widths.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <stdio.h>
#include <string.h>

#include "tui/layout.h"

/* The Options title of the demo's run at 80 columns. */
static void test_title(void **state)
{
    (void)state;
    const struct tui_field fields[] = {
        {"", " Run 1", 0},           {" ", "paper space", 4},
        {" ", "roof.obj", 3},        {" | ", "exhaustive", 2},
        {" | ", "done", 0},          {" | ", "336 options", 0},
        {", ", "12 Pareto", 1},      {", ", "knee 324", 0},
    };
    char out[256];
    int w = tui_fit_fields(out, sizeof out, 80, fields, 8);
    assert_true(w <= 80);
    assert_string_equal(out, " Run 1 roof.obj | exhaustive | done | "
                             "336 options, 12 Pareto, knee 324");
    /* wide: everything */
    tui_fit_fields(out, sizeof out, 200, fields, 8);
    assert_string_equal(out, " Run 1 paper space roof.obj | exhaustive | "
                             "done | 336 options, 12 Pareto, knee 324");
    /* narrow: only what is never dropped, whole */
    tui_fit_fields(out, sizeof out, 30, fields, 8);
    assert_string_equal(out, " Run 1 | done | 336 options, knee 324");
    /* UTF-8 counts one column per code point */
    assert_int_equal(tui_text_width("Dach \xc3\xa4\xc3\xb6"), 7);
}

/* Every width from 10 to 120: the title either fits or holds only the
 * undroppable fields; a field is dropped only if every field kept that
 * can be dropped has a drop number no larger (the order of dropping);
 * and what is kept is whole (each kept text appears intact). */
static void test_title_oracle(void **state)
{
    (void)state;
    const struct tui_field fields[] = {
        {"", "A1234", 0}, {" ", "bbbbbbbbb", 3}, {" | ", "cc", 1},
        {" | ", "ddddddd", 2}, {" | ", "e 77", 0}, {", ", "ffff", 1},
        {", ", "gggggggggggg", 5},
    };
    int n = (int)(sizeof fields / sizeof fields[0]);
    int undroppable = 5 + 3 + 4;  /* "A1234 | e 77" */
    for (int width = 10; width <= 120; width++) {
        char out[256];
        int w = tui_fit_fields(out, sizeof out, width, fields, n);
        assert_int_equal(w, (int)strlen(out));
        assert_true(w <= width || w == undroppable);
        int max_kept = 0, min_dropped = 99;
        for (int k = 0; k < n; k++) {
            int kept = strstr(out, fields[k].text) != NULL;
            if (fields[k].drop == 0)
                assert_true(kept);
            else if (kept && fields[k].drop > max_kept)
                max_kept = fields[k].drop;
            else if (!kept && fields[k].drop < min_dropped)
                min_dropped = fields[k].drop;
        }
        assert_true(max_kept <= min_dropped);
    }
}

/* The bar at every width it can be drawn in: keys in order, a blank
 * (at least) between a label's field and the next key, inside width, and
 * a label cut only when the width leaves no choice. */
static void test_fkeys(void **state)
{
    (void)state;
    const char *const options[10] = {"Help", "Cols", "Filter", "Pareto",
                                     "Plot", "Sort", "Compare", "Map",
                                     NULL, "Quit"};
    const char *const runs[10] = {"Help", NULL, "Search", NULL, NULL,
                                  "Resume", "New", "Delete", NULL, "Quit"};
    const char *const *sets[2] = {options, runs};
    for (int set = 0; set < 2; set++) {
        const char *const *labels = sets[set];
        int natural = 0, used = 0;
        for (int k = 0; k < 10; k++)
            if (labels[k]) {
                natural += (k == 9 ? 3 : 2) + (int)strlen(labels[k]) + 1;
                used++;
            }
        natural -= 1;
        for (int width = 30; width <= 200; width++) {
            int x[10], lw[10];
            int w = tui_fkey_layout(labels, width, x, lw);
            if (w > width)
                continue;  /* too narrow for any bar: not drawn whole */
            int end = -1, drawn = 0;
            for (int k = 0; k < 10; k++) {
                if (labels[k] == NULL) {
                    assert_int_equal(x[k], -1);
                    continue;
                }
                drawn++;
                assert_true(x[k] > end);  /* a blank after the last */
                end = x[k] + (k == 9 ? 3 : 2) + lw[k];
                assert_true(end <= width);
                if (width >= natural)
                    assert_true(lw[k] >= (int)strlen(labels[k]));
                /* a click on the key or its label finds it; the blank
                 * after it finds none */
                assert_int_equal(tui_fkey_at(x, lw, x[k]), k + 1);
                assert_int_equal(tui_fkey_at(x, lw, end - 1), k + 1);
                assert_int_equal(tui_fkey_at(x, lw, end), 0);
            }
            assert_int_equal(drawn, used);
        }
    }
    /* at 80 columns, the options bar has every label whole */
    int x[10], lw[10];
    assert_true(tui_fkey_layout(options, 80, x, lw) <= 80);
    assert_int_equal(lw[6], 7);  /* "Compare" */
    /* htop's six-column fields where they fit */
    tui_fkey_layout(runs, 80, x, lw);
    assert_int_equal(lw[2], 6);
    assert_int_equal(lw[6], 6);
}

static void test_help(void **state)
{
    (void)state;
    for (int height = 4; height <= 60; height++)
        for (int lines = 1; lines <= 90; lines += 7)
            for (int top = -3; top <= 100; top += 9) {
                struct tui_help_page p;
                tui_help_layout(lines, height, 80, 78, top, &p);
                assert_int_equal(p.columns, 1);  /* 80 < 2 * 78 + 3 */
                assert_true(p.per_page + 3 <= height || p.per_page == 1);
                assert_true(p.top >= 0);
                /* the last page is full when there is more than one */
                if (lines > p.per_page)
                    assert_true(p.top + p.per_page <= lines);
                else
                    assert_int_equal(p.top, 0);
            }
    struct tui_help_page p;
    tui_help_layout(40, 22, 200, 78, 0, &p);
    assert_int_equal(p.columns, 2);
    tui_help_layout(10, 22, 200, 78, 0, &p);
    assert_int_equal(p.columns, 1);
}

static void test_column_at(void **state)
{
    (void)state;
    const int widths[] = {7, 1, 9, 8, 10};
    int n = 5;
    /* brute force: paint each column's cells and compare */
    int owner[60];
    for (int x = 0; x < 60; x++)
        owner[x] = -1;
    int at = 0;
    for (int k = 0; k < n; k++) {
        for (int c = 0; c < widths[k]; c++)
            owner[at + c] = k;
        at += widths[k] + 1;
    }
    for (int x = 0; x < 60; x++)
        assert_int_equal(tui_column_at(widths, n, x), owner[x]);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_title),
        cmocka_unit_test(test_title_oracle),
        cmocka_unit_test(test_fkeys),
        cmocka_unit_test(test_help),
        cmocka_unit_test(test_column_at),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
