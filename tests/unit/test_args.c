/*
 * test_args.c: the shared option parser, each value landing where its
 * table's offset says.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/args.h"
#include "cli/command.h"

/* The values a test's tables parse into. */
struct values {
    const char *units, *output;
    int json;
};

static const struct arg_option forms_options[] = {
    {"units", 0, ARG_STRING, offsetof(struct values, units), "U",
     "the units", NULL},
    {"output", 'o', ARG_STRING, offsetof(struct values, output), "FILE",
     "where to write", NULL},
    {"json", 0, ARG_FLAG, offsetof(struct values, json), NULL, "as JSON",
     NULL},
    {NULL, 0, ARG_FLAG, 0, NULL, NULL, NULL},
};

static void test_forms(void **state)
{
    (void)state;
    struct values v = {NULL, NULL, 0};
    const struct arg_table own = {forms_options, &v};
    char *argv[] = {"info", "a.obj", "--units=mm", "-o", "x", "--json",
                    "--", "--b.obj"};
    const char *positional[2];
    int count;
    struct facet_error err;
    assert_int_equal(args_parse(8, argv, &own, NULL, positional, 2, &count,
                                &err), FACET_OK);
    assert_int_equal(count, 2);
    assert_string_equal(positional[0], "a.obj");
    assert_string_equal(positional[1], "--b.obj");
    assert_string_equal(v.units, "mm");
    assert_string_equal(v.output, "x");
    assert_int_equal(v.json, 1);
}

static void test_errors(void **state)
{
    (void)state;
    struct values v = {NULL, NULL, 0};
    const struct arg_table own = {forms_options, &v};
    const char *positional[1];
    int count;
    struct facet_error err;
    char *unknown[] = {"info", "--unit", "mm"};
    assert_int_equal(args_parse(3, unknown, &own, NULL, positional, 1,
                                &count, &err), FACET_EINPUT);
    assert_non_null(strstr(err.message, "--unit"));
    char *missing[] = {"info", "--units"};
    assert_int_equal(args_parse(2, missing, &own, NULL, positional, 1,
                                &count, &err), FACET_EINPUT);
    assert_non_null(strstr(err.message, "needs a value"));
    char *surplus[] = {"info", "a", "b"};
    assert_int_equal(args_parse(3, surplus, &own, NULL, positional, 1,
                                &count, &err), FACET_EINPUT);
    char *flag_value[] = {"info", "--json=1"};
    assert_int_equal(args_parse(2, flag_value, &own, NULL, positional, 1,
                                &count, &err), FACET_EINPUT);
}

/* Every unknown option of a line in its one error, each once, in the
 * order given, whatever else is wrong with the line; an unknown option
 * takes no value, so the word after it is read as usual; one unknown
 * option keeps its nearest known one. */
static void test_unknowns(void **state)
{
    (void)state;
    struct values v = {NULL, NULL, 0};
    const struct arg_table own = {forms_options, &v};
    const char *positional[1];
    int count;
    struct facet_error err;
    char *several[] = {"info", "--frob", "a.obj", "--json=1", "-q",
                       "--units", "--zap", "--frob=2", "b.obj", "--output"};
    assert_int_equal(args_parse(10, several, &own, NULL, positional, 1,
                                &count, &err), FACET_EINPUT);
    assert_string_equal(err.message, "info: unknown options '--frob', "
                        "'-q' (see 'facet info --help')");
    /* --units took --zap as its value: not an option there */
    char *after_value[] = {"info", "--unit", "--units", "--zap", "--zip"};
    assert_int_equal(args_parse(5, after_value, &own, NULL, positional, 1,
                                &count, &err), FACET_EINPUT);
    assert_string_equal(err.message, "info: unknown options '--unit', "
                        "'--zip' (see 'facet info --help')");
    char *one[] = {"info", "a.obj", "--jsn"};
    assert_int_equal(args_parse(3, one, &own, NULL, positional, 1, &count,
                                &err), FACET_EINPUT);
    assert_string_equal(err.message,
                        "info: unknown option '--jsn' (did you mean --json?)");
    /* More than one line holds: the first ones, and the rest counted. */
    enum { MANY = 200 };
    char *many[1 + MANY];
    char names[MANY][24];
    many[0] = "info";
    for (int k = 0; k < MANY; k++) {
        snprintf(names[k], sizeof names[k], "--no-such-%d", k);
        many[1 + k] = names[k];
    }
    assert_int_equal(args_parse(1 + MANY, many, &own, NULL, positional, 1,
                                &count, &err), FACET_EINPUT);
    assert_non_null(strstr(err.message, "info: unknown options '--no-such-0', "
                                        "'--no-such-1', "));
    assert_non_null(strstr(err.message, " more (see 'facet info --help')"));
    assert_null(strchr(err.message, '\n'));
    /* every option named or counted, none twice */
    int named = 0;
    for (const char *at = err.message; (at = strstr(at, "'--no-such-")); at++)
        named++;
    int more = atoi(strstr(err.message, " and ") + 5);
    assert_int_equal(named + more, MANY);
}

/* An ARG_LIST option given again and again: every value, in order, and
 * a clear error past ARG_LIST_MAX. */
struct list_values {
    struct arg_list lines;
};

static const struct arg_option list_options[] = {
    {"sbatch", 0, ARG_LIST, offsetof(struct list_values, lines), "LINE",
     "one more line", NULL},
    {NULL, 0, ARG_FLAG, 0, NULL, NULL, NULL},
};

static void test_list(void **state)
{
    (void)state;
    struct list_values v;
    memset(&v, 0, sizeof v);
    const struct arg_table own = {list_options, &v};
    char *argv[] = {"slurm", "--sbatch", "--gres=gpu:1", "x.obj",
                    "--sbatch=--mail-type=END", "--sbatch", "-N 2"};
    const char *positional[2];
    int count;
    struct facet_error err;
    assert_int_equal(args_parse(7, argv, &own, NULL, positional, 2, &count,
                                &err), FACET_OK);
    assert_int_equal(count, 1);
    assert_int_equal(v.lines.count, 3);
    assert_string_equal(v.lines.item[0], "--gres=gpu:1");
    assert_string_equal(v.lines.item[1], "--mail-type=END");
    assert_string_equal(v.lines.item[2], "-N 2");

    char *many[1 + 2 * (ARG_LIST_MAX + 1)];
    many[0] = "slurm";
    for (int k = 0; k < ARG_LIST_MAX + 1; k++) {
        many[1 + 2 * k] = "--sbatch";
        many[2 + 2 * k] = "-N 1";
    }
    memset(&v, 0, sizeof v);
    assert_int_equal(args_parse(1 + 2 * ARG_LIST_MAX, many, &own, NULL,
                                positional, 2, &count, &err), FACET_OK);
    assert_int_equal(v.lines.count, ARG_LIST_MAX);
    memset(&v, 0, sizeof v);
    assert_int_equal(args_parse(1 + 2 * (ARG_LIST_MAX + 1), many, &own,
                                NULL, positional, 2, &count, &err),
                     FACET_EINPUT);
    assert_non_null(strstr(err.message, "'--sbatch' is given more than"));
    char *missing[] = {"slurm", "--sbatch"};
    assert_int_equal(args_parse(2, missing, &own, NULL, positional, 2,
                                &count, &err), FACET_EINPUT);
    assert_non_null(strstr(err.message, "needs a value"));
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
 * in its own table's values, and a misspelling is matched against both. */
struct own_values {
    const char *grid;
};

struct shared_values {
    int flip;
    const char *units;
};

static const struct arg_option own_options[] = {
    {"grid", 'g', ARG_STRING, offsetof(struct own_values, grid), "NUxNV",
     "the grid", NULL},
    {NULL, 0, ARG_FLAG, 0, NULL, NULL, NULL},
};

static const struct arg_option shared_options[] = {
    {"units", 'u', ARG_STRING, offsetof(struct shared_values, units), "U",
     "the units", NULL},
    {"flip-normals", 0, ARG_FLAG, offsetof(struct shared_values, flip), NULL,
     "flip them", NULL},
    {NULL, 0, ARG_FLAG, 0, NULL, NULL, NULL},
};

static void test_shared_table(void **state)
{
    (void)state;
    struct own_values o = {NULL};
    struct shared_values sv = {0, NULL};
    const struct arg_table own = {own_options, &o};
    const struct arg_table shared = {shared_options, &sv};
    char *argv[] = {"classify", "-u", "mm", "a.obj", "--grid", "3x4",
                    "--flip-normals"};
    const char *positional[1];
    int count;
    struct facet_error err;
    assert_int_equal(args_parse(7, argv, &own, &shared, positional, 1,
                                &count, &err), FACET_OK);
    assert_string_equal(o.grid, "3x4");
    assert_string_equal(sv.units, "mm");
    assert_int_equal(sv.flip, 1);
    assert_string_equal(positional[0], "a.obj");
    char *typo[] = {"classify", "--flip-normal"};
    assert_int_equal(args_parse(2, typo, &own, &shared, positional, 1,
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

static void default_two(char *out, size_t size)
{
    snprintf(out, size, "%d", 2);
}

/* The help of a table, as --help prints it: the names and value left,
 * another spelling on its entry's line, the default last, the text
 * wrapped from column 23 at 78 columns, a left column too wide for it
 * on a line of its own. */
static void test_help_lines(void **state)
{
    (void)state;
    static const struct arg_option table[] = {
        {"colour", 'c', ARG_STRING, 0, "C", "panels coloured by type or "
         "class", default_two},
        {"color", 0, ARG_STRING, 0, "C", NULL, NULL},
        {"json", 0, ARG_FLAG, 0, NULL, "one JSON object: vertices, "
         "texcoords, normals, faces (as in the file), triangles, has_uv",
         NULL},
        {"max-panel-area", 0, ARG_STRING, 0, "M2", "feasibility limit",
         NULL},
        {NULL, 0, ARG_FLAG, 0, NULL, NULL, NULL},
    };
    char *text = NULL;
    size_t size = 0;
    FILE *out = open_memstream(&text, &size);
    assert_non_null(out);
    args_print_help(out, table);
    fclose(out);
    assert_string_equal(text,
        "  --colour C, -c C, --color C\n"
        "                      panels coloured by type or class (default 2)\n"
        "  --json              one JSON object: vertices, texcoords, normals, "
        "faces (as\n"
        "                      in the file), triangles, has_uv\n"
        "  --max-panel-area M2 feasibility limit\n");
    free(text);
}

/* Every command's tables as the parser and --help read them: a value's
 * name for every valued option, help for every entry but another
 * spelling of the one before, and no flag or alias in both of a
 * command's tables (the second would never be reached). */
static void test_command_tables(void **state)
{
    (void)state;
    for (int c = 0; command_table[c] != NULL; c++) {
        const struct command *cmd = command_table[c];
        const struct arg_option *tables[2] = {cmd->options, cmd->shared};
        const struct arg_option *all[128];
        size_t n = 0;
        for (int t = 0; t < 2; t++)
            for (const struct arg_option *o = tables[t];
                 o != NULL && o->name != NULL; o++) {
                if (o->kind != ARG_FLAG && o->value == NULL)
                    fail_msg("%s --%s: no value name", cmd->name, o->name);
                if (o->help == NULL && o == tables[t])
                    fail_msg("%s --%s: no help", cmd->name, o->name);
                assert_true(n < 128);
                all[n++] = o;
            }
        for (size_t i = 0; i < n; i++)
            for (size_t j = i + 1; j < n; j++)
                if (strcmp(all[i]->name, all[j]->name) == 0 ||
                    (all[i]->alias && all[i]->alias == all[j]->alias))
                    fail_msg("%s: --%s twice", cmd->name, all[i]->name);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_forms),
        cmocka_unit_test(test_errors),
        cmocka_unit_test(test_shared_table),
        cmocka_unit_test(test_unknowns),
        cmocka_unit_test(test_list),
        cmocka_unit_test(test_numbers),
        cmocka_unit_test(test_grid_override),
        cmocka_unit_test(test_help_lines),
        cmocka_unit_test(test_command_tables),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
