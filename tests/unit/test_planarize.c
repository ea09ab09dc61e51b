/*
 * test_planarize.c: planarizing a quad grid near a surface (core/planar/),
 * against closed forms.
 *
 *   - A conjugate net (a surface of revolution's meridians and parallels,
 *     a sphere's latitudes and longitudes) planarizes to quads planar to
 *     1e-6 of their diagonal with the corners on the surface, also from a
 *     start whose corners were pushed off it.
 *   - A cylinder's grid along its rulings is planar already: nothing moves.
 *   - A hypar's grid along its rulings twists every quad by a b / 20
 *     (z = x y / 20, sides a, b): it cannot be planarized within 5 mm,
 *     and is reported infeasible with the closeness it reached.
 *
 * And the solver keeps to the calling thread (core/planar/sparse_solver.h):
 * asked of OpenMP and OpenBLAS themselves, where CHOLMOD loaded them.
 *
 * Every truth is measured here, apart from Facet's code: planarity as the
 * height of the fourth corner over the plane of the other three, the
 * distance to the mesh over every triangle by brute force, the distance
 * to the surface from its formula.
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

#include <dlfcn.h>

#include "core/planar/planarize.h"
#include "core/planar/sparse_solver.h"
#include "core/surface/surface.h"
#include "tests/support/surface_fixture.h"

/* A surface of revolution about z: radius 6 + 1.5 sin(z / 2), z from 0
 * to 10, half way round (s: angle 0..pi, t: z). */
static double vase_radius(double z)
{
    return 6 + 1.5 * sin(z / 2);
}

static void vase(const void *shape, double s, double t, double p[3])
{
    (void)shape;
    double a = M_PI * s, z = 10 * t, r = vase_radius(z);
    p[0] = r * cos(a);
    p[1] = r * sin(a);
    p[2] = z;
}

/* A sphere of radius 15, longitude 0..pi, latitude -60..60 degrees. */
#define SPHERE_R 15.0
static void sphere(const void *shape, double s, double t, double p[3])
{
    (void)shape;
    double lon = M_PI * s, lat = (-60 + 120 * t) * M_PI / 180;
    p[0] = SPHERE_R * cos(lat) * cos(lon);
    p[1] = SPHERE_R * cos(lat) * sin(lon);
    p[2] = SPHERE_R * sin(lat);
}

/* f sampled on ns x nt quads, each split in two, with vt (s, t), opened
 * and prepared (the shared writer of tests/support). */
static void open_formula(surface_formula f, int ns, int nt, struct surface *s)
{
    struct facet_error err;
    if (surface_fixture_formula(f, NULL, ns, nt, FORMULA_TRIANGLES, s, &err) !=
        FACET_OK)
        fail_msg("%s", err.message);
}

/* The grid's corners of s at nu x nv. */
static void start_grid(const struct surface *s, int nu, int nv,
                       struct quad_grid *g)
{
    struct panelization panels;
    struct facet_error err;
    assert_int_equal(panels_build_fast(&s->panels, PANEL_EXTREMES, nu, nv,
                                       &panels, &err), FACET_OK);
    assert_int_equal(quad_grid_from_panels(&panels, g, &err), FACET_OK);
    panelization_free(&panels);
}

/* The height of corner 3 over the plane of corners 0, 1, 2 (m). */
static double fourth_corner_height(const double c[4][3])
{
    double a[3], b[3], n[3], w[3];
    for (int x = 0; x < 3; x++) {
        a[x] = c[1][x] - c[0][x];
        b[x] = c[2][x] - c[0][x];
        w[x] = c[3][x] - c[0][x];
    }
    n[0] = a[1] * b[2] - a[2] * b[1];
    n[1] = a[2] * b[0] - a[0] * b[2];
    n[2] = a[0] * b[1] - a[1] * b[0];
    double length = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    return fabs(n[0] * w[0] + n[1] * w[1] + n[2] * w[2]) / length;
}

/* The distance of p to the nearest of the mesh's triangles, each tried:
 * the point of the plane if it projects inside, else the nearest of the
 * three sides. */
static double segment_distance(const double p[3], const double a[3],
                               const double b[3])
{
    double ab[3], ap[3], d2 = 0, t = 0, ab2 = 0;
    for (int x = 0; x < 3; x++) {
        ab[x] = b[x] - a[x];
        ap[x] = p[x] - a[x];
        t += ab[x] * ap[x];
        ab2 += ab[x] * ab[x];
    }
    t = ab2 > 0 ? fmin(1, fmax(0, t / ab2)) : 0;
    for (int x = 0; x < 3; x++) {
        double d = ap[x] - t * ab[x];
        d2 += d * d;
    }
    return sqrt(d2);
}

static double mesh_distance_brute(const struct mesh *m, const double p[3])
{
    double best = INFINITY;
    for (size_t t = 0; t < m->ntriangles; t++) {
        const double *v[3];
        for (int k = 0; k < 3; k++)
            v[k] = &m->position[3 * (size_t)m->triangle[3 * t + k]];
        double e1[3], e2[3], n[3], w[3];
        for (int x = 0; x < 3; x++) {
            e1[x] = v[1][x] - v[0][x];
            e2[x] = v[2][x] - v[0][x];
            w[x] = p[x] - v[0][x];
        }
        n[0] = e1[1] * e2[2] - e1[2] * e2[1];
        n[1] = e1[2] * e2[0] - e1[0] * e2[2];
        n[2] = e1[0] * e2[1] - e1[1] * e2[0];
        double nn = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
        double h = (w[0] * n[0] + w[1] * n[1] + w[2] * n[2]) / nn;
        double q[3];
        for (int x = 0; x < 3; x++)
            q[x] = w[x] - h * n[x];  /* p's foot on the plane, from v0 */
        /* Barycentric coordinates of the foot. */
        double c1[3], c2[3];
        c1[0] = q[1] * e2[2] - q[2] * e2[1];
        c1[1] = q[2] * e2[0] - q[0] * e2[2];
        c1[2] = q[0] * e2[1] - q[1] * e2[0];
        c2[0] = e1[1] * q[2] - e1[2] * q[1];
        c2[1] = e1[2] * q[0] - e1[0] * q[2];
        c2[2] = e1[0] * q[1] - e1[1] * q[0];
        double b1 = (c1[0] * n[0] + c1[1] * n[1] + c1[2] * n[2]) / nn;
        double b2 = (c2[0] * n[0] + c2[1] * n[1] + c2[2] * n[2]) / nn;
        double d;
        if (b1 >= 0 && b2 >= 0 && b1 + b2 <= 1)
            d = fabs(h) * sqrt(nn);
        else
            d = fmin(segment_distance(p, v[0], v[1]),
                     fmin(segment_distance(p, v[1], v[2]),
                          segment_distance(p, v[2], v[0])));
        best = fmin(best, d);
    }
    return best;
}

/* What the test measures of a planarized grid, itself. */
struct truth {
    double worst_height;     /* largest fourth-corner height over the
                                quad's longer diagonal */
    double worst_distance;   /* largest distance to the mesh (m) */
};

static struct truth measure_truth(const struct mesh *m,
                                  const struct quad_grid *g)
{
    struct truth t = {0, 0};
    for (int j = 0; j < g->nv; j++)
        for (int i = 0; i < g->nu; i++) {
            if (!g->quad[(size_t)j * g->nu + i])
                continue;
            double c[4][3];
            quad_grid_corners(g, i, j, c);
            double d = 0;
            for (int k = 0; k < 2; k++) {
                double e = 0;
                for (int x = 0; x < 3; x++)
                    e += pow(c[k + 2][x] - c[k][x], 2);
                d = fmax(d, sqrt(e));
            }
            t.worst_height = fmax(t.worst_height, fourth_corner_height(c) / d);
        }
    for (int j = 0; j <= g->nv; j++)
        for (int i = 0; i <= g->nu; i++) {
            const double *p = quad_grid_node(g, i, j);
            if (!isnan(p[0]))
                t.worst_distance = fmax(t.worst_distance,
                                        mesh_distance_brute(m, p));
        }
    return t;
}

static void run_planarize(const struct surface *s, const struct quad_grid *g,
                          double closeness, double planarity,
                          struct planarize_result *r)
{
    struct nearest_index index;
    struct facet_error err;
    assert_int_equal(nearest_index_build(&s->mesh, &index, &err), FACET_OK);
    struct planarize_options o;
    planarize_options_defaults(&o);
    o.closeness = closeness;
    o.planarity = planarity;
    int rc = planarize(&s->mesh, &index, g, &o, r, &err);
    nearest_index_free(&index);
    if (rc != FACET_OK)
        fail_msg("%s", err.message);
}

/* Pushes node (i, j) of g off its place by a smooth field of up to
 * amplitude (m) along each axis: a designer's grid moved, not noise. */
static void push_off(struct quad_grid *g, double amplitude)
{
    for (int j = 0; j <= g->nv; j++)
        for (int i = 0; i <= g->nu; i++) {
            double *p = quad_grid_node(g, i, j);
            double s = (double)i / g->nu, t = (double)j / g->nv;
            p[0] += amplitude * sin(M_PI * s) * sin(M_PI * t);
            p[1] += amplitude * cos(2 * M_PI * t);
            p[2] += amplitude * sin(2 * M_PI * s + 1);
        }
}

/* A conjugate net planarizes, its corners on the surface: formula f
 * meshed at ns x nt, the grid nu x nv, started from pushed (m) off. */
static void check_conjugate(surface_formula f, int ns, int nt, int nu, int nv,
                            double pushed,
                            double (*off_surface)(const double p[3]))
{
    struct surface s;
    open_formula(f, ns, nt, &s);
    struct quad_grid g;
    start_grid(&s, nu, nv, &g);
    assert_int_equal(g.nquads, (size_t)nu * nv);
    push_off(&g, pushed);
    struct truth pushed_truth = measure_truth(&s.mesh, &g);
    struct planarize_result r;
    run_planarize(&s, &g, 0.005, 1e-6, &r);
    struct truth t = measure_truth(&s.mesh, &r.grid);
    printf("pushed %.3g mm off; start %.3g, reached %.3g of the diagonal (own measure %.3g), "
           "corners within %.3g mm of the mesh (own %.3g mm), "
           "%d iterations\n", pushed_truth.worst_distance * 1000,
           r.start_max_relative, r.max_relative,
           t.worst_height, r.max_distance * 1000, t.worst_distance * 1000,
           r.iterations);
    assert_true(r.max_relative <= 1e-6);
    assert_int_equal(r.over, 0);
    /* The fourth corner's height is at most twice the diagonals'
     * distance in these near-rectangular quads. */
    assert_true(t.worst_height <= 2e-6);
    /* On the mesh; from a pushed start, back within a fifth of the push:
     * the grid is held to its start by a hundredth of the pull to the
     * surface (planarize.h), so the pushed grid's own place pulls too. */
    if (pushed == 0)
        assert_true(t.worst_distance <= 1e-4);
    else
        assert_true(t.worst_distance <= 0.2 * pushed_truth.worst_distance);
    assert_true(fabs(t.worst_distance - r.max_distance) <= 1e-9);
    assert_true(r.feasible);
    double worst = 0;
    for (int j = 0; j <= nv; j++)
        for (int i = 0; i <= nu; i++)
            worst = fmax(worst, off_surface(quad_grid_node(&r.grid, i, j)));
    /* Off the design surface by no more than the mesh's own chords sag
     * (under 5 mm at these resolutions) and the 0.1 mm above. */
    assert_true(worst <= 5e-3 + 1e-4);
    planarize_result_free(&r);
    quad_grid_free(&g);
    surface_close(&s);
}

static double vase_off(const double p[3])
{
    return fabs(hypot(p[0], p[1]) - vase_radius(p[2]));
}

static double sphere_off(const double p[3])
{
    return fabs(sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]) - SPHERE_R);
}

/* Meridians and parallels, the mesh finer than the grid and not aligned
 * with it: the corners start on chords, a little off planar. */
static void test_revolution_planarizes(void **state)
{
    (void)state;
    check_conjugate(vase, 90, 61, 16, 12, 0, vase_off);
}

/* The same from corners pushed up to 3 mm off in every direction. */
static void test_revolution_from_pushed_corners(void **state)
{
    (void)state;
    check_conjugate(vase, 90, 61, 16, 12, 0.003, vase_off);
}

static void test_sphere_planarizes(void **state)
{
    (void)state;
    check_conjugate(sphere, 100, 70, 18, 14, 0.003, sphere_off);
}

/* The example cylinder (radius 10, axis along y, vt around and along):
 * quads between two rulings and two circles are planar, also on the
 * mesh's chords: no corner moves. */
static void test_cylinder_needs_no_move(void **state)
{
    (void)state;
    struct surface s;
    struct facet_error err;
    if (surface_fixture_example("cylinder", 47, &s, &err) != FACET_OK)
        fail_msg("%s", err.message);
    struct quad_grid g;
    start_grid(&s, 13, 9, &g);
    struct planarize_result r;
    run_planarize(&s, &g, 0.005, 1e-6, &r);
    struct truth t = measure_truth(&s.mesh, &r.grid);
    printf("cylinder: moved at most %.3g m, %d iterations\n", r.max_moved,
           r.iterations);
    assert_true(r.max_moved <= 1e-9);
    assert_true(r.feasible);
    assert_true(t.worst_height <= 2e-6);
    assert_true(t.worst_distance <= 1e-9);
    planarize_result_free(&r);
    quad_grid_free(&g);
    surface_close(&s);
}

/* The example hypar z = x y / 20 over 20 m x 20 m, grid 10 x 10 along
 * its rulings: each quad twists by 2 x 2 / 20 = 0.2 m (the height of its
 * fourth corner, z0 - z1 + z2 - z3). Infeasible at 5 mm, said so, with
 * the closeness reached, which the test measures again. */
static void test_hypar_is_infeasible(void **state)
{
    (void)state;
    struct surface s;
    struct facet_error err;
    if (surface_fixture_example("hypar", 60, &s, &err) != FACET_OK)
        fail_msg("%s", err.message);
    struct quad_grid g;
    start_grid(&s, 10, 10, &g);
    /* The start twists as the formula says. */
    double c[4][3];
    quad_grid_corners(&g, 3, 4, c);
    assert_true(fabs(c[0][2] - c[1][2] + c[2][2] - c[3][2]) -
                0.2 < 1e-9);
    struct planarize_result r;
    run_planarize(&s, &g, 0.005, 1e-3, &r);
    struct truth t = measure_truth(&s.mesh, &r.grid);
    printf("hypar: %zu of %zu quads over 1e-3, corners up to %.1f mm from "
           "the mesh (own %.1f mm), moved up to %.1f mm, %d iterations\n",
           r.over, r.nquads, r.max_distance * 1000, t.worst_distance * 1000,
           r.max_moved * 1000, r.iterations);
    assert_false(r.feasible);
    assert_true(r.max_distance > 0.005);
    assert_true(fabs(t.worst_distance - r.max_distance) <= 1e-9);
    planarize_result_free(&r);
    quad_grid_free(&g);
    surface_close(&s);
}

/* The nearest point of the index is the brute force one. */
static void test_nearest_is_brute_force(void **state)
{
    (void)state;
    struct surface s;
    struct facet_error err;
    if (surface_fixture_example("roof", 80, &s, &err) != FACET_OK)
        fail_msg("%s", err.message);
    struct nearest_index index;
    assert_int_equal(nearest_index_build(&s.mesh, &index, &err), FACET_OK);
    unsigned state_rng = 99;
    for (int k = 0; k < 2000; k++) {
        double p[3];
        /* Half anywhere in and around the box, half within a few cells
         * of a vertex, where the nearest triangle is often in the next
         * cell but one. */
        const double *near = &s.mesh.position[3 * (size_t)(k * 7919 %
                                                   s.mesh.nvertices)];
        for (int x = 0; x < 3; x++) {
            state_rng = state_rng * 1103515245u + 12345u;
            double r = ((state_rng >> 8) & 0xffff) / 65535.0;
            double lo = s.mesh.bbox_min[x], hi = s.mesh.bbox_max[x];
            if (k % 2)
                p[x] = lo - 0.3 * (hi - lo + 1) + r * 1.6 * (hi - lo + 1);
            else
                p[x] = near[x] + (r * 2 - 1) * 3 * index.cell[x];
        }
        struct nearest_hit hit;
        nearest_point(&index, p, &hit);
        double brute = mesh_distance_brute(&s.mesh, p);
        if (fabs(hit.distance - brute) > 1e-9)
            fail_msg("point %d: index %.12g, brute force %.12g", k,
                     hit.distance, brute);
    }
    nearest_index_free(&index);
    surface_close(&s);
}

/* CHOLMOD 3 opens OpenMP regions of 4 threads and OpenBLAS starts one
 * per core; on 2 shared cores they spun more than they computed. Once
 * the solver is open, OpenMP runs every region on the thread that opens
 * it (no active level) and OpenBLAS uses one thread. */
static void test_solver_keeps_to_the_calling_thread(void **state)
{
    (void)state;
    struct sparse_solver s;
    struct facet_error err;
    assert_int_equal(sparse_solver_open(&s, &err), FACET_OK);
    int (*levels)(void);
    *(void **)&levels = dlsym(s.library, "omp_get_max_active_levels");
    assert_non_null(levels);   /* Debian's CHOLMOD is built with OpenMP */
    assert_int_equal(levels(), 0);
    int (*blas_threads)(void);
    *(void **)&blas_threads = dlsym(s.library, "openblas_get_num_threads");
    if (blas_threads != NULL)
        assert_int_equal(blas_threads(), 1);
    else
        printf("the system BLAS is not OpenBLAS: its threads not asked\n");
    sparse_solver_close(&s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_nearest_is_brute_force),
        cmocka_unit_test(test_solver_keeps_to_the_calling_thread),
        cmocka_unit_test(test_cylinder_needs_no_move),
        cmocka_unit_test(test_revolution_planarizes),
        cmocka_unit_test(test_revolution_from_pushed_corners),
        cmocka_unit_test(test_sphere_planarizes),
        cmocka_unit_test(test_hypar_is_infeasible),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
