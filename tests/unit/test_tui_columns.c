/*
 * test_tui_columns.c: the column chooser's model: the default columns
 * (the 80-column table), hiding and showing, never hiding the last one,
 * moving a column through the order, and the width the table takes.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <string.h>

#include "tui/columns.h"
#include "tui/format.h"

static const char *name(int index)
{
    return tui_option_columns[index].column;
}

static void test_default(void **state)
{
    (void)state;
    struct tui_column_set set;
    tui_columns_default(&set);
    assert_int_equal(set.n, tui_option_column_count);
    int vis[TUI_COLUMNS_MAX];
    int n = tui_columns_visible(&set, vis);
    assert_int_equal(n, tui_option_column_default_count);
    assert_int_equal(n, 12);
    assert_string_equal(name(vis[0]), "number");
    assert_string_equal(name(vis[4]), "cost");
    assert_string_equal(name(vis[11]), "rank");
    assert_int_equal(tui_columns_width(&set), 80);
    /* the hidden ones exist and are store columns */
    assert_true(set.n > 12);
    for (int k = 12; k < set.n; k++)
        assert_false(set.shown[k]);
}

static void test_toggle_and_move(void **state)
{
    (void)state;
    struct tui_column_set set;
    tui_columns_default(&set);
    int vis[TUI_COLUMNS_MAX];
    /* hide planarity: 80 - 10 characters */
    assert_int_equal(tui_columns_toggle(&set, 2), 0);
    assert_int_equal(tui_columns_width(&set), 70);
    int n = tui_columns_visible(&set, vis);
    assert_int_equal(n, 11);
    assert_string_equal(name(vis[2]), "dp_area");
    /* show the area column and move it to the front */
    assert_int_equal(tui_columns_toggle(&set, 12), 0);
    assert_string_equal(name(set.order[12]), "area");
    assert_int_equal(tui_columns_move(&set, 12, -100), 0);
    n = tui_columns_visible(&set, vis);
    assert_string_equal(name(vis[0]), "area");
    assert_string_equal(name(vis[1]), "number");
    assert_true(set.shown[0]);
    /* planarity kept its hidden flag while it moved down one */
    assert_string_equal(name(set.order[3]), "planarity");
    assert_false(set.shown[3]);
    /* moving down, clamped at the end */
    assert_int_equal(tui_columns_move(&set, 0, 1), 1);
    assert_string_equal(name(set.order[1]), "area");
    assert_int_equal(tui_columns_move(&set, 1, 1000), set.n - 1);
    assert_string_equal(name(set.order[set.n - 1]), "area");
    assert_int_equal(tui_columns_move(&set, -1, 1), -1);  /* no such place */
    /* every column is a place once */
    int seen[TUI_COLUMNS_MAX] = {0};
    for (int k = 0; k < set.n; k++)
        seen[set.order[k]]++;
    for (int k = 0; k < set.n; k++)
        assert_int_equal(seen[k], 1);
    /* the last shown column stays */
    for (int k = 0; k < set.n; k++)
        if (set.shown[k])
            tui_columns_toggle(&set, k);
    n = tui_columns_visible(&set, vis);
    assert_int_equal(n, 1);
    for (int k = 0; k < set.n; k++)
        if (set.shown[k])
            assert_int_equal(tui_columns_toggle(&set, k), -1);
    assert_int_equal(tui_columns_toggle(&set, set.n), -1);
    tui_columns_default(&set);
    assert_int_equal(tui_columns_width(&set), 80);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_default),
        cmocka_unit_test(test_toggle_and_move),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
