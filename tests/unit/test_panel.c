/*
 * test_panel.c: panels of the example surfaces against what geometry says
 * they must be: areas that add up to the mesh area, deviations of a
 * cylinder's panels against the analytic best-fit plane of an arc, and the
 * classes DESIGN.md's validation names (plane flat, cylinder ruled, sphere
 * round, hypar feature-curve split by the sign of H).
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

#include "core/surface/example.h"
#include "core/search/optimize.h"
#include "core/evaluate/evaluate.h"
#include "core/panel/panel_lattice.h"
#include "tests/support/surface_fixture.h"

#define PI 3.14159265358979323846

/* Writes example name at res to a temporary file and opens and prepares
 * it as a surface. */
static void open_example(const char *name, int res, struct surface *s)
{
    struct facet_error err;
    if (surface_fixture_example(name, res, s, &err) != FACET_OK)
        fail_msg("%s: %s", name, err.message);
}

/* option_evaluate with the panels typed by class alone (the paper's
 * typing) when by_class is set, else as built. */
static void evaluate_typed(const struct surface *s, int nu, int nv,
                           double threshold, int by_class,
                           struct panelization *p, struct option_totals *t)
{
    struct option_params params;
    memset(&params, 0, sizeof params);
    params.nu = nu;
    params.nv = nv;
    params.mode = PANEL_EXTREMES;
    classify_defaults(&params.classify);
    params.classify.threshold = threshold;
    params.classify.sp_by_class = by_class;
    struct facet_error err;
    int rc = option_evaluate(s, &params, NULL, p, t, &err);
    if (rc != FACET_OK)
        fail_msg("%s", err.message);
}

static void evaluate(const struct surface *s, int nu, int nv,
                     double threshold, struct panelization *p,
                     struct option_totals *t)
{
    evaluate_typed(s, nu, nv, threshold, 0, p, t);
}

static void test_plane_panels(void **state)
{
    (void)state;
    struct surface s;
    open_example("plane", 0, &s);
    struct panelization p;
    struct option_totals t;
    evaluate(&s, 4, 3, 0.003, &p, &t);
    assert_int_equal(p.npanels, 12);
    for (size_t n = 0; n < p.npanels; n++) {
        /* Positions are written with 9 significant digits. */
        assert_true(fabs(p.panels[n].area - 25) < 1e-6);
        assert_true(p.panels[n].deviation < 1e-9);
        assert_int_equal(p.panels[n].class, CLASS_FLAT);
        assert_int_equal(p.panels[n].type, TYPE_FP);
        assert_int_equal(p.panels[n].ncorners, 4);
        assert_false(p.panels[n].trimmed);
        /* 5 m x 5 m cells: the diagonal. */
        assert_true(fabs(p.panels[n].diameter - sqrt(50)) < 1e-7);
        assert_true(p.panels[n].corner_planarity < 1e-7);
    }
    assert_true(fabs(t.cost - 300 * 701) < 1e-6);
    assert_true(fabs(t.planarity) < 1e-8);
    panelization_free(&p);
    surface_close(&s);
}

static void test_areas_add_up(void **state)
{
    (void)state;
    const char *names[] = {"roof", "dome", "torus", "wave"};
    int grids[][2] = {{37, 49}, {20, 35}, {7, 3}, {40, 1}, {1, 1}};
    for (int e = 0; e < 4; e++) {
        struct surface s;
        open_example(names[e], 0, &s);
        for (int g = 0; g < 5; g++) {
            struct panelization p;
            struct option_totals t;
            evaluate(&s, grids[g][0], grids[g][1], 0.003, &p, &t);
            double sum = 0;
            for (size_t n = 0; n < p.npanels; n++)
                sum += p.panels[n].area;
            assert_true(fabs(sum - s.mesh.area) <= 1e-9 * s.mesh.area);
            assert_true(fabs(t.area - s.mesh.area) <= 1e-9 * s.mesh.area);
            assert_int_equal(t.panels, p.npanels);
            assert_int_equal(t.count[0] + t.count[1] + t.count[2],
                             p.npanels);
            panelization_free(&p);
        }
        surface_close(&s);
    }
}

/* A cylinder panel spanning angle 2a of radius r: its least-squares plane
 * lies at the arc's mean distance from the axis, r sin(a)/a, so its
 * deviation is max(r - r sin(a)/a, r sin(a)/a - r cos(a)). */
static void test_cylinder_deviation(void **state)
{
    (void)state;
    struct surface s;
    open_example("cylinder", 140, &s);
    double r = 10, span = 120 * PI / 180;
    for (int nu = 4; nu <= 24; nu += 10) {
        struct panelization p;
        struct option_totals t;
        evaluate(&s, nu, 5, 0.003, &p, &t);
        double a = span / nu / 2;
        double mean = r * sin(a) / a;
        double expected = fmax(r - mean, mean - r * cos(a));
        /* The curved direction may be u or v: find the panels along it. */
        int curved_u = p.panels[0].deviation > 1e-6;
        for (size_t n = 0; n < p.npanels; n++) {
            if (!curved_u)
                break;
            /* The mesh is a polygon of 140 chords, each off the arc by its
             * sagitta: the panel's deviation can differ by that much. */
            double sagitta = r * (1 - cos(span / 140 / 2));
            double deviation = p.panels[n].deviation;
            assert_true(fabs(deviation - expected) <
                        0.01 * expected + 2 * sagitta);
            assert_int_equal(p.panels[n].class, CLASS_RULED_CONVEX);
        }
        if (!curved_u) {
            /* Then u runs along the axis; every panel must be ruled. */
            for (size_t n = 0; n < p.npanels; n++)
                assert_int_equal(p.panels[n].class, CLASS_RULED_CONVEX);
        }
        panelization_free(&p);
    }
    surface_close(&s);
}

/* Below the sagitta every cylinder panel is ruled and SP by class (as
 * built, at t = 0.1 mm, the mesh's own facet sag may make misfits of
 * them: sp_fit.h); once the threshold exceeds the largest deviation,
 * every panel is FP. */
static void test_cylinder_threshold(void **state)
{
    (void)state;
    struct surface s;
    open_example("cylinder", 0, &s);
    struct panelization p;
    struct option_totals t;
    evaluate_typed(&s, 12, 10, 0.0001, 1, &p, &t);
    assert_int_equal(t.count[TYPE_SP], p.npanels);
    assert_int_equal(t.sp_fitted + t.sp_misfits, p.npanels);
    for (size_t n = 0; n < p.npanels; n++)
        assert_int_equal(p.panels[n].class, CLASS_RULED_CONVEX);
    double largest = t.max_deviation;
    panelization_free(&p);
    evaluate(&s, 12, 10, largest * 1.001, &p, &t);
    assert_int_equal(t.count[TYPE_FP], p.npanels);
    assert_true(fabs(t.cost - 701 * t.area) < 1e-6 * t.cost);
    panelization_free(&p);
    surface_close(&s);
}

/* The torus section: round where the tube faces out, feature-curve where
 * it faces the axis (K < 0). */
static void test_torus_outside_and_inside(void **state)
{
    (void)state;
    struct surface s;
    open_example("torus", 0, &s);
    struct panelization p;
    struct option_totals t;
    evaluate(&s, 10, 12, 0.003, &p, &t);
    size_t outside = 0, inside = 0;
    for (size_t n = 0; n < p.npanels; n++) {
        const struct panel *panel = &p.panels[n];
        const double *c = panel->centroid;
        double q = atan2(c[2], hypot(c[0], c[1]) - 20);
        if (cos(q) > 0.3) {
            assert_int_equal(panel->class, CLASS_CONVEX_ROUND);
            outside++;
        } else if (cos(q) < -0.3) {
            assert_true(panel->class == CLASS_CONVEX_FEATURE_CURVE ||
                        panel->class == CLASS_CONCAVE_FEATURE_CURVE);
            assert_true(panel->K < 0);
            inside++;
        }
    }
    assert_true(outside > 0 && inside > 0);
    panelization_free(&p);
    surface_close(&s);
}

/* Refining the mesh moves triangle edges across panel borders; panel
 * areas must not care (within 0.5 %). */
static void test_refinement_keeps_areas(void **state)
{
    (void)state;
    struct surface coarse, fine;
    open_example("roof", 100, &coarse);
    open_example("roof", 173, &fine);
    struct panelization a, b;
    struct option_totals ta, tb;
    evaluate(&coarse, 37, 49, 0.003, &a, &ta);
    evaluate(&fine, 37, 49, 0.003, &b, &tb);
    assert_int_equal(a.npanels, b.npanels);
    for (size_t n = 0; n < a.npanels; n++)
        assert_true(fabs(a.panels[n].area - b.panels[n].area) <
                    0.005 * b.panels[n].area);
    assert_true(fabs(ta.area - tb.area) < 0.005 * tb.area);
    panelization_free(&a);
    panelization_free(&b);
    surface_close(&coarse);
    surface_close(&fine);
}

static void test_dome_is_round_and_convex(void **state)
{
    (void)state;
    struct surface s;
    open_example("dome", 0, &s);
    struct panelization p;
    struct option_totals t;
    evaluate(&s, 10, 10, 0.003, &p, &t);
    for (size_t n = 0; n < p.npanels; n++) {
        assert_int_equal(p.panels[n].class, CLASS_CONVEX_ROUND);
        assert_true(p.panels[n].k1 < 0 && p.panels[n].k2 < 0);
    }
    panelization_free(&p);
    surface_close(&s);
}

/* The paper's validation: a hyperbolic paraboloid on a 5 x 5 grid has only
 * feature-curve areas, convex and concave by the sign of H. */
static void test_hypar_feature_curves(void **state)
{
    (void)state;
    struct surface s;
    open_example("hypar", 0, &s);
    struct panelization p;
    struct option_totals t;
    evaluate(&s, 5, 5, 0.003, &p, &t);
    assert_int_equal(p.npanels, 25);
    size_t convex = 0, concave = 0;
    for (size_t n = 0; n < p.npanels; n++) {
        const struct panel *panel = &p.panels[n];
        assert_true(panel->K < 0);
        assert_true(panel->class == CLASS_CONVEX_FEATURE_CURVE ||
                    panel->class == CLASS_CONCAVE_FEATURE_CURVE ||
                    panel->class == CLASS_SADDLE);
        if (panel->class == CLASS_CONVEX_FEATURE_CURVE) {
            assert_true(panel->H < 0);
            convex++;
        }
        if (panel->class == CLASS_CONCAVE_FEATURE_CURVE) {
            assert_true(panel->H > 0);
            concave++;
        }
    }
    assert_true(convex > 0 && concave > 0);
    /* For z = xy/20, H has the sign of -xy: convex where x y > 0. */
    for (size_t n = 0; n < p.npanels; n++) {
        const double *c = p.panels[n].centroid;
        if (fabs(c[0]) < 2 || fabs(c[1]) < 2 ||
            p.panels[n].class == CLASS_SADDLE)
            continue;
        assert_int_equal(p.panels[n].class, c[0] * c[1] > 0
                                                ? CLASS_CONVEX_FEATURE_CURVE
                                                : CLASS_CONCAVE_FEATURE_CURVE);
    }

    /* Forcing k1 = 0 on two panels makes them ruled. */
    p.panels[3].k1 = 0;
    p.panels[7].k1 = 0;
    struct classify_options options;
    classify_defaults(&options);
    classify_panels(&p, &options, &t);
    assert_true(p.panels[3].class == CLASS_RULED_CONVEX);
    assert_true(p.panels[7].class == CLASS_RULED_CONVEX);
    panelization_free(&p);
    surface_close(&s);
}

static void test_roof_has_every_type(void **state)
{
    (void)state;
    struct surface s;
    open_example("roof", 0, &s);
    struct panelization p;
    struct option_totals t;
    evaluate(&s, 37, 49, 0.003, &p, &t);
    assert_true(t.count[TYPE_FP] > 0);
    assert_true(t.count[TYPE_SP] > 0);
    assert_true(t.count[TYPE_DP] > 0);
    assert_true(t.feasible);
    panelization_free(&p);
    surface_close(&s);
}

static void test_bad_grid(void **state)
{
    (void)state;
    struct surface s;
    open_example("plane", 4, &s);
    struct option_params params;
    memset(&params, 0, sizeof params);
    classify_defaults(&params.classify);
    params.nu = 0;
    params.nv = 3;
    struct panelization p;
    struct option_totals t;
    struct facet_error err;
    assert_int_equal(option_evaluate(&s, &params, NULL, &p, &t, &err),
                     FACET_EINPUT);
    assert_non_null(strstr(err.message, "0x3"));
    panelization_free(&p);
    params.nu = PANEL_MAX_GRID + 1;
    assert_int_equal(option_evaluate(&s, &params, NULL, &p, &t, &err),
                     FACET_EINPUT);
    panelization_free(&p);
    surface_close(&s);
}

/* Writes a curved disc (no vt, so UV is the projection onto its plane):
 * the grid's boundary cells are trimmed panels and many are no panels. */
static void open_trimmed_disc(struct surface *s)
{
    char path[] = "/tmp/facet_test_panel_disc_XXXXXX";
    int fd = mkstemp(path);
    assert_true(fd >= 0);
    FILE *out = fdopen(fd, "w");
    enum { N = 60 };
    for (int j = 0; j <= N; j++)
        for (int i = 0; i <= N; i++) {
            double x = 10.0 * i / N - 5, y = 10.0 * j / N - 5;
            fprintf(out, "v %.17g %.17g %.17g\n", x + 1000, y + 2000,
                    0.05 * x * x - 0.02 * y * y + 0.01 * x * y);
        }
    for (int j = 0; j < N; j++)
        for (int i = 0; i < N; i++) {
            int a = j * (N + 1) + i + 1, b = a + 1, c = a + N + 1,
                d = c + 1;
            double x = 10.0 * (i + 0.5) / N - 5, y = 10.0 * (j + 0.5) / N - 5;
            if (x * x + y * y > 21)
                continue;
            fprintf(out, "f %d %d %d\nf %d %d %d\n", a, b, d, a, d, c);
        }
    fclose(out);
    struct mesh_options options = {UNITS_M, NULL, NULL};
    struct facet_error err;
    int rc = surface_open(path, &options, s, &err);
    if (rc == FACET_OK)
        rc = surface_prepare(s, 0, PARAM_AUTO, &err);
    unlink(path);
    if (rc != FACET_OK)
        fail_msg("disc: %s", err.message);
}

static void assert_close(double fast, double reference, double tolerance,
                         const char *what, const struct panel *panel)
{
    if (!(fabs(fast - reference) <= tolerance))
        fail_msg("panel (%d, %d) %s: fast %.17g, reference %.17g",
                 panel->i, panel->j, what, fast, reference);
}

/* Opens one of the surfaces the ways of measuring are compared on: an
 * example at its default resolution, or "disc", the trimmed disc. */
static void open_test_surface(const char *name, struct surface *s)
{
    if (strcmp(name, "disc") == 0)
        open_trimmed_disc(s);
    else
        open_example(name, 0, s);
}

/* Asserts that got has reference's panels, every measure to 1e-9 of its
 * scale (a sliver's judged against a triangle's area: both computations
 * round relative to the triangles they cut); returns its trimmed panels. */
static size_t assert_same_panels(const struct surface *s,
                                 const struct panelization *got,
                                 const struct panelization *reference)
{
    double triangle_area = s->mesh.area / (double)s->mesh.ntriangles;
    double triangle_uv = 0;
    for (size_t t = 0; t < s->mesh.ntriangles; t++) {
        const double *c = s->uv.uv + 6 * t;
        triangle_uv += 0.5 * fabs((c[2] - c[0]) * (c[5] - c[1]) -
                                  (c[4] - c[0]) * (c[3] - c[1]));
    }
    triangle_uv /= (double)s->mesh.ntriangles;
    int nu = reference->nu, nv = reference->nv;
    size_t trimmed = 0;
    assert_int_equal(got->npanels, reference->npanels);
    assert_memory_equal(got->cell_panel, reference->cell_panel,
                        (size_t)nu * nv * sizeof(int));
    for (size_t n = 0; n < got->npanels; n++) {
        const struct panel *f = &got->panels[n];
        const struct panel *r = &reference->panels[n];
        assert_int_equal(f->i, r->i);
        assert_int_equal(f->j, r->j);
        assert_int_equal(f->trimmed, r->trimmed);
        assert_int_equal(f->ncorners, r->ncorners);
        trimmed += (size_t)r->trimmed;
        double size = r->diameter;
        assert_true(size > 0);
        double area = fmax(r->area, triangle_area);
        /* ...and so is the plane of a sliver. */
        double tol = 1e-9 * fmax(1, triangle_area / r->area);
        assert_close(f->area, r->area, 1e-9 * area, "area", r);
        assert_close(f->uv_area, r->uv_area,
                     1e-9 * fmax(r->uv_area, triangle_uv), "uv_area", r);
        for (int x = 0; x < 3; x++) {
            assert_close(f->centroid[x], r->centroid[x], tol * size,
                         "centroid", r);
            assert_close(f->normal[x], r->normal[x], tol, "normal", r);
        }
        assert_close(f->deviation, r->deviation, tol * size, "deviation", r);
        assert_close(f->p_dist, r->p_dist, tol * area * size * size,
                     "p_dist", r);
        assert_close(f->diameter, r->diameter, tol * size, "diameter", r);
        double k = fmax(fabs(r->k1), fabs(r->k2));
        assert_close(f->k1, r->k1, tol * k + 1e-300, "k1", r);
        assert_close(f->k2, r->k2, tol * k + 1e-300, "k2", r);
    }
    return trimmed;
}

/* panels_build_fast (what option_evaluate uses: per-surface sums, only
 * crossing triangles clipped) against panels_build (every triangle
 * clipped): the same panels, every measure to 1e-9 of its scale. */
static void test_fast_matches_reference(void **state)
{
    (void)state;
    const char *names[] = {"roof", "torus", "hypar", "disc"};
    int grids[][2] = {{37, 49}, {20, 35}, {28, 32}, {7, 3}, {1, 1},
                      {90, 60}};
    for (int e = 0; e < 4; e++) {
        struct surface s;
        open_test_surface(names[e], &s);
        size_t trimmed = 0;
        for (int g = 0; g < 6; g++)
            for (int mode = 0; mode < 2; mode++) {
                struct panelization fast, reference;
                struct facet_error err;
                int nu = grids[g][0], nv = grids[g][1];
                assert_int_equal(panels_build_fast(&s.panels, mode, nu, nv,
                                                   &fast, &err), FACET_OK);
                assert_int_equal(panels_build(&s.mesh, &s.uv, &s.curvature,
                                              mode, nu, nv, &reference,
                                              &err), FACET_OK);
                trimmed += assert_same_panels(&s, &fast, &reference);
                panelization_free(&fast);
                panelization_free(&reference);
            }
        /* The disc and the torus's ends must have put the trimmed path
         * to the test. */
        if (strcmp(names[e], "disc") == 0)
            assert_true(trimmed > 0);
        surface_close(&s);
    }
}

/* panels_build_lattice (what a run over a design space uses) against
 * panels_build: every grid of three spaces on each surface, including
 * the paper's ranges and grids whose lines fall on mesh vertices. */
static void test_lattice_matches_reference(void **state)
{
    (void)state;
    const char *names[] = {"roof", "torus", "hypar", "disc"};
    int spaces[][4] = {{20, 24, 35, 38}, {1, 8, 1, 4}, {36, 40, 46, 50}};
    for (int e = 0; e < 4; e++) {
        struct surface s;
        open_test_surface(names[e], &s);
        size_t trimmed = 0;
        for (int k = 0; k < 3; k++) {
            struct panel_lattice *lattice;
            struct facet_error err;
            int *space = spaces[k];
            /* One job and three: the bands must not matter. */
            assert_int_equal(panel_lattice_build(&s.panels, space[0],
                                                 space[1], space[2], space[3],
                                                 1 + 2 * (k % 2), &lattice,
                                                 &err), FACET_OK);
            assert_non_null(lattice);
            for (int nu = space[0]; nu <= space[1]; nu++)
                for (int nv = space[2]; nv <= space[3]; nv++) {
                    struct panelization got, reference;
                    assert_int_equal(panels_build_lattice(lattice, nu, nv,
                                                          &got, &err),
                                     FACET_OK);
                    assert_int_equal(panels_build(&s.mesh, &s.uv,
                                                  &s.curvature,
                                                  PANEL_EXTREMES, nu, nv,
                                                  &reference, &err),
                                     FACET_OK);
                    trimmed += assert_same_panels(&s, &got, &reference);
                    panelization_free(&got);
                    panelization_free(&reference);
                }
            /* A grid outside the space is refused, not approximated. */
            struct panelization outside;
            assert_int_equal(panels_build_lattice(lattice, space[1] + 1,
                                                  space[2], &outside, &err),
                             FACET_EINPUT);
            panelization_free(&outside);
            panel_lattice_free(lattice);
        }
        if (strcmp(names[e], "disc") == 0)
            assert_true(trimmed > 0);
        surface_close(&s);
    }
}

/* A UV coordinate's cell as panel_internal.h's panel_cell_coordinate
 * documents it: floor((x - origin) / step), 0 below, count - 1 above. */
static int cell_of(double x, double origin, double step, int count)
{
    double f = floor((x - origin) / step);
    return !(f > 0) ? 0 : f >= count ? count - 1 : (int)f;
}

/* Every panel's k1_error and k2_error against a scan of the vertices
 * themselves, as panel_internal.h's panels_curvature_range states them:
 * triangle by triangle, vertex by vertex, C's fmax and fmin over k -+ c e
 * for every triangle whose UV box meets the panel's cell. To the bit: the
 * panels keep each triangle's extremes (panel_prep_build) and take the
 * extremes of those, which must not change one (issue 27). */
static void assert_curvature_ranges(const struct surface *s,
                                    const struct panelization *p, int mode)
{
    const struct curvature *c = &s->curvature;
    assert_non_null(c->k1_error);
    size_t np = p->npanels;
    double *o = malloc(6 * (np ? np : 1) * sizeof *o);
    assert_non_null(o);
    for (size_t n = 0; n < np; n++) {
        o[6 * n] = o[6 * n + 1] = -INFINITY;
        o[6 * n + 2] = o[6 * n + 3] = INFINITY;
        o[6 * n + 4] = o[6 * n + 5] = 0;
    }
    double du = (p->umax - p->umin) / p->nu, dv = (p->vmax - p->vmin) / p->nv;
    for (size_t t = 0; t < s->mesh.ntriangles; t++) {
        const double *uv = s->uv.uv + 6 * t;
        double u0 = fmin(uv[0], fmin(uv[2], uv[4]));
        double u1 = fmax(uv[0], fmax(uv[2], uv[4]));
        double v0 = fmin(uv[1], fmin(uv[3], uv[5]));
        double v1 = fmax(uv[1], fmax(uv[3], uv[5]));
        if (!isfinite(u0 + u1 + v0 + v1))
            continue;
        for (int j = cell_of(v0, p->vmin, dv, p->nv);
             j <= cell_of(v1, p->vmin, dv, p->nv); j++)
            for (int i = cell_of(u0, p->umin, du, p->nu);
                 i <= cell_of(u1, p->umin, du, p->nu); i++) {
                int n = p->cell_panel[(size_t)j * p->nu + i];
                if (n < 0)
                    continue;
                double *x = o + 6 * (size_t)n;
                for (int k = 0; k < 3; k++) {
                    uint32_t v = s->mesh.triangle[3 * t + k];
                    double e1 = CURVATURE_ERROR_SIGMAS * c->k1_error[v];
                    double e2 = CURVATURE_ERROR_SIGMAS * c->k2_error[v];
                    x[0] = fmax(x[0], c->k1[v] - e1);
                    x[1] = fmax(x[1], c->k1[v] + e1);
                    x[2] = fmin(x[2], c->k2[v] - e2);
                    x[3] = fmin(x[3], c->k2[v] + e2);
                    x[4] = fmax(x[4], e1);
                    x[5] = fmax(x[5], e2);
                }
            }
    }
    for (size_t n = 0; n < np; n++) {
        const struct panel *panel = &p->panels[n];
        const double *x = o + 6 * n;
        double want[4];
        if (mode == PANEL_MEAN || !(x[0] <= x[1])) {
            want[0] = want[1] = x[4];
            want[2] = want[3] = x[5];
        } else {
            want[0] = fmax(panel->k1 - x[0], 0);
            want[1] = fmax(x[1] - panel->k1, 0);
            want[2] = fmax(panel->k2 - x[2], 0);
            want[3] = fmax(x[3] - panel->k2, 0);
        }
        double got[4] = {panel->k1_error[0], panel->k1_error[1],
                         panel->k2_error[0], panel->k2_error[1]};
        if (memcmp(got, want, sizeof got) != 0)
            fail_msg("panel %zu of %dx%d (mode %d): k errors %.17g %.17g "
                     "%.17g %.17g, the vertices give %.17g %.17g %.17g %.17g",
                     n, p->nu, p->nv, mode, got[0], got[1], got[2], got[3],
                     want[0], want[1], want[2], want[3]);
    }
    free(o);
}

/* Each way of building panels (panels_build, panels_build_fast in both
 * modes, a lattice's grids) against the vertices' own curvature ranges. */
static void test_curvature_range_from_vertices(void **state)
{
    (void)state;
    const char *names[] = {"roof", "torus", "hypar", "disc"};
    int grids[][2] = {{37, 49}, {20, 35}, {7, 3}, {1, 1}};
    for (int e = 0; e < 4; e++) {
        struct surface s;
        open_test_surface(names[e], &s);
        struct facet_error err;
        for (int g = 0; g < 4; g++)
            for (int mode = 0; mode < 2; mode++) {
                struct panelization fast, reference;
                int nu = grids[g][0], nv = grids[g][1];
                assert_int_equal(panels_build_fast(&s.panels, mode, nu, nv,
                                                   &fast, &err), FACET_OK);
                assert_curvature_ranges(&s, &fast, mode);
                assert_int_equal(panels_build(&s.mesh, &s.uv, &s.curvature,
                                              mode, nu, nv, &reference,
                                              &err), FACET_OK);
                assert_curvature_ranges(&s, &reference, mode);
                panelization_free(&fast);
                panelization_free(&reference);
            }
        struct panel_lattice *lattice;
        assert_int_equal(panel_lattice_build(&s.panels, 20, 22, 35, 37, 2,
                                             &lattice, &err), FACET_OK);
        for (int nu = 20; nu <= 22; nu++)
            for (int nv = 35; nv <= 37; nv++) {
                struct panelization got;
                assert_int_equal(panels_build_lattice(lattice, nu, nv, &got,
                                                      &err), FACET_OK);
                assert_curvature_ranges(&s, &got, PANEL_EXTREMES);
                panelization_free(&got);
            }
        panel_lattice_free(lattice);
        surface_close(&s);
    }
}

/* The lattice and panels_build_fast against panels_build on real
 * surfaces from ../shared/data (FACET_DATA): a UV map from libigl
 * (igloo), harmonic parameterizations of a disk (hemisphere) and of a
 * gridshell roof (bubble), a planar-quad roof (conical1), a Rhino quad
 * grid (barrel), and the small Rhino exports (a hypar and a free-form
 * patch, quad grids, a flat grid with its own UV). (fish.obj, a 5-chart
 * atlas, is refused since a panel must not hold two charts.): irregular triangles, curved
 * trimmed boundaries, every grid of a space. */
static void test_lattice_real_surfaces(void **state)
{
    (void)state;
    const char *files[] = {"igloo.obj", "hemisphere.obj",
                           "botanic-garden-bubble-0.obj", "conical1.obj",
                           "barrel.obj", "compas_hypar.obj",
                           "compas_quadmesh.obj", "rhinomesh.obj"};
    size_t trimmed = 0, grids = 0;
    for (size_t f = 0; f < sizeof files / sizeof *files; f++) {
        char path[1024];
        if (!surface_fixture_data(files[f], path, sizeof path))
            skip();
        struct surface s;
        struct facet_error err;
        if (surface_fixture_open(path, &s, &err) != FACET_OK)
            fail_msg("%s: %s", path, err.message);
        struct panel_lattice *lattice;
        assert_int_equal(panel_lattice_build(&s.panels, 7, 12, 9, 13, 2,
                                             &lattice, &err), FACET_OK);
        assert_non_null(lattice);
        for (int nu = 7; nu <= 12; nu++)
            for (int nv = 9; nv <= 13; nv++) {
                struct panelization got, reference;
                assert_int_equal(panels_build_lattice(lattice, nu, nv, &got,
                                                      &err), FACET_OK);
                assert_int_equal(panels_build(&s.mesh, &s.uv, &s.curvature,
                                              PANEL_EXTREMES, nu, nv,
                                              &reference, &err), FACET_OK);
                trimmed += assert_same_panels(&s, &got, &reference);
                grids++;
                panelization_free(&got);
                /* And the way a single grid is measured. */
                assert_int_equal(panels_build_fast(&s.panels, PANEL_EXTREMES,
                                                   nu, nv, &got, &err),
                                 FACET_OK);
                assert_same_panels(&s, &got, &reference);
                panelization_free(&got);
                panelization_free(&reference);
            }
        panel_lattice_free(lattice);
        surface_close(&s);
    }
    assert_int_equal(grids, 8 * 30);
    assert_true(trimmed > 0);
}

/* A space whose lines cross too often gets no lattice (each grid is then
 * evaluated on its own); sides out of range are refused. */
static void test_lattice_limits(void **state)
{
    (void)state;
    struct surface s;
    open_example("hypar", 8, &s);
    struct panel_lattice *lattice = (struct panel_lattice *)&s;
    struct facet_error err;
    assert_int_equal(panel_lattice_build(&s.panels, 1, 2000, 1, 2000, 2,
                                         &lattice, &err), FACET_OK);
    assert_null(lattice);
    assert_int_equal(panel_lattice_build(&s.panels, 10, 80, 10, 80, 2,
                                         &lattice, &err), FACET_OK);
    assert_null(lattice);
    assert_int_equal(panel_lattice_build(&s.panels, 0, 3, 1, 3, 2, &lattice,
                                         &err), FACET_EINPUT);
    assert_non_null(strstr(err.message, "out of range"));
    assert_int_equal(panel_lattice_build(&s.panels, 3, 2, 1, 3, 2, &lattice,
                                         &err), FACET_EINPUT);
    assert_int_equal(panel_lattice_build(&s.panels, 1, 3, 1, 2001, 2,
                                         &lattice, &err), FACET_EINPUT);
    /* And a lattice that is built says what it holds. */
    assert_int_equal(panel_lattice_build(&s.panels, 2, 5, 3, 4, 1, &lattice,
                                         &err), FACET_OK);
    assert_non_null(lattice);
    assert_true(panel_lattice_has(lattice, 2, 4));
    assert_false(panel_lattice_has(lattice, 1, 4));
    assert_false(panel_lattice_has(lattice, 5, 5));
    assert_true(panel_lattice_bytes(lattice) > 0);
    panel_lattice_free(lattice);
    surface_close(&s);
}

/* A batch whose points share grids (only the threshold differs), given in
 * no particular order, panelizes each grid once and gives every point the
 * totals option_evaluate gives it alone, on one thread and on several. */
static void test_batch_shares_grids(void **state)
{
    (void)state;
    struct surface s;
    open_example("roof", 24, &s);
    static const struct design_point points[] = {
        {8, 6, 0}, {9, 6, 3}, {8, 6, 5}, {8, 7, 5}, {9, 6, 0}, {8, 6, 100},
        {8, 7, 0}, {9, 6, 3.5}, {8, 6, 1},
    };
    size_t n = sizeof points / sizeof points[0];
    struct option_params base;
    memset(&base, 0, sizeof base);
    base.mode = PANEL_EXTREMES;
    classify_defaults(&base.classify);
    struct option_totals alone[sizeof points / sizeof points[0]];
    for (size_t k = 0; k < n; k++) {
        struct panelization p;
        evaluate(&s, points[k].nu, points[k].nv,
                 points[k].threshold_mm / 1000, &p, &alone[k]);
        panelization_free(&p);
    }
    /* The thresholds do change the totals: the sharing is not vacuous.
     * (100 mm, which makes 10 more of this coarse roof's 8 x 6 panels FP
     * by the threshold rule; 40 mm changed them only through eps, until
     * curvature the estimate cannot tell from zero counted as zero
     * whatever t, issue 29.) */
    assert_true(alone[0].count[TYPE_FP] != alone[5].count[TYPE_FP] ||
                alone[0].count[TYPE_SP] != alone[5].count[TYPE_SP] ||
                alone[0].sp_misfits != alone[5].sp_misfits ||
                alone[0].planarity != alone[5].planarity);
    for (int jobs = 1; jobs <= 4; jobs++) {
        struct option_totals batch[sizeof points / sizeof points[0]];
        memset(batch, 0xff, sizeof batch);
        struct facet_error err;
        assert_int_equal(optimize_evaluate(&s, NULL, &base, points, n, jobs,
                                           batch, &err), FACET_OK);
        for (size_t k = 0; k < n; k++)
            assert_memory_equal(&batch[k], &alone[k], sizeof alone[k]);
    }
    surface_close(&s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_plane_panels),
        cmocka_unit_test(test_areas_add_up),
        cmocka_unit_test(test_cylinder_deviation),
        cmocka_unit_test(test_cylinder_threshold),
        cmocka_unit_test(test_torus_outside_and_inside),
        cmocka_unit_test(test_refinement_keeps_areas),
        cmocka_unit_test(test_dome_is_round_and_convex),
        cmocka_unit_test(test_hypar_feature_curves),
        cmocka_unit_test(test_roof_has_every_type),
        cmocka_unit_test(test_bad_grid),
        cmocka_unit_test(test_fast_matches_reference),
        cmocka_unit_test(test_lattice_matches_reference),
        cmocka_unit_test(test_curvature_range_from_vertices),
        cmocka_unit_test(test_lattice_real_surfaces),
        cmocka_unit_test(test_lattice_limits),
        cmocka_unit_test(test_batch_shares_grids),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
