/*
 * test_tui_keys.c: the key map every screen of `facet tui` shares (vi
 * keys and arrows alike, function keys, key names for help) and the
 * one-line editor of the filter line and forms, and a prompt closing on
 * Enter or Esc (tui_prompt_key).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <curses.h>
#include <string.h>

#include "tui/app.h"
#include "tui/input.h"
#include "tui/keys.h"

static void test_actions(void **state)
{
    (void)state;
    const struct { int key; enum tui_action action; } map[] = {
        {'j', ACTION_DOWN}, {KEY_DOWN, ACTION_DOWN},
        {'k', ACTION_UP}, {KEY_UP, ACTION_UP},
        {'h', ACTION_LEFT}, {KEY_LEFT, ACTION_LEFT},
        {'l', ACTION_RIGHT}, {KEY_RIGHT, ACTION_RIGHT},
        {'g', ACTION_TOP}, {KEY_HOME, ACTION_TOP},
        {'G', ACTION_BOTTOM}, {KEY_END, ACTION_BOTTOM},
        {KEY_NPAGE, ACTION_PAGE_DOWN}, {6 /* Ctrl-F */, ACTION_PAGE_DOWN},
        {KEY_PPAGE, ACTION_PAGE_UP}, {2 /* Ctrl-B */, ACTION_PAGE_UP},
        {'/', ACTION_SEARCH}, {'n', ACTION_NEXT}, {'N', ACTION_PREVIOUS},
        {'\r', ACTION_OPEN}, {'\n', ACTION_OPEN}, {KEY_ENTER, ACTION_OPEN},
        {'q', ACTION_BACK}, {27, ACTION_BACK},
        {KEY_F(10), ACTION_QUIT},
        {'?', ACTION_HELP}, {KEY_F(1), ACTION_HELP},
        {12 /* Ctrl-L */, ACTION_REDRAW},
        {'x', ACTION_NONE}, {KEY_F(5), ACTION_NONE},
    };
    for (size_t k = 0; k < sizeof map / sizeof map[0]; k++)
        assert_int_equal(tui_key_action(map[k].key), map[k].action);
}

/* Bytes after an Esc, as curses hands them over for a sequence its TERM
 * does not know. */
struct bytes {
    const char *text;
    size_t at;
};

static int next_byte(void *context)
{
    struct bytes *b = context;
    if (b->text[b->at] == '\0')
        return -1;
    return (unsigned char)b->text[b->at++];
}

/* Every sequence is read to its end (nothing of it is left to act as a
 * key: under a mismatched TERM, F5's "[15~" after the Esc went back and
 * F10's quit), the common ones are their keys, the rest nothing. */
static void test_escape(void **state)
{
    (void)state;
    const struct { const char *after_esc; int key; } map[] = {
        {"[15~", KEY_F(5)}, {"[21~", KEY_F(10)}, {"[11~", KEY_F(1)},
        {"[24~", KEY_F(12)}, {"[17~", KEY_F(6)}, {"OP", KEY_F(1)},
        {"OS", KEY_F(4)}, {"[[A", KEY_F(1)}, {"[[E", KEY_F(5)},
        {"[A", KEY_UP}, {"[B", KEY_DOWN}, {"OC", KEY_RIGHT},
        {"[1;5D", KEY_LEFT}, {"[15;2~", KEY_F(5)}, {"[H", KEY_HOME},
        {"[4~", KEY_END}, {"[5~", KEY_PPAGE}, {"[6~", KEY_NPAGE},
        {"[3~", KEY_DC},
        /* unknown: ignored whole */
        {"[99~", TUI_KEY_NONE}, {"[<0;10;5M", TUI_KEY_NONE},
        {"[M !!", TUI_KEY_NONE}, {"[200~", TUI_KEY_NONE},
        {"[?1;2c", TUI_KEY_NONE}, {"x", TUI_KEY_NONE},
        {"[~", TUI_KEY_NONE}, {"O", TUI_KEY_NONE}, {"[12", TUI_KEY_NONE},
        /* an Esc alone */
        {"", 27},
    };
    for (size_t k = 0; k < sizeof map / sizeof map[0]; k++) {
        struct bytes b = {map[k].after_esc, 0};
        int pushback;
        int key = tui_key_escape(next_byte, &b, &pushback);
        if (key != map[k].key)
            fail_msg("ESC %s: key %d, want %d", map[k].after_esc, key,
                     map[k].key);
        assert_int_equal(pushback, -1);
        assert_int_equal(b.at, strlen(map[k].after_esc));
    }
    /* Esc Esc: one back, and the second Esc is the next key */
    struct bytes b = {"\033", 0};
    int pushback;
    assert_int_equal(tui_key_escape(next_byte, &b, &pushback), 27);
    assert_int_equal(pushback, 27);
    /* what follows a sequence is not read */
    struct bytes c = {"[15~q", 0};
    assert_int_equal(tui_key_escape(next_byte, &c, &pushback), KEY_F(5));
    assert_int_equal(c.at, 4);
}

static void test_names(void **state)
{
    (void)state;
    char buffer[16];
    assert_string_equal(tui_key_name(KEY_F(5), buffer), "F5");
    assert_string_equal(tui_key_name(KEY_F(10), buffer), "F10");
    assert_string_equal(tui_key_name('\n', buffer), "Enter");
    assert_string_equal(tui_key_name(' ', buffer), "Space");
    assert_string_equal(tui_key_name(12, buffer), "Ctrl-L");
    assert_string_equal(tui_key_name('K', buffer), "K");
    assert_string_equal(tui_key_name(KEY_NPAGE, buffer), "PgDn");
}

static void type(struct tui_input *in, const char *text)
{
    for (const char *p = text; *p; p++)
        assert_int_equal(tui_input_key(in, (unsigned char)*p),
                         INPUT_EDITING);
}

static void test_input(void **state)
{
    (void)state;
    struct tui_input in;
    tui_input_set(&in, "cost < 1");
    assert_int_equal(in.cursor, 8);
    type(&in, ".5M");
    assert_string_equal(in.text, "cost < 1.5M");
    assert_int_equal(tui_input_key(&in, KEY_HOME), INPUT_EDITING);
    type(&in, "(");
    assert_int_equal(tui_input_key(&in, KEY_END), INPUT_EDITING);
    type(&in, ")");
    assert_string_equal(in.text, "(cost < 1.5M)");
    assert_int_equal(tui_input_key(&in, KEY_BACKSPACE), INPUT_EDITING);
    assert_int_equal(tui_input_key(&in, KEY_LEFT), INPUT_EDITING);
    assert_int_equal(tui_input_key(&in, KEY_DC), INPUT_EDITING);
    assert_string_equal(in.text, "(cost < 1.5");
    assert_int_equal(tui_input_key(&in, 23 /* Ctrl-W */), INPUT_EDITING);
    assert_string_equal(in.text, "(cost < ");
    assert_int_equal(tui_input_key(&in, 21 /* Ctrl-U */), INPUT_EDITING);
    assert_string_equal(in.text, "");
    assert_int_equal(in.cursor, 0);
    assert_int_equal(tui_input_key(&in, KEY_BACKSPACE), INPUT_EDITING);
    assert_int_equal(tui_input_key(&in, '\r'), INPUT_DONE);
    assert_int_equal(tui_input_key(&in, 27), INPUT_CANCEL);
    assert_int_equal(tui_input_key(&in, KEY_F(5)), INPUT_IGNORED);
    /* the view scrolls to keep the cursor visible */
    tui_input_set(&in, "abcdefghijklmnopqrstuvwxyz");
    assert_int_equal(tui_input_scroll(&in, 10), 17);
    assert_int_equal(tui_input_scroll(&in, 40), 0);
    /* a full buffer takes no more */
    char big[TUI_INPUT_MAX + 10];
    memset(big, 'a', sizeof big - 1);
    big[sizeof big - 1] = '\0';
    tui_input_set(&in, big);
    assert_int_equal(in.length, TUI_INPUT_MAX - 1);
    tui_input_key(&in, 'b');
    assert_int_equal(in.length, TUI_INPUT_MAX - 1);
    assert_int_equal(strlen(in.text), TUI_INPUT_MAX - 1);
}

static void test_prompt(void **state)
{
    (void)state;
    static struct tui_app app;
    struct tui_input in;
    int open = 1;
    tui_input_set(&in, "");
    tui_prompt(&app, "Range:", &in);
    assert_non_null(app.prompt);
    assert_int_equal(tui_prompt_key(&app, &in, &open, '1'), INPUT_EDITING);
    assert_int_equal(tui_prompt_key(&app, &in, &open, KEY_F(5)),
                     INPUT_EDITING);  /* ignored keys keep it open */
    assert_int_equal(open, 1);
    assert_non_null(app.prompt);
    assert_int_equal(tui_prompt_key(&app, &in, &open, '\n'), INPUT_DONE);
    assert_int_equal(open, 0);
    assert_null(app.prompt);
    assert_null(app.input);
    assert_string_equal(in.text, "1");
    open = 1;
    tui_prompt(&app, "Range:", &in);
    assert_int_equal(tui_prompt_key(&app, &in, &open, 27), INPUT_CANCEL);
    assert_int_equal(open, 0);
    assert_null(app.prompt);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_actions),
        cmocka_unit_test(test_names),
        cmocka_unit_test(test_escape),
        cmocka_unit_test(test_input),
        cmocka_unit_test(test_prompt),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
