/*
 * test_tui_complete.c: path completion for the New run form, in a
 * directory made for the test: the common part of several candidates,
 * a lone file completed whole, a lone directory with its '/', only
 * directories and OBJ files offered, hidden entries only when asked for,
 * an unreadable directory, sorted candidates.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "tui/complete.h"

static char dir[256];

static void touch(const char *name)
{
    char path[512];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fclose(f);
}

static int setup(void **state)
{
    (void)state;
    snprintf(dir, sizeof dir, "/tmp/facet_complete_XXXXXX");
    if (mkdtemp(dir) == NULL)
        return -1;
    touch("roof.obj");
    touch("roof_big.OBJ");
    touch("roof.txt");
    touch("dome.obj");
    touch(".hidden.obj");
    char sub[512];
    snprintf(sub, sizeof sub, "%s/surfaces", dir);
    mkdir(sub, 0755);
    snprintf(sub, sizeof sub, "%s/surfaces/wave.obj", dir);
    FILE *f = fopen(sub, "w");
    if (f)
        fclose(f);
    return 0;
}

static int teardown(void **state)
{
    (void)state;
    char command[600];
    snprintf(command, sizeof command, "rm -rf '%s'", dir);
    return system(command) == 0 ? 0 : -1;
}

static void test_complete(void **state)
{
    (void)state;
    struct tui_completion c;
    char path[512], want[512];
    /* roof.obj and roof_big.OBJ share "roof"; roof.txt is no OBJ */
    snprintf(path, sizeof path, "%s/ro", dir);
    assert_int_equal(tui_complete_path(path, &c), 2);
    snprintf(want, sizeof want, "%s/roof", dir);
    assert_string_equal(c.text, want);
    assert_string_equal(c.name[0], "roof.obj");
    assert_string_equal(c.name[1], "roof_big.OBJ");
    /* one candidate: the whole name */
    snprintf(path, sizeof path, "%s/d", dir);
    assert_int_equal(tui_complete_path(path, &c), 1);
    snprintf(want, sizeof want, "%s/dome.obj", dir);
    assert_string_equal(c.text, want);
    /* a directory gets its slash, then its files complete */
    snprintf(path, sizeof path, "%s/su", dir);
    assert_int_equal(tui_complete_path(path, &c), 1);
    snprintf(want, sizeof want, "%s/surfaces/", dir);
    assert_string_equal(c.text, want);
    assert_int_equal(tui_complete_path(c.text, &c), 1);
    snprintf(want, sizeof want, "%s/surfaces/wave.obj", dir);
    assert_string_equal(c.text, want);
    /* everything in the directory, hidden ones left out */
    snprintf(path, sizeof path, "%s/", dir);
    assert_int_equal(tui_complete_path(path, &c), 4);
    assert_string_equal(c.text, path);   /* nothing shared */
    assert_string_equal(c.name[0], "dome.obj");
    assert_string_equal(c.name[3], "surfaces/");
    /* hidden ones when the name starts with a dot */
    snprintf(path, sizeof path, "%s/.h", dir);
    assert_int_equal(tui_complete_path(path, &c), 1);
    /* nothing matches; a missing directory */
    snprintf(path, sizeof path, "%s/zzz", dir);
    assert_int_equal(tui_complete_path(path, &c), 0);
    assert_string_equal(c.text, path);
    assert_int_equal(tui_complete_path("/nonexistent-dir/x", &c), 0);
    /* a relative path lists the current directory */
    char cwd[512];
    assert_non_null(getcwd(cwd, sizeof cwd));
    assert_int_equal(chdir(dir), 0);
    assert_int_equal(tui_complete_path("dom", &c), 1);
    assert_string_equal(c.text, "dome.obj");
    assert_int_equal(chdir(cwd), 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_complete),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
