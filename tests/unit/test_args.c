/*
 * test_args.c: the shared option parser.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <string.h>

#include "cli/args.h"
#include "cli/command.h"

static void test_forms(void **state)
{
    (void)state;
    const char *units = NULL, *output = NULL;
    int json = 0;
    const struct arg_option options[] = {
        {"units", 0, ARG_STRING, &units, NULL},
        {"output", 'o', ARG_STRING, &output, NULL},
        {"json", 0, ARG_FLAG, NULL, &json},
        {NULL, 0, ARG_FLAG, NULL, NULL},
    };
    char *argv[] = {"info", "a.obj", "--units=mm", "-o", "x", "--json",
                    "--", "--b.obj"};
    const char *positional[2];
    int count;
    struct facet_error err;
    assert_int_equal(args_parse(8, argv, options, positional, 2, &count,
                                &err), FACET_OK);
    assert_int_equal(count, 2);
    assert_string_equal(positional[0], "a.obj");
    assert_string_equal(positional[1], "--b.obj");
    assert_string_equal(units, "mm");
    assert_string_equal(output, "x");
    assert_int_equal(json, 1);
}

static void test_errors(void **state)
{
    (void)state;
    const char *units = NULL;
    int json = 0;
    const struct arg_option options[] = {
        {"units", 0, ARG_STRING, &units, NULL},
        {"json", 0, ARG_FLAG, NULL, &json},
        {NULL, 0, ARG_FLAG, NULL, NULL},
    };
    const char *positional[1];
    int count;
    struct facet_error err;
    char *unknown[] = {"info", "--unit", "mm"};
    assert_int_equal(args_parse(3, unknown, options, positional, 1, &count,
                                &err), FACET_EINPUT);
    assert_non_null(strstr(err.message, "--unit"));
    char *missing[] = {"info", "--units"};
    assert_int_equal(args_parse(2, missing, options, positional, 1, &count,
                                &err), FACET_EINPUT);
    assert_non_null(strstr(err.message, "needs a value"));
    char *surplus[] = {"info", "a", "b"};
    assert_int_equal(args_parse(3, surplus, options, positional, 1, &count,
                                &err), FACET_EINPUT);
    char *flag_value[] = {"info", "--json=1"};
    assert_int_equal(args_parse(2, flag_value, options, positional, 1,
                                &count, &err), FACET_EINPUT);
}

static void test_numbers(void **state)
{
    (void)state;
    long n;
    struct facet_error err;
    assert_int_equal(args_int("37", 1, 100, "--u", &n, &err), FACET_OK);
    assert_int_equal(n, 37);
    assert_int_equal(args_int("0", 1, 100, "--u", &n, &err), FACET_EINPUT);
    assert_int_equal(args_int("3x", 1, 100, "--u", &n, &err), FACET_EINPUT);
    assert_int_equal(args_int("99999999999999999999", 1, 100, "--u", &n,
                              &err), FACET_EINPUT);
}

/* A command's own table and a shared one parse as one: each flag lands
 * where its own table points, and a misspelling is matched against both. */
static void test_shared_table(void **state)
{
    (void)state;
    const char *grid = NULL, *units = NULL;
    int flip = 0;
    const struct arg_option own[] = {
        {"grid", 'g', ARG_STRING, &grid, NULL},
        {NULL, 0, ARG_FLAG, NULL, NULL},
    };
    const struct arg_option shared[] = {
        {"units", 'u', ARG_STRING, &units, NULL},
        {"flip-normals", 0, ARG_FLAG, NULL, &flip},
        {NULL, 0, ARG_FLAG, NULL, NULL},
    };
    char *argv[] = {"classify", "-u", "mm", "a.obj", "--grid", "3x4",
                    "--flip-normals"};
    const char *positional[1];
    int count;
    struct facet_error err;
    assert_int_equal(args_parse_shared(7, argv, own, shared, positional, 1,
                                       &count, &err), FACET_OK);
    assert_string_equal(grid, "3x4");
    assert_string_equal(units, "mm");
    assert_int_equal(flip, 1);
    assert_string_equal(positional[0], "a.obj");
    char *typo[] = {"classify", "--flip-normal"};
    assert_int_equal(args_parse_shared(2, typo, own, shared, positional, 1,
                                       &count, &err), FACET_EINPUT);
    assert_non_null(strstr(err.message, "did you mean --flip-normals?"));
}

/* A project surface's own grid is a grid as facet classify reads one:
 * 12X40 and 12 x 40 are 12x40 there too. */
static void test_grid_override(void **state)
{
    (void)state;
    const char *good[] = {"roof_3=12x40", "roof_3=12X40", "roof_3=12 x 40",
                          "a=1x2,b=3X4"};
    for (size_t k = 0; k < sizeof good / sizeof *good; k++) {
        char *argv[] = {"optimize", "skin.obj", "--db", "runs.db",
                        "--module", "1.2x1.0", "--grid", (char *)good[k]};
        struct facet_error err;
        if (optimize_args_check(8, argv, &err) != FACET_OK)
            fail_msg("--grid %s: %s", good[k], err.message);
    }
    const char *bad[] = {"roof_3", "=12x40", "roof_3=12", "roof_3=0x40",
                         "roof_3=12x40x2", "roof_3=12xx40", "a=1x2,"};
    for (size_t k = 0; k < sizeof bad / sizeof *bad; k++) {
        char *argv[] = {"optimize", "skin.obj", "--db", "runs.db",
                        "--module", "1.2x1.0", "--grid", (char *)bad[k]};
        struct facet_error err;
        if (optimize_args_check(8, argv, &err) != FACET_EINPUT)
            fail_msg("--grid %s accepted", bad[k]);
        assert_non_null(strstr(err.message, "--grid"));
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_forms),
        cmocka_unit_test(test_errors),
        cmocka_unit_test(test_shared_table),
        cmocka_unit_test(test_numbers),
        cmocka_unit_test(test_grid_override),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
