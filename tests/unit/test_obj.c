/*
 * test_obj.c: the OBJ loader reads every statement and index form it
 * promises, and refuses every kind of bad input with "FILE:LINE: what".
 * Text goes through obj_parse; files (temporary, in /tmp) through obj_load.
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
#include <sys/stat.h>
#include <unistd.h>

#include "core/obj/obj.h"
#include "core/obj/obj_table.h"
#include "core/obj/obj_tuning_internal.h"

static void parse_ok(const char *text, struct obj_file *obj)
{
    struct facet_error err;
    int rc = obj_parse(text, strlen(text), "t.obj", obj, &err);
    if (rc != FACET_OK)
        fail_msg("obj_parse failed: %s", err.message);
}

/* Parses text, expecting FACET_EINPUT with a message that starts with
 * where ("t.obj:LINE:") and contains what. */
static void parse_fails(const char *text, const char *where, const char *what)
{
    struct obj_file obj;
    struct facet_error err;
    int rc = obj_parse(text, strlen(text), "t.obj", &obj, &err);
    obj_free(&obj);
    if (rc != FACET_EINPUT || err.code != FACET_EINPUT ||
        strncmp(err.message, where, strlen(where)) != 0 ||
        strstr(err.message, what) == NULL)
        fail_msg("for %s: got %d \"%s\", wanted \"%s ... %s\"", text, rc,
                 err.message, where, what);
}

static void assert_corner(const struct obj_corner *c, uint32_t v, uint32_t vt,
                          uint32_t vn)
{
    assert_int_equal(c->v, v);
    assert_int_equal(c->vt, vt);
    assert_int_equal(c->vn, vn);
}

/* Writes length bytes to a new temporary file and returns its path (owned
 * by the caller; unlink and free it). */
static char *temp_file(const char *bytes, size_t length)
{
    char *path = strdup("/tmp/facet_test_obj_XXXXXX");
    int fd = mkstemp(path);
    assert_true(fd >= 0);
    size_t done = 0;
    while (done < length) {
        ssize_t n = write(fd, bytes + done, length - done);
        assert_true(n > 0);
        done += (size_t)n;
    }
    close(fd);
    return path;
}

/* ---- features --------------------------------------------------------- */

static void test_vertices_with_w_and_colors(void **state)
{
    (void)state;
    struct obj_file obj;
    parse_ok("v 1 2 3\n"
             "v 4 5 6 0.5\n"
             "v 7 8 9 0.1 0.2 0.3\n"
             "v 1.5 -2.5 3e2 1 0.4 0.5 0.6\n", &obj);
    assert_int_equal(obj.nvertices, 4);
    double want[] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 1.5, -2.5, 300};
    for (int i = 0; i < 12; i++)
        assert_true(obj.position[i] == want[i]);
    assert_int_equal(obj.ncolors, 2);
    assert_non_null(obj.color);
    double color[] = {1, 1, 1, 1, 1, 1, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6};
    for (int i = 0; i < 12; i++)
        assert_true(obj.color[i] == color[i]);
    obj_free(&obj);
    parse_ok("v 1 2 3\n", &obj);
    assert_null(obj.color);
    assert_int_equal(obj.ncolors, 0);
    obj_free(&obj);
}

static void test_texcoords_and_normals(void **state)
{
    (void)state;
    struct obj_file obj;
    parse_ok("vt 0.25 0.75\nvt 0.5 0.5 0.9\nvt 0.125\n"
             "vn 0 0 2\nvn -1 0 0\n", &obj);
    assert_int_equal(obj.ntexcoords, 3);
    double uv[] = {0.25, 0.75, 0.5, 0.5, 0.125, 0};
    for (int i = 0; i < 6; i++)
        assert_true(obj.texcoord[i] == uv[i]);
    assert_int_equal(obj.nnormals, 2);
    assert_true(obj.normal[2] == 2.0 && obj.normal[3] == -1.0);
    obj_free(&obj);
}

static void test_face_index_forms(void **state)
{
    (void)state;
    struct obj_file obj;
    parse_ok("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\n"
             "vn 0 0 1\n"
             "f 1 2 3\n"
             "f 1/1 2/2 3/3\n"
             "f 1//1 2//1 3//1\n"
             "f 1/1/1 2/2/1 3/3/1\n"
             "f 1/1 2 3//1\n", &obj);
    assert_int_equal(obj.nfaces, 5);
    assert_int_equal(obj.ntriangles, 5);
    assert_corner(&obj.corner[0], 0, OBJ_NONE, OBJ_NONE);
    assert_corner(&obj.corner[4], 1, 1, OBJ_NONE);
    assert_corner(&obj.corner[8], 2, OBJ_NONE, 0);
    assert_corner(&obj.corner[11], 2, 2, 0);
    assert_corner(&obj.corner[12], 0, 0, OBJ_NONE);  /* mixed corners */
    assert_corner(&obj.corner[13], 1, OBJ_NONE, OBJ_NONE);
    assert_corner(&obj.corner[14], 2, OBJ_NONE, 0);
    for (uint32_t t = 0; t < 5; t++)
        assert_int_equal(obj.triangle_face[t], t);
    obj_free(&obj);
}

static void test_negative_indices(void **state)
{
    (void)state;
    struct obj_file obj;
    parse_ok("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 1\n"
             "f -3/-2 -2/-1 -1/-1\n"
             "v 5 5 5\n"
             "f -1 -2 -3\n", &obj);
    assert_int_equal(obj.ntriangles, 2);
    assert_corner(&obj.corner[0], 0, 0, OBJ_NONE);
    assert_corner(&obj.corner[1], 1, 1, OBJ_NONE);
    assert_corner(&obj.corner[2], 2, 1, OBJ_NONE);
    assert_corner(&obj.corner[3], 3, OBJ_NONE, OBJ_NONE);
    assert_corner(&obj.corner[5], 1, OBJ_NONE, OBJ_NONE);
    obj_free(&obj);
}

static void test_forward_references(void **state)
{
    (void)state;
    struct obj_file obj;
    parse_ok("f 1 2 3 4\n"
             "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
             "f 1 2 3\n", &obj);
    assert_int_equal(obj.ntriangles, 3);
    assert_int_equal(obj.triangle_face[0], 0);
    assert_int_equal(obj.triangle_face[1], 0);
    assert_int_equal(obj.triangle_face[2], 1);
    for (int k = 0; k < 6; k++)
        assert_true(obj.corner[k].v < 4);
    obj_free(&obj);
}

static void test_polygons_triangulated(void **state)
{
    (void)state;
    struct obj_file obj;
    /* A quad, a concave L hexagon (reflex corner at vertex 8) and an
     * octagon. */
    parse_ok("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
             "v 0 0 1\nv 3 0 1\nv 3 1 1\nv 1 1 1\nv 1 3 1\nv 0 3 1\n"
             "f 1 2 3 4\n"
             "f 5 6 7 8 9 10\n"
             "f 1 2 3 4 1 2 3 4\n", &obj);
    assert_int_equal(obj.nfaces, 3);
    assert_int_equal(obj.ntriangles, 2 + 4 + 6);
    /* The L's triangles must add up to its area, 5. */
    double area = 0;
    for (size_t t = 2; t < 6; t++) {
        const double *a = obj.position + 3 * obj.corner[3 * t].v;
        const double *b = obj.position + 3 * obj.corner[3 * t + 1].v;
        const double *c = obj.position + 3 * obj.corner[3 * t + 2].v;
        area += ((b[0] - a[0]) * (c[1] - a[1]) -
                 (b[1] - a[1]) * (c[0] - a[0])) / 2;
        assert_int_equal(obj.triangle_face[t], 1);
    }
    assert_true(fabs(area - 5) < 1e-12);
    obj_free(&obj);
}

static void test_big_face(void **state)
{
    (void)state;
    size_t n = 5000;
    size_t size = n * 64 + 64;
    char *text = malloc(size);
    size_t k = 0;
    for (size_t i = 0; i < n; i++) {
        double a = 2 * M_PI * (double)i / (double)n;
        k += (size_t)snprintf(text + k, size - k, "v %.9f %.9f 0\n", cos(a),
                              sin(a));
    }
    k += (size_t)snprintf(text + k, size - k, "f");
    for (size_t i = 0; i < n; i++)
        k += (size_t)snprintf(text + k, size - k, " %zu", i + 1);
    snprintf(text + k, size - k, "\n");
    struct obj_file obj;
    parse_ok(text, &obj);
    assert_int_equal(obj.ntriangles, n - 2);
    obj_free(&obj);
    free(text);
}

static void test_names(void **state)
{
    (void)state;
    struct obj_file obj;
    parse_ok("mtllib roof.mtl extra.mtl\n"
             "v 0 0 0\nv 1 0 0\nv 0 1 0\n"
             "f 1 2 3\n"
             "o roof\n"
             "g north side \t\n"
             "usemtl glass\n"
             "f 1 2 3\n"
             "o wall\n"
             "f 1 2 3\n"
             "g\n"
             "o roof\n"
             "usemtl\n"
             "f 1 2 3\n", &obj);
    assert_int_equal(obj.nobjects, 3);
    assert_string_equal(obj.objects[0].text, "");
    assert_string_equal(obj.objects[1].text, "roof");
    assert_string_equal(obj.objects[2].text, "wall");
    assert_int_equal(obj.ngroups, 2);
    assert_string_equal(obj.groups[1].text, "north side");
    assert_int_equal(obj.nmaterials, 2);
    assert_string_equal(obj.materials[1].text, "glass");
    assert_int_equal(obj.nmtllibs, 1);
    assert_string_equal(obj.mtllibs[0].text, "roof.mtl extra.mtl");
    uint32_t object[] = {0, 1, 2, 1}, group[] = {0, 1, 1, 0},
             material[] = {0, 1, 1, 0};
    for (int t = 0; t < 4; t++) {
        assert_int_equal(obj.triangle_object[t], object[t]);
        assert_int_equal(obj.triangle_group[t], group[t]);
        assert_int_equal(obj.triangle_material[t], material[t]);
    }
    obj_free(&obj);
}

static void test_many_groups(void **state)
{
    (void)state;
    size_t n = 20000, size = n * 40 + 64, k = 0;
    char *text = malloc(size);
    k += (size_t)snprintf(text + k, size - k, "v 0 0 0\nv 1 0 0\nv 0 1 0\n");
    for (size_t i = 0; i < n; i++)
        k += (size_t)snprintf(text + k, size - k, "g part%zu\nf 1 2 3\n",
                              i % 5000);
    struct obj_file obj;
    parse_ok(text, &obj);
    assert_int_equal(obj.ngroups, 5001);
    assert_int_equal(obj.triangle_group[n - 1], 5000);
    assert_string_equal(obj.groups[5000].text, "part4999");
    obj_free(&obj);
    free(text);
}

static void test_skipped_comments_blank(void **state)
{
    (void)state;
    struct obj_file obj;
    parse_ok("# a comment\n\n   \n\t\n"
             "s 1\ns off\nl 1 2\np 1\ncstype bspline\nvp 0.5\n"
             "v 0 0 0 # trailing comment\nv 1 0 0\nv 0 1 0\n"
             "f 1 2 3 # and here\n", &obj);
    assert_int_equal(obj.nskipped, 6);
    assert_int_equal(obj.nvertices, 3);
    assert_int_equal(obj.ntriangles, 1);
    assert_int_equal(obj.nlines, 14);
    obj_free(&obj);
}

static void test_crlf_tabs_continuation_no_final_newline(void **state)
{
    (void)state;
    struct obj_file obj;
    parse_ok("v\t0 0 0\r\n"
             "v 1 \\\r\n 0 0\r\n"
             "v 0 1 \\\n0\n"
             "g long \\\nname\n"
             "f 1 2 \\\n 3", &obj);
    assert_int_equal(obj.nvertices, 3);
    assert_true(obj.position[3] == 1 && obj.position[8] == 0);
    assert_int_equal(obj.ntriangles, 1);
    assert_corner(&obj.corner[2], 2, OBJ_NONE, OBJ_NONE);
    assert_string_equal(obj.groups[1].text, "long name");
    assert_int_equal(obj.nlines, 9);
    obj_free(&obj);
}

static void test_not_nul_terminated(void **state)
{
    (void)state;
    const char text[] = "v 1 2 3\nv 4 5 6\nv 7 8 999";
    struct obj_file obj;
    struct facet_error err;
    /* Stop before the last "99": the last number must read as 9. */
    assert_int_equal(obj_parse(text, sizeof text - 3, "t.obj", &obj, &err),
                     FACET_OK);
    assert_true(obj.position[8] == 9.0);
    obj_free(&obj);
}

/* ---- errors ----------------------------------------------------------- */

static void test_index_errors(void **state)
{
    (void)state;
    parse_fails("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n", "t.obj:4:",
                "face index 0 is invalid (OBJ indices start at 1)");
    parse_fails("v 0 0 0\nv 1 0 0\nv 0 1 0\n\nf -4 -2 -1\n", "t.obj:5:",
                "relative vertex index -4 points before the first vertex "
                "(file has 3 vertices so far)");
    parse_fails("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 900\nv 1 1 1\n",
                "t.obj:4:",
                "vertex index 900 out of range (file has 4 vertices)");
    parse_fails("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/2 3/1\n",
                "t.obj:5:", "texture coordinate index 2 out of range");
    parse_fails("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1//1 2//1 3//1\n", "t.obj:4:",
                "normal index 1 out of range (file has 0 normals)");
    parse_fails("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/-1 2 3\n", "t.obj:4:",
                "relative texture coordinate index -1");
    parse_fails("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99999999999999999999\n",
                "t.obj:4:", "too large");
}

static void test_face_errors(void **state)
{
    (void)state;
    const char *v = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    char text[256];
    snprintf(text, sizeof text, "%sf 1 2\n", v);
    parse_fails(text, "t.obj:4:", "face has 2 vertices");
    snprintf(text, sizeof text, "%sf\n", v);
    parse_fails(text, "t.obj:4:", "face has 0 vertices");
    snprintf(text, sizeof text, "%sf 1/\n", v);
    parse_fails(text, "t.obj:4:", "face corner \"1/\" does not parse");
    snprintf(text, sizeof text, "%sf 1 2 3/1/\n", v);
    parse_fails(text, "t.obj:4:", "face corner \"3/1/\" does not parse");
    snprintf(text, sizeof text, "%sf 1 2 x\n", v);
    parse_fails(text, "t.obj:4:", "face corner \"x\" does not parse");
    snprintf(text, sizeof text, "%sf 1 2 3.0\n", v);
    parse_fails(text, "t.obj:4:", "face corner \"3.0\" does not parse");
    snprintf(text, sizeof text, "%sf 1 2 3//\n", v);
    parse_fails(text, "t.obj:4:", "does not parse");
}

static void test_number_errors(void **state)
{
    (void)state;
    parse_fails("v 1 2\n", "t.obj:1:", "vertex has 2 coordinates");
    parse_fails("v\n", "t.obj:1:", "vertex has 0 coordinates");
    parse_fails("# x\nv 1 2 3 4 5\n", "t.obj:2:", "vertex has 5 numbers");
    parse_fails("v 1 2 3 4 5 6 7 8\n", "t.obj:1:", "more than 7 numbers");
    parse_fails("v 1 2 abc\n", "t.obj:1:", "number does not parse: \"abc\"");
    parse_fails("v 1 2 3.4.5\n", "t.obj:1:", "number does not parse");
    parse_fails("v 1 2 3e\n", "t.obj:1:", "number does not parse: \"3e\"");
    parse_fails("v 1 nan 3\n", "t.obj:1:", "NaN or infinite coordinate");
    parse_fails("v 1 2 -inf\n", "t.obj:1:", "NaN or infinite coordinate");
    parse_fails("v 1 2 1e999\n", "t.obj:1:", "NaN or infinite coordinate");
    parse_fails("vt\n", "t.obj:1:", "texture coordinate has no numbers");
    parse_fails("vn 1 2\n", "t.obj:1:", "normal has 2 numbers");
    parse_fails("vn 1 2 3 4\n", "t.obj:1:", "more than 3 numbers");
    parse_fails("vt 1 2 3 4\n", "t.obj:1:", "more than 3 numbers");
    parse_fails("vn 0 0 1\r\nvn 1 x 2\r\n", "t.obj:2:", "does not parse");
}

static void test_line_numbers_count_physical_lines(void **state)
{
    (void)state;
    parse_fails("v 1 \\\n2 \\\n3\n\n\nv 1 2\n", "t.obj:6:",
                "vertex has 2 coordinates");
    parse_fails("v 1 2 3\r\nv 1 2 3\r\n\r\nv x 1 2", "t.obj:4:",
                "does not parse");
}

static void test_empty_and_binary(void **state)
{
    (void)state;
    parse_fails("", "t.obj:", "empty file");
    parse_fails("# only a comment\n\n", "t.obj:", "empty file");
    char binary[600];
    for (size_t i = 0; i < sizeof binary; i++)
        binary[i] = (char)(i * 37 % 251);
    struct obj_file obj;
    struct facet_error err;
    assert_int_equal(obj_parse(binary, sizeof binary, "b.obj", &obj, &err),
                     FACET_EINPUT);
    assert_string_equal(err.message, "b.obj: binary file, not OBJ text");
    obj_free(&obj);
    const char nul[] = "v 1 2 3\n\0v 1 2 3\n";
    assert_int_equal(obj_parse(nul, sizeof nul - 1, "n.obj", &obj, &err),
                     FACET_EINPUT);
    assert_non_null(strstr(err.message, "binary file"));
    obj_free(&obj);
    /* UTF-8 names and comments are text. */
    parse_ok("# 屋根の曲面 — Dachfläche\ng 屋根\nv 1 2 3\n", &obj);
    assert_string_equal(obj.groups[1].text, "屋根");
    obj_free(&obj);
}

static void test_error_without_err(void **state)
{
    (void)state;
    struct obj_file obj;
    assert_int_equal(obj_parse("f 1/", 4, "t.obj", &obj, NULL), FACET_EINPUT);
    obj_free(&obj);
}

/* ---- files ------------------------------------------------------------ */

static void test_load_file(void **state)
{
    (void)state;
    const char *text = "o grid\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                       "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nf 1/1 2/2 3/3 4/4\n";
    char *path = temp_file(text, strlen(text));
    struct obj_file obj;
    struct facet_error err;
    assert_int_equal(obj_load(path, &obj, &err), FACET_OK);
    assert_int_equal(obj.nvertices, 4);
    assert_int_equal(obj.ntriangles, 2);
    assert_int_equal(obj.nlines, 10);
    assert_string_equal(obj.objects[1].text, "grid");
    obj_free(&obj);
    unlink(path);
    free(path);
}

/* Lines far longer than the read buffer, and many lines across its
 * chunk boundaries, read the same as from memory. */
static void test_load_long_lines_and_chunks(void **state)
{
    (void)state;
    size_t nv = 300000, size = nv * 40 + ((size_t)8 << 20), k = 0;
    char *text = malloc(size);
    for (size_t i = 0; i < nv; i++)
        k += (size_t)snprintf(text + k, size - k, "v %zu.25 %zu 0.125\n",
                              i, i % 7);
    k += (size_t)snprintf(text + k, size - k, "g ");
    for (size_t i = 0; i < (6u << 20); i++)  /* a 6 MB group name */
        text[k++] = (char)('a' + i % 26);
    text[k++] = '\n';
    k += (size_t)snprintf(text + k, size - k, "f");
    for (size_t i = 0; i < nv; i++)  /* a ~2 MB face */
        k += (size_t)snprintf(text + k, size - k, " %zu", i + 1);
    text[k++] = '\n';
    char *path = temp_file(text, k);
    struct obj_file from_file, from_memory;
    struct facet_error err;
    assert_int_equal(obj_load(path, &from_file, &err), FACET_OK);
    assert_int_equal(obj_parse(text, k, "m", &from_memory, &err), FACET_OK);
    assert_int_equal(from_file.nvertices, nv);
    assert_int_equal(from_file.ntriangles, nv - 2);
    assert_memory_equal(from_file.position, from_memory.position,
                        nv * 3 * sizeof(double));
    assert_memory_equal(from_file.corner, from_memory.corner,
                        (nv - 2) * 3 * sizeof(struct obj_corner));
    assert_int_equal(strlen(from_file.groups[1].text), 6u << 20);
    assert_true(from_file.position[3 * (nv - 1)] == (double)(nv - 1) + 0.25);
    obj_free(&from_file);
    obj_free(&from_memory);
    unlink(path);
    free(path);
    free(text);
}

static void test_load_errors(void **state)
{
    (void)state;
    struct obj_file obj;
    struct facet_error err;
    assert_int_equal(obj_load("/tmp/facet-no-such-file.obj", &obj, &err),
                     FACET_EINPUT);
    assert_non_null(strstr(err.message, "/tmp/facet-no-such-file.obj: "));
    assert_non_null(strstr(err.message, "No such file"));
    obj_free(&obj);

    assert_int_equal(obj_load("/tmp", &obj, &err), FACET_EINPUT);
    assert_string_equal(err.message, "/tmp: is a directory, not an OBJ file");
    obj_free(&obj);

    char *path = temp_file("", 0);
    assert_int_equal(obj_load(path, &obj, &err), FACET_EINPUT);
    assert_non_null(strstr(err.message, "empty file"));
    assert_non_null(strstr(err.message, path));
    obj_free(&obj);
    unlink(path);
    free(path);

    const char bad[] = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 0\n";
    path = temp_file(bad, sizeof bad - 1);
    assert_int_equal(obj_load(path, &obj, &err), FACET_EINPUT);
    char want[128];
    snprintf(want, sizeof want, "%s:4: face index 0 is invalid", path);
    assert_non_null(strstr(err.message, want));
    obj_free(&obj);
    unlink(path);
    free(path);

    unsigned char elf[4096];
    for (size_t i = 0; i < sizeof elf; i++)
        elf[i] = (unsigned char)(i % 5 == 0 ? 0 : i);
    path = temp_file((const char *)elf, sizeof elf);
    assert_int_equal(obj_load(path, &obj, &err), FACET_EINPUT);
    assert_non_null(strstr(err.message, "binary file, not OBJ text"));
    obj_free(&obj);
    unlink(path);
    free(path);
}

/* ---- parallel parts and streaming windows ---------------------------- */

static void same_names(const struct obj_name *a, size_t na,
                       const struct obj_name *b, size_t nb)
{
    assert_int_equal(na, nb);
    for (size_t i = 0; i < na; i++)
        assert_string_equal(a[i].text, b[i].text);
}

static void same_doubles(const double *a, const double *b, size_t n)
{
    if (n == 0)
        return;
    assert_non_null(a);
    assert_non_null(b);
    assert_memory_equal(a, b, n * sizeof *a);
}

/* Every field of a equals that of b. */
static void same_obj(const struct obj_file *a, const struct obj_file *b)
{
    assert_int_equal(a->nvertices, b->nvertices);
    same_doubles(a->position, b->position, 3 * a->nvertices);
    assert_int_equal(a->ncolors, b->ncolors);
    assert_true((a->color == NULL) == (b->color == NULL));
    if (a->color != NULL)
        same_doubles(a->color, b->color, 3 * a->nvertices);
    assert_int_equal(a->ntexcoords, b->ntexcoords);
    same_doubles(a->texcoord, b->texcoord, 2 * a->ntexcoords);
    assert_int_equal(a->nnormals, b->nnormals);
    same_doubles(a->normal, b->normal, 3 * a->nnormals);
    assert_int_equal(a->nfaces, b->nfaces);
    assert_int_equal(a->ntriangles, b->ntriangles);
    size_t n = a->ntriangles;
    if (n > 0) {
        assert_memory_equal(a->corner, b->corner, 3 * n * sizeof *a->corner);
        assert_memory_equal(a->triangle_face, b->triangle_face, n * 4);
        assert_memory_equal(a->triangle_object, b->triangle_object, n * 4);
        assert_memory_equal(a->triangle_group, b->triangle_group, n * 4);
        assert_memory_equal(a->triangle_material, b->triangle_material,
                            n * 4);
    }
    same_names(a->objects, a->nobjects, b->objects, b->nobjects);
    same_names(a->groups, a->ngroups, b->groups, b->ngroups);
    same_names(a->materials, a->nmaterials, b->materials, b->nmaterials);
    same_names(a->mtllibs, a->nmtllibs, b->mtllibs, b->nmtllibs);
    assert_int_equal(a->nlines, b->nlines);
    assert_int_equal(a->nskipped, b->nskipped);
}

/* Parses text whole on one thread, then cut into parts of every small size
 * on 1 to 3 threads, from memory and (streamed in small windows) from a
 * file: every way must give the same obj_file, or the same error. */
static void split_agrees(const char *text)
{
    size_t length = strlen(text);
    struct obj_tuning serial = {.nthreads = 1, .part_bytes = SIZE_MAX};
    struct obj_file want, got;
    struct facet_error want_err, got_err;
    int want_rc = obj_parse_tuned(text, length, "t.obj", &want, &want_err,
                                  &serial);
    char *path = temp_file(text, length);
    static const size_t sizes[] = {1, 2, 3, 5, 8, 13, 21, 64};
    for (unsigned threads = 1; threads <= 3; threads++) {
        for (size_t i = 0; i < sizeof sizes / sizeof sizes[0]; i++) {
            struct obj_tuning split = {.nthreads = threads,
                                       .part_bytes = sizes[i],
                                       .max_parts = SIZE_MAX,
                                       .window_bytes = 4 * sizes[i],
                                       .whole_bytes = 1};
            for (int from_file = 0; from_file < 2; from_file++) {
                int rc = from_file
                    ? obj_load_tuned(path, &got, &got_err, &split)
                    : obj_parse_tuned(text, length, "t.obj", &got, &got_err,
                                      &split);
                if (rc != want_rc)
                    fail_msg("threads %u parts of %zu%s: rc %d (%s), "
                             "wanted %d (%s)", threads, sizes[i],
                             from_file ? " (file)" : "", rc,
                             got_err.message, want_rc, want_err.message);
                if (rc == FACET_OK) {
                    same_obj(&want, &got);
                } else if (!from_file &&
                           strcmp(got_err.message, want_err.message) != 0) {
                    fail_msg("threads %u parts of %zu: \"%s\", wanted "
                             "\"%s\"", threads, sizes[i], got_err.message,
                             want_err.message);
                } else if (from_file) {
                    /* Same message, but naming the file's path. */
                    const char *a = strchr(got_err.message, ':');
                    const char *b = strchr(want_err.message, ':');
                    assert_non_null(a);
                    assert_non_null(b);
                    assert_string_equal(a, b);
                }
                obj_free(&got);
            }
        }
    }
    obj_free(&want);
    unlink(path);
    free(path);
}

static void test_split_matches_serial(void **state)
{
    (void)state;
    /* Names first seen late, inherited names, colours in some parts only,
     * vt/vn, n-gons, forward references, comments, skipped statements. */
    split_agrees("mtllib a.mtl\n"
                 "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                 "vt 0 0\nvt 1 0\nvt 1 1\n"
                 "f 1/1 2/2 3/3 4/1\n"
                 "o first\ng left\nusemtl red\n"
                 "f 1 2 3\n"
                 "s 1\n# a comment\n\n"
                 "v 2 0 0 0.5 0.25 0.125\n"
                 "vn 0 0 1\nvn 0 1 0\n"
                 "f 1//1 2//2 5//1\n"
                 "g right\nmtllib b.mtl\n"
                 "f 1 2 3 4 5\n"
                 "f 1 2 6\n"
                 "usemtl red\no second\n"
                 "v 0 2 0\n"
                 "f 6 5 2 3\n"
                 "g left\n"
                 "f 1 3 6\n");
}

static void test_split_negative_indices_across_parts(void **state)
{
    (void)state;
    split_agrees("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                 "vt 0 0\nvt 1 1\nvn 0 0 1\n"
                 "f -4/-2/-1 -3/-1/-1 -2/-2/-1 -1/-1/-1\n"
                 "v 2 2 0\n"
                 "f -1 -2 -3\n"
                 "f -5 2 -1\n"
                 "f 1//-1 -4//1 5//-1\n");
    /* Reaching before the first vertex from a later part. */
    split_agrees("v 0 0 0\nv 1 0 0\nv 1 1 0\n"
                 "f 1 2 3\n"
                 "f -1 -2 -4\n");
    split_agrees("v 0 0 0\nv 1 0 0\nv 1 1 0\nvt 0 0\n"
                 "f 1/-2 2/1 3/1\n");
}

static void test_split_continuations(void **state)
{
    (void)state;
    /* Joined lines across every possible cut, with CRLF and a final
     * continuation and no final newline. */
    split_agrees("v 0 0 \\\n0\nv 1 \\\r\n 0 \\\n 0\r\n"
                 "v 1 1 0\\\n\nf 1 \\\n2 \\\n\\\n3\n"
                 "g a long \\\n name\n"
                 "f 3 2 1 \\");
    split_agrees("\\\n\\\nv 0 0 0\n\\\nv 0 1 0\nv 1 1 1\n\\\n"
                 "f 1 2 3");
}

static void test_split_errors_name_the_line(void **state)
{
    (void)state;
    /* An error in a later part names its own line; the earliest error in
     * file order wins, whichever part finds it. */
    split_agrees("v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 3\n"
                 "\\\n\\\nf 1 2\n"
                 "v bad 0 0\n");
    split_agrees("v 0 0 0\nv 1 0 0\nv 1 1 0\n"
                 "f 1 2 3\nf 1 2 -9\n"
                 "v bad 0 0\n");
    split_agrees("v 0 0 0\nv 1 0 0\nv 1 1 0\n"
                 "f 1 2 9\nf 1 2 3\n"
                 "f 1 2 8\n");
    split_agrees("v 0 0 0\nv 1 0 0\nv 1 1 0\n"
                 "f 1 2 9\nf 1 2 x\n");
    split_agrees("v 0 0 0\nv 1 0 0\nv 1 1 0\nf 0 -1 2\n");
    split_agrees("v 0 0 0\nv 1 0 0\nv 1 1 0\nf -7 0 2\n");
    split_agrees("# nothing\n\n# but comments\n");

    struct obj_tuning split = {.nthreads = 2, .part_bytes = 1,
                               .max_parts = SIZE_MAX};
    const char *text = "v 0 0 0\nv 1 0 0\nv 1 1 0\n"
                       "f 1 2 3\n\nf -1 -2 -5\n";
    struct obj_file obj;
    struct facet_error err;
    assert_int_equal(obj_parse_tuned(text, strlen(text), "t.obj", &obj, &err,
                                     &split), FACET_EINPUT);
    assert_string_equal(err.message, "t.obj:6: relative vertex index -5 "
                        "points before the first vertex (file has 3 "
                        "vertices so far)");
    obj_free(&obj);
}

/* Names first used in a later part keep the order of first use, and a
 * part that starts with no o/g/usemtl of its own inherits them. */
static void test_split_names_in_later_parts(void **state)
{
    (void)state;
    struct obj_tuning split = {.nthreads = 3, .part_bytes = 1,
                               .max_parts = SIZE_MAX};
    const char *text = "v 0 0 0\nv 1 0 0\nv 1 1 0\n"
                       "f 1 2 3\n"
                       "g b\nf 1 2 3\n"
                       "o x\nusemtl m\nf 1 2 3\n"
                       "g a\nf 1 2 3\n"
                       "g b\nf 1 2 3\n";
    struct obj_file obj;
    struct facet_error err;
    assert_int_equal(obj_parse_tuned(text, strlen(text), "t.obj", &obj, &err,
                                     &split), FACET_OK);
    assert_int_equal(obj.ngroups, 3);
    assert_string_equal(obj.groups[1].text, "b");
    assert_string_equal(obj.groups[2].text, "a");
    uint32_t groups[] = {0, 1, 1, 2, 1};
    uint32_t objects[] = {0, 0, 1, 1, 1};
    uint32_t materials[] = {0, 0, 1, 1, 1};
    for (int t = 0; t < 5; t++) {
        assert_int_equal(obj.triangle_group[t], groups[t]);
        assert_int_equal(obj.triangle_object[t], objects[t]);
        assert_int_equal(obj.triangle_material[t], materials[t]);
    }
    obj_free(&obj);
}

/* A larger generated mesh (quads, triangles, n-gons, negative indices,
 * groups) parsed with the default cut on 2 threads and with many parts
 * agrees with the serial parse, from memory and streamed from a file. */
static void test_split_large_mesh(void **state)
{
    (void)state;
    size_t n = 120, size = 64u << 20, k = 0;
    char *text = malloc(size);
    for (size_t j = 0; j <= n; j++)
        for (size_t i = 0; i <= n; i++)
            k += (size_t)snprintf(text + k, size - k, "v %zu %zu %.6f\n", i,
                                  j, 0.001 * (double)(i * j % 17));
    for (size_t j = 0; j <= n; j++)
        for (size_t i = 0; i <= n; i++)
            k += (size_t)snprintf(text + k, size - k, "vt %.4f %.4f\n",
                                  (double)i / n, (double)j / n);
    for (size_t j = 0; j < n; j++) {
        k += (size_t)snprintf(text + k, size - k, "g row%zu\n", j % 7);
        for (size_t i = 0; i < n; i++) {
            size_t a = j * (n + 1) + i + 1, b = a + 1, c = b + n + 1;
            size_t d = a + n + 1;
            if (i % 3 == 0)
                k += (size_t)snprintf(text + k, size - k,
                    "f %zu/%zu %zu/%zu %zu/%zu %zu/%zu\n", a, a, b, b, c, c,
                    d, d);
            else if (i % 3 == 1)
                k += (size_t)snprintf(text + k, size - k,
                    "f %zu %zu %zu\nf %zu %zu %zu\n", a, b, c, a, c, d);
            else
                k += (size_t)snprintf(text + k, size - k,
                    "v %zu.5 %zu.5 0\nf %zu %zu -1 %zu %zu\n", i, j, a, b,
                    c, d);
        }
    }
    text[k] = '\0';
    struct obj_tuning serial = {.nthreads = 1, .part_bytes = SIZE_MAX};
    struct obj_tuning tunings[] = {
        {.nthreads = 2, .part_bytes = 4096},
        {.nthreads = 3, .part_bytes = 1000, .max_parts = 37},
        {.nthreads = 2, .part_bytes = 4096, .window_bytes = 100000,
         .whole_bytes = 1},
    };
    struct obj_file want, got;
    struct facet_error err;
    assert_int_equal(obj_parse_tuned(text, k, "m", &want, &err, &serial),
                     FACET_OK);
    assert_true(want.ntriangles > 2 * n * n);
    char *path = temp_file(text, k);
    for (size_t t = 0; t < sizeof tunings / sizeof tunings[0]; t++) {
        assert_int_equal(obj_parse_tuned(text, k, "m", &got, &err,
                                         &tunings[t]), FACET_OK);
        same_obj(&want, &got);
        obj_free(&got);
        assert_int_equal(obj_load_tuned(path, &got, &err, &tunings[t]),
                         FACET_OK);
        same_obj(&want, &got);
        obj_free(&got);
    }
    assert_int_equal(obj_load(path, &got, &err), FACET_OK);
    same_obj(&want, &got);
    obj_free(&got);
    obj_free(&want);
    unlink(path);
    free(path);
    free(text);
}

/* A NUL byte past the 4 KB the binary check reads, inside an object, a
 * group, a material name, a comment or a vertex: a FILE:LINE: error, the
 * file loaded whole through the real reader (obj_load, several parts). */
static void test_nul_past_the_binary_check(void **state)
{
    (void)state;
    static const char *const lines[] = {
        "o abc\0def\n", "g abc\0\n", "usemtl m\0x\n", "# note \0\n",
        "v 1 2\0 3\n",
    };
    static const size_t line_length[] = {10, 7, 11, 9, 9};
    for (size_t k = 0; k < sizeof lines / sizeof *lines; k++) {
        /* 300 KB of plain statements, then the line with a NUL. */
        size_t head = 0, size = 400000;
        char *text = malloc(size);
        assert_non_null(text);
        head += (size_t)snprintf(text, size, "o abc\ng abc\nusemtl m\n");
        size_t lines_before = 3;
        while (head < 300000) {
            head += (size_t)snprintf(text + head, size - head,
                                     "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\n");
            lines_before += 4;
        }
        memcpy(text + head, lines[k], line_length[k]);
        head += line_length[k];
        head += (size_t)snprintf(text + head, size - head, "f 1 2 3\n");
        char *path = temp_file(text, head);
        struct obj_file obj;
        struct facet_error err;
        int rc = obj_load(path, &obj, &err);
        char where[64];
        snprintf(where, sizeof where, ":%zu: ", lines_before + 1);
        if (rc != FACET_EINPUT || strstr(err.message, where) == NULL ||
            strstr(err.message, "NUL byte") == NULL)
            fail_msg("line %zu (%zu): rc %d, %s", k, lines_before + 1, rc,
                     err.message);
        obj_free(&obj);
        unlink(path);
        free(path);
        free(text);
    }
}

/* Names compare by their stored length: a shorter stored name is never
 * read past its end (ASan watches), and a longer text is another name. */
static void test_names_compare_by_length(void **state)
{
    (void)state;
    struct obj_names table;
    memset(&table, 0, sizeof table);
    uint32_t a, b, c;
    assert_int_equal(obj_names_find(&table, "abc", 3, &a, NULL), 0);
    assert_int_equal(obj_names_find(&table, "abc\0def", 7, &b, NULL), 0);
    assert_int_equal(obj_names_find(&table, "abc", 3, &c, NULL), 0);
    assert_true(a != b);
    assert_int_equal(a, c);
    obj_names_free(&table);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_vertices_with_w_and_colors),
        cmocka_unit_test(test_texcoords_and_normals),
        cmocka_unit_test(test_face_index_forms),
        cmocka_unit_test(test_negative_indices),
        cmocka_unit_test(test_forward_references),
        cmocka_unit_test(test_polygons_triangulated),
        cmocka_unit_test(test_big_face),
        cmocka_unit_test(test_names),
        cmocka_unit_test(test_many_groups),
        cmocka_unit_test(test_skipped_comments_blank),
        cmocka_unit_test(test_crlf_tabs_continuation_no_final_newline),
        cmocka_unit_test(test_not_nul_terminated),
        cmocka_unit_test(test_index_errors),
        cmocka_unit_test(test_face_errors),
        cmocka_unit_test(test_number_errors),
        cmocka_unit_test(test_line_numbers_count_physical_lines),
        cmocka_unit_test(test_empty_and_binary),
        cmocka_unit_test(test_error_without_err),
        cmocka_unit_test(test_load_file),
        cmocka_unit_test(test_load_long_lines_and_chunks),
        cmocka_unit_test(test_load_errors),
        cmocka_unit_test(test_split_matches_serial),
        cmocka_unit_test(test_split_negative_indices_across_parts),
        cmocka_unit_test(test_split_continuations),
        cmocka_unit_test(test_split_errors_name_the_line),
        cmocka_unit_test(test_split_names_in_later_parts),
        cmocka_unit_test(test_split_large_mesh),
        cmocka_unit_test(test_nul_past_the_binary_check),
        cmocka_unit_test(test_names_compare_by_length),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
