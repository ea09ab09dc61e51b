/*
 * test_curvature_boundary.c: the vertex curvature on the boundary of coarse
 * meshes and on strips one or two faces wide (issue 29, item 4), against
 * the analytic curvature of the surface each mesh samples, and against
 * CGAL's 2-ring jet fit (Monge_via_jet_fitting, degree 2) on the very same
 * meshes.
 *
 * The truth at each vertex is the principal curvatures of the formula the
 * vertex was written from, k = <r'', n> with n = Pu x Pv (the winding of
 * the faces), from the fundamental forms of central differences of the
 * formula (step 1e-4 of the parameter range: 1e-8 of the curvature),
 * never from the mesh.
 *
 * The error of a vertex is max(|k1 - t1|, |k2 - t2|) / max(|t1|, |t2|); a
 * sign flip is a curvature whose truth is at least a tenth of the larger
 * one, read with the other sign at a twentieth of it or more. The bound
 * of each mesh is CGAL's worst vertex on it, measured by a small C++
 * program outside the repository (CGAL 5.5, Debian's libcgal-dev, which
 * is no dependency of Facet): the 2-ring of each vertex through the OBJ
 * faces (grown a ring when it holds fewer than 6 points), fitted by
 * CGAL::Monge_via_jet_fitting(points, 2, 2), its normal turned to the
 * truth's side, the same error:
 *
 *   g++ -O2 -I/usr/include/eigen3 -o oracle oracle.cpp
 *   ./oracle mesh.obj truth.txt     (one mesh written as write_obj does)
 *
 * Before this test (the boundary cubic wherever it had the points), the
 * worst vertices were, quads / triangles: hypar 2 x 12 59.8 / 60.1 %,
 * cap 7 x 7 0.0 / 35.9 %, cylinder 8 x 8 30.3 / 30.3 %, cone 10 x 10
 * 61.0 / 71.2 %, z = x^2/8 83.2 / 98.3 %, catenoid 148.7 / 108.9 %,
 * Enneper 173.1 / 160.1 %, and the wide triangulated strip 123 % with 2
 * sign flips.
 *
 * Two meshes stay above CGAL, and their bounds say so (short): z = x^2/8,
 * whose rim's curvature falls by a third over the two rings a one-sided
 * quadric needs (45.0 % against CGAL's 42.3 / 43.0 %; the cubic that
 * could follow it swings to 83 %), and the corner of the Enneper surface
 * on quads (61.9 % against 57.0 %; 61.9 % against CGAL's 76.5 % on
 * triangles). A strip one face wide cannot tell its curvature across
 * from its slope: both estimators read about 0 across, an error of 100 %
 * (CGAL 99.9998 to 100.0000 %, Facet up to 100.2 %, its curvature across
 * 2e-4 of the other); there the bound is 100.5 % and no sign flip.
 */
/*
 * The surface normal at the boundary vertices (curvature.h's
 * surface_normal, which a boundary joint's kink reads) against the unit
 * Pu x Pv of the formula: within 2 degrees, a strip one face wide within
 * half its angle across (NORMAL_BOUND). Before the boundary's quadric
 * fits kept their own normal (the cubic for it was fitted on buffers the
 * boundary's 2-ring had taken), the worst vertices were, quads /
 * triangles: strips 1 x 30 15.0 / 17.5 degrees, wide strip 12.6 / 98.0,
 * graph strip 1 x 12 22.3 / 24.7, hypar 2 x 12 0.48 / 2.76, z = x^2/8
 * 1.03 / 28.3, catenoid 11.0 / 10.6, Enneper 10.3 / 7.6; the cone 10 x 10
 * 1.33 / 1.10, now 1.71 / 1.65 (its rim at slant 3 m, where the 2-ring's
 * quadric takes in the cubic term of a curvature that changes by a
 * quarter over one face: a cubic on the wider neighbourhood reads 1.21
 * there but 1.98 at the corners, and elsewhere up to 71 degrees).
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
#include "core/surface/mesh.h"

#define DEG (M_PI / 180)

/* A surface P(u, v) on an nu x nv grid of quads over [u0, u1] x [v0, v1]. */
struct analytic {
    const char *name;
    int nu, nv;
    double u0, u1, v0, v1;
    void (*at)(double u, double v, double *p);
    double cgal[2];     /* CGAL's worst vertex: quads, triangles */
    double bound[2];    /* what is asserted: CGAL's, unless said short */
    double normal_bound;  /* the surface normal's at the boundary (deg) */
};

static void sphere9(double a, double b, double *p)
{
    p[0] = 9 * cos(b) * sin(a);
    p[1] = 9 * sin(b);
    p[2] = 9 * cos(b) * cos(a);
}

static void sphere9_across(double b, double a, double *p)
{
    sphere9(a, -b, p);
}

static void sphere9_graph(double x, double y, double *p)
{
    p[0] = x;
    p[1] = y;
    p[2] = sqrt(81 - x * x - y * y);
}

static void hypar5(double u, double v, double *p)
{
    p[0] = u;
    p[1] = v;
    p[2] = u * v / 5;
}

static void hypar20(double u, double v, double *p)
{
    p[0] = u;
    p[1] = v;
    p[2] = u * v / 20;
}

static void cap5(double x, double y, double *p)
{
    p[0] = x;
    p[1] = y;
    p[2] = sqrt(25 - x * x - y * y);
}

static void cylinder5(double a, double y, double *p)
{
    p[0] = 5 * sin(a);
    p[1] = y;
    p[2] = 5 * cos(a);
}

/* half-angle 30 degrees, slant s, angle t around */
static void cone30(double s, double t, double *p)
{
    p[0] = s * sin(30 * DEG) * cos(t);
    p[1] = s * sin(30 * DEG) * sin(t);
    p[2] = s * cos(30 * DEG);
}

static void parabolic8(double u, double v, double *p)
{
    p[0] = u;
    p[1] = v;
    p[2] = u * u / 8;
}

static void catenoid2(double u, double v, double *p)
{
    p[0] = 2 * cosh(v / 2) * cos(u);
    p[1] = 2 * cosh(v / 2) * sin(u);
    p[2] = v;
}

static void enneper3(double u, double v, double *p)
{
    p[0] = 3 * (u - u * u * u / 3 + u * v * v);
    p[1] = 3 * (v - v * v * v / 3 + v * u * u);
    p[2] = 3 * (u * u - v * v);
}

/* The cap's square, its corners 60 degrees from the pole of R = 5 m:
 * 5 sin(60 deg) / sqrt(2), written out for a constant initializer. */
#define CAP_HALF 3.0618621784789726
/* A strip one face wide: both estimators read ~0 across (see above). */
#define STRIP_BOUND 1.005

/* The surface normal at the boundary: within 2 degrees of the analytic
 * normal, but on a strip one face wide, which cannot tell its slope across
 * (as it cannot its curvature across): there the normal is the strip's
 * middle, off at either edge by half the angle the strip spans across
 * (1% more); on the graph strips of half-width 0.5 m on R = 9 m, that
 * angle is asin(0.5 / 9) at the middle of the strip's length. */
#define NORMAL_BOUND 2.0
#define STRIP_NORMAL(half) (1.01 * (half))
#define GRAPH_STRIP_HALF 3.1847

static const struct analytic surfaces[] = {
    {"sphere R 9, strip 1 x 30", 30, 1, -75 * DEG, 75 * DEG, -2.5 * DEG,
     2.5 * DEG, sphere9, {1.000000, 0.999998}, {STRIP_BOUND, STRIP_BOUND},
     STRIP_NORMAL(2.5)},
    {"sphere R 9, strip 1 x 12", 12, 1, -30 * DEG, 30 * DEG, -2.5 * DEG,
     2.5 * DEG, sphere9, {1.000000, 1.000000}, {STRIP_BOUND, STRIP_BOUND},
     STRIP_NORMAL(2.5)},
    {"sphere R 9, strip 30 x 1", 1, 30, -2.5 * DEG, 2.5 * DEG, -75 * DEG,
     75 * DEG, sphere9_across, {1.000000, 0.999998},
     {STRIP_BOUND, STRIP_BOUND}, STRIP_NORMAL(2.5)},
    {"sphere R 9, wide strip 1 x 30", 30, 1, -75 * DEG, 75 * DEG, -8 * DEG,
     8 * DEG, sphere9, {1.000000, 1.000000}, {STRIP_BOUND, STRIP_BOUND},
     STRIP_NORMAL(8)},
    {"sphere R 9 graph, strip 1 x 30", 1, 30, -0.5, 0.5, -7.5, 7.5,
     sphere9_graph, {1.000000, 1.000000}, {STRIP_BOUND, STRIP_BOUND},
     STRIP_NORMAL(GRAPH_STRIP_HALF)},
    {"sphere R 9 graph, strip 1 x 12", 1, 12, -0.5, 0.5, -6, 6,
     sphere9_graph, {1.000000, 1.000000}, {STRIP_BOUND, STRIP_BOUND},
     STRIP_NORMAL(GRAPH_STRIP_HALF)},
    {"hypar z = xy/5, 2 x 12", 2, 12, -1, 1, -6, 6, hypar5,
     {0.283961, 0.283961}, {0.283961, 0.283961}, NORMAL_BOUND},
    {"hypar z = xy/20, 10 x 10", 10, 10, -10, 10, -10, 10, hypar20,
     {0.125121, 0.125121}, {0.125121, 0.125121}, NORMAL_BOUND},
    {"cap R 5, 7 x 7, corners 60 deg", 7, 7, -CAP_HALF, CAP_HALF,
     -CAP_HALF, CAP_HALF, cap5, {0.125069, 0.125069},
     {0.125069, 0.125069}, NORMAL_BOUND},
    {"cylinder R 5, 90 deg, 8 x 8", 8, 8, -45 * DEG, 45 * DEG, 0, 6,
     cylinder5, {0.046341, 0.046341}, {0.046341, 0.046341}, NORMAL_BOUND},
    {"cone 30 deg, slant 3..10 m, 150 deg, 10 x 10", 10, 10, 3, 10, 0,
     150 * DEG, cone30, {0.308883, 0.264486}, {0.308883, 0.264486},
     NORMAL_BOUND},
    {"z = x^2/8 over 10 x 8 m, 10 x 10 (short)", 10, 10, -5, 5, -4, 4,
     parabolic8, {0.422937, 0.429889}, {0.4505, 0.4505}, NORMAL_BOUND},
    {"catenoid c 2, 10 x 10", 10, 10, 0, M_PI, -2, 2, catenoid2,
     {0.850063, 0.437598}, {0.850063, 0.437598}, NORMAL_BOUND},
    {"Enneper x 3, |u|, |v| <= 1.2, 10 x 10 (short on quads)", 10, 10,
     -1.2, 1.2, -1.2, 1.2, enneper3, {0.569498, 0.765274},
     {0.6190, 0.765274}, NORMAL_BOUND},
};

static void grid_point(const struct analytic *s, int i, int j, double *u,
                       double *v)
{
    *u = s->u0 + (s->u1 - s->u0) * i / s->nu;
    *v = s->v0 + (s->v1 - s->v0) * j / s->nv;
}

/* The principal curvatures t1 >= t2 of s at (u, v), normal Pu x Pv. */
static void truth(const struct analytic *s, double u, double v, double *t1,
                  double *t2)
{
    double hu = 1e-4 * (s->u1 - s->u0), hv = 1e-4 * (s->v1 - s->v0);
    double p[3][3][3];
    for (int a = -1; a <= 1; a++)
        for (int b = -1; b <= 1; b++)
            s->at(u + a * hu, v + b * hv, p[a + 1][b + 1]);
    double pu[3], pv[3], puu[3], puv[3], pvv[3], n[3];
    for (int r = 0; r < 3; r++) {
        pu[r] = (p[2][1][r] - p[0][1][r]) / (2 * hu);
        pv[r] = (p[1][2][r] - p[1][0][r]) / (2 * hv);
        puu[r] = (p[2][1][r] - 2 * p[1][1][r] + p[0][1][r]) / (hu * hu);
        pvv[r] = (p[1][2][r] - 2 * p[1][1][r] + p[1][0][r]) / (hv * hv);
        puv[r] = (p[2][2][r] - p[2][0][r] - p[0][2][r] + p[0][0][r]) /
                 (4 * hu * hv);
    }
    n[0] = pu[1] * pv[2] - pu[2] * pv[1];
    n[1] = pu[2] * pv[0] - pu[0] * pv[2];
    n[2] = pu[0] * pv[1] - pu[1] * pv[0];
    double length = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    double e = 0, f = 0, g = 0, l = 0, m = 0, nn = 0;
    for (int r = 0; r < 3; r++) {
        n[r] /= length;
        e += pu[r] * pu[r];
        f += pu[r] * pv[r];
        g += pv[r] * pv[r];
        l += puu[r] * n[r];
        m += puv[r] * n[r];
        nn += pvv[r] * n[r];
    }
    double det = e * g - f * f;
    double mean = (e * nn - 2 * f * m + g * l) / (2 * det);
    double gauss = (l * nn - m * m) / det;
    double disc = mean * mean - gauss;
    double root = sqrt(disc > 0 ? disc : 0);
    *t1 = mean + root;
    *t2 = mean - root;
}

/* The OBJ text of s's grid: vertex (i, j) is number j (nu + 1) + i + 1;
 * quads, or each split along its (i, j)-(i+1, j+1) diagonal, wound so that
 * their normal is Pu x Pv. */
static char *grid_text(const struct analytic *s, int triangles,
                       size_t *length)
{
    char *text = NULL;
    FILE *out = open_memstream(&text, length);
    assert_non_null(out);
    for (int j = 0; j <= s->nv; j++)
        for (int i = 0; i <= s->nu; i++) {
            double u, v, p[3];
            grid_point(s, i, j, &u, &v);
            s->at(u, v, p);
            fprintf(out, "v %.12f %.12f %.12f\n", p[0], p[1], p[2]);
        }
    for (int j = 0; j < s->nv; j++)
        for (int i = 0; i < s->nu; i++) {
            int a = j * (s->nu + 1) + i + 1, b = a + 1;
            int c = b + s->nu + 1, d = a + s->nu + 1;
            if (triangles)
                fprintf(out, "f %d %d %d\nf %d %d %d\n", a, b, c, a, c, d);
            else
                fprintf(out, "f %d %d %d %d\n", a, b, c, d);
        }
    assert_int_equal(fclose(out), 0);
    return text;
}

/* The unit normal Pu x Pv of s at (u, v), by central differences of the
 * formula (step 1e-4 of the parameter range). */
static void truth_normal(const struct analytic *s, double u, double v,
                         double *n)
{
    double hu = 1e-4 * (s->u1 - s->u0), hv = 1e-4 * (s->v1 - s->v0);
    double pu0[3], pu1[3], pv0[3], pv1[3], pu[3], pv[3];
    s->at(u - hu, v, pu0);
    s->at(u + hu, v, pu1);
    s->at(u, v - hv, pv0);
    s->at(u, v + hv, pv1);
    for (int r = 0; r < 3; r++) {
        pu[r] = (pu1[r] - pu0[r]) / (2 * hu);
        pv[r] = (pv1[r] - pv0[r]) / (2 * hv);
    }
    n[0] = pu[1] * pv[2] - pu[2] * pv[1];
    n[1] = pu[2] * pv[0] - pu[0] * pv[2];
    n[2] = pu[0] * pv[1] - pu[1] * pv[0];
    double length = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (int r = 0; r < 3; r++)
        n[r] /= length;
}

/* Builds the mesh of s's grid into *mesh and estimates its curvature
 * into *c (both the caller's to free). */
static void estimate_grid(const struct analytic *s, int triangles,
                          struct mesh *mesh, struct curvature *c)
{
    size_t length = 0;
    char *text = grid_text(s, triangles, &length);
    struct obj_file obj;
    struct facet_error err;
    struct mesh_options options = {UNITS_M, NULL, NULL};
    if (obj_parse(text, length, "test", &obj, &err) != FACET_OK)
        fail_msg("obj_parse: %s", err.message);
    if (mesh_build(&obj, &options, mesh, &err) != FACET_OK)
        fail_msg("mesh_build: %s", err.message);
    obj_free(&obj);
    free(text);
    assert_int_equal(mesh->nvertices, (size_t)(s->nu + 1) * (s->nv + 1));
    if (curvature_at_vertices(mesh, 0, c, &err) != FACET_OK)
        fail_msg("curvature: %s", err.message);
}

/* The parameters (u, v) of s's grid vertex that mesh vertex v came from. */
static void vertex_parameters(const struct analytic *s,
                              const struct mesh *mesh, size_t v, double *u,
                              double *w)
{
    uint32_t id = mesh->source_vertex[v];
    int i = (int)(id % (uint32_t)(s->nu + 1));
    int j = (int)(id / (uint32_t)(s->nu + 1));
    grid_point(s, i, j, u, w);
}

/* Estimates the curvature of s's grid and returns its worst relative
 * error, counting sign flips into *flips. */
static double worst_error(const struct analytic *s, int triangles,
                          int *flips)
{
    struct mesh mesh;
    struct curvature c;
    estimate_grid(s, triangles, &mesh, &c);
    double worst = 0;
    *flips = 0;
    for (size_t v = 0; v < mesh.nvertices; v++) {
        double u, w, t1, t2;
        vertex_parameters(s, &mesh, v, &u, &w);
        truth(s, u, w, &t1, &t2);
        double scale = fmax(fabs(t1), fabs(t2));
        double k1 = c.k1[v], k2 = c.k2[v];
        assert_true(isfinite(k1) && isfinite(k2));
        worst = fmax(worst, fmax(fabs(k1 - t1), fabs(k2 - t2)) / scale);
        if ((fabs(t1) >= 0.1 * scale && fabs(k1) >= 0.05 * scale &&
             k1 * t1 < 0) ||
            (fabs(t2) >= 0.1 * scale && fabs(k2) >= 0.05 * scale &&
             k2 * t2 < 0))
            ++*flips;
    }
    curvature_free(&c);
    mesh_free(&mesh);
    return worst;
}

/* The largest angle (rad) between the surface normal the estimator gives
 * a boundary vertex of s's grid and the analytic normal there. */
static double worst_boundary_normal(const struct analytic *s, int triangles)
{
    struct mesh mesh;
    struct curvature c;
    estimate_grid(s, triangles, &mesh, &c);
    double worst = 0;
    for (size_t v = 0; v < mesh.nvertices; v++) {
        if (!mesh.on_boundary[v])
            continue;
        double u, w, n[3];
        vertex_parameters(s, &mesh, v, &u, &w);
        truth_normal(s, u, w, n);
        const double *m = c.surface_normal + 3 * v;
        double cross[3] = {m[1] * n[2] - m[2] * n[1],
                           m[2] * n[0] - m[0] * n[2],
                           m[0] * n[1] - m[1] * n[0]};
        double angle = atan2(sqrt(cross[0] * cross[0] + cross[1] * cross[1] +
                                  cross[2] * cross[2]),
                             m[0] * n[0] + m[1] * n[1] + m[2] * n[2]);
        worst = fmax(worst, angle);
    }
    curvature_free(&c);
    mesh_free(&mesh);
    return worst;
}

static void test_boundary_surface_normal(void **state)
{
    (void)state;
    int failed = 0;
    for (size_t k = 0; k < sizeof surfaces / sizeof surfaces[0]; k++)
        for (int triangles = 0; triangles <= 1; triangles++) {
            const struct analytic *s = &surfaces[k];
            double worst = worst_boundary_normal(s, triangles);
            int bad = !(worst <= s->normal_bound * DEG);
            print_message("%-52s %-9s normal %8.4f deg (bound %.4f)%s\n",
                          s->name, triangles ? "triangles" : "quads",
                          worst / DEG, s->normal_bound,
                          bad ? "  FAILS" : "");
            failed += bad;
        }
    assert_int_equal(failed, 0);
}

static void test_boundary_against_jet_fit(void **state)
{
    (void)state;
    int failed = 0;
    for (size_t k = 0; k < sizeof surfaces / sizeof surfaces[0]; k++)
        for (int triangles = 0; triangles <= 1; triangles++) {
            const struct analytic *s = &surfaces[k];
            int flips;
            double worst = worst_error(s, triangles, &flips);
            int bad = flips > 0 || !(worst <= s->bound[triangles]);
            print_message("%-52s %-9s worst %7.2f %% (CGAL %7.2f %%), "
                          "sign flips %d%s\n", s->name,
                          triangles ? "triangles" : "quads", 100 * worst,
                          100 * s->cgal[triangles], flips,
                          bad ? "  FAILS" : "");
            failed += bad;
        }
    assert_int_equal(failed, 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_boundary_against_jet_fit),
        cmocka_unit_test(test_boundary_surface_normal),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
