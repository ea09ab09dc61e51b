/*
 * test_tui_map.c: the panel maps' arithmetic (map_model.h): a surface's
 * extent from its panels' corners against a plane of known sides, the
 * fitted picture's aspect, and what a character shows when it covers
 * several panels or part of one, against a brute force that samples each
 * character's share of the grid finely and counts.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/base/units.h"
#include "core/classify/classify.h"
#include "tui/map_model.h"

/* An nu x nv grid over a plane w x h (m) at z = 0, every cell a panel of
 * a type drawn from seed, a hole where the draw gives -1. */
static void grid(struct panelization *p, int nu, int nv, double w, double h,
                 unsigned seed, int holes)
{
    memset(p, 0, sizeof *p);
    p->nu = nu;
    p->nv = nv;
    p->umax = p->vmax = 1;
    p->panels = calloc((size_t)nu * (size_t)nv, sizeof *p->panels);
    p->cell_panel = calloc((size_t)nu * (size_t)nv, sizeof *p->cell_panel);
    assert_non_null(p->panels);
    assert_non_null(p->cell_panel);
    srand(seed);
    for (int j = 0; j < nv; j++)
        for (int i = 0; i < nu; i++) {
            int cell = j * nu + i;
            if (holes && rand() % 7 == 0) {
                p->cell_panel[cell] = -1;
                continue;
            }
            struct panel *q = &p->panels[p->npanels];
            q->i = i;
            q->j = j;
            q->type = (enum panel_type)(rand() % TYPE_COUNT);
            q->class = (enum panel_class)(rand() % CLASS_COUNT);
            double x0 = w * i / nu, x1 = w * (i + 1) / nu;
            double y0 = h * j / nv, y1 = h * (j + 1) / nv;
            double c[4][2] = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
            for (int k = 0; k < 4; k++) {
                q->corner[k][0] = c[k][0];
                q->corner[k][1] = c[k][1];
                q->corner[k][2] = 0;
            }
            p->cell_panel[cell] = (int)p->npanels++;
        }
}

static void grid_free(struct panelization *p)
{
    free(p->panels);
    free(p->cell_panel);
}

static void test_surface_size(void **state)
{
    (void)state;
    struct panelization p;
    grid(&p, 40, 38, 36.0, 24.0, 1, 0);
    double w, h;
    map_surface_size(&p, &w, &h);
    assert_true(fabs(w - 36.0) < 1e-9);
    assert_true(fabs(h - 24.0) < 1e-9);
    grid_free(&p);
}

static void test_fit_box(void **state)
{
    (void)state;
    int cols, rows;
    /* 36 m x 24 m in at most 43 x 17 characters twice as tall as wide:
     * 17 rows, 17 x 1.5 x 2 = 51 columns > 43, so 43 columns, 14 rows */
    map_fit_box(36, 24, 43, 17, 2.0, &cols, &rows);
    assert_int_equal(cols, 43);
    assert_int_equal(rows, 14);
    /* a tall surface fills the rows */
    map_fit_box(10, 40, 43, 17, 2.0, &cols, &rows);
    assert_int_equal(rows, 17);
    assert_int_equal(cols, 9);  /* 17 x 0.25 x 2 = 8.5, rounded */
    /* every box fits, and its aspect is the surface's to a character */
    for (int k = 1; k < 200; k++) {
        double w = k * 0.37, h = 50.0 / k;
        map_fit_box(w, h, 60, 20, 2.0, &cols, &rows);
        assert_true(cols >= 1 && cols <= 60 && rows >= 1 && rows <= 20);
        assert_true(cols == 60 || rows == 20 || cols == 1 || rows == 1);
        if (cols > 1 && rows > 1)
            assert_true(fabs(cols / (rows * 2.0) - w / h) <=
                        (w / h) / rows + 1.0 / (rows * 2.0));
    }
}

/* The panel (index, or -1) under sample (a, b) of an S x S sampling of
 * character (c, r) of a cols x rows picture of p. */
static int sampled_panel(const struct panelization *p, int cols, int rows,
                         int c, int r, int a, int b, int S)
{
    double u = (c + (a + 0.5) / S) / cols * p->nu;
    double v = (rows - 1 - r + (b + 0.5) / S) / rows * p->nv;
    return p->cell_panel[(int)floor(v) * p->nu + (int)floor(u)];
}

/* The brute force: sample the character's share of the grid on a fine
 * lattice, count the value under each sample. */
static int brute_cell(const struct panelization *p, int cols, int rows,
                      int c, int r, int by_class, double *margin)
{
    enum { S = 240 };
    double count[CLASS_COUNT + 1] = {0};
    for (int a = 0; a < S; a++)
        for (int b = 0; b < S; b++) {
            int k = sampled_panel(p, cols, rows, c, r, a, b, S);
            int value = k < 0 ? CLASS_COUNT
                        : by_class ? (int)p->panels[k].class
                                   : (int)p->panels[k].type;
            count[value]++;
        }
    int values = by_class ? CLASS_COUNT : TYPE_COUNT, best = -1;
    for (int k = 0; k < values; k++)
        if (count[k] > 0 && (best < 0 || count[k] >= count[best]))
            best = k;
    /* how clear the decision is: the gap to the nearest competitor */
    double second = count[CLASS_COUNT];
    for (int k = 0; k < values; k++)
        if (k != best && count[k] > second)
            second = count[k];
    *margin = best < 0 ? S * S : fabs(count[best] - second) / (S * S);
    return best >= 0 && count[best] >= count[CLASS_COUNT] ? best : -1;
}

static void test_cell_value(void **state)
{
    (void)state;
    int checked = 0;
    for (unsigned seed = 1; seed <= 6; seed++) {
        struct panelization p;
        int nu = 20 + (int)seed * 7, nv = 15 + (int)seed * 5;
        grid(&p, nu, nv, 30, 20, seed, seed % 2);
        int sizes[][2] = {{nu, nv}, {nu / 2, nv / 3}, {13, 9}, {57, 41},
                          {7, 5}};
        for (size_t z = 0; z < sizeof sizes / sizeof sizes[0]; z++) {
            int cols = sizes[z][0], rows = sizes[z][1];
            for (int by = 0; by < 2; by++)
                for (int r = 0; r < rows; r++)
                    for (int c = 0; c < cols; c++) {
                        double margin;
                        int want = brute_cell(&p, cols, rows, c, r, by,
                                              &margin);
                        if (margin < 0.01)
                            continue;  /* too close for the sampling */
                        assert_int_equal(map_cell_value(&p, cols, rows, c,
                                                        r, by, NULL), want);
                        checked++;
                    }
        }
        /* one character per panel shows each panel's own type */
        for (int j = 0; j < nv; j++)
            for (int i = 0; i < nu; i++) {
                int k = p.cell_panel[j * nu + i], c, r;
                map_cell_of(&p, nu, nv, i, j, &c, &r);
                assert_int_equal(c, i);
                assert_int_equal(r, nv - 1 - j);
                assert_int_equal(map_cell_value(&p, nu, nv, c, r, 0, NULL),
                                 k < 0 ? -1 : (int)p.panels[k].type);
            }
        grid_free(&p);
    }
    assert_true(checked > 10000);
}

/* By mould: each SP or DP panel in one of 12 families drawn from the seed,
 * FP panels in none. The same brute force, over the families (FP one
 * value, MAP_NO_MOULD); and a family's size is its panels, counted here. */
static void test_cell_value_by_mould(void **state)
{
    (void)state;
    enum { S = 120, FAMILIES = 12 };
    int checked = 0;
    for (unsigned seed = 1; seed <= 4; seed++) {
        struct panelization p;
        int nu = 18 + (int)seed * 5, nv = 12 + (int)seed * 3;
        grid(&p, nu, nv, 30, 20, seed, seed % 2);
        size_t size[FAMILIES] = {0};
        for (size_t k = 0; k < p.npanels; k++) {
            p.panels[k].mould = p.panels[k].type == TYPE_FP
                                    ? -1 : rand() % FAMILIES;
            if (p.panels[k].mould >= 0)
                size[p.panels[k].mould]++;
        }
        for (int f = 0; f < FAMILIES; f++)
            assert_int_equal(map_family_size(&p, f), size[f]);
        assert_int_equal(map_family_size(&p, -1), 0);
        int sizes[][2] = {{nu, nv}, {nu / 2, nv / 3}, {7, 5}};
        for (size_t z = 0; z < sizeof sizes / sizeof sizes[0]; z++) {
            int cols = sizes[z][0], rows = sizes[z][1];
            for (int r = 0; r < rows; r++)
                for (int c = 0; c < cols; c++) {
                    /* count[0] empty, [1] FP, [2 + f] family f */
                    double count[2 + FAMILIES] = {0};
                    for (int a = 0; a < S; a++)
                        for (int b = 0; b < S; b++) {
                            int k = sampled_panel(&p, cols, rows, c, r, a,
                                                  b, S);
                            count[k < 0 ? 0 : p.panels[k].mould + 2]++;
                        }
                    int best = -1;
                    double second = count[0];
                    for (int k = 1; k < 2 + FAMILIES; k++)
                        if (best < 0 || count[k] > count[best])
                            best = k;
                    for (int k = 1; k < 2 + FAMILIES; k++)
                        if (k != best && count[k] > second)
                            second = count[k];
                    if (fabs(count[best] - second) / (S * S) < 0.02)
                        continue;  /* too close for the sampling */
                    int want = count[best] < count[0] ? -1
                               : best == 1 ? MAP_NO_MOULD : best - 2;
                    assert_int_equal(map_cell_value(&p, cols, rows, c, r,
                                                    MAP_BY_MOULD, NULL),
                                     want);
                    checked++;
                }
        }
        grid_free(&p);
    }
    assert_true(checked > 500);
}

/* The levels of a map by gap or kink: with a limit, a half, three
 * quarters, the limit and beyond; without, the quarters of the worst;
 * NaN (never measured) is no level. A character shows the highest level
 * of any panel whose cell reaches into its share, against a brute force
 * that samples the share finely. */
static void test_cell_level_by_gap(void **state)
{
    (void)state;
    double bound[MAP_LEVELS];
    map_level_bounds(6, 99, bound);
    assert_true(bound[0] == 3 && bound[1] == 4.5 && bound[2] == 6 &&
                isinf(bound[3]));
    assert_int_equal(map_level(0, bound), 0);
    assert_int_equal(map_level(3, bound), 0);
    assert_int_equal(map_level(3.01, bound), 1);
    assert_int_equal(map_level(6, bound), 2);
    assert_int_equal(map_level(6.01, bound), 3);
    assert_int_equal(map_level(NAN, bound), -1);
    map_level_bounds(0, 8, bound);
    assert_true(bound[0] == 2 && bound[1] == 4 && bound[2] == 6);
    assert_int_equal(map_level(8, bound), 3);
    map_level_bounds(0, 0, bound);  /* a plane: every gap 0, level 0 */
    assert_int_equal(map_level(0, bound), 0);

    enum { S = 60 };
    int checked = 0;
    for (unsigned seed = 1; seed <= 3; seed++) {
        struct panelization p;
        int nu = 17 + (int)seed * 4, nv = 11 + (int)seed * 3;
        grid(&p, nu, nv, 30, 20, seed, seed % 2);
        for (size_t k = 0; k < p.npanels; k++) {
            p.panels[k].worst_gap = units_m_of_mm((rand() % 100) / 10.0);
            p.panels[k].worst_kink =
                (rand() % 7 == 0) ? NAN : units_rad_of_deg(1);
        }
        map_level_bounds(6, 0, bound);
        int sizes[][2] = {{nu, nv}, {nu / 2, nv / 3}, {7, 5}};
        for (size_t z = 0; z < sizeof sizes / sizeof sizes[0]; z++) {
            int cols = sizes[z][0], rows = sizes[z][1];
            for (int r = 0; r < rows; r++)
                for (int c = 0; c < cols; c++) {
                    int want = -1;
                    for (int a = 0; a < S; a++)
                        for (int b = 0; b < S; b++) {
                            int k = sampled_panel(&p, cols, rows, c, r, a,
                                                  b, S);
                            if (k < 0)
                                continue;
                            double g = units_mm(p.panels[k].worst_gap);
                            int level = g <= 3 ? 0 : g <= 4.5 ? 1
                                        : g <= 6 ? 2 : 3;
                            if (level > want)
                                want = level;
                        }
                    assert_int_equal(map_cell_value(&p, cols, rows, c, r,
                                                    MAP_BY_GAP, bound),
                                     want);
                    checked++;
                }
        }
        grid_free(&p);
    }
    assert_true(checked > 500);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_surface_size),
        cmocka_unit_test(test_fit_box),
        cmocka_unit_test(test_cell_value),
        cmocka_unit_test(test_cell_value_by_mould),
        cmocka_unit_test(test_cell_level_by_gap),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
