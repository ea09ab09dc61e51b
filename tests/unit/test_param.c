/*
 * test_param.c: the UV panels follow, against what the surface is.
 *
 * A structured quad grid takes its own (i, j): an NU x NV panel grid is one
 * panel per quad, each with the quad's area (a planar quad's, from its
 * diagonals) and corners. A surface with holes that folds when projected
 * gets the harmonic map of its capped disk: no fold, and its panels add up
 * to its area counted cell by cell. A vt map of several charts is refused,
 * naming them. The real files of ../shared/data (FACET_DATA): the
 * planar-quad roof and the barrel vault are flat panels at their own grids,
 * one panel per quad matched by brute force; the fish atlas is refused.
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
#include <unistd.h>

#include "core/evaluate/evaluate.h"
#include "core/surface/surface.h"
#include "core/base/vec3.h"
#include "tests/support/surface_fixture.h"

#define PI 3.14159265358979323846

/* --- writing and opening surfaces --- */

struct text {
    char *data;
    size_t length, capacity;
};

static void add(struct text *t, const char *fmt, ...)
    __attribute__((format(printf, 2, 3)));

static void add(struct text *t, const char *fmt, ...)
{
    for (;;) {
        va_list ap;
        va_start(ap, fmt);
        size_t room = t->capacity - t->length;
        int n = vsnprintf(t->data ? t->data + t->length : NULL,
                          t->data ? room : 0, fmt, ap);
        va_end(ap);
        assert_true(n >= 0);
        if (t->data && (size_t)n < room) {
            t->length += (size_t)n;
            return;
        }
        t->capacity = 2 * t->capacity + (size_t)n + 256;
        t->data = realloc(t->data, t->capacity);
        assert_non_null(t->data);
    }
}

/* Writes text to a temporary file and opens and prepares it with the UV
 * method want; the surface is left open for the caller (surface_close)
 * whatever the outcome, which is returned with err. */
static int open_text(struct text *t, enum param_method want,
                     struct surface *s, struct facet_error *err)
{
    char path[] = "/tmp/facet_test_param_XXXXXX";
    int fd = mkstemp(path);
    assert_true(fd >= 0);
    FILE *out = fdopen(fd, "w");
    fwrite(t->data, 1, t->length, out);
    fclose(out);
    free(t->data);
    memset(t, 0, sizeof *t);
    struct mesh_options options = {UNITS_M, NULL, NULL};
    int rc = surface_open(path, &options, s, err);
    if (rc == FACET_OK)
        rc = surface_prepare(s, 0, want, err);
    unlink(path);
    return rc;
}

static void evaluate(const struct surface *s, int nu, int nv,
                     struct panelization *p, struct option_totals *t)
{
    struct option_params params;
    memset(&params, 0, sizeof params);
    params.nu = nu;
    params.nv = nv;
    params.mode = PANEL_EXTREMES;
    classify_defaults(&params.classify);
    struct facet_error err;
    if (option_evaluate(s, &params, NULL, p, t, &err) != FACET_OK)
        fail_msg("%s", err.message);
}

/* --- a structured grid --- */

#define GRID_NU 7
#define GRID_NV 5

/* A translation surface z = f(x) + g(y) over unevenly spaced lines: every
 * quad is planar (z00 + z11 = z10 + z01) and of its own size. */
static void grid_point(int i, int j, double p[3])
{
    double x = i + 0.3 * i * i / GRID_NU;
    double y = 1.3 * j + 0.1 * j * j;
    p[0] = x;
    p[1] = y;
    p[2] = 0.2 * x * x / GRID_NU + 0.5 * sin(y);
}

/* The grid as OBJ quads, or as two triangles per quad (split along the
 * diagonal from its corner (i, j)), wound counter-clockwise seen from +z;
 * rows of the file along i (row_major) or along j. */
static void write_grid(struct text *t, int row_major, int triangles)
{
    for (int outer = 0; outer <= (row_major ? GRID_NV : GRID_NU); outer++)
        for (int inner = 0; inner <= (row_major ? GRID_NU : GRID_NV);
             inner++) {
            double p[3];
            grid_point(row_major ? inner : outer, row_major ? outer : inner,
                       p);
            add(t, "v %.17g %.17g %.17g\n", p[0], p[1], p[2]);
        }
    for (int j = 0; j < GRID_NV; j++)
        for (int i = 0; i < GRID_NU; i++) {
            int corner[4][2] = {{i, j}, {i + 1, j}, {i + 1, j + 1},
                                {i, j + 1}};
            int index[4];
            for (int k = 0; k < 4; k++) {
                int a = corner[k][0], b = corner[k][1];
                index[k] = row_major ? b * (GRID_NU + 1) + a + 1
                                     : a * (GRID_NV + 1) + b + 1;
            }
            if (triangles)
                add(t, "f %d %d %d\nf %d %d %d\n", index[0], index[1],
                    index[2], index[0], index[2], index[3]);
            else
                add(t, "f %d %d %d %d\n", index[0], index[1], index[2],
                    index[3]);
        }
}

/* Area of the planar quad (i, j): half the cross product of its
 * diagonals. */
static double grid_quad_area(int i, int j)
{
    double p00[3], p10[3], p11[3], p01[3], d1[3], d2[3], n[3];
    grid_point(i, j, p00);
    grid_point(i + 1, j, p10);
    grid_point(i + 1, j + 1, p11);
    grid_point(i, j + 1, p01);
    vec3_sub(p11, p00, d1);
    vec3_sub(p01, p10, d2);
    vec3_cross(d1, d2, n);
    return vec3_length(n) / 2;
}

/* The file's rows along i: u = i, v = j, one panel per quad with its
 * area, its four corners and no deviation; the same when the file holds
 * the quads as triangles. */
static void check_grid(int triangles)
{
    struct text t = {0};
    write_grid(&t, 1, triangles);
    struct surface s;
    struct facet_error err;
    if (open_text(&t, PARAM_AUTO, &s, &err) != FACET_OK)
        fail_msg("%s", err.message);
    assert_int_equal(s.param.method, PARAM_GRID);
    assert_int_equal(s.param.grid_nu, GRID_NU);
    assert_int_equal(s.param.grid_nv, GRID_NV);
    assert_non_null(strstr(s.param.reason, "7 x 5 quads, structured"));
    assert_int_equal(strstr(s.param.reason, "paired") != NULL, triangles);
    assert_int_equal(s.param.report.flipped, 0);
    assert_int_equal(s.param.report.overlapping, 0);
    /* The winding is kept: counter-clockwise faces, counter-clockwise UV. */
    const double *uv = s.param.uv;
    double turn = (uv[2] - uv[0]) * (uv[5] - uv[1]) -
                  (uv[3] - uv[1]) * (uv[4] - uv[0]);
    assert_true(turn > 0);

    struct panelization p;
    struct option_totals totals;
    evaluate(&s, GRID_NU, GRID_NV, &p, &totals);
    assert_int_equal(p.npanels, GRID_NU * GRID_NV);
    for (size_t n = 0; n < p.npanels; n++) {
        const struct panel *panel = &p.panels[n];
        double want = grid_quad_area(panel->i, panel->j);
        assert_true(fabs(panel->area - want) < 1e-9 * want);
        assert_false(panel->trimmed);
        assert_true(panel->deviation < 1e-9);
        assert_int_equal(panel->type, TYPE_FP);
        static const int offset[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
        for (int k = 0; k < 4; k++) {
            double q[3];
            grid_point(panel->i + offset[k][0], panel->j + offset[k][1], q);
            assert_true(vec3_distance(q, panel->corner[k]) < 1e-9);
        }
    }
    assert_true(fabs(totals.area_of[TYPE_FP] - s.mesh.area) < 1e-9 * s.mesh.area);
    panelization_free(&p);
    surface_close(&s);
}

static void test_grid_one_panel_per_quad(void **state)
{
    (void)state;
    check_grid(0);
}

static void test_grid_of_triangles(void **state)
{
    (void)state;
    check_grid(1);
}

/* The file's rows along j: u follows them, so the grid is 5 x 7, still
 * one panel per quad (matched by its corners) and unmirrored. */
static void test_grid_follows_file_rows(void **state)
{
    (void)state;
    struct text t = {0};
    write_grid(&t, 0, 0);
    struct surface s;
    struct facet_error err;
    if (open_text(&t, PARAM_AUTO, &s, &err) != FACET_OK)
        fail_msg("%s", err.message);
    assert_int_equal(s.param.method, PARAM_GRID);
    assert_int_equal(s.param.grid_nu, GRID_NV);
    assert_int_equal(s.param.grid_nv, GRID_NU);
    struct panelization p;
    struct option_totals totals;
    evaluate(&s, GRID_NV, GRID_NU, &p, &totals);
    assert_int_equal(p.npanels, GRID_NU * GRID_NV);
    int seen[GRID_NU][GRID_NV] = {{0}};
    for (size_t n = 0; n < p.npanels; n++) {
        const struct panel *panel = &p.panels[n];
        int found = 0;
        for (int i = 0; i < GRID_NU && !found; i++)
            for (int j = 0; j < GRID_NV && !found; j++) {
                double q[3];
                grid_point(i, j, q);
                double r[3];
                grid_point(i + 1, j + 1, r);
                int has_q = 0, has_r = 0;
                for (int k = 0; k < 4; k++) {
                    has_q |= vec3_distance(q, panel->corner[k]) < 1e-9;
                    has_r |= vec3_distance(r, panel->corner[k]) < 1e-9;
                }
                if (has_q && has_r) {
                    found = 1;
                    seen[i][j]++;
                    double want = grid_quad_area(i, j);
                    assert_true(fabs(panel->area - want) < 1e-9 * want);
                }
            }
        assert_true(found);
    }
    for (int i = 0; i < GRID_NU; i++)
        for (int j = 0; j < GRID_NV; j++)
            assert_int_equal(seen[i][j], 1);
    const double *uv = s.param.uv;
    double turn = (uv[2] - uv[0]) * (uv[5] - uv[1]) -
                  (uv[3] - uv[1]) * (uv[4] - uv[0]);
    assert_true(turn > 0);
    panelization_free(&p);
    surface_close(&s);
}

/* An L of quads is no grid (its inner corner is in three quads): the plane projection is taken
 * and says why; asking for the grid is refused with that reason. Asking
 * for vt without vt is refused; the harmonic map can be asked for. */
static void test_not_a_grid(void **state)
{
    (void)state;
    struct text t = {0};
    /* 3 x 3 vertices' quads minus the top right one: an L. */
    for (int j = 0; j <= 2; j++)
        for (int i = 0; i <= 2; i++)
            add(&t, "v %d %d %g\n", i, j, 0.1 * i * j);
    add(&t, "f 1 2 5 4\nf 2 3 6 5\nf 4 5 8 7\n");
    char copy[512];
    snprintf(copy, sizeof copy, "%.*s", (int)t.length, t.data);
    struct surface s;
    struct facet_error err;
    assert_int_equal(open_text(&t, PARAM_AUTO, &s, &err), FACET_OK);
    assert_int_equal(s.param.method, PARAM_PLANE);
    assert_non_null(strstr(s.param.reason, "not a structured quad grid"));
    assert_non_null(strstr(s.param.reason, "more quads than a grid's"));
    surface_close(&s);

    static const enum param_method refused[] = {PARAM_GRID, PARAM_VT};
    static const char *const because[] = {"more quads than a grid's",
                                          "no texture"};
    for (int k = 0; k < 2; k++) {
        add(&t, "%s", copy);
        assert_int_equal(open_text(&t, refused[k], &s, &err), FACET_EINPUT);
        assert_non_null(strstr(err.message, because[k]));
        assert_null(strchr(err.message, '\n'));
        surface_close(&s);
    }
    add(&t, "%s", copy);
    assert_int_equal(open_text(&t, PARAM_HARMONIC, &s, &err), FACET_OK);
    assert_int_equal(s.param.method, PARAM_HARMONIC);
    assert_int_equal(s.param.report.flipped, 0);
    surface_close(&s);
}

/* --- holes --- */

#define HOLED_NT 48
#define HOLED_NZ 24
#define HOLED_RADIUS 5.0
#define HOLED_SWEEP (240 * PI / 180)
#define HOLED_LENGTH 12.0

/* Whether cell (a, b) of the holed vault is cut away: a round oculus of
 * radius 2 m (by arc length and height) and a rectangular opening. */
static int holed_cut(int a, int b)
{
    double s = HOLED_RADIUS * HOLED_SWEEP * (a + 0.5) / HOLED_NT;
    double z = HOLED_LENGTH * (b + 0.5) / HOLED_NZ;
    double ds = s - HOLED_RADIUS * HOLED_SWEEP * 0.3, dz = z - 6;
    if (ds * ds + dz * dz < 4)
        return 1;
    return a >= 30 && a < 38 && b >= 14 && b < 20;
}

/* A 240-degree vault (its projection on any plane folds) with two holes,
 * as quads without vt; returns its area, counted cell by cell (each a
 * rectangle: a chord times a height). */
static double write_holed(struct text *t)
{
    for (int b = 0; b <= HOLED_NZ; b++)
        for (int a = 0; a <= HOLED_NT; a++) {
            double angle = HOLED_SWEEP * a / HOLED_NT;
            add(t, "v %.17g %.17g %.17g\n", HOLED_RADIUS * cos(angle),
                HOLED_LENGTH * b / HOLED_NZ, HOLED_RADIUS * sin(angle));
        }
    size_t kept = 0;
    for (int b = 0; b < HOLED_NZ; b++)
        for (int a = 0; a < HOLED_NT; a++) {
            if (holed_cut(a, b))
                continue;
            int v = b * (HOLED_NT + 1) + a + 1;
            add(t, "f %d %d %d %d\n", v, v + HOLED_NT + 1,
                v + HOLED_NT + 2, v + 1);
            kept++;
        }
    double chord = 2 * HOLED_RADIUS * sin(HOLED_SWEEP / HOLED_NT / 2);
    return (double)kept * chord * HOLED_LENGTH / HOLED_NZ;
}

static void test_holes_capped(void **state)
{
    (void)state;
    struct text t = {0};
    double area = write_holed(&t);
    struct surface s;
    struct facet_error err;
    if (open_text(&t, PARAM_AUTO, &s, &err) != FACET_OK)
        fail_msg("%s", err.message);
    assert_int_equal(s.mesh.nloops, 3);
    assert_true(fabs(s.mesh.area - area) < 1e-9 * area);
    assert_int_equal(s.param.method, PARAM_HARMONIC);
    assert_int_equal(s.param.holes, 2);
    assert_non_null(strstr(s.param.reason, "plane projection folds"));
    assert_non_null(strstr(s.param.reason, "2 holes capped"));
    assert_int_equal(s.param.report.flipped, 0);
    assert_int_equal(s.param.report.overlapping, 0);
    assert_int_equal(s.param.report.degenerate, 0);
    static const int grids[][2] = {{12, 10}, {7, 13}, {30, 20}};
    for (size_t g = 0; g < sizeof grids / sizeof *grids; g++) {
        struct panelization p;
        struct option_totals totals;
        evaluate(&s, grids[g][0], grids[g][1], &p, &totals);
        double sum = 0;
        size_t trimmed = 0;
        for (size_t n = 0; n < p.npanels; n++) {
            sum += p.panels[n].area;
            trimmed += p.panels[n].trimmed != 0;
        }
        assert_true(fabs(sum - area) < 1e-9 * area);
        assert_true(fabs(totals.area - area) < 1e-9 * area);
        assert_true(trimmed > 0);  /* the holes cut panels */
        panelization_free(&p);
    }
    surface_close(&s);

    /* Asked for, the plane projection is refused with what it folds. */
    write_holed(&t);
    assert_int_equal(open_text(&t, PARAM_PLANE, &s, &err), FACET_EINPUT);
    assert_non_null(strstr(err.message, "plane projection folds"));
    surface_close(&s);
}

/* A flat plate with a hole: the plane projection is taken, and the
 * harmonic map, asked for, folds nothing and adds up too. */
static void test_holed_plate(void **state)
{
    (void)state;
    for (int want = 0; want < 2; want++) {
        struct text t = {0};
        int n = 10;
        for (int j = 0; j <= n; j++)
            for (int i = 0; i <= n; i++)
                add(&t, "v %d %d 0\n", i, j);
        for (int j = 0; j < n; j++)
            for (int i = 0; i < n; i++) {
                if (i >= 3 && i < 6 && j >= 4 && j < 7)
                    continue;
                int v = j * (n + 1) + i + 1;
                add(&t, "f %d %d %d %d\n", v, v + 1, v + n + 2, v + n + 1);
            }
        struct surface s;
        struct facet_error err;
        if (open_text(&t, want ? PARAM_HARMONIC : PARAM_AUTO, &s, &err) !=
            FACET_OK)
            fail_msg("%s", err.message);
        assert_int_equal(s.param.method, want ? PARAM_HARMONIC : PARAM_PLANE);
        assert_int_equal(s.param.report.flipped, 0);
        assert_int_equal(s.param.report.overlapping, 0);
        struct panelization p;
        struct option_totals totals;
        evaluate(&s, 6, 5, &p, &totals);
        assert_true(fabs(totals.area - 91) < 1e-9 * 91);
        panelization_free(&p);
        surface_close(&s);
    }
}

/* --- charts --- */

/* Two unit squares side by side, as four triangles with vt: continuous
 * across the shared edge, or laid out as two charts apart in UV. */
static void write_two_squares(struct text *t, int split)
{
    add(t, "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nv 1 1 0\nv 2 1 0\n");
    add(t, "vt 0 0\nvt 0.5 0\nvt 1 0\nvt 0 1\nvt 0.5 1\nvt 1 1\n");
    add(t, "vt 0.6 0\nvt 0.6 1\n");  /* the right chart's left edge */
    int left = split ? 7 : 2, top = split ? 8 : 5;
    add(t, "f 1/1 2/2 5/5\nf 1/1 5/5 4/4\n");
    add(t, "f 2/%d 3/3 6/6\nf 2/%d 6/6 5/%d\n", left, left, top);
}

static void test_charts(void **state)
{
    (void)state;
    struct text t = {0};
    struct surface s;
    struct facet_error err;
    write_two_squares(&t, 0);
    assert_int_equal(open_text(&t, PARAM_AUTO, &s, &err), FACET_OK);
    assert_int_equal(s.param.method, PARAM_VT);
    surface_close(&s);

    write_two_squares(&t, 1);
    assert_int_equal(open_text(&t, PARAM_AUTO, &s, &err), FACET_EINPUT);
    assert_non_null(strstr(err.message, "2 separate UV charts"));
    assert_non_null(strstr(err.message, "2 triangles in u 0..0.5"));
    assert_non_null(strstr(err.message, "2 triangles in u 0.6..1"));
    assert_non_null(strstr(err.message, "select its object or group"));
    assert_int_equal(err.setting, FACET_SETTING_CHART);
    assert_null(strchr(err.message, '\n'));
    surface_close(&s);

    /* Asked for, vt is refused alike; the harmonic map ignores the vt. */
    write_two_squares(&t, 1);
    assert_int_equal(open_text(&t, PARAM_VT, &s, &err), FACET_EINPUT);
    surface_close(&s);
    write_two_squares(&t, 1);
    assert_int_equal(open_text(&t, PARAM_HARMONIC, &s, &err), FACET_OK);
    assert_int_equal(s.param.method, PARAM_HARMONIC);
    surface_close(&s);
}

/* --- the real files --- */


/* The file's quad faces, by brute force from the OBJ itself: the two
 * triangles of face f and their areas, in m^2. */
static void face_areas(const struct obj_file *obj, double *area)
{
    memset(area, 0, obj->nfaces * sizeof *area);
    for (size_t t = 0; t < obj->ntriangles; t++) {
        const double *a = obj->position + 3 * obj->corner[3 * t].v;
        const double *b = obj->position + 3 * obj->corner[3 * t + 1].v;
        const double *c = obj->position + 3 * obj->corner[3 * t + 2].v;
        double ab[3], ac[3], n[3];
        vec3_sub(b, a, ab);
        vec3_sub(c, a, ac);
        vec3_cross(ab, ac, n);
        area[obj->triangle_face[t]] += vec3_length(n) / 2;
    }
}

/* A quad grid of the real data at its own size: at least 95 % of its area
 * flat at the default 3 mm, and each panel exactly one of the file's
 * quads: its corners are the face's, its area the face's, every face
 * once. */
static void check_real_grid(const char *name, int nu, int nv)
{
    char path[1024];
    if (!surface_fixture_data(name, path, sizeof path))
        skip();
    struct surface s;
    struct facet_error err;
    if (surface_fixture_open(path, &s, &err) != FACET_OK)
        fail_msg("%s: %s", path, err.message);
    assert_int_equal(s.param.method, PARAM_GRID);
    assert_int_equal(s.param.grid_nu, nu);
    assert_int_equal(s.param.grid_nv, nv);
    struct panelization p;
    struct option_totals totals;
    evaluate(&s, nu, nv, &p, &totals);
    print_message("%s at %dx%d: %.1f %% of the area FP\n", name, nu, nv,
                  100 * totals.area_of[TYPE_FP] / totals.area);
    assert_true(totals.area_of[TYPE_FP] >= 0.95 * totals.area);
    assert_int_equal(p.npanels, (size_t)nu * nv);

    const struct obj_file *obj = &s.obj;
    double *area = malloc(obj->nfaces * sizeof *area);
    int *seen = calloc(obj->nfaces, sizeof *seen);
    assert_non_null(area);
    assert_non_null(seen);
    face_areas(obj, area);
    /* The corners of face f: its triangles' corners. */
    for (size_t n = 0; n < p.npanels; n++) {
        const struct panel *panel = &p.panels[n];
        double scale = panel->diameter;
        size_t found = obj->nfaces;
        for (size_t t = 0; t < obj->ntriangles && found == obj->nfaces;
             t += 2) {
            int matched = 0;
            for (int k = 0; k < 4; k++)
                for (int c = 0; c < 6; c++) {
                    const double *q = obj->position +
                                      3 * obj->corner[3 * t + c].v;
                    if (vec3_distance(q, panel->corner[k]) < 1e-9 * scale) {
                        matched++;
                        break;
                    }
                }
            if (matched == 4)
                found = obj->triangle_face[t];
        }
        assert_true(found < obj->nfaces);
        seen[found]++;
        assert_true(fabs(panel->area - area[found]) < 1e-9 * area[found]);
    }
    for (size_t f = 0; f < obj->nfaces; f++)
        assert_int_equal(seen[f], 1);
    free(area);
    free(seen);
    panelization_free(&p);
    surface_close(&s);
}

static void test_conical_roof(void **state)
{
    (void)state;
    check_real_grid("conical1.obj", 30, 36);
}

static void test_barrel(void **state)
{
    (void)state;
    check_real_grid("barrel.obj", 20, 20);
}

/* fish.obj, closed with a 5-chart atlas, is refused with its charts. */
static void test_fish_atlas(void **state)
{
    (void)state;
    char path[1024];
    if (!surface_fixture_data("fish.obj", path, sizeof path))
        skip();
    struct mesh_options options = {UNITS_M, NULL, NULL};
    struct surface s;
    struct facet_error err;
    assert_int_equal(surface_open(path, &options, &s, &err), FACET_OK);
    assert_int_equal(surface_prepare(&s, 0, PARAM_AUTO, &err), FACET_EINPUT);
    assert_non_null(strstr(err.message, "5 separate UV charts"));
    surface_close(&s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_grid_one_panel_per_quad),
        cmocka_unit_test(test_grid_of_triangles),
        cmocka_unit_test(test_grid_follows_file_rows),
        cmocka_unit_test(test_not_a_grid),
        cmocka_unit_test(test_holes_capped),
        cmocka_unit_test(test_holed_plate),
        cmocka_unit_test(test_charts),
        cmocka_unit_test(test_conical_roof),
        cmocka_unit_test(test_barrel),
        cmocka_unit_test(test_fish_atlas),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
