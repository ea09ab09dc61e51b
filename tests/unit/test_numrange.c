/*
 * test_numrange.c: the one parser of each design-space syntax (a range
 * A:B[:STEP], a pair LEFT x RIGHT) through the callers' own limits: the
 * grid sides and the threshold of a design space (optimize.h), a module
 * range (module.h) and a grid NUxNV, which the CLI and the New-run form
 * share. Each input against the values a designer means by it, written
 * out by hand, or against the whole message it is refused with.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <string.h>

#include "core/base/numrange.h"
#include "core/panel/panel.h"
#include "core/project/module.h"
#include "core/search/optimize.h"

enum syntax { SIDES, THRESHOLD, MODULE, GRID };

struct parse_case {
    enum syntax syntax;
    const char *text;
    /* NULL: accepted with v (sides: lo, hi; threshold: min, max, step;
     * module: width min, max, step, height min, max, step; grid: nu, nv);
     * else the whole message it is refused with */
    const char *refusal;
    double v[6];
};

#define NOT_SIDES(t) "--u: '" t "' is not N or a range A:B of whole numbers"
#define NOT_T(t) "--threshold: '" t "' is not a number, A:B or A:B:STEP"
#define NOT_MODULE(t) "--module: '" t "' is not a module range (WMIN:WMAX " \
    "x HMIN:HMAX in metres, each optionally :STEP, such as 1.2:2.0x1.0:1.6)"
#define NOT_GRID(t) "--grid: '" t "' is not NUxNV (e.g. 37x49)"
#define GRID_RANGE(t) "--grid: '" t "' is out of range (each side 1 to 2000)"

static const struct parse_case cases[] = {
    /* grid sides: whole numbers 1 to 2000, no step */
    {SIDES, "20:40", NULL, {20, 40}},
    {SIDES, "30", NULL, {30, 30}},
    {SIDES, "1:2000", NULL, {1, 2000}},
    {SIDES, "020:040", NULL, {20, 40}},
    {SIDES, "0:5", "--u: '0:5' is out of range (1 to 2000)", {0}},
    {SIDES, "2001", "--u: '2001' is out of range (1 to 2000)", {0}},
    {SIDES, "4294967297:4294967300",
     "--u: '4294967297:4294967300' is out of range (1 to 2000)", {0}},
    {SIDES, "99999999999999999999999",
     "--u: '99999999999999999999999' is out of range (1 to 2000)", {0}},
    {SIDES, "40:20", "--u: 40:20 runs backwards", {0}},
    {SIDES, "", NOT_SIDES(""), {0}},
    {SIDES, "20:", NOT_SIDES("20:"), {0}},
    {SIDES, ":40", NOT_SIDES(":40"), {0}},
    {SIDES, ":", NOT_SIDES(":"), {0}},
    {SIDES, "20::40", NOT_SIDES("20::40"), {0}},
    {SIDES, "20:40:2", NOT_SIDES("20:40:2"), {0}},
    {SIDES, "2x3", NOT_SIDES("2x3"), {0}},
    {SIDES, "-5", NOT_SIDES("-5"), {0}},
    {SIDES, "+5", NOT_SIDES("+5"), {0}},
    {SIDES, "1.5", NOT_SIDES("1.5"), {0}},
    {SIDES, "1e3", NOT_SIDES("1e3"), {0}},
    {SIDES, " 20:40", NOT_SIDES(" 20:40"), {0}},
    {SIDES, "20:40 ", NOT_SIDES("20:40 "), {0}},
    {SIDES, "0x10", NOT_SIDES("0x10"), {0}},
    {SIDES, "nan", NOT_SIDES("nan"), {0}},
    {SIDES, "inf", NOT_SIDES("inf"), {0}},

    /* threshold: decimals 0 to 1e6 mm, a step above 0, at most 1e6 steps */
    {THRESHOLD, "3", NULL, {3, 3, 0}},
    {THRESHOLD, "1:5", NULL, {1, 5, 0}},
    {THRESHOLD, "1:5:0.5", NULL, {1, 5, 0.5}},
    {THRESHOLD, ".5:2.5e0:+.25", NULL, {0.5, 2.5, 0.25}},
    {THRESHOLD, "0", NULL, {0, 0, 0}},
    {THRESHOLD, "1e6:1e6:1e6", NULL, {1e6, 1e6, 1e6}},
    {THRESHOLD, "0:999999:1", NULL, {0, 999999, 1}},   /* 1e6 steps */
    {THRESHOLD, "0:1e6:1",
     "--threshold: '0:1e6:1' is 1000001 steps (at most 1000000: take a "
     "larger step, or a continuous range A:B)", {0}},
    {THRESHOLD, "0:1e6:1e-300",
     "--threshold: '0:1e6:1e-300' is 1e+306 steps (at most 1000000: take "
     "a larger step, or a continuous range A:B)", {0}},
    {THRESHOLD, "1000000.1",
     "--threshold: '1000000.1' is out of range (0 to 1e+06)", {0}},
    {THRESHOLD, "-1", "--threshold: '-1' is out of range (0 to 1e+06)", {0}},
    {THRESHOLD, "1e999", "--threshold: '1e999' is out of range (0 to 1e+06)",
     {0}},
    {THRESHOLD, "1:1e999",
     "--threshold: '1:1e999' is out of range (0 to 1e+06)", {0}},
    {THRESHOLD, "1:5:1e999",
     "--threshold: '1:5:1e999' is out of range (0 to 1e+06)", {0}},
    {THRESHOLD, "5:1", "--threshold: 5:1 runs backwards", {0}},
    {THRESHOLD, "5:1:0.5", "--threshold: 5:1 runs backwards", {0}},
    {THRESHOLD, "1:5:0", "--threshold: the step of '1:5:0' must be above 0",
     {0}},
    {THRESHOLD, "1:5:-0",
     "--threshold: the step of '1:5:-0' must be above 0", {0}},
    {THRESHOLD, "1:5:-1",
     "--threshold: the step of '1:5:-1' must be above 0", {0}},
    {THRESHOLD, "1:5:2e6",
     "--threshold: the step of '1:5:2e6' must be at most 1e+06", {0}},
    {THRESHOLD, "", NOT_T(""), {0}},
    {THRESHOLD, "1:5:0.5:1", NOT_T("1:5:0.5:1"), {0}},
    {THRESHOLD, "1::2", NOT_T("1::2"), {0}},
    {THRESHOLD, "1:", NOT_T("1:"), {0}},
    {THRESHOLD, ":5", NOT_T(":5"), {0}},
    {THRESHOLD, "1:5:", NOT_T("1:5:"), {0}},
    {THRESHOLD, "nan", NOT_T("nan"), {0}},
    {THRESHOLD, "inf", NOT_T("inf"), {0}},
    {THRESHOLD, "1:-inf", NOT_T("1:-inf"), {0}},
    {THRESHOLD, "0x10", NOT_T("0x10"), {0}},
    {THRESHOLD, "1;2", NOT_T("1;2"), {0}},
    {THRESHOLD, "1 :5", NOT_T("1 :5"), {0}},
    {THRESHOLD, "1:5 ", NOT_T("1:5 "), {0}},
    {THRESHOLD, "3mm", NOT_T("3mm"), {0}},
    {THRESHOLD, "1e999:x", NOT_T("1e999:x"), {0}},

    /* module ranges: a pair of decimal ranges of at least 0.001 m, step
     * 0.1 m unless given, at most 10000 values each */
    {MODULE, "1.2:2.0x1.0:1.6", NULL, {1.2, 2.0, 0.1, 1.0, 1.6, 0.1}},
    {MODULE, "1.5x1.2", NULL, {1.5, 1.5, 0.1, 1.2, 1.2, 0.1}},
    {MODULE, " 1.2:2.0:0.25 \t x 1.5 ", NULL,
     {1.2, 2.0, 0.25, 1.5, 1.5, 0.1}},
    {MODULE, "1.2X1.0", NULL, {1.2, 1.2, 0.1, 1.0, 1.0, 0.1}},
    {MODULE, "1:1000x1", NULL, {1, 1000, 0.1, 1, 1, 0.1}},  /* 9991 */
    {MODULE, "0.001:0.001:0.001x1e300", NULL,
     {0.001, 0.001, 0.001, 1e300, 1e300, 0.1}},
    {MODULE, "1:2x", NOT_MODULE("1:2x"), {0}},
    {MODULE, "x1", NOT_MODULE("x1"), {0}},
    {MODULE, " x 1", NOT_MODULE(" x 1"), {0}},
    {MODULE, "1x1x1", NOT_MODULE("1x1x1"), {0}},
    {MODULE, "1xX1", NOT_MODULE("1xX1"), {0}},
    {MODULE, "1.2:2.0", NOT_MODULE("1.2:2.0"), {0}},
    {MODULE, "", NOT_MODULE(""), {0}},
    {MODULE, "0:1x1",
     "--module width: '0:1' is out of range (at least 0.001)", {0}},
    {MODULE, "1x1e-10",
     "--module height: '1e-10' is out of range (at least 0.001)", {0}},
    {MODULE, "1e999x1",
     "--module width: '1e999' is out of range (at least 0.001)", {0}},
    {MODULE, "1:2:1e-12x1",
     "--module width: the step of '1:2:1e-12' must be at least 0.001", {0}},
    {MODULE, "1:2:0x1",
     "--module width: the step of '1:2:0' must be at least 0.001", {0}},
    {MODULE, "2:1x1", "--module width: 2:1 runs backwards", {0}},
    {MODULE, "1:1001x1",
     "--module width: '1:1001' is 10001 steps (at most 10000: take a "
     "larger step)", {0}},
    {MODULE, "1x1:100000:0.001",
     "--module height: '1:100000:0.001' is 99999001 steps (at most 10000: "
     "take a larger step)", {0}},
    /* 10001 widths as module_widths counts them (within a billionth of a
     * step of 10001): over the limit, however close */
    {MODULE, "1:10000.9999999995:1x1",
     "--module width: '1:10000.9999999995:1' is 10001 steps (at most "
     "10000: take a larger step)", {0}},
    {MODULE, "ax1",
     "--module width: 'a' is not a number, A:B or A:B:STEP", {0}},
    {MODULE, "nanx1",
     "--module width: 'nan' is not a number, A:B or A:B:STEP", {0}},
    {MODULE, "1.2:2.0x1.0:1.6 junk",
     "--module height: '1.0:1.6 junk' is not a number, A:B or A:B:STEP",
     {0}},

    /* grids: a pair of whole numbers 1 to 2000 */
    {GRID, "37x49", NULL, {37, 49}},
    {GRID, "37X49", NULL, {37, 49}},
    {GRID, " 37 x\t49 ", NULL, {37, 49}},
    {GRID, "1x2000", NULL, {1, 2000}},
    {GRID, "37by49", NOT_GRID("37by49"), {0}},
    {GRID, "37x", NOT_GRID("37x"), {0}},
    {GRID, "x49", NOT_GRID("x49"), {0}},
    {GRID, "37x49x2", NOT_GRID("37x49x2"), {0}},
    {GRID, "37xx49", NOT_GRID("37xx49"), {0}},
    {GRID, "-1x5", NOT_GRID("-1x5"), {0}},
    {GRID, "+1x5", NOT_GRID("+1x5"), {0}},
    {GRID, "1.5x2", NOT_GRID("1.5x2"), {0}},
    {GRID, "1e2x5", NOT_GRID("1e2x5"), {0}},
    {GRID, "nanx5", NOT_GRID("nanx5"), {0}},
    {GRID, "37x49 junk", NOT_GRID("37x49 junk"), {0}},
    {GRID, "", NOT_GRID(""), {0}},
    {GRID, "99999999999999999999999x5y", NOT_GRID("99999999999999999999999x5y"),
     {0}},
    {GRID, "0x5", GRID_RANGE("0x5"), {0}},
    {GRID, "5x2001", GRID_RANGE("5x2001"), {0}},
    {GRID, "4294967297x5", GRID_RANGE("4294967297x5"), {0}},
    {GRID, "99999999999999999999999x5", GRID_RANGE("99999999999999999999999x5"),
     {0}},
};

/* Parses c's text by its syntax into v; the caller's return code. */
static int parse(const struct parse_case *c, double v[6],
                 struct facet_error *err)
{
    int rc, lo = 0, hi = 0;
    struct design_space space = {0};
    struct module_range m;
    switch (c->syntax) {
    case SIDES:
        rc = design_space_parse_sides(c->text, "--u", &lo, &hi, err);
        v[0] = lo;
        v[1] = hi;
        return rc;
    case THRESHOLD:
        rc = design_space_parse_threshold(c->text, "--threshold", &space,
                                          err);
        v[0] = space.t_min_mm;
        v[1] = space.t_max_mm;
        v[2] = space.t_step_mm;
        return rc;
    case MODULE:
        memset(&m, 0, sizeof m);
        rc = module_parse(c->text, "--module", &m, err);
        v[0] = m.width_min;
        v[1] = m.width_max;
        v[2] = m.width_step;
        v[3] = m.height_min;
        v[4] = m.height_max;
        v[5] = m.height_step;
        return rc;
    default:
        rc = numrange_grid(c->text, PANEL_MAX_GRID, "--grid", &lo, &hi, err);
        v[0] = lo;
        v[1] = hi;
        return rc;
    }
}

static void test_table(void **state)
{
    (void)state;
    for (size_t k = 0; k < sizeof cases / sizeof *cases; k++) {
        const struct parse_case *c = &cases[k];
        double v[6] = {0, 0, 0, 0, 0, 0};
        struct facet_error err;
        facet_error_clear(&err);
        int rc = parse(c, v, &err);
        if (c->refusal == NULL) {
            if (rc != FACET_OK)
                fail_msg("'%s' refused: %s", c->text, err.message);
            for (int i = 0; i < 6; i++)
                if (v[i] != c->v[i])
                    fail_msg("'%s': value %d is %.17g, want %.17g", c->text,
                             i, v[i], c->v[i]);
        } else {
            if (rc != FACET_EINPUT)
                fail_msg("'%s' accepted", c->text);
            if (strcmp(err.message, c->refusal) != 0)
                fail_msg("'%s': '%s'\n  want '%s'", c->text, err.message,
                         c->refusal);
        }
    }
}

/* -0 is the 0 it means: no "-0" reaches a table. */
static void test_minus_zero(void **state)
{
    (void)state;
    struct design_space space = {0};
    struct facet_error err;
    assert_int_equal(design_space_parse_threshold("-0:-0", "t", &space,
                                                  &err), FACET_OK);
    assert_false(signbit(space.t_min_mm));
    assert_false(signbit(space.t_max_mm));
}

/* A range's values, counted as its walk takes them: within slack of a
 * step the last one is on it; a count too large for any integer stays a
 * number that compares. */
static void test_count(void **state)
{
    (void)state;
    assert_true(numrange_count(1, 5, 0.5, 1e-3) == 9);
    assert_true(numrange_count(1.2, 2.0, 0.1, 1e-9) == 9);
    assert_true(numrange_count(0, 1, 0.3, 1e-3) == 4);   /* 0 .3 .6 .9 */
    assert_true(numrange_count(0, 0.9999, 0.1, 1e-3) == 10);
    assert_true(numrange_count(0, 0.99, 0.1, 1e-3) == 10);
    assert_true(numrange_count(0, 0.98, 0.1, 1e-3) == 10);
    assert_true(numrange_count(3, 3, 1, 1e-3) == 1);
    assert_true(numrange_count(1, 5, 0, 1e-3) == 1);     /* continuous */
    assert_true(numrange_count(0, 1e6, 1e-300, 1e-3) > 1e305);
}

/* The sides of a pair, blanks trimmed; each refusal. */
static void test_pair(void **state)
{
    (void)state;
    const char *text = " a:b\tX c ";
    struct numrange_pair p;
    assert_int_equal(numrange_pair_split(text, text + strlen(text), &p), 0);
    assert_int_equal(p.left - text, 1);
    assert_int_equal(p.left_end - text, 4);
    assert_int_equal(p.right - text, 7);
    assert_int_equal(p.right_end - text, 8);
    /* the end pointer bounds it: the x beyond it is not seen */
    const char *three = "1x2x3";
    assert_int_equal(numrange_pair_split(three, three + 3, &p), 0);
    const char *bad[] = {"", "x", "1x", "x1", " x ", "1 2", "1x2x3",
                         "1xX2"};
    for (size_t k = 0; k < sizeof bad / sizeof *bad; k++)
        if (numrange_pair_split(bad[k], bad[k] + strlen(bad[k]), &p) != -1)
            fail_msg("'%s' split", bad[k]);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_table),
        cmocka_unit_test(test_minus_zero),
        cmocka_unit_test(test_count),
        cmocka_unit_test(test_pair),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
