/*
 * test_tui_parallel.c: the parallel coordinates' arithmetic: values to dot
 * rows (clamped, flat ranges, NaN), brush edges stepped and rounded
 * outward, typed ranges, the brush written as a --where filter that the
 * real filter compiler accepts and that reads back into the same brushes
 * (with the filter's other terms kept), and lines on the braille canvas.
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

#include "store/filter.h"
#include "tui/parallel_model.h"

enum { U, V, T, PLANARITY, DP, COST, FP, SP };

static void ranges(struct pc_state *st)
{
    memset(st, 0, sizeof *st);
    static const double lo[PC_AXES] = {4, 4, 2, 0, 826.21, 1551317.2,
                                       169.54, 0};
    static const double hi[PC_AXES] = {8, 8, 4, 2.5217, 1069.74, 1742720.4,
                                       296.7, 116.38};
    for (int a = 0; a < PC_AXES; a++) {
        st->min[a] = lo[a];
        st->max[a] = hi[a];
    }
}

static void test_axes(void **state)
{
    (void)state;
    assert_string_equal(pc_axes[U].column, "nu");
    assert_string_equal(pc_axes[COST].column, "cost");
    assert_string_equal(pc_axes[SP].column, "sp_area");
    assert_int_equal(pc_axis_dot(10, 0, 10, 40), 0);    /* max at the top */
    assert_int_equal(pc_axis_dot(0, 0, 10, 40), 39);    /* min at the bottom */
    assert_int_equal(pc_axis_dot(5, 0, 10, 41), 20);
    assert_int_equal(pc_axis_dot(-5, 0, 10, 40), 39);   /* clamped */
    assert_int_equal(pc_axis_dot(50, 0, 10, 40), 0);
    assert_int_equal(pc_axis_dot(3, 3, 3, 40), 20);     /* flat range */
    assert_int_equal(pc_axis_dot(NAN, 0, 10, 40), -1);
    assert_int_equal(pc_axis_dot(INFINITY, 0, 10, 40), -1);
    assert_int_equal(pc_axis_dot(1, 0, 10, 0), -1);
}

static void test_brush_steps(void **state)
{
    (void)state;
    struct pc_state st;
    ranges(&st);
    char text[512];
    struct facet_error err;
    assert_int_equal(pc_filter_text(&st, text, sizeof text, &err),
                     FACET_OK);
    assert_string_equal(text, "");
    /* the high edge of cost down two steps: 1/20 of the range each,
     * rounded up to a thousand (a hundredth of the range's magnitude) */
    pc_brush_move(&st, COST, 1, -2);
    assert_true(st.brush[COST].active);
    assert_true(st.brush[COST].lo == st.min[COST]);
    double step = (1742720.4 - 1551317.2) / 20;
    assert_true(st.brush[COST].hi >= 1742720.4 - 2 * step);
    assert_true(st.brush[COST].hi < 1742720.4 - 2 * step + 1000);
    assert_true(fmod(st.brush[COST].hi, 1000) == 0);
    pc_filter_text(&st, text, sizeof text, &err);
    assert_string_equal(text, "cost <= 1724000");
    /* integer axes step by whole numbers */
    pc_brush_move(&st, U, 0, 1);
    assert_true(st.brush[U].lo == 5);
    pc_filter_text(&st, text, sizeof text, &err);
    assert_string_equal(text, "nu >= 5 and cost <= 1724000");
    /* edges never cross, and stay in the range */
    pc_brush_move(&st, U, 0, 100);
    assert_true(st.brush[U].lo == 8 && st.brush[U].hi == 8);
    pc_brush_move(&st, U, 1, -100);
    assert_true(st.brush[U].lo == 8 && st.brush[U].hi == 8);
    pc_brush_move(&st, U, 0, -100);
    assert_true(st.brush[U].lo == 4 && st.brush[U].hi == 8);
    assert_false(st.brush[U].active);   /* the whole range: no brush */
    /* back out to the whole range: the brush goes */
    pc_brush_move(&st, COST, 1, 5);
    assert_false(st.brush[COST].active);
    assert_int_equal(pc_filter_text(&st, text, sizeof text, &err),
                     FACET_OK);
    assert_string_equal(text, "");
    /* a small metric rounds to hundredths */
    pc_brush_move(&st, PLANARITY, 0, 3);
    pc_filter_text(&st, text, sizeof text, &err);
    assert_string_equal(text, "planarity >= 0.37");
    /* no range (no options): nothing happens */
    st.min[DP] = st.max[DP] = NAN;
    pc_brush_move(&st, DP, 0, 1);
    assert_false(st.brush[DP].active);
    /* too small a buffer */
    assert_int_equal(pc_filter_text(&st, text, 5, &err), FACET_EINPUT);
    assert_string_equal(err.message, "the filter is too long");
}

static void test_typed_range(void **state)
{
    (void)state;
    double lo, hi;
    struct facet_error err;
    assert_int_equal(pc_parse_range("1.1M:1.2M", 0, 9e9, &lo, &hi, &err),
                     FACET_OK);
    assert_true(lo == 1.1e6 && hi == 1.2e6);
    assert_int_equal(pc_parse_range("1.5e6..1.6e6", 0, 9e9, &lo, &hi, &err),
                     FACET_OK);
    assert_true(lo == 1.5e6 && hi == 1.6e6);
    assert_int_equal(pc_parse_range(":900", 826, 1069, &lo, &hi, &err),
                     FACET_OK);
    assert_true(lo == 826 && hi == 900);
    assert_int_equal(pc_parse_range("20: ", 4, 60, &lo, &hi, &err),
                     FACET_OK);
    assert_true(lo == 20 && hi == 60);
    assert_int_equal(pc_parse_range("2 3", 0, 9, &lo, &hi, &err),
                     FACET_OK);
    assert_true(lo == 2 && hi == 3);
    assert_int_equal(pc_parse_range("800k:", 0, 9e9, &lo, &hi, &err),
                     FACET_OK);
    assert_true(lo == 8e5);
    assert_int_equal(pc_parse_range(":", 0, 9, &lo, &hi, &err),
                     FACET_EINPUT);
    assert_int_equal(pc_parse_range("abc:3", 0, 9, &lo, &hi, &err),
                     FACET_EINPUT);
    assert_int_equal(pc_parse_range("3", 0, 9, &lo, &hi, &err),
                     FACET_EINPUT);
    assert_int_equal(pc_parse_range("1:nan", 0, 9, &lo, &hi, &err),
                     FACET_EINPUT);
    assert_string_equal(err.message, "range: '1:nan' is not LO:HI (e.g. "
                                     "1.1M:1.2M, :900, 20:)");
    /* a set range is ordered and clamped */
    struct pc_state st;
    ranges(&st);
    pc_brush_set(&st, DP, 950, 900);
    assert_true(st.brush[DP].lo == 900 && st.brush[DP].hi == 950);
    pc_brush_set(&st, DP, 0, 1e9);
    assert_false(st.brush[DP].active);
}

/* The brushes' text compiles; its canonical form reads back into the same
 * brushes, with the rest of the filter kept as the base. */
static void test_filter_round_trip(void **state)
{
    (void)state;
    struct pc_state st;
    ranges(&st);
    snprintf(st.base, sizeof st.base, "pareto");
    pc_brush_set(&st, COST, 1.6e6, 1.7e6);
    pc_brush_set(&st, V, 5, 8);
    char text[512];
    struct facet_error err;
    assert_int_equal(pc_filter_text(&st, text, sizeof text, &err),
                     FACET_OK);
    assert_string_equal(text, "pareto and nv >= 5 and cost >= 1600000 and "
                              "cost <= 1700000");
    struct filter *f;
    assert_int_equal(filter_compile(text, &f, &err), FACET_OK);
    struct pc_state back;
    ranges(&back);
    pc_from_filter(&back, filter_text(f));
    filter_free(f);
    assert_string_equal(back.base, "pareto");
    assert_true(back.brush[COST].active);
    assert_true(back.brush[COST].lo == 1.6e6 && back.brush[COST].hi == 1.7e6);
    assert_true(back.brush[V].active && back.brush[V].lo == 5 &&
                back.brush[V].hi == 8);
    assert_false(back.brush[U].active);
    /* a typed filter becomes brushes too */
    assert_int_equal(filter_compile("cost >= 1.6e6 and cost <= 1.65M and "
                                    "dp_area < 900", &f, &err), FACET_OK);
    ranges(&back);
    pc_from_filter(&back, filter_text(f));
    filter_free(f);
    assert_true(back.brush[COST].active && back.brush[COST].lo == 1.6e6 &&
                back.brush[COST].hi == 1.65e6);
    /* a strict comparison is an edge that excludes itself (issue 32 item
     * 11: the help's own example, "cost < 1.6M", drew no brush), and its
     * text says it again as it was */
    assert_string_equal(back.base, "");
    assert_true(back.brush[DP].active && back.brush[DP].hi == 900 &&
                back.brush[DP].hi_open && !back.brush[DP].lo_open);
    assert_false(back.brush[COST].lo_open || back.brush[COST].hi_open);
    assert_int_equal(pc_filter_text(&back, text, sizeof text, &err),
                     FACET_OK);
    assert_string_equal(text, "dp_area < 900 and cost >= 1600000 and "
                              "cost <= 1650000");
    /* ">" at the axis's own minimum still excludes it; "=" is both
     * edges, closed; an edge moved includes itself again */
    assert_int_equal(filter_compile("cost > 1551317.2 and nu = 6", &f, &err),
                     FACET_OK);
    ranges(&back);
    pc_from_filter(&back, filter_text(f));
    filter_free(f);
    assert_true(back.brush[U].active && back.brush[U].lo == 6 &&
                back.brush[U].hi == 6 && !back.brush[U].lo_open &&
                !back.brush[U].hi_open);
    assert_true(back.brush[COST].active && back.brush[COST].lo_open);
    pc_filter_text(&back, text, sizeof text, &err);
    assert_non_null(strstr(text, "cost > 1551317.2"));
    pc_brush_move(&back, COST, 0, 1);
    assert_false(back.brush[COST].lo_open);
    /* an "or" at the top is all base, and is parenthesised when more is
     * added to it */
    assert_int_equal(filter_compile("cost <= 1.6M or pareto", &f, &err),
                     FACET_OK);
    ranges(&back);
    pc_from_filter(&back, filter_text(f));
    filter_free(f);
    assert_false(back.brush[COST].active);
    pc_brush_set(&back, U, 6, 8);
    pc_filter_text(&back, text, sizeof text, &err);
    assert_string_equal(text, "((cost <= 1600000) or pareto) and nu >= 6");
    assert_int_equal(filter_compile(text, &f, &err), FACET_OK);
    filter_free(f);
    /* the empty filter: nothing */
    pc_from_filter(&back, "");
    assert_string_equal(back.base, "");
    for (int a = 0; a < PC_AXES; a++)
        assert_false(back.brush[a].active);
    /* a single comparison (no parentheses) is an edge */
    pc_from_filter(&back, "sp_area <= 50");
    assert_true(back.brush[SP].active && back.brush[SP].hi == 50);
}

static void test_canvas(void **state)
{
    (void)state;
    struct pc_canvas c;
    struct facet_error err;
    assert_int_equal(pc_canvas_init(&c, 4, 2, &err), FACET_OK);
    /* a horizontal line along the top dot row of both cell rows' first */
    pc_canvas_line(&c, 0, 0, 7, 0, 1);
    for (int x = 0; x < 4; x++) {
        assert_int_equal(c.level[x], 1);
        assert_int_equal(c.dots[x], 0x01 | 0x08);
        assert_int_equal(c.slope[x], '-');
    }
    assert_int_equal(c.level[4], 0);
    /* a higher level replaces the dots of a cell; a lower one is under */
    pc_canvas_line(&c, 0, 1, 0, 1, 3);
    assert_int_equal(c.level[0], 3);
    assert_int_equal(c.dots[0], 0x02);
    pc_canvas_line(&c, 1, 1, 1, 1, 2);
    assert_int_equal(c.dots[0], 0x02);
    /* a vertical line; dots outside are skipped */
    pc_canvas_line(&c, 7, -5, 7, 20, 2);
    assert_int_equal(c.slope[3], '|');
    assert_int_equal(c.dots[7], 0x80 | 0x20 | 0x10 | 0x08);
    /* rising to the right is '/' */
    pc_canvas_line(&c, 2, 7, 5, 1, 5);
    assert_int_equal(c.slope[5], '/');
    pc_canvas_free(&c);
    assert_int_equal(pc_canvas_init(&c, 0, 3, &err), FACET_EINPUT);
    pc_canvas_free(&c);
    char glyph[4];
    pc_braille(0, glyph);
    assert_string_equal(glyph, "\u2800");
    pc_braille(0xff, glyph);
    assert_string_equal(glyph, "\u28ff");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_axes),
        cmocka_unit_test(test_brush_steps),
        cmocka_unit_test(test_typed_range),
        cmocka_unit_test(test_filter_round_trip),
        cmocka_unit_test(test_canvas),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
