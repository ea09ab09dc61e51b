/*
 * test_curvature_pinned.c: the vertex curvature, bit for bit, on surfaces
 * chosen to take every way through the estimator (interior quadrics, the
 * boundary cubic, the coarse fallback to the 2-ring, thin strips fitted
 * straight across, Newton steps of the osculating correction, vn normals,
 * flip_normals). The hashes were computed by the estimator as it stood
 * before it was made faster (issue 27): a change that is meant to be
 * faster only must leave them all as they are. One that changes a result
 * on purpose says so in its commit, with its accuracy against the
 * analytic surfaces (test_curvature), and pins the new hashes here.
 *
 * Re-pinned for issue 29 item 4 (the boundary's sharp 2-ring quadric):
 * only boundary vertices changed (every other vertex the same to the bit,
 * checked vertex by vertex), and on the surfaces with an analytic truth
 * the changed vertices' worst error went down: cylinder at 5 4.0e-6 to
 * 1.3e-6 1/m, dome at 5 1.2e-2 to 1.9e-9, hypar at 6 17.2 % to 13.2 %,
 * torus at 8 21.0 % to 12.8 %, wave at 9 0.071 to 0.040 1/m, roof at 12
 * 0.194 to 0.110 1/m, roof at 48 0.099 to 0.061 1/m, strip 3.0e-6 to
 * 3.4e-7 1/m, cap 4.6 % to 1.3 %.
 *
 * The hash is FNV-1a over the 64-bit patterns of k1, k2, dir1, dir2 and
 * normal, so it does not depend on the byte order.
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

#include "core/obj/obj.h"
#include "core/surface/curvature.h"
#include "core/surface/example.h"
#include "core/surface/mesh.h"

static uint64_t hash_doubles(uint64_t h, const double *x, size_t n)
{
    for (size_t i = 0; i < n; i++) {
        uint64_t bits;
        memcpy(&bits, x + i, sizeof bits);
        for (int b = 0; b < 8; b++) {
            h ^= (bits >> (8 * b)) & 0xff;
            h *= 1099511628211ULL;
        }
    }
    return h;
}

static uint64_t hash_curvature(const struct curvature *c)
{
    size_t n = c->nvertices;
    uint64_t h = 14695981039346656037ULL;
    h = hash_doubles(h, c->k1, n);
    h = hash_doubles(h, c->k2, n);
    h = hash_doubles(h, c->dir1, 3 * n);
    h = hash_doubles(h, c->dir2, 3 * n);
    return hash_doubles(h, c->normal, 3 * n);
}

static void mesh_from_text(const char *text, size_t length, struct mesh *mesh)
{
    struct obj_file obj;
    struct facet_error err;
    struct mesh_options options = {UNITS_M, NULL, NULL};
    if (obj_parse(text, length, "test", &obj, &err) != FACET_OK)
        fail_msg("obj_parse: %s", err.message);
    if (mesh_build(&obj, &options, mesh, &err) != FACET_OK)
        fail_msg("mesh_build: %s", err.message);
    obj_free(&obj);
}

static void mesh_from_example(const char *name, int res, struct mesh *mesh)
{
    char *text = NULL;
    size_t length = 0;
    struct facet_error err;
    FILE *out = open_memstream(&text, &length);
    assert_non_null(out);
    if (example_write(name, res, out, &err) != FACET_OK)
        fail_msg("example_write %s: %s", name, err.message);
    assert_int_equal(fclose(out), 0);
    mesh_from_text(text, length, mesh);
    free(text);
}

/* A serpentine strip one quad (1.5 m) wide, rows of six quads joined at
 * alternate ends, wrapped on a cylinder of radius 4 m about the y axis:
 * every vertex on the boundary, every neighbourhood thin. Written as
 * quads, so that the rings take whole faces. */
static void mesh_strip(struct mesh *mesh)
{
    enum { COLS = 6, ROWS = 7 };
    int cell[ROWS][COLS] = {{0}};
    for (int r = 0; r < ROWS; r += 2) {
        for (int c = 0; c < COLS; c++)
            cell[r][c] = 1;
        if (r + 1 < ROWS)
            cell[r + 1][(r / 2) % 2 == 0 ? COLS - 1 : 0] = 1;
    }
    int id[ROWS + 1][COLS + 1] = {{0}}, next = 1;
    char *text = NULL;
    size_t length = 0;
    FILE *out = open_memstream(&text, &length);
    assert_non_null(out);
    for (int r = 0; r < ROWS; r++)
        for (int c = 0; c < COLS; c++)
            for (int b = 0; cell[r][c] && b <= 1; b++)
                for (int a = 0; a <= 1; a++) {
                    if (id[r + b][c + a])
                        continue;
                    id[r + b][c + a] = next++;
                    double u = (c + a) * 1.5, v = (r + b) * 1.5;
                    /* To the nanometre: the last bit of sin and cos
                     * varies with the compiler (folded or called) and
                     * the libm variant, and the pin is of the
                     * estimator, not of them. */
                    fprintf(out, "v %.9f %.9f %.9f\n", 4 * sin(u / 4), v,
                            4 * cos(u / 4));
                }
    for (int r = 0; r < ROWS; r++)
        for (int c = 0; c < COLS; c++)
            if (cell[r][c])
                fprintf(out, "f %d %d %d %d\n", id[r][c], id[r][c + 1],
                        id[r + 1][c + 1], id[r + 1][c]);
    assert_int_equal(fclose(out), 0);
    mesh_from_text(text, length, mesh);
    free(text);
}

/* A spherical cap of radius 4.5 m on 6 x 6 quads, its corners 85 degrees
 * down from the top: a coarse one-sided neighbourhood spans a wide arc,
 * where the boundary cubic gives way to the 2-ring quadric. */
static void mesh_cap(struct mesh *mesh)
{
    const int n = 6;
    const double radius = 4.5, corner = 85 * M_PI / 180;
    double half = radius * sin(corner) / sqrt(2);
    char *text = NULL;
    size_t length = 0;
    FILE *out = open_memstream(&text, &length);
    assert_non_null(out);
    for (int j = 0; j <= n; j++)
        for (int i = 0; i <= n; i++) {
            double x = half * (2.0 * i / n - 1), y = half * (2.0 * j / n - 1);
            /* to the nanometre, as the strip's */
            fprintf(out, "v %.9f %.9f %.9f\n", x, y,
                    sqrt(radius * radius - x * x - y * y));
        }
    for (int j = 0; j < n; j++)
        for (int i = 0; i < n; i++) {
            int a = j * (n + 1) + i + 1;
            fprintf(out, "f %d %d %d %d\n", a, a + 1, a + n + 2, a + n + 1);
        }
    assert_int_equal(fclose(out), 0);
    mesh_from_text(text, length, mesh);
    free(text);
}

/* The dome with exact vn at every corner, pointing inwards. */
static void mesh_dome_vn(struct mesh *mesh)
{
    mesh_from_example("dome", 16, mesh);
    free(mesh->corner_normal);
    mesh->corner_normal = malloc(9 * mesh->ntriangles * sizeof(double));
    assert_non_null(mesh->corner_normal);
    mesh->has_normals = 1;
    for (size_t k = 0; k < 3 * mesh->ntriangles; k++) {
        const double *p = mesh->position + 3 * (size_t)mesh->triangle[k];
        double in[3] = {-p[0], -p[1], -(p[2] + sqrt(200))};
        for (int r = 0; r < 3; r++)
            mesh->corner_normal[3 * k + r] = in[r] / 20;
    }
}

/* Checks the estimator's answer on mesh (either orientation, on one
 * thread and on three) against the pinned hashes. */
static void check(const char *label, struct mesh *mesh, uint64_t pinned,
                  uint64_t pinned_flipped)
{
    for (int flip = 0; flip <= 1; flip++) {
        uint64_t want = flip ? pinned_flipped : pinned, got[2];
        for (int t = 0; t < 2; t++) {
            struct curvature c;
            struct facet_error err;
            if (curvature_at_vertices_jobs(mesh, flip, t ? 3 : 1, &c,
                                           &err) != FACET_OK)
                fail_msg("%s: %s", label, err.message);
            got[t] = hash_curvature(&c);
            if (got[t] != want)
                print_message("%s%s: hash 0x%016llx, pinned 0x%016llx "
                              "(k1[0] %a, k2[0] %a)\n", label,
                              flip ? ", flipped" : "",
                              (unsigned long long)got[t],
                              (unsigned long long)want, c.k1[0], c.k2[0]);
            curvature_free(&c);
        }
        assert_true(got[0] == want && got[1] == want);
    }
    mesh_free(mesh);
}

static void test_examples(void **state)
{
    (void)state;
    static const struct {
        const char *name;
        int res;
        uint64_t hash, flipped;
    } pinned[] = {
        {"plane", 6, 0x83440e6d18635338ULL,
         0x61dfee33e4f55db8ULL},
        {"cylinder", 5, 0xc82aba4c4f4df9c1ULL,
         0xf622064e9d067af1ULL},
        {"cylinder", 30, 0x19850a159c6d82b8ULL,
         0xbcedb746711cfcefULL},
        {"dome", 5, 0x3efbfba0e0579d4aULL,
         0x555cfd8c5b5d1212ULL},
        {"dome", 30, 0xa2ea6ca159cb9a67ULL,
         0xe0378a5f9ee8faf4ULL},
        {"hypar", 6, 0x18ba4d9bf5f6ee39ULL,
         0x81400ba0eaf6fbfdULL},
        {"hypar", 30, 0x7fe9d2eab31553b5ULL,
         0xd34f21d481d5d940ULL},
        {"torus", 8, 0x7d24fd508d3025aaULL,
         0xda830e441d1d1ce9ULL},
        {"torus", 30, 0xb93d1d334e0e8e71ULL,
         0xacc1a2bb2d6ae872ULL},
        {"wave", 9, 0x516d594cc51fba42ULL,
         0x29c0fea86bd6e3a1ULL},
        {"wave", 30, 0x334c69d46ae9749aULL,
         0xb263ddcdd0b4370dULL},
        {"roof", 12, 0x02fba45a669ea152ULL,
         0x733665e43e705f85ULL},
        {"roof", 48, 0x955fc1893f63b548ULL,
         0xee543062e58887b8ULL},
    };
    for (size_t i = 0; i < sizeof pinned / sizeof pinned[0]; i++) {
        char label[64];
        struct mesh mesh;
        snprintf(label, sizeof label, "%s at %d", pinned[i].name,
                 pinned[i].res);
        mesh_from_example(pinned[i].name, pinned[i].res, &mesh);
        check(label, &mesh, pinned[i].hash, pinned[i].flipped);
    }
}

static void test_strip(void **state)
{
    (void)state;
    struct mesh mesh;
    mesh_strip(&mesh);
    check("strip", &mesh, 0xa776aba02fa0b006ULL,
          0x5435dea5a586c605ULL);
}

static void test_cap(void **state)
{
    (void)state;
    struct mesh mesh;
    mesh_cap(&mesh);
    check("cap", &mesh, 0x970d9d2de28e78c4ULL,
          0xbd7d440e7875d8eeULL);
}

static void test_dome_vn(void **state)
{
    (void)state;
    struct mesh mesh;
    mesh_dome_vn(&mesh);
    check("dome with vn", &mesh, 0x6473c02e50da50f6ULL,
          0x47f5b7cf88a0b18dULL);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_examples),
        cmocka_unit_test(test_strip),
        cmocka_unit_test(test_cap),
        cmocka_unit_test(test_dome_vn),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
