/*
 * test_tui_history.c: the filter line's history (tui/history.h) against
 * what a shell does (issue 32 item 10): Up goes to older texts, Down to
 * newer ones and past the newest back to what was being typed; empty
 * texts and a repeat of the newest are not kept; the oldest goes when it
 * is full; a refused text is what the prompt opens on next.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "tui/history.h"

static void test_up_and_down(void **state)
{
    (void)state;
    struct tui_history *h = calloc(1, sizeof *h);
    assert_non_null(h);
    tui_history_open(h);
    assert_null(tui_history_step(h, -1, "x"));  /* nothing yet */
    tui_history_add(h, "cost < 1.5M", 0);
    tui_history_add(h, "", 0);                  /* not kept */
    tui_history_add(h, "dp_aera > 1", 1);
    tui_history_add(h, "dp_area > 1", 0);
    tui_history_add(h, "dp_area > 1", 0);       /* a repeat: kept once */
    assert_int_equal(h->n, 3);
    tui_history_open(h);
    assert_string_equal(tui_history_step(h, -1, "pla"), "dp_area > 1");
    assert_string_equal(tui_history_step(h, -1, "dp_area > 1"),
                        "dp_aera > 1");
    assert_string_equal(tui_history_step(h, -1, "dp_aera > 1"),
                        "cost < 1.5M");
    assert_null(tui_history_step(h, -1, "cost < 1.5M"));   /* the oldest */
    assert_string_equal(tui_history_step(h, 1, "cost < 1.5M"),
                        "dp_aera > 1");
    assert_string_equal(tui_history_step(h, 1, "dp_aera > 1"),
                        "dp_area > 1");
    /* past the newest: what was being typed, then nothing further */
    assert_string_equal(tui_history_step(h, 1, "dp_area > 1"), "pla");
    assert_null(tui_history_step(h, 1, "pla"));
    free(h);
}

static void test_refused_reopens(void **state)
{
    (void)state;
    struct tui_history *h = calloc(1, sizeof *h);
    assert_non_null(h);
    assert_null(tui_history_refused(h));
    tui_history_add(h, "cost < 2M and dp_aera > 1", 1);
    assert_string_equal(tui_history_refused(h), "cost < 2M and dp_aera > 1");
    tui_history_add(h, "cost < 2M and dp_area > 1", 0);
    assert_null(tui_history_refused(h));
    /* the same text refused again (the store changed under it) */
    tui_history_add(h, "cost < 2M and dp_area > 1", 1);
    assert_string_equal(tui_history_refused(h), "cost < 2M and dp_area > 1");
    free(h);
}

static void test_full(void **state)
{
    (void)state;
    struct tui_history *h = calloc(1, sizeof *h);
    assert_non_null(h);
    char text[32];
    for (int k = 0; k < TUI_HISTORY_MAX + 5; k++) {
        snprintf(text, sizeof text, "nu = %d", k);
        tui_history_add(h, text, 0);
    }
    assert_int_equal(h->n, TUI_HISTORY_MAX);
    assert_string_equal(h->text[0], "nu = 5");
    snprintf(text, sizeof text, "nu = %d", TUI_HISTORY_MAX + 4);
    assert_string_equal(h->text[TUI_HISTORY_MAX - 1], text);
    tui_history_open(h);
    const char *last = NULL, *t;
    int steps = 0;
    while ((t = tui_history_step(h, -1, "")) != NULL) {
        last = t;
        steps++;
    }
    assert_int_equal(steps, TUI_HISTORY_MAX);
    assert_string_equal(last, "nu = 5");
    free(h);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_up_and_down),
        cmocka_unit_test(test_refused_reopens),
        cmocka_unit_test(test_full),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
