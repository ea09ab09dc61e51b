/*
 * test_project.c: a project's surfaces (core/project), the example skin
 * they are tested on, the u and v lengths and the module grids.
 *
 * Truths: the skin's formula (skin_point) by quadrature and finite
 * differences, exact areas and lengths of its flat faces, a circle's arc
 * length, hand-computed grid counts, and the line numbers of small files
 * written here.
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

#include "core/project/module.h"
#include "core/project/project.h"
#include "core/project/project_lengths.h"
#include "core/surface/example.h"
#include "core/surface/example_skin.h"
#include "tests/support/quadrature.h"
#include "tests/support/temp_dir.h"

#define PI 3.14159265358979323846

static char dir[64];

static int make_dir(void **state)
{
    (void)state;
    return temp_dir_make(dir, sizeof dir, "project");
}

static int remove_dir(void **state)
{
    (void)state;
    return temp_dir_remove(dir);
}

/* Writes text to dir/name and returns the path (static storage, one of
 * four in turn). */
static const char *write_file(const char *name, const char *text)
{
    static char paths[4][128];
    static int next;
    char *path = paths[next++ % 4];
    snprintf(path, 128, "%s/%s", dir, name);
    FILE *out = fopen(path, "w");
    assert_non_null(out);
    fputs(text, out);
    fclose(out);
    return path;
}

static const char *write_skin(int res)
{
    static char path[128];
    snprintf(path, sizeof path, "%s/skin%d.obj", dir, res);
    FILE *out = fopen(path, "w");
    assert_non_null(out);
    struct facet_error err;
    assert_int_equal(skin_write(res, out, &err), FACET_OK);
    fclose(out);
    return path;
}

static void face_point(const void *data, double s, double t, double p[3])
{
    skin_point(*(const int *)data, s, t, p);
}

/* The area of face f by quadrature of its formula. */
static double face_area(int f)
{
    return quadrature_area(face_point, &f, 200);
}

/* The Gaussian curvature of face f at (s, t), and the largest normal
 * curvature's size, by finite differences of the formula. */
static void curvatures(int f, double s, double t, double *gauss,
                       double *largest)
{
    const double h = 1e-3;
    double p[3][3][3];
    for (int a = -1; a <= 1; a++)
        for (int b = -1; b <= 1; b++)
            skin_point(f, s + a * h, t + b * h, p[a + 1][b + 1]);
    double su[3], sv[3], suu[3], svv[3], suv[3], n[3];
    for (int k = 0; k < 3; k++) {
        su[k] = (p[2][1][k] - p[0][1][k]) / (2 * h);
        sv[k] = (p[1][2][k] - p[1][0][k]) / (2 * h);
        suu[k] = (p[2][1][k] - 2 * p[1][1][k] + p[0][1][k]) / (h * h);
        svv[k] = (p[1][2][k] - 2 * p[1][1][k] + p[1][0][k]) / (h * h);
        suv[k] = (p[2][2][k] - p[2][0][k] - p[0][2][k] + p[0][0][k]) /
                 (4 * h * h);
    }
    n[0] = su[1] * sv[2] - su[2] * sv[1];
    n[1] = su[2] * sv[0] - su[0] * sv[2];
    n[2] = su[0] * sv[1] - su[1] * sv[0];
    double length = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    double E = 0, F = 0, G = 0, L = 0, M = 0, N = 0;
    for (int k = 0; k < 3; k++) {
        n[k] /= length;
        E += su[k] * su[k];
        F += su[k] * sv[k];
        G += sv[k] * sv[k];
        L += suu[k] * n[k];
        M += suv[k] * n[k];
        N += svv[k] * n[k];
    }
    double det = E * G - F * F;
    *gauss = (L * N - M * M) / det;
    double mean = (E * N - 2 * F * M + G * L) / (2 * det);
    *largest = fabs(mean) + sqrt(fmax(0, mean * mean - *gauss));
}

static void test_skin_faces_are_what_they_say(void **state)
{
    (void)state;
    int kinds[3] = {0, 0, 0};
    for (int f = 0; f < SKIN_FACES; f++) {
        enum skin_kind kind = skin_face_kind(f);
        kinds[kind]++;
        double gauss = 0, largest = 0;
        double worst_gauss = 0, worst_largest = 0;
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++) {
                curvatures(f, 0.2 + 0.3 * i, 0.2 + 0.3 * j, &gauss,
                           &largest);
                worst_gauss = fmax(worst_gauss, fabs(gauss));
                worst_largest = fmax(worst_largest, largest);
            }
        if (kind == SKIN_FLAT && worst_largest > 1e-6)
            fail_msg("face %d: flat, but a curvature of %g", f,
                     worst_largest);
        if (kind == SKIN_SINGLE &&
            (worst_largest < 1e-3 || worst_gauss > 1e-6))
            fail_msg("face %d: single-curved, but k %g, K %g", f,
                     worst_largest, worst_gauss);
        if (kind == SKIN_DOUBLE && worst_gauss < 1e-6)
            fail_msg("face %d: double-curved, but K %g", f, worst_gauss);
    }
    assert_true(SKIN_FACES >= 100);
    assert_int_equal(kinds[SKIN_FLAT], 24);
    assert_int_equal(kinds[SKIN_SINGLE], 64);
    assert_int_equal(kinds[SKIN_DOUBLE], 92);
}

/* The whole file is one watertight tube: welded, one component, two
 * boundary loops (top and bottom), no edge used thrice. */
static void test_skin_is_watertight(void **state)
{
    (void)state;
    const char *path = write_skin(4);
    struct obj_file obj;
    struct facet_error err;
    assert_int_equal(obj_load(path, &obj, &err), FACET_OK);
    assert_int_equal(obj.nobjects, SKIN_FACES + 1);
    struct mesh_options options = {UNITS_M, NULL, NULL};
    struct mesh m;
    assert_int_equal(mesh_build(&obj, &options, &m, &err), FACET_OK);
    assert_int_equal(m.ntriangles, SKIN_FACES * 2 * 4 * 4);
    assert_int_equal(m.nvertices, SKIN_COLUMNS * 4 * (SKIN_ROWS * 4 + 1));
    assert_int_equal(m.ncomponents, 1);
    assert_int_equal(m.nloops, 2);
    assert_int_equal(m.nonmanifold_edges, 0);
    mesh_free(&m);
    obj_free(&obj);
}

static void test_skin_is_deterministic_and_refuses_bad_res(void **state)
{
    (void)state;
    char *a = NULL, *b = NULL;
    size_t na = 0, nb = 0;
    struct facet_error err;
    FILE *out = open_memstream(&a, &na);
    assert_int_equal(example_write("skin", 3, out, &err), FACET_OK);
    fclose(out);
    out = open_memstream(&b, &nb);
    assert_int_equal(skin_write(3, out, &err), FACET_OK);
    fclose(out);
    assert_int_equal(na, nb);
    assert_memory_equal(a, b, na);
    free(a);
    free(b);
    FILE *null = fopen("/dev/null", "w");
    assert_int_equal(skin_write(SKIN_MAX_RES + 1, null, &err), FACET_EINPUT);
    assert_int_equal(skin_write(-1, null, &err), FACET_EINPUT);
    fclose(null);
    FILE *full = fopen("/dev/full", "w");
    if (full != NULL) {
        assert_int_equal(skin_write(8, full, &err), FACET_EWORK);
        fclose(full);
    }
}

/* The skin as a project: 180 surfaces named as the example says, each
 * with its vt, areas against quadrature (exact on the flat faces), and
 * lengths against the faces' widths and arcs. */
static void test_skin_project(void **state)
{
    (void)state;
    const char *path = write_skin(16);
    struct project p;
    struct facet_error err;
    if (project_open(&path, 1, UNITS_M, &p, &err) != FACET_OK)
        fail_msg("%s", err.message);
    assert_int_equal(p.nsurfaces, SKIN_FACES);
    assert_int_equal(p.ntriangles, SKIN_FACES * 2 * 16 * 16);
    if (project_prepare(&p, 0, PARAM_AUTO, &err) != FACET_OK)
        fail_msg("%s", err.message);
    double total = 0;
    for (int f = 0; f < SKIN_FACES; f++) {
        const struct project_surface *s = &p.surfaces[f];
        char name[32];
        skin_face_name(f, name, sizeof name);
        assert_string_equal(s->name, name);
        assert_int_equal(s->key, PROJECT_OBJECT);
        assert_int_equal(s->surface.mesh.ntriangles, 2 * 16 * 16);
        assert_true(s->surface.mesh.has_uv);
        assert_int_equal(s->surface.param.method, PARAM_VT);
        assert_ptr_equal(project_find(&p, name), s);
        double oracle = face_area(f);
        double area = s->surface.mesh.area;
        total += area;
        if (fabs(area - oracle) > 2e-3 * oracle)
            fail_msg("%s: area %.6f, quadrature %.6f", name, area, oracle);
        int row = f / SKIN_COLUMNS, c = f % SKIN_COLUMNS;
        if (row < 2) {
            /* The podium: straights 12 m or 16 m wide, arcs a quarter of
             * an 18 m circle in 2 columns; 20 m high. */
            int arc = skin_face_kind(f) == SKIN_SINGLE;
            double width = arc ? 18 * PI / 4 : (c % 10 < 2 ? 12 : 16);
            double tolerance = arc ? 2e-3 * width : 1e-9 * width;
            if (!arc)
                assert_true(fabs(area - width * 20) < 1e-9 * area);
            if (fabs(s->u_length - width) > tolerance ||
                fabs(s->v_length - 20) > 1e-9 * 20)
                fail_msg("%s: u %.9f v %.9f, want %.9f and 20", name,
                         s->u_length, s->v_length, width);
        }
    }
    assert_true(fabs(total - p.area) < 1e-9 * total);
    assert_null(project_find(&p, "nope"));
    project_close(&p);
}

/* Lengths on the single examples: the plane 20 x 15 m, the cylinder's
 * 120-degree arc of radius 10 (2 pi 10 / 3) by 30 m. */
static void test_uv_lengths(void **state)
{
    (void)state;
    const char *names[] = {"plane", "cylinder"};
    const double want[2][2] = {{20, 15}, {2 * PI * 10 / 3, 30}};
    for (int e = 0; e < 2; e++) {
        char path[128];
        snprintf(path, sizeof path, "%s/%s.obj", dir, names[e]);
        FILE *out = fopen(path, "w");
        struct facet_error err;
        assert_int_equal(example_write(names[e], 60, out, &err), FACET_OK);
        fclose(out);
        const char *paths[1] = {path};
        struct project p;
        assert_int_equal(project_open(paths, 1, UNITS_M, &p, &err),
                         FACET_OK);
        assert_int_equal(p.nsurfaces, 1);
        /* The single example names its one object after itself. */
        assert_string_equal(p.surfaces[0].name, names[e]);
        assert_int_equal(project_prepare(&p, 0, PARAM_AUTO, &err),
                         FACET_OK);
        double lu = p.surfaces[0].u_length, lv = p.surfaces[0].v_length;
        if (fabs(lu - want[e][0]) > 1e-3 * want[e][0] ||
            fabs(lv - want[e][1]) > 1e-9 * want[e][1])
            fail_msg("%s: u %.9f v %.9f", names[e], lu, lv);
        project_close(&p);
    }
}

static void expect_error(const char *const *paths, size_t n,
                         const char *const *parts)
{
    struct project p;
    struct facet_error err;
    int rc = project_open(paths, n, UNITS_M, &p, &err);
    project_close(&p);
    if (rc != FACET_EINPUT)
        fail_msg("accepted (rc %d), want an error with '%s'", rc, parts[0]);
    for (int k = 0; parts[k] != NULL; k++)
        if (strstr(err.message, parts[k]) == NULL)
            fail_msg("'%s' lacks '%s'", err.message, parts[k]);
    assert_null(strchr(err.message, '\n'));
}

#define TRIANGLE "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\n"

static void test_errors_name_file_line_and_surface(void **state)
{
    (void)state;
    const char *path = write_file("novt.obj",
        "o a\n" TRIANGLE "f 1/1 2/2 3/3\n"   /* f at line 8 */
        "o b\nf 1/1 2/2 3/3\nf 1 2 3\n");     /* f at line 11 */
    char where[160];
    snprintf(where, sizeof where, "%s:11:", path);
    expect_error(&path, 1, (const char *[]){where, "object 'b'", "vt",
                                             NULL});

    path = write_file("again.obj",
        TRIANGLE "o a\nf 1/1 2/2 3/3\no b\nf 1/1 2/2 3/3\n"
        "o a\nf 1/1 2/2 3/3\n");             /* again at line 12 */
    snprintf(where, sizeof where, "%s:12:", path);
    expect_error(&path, 1, (const char *[]){where, "object 'a' again",
                                             "line 8", NULL});

    path = write_file("empty.obj",
        TRIANGLE "g first\ng second\nf 1/1 2/2 3/3\n");
    snprintf(where, sizeof where, "%s:7:", path);
    expect_error(&path, 1, (const char *[]){where, "group 'first'",
                                             "no faces", NULL});

    path = write_file("outside.obj",
        TRIANGLE "f 1/1 2/2 3/3\no a\nf 1/1 2/2 3/3\no b\nf 1/1 2/2 3/3\n");
    snprintf(where, sizeof where, "%s:7:", path);
    expect_error(&path, 1, (const char *[]){where, "outside any object",
                                             NULL});

    const char *two[2];
    two[0] = write_file("one.obj", "o x\n" TRIANGLE "f 1/1 2/2 3/3\n"
                        "o y\nf 1/1 2/2 3/3\n");
    two[1] = write_file("two.obj", "o z\n" TRIANGLE "f 1 2 3\n"
                        "o y\nf 1 2 3\n");
    char first[160], second[160];
    snprintf(first, sizeof first, "%s:10:", two[1]);
    snprintf(second, sizeof second, "also in %s (line 10)", two[0]);
    expect_error(two, 2, (const char *[]){first, "object 'y'", second,
                                          NULL});
    const char *missing = "/nonexistent/facet.obj";
    expect_error(&missing, 1, (const char *[]){missing, NULL});
}

/* Several files, a file without names, groups: who names what. */
static void test_several_files(void **state)
{
    (void)state;
    const char *paths[3];
    paths[0] = write_file("east.obj", TRIANGLE "f 1/1 2/2 3/3\n");
    paths[1] = write_file("west.obj", TRIANGLE
                          "g w1\nf 1/1 2/2 3/3\ng w2\nf 3/3 2/2 1/1\n");
    paths[2] = write_file("roof.obj", "v 0 0 0\nv 2 0 0\nv 0 2 0\n"
                          "v 2 2 0\nf 1 2 4\nf 1 4 3\n");
    struct project p;
    struct facet_error err;
    if (project_open(paths, 3, UNITS_M, &p, &err) != FACET_OK)
        fail_msg("%s", err.message);
    assert_int_equal(p.nsurfaces, 4);
    const char *names[] = {"east", "w1", "w2", "roof"};
    const enum project_key keys[] = {PROJECT_FILE, PROJECT_GROUP,
                                     PROJECT_GROUP, PROJECT_FILE};
    for (int i = 0; i < 4; i++) {
        assert_string_equal(p.surfaces[i].name, names[i]);
        assert_int_equal(p.surfaces[i].key, keys[i]);
    }
    assert_string_equal(p.surfaces[1].file, paths[1]);
    assert_int_equal(p.ntriangles, 5);
    assert_true(fabs(p.area - (0.5 * 3 + 4)) < 1e-12);
    project_close(&p);
}

/* Prepared on several threads, a project reports the first surface in
 * project order that fails, whatever the timing. */
static void test_prepare_names_the_first_failure(void **state)
{
    (void)state;
    char text[4096] = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    for (int i = 0; i < 40; i++) {
        char more[64];
        snprintf(more, sizeof more, "o s%02d\nf 1 2 3\n", i);
        strcat(text, more);
    }
    const char *path = write_file("many.obj", text);
    struct project p;
    struct facet_error err;
    assert_int_equal(project_open(&path, 1, UNITS_M, &p, &err), FACET_OK);
    assert_int_equal(p.nsurfaces, 40);
    for (int run = 0; run < 5; run++) {
        assert_int_equal(project_prepare(&p, 0, PARAM_VT, &err),
                         FACET_EINPUT);
        if (strstr(err.message, "object 's00'") == NULL)
            fail_msg("run %d: %s", run, err.message);
    }
    project_close(&p);
}

static void test_module_grid(void **state)
{
    (void)state;
    int nu, nv;
    module_grid(20, 15, 1.5, 1.2, &nu, &nv);  /* 13.33, 12.5 */
    assert_int_equal(nu, 13);
    assert_int_equal(nv, 13);
    module_grid(5, 12.5, 2, 1, &nu, &nv);     /* 2.5 and 12.5: halves up */
    assert_int_equal(nu, 3);
    assert_int_equal(nv, 13);
    module_grid(0.5, 0, 2, 1.6, &nu, &nv);    /* narrower than a module */
    assert_int_equal(nu, 1);
    assert_int_equal(nv, 1);
    module_grid(14.137, 20, 1.2, 1.6, &nu, &nv);  /* 11.78, 12.5 */
    assert_int_equal(nu, 12);
    assert_int_equal(nv, 13);
    module_grid(1e12, 1, 1, 1, &nu, &nv);
    assert_int_equal(nu, MODULE_MAX_COUNT);
}

static void test_module_range(void **state)
{
    (void)state;
    struct module_range r;
    struct facet_error err;
    assert_int_equal(module_parse("1.2:2.0x1.0:1.6", "module", &r, &err),
                     FACET_OK);
    assert_int_equal(module_widths(&r), 9);   /* 1.2 .. 2.0 by 0.1 */
    assert_int_equal(module_heights(&r), 7);  /* 1.0 .. 1.6 */
    assert_int_equal(module_count(&r), 63);
    double w, h;
    module_at(&r, 0, &w, &h);
    assert_true(w == 1.2 && h == 1.0);
    module_at(&r, 1, &w, &h);
    assert_true(w == 1.2 && h == 1.1);
    module_at(&r, 7, &w, &h);
    assert_true(w == 1.3 && h == 1.0);
    module_at(&r, 62, &w, &h);
    assert_true(w == 2.0 && h == 1.6);
    module_at(&r, 3 * 7 + 3, &w, &h);
    assert_true(w == 1.5 && h == 1.3);

    assert_int_equal(module_parse("1.2:2.0:0.25 x 1.5", "module", &r, &err),
                     FACET_OK);
    assert_int_equal(module_widths(&r), 4);   /* 1.2 1.45 1.7 1.95 */
    assert_int_equal(module_heights(&r), 1);
    module_at(&r, 3, &w, &h);
    assert_true(w == 1.95 && h == 1.5);
    assert_int_equal(module_parse("1x1:1.3:0.1", "module", &r, &err),
                     FACET_OK);
    assert_int_equal(module_count(&r), 4);    /* 1.3 on a step */
    /* a pair as a grid is written: X for x, as --grid 37X49 */
    assert_int_equal(module_parse("1.2:1.4X1.0", "module", &r, &err),
                     FACET_OK);
    assert_int_equal(module_count(&r), 3);
    /* Too large to round to the nanometre: the module itself, not
     * infinity (fuzz_project). */
    assert_int_equal(module_parse("1e300x1", "module", &r, &err), FACET_OK);
    module_at(&r, 0, &w, &h);
    assert_true(w == 1e300 && h == 1.0);

    const char *bad[] = {"1.2:2.0", "2.0:1.2x1:1.6", "0:1x1:2", "1x-1",
                         "ax1", "1x1x1", "1:2:0x1", "1:2:3:4x1", "",
                         "1:100000:0.001x1", "1.2:2.0x1.0:1.6 junk",
                         /* 10001 widths as module_widths counts them */
                         "1:10000.9999999995:1x1"};
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++) {
        if (module_parse(bad[k], "module", &r, &err) != FACET_EINPUT)
            fail_msg("'%s' accepted", bad[k]);
        assert_non_null(strstr(err.message, "module"));
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_skin_faces_are_what_they_say),
        cmocka_unit_test(test_skin_is_watertight),
        cmocka_unit_test(test_skin_is_deterministic_and_refuses_bad_res),
        cmocka_unit_test(test_skin_project),
        cmocka_unit_test(test_uv_lengths),
        cmocka_unit_test(test_errors_name_file_line_and_surface),
        cmocka_unit_test(test_several_files),
        cmocka_unit_test(test_prepare_names_the_first_failure),
        cmocka_unit_test(test_module_grid),
        cmocka_unit_test(test_module_range),
    };
    return cmocka_run_group_tests(tests, make_dir, remove_dir);
}
