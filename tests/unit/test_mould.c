/*
 * test_mould.c: mould families against exact answers from symmetry.
 *
 * The surfaces are generated here with vt = their parameters, on a mesh
 * whose quads align with the panel grid and are each split into four
 * triangles around a centre vertex: a triangulation that every symmetry
 * of the grid maps onto itself, so cells that symmetry says are congruent
 * are congruent on the mesh too, to rounding. They go through the real
 * path (obj_parse, mesh_build, uv_index_build, curvature, panels_build_fast,
 * classify_panels). The truths:
 *   - a cylinder: every cell congruent, one SP family;
 *   - a torus section symmetric about the equator: the cells of a row are
 *     congruent, and rows mirrored about the equator are properly
 *     congruent: one family per row up to that mirror;
 *   - a square grid centred on a spherical cap: the families are the
 *     orbits of the cells under the grid's 8 symmetries with mirror images
 *     allowed, under its 4 turns without (counted by brute force on (i, j));
 *   - a plane: no moulds;
 *   - two cylinders, one a scaled copy of the other: the best fit of a
 *     cell onto its copy is known in closed form (no turn, centroids
 *     matched, deviation (k - 1) max |a - centroid|), so the families merge
 *     at a tolerance just above it and not just below;
 *   - a noisy surface: the greedy's own promises, checked with a second
 *     fit (Horn's quaternion method) and a second relabeling.
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

#include "core/base/rng.h"
#include "core/classify/classify.h"
#include "core/mould/mould.h"
#include "core/mould/mould_fit.h"
#include "core/mould/mould_sample.h"
#include "core/obj/obj.h"
#include "core/panel/panel.h"
#include "core/surface/curvature.h"
#include "core/surface/example.h"
#include "core/surface/mesh.h"
#include "core/surface/surface.h"
#include "core/surface/uv_index.h"

#define PI 3.14159265358979323846

/* A surface S(s, t) on the unit square (m). */
struct shape {
    void (*point)(const struct shape *shape, double s, double t,
                  double p[3]);
    double scale;        /* every point multiplied by it */
    double shift;        /* then moved this far along x (m) */
    double noise;        /* each vertex moved up to this far (m) */
    struct rng *rng;     /* for the noise */
};

static void cylinder(const struct shape *shape, double s, double t,
                     double p[3])
{
    (void)shape;
    double a = (-60 + 120 * s) * PI / 180;
    p[0] = 10 * sin(a);
    p[1] = 30 * t;
    p[2] = 10 * cos(a);
}

/* R 20, r 6: 90 degrees around the axis, -60..60 around the tube. */
static void torus(const struct shape *shape, double s, double t,
                  double p[3])
{
    (void)shape;
    double a = 90 * s * PI / 180, q = (-60 + 120 * t) * PI / 180;
    p[0] = (20 + 6 * cos(q)) * cos(a);
    p[1] = (20 + 6 * cos(q)) * sin(a);
    p[2] = 6 * sin(q);
}

/* A sphere of radius 20 over the square [-10, 10]^2. */
static void cap(const struct shape *shape, double s, double t, double p[3])
{
    (void)shape;
    p[0] = 20 * s - 10;
    p[1] = 20 * t - 10;
    p[2] = sqrt(400 - p[0] * p[0] - p[1] * p[1]);
}

/* z = 2 sin(x') (t + t^2 / 2), x' = 2.4 s - 1.2: turning it half a turn
 * about the y axis, (x, y, z) -> (-x, y, -z), maps it onto itself, cell
 * (0, j) onto cell (1, j) of a 2 x nv grid with its other face out; the
 * cells have no symmetry of their own. */
static void turned(const struct shape *shape, double s, double t,
                   double p[3])
{
    (void)shape;
    p[0] = 3 * (2.4 * s - 1.2);
    p[1] = 3 * t;
    p[2] = 2 * sin(2.4 * s - 1.2) * (t + t * t / 2);
}

static void plane(const struct shape *shape, double s, double t,
                  double p[3])
{
    (void)shape;
    p[0] = 20 * s;
    p[1] = 15 * t;
    p[2] = 0;
}

struct built {
    struct mesh mesh;
    struct uv_index index;
    struct curvature curvature;
    struct panel_prep prep;
    struct panelization panels;
};

static void append(char **text, size_t *length, size_t *size,
                   const char *fmt, ...)
{
    va_list ap;
    for (;;) {
        va_start(ap, fmt);
        int n = vsnprintf(*text + *length, *size - *length, fmt, ap);
        va_end(ap);
        assert_true(n >= 0);
        if ((size_t)n < *size - *length) {
            *length += (size_t)n;
            return;
        }
        *size *= 2;
        *text = realloc(*text, *size);
        assert_non_null(*text);
    }
}

/* Builds npatches surfaces side by side in UV, each an nu x nv grid of
 * cells of m x m mesh quads over a unit of u, one empty column of cells
 * between two (a UV edge shared by two surfaces would give its points to
 * either), omitting the quads of patch 0 for which omit(i, j) says so
 * (NULL: none); panelizes them as an (npatches (nu + 1) - 1) x nv grid and
 * classifies at the paper's defaults. */
static void build(const struct shape *patch, int npatches, int nu, int nv,
                  int m, int (*omit)(int i, int j), struct built *b)
{
    size_t size = 1 << 16, length = 0;
    char *text = malloc(size);
    assert_non_null(text);
    text[0] = 0;
    int qu = nu * m, qv = nv * m;
    size_t base = 1;
    for (int k = 0; k < npatches; k++) {
        const struct shape *sh = &patch[k];
        /* Grid vertices, then the quads' centres. */
        for (int pass = 0; pass < 2; pass++)
            for (int j = 0; j <= qv - pass; j++)
                for (int i = 0; i <= qu - pass; i++) {
                    double s = (i + 0.5 * pass) / qu;
                    double t = (j + 0.5 * pass) / qv, p[3];
                    sh->point(sh, s, t, p);
                    for (int x = 0; x < 3; x++) {
                        p[x] = p[x] * sh->scale + (x == 0 ? sh->shift : 0);
                        if (sh->noise > 0)
                            p[x] += sh->noise * (2 * rng_uniform(sh->rng) - 1);
                    }
                    append(&text, &length, &size,
                           "v %.17g %.17g %.17g\nvt %.17g %.17g\n", p[0],
                           p[1], p[2], k * (1 + 1.0 / nu) + s, t);
                }
        size_t centres = base + (size_t)(qu + 1) * (qv + 1);
        for (int j = 0; j < qv; j++)
            for (int i = 0; i < qu; i++) {
                if (k == 0 && omit != NULL && omit(i, j))
                    continue;
                size_t c[4] = {
                    base + (size_t)j * (qu + 1) + i,
                    base + (size_t)j * (qu + 1) + i + 1,
                    base + (size_t)(j + 1) * (qu + 1) + i + 1,
                    base + (size_t)(j + 1) * (qu + 1) + i,
                };
                size_t e = centres + (size_t)j * qu + i;
                for (int r = 0; r < 4; r++)
                    append(&text, &length, &size,
                           "f %zu/%zu %zu/%zu %zu/%zu\n", c[r], c[r],
                           c[(r + 1) % 4], c[(r + 1) % 4], e, e);
            }
        base = centres + (size_t)qu * qv;
    }
    struct facet_error err;
    struct obj_file obj;
    struct mesh_options options = {UNITS_M, NULL, NULL};
    memset(b, 0, sizeof *b);
    int rc = obj_parse(text, length, "test", &obj, &err);
    if (rc == FACET_OK)
        rc = mesh_build(&obj, &options, &b->mesh, &err);
    obj_free(&obj);
    free(text);
    if (rc == FACET_OK)
        rc = uv_index_build(b->mesh.uv, b->mesh.ntriangles, &b->index, &err);
    if (rc == FACET_OK)
        rc = curvature_at_vertices(&b->mesh, 0, &b->curvature, &err);
    if (rc == FACET_OK)
        rc = panel_prep_build(&b->mesh, &b->index, &b->curvature, &b->prep,
                              &err);
    if (rc == FACET_OK)
        rc = panels_build_fast(&b->prep, PANEL_EXTREMES,
                               npatches * (nu + 1) - 1, nv, &b->panels, &err);
    if (rc != FACET_OK)
        fail_msg("%s", err.message);
    struct classify_options classify;
    classify_defaults(&classify);
    struct option_totals totals;
    classify_panels(&b->panels, &classify, &totals);
}

static void built_free(struct built *b)
{
    panelization_free(&b->panels);
    panel_prep_free(&b->prep);
    curvature_free(&b->curvature);
    uv_index_free(&b->index);
    mesh_free(&b->mesh);
}

static void families(const struct built *b, double tolerance, int mirror,
                     struct mould_families *f)
{
    struct mould_options options = {tolerance, mirror, 0, NULL};
    struct facet_error err;
    if (mould_families_build(&b->mesh, &b->index, &b->panels, &options, f,
                             &err) != FACET_OK)
        fail_msg("%s", err.message);
    assert_int_equal(f->npanels, b->panels.npanels);
}

/* Every panel of b is of type type. */
static void assert_all_of_type(const struct built *b, enum panel_type type)
{
    for (size_t n = 0; n < b->panels.npanels; n++)
        if (b->panels.panels[n].type != type)
            fail_msg("panel (%d, %d) is %s, not %s", b->panels.panels[n].i,
                     b->panels.panels[n].j,
                     panel_type_name(b->panels.panels[n].type),
                     panel_type_name(type));
}

/* The families of f are exactly the classes class[n] (any labels): two
 * panels share a family when and only when they share a class. */
static void assert_partition(const struct mould_families *f,
                             const int *class)
{
    for (size_t a = 0; a < f->npanels; a++)
        for (size_t b = 0; b < f->npanels; b++)
            if ((f->family[a] == f->family[b]) != (class[a] == class[b]))
                fail_msg("panels %zu and %zu: families %d and %d, classes "
                         "%d and %d", a, b, f->family[a], f->family[b],
                         class[a], class[b]);
}

/* build of one patch of point, nu x nv cells of 4 x 4 quads, whose panels
 * must all be of type type. */
static void build_typed(void (*point)(const struct shape *, double, double,
                                      double *),
                        int nu, int nv, enum panel_type type,
                        struct built *b)
{
    struct shape s = {point, 1, 0, 0, NULL};
    build(&s, 1, nu, nv, 4, NULL, b);
    assert_all_of_type(b, type);
}

/* The families of b at tolerance are exactly the classes class[n], all of
 * type type: as many families of it as there are classes, none of another
 * type, two panels together when and only when their classes are. */
static void expect_classes(const struct built *b, double tolerance,
                           int mirror, enum panel_type type,
                           const int *class)
{
    struct mould_families f;
    families(b, tolerance, mirror, &f);
    size_t classes = 0;
    for (size_t n = 0; n < f.npanels; n++) {
        size_t first = 0;
        while (class[first] != class[n])
            first++;
        classes += first == n;
    }
    assert_int_equal(f.nfamilies, classes);
    assert_int_equal(f.count[type], classes);
    assert_partition(&f, class);
    mould_families_free(&f);
}

/* expect_classes at tolerances below the numerical noise (0, 1e-12 and
 * 1e-9 m: the rounding allowance keeps exact families whole) and at
 * loose (m). */
static void expect_classes_below(const struct built *b, double loose,
                                 int mirror, enum panel_type type,
                                 const int *class)
{
    const double below_noise[] = {0, 1e-12, 1e-9};
    for (int k = 0; k < 3; k++)
        expect_classes(b, below_noise[k], mirror, type, class);
    expect_classes(b, loose, mirror, type, class);
}

static void test_cylinder_one_family(void **state)
{
    (void)state;
    struct built b;
    build_typed(cylinder, 6, 4, TYPE_SP, &b);
    int one[24] = {0};
    expect_classes_below(&b, 0.003, 0, TYPE_SP, one);
    built_free(&b);
}

/* The shipped example cylinder: 140 x 140 mesh quads cut into diagonals
 * one way, not aligned with a 6 x 5 grid, so its cells differ by the
 * chords' sagitta (0.27 mm), well within 3 mm. */
static void test_example_cylinder(void **state)
{
    (void)state;
    char path[] = "/tmp/facet_test_mould_XXXXXX";
    int fd = mkstemp(path);
    assert_true(fd >= 0);
    FILE *out = fdopen(fd, "w");
    struct facet_error err;
    assert_int_equal(example_write("cylinder", 140, out, &err), FACET_OK);
    fclose(out);
    struct surface s;
    struct mesh_options options = {UNITS_M, NULL, NULL};
    int rc = surface_open(path, &options, &s, &err);
    if (rc == FACET_OK)
        rc = surface_prepare(&s, 0, PARAM_AUTO, &err);
    unlink(path);
    if (rc != FACET_OK)
        fail_msg("%s", err.message);
    struct panelization p;
    assert_int_equal(panels_build_fast(&s.panels, PANEL_EXTREMES, 6, 5, &p,
                                       &err), FACET_OK);
    struct classify_options classify;
    classify_defaults(&classify);
    struct option_totals totals;
    classify_panels(&p, &classify, &totals);
    assert_int_equal(totals.count[TYPE_SP], 30);
    struct mould_options mo = {0.003, 0, 0, NULL};
    struct mould_families f;
    assert_int_equal(mould_families_build(&s.mesh, &s.uv, &p, &mo, &f, &err),
                     FACET_OK);
    assert_int_equal(f.count[TYPE_SP], 1);
    assert_int_equal(f.largest, 30);
    assert_true(f.worst > 0 && f.worst < 0.001);
    mould_families_free(&f);
    /* At 0.01 mm the chords show. */
    mo.tolerance = 1e-5;
    assert_int_equal(mould_families_build(&s.mesh, &s.uv, &p, &mo, &f, &err),
                     FACET_OK);
    assert_true(f.count[TYPE_SP] > 1);
    mould_families_free(&f);
    panelization_free(&p);
    surface_close(&s);
}

static void test_torus_rows(void **state)
{
    (void)state;
    for (int nv = 5; nv <= 6; nv++) {
        struct built b;
        build_typed(torus, 8, nv, TYPE_DP, &b);
        int *row = malloc(b.panels.npanels * sizeof *row);
        for (size_t n = 0; n < b.panels.npanels; n++) {
            int j = b.panels.panels[n].j;
            row[n] = j < nv - 1 - j ? j : nv - 1 - j;
        }
        for (int mirror = 0; mirror <= 1; mirror++)
            expect_classes_below(&b, 1e-4, mirror, TYPE_DP, row);
        free(row);
        built_free(&b);
    }
}

/* The orbit of cell (i, j) of an n x n grid under its 4 turns, or all 8
 * symmetries when mirror: the least index j n + i over the orbit. */
static int orbit(int i, int j, int n, int mirror)
{
    int best = j * n + i;
    for (int flip = 0; flip <= mirror; flip++) {
        int x = flip ? j : i, y = flip ? i : j;
        for (int turn = 0; turn < 4; turn++) {
            int t = x;
            x = n - 1 - y;
            y = t;
            best = y * n + x < best ? y * n + x : best;
        }
    }
    return best;
}

static void test_cap_orbits(void **state)
{
    (void)state;
    for (int n = 5; n <= 6; n++) {
        struct built b;
        build_typed(cap, n, n, TYPE_DP, &b);
        int *class = malloc(b.panels.npanels * sizeof *class);
        for (int mirror = 0; mirror <= 1; mirror++) {
            int orbits = 0;
            for (size_t p = 0; p < b.panels.npanels; p++) {
                const struct panel *panel = &b.panels.panels[p];
                class[p] = orbit(panel->i, panel->j, n, mirror);
                orbits += class[p] == panel->j * n + panel->i;
            }
            /* By hand: 5 x 5, 24 cells in fours around the centre's one,
             * or the 6 of a triangle of the square when mirrored; 6 x 6,
             * 36 in fours, or the 6 of a triangle. */
            assert_int_equal(orbits, mirror ? 6 : n == 5 ? 7 : 9);
            expect_classes_below(&b, 1e-4, mirror, TYPE_DP, class);
        }
        free(class);
        built_free(&b);
    }
}

/* A panel turned over comes off the same mould (a proper move with the
 * corner order reversed); its mirror image does too when mirrors share, but
 * the rows here are not mirror images of each other. */
static void test_turned_over(void **state)
{
    (void)state;
    struct built b;
    build_typed(turned, 2, 3, TYPE_DP, &b);
    int row[6];
    for (size_t n = 0; n < b.panels.npanels; n++)
        row[n] = b.panels.panels[n].j;
    for (int mirror = 0; mirror <= 1; mirror++)
        expect_classes_below(&b, 1e-4, mirror, TYPE_DP, row);
    built_free(&b);
}

/* SP and DP panels never share a family, however loose the tolerance: a
 * cylinder beside the DP surface of test_turned_over, at 100 m. */
static void test_types_apart(void **state)
{
    (void)state;
    struct shape s[2] = {{cylinder, 1, 0, 0, NULL},
                         {turned, 1, 40, 0, NULL}};
    struct built b;
    build(s, 2, 2, 3, 4, NULL, &b);
    struct mould_families f;
    families(&b, 100, 1, &f);
    assert_int_equal(f.count[TYPE_SP], 1);
    assert_int_equal(f.count[TYPE_DP], 1);
    for (size_t n = 0; n < f.npanels; n++)
        assert_int_equal(b.panels.panels[n].type,
                         b.panels.panels[n].i < 2 ? TYPE_SP : TYPE_DP);
    assert_int_equal(f.largest, 6);
    mould_families_free(&f);
    built_free(&b);
}

static void test_plane_no_moulds(void **state)
{
    (void)state;
    struct built b;
    build_typed(plane, 4, 3, TYPE_FP, &b);
    struct mould_families f;
    families(&b, 0.003, 1, &f);
    assert_int_equal(f.nfamilies, 0);
    assert_int_equal(f.largest, 0);
    assert_int_equal(f.singletons, 0);
    for (size_t n = 0; n < f.npanels; n++)
        assert_int_equal(f.family[n], -1);
    mould_families_free(&f);
    built_free(&b);
}

/* Two cylinders, the second k times the first: below the closed-form
 * deviation of a cell from its copy, two families; above it, one. */
static void test_tolerance_merges(void **state)
{
    (void)state;
    const double k = 1.001;
    struct shape s[2] = {{cylinder, 1, 0, 0, NULL},
                         {cylinder, k, 40, 0, NULL}};
    const int nu = 4, nv = 3;
    struct built b;
    build(s, 2, nu, nv, 4, NULL, &b);
    assert_all_of_type(&b, TYPE_SP);
    /* The lattice points of cell (0, 0) of the first: mesh vertices. */
    double a[MOULD_SAMPLES][3], g[3] = {0, 0, 0};
    for (int y = 0; y < MOULD_SIDE; y++)
        for (int x = 0; x < MOULD_SIDE; x++) {
            double *p = a[mould_sample_index(x, y)];
            cylinder(&s[0], (double)x / (MOULD_SIDE - 1) / nu,
                     (double)y / (MOULD_SIDE - 1) / nv, p);
            for (int c = 0; c < 3; c++)
                g[c] += p[c] / MOULD_SAMPLES;
        }
    double spread = 0;
    for (int q = 0; q < MOULD_SAMPLES; q++)
        spread = fmax(spread, sqrt(pow(a[q][0] - g[0], 2) +
                                   pow(a[q][1] - g[1], 2) +
                                   pow(a[q][2] - g[2], 2)));
    double difference = (k - 1) * spread;
    struct mould_families f;
    families(&b, difference * (1 - 1e-3), 0, &f);
    assert_int_equal(f.count[TYPE_SP], 2);
    assert_int_equal(f.largest, (size_t)(nu * nv));
    for (size_t n = 0; n < f.npanels; n++)
        assert_int_equal(f.family[n], b.panels.panels[n].i > nu);
    mould_families_free(&f);
    families(&b, difference * (1 + 1e-6), 0, &f);
    assert_int_equal(f.count[TYPE_SP], 1);
    assert_true(fabs(f.worst - difference) <= 1e-9 * difference + 1e-12);
    mould_families_free(&f);
    built_free(&b);
}

/* A hole of one mesh quad inside cell (1, 1), between its lattice points,
 * which all stay on the surface: that panel is trimmed, and has a family
 * of its own although its samples are those of every other cell. */
static int hole(int i, int j)
{
    return i == 5 && j == 5;
}

static void test_trimmed_own_family(void **state)
{
    (void)state;
    struct shape s = {cylinder, 1, 0, 0, NULL};
    struct built b;
    build(&s, 1, 3, 3, 4, hole, &b);
    assert_all_of_type(&b, TYPE_SP);
    struct mould_families f;
    families(&b, 0.003, 1, &f);
    assert_int_equal(f.count[TYPE_SP], 2);
    assert_int_equal(f.trimmed, 1);
    assert_int_equal(f.singletons, 1);
    assert_int_equal(f.largest, 8);
    for (size_t n = 0; n < f.npanels; n++) {
        const struct panel *p = &b.panels.panels[n];
        assert_int_equal(p->trimmed, p->i == 1 && p->j == 1);
        assert_int_equal(f.family[n], p->trimmed ? 1 : 0);
    }
    mould_families_free(&f);
    built_free(&b);
}

static void test_bad_tolerance(void **state)
{
    (void)state;
    struct built b;
    build_typed(plane, 2, 2, TYPE_FP, &b);
    const double bad[] = {-1e-3, NAN, INFINITY};
    for (int k = 0; k < 3; k++) {
        struct mould_options options = {bad[k], 0, 0, NULL};
        struct mould_families f;
        struct facet_error err;
        assert_int_equal(mould_families_build(&b.mesh, &b.index, &b.panels,
                                              &options, &f, &err),
                         FACET_EINPUT);
        mould_families_free(&f);
    }
    built_free(&b);
}

/* ---- A second fit: Horn's quaternion method, with its own relabeling. */

/* Eigenvector of the largest eigenvalue of the symmetric 4x4 a, by cyclic
 * Jacobi. */
static void largest_eigenvector4(double a[4][4], double q[4])
{
    double v[4][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0},
                      {0, 0, 0, 1}};
    for (int sweep = 0; sweep < 100; sweep++) {
        double off = 0;
        for (int p = 0; p < 4; p++)
            for (int r = p + 1; r < 4; r++)
                off += fabs(a[p][r]);
        if (off < 1e-300)
            break;
        for (int p = 0; p < 4; p++)
            for (int r = p + 1; r < 4; r++) {
                if (fabs(a[p][r]) < 1e-300)
                    continue;
                double theta = (a[r][r] - a[p][p]) / (2 * a[p][r]);
                double t = (theta >= 0 ? 1 : -1) /
                           (fabs(theta) + sqrt(theta * theta + 1));
                double c = 1 / sqrt(t * t + 1), s = t * c;
                for (int k = 0; k < 4; k++) {
                    double x = a[k][p], y = a[k][r];
                    a[k][p] = c * x - s * y;
                    a[k][r] = s * x + c * y;
                }
                for (int k = 0; k < 4; k++) {
                    double x = a[p][k], y = a[r][k];
                    a[p][k] = c * x - s * y;
                    a[r][k] = s * x + c * y;
                }
                for (int k = 0; k < 4; k++) {
                    double x = v[k][p], y = v[k][r];
                    v[k][p] = c * x - s * y;
                    v[k][r] = s * x + c * y;
                }
            }
    }
    int best = 0;
    for (int k = 1; k < 4; k++)
        if (a[k][k] > a[best][best])
            best = k;
    for (int k = 0; k < 4; k++)
        q[k] = v[k][best];
}

/* The largest distance after Horn's least-squares fit of a[k] onto b[k]
 * (n points); mirrored fits the mirror image of a (x negated), which is
 * the best improper fit of a. */
static double horn_deviation(const double (*a)[3], const double (*b)[3],
                             int n, int mirrored)
{
    double ca[3] = {0, 0, 0}, cb[3] = {0, 0, 0};
    double (*x)[3] = malloc(sizeof(double[3]) * (size_t)n);
    for (int k = 0; k < n; k++)
        for (int c = 0; c < 3; c++) {
            x[k][c] = a[k][c] * (mirrored && c == 0 ? -1 : 1);
            ca[c] += x[k][c] / n;
            cb[c] += b[k][c] / n;
        }
    double S[3][3] = {{0}};
    for (int k = 0; k < n; k++)
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++)
                S[i][j] += (x[k][i] - ca[i]) * (b[k][j] - cb[j]);
    double N[4][4] = {
        {S[0][0] + S[1][1] + S[2][2], S[1][2] - S[2][1], S[2][0] - S[0][2],
         S[0][1] - S[1][0]},
        {S[1][2] - S[2][1], S[0][0] - S[1][1] - S[2][2], S[0][1] + S[1][0],
         S[2][0] + S[0][2]},
        {S[2][0] - S[0][2], S[0][1] + S[1][0], -S[0][0] + S[1][1] - S[2][2],
         S[1][2] + S[2][1]},
        {S[0][1] - S[1][0], S[2][0] + S[0][2], S[1][2] + S[2][1],
         -S[0][0] - S[1][1] + S[2][2]},
    };
    double q[4];
    largest_eigenvector4(N, q);
    double w = q[0], i = q[1], j = q[2], k = q[3];
    double R[3][3] = {
        {w * w + i * i - j * j - k * k, 2 * (i * j - w * k),
         2 * (i * k + w * j)},
        {2 * (i * j + w * k), w * w - i * i + j * j - k * k,
         2 * (j * k - w * i)},
        {2 * (i * k - w * j), 2 * (j * k + w * i),
         w * w - i * i - j * j + k * k},
    };
    double worst = 0;
    for (int p = 0; p < n; p++) {
        double d2 = 0;
        for (int r = 0; r < 3; r++) {
            double y = cb[r] - b[p][r];
            for (int c = 0; c < 3; c++)
                y += R[r][c] * (x[p][c] - ca[c]);
            d2 += y * y;
        }
        worst = fmax(worst, sqrt(d2));
    }
    free(x);
    return worst;
}

/* The least deviation of a onto b over the 8 ways of laying the lattice,
 * each written as a map of the centred integer lattice: turn by quarter
 * turns after an optional transpose. */
static double horn_congruence(const double a[MOULD_SAMPLES][3],
                              const double b[MOULD_SAMPLES][3], int mirror)
{
    const int h = (MOULD_SIDE - 1) / 2;
    double best = INFINITY;
    for (int transpose = 0; transpose <= 1; transpose++)
        for (int turn = 0; turn < 4; turn++) {
            double moved[MOULD_SAMPLES][3];
            for (int y = -h; y <= h; y++)
                for (int x = -h; x <= h; x++) {
                    int px = transpose ? y : x, py = transpose ? x : y;
                    for (int t = 0; t < turn; t++) {
                        int keep = px;
                        px = -py;
                        py = keep;
                    }
                    memcpy(moved[(y + h) * MOULD_SIDE + x + h],
                           a[(py + h) * MOULD_SIDE + px + h],
                           sizeof moved[0]);
                }
            for (int m = 0; m <= mirror; m++)
                best = fmin(best, horn_deviation(
                    (const double (*)[3])moved, (const double (*)[3])b,
                    MOULD_SAMPLES, m));
        }
    return best;
}

static void test_fit_recovers_motion(void **state)
{
    (void)state;
    struct rng rng;
    rng_seed(&rng, 15);
    for (int trial = 0; trial < 200; trial++) {
        double a[12][3], b[12][3], mirror_b[12][3];
        double q[4], len = 0;
        for (int k = 0; k < 4; k++) {
            q[k] = 2 * rng_uniform(&rng) - 1;
            len += q[k] * q[k];
        }
        for (int k = 0; k < 4; k++)
            q[k] /= sqrt(len);
        double w = q[0], i = q[1], j = q[2], k = q[3];
        double R[3][3] = {
            {w * w + i * i - j * j - k * k, 2 * (i * j - w * k),
             2 * (i * k + w * j)},
            {2 * (i * j + w * k), w * w - i * i + j * j - k * k,
             2 * (j * k - w * i)},
            {2 * (i * k - w * j), 2 * (j * k + w * i),
             w * w - i * i - j * j + k * k},
        };
        double t[3] = {100 * rng_uniform(&rng), -50 * rng_uniform(&rng), 3};
        /* Flat-ish clouds as well as round ones: a panel's samples. */
        double flat = trial % 2 ? 1 : 1e-3;
        for (int p = 0; p < 12; p++) {
            a[p][0] = 2 * rng_uniform(&rng);
            a[p][1] = rng_uniform(&rng);
            a[p][2] = flat * rng_uniform(&rng);
            for (int r = 0; r < 3; r++) {
                b[p][r] = t[r];
                for (int c = 0; c < 3; c++)
                    b[p][r] += R[r][c] * a[p][c];
            }
            mirror_b[p][0] = -b[p][0];
            mirror_b[p][1] = b[p][1];
            mirror_b[p][2] = b[p][2];
        }
        double rotation[9], translation[3];
        double d = mould_fit_points((const double (*)[3])a,
                                    (const double (*)[3])b, NULL, 12, 0,
                                    rotation, translation);
        assert_true(d < 1e-9);
        for (int r = 0; r < 3; r++) {
            assert_true(fabs(translation[r] - t[r]) < 1e-9);
            for (int c = 0; c < 3; c++)
                assert_true(fabs(rotation[3 * r + c] - R[r][c]) < 1e-9);
        }
        /* The mirror image: only a mirrored fit lies on it. */
        assert_true(mould_fit_points((const double (*)[3])a,
                                     (const double (*)[3])mirror_b, NULL, 12,
                                     1, NULL, NULL) < 1e-9);
        if (flat == 1)
            assert_true(mould_fit_points((const double (*)[3])a,
                                         (const double (*)[3])mirror_b, NULL,
                                         12, 0, NULL, NULL) > 1e-3);
        /* With noise, the least-squares fit is Horn's too. */
        for (int p = 0; p < 12; p++)
            for (int r = 0; r < 3; r++)
                b[p][r] += 0.05 * (rng_uniform(&rng) - 0.5);
        for (int m = 0; m <= 1; m++) {
            double ours = mould_fit_points((const double (*)[3])a,
                                           (const double (*)[3])b, NULL, 12,
                                           m, NULL, NULL);
            double horn = horn_deviation((const double (*)[3])a,
                                         (const double (*)[3])b, 12, m);
            assert_true(fabs(ours - horn) < 1e-9);
        }
    }
}

/* Relabelings 0..3 keep the corners' cyclic order, 4..7 reverse it, and
 * all 8 are different permutations of the lattice. */
static void test_relabelings(void **state)
{
    (void)state;
    const int e = MOULD_SIDE - 1;
    const int corner[4] = {mould_sample_index(0, 0), mould_sample_index(e, 0),
                           mould_sample_index(e, e), mould_sample_index(0, e)};
    int order[MOULD_RELABELINGS][MOULD_SAMPLES];
    for (int r = 0; r < MOULD_RELABELINGS; r++) {
        mould_relabeling(r, order[r]);
        int seen[MOULD_SAMPLES] = {0};
        for (int k = 0; k < MOULD_SAMPLES; k++)
            seen[order[r][k]]++;
        for (int k = 0; k < MOULD_SAMPLES; k++)
            assert_int_equal(seen[k], 1);
        int at[4];
        for (int c = 0; c < 4; c++) {
            at[c] = -1;
            for (int d = 0; d < 4; d++)
                if (order[r][corner[c]] == corner[d])
                    at[c] = d;
            assert_true(at[c] >= 0);
        }
        int step = (at[1] - at[0] + 4) % 4;
        assert_int_equal(step, r < 4 ? 1 : 3);
        for (int s = 0; s < r; s++)
            assert_true(memcmp(order[s], order[r], sizeof order[r]) != 0);
    }
}

/* A cylinder with every vertex moved at random by up to 0.5 mm: at 1 mm
 * the families are partial. Checked with Horn: every member within the
 * limit of its representative, and no panel congruent to the
 * representative of an earlier family of its type. */
static void test_greedy_brute_force(void **state)
{
    (void)state;
    for (int mirror = 0; mirror <= 1; mirror++) {
        struct rng rng;
        rng_seed(&rng, 7 + (uint64_t)mirror);
        struct shape s = {cylinder, 1, 0, 5.5e-4, &rng};
        struct built b;
        build(&s, 1, 6, 5, 4, NULL, &b);
        struct mould_families f;
        const double tolerance = 0.001;
        families(&b, tolerance, mirror, &f);
        size_t n = b.panels.npanels;
        double (*sample)[MOULD_SAMPLES][3] = malloc(n * sizeof *sample);
        for (size_t p = 0; p < n; p++)
            assert_true(mould_sample_panel(&b.mesh, &b.index, &b.panels, p,
                                           sample[p]));
        struct mould_options options = {tolerance, mirror, 0, NULL};
        size_t shared = 0;
        for (size_t p = 0; p < n; p++) {
            const struct panel *panel = &b.panels.panels[p];
            int fam = f.family[p];
            assert_true(fam >= 0 && (size_t)fam < f.nfamilies);
            size_t rep = f.representative[fam];
            assert_true(rep <= p);
            assert_int_equal(f.family[rep], fam);
            if (rep != p) {
                shared++;
                double limit = mould_limit(&options,
                                           b.panels.panels[rep].diameter,
                                           panel->diameter);
                double d = horn_congruence(
                    (const double (*)[3])sample[rep],
                    (const double (*)[3])sample[p], mirror);
                assert_true(d <= limit * (1 + 1e-9));
            }
            for (int g = 0; g < fam; g++) {
                size_t r = f.representative[g];
                if (b.panels.panels[r].type != panel->type)
                    continue;
                double limit = mould_limit(&options,
                                           b.panels.panels[r].diameter,
                                           panel->diameter);
                double d = horn_congruence((const double (*)[3])sample[r],
                                           (const double (*)[3])sample[p],
                                           mirror);
                assert_true(d > limit * (1 - 1e-9));
            }
        }
        /* Not vacuous: some panels share, some families are apart. */
        assert_true(shared > 0);
        assert_true(f.nfamilies > 2);
        size_t total = 0;
        for (size_t g = 0; g < f.nfamilies; g++)
            total += f.size[g];
        assert_int_equal(total, n);
        free(sample);
        mould_families_free(&f);
        built_free(&b);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_fit_recovers_motion),
        cmocka_unit_test(test_relabelings),
        cmocka_unit_test(test_cylinder_one_family),
        cmocka_unit_test(test_example_cylinder),
        cmocka_unit_test(test_torus_rows),
        cmocka_unit_test(test_cap_orbits),
        cmocka_unit_test(test_turned_over),
        cmocka_unit_test(test_types_apart),
        cmocka_unit_test(test_plane_no_moulds),
        cmocka_unit_test(test_tolerance_merges),
        cmocka_unit_test(test_trimmed_own_family),
        cmocka_unit_test(test_bad_tolerance),
        cmocka_unit_test(test_greedy_brute_force),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
