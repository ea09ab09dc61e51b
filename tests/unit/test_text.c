/*
 * test_text.c: text_break, the one word-wrapper of the workbench's status
 * line and Compare and of the SVG plot's legend, against rows worked out
 * by hand: display columns of UTF-8 text (a multi-byte glyph is one
 * column), breaks at blanks, a figure kept with its unit, a word wider
 * than the row cut on a character's boundary (issue 32 item 2).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <string.h>

#include "core/base/text.h"

#define MAX_ROWS 16

/* text wrapped at width as the callers do: a row, the blanks after it
 * skipped, the next row; the rows joined by '|' into out. */
static void wrap(const char *text, int width, char *out, size_t size)
{
    size_t used = 0;
    out[0] = '\0';
    for (int row = 0; *text != '\0'; row++) {
        assert_true(row < MAX_ROWS);
        size_t n = text_break(text, width);
        assert_true(n > 0);
        assert_true(used + n + 2 < size);
        if (row > 0)
            out[used++] = '|';
        memcpy(out + used, text, n);
        used += n;
        out[used] = '\0';
        text += n;
        while (*text == ' ')
            text++;
    }
}

static void check(const char *text, int width, const char *want)
{
    char out[512];
    wrap(text, width, out, sizeof out);
    assert_string_equal(out, want);
}

/* ASCII: whole text, breaks at the last blank that fits, a blank right
 * after a full row, a leading blank that is no break. */
static void test_ascii(void **state)
{
    (void)state;
    check("abc def", 7, "abc def");
    check("abc def", 8, "abc def");
    check("abc def", 3, "abc|def");
    check("abc def", 6, "abc|def");
    check("ab cdefgh", 4, "ab|cdef|gh");
    check("abcdefgh", 3, "abc|def|gh");
    check("a b c", 1, "a|b|c");
    check(" Map: option", 3, " Ma|p:|opt|ion");
    check("front at bounds of the space", 10,
          "front at|bounds of|the space");
}

/* UTF-8: a glyph of two or three bytes is one column, so "façade" (7
 * bytes) fits 6 columns, and a cut falls between characters. A byte-
 * counting wrapper gives "faça|de" at 6 and cuts "é" in two at 3. */
static void test_utf8(void **state)
{
    (void)state;
    check("façade panels", 6, "façade|panels");
    check("façade panels", 13, "façade panels");
    check("façade panels", 12, "façade|panels");
    check("ééééé", 3, "ééé|éé");
    check("ééééé", 5, "ééééé");
    check("1,240 m² → 2 m²", 8, "1,240 m²|→ 2 m²");
    check("€€ €€€", 2, "€€|€€|€");
    /* the rows never hold more columns than width */
    const char *text = "surface 1 of 4: façade (15 × 12), Größe °C ≤ 4";
    for (int width = 1; width <= 50; width++) {
        const char *t = text;
        while (*t != '\0') {
            size_t n = text_break(t, width);
            int columns = 0;
            for (size_t k = 0; k < n; k++)
                columns += (t[k] & 0xC0) != 0x80;
            assert_true(columns <= width);
            assert_true((t[n] & 0xC0) != 0x80);  /* a character's start */
            t += n;
            while (*t == ' ')
                t++;
        }
    }
}

/* A byte that is not UTF-8 is a column, as the terminal shows it: '?'. */
static void test_bad_bytes(void **state)
{
    (void)state;
    check("\xff\xff" "ab cd", 4, "\xff\xff" "ab|cd");
    check("\xff\xff\xff", 2, "\xff\xff|\xff");
}

/* A unit stays with its figure while another blank will do: "t 4.00 mm"
 * never reads "t 4.00|mm"; a unit is separated only when figure and unit
 * together are wider than the row, and then at the blank, never cut. */
static void test_units(void **state)
{
    (void)state;
    check("t 4.00 mm", 7, "t|4.00 mm");
    check("t 4.00 mm", 8, "t|4.00 mm");
    check("t 4.00 mm", 9, "t 4.00 mm");
    check("gap 3 mm, kink 2 deg", 10, "gap 3 mm,|kink 2 deg");
    check("area 1240 m^2 of it", 11, "area|1240 m^2 of|it");
    check("area 1240 m^2 of it", 10, "area|1240 m^2|of it");
    check("4.00 mm thick", 5, "4.00|mm|thick");
    /* a word that is no unit may follow a figure on its own row */
    check("run 1 paper space", 6, "run 1|paper|space");
}

/* Columns and cuts by hand: a glyph of two or three bytes is one
 * column, a byte that is not UTF-8 one column, a cut never inside a
 * character. */
static void test_columns(void **state)
{
    (void)state;
    assert_int_equal(text_columns(""), 0);
    assert_int_equal(text_columns("façade"), 6);
    assert_int_equal(text_columns("1,240 m² → 2 m²"), 15);
    assert_int_equal(text_columns("\xff\xff" "ab"), 4);
    assert_int_equal(text_columns("\x80" "a"), 2);  /* a lone continuation */
    assert_int_equal(text_cut("ééé", 2), 4);
    assert_int_equal(text_cut("ééé", 3), 6);
    assert_int_equal(text_cut("ééé", 9), 6);
    assert_int_equal(text_cut("abc", 0), 0);
    assert_int_equal(text_cut("abc", -1), 0);
    assert_int_equal(text_cut("fa\xc3\xa7" "ade", 3), 4);  /* "faç" */
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_ascii),
        cmocka_unit_test(test_utf8),
        cmocka_unit_test(test_bad_bytes),
        cmocka_unit_test(test_units),
        cmocka_unit_test(test_columns),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
