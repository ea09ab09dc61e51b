/*
 * test_tui_project.c: the workbench's pure parts for a project's option
 * (issue 17): paging through the surfaces of the panel map (map_model.h)
 * against a walk that counts, the map's header, and the Surfaces
 * screen's rows (surface_rows.h): every field read back with sscanf,
 * every column right-aligned under its header, a long name cut, a joint
 * never measured shown as "-".
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "tui/map_model.h"
#include "tui/surface_rows.h"

/* ] from the first surface of 180 walks each in turn to the last and
 * stays there; [ walks back; one surface never moves. */
static void test_surface_step(void **state)
{
    (void)state;
    int k = 0;
    for (int step = 1; step <= 200; step++) {
        k = map_surface_step(k, 180, 1);
        assert_int_equal(k, step < 179 ? step : 179);
    }
    for (int step = 1; step <= 200; step++) {
        k = map_surface_step(k, 180, -1);
        assert_int_equal(k, step < 179 ? 179 - step : 0);
    }
    assert_int_equal(map_surface_step(0, 1, 1), 0);
    assert_int_equal(map_surface_step(0, 1, -1), 0);
    assert_int_equal(map_surface_step(3, 4, 1), 3);
}

static void test_surface_title(void **state)
{
    (void)state;
    char text[128];
    map_surface_title(text, sizeof text, 1, 4, "cylinder", 21, 30);
    assert_string_equal(text, "surface 2 of 4: cylinder (21 x 30)");
    map_surface_title(text, sizeof text, 179, 180, "F180", 7, 9);
    assert_string_equal(text, "surface 180 of 180: F180 (7 x 9)");
}

static struct option_surface_row sample_row(void)
{
    struct option_surface_row r;
    memset(&r, 0, sizeof r);
    r.nu = 21;
    r.nv = 30;
    r.totals.panels = 630;
    r.totals.count[TYPE_FP] = 180;
    r.totals.count[TYPE_SP] = 7;
    r.totals.count[TYPE_DP] = 443;
    r.totals.cost = 806543.9147;
    r.totals.moulds = 8;
    r.moulds_used = 11;
    r.totals.max_deviation = 0.0018716;  /* m: 1.87 mm */
    r.totals.max_gap = 0.0018716;         /* m: 1.87 mm */
    r.totals.max_kink = 3.3937 * M_PI / 180;  /* rad: 3.39 deg */
    return r;
}

/* The end (one past the last character) of each blank-separated field
 * of line, at most max of them. */
static int field_ends(const char *line, int ends[], int max)
{
    int n = 0;
    for (int k = 0; line[k] != '\0' && n < max; k++)
        if (line[k] != ' ' && (line[k + 1] == ' ' || line[k + 1] == '\0'))
            ends[n++] = k + 1;
    return n;
}

static void test_row_fields(void **state)
{
    (void)state;
    struct option_surface_row r = sample_row();
    char line[160], name[32], grid[16], cost[32], moulds[16];
    unsigned panels, fp, sp, dp;
    double dev, gap, kink;
    surface_rows_line(line, sizeof line, "cylinder", &r);
    assert_int_equal(strlen(line), SURFACE_ROW_WIDTH);
    assert_int_equal(sscanf(line, "%31s %15s %u %u %u %u %31s %15s %lf %lf "
                                  "%lf", name, grid, &panels, &fp, &sp, &dp,
                            cost, moulds, &dev, &gap, &kink), 11);
    assert_string_equal(name, "cylinder");
    assert_string_equal(grid, "21x30");
    assert_int_equal(panels, 630);
    assert_int_equal(fp, 180);
    assert_int_equal(sp, 7);
    assert_int_equal(dp, 443);
    assert_string_equal(cost, "806,544");
    assert_string_equal(moulds, "8/11");
    assert_true(fabs(dev - 1.87) < 1e-9);
    assert_true(fabs(gap - 1.87) < 1e-9);
    assert_true(fabs(kink - 3.39) < 1e-9);
}

/* Every value ends where its column's heading and unit end. */
static void test_row_columns(void **state)
{
    (void)state;
    char names[160], units[160], line[160];
    surface_rows_header(names, units, sizeof names);
    assert_int_equal(strlen(names), SURFACE_ROW_WIDTH);
    assert_int_equal(strlen(units), SURFACE_ROW_WIDTH);
    struct option_surface_row r = sample_row();
    surface_rows_line(line, sizeof line, "cylinder", &r);
    int head[16], row[16], unit[16];
    int nh = field_ends(names, head, 16);
    int nr = field_ends(line, row, 16);
    int nu = field_ends(units, unit, 16);
    assert_int_equal(nh, 11);
    assert_int_equal(nr, 11);
    /* the name column is left-aligned; the others right */
    for (int k = 1; k < nh; k++)
        assert_int_equal(row[k], head[k]);
    /* the units (cost on) sit under the last five columns' ends */
    assert_int_equal(nu, 5);
    for (int k = 0; k < nu; k++)
        assert_int_equal(unit[k], head[6 + k]);
}

static void test_row_cut_and_unknown(void **state)
{
    (void)state;
    struct option_surface_row r = sample_row();
    r.totals.max_gap = NAN;  /* no joint measured */
    r.totals.max_kink = NAN;
    char line[160], name[32];
    surface_rows_line(line, sizeof line, "a_very_long_surface_name", &r);
    assert_int_equal(strlen(line), SURFACE_ROW_WIDTH);
    assert_int_equal(sscanf(line, "%31s", name), 1);
    assert_string_equal(name, "a_very_long~");
    size_t n = strlen(line);
    assert_true(n > 17);
    assert_string_equal(line + n - 17, " 1.87     -     -");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_surface_step),
        cmocka_unit_test(test_surface_title),
        cmocka_unit_test(test_row_fields),
        cmocka_unit_test(test_row_columns),
        cmocka_unit_test(test_row_cut_and_unknown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
