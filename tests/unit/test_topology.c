/*
 * test_topology.c: the surface model on small hand-written OBJ files:
 * welding, UV seams, adjacency, boundary loops, components, units and
 * selection, each against counts worked out by hand.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "core/surface/mesh.h"

/* Parses text and builds its mesh with units and selection; fails the test
 * on any error. */
static void build(const char *text, enum mesh_units units, const char *object,
                  const char *group, struct mesh *mesh)
{
    struct obj_file obj;
    struct facet_error err;
    int rc = obj_parse(text, strlen(text), "test.obj", &obj, &err);
    if (rc != FACET_OK)
        fail_msg("parse: %s", err.message);
    struct mesh_options options = {units, object, group};
    rc = mesh_build(&obj, &options, mesh, &err);
    obj_free(&obj);
    if (rc != FACET_OK)
        fail_msg("mesh: %s", err.message);
}

static size_t loop_length(const struct mesh *m, size_t loop)
{
    return m->loop_start[loop + 1] - m->loop_start[loop];
}

static void test_single_triangle(void **state)
{
    (void)state;
    struct mesh m;
    build("v 0 0 0\nv 2 0 0\nv 0 3 0\nf 1 2 3\n", UNITS_M, NULL, NULL, &m);
    assert_int_equal(m.nvertices, 3);
    assert_int_equal(m.ntriangles, 1);
    assert_true(fabs(m.area - 3) < 1e-15);
    assert_true(m.face_normal[2] == 1);
    assert_int_equal(m.nloops, 1);
    assert_int_equal(loop_length(&m, 0), 3);
    assert_int_equal(m.ncomponents, 1);
    assert_false(m.has_uv);
    for (int k = 0; k < 3; k++)
        assert_int_equal(m.neighbour[k], MESH_NONE);
    assert_true(m.bbox_max[0] == 2 && m.bbox_max[1] == 3);
    mesh_free(&m);
}

static void test_two_quads_share_an_edge(void **state)
{
    (void)state;
    struct mesh m;
    build("v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nv 1 1 0\nv 2 1 0\n"
          "f 1 2 5 4\nf 2 3 6 5\n", UNITS_M, NULL, NULL, &m);
    assert_int_equal(m.ntriangles, 4);
    assert_int_equal(m.nloops, 1);
    assert_int_equal(loop_length(&m, 0), 6);
    assert_int_equal(m.ncomponents, 1);
    size_t inner = 0;
    for (size_t h = 0; h < 12; h++)
        inner += m.neighbour[h] != MESH_NONE;
    assert_int_equal(inner, 6);  /* three inner edges, seen from both sides */
    assert_true(fabs(m.area - 2) < 1e-15);
    for (size_t v = 0; v < 6; v++)
        assert_true(m.on_boundary[v]);
    mesh_free(&m);
}

static void test_closed_tetrahedron(void **state)
{
    (void)state;
    struct mesh m;
    build("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
          "f 1 3 2\nf 1 2 4\nf 2 3 4\nf 3 1 4\n", UNITS_M, NULL, NULL, &m);
    assert_int_equal(m.nloops, 0);
    assert_int_equal(m.ncomponents, 1);
    for (size_t h = 0; h < 12; h++)
        assert_int_not_equal(m.neighbour[h], MESH_NONE);
    for (size_t v = 0; v < 4; v++)
        assert_false(m.on_boundary[v]);
    mesh_free(&m);
}

static void test_two_squares_and_a_hole(void **state)
{
    (void)state;
    struct mesh m;
    build("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
          "v 5 0 0\nv 6 0 0\nv 6 1 0\nv 5 1 0\n"
          "f 1 2 3 4\nf 5 6 7 8\n", UNITS_M, NULL, NULL, &m);
    assert_int_equal(m.ncomponents, 2);
    assert_int_equal(m.nloops, 2);
    assert_int_not_equal(m.component[0], m.component[2]);
    mesh_free(&m);

    /* A 3 x 3 square of unit cells with the middle cell missing: an
     * annulus, two boundary loops of 12 and 4 edges. */
    char text[2048] = "";
    for (int j = 0; j <= 3; j++)
        for (int i = 0; i <= 3; i++) {
            char line[64];
            snprintf(line, sizeof line, "v %d %d 0\n", i, j);
            strcat(text, line);
        }
    for (int j = 0; j < 3; j++)
        for (int i = 0; i < 3; i++) {
            if (i == 1 && j == 1)
                continue;
            int a = j * 4 + i + 1;
            char line[64];
            snprintf(line, sizeof line, "f %d %d %d %d\n", a, a + 1, a + 5,
                     a + 4);
            strcat(text, line);
        }
    build(text, UNITS_M, NULL, NULL, &m);
    assert_int_equal(m.ncomponents, 1);
    assert_int_equal(m.nloops, 2);
    size_t a = loop_length(&m, 0), b = loop_length(&m, 1);
    assert_true((a == 12 && b == 4) || (a == 4 && b == 12));
    assert_true(fabs(m.area - 8) < 1e-15);
    mesh_free(&m);
}

/* A strip closed into a ring whose vt is split at the seam: positions are
 * shared, UV is not, and the mesh is one piece across the seam. */
static void test_uv_seam(void **state)
{
    (void)state;
    struct mesh m;
    build("v 1 0 0\nv 0 1 0\nv -1 0 0\nv 0 -1 0\n"
          "v 1 0 1\nv 0 1 1\nv -1 0 1\nv 0 -1 1\n"
          "vt 0 0\nvt 0.25 0\nvt 0.5 0\nvt 0.75 0\nvt 1 0\n"
          "vt 0 1\nvt 0.25 1\nvt 0.5 1\nvt 0.75 1\nvt 1 1\n"
          "f 1/1 2/2 6/7 5/6\nf 2/2 3/3 7/8 6/7\nf 3/3 4/4 8/9 7/8\n"
          "f 4/4 1/5 5/10 8/9\n", UNITS_M, NULL, NULL, &m);
    assert_int_equal(m.nvertices, 8);
    assert_true(m.has_uv);
    assert_int_equal(m.ncomponents, 1);
    assert_int_equal(m.nloops, 2);  /* the ring's top and bottom */
    /* The last quad's corner at vertex 1 carries u = 1, the first's u = 0. */
    int seen_zero = 0, seen_one = 0;
    for (size_t t = 0; t < m.ntriangles; t++)
        for (int k = 0; k < 3; k++)
            if (m.triangle[3 * t + k] == 0) {
                seen_zero |= m.uv[6 * t + 2 * k] == 0;
                seen_one |= m.uv[6 * t + 2 * k] == 1;
            }
    assert_true(seen_zero && seen_one);
    mesh_free(&m);
}

static void test_welding(void **state)
{
    (void)state;
    struct mesh m;
    /* Two triangles written with their own copies of the shared edge. */
    build("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
          "f 1 2 3\nf 4 5 6\n", UNITS_M, NULL, NULL, &m);
    assert_int_equal(m.nvertices, 4);
    assert_int_equal(m.ncomponents, 1);
    assert_int_equal(m.nloops, 1);
    mesh_free(&m);
    /* A triangle whose corners weld together is dropped and counted. */
    build("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 0\n"
          "f 1 2 3\nf 1 4 2\n", UNITS_M, NULL, NULL, &m);
    assert_int_equal(m.ntriangles, 1);
    assert_int_equal(m.ndegenerate, 1);
    mesh_free(&m);
}

/* Issue 32 item 18: a file in millimetres read as metres is no
 * building's size, and millimetres give it one. The sizes are the
 * triangle's own: legs a and b, diagonal hypot(a, b). */
static void test_units_mistaken(void **state)
{
    (void)state;
    struct mesh m;
    enum mesh_units better = UNITS_FT;
    /* 40 x 30 m as millimetres read in metres: a 50 km diagonal. */
    build("v 0 0 0\nv 40000 0 0\nv 0 30000 0\nf 1 2 3\n", UNITS_M, NULL,
          NULL, &m);
    assert_true(fabs(mesh_diagonal(&m) - 50000) < 1e-9);
    assert_int_equal(mesh_units_mistaken(&m, UNITS_M, &better), 1);
    assert_int_equal(better, UNITS_MM);
    mesh_free(&m);
    /* The same file read in millimetres: a building, nothing to say. */
    build("v 0 0 0\nv 40000 0 0\nv 0 30000 0\nf 1 2 3\n", UNITS_MM, NULL,
          NULL, &m);
    assert_int_equal(mesh_units_mistaken(&m, UNITS_MM, &better), 0);
    mesh_free(&m);
    /* 1,500 m across in metres (a long airport roof) is a building. */
    build("v 0 0 0\nv 1200 0 0\nv 0 900 0\nf 1 2 3\n", UNITS_M, NULL,
          NULL, &m);
    assert_int_equal(mesh_units_mistaken(&m, UNITS_M, &better), 0);
    mesh_free(&m);
    /* 5,000 km in metres: 5 km even in millimetres, the smallest unit;
     * no unit mends it, the warning alone says it. */
    build("v 0 0 0\nv 4e6 0 0\nv 0 3e6 0\nf 1 2 3\n", UNITS_M, NULL, NULL,
          &m);
    assert_int_equal(mesh_units_mistaken(&m, UNITS_M, &better), 0);
    mesh_free(&m);
    /* 5 mm across in metres: no unit is larger than the metre. */
    build("v 0 0 0\nv 0.004 0 0\nv 0 0.003 0\nf 1 2 3\n", UNITS_M, NULL,
          NULL, &m);
    assert_int_equal(mesh_units_mistaken(&m, UNITS_M, &better), 0);
    mesh_free(&m);
    /* 30 m in metres read as millimetres (30 mm): metres (30 m) and feet
     * (9.1 m) both give a building; feet land nearer the middle of a
     * building's sizes, sqrt(0.05 * 2000) = 10 m. */
    build("v 0 0 0\nv 24 0 0\nv 0 18 0\nf 1 2 3\n", UNITS_MM, NULL, NULL,
          &m);
    assert_int_equal(mesh_units_mistaken(&m, UNITS_MM, &better), 1);
    assert_int_equal(better, UNITS_FT);
    mesh_free(&m);
}

static void test_units_and_warning(void **state)
{
    (void)state;
    struct mesh m;
    char warning[256];
    build("v 0 0 0\nv 20000 0 0\nv 0 30000 0\nf 1 2 3\n", UNITS_MM, NULL,
          NULL, &m);
    assert_true(fabs(m.area - 300) < 1e-9);
    assert_int_equal(mesh_units_warning(&m, UNITS_MM, warning,
                                        sizeof warning), 0);
    mesh_free(&m);
    build("v 0 0 0\nv 20000 0 0\nv 0 30000 0\nf 1 2 3\n", UNITS_M, NULL,
          NULL, &m);
    assert_int_equal(mesh_units_warning(&m, UNITS_M, warning,
                                        sizeof warning), 1);
    assert_non_null(strstr(warning, "set its units to mm"));
    mesh_free(&m);
    build("v 0 0 0\nv 0.02 0 0\nv 0 0.03 0\nf 1 2 3\n", UNITS_M, NULL, NULL,
          &m);
    assert_int_equal(mesh_units_warning(&m, UNITS_M, warning,
                                        sizeof warning), 1);
    mesh_free(&m);
    assert_true(mesh_units_scale(UNITS_IN) == 0.0254);
    assert_true(mesh_units_scale(UNITS_FT) == 0.3048);
    enum mesh_units units;
    struct facet_error err;
    assert_int_equal(mesh_units_parse("ft", "units", &units, &err), FACET_OK);
    assert_int_equal(units, UNITS_FT);
    assert_int_equal(mesh_units_parse("yd", "units", &units, &err), FACET_EINPUT);
}

static void test_selection(void **state)
{
    (void)state;
    const char *text = "o left\ng low\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"
                       "o right\ng high\nv 5 0 0\nv 6 0 0\nv 5 1 0\n"
                       "f 4 5 6\n";
    struct mesh m;
    build(text, UNITS_M, NULL, NULL, &m);
    assert_int_equal(m.ncomponents, 2);
    mesh_free(&m);
    build(text, UNITS_M, "right", NULL, &m);
    assert_int_equal(m.ntriangles, 1);
    assert_int_equal(m.nvertices, 3);
    assert_true(m.bbox_min[0] == 5);
    mesh_free(&m);
    build(text, UNITS_M, NULL, "low", &m);
    assert_true(m.bbox_max[0] == 1);
    mesh_free(&m);

    struct obj_file obj;
    struct facet_error err;
    assert_int_equal(obj_parse(text, strlen(text), "t.obj", &obj, &err), 0);
    struct mesh_options options = {UNITS_M, "middle", NULL};
    assert_int_equal(mesh_build(&obj, &options, &m, &err), FACET_EINPUT);
    assert_non_null(strstr(err.message, "middle"));
    assert_non_null(strstr(err.message, "left, right"));
    mesh_free(&m);
    obj_free(&obj);
}

static void test_bowtie_and_nonmanifold(void **state)
{
    (void)state;
    struct mesh m;
    /* Two triangles touching at one vertex: two loops that share it, and
     * the walk must end. */
    build("v 0 0 0\nv 1 0 0\nv 0 1 0\nv -1 0 0\nv 0 -1 0\n"
          "f 1 2 3\nf 1 4 5\n", UNITS_M, NULL, NULL, &m);
    assert_int_equal(m.ncomponents, 2);
    assert_int_equal(m.loop_start[m.nloops], 6);
    mesh_free(&m);
    /* Three triangles on one edge. */
    build("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\n"
          "f 1 2 3\nf 2 1 4\nf 1 2 5\n", UNITS_M, NULL, NULL, &m);
    assert_int_equal(m.nonmanifold_edges, 1);
    assert_int_equal(m.neighbour[0], MESH_NONE);
    mesh_free(&m);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_single_triangle),
        cmocka_unit_test(test_two_quads_share_an_edge),
        cmocka_unit_test(test_closed_tetrahedron),
        cmocka_unit_test(test_two_squares_and_a_hole),
        cmocka_unit_test(test_uv_seam),
        cmocka_unit_test(test_welding),
        cmocka_unit_test(test_units_and_warning),
        cmocka_unit_test(test_units_mistaken),
        cmocka_unit_test(test_selection),
        cmocka_unit_test(test_bowtie_and_nonmanifold),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
