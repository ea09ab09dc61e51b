/*
 * test_mould_jig.c: SP panels share a bending jig by their fitted surface
 * (mould.h's jigs), against answers known from the surfaces' formulas.
 *
 * The surfaces are written here from their formulas (a cylinder, a cone
 * band), their vt the formula's parameters, each cell of the panel grid
 * m x n mesh quads split into four triangles around a centre vertex, and
 * go through the real path: surface_open, surface_prepare, the evaluation
 * as built (option_evaluate, the default: SP panels fitted). The angle
 * around the axis is not proportional to u, so the panels of one row are
 * of different widths and no two columns are congruent: matched by shape
 * (the rule before jigs) they need one mould per column. The truths:
 *   - one cylinder: every panel lies on it, so one jig;
 *   - two cylinders of radii 8 and 12 m: two jigs, one a cylinder;
 *   - two cone bands of half-angles 10 and 45 degrees whose panels bend
 *     alike at their middle (cos(a) / rho the same): two jigs, one a band.
 * The brute force, independent of Facet's fits: each member's samples
 * (mould_sample_panel) against the analytic surface its representative
 * lies on, where it is (so a family is valid: all within the tolerance);
 * and, for two surfaces, the least largest distance a pattern search over
 * rigid placements finds for a panel of one on the other's analytic
 * surface, above the tolerance (so no jig can serve both).
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
#include "core/mould/mould.h"
#include "core/mould/mould_sample.h"
#include "core/surface/surface.h"
#include "tests/support/surface_fixture.h"

#define PI 3.14159265358979323846
#define TOLERANCE 0.003  /* the mould tolerance: t = 3 mm, the default */

/* An analytic surface: a cylinder about the y axis through (x0, 0, 0) of
 * radius radius, or a cone with apex (x0, 0, 0) about the y axis of
 * half-angle half_angle, its band between slant distances l0 and l1. */
struct analytic {
    int cone;
    double x0;
    double radius;                 /* cylinder (m) */
    double length;                 /* cylinder: along the axis (m) */
    double half_angle, l0, l1;     /* cone (rad, m) */
    double a0, a1;                 /* angle around the axis (rad) */
};

/* The point at parameters (s, t) in the unit square: the angle around the
 * axis goes as s^1.6, so equal steps of u are panels of growing width. */
static void analytic_point(const struct analytic *a, double s, double t,
                           double p[3])
{
    double angle = a->a0 + (a->a1 - a->a0) * pow(s, 1.6);
    if (!a->cone) {
        p[0] = a->x0 + a->radius * sin(angle);
        p[1] = a->length * t;
        p[2] = a->radius * cos(angle);
        return;
    }
    double l = a->l0 + (a->l1 - a->l0) * t;
    double rho = l * sin(a->half_angle);
    p[0] = a->x0 + rho * sin(angle);
    p[1] = l * cos(a->half_angle);
    p[2] = rho * cos(angle);
}

/* The distance of x from the analytic surface (m). */
static double analytic_distance(const struct analytic *a, const double x[3])
{
    double q[3] = {x[0] - a->x0, x[1], x[2]};
    double rho = sqrt(q[0] * q[0] + q[2] * q[2]);
    if (!a->cone)
        return fabs(rho - a->radius);
    /* In the half-plane through the axis: the ruling at half_angle. */
    double c = cos(a->half_angle), s = sin(a->half_angle);
    double along = q[1] * c + rho * s;
    if (along < 0)
        return sqrt(q[1] * q[1] + rho * rho);
    return fabs(rho * c - q[1] * s);
}

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

/* Writes surface a as nu x nv cells of mu x mv mesh quads, each split
 * into four triangles around its centre, its vt the parameters, and opens
 * and prepares it into *s. */
static void write_surface(const struct analytic *a, int nu, int nv, int mu,
                          int mv, struct surface *s)
{
    size_t size = 1 << 20, length = 0;
    char *text = malloc(size);
    assert_non_null(text);
    text[0] = 0;
    int qu = nu * mu, qv = nv * mv;
    /* Grid vertices, then the quads' centres. */
    for (int pass = 0; pass < 2; pass++)
        for (int j = 0; j <= qv - pass; j++)
            for (int i = 0; i <= qu - pass; i++) {
                double u = (i + 0.5 * pass) / qu;
                double v = (j + 0.5 * pass) / qv, p[3];
                analytic_point(a, u, v, p);
                append(&text, &length, &size,
                       "v %.17g %.17g %.17g\nvt %.17g %.17g\n", p[0], p[1],
                       p[2], u, v);
            }
    size_t centres = 1 + (size_t)(qu + 1) * (qv + 1);
    for (int j = 0; j < qv; j++)
        for (int i = 0; i < qu; i++) {
            size_t c[4] = {
                1 + (size_t)j * (qu + 1) + i,
                1 + (size_t)j * (qu + 1) + i + 1,
                1 + (size_t)(j + 1) * (qu + 1) + i + 1,
                1 + (size_t)(j + 1) * (qu + 1) + i,
            };
            size_t e = centres + (size_t)j * qu + i;
            for (int r = 0; r < 4; r++)
                append(&text, &length, &size, "f %zu/%zu %zu/%zu %zu/%zu\n",
                       c[r], c[r], c[(r + 1) % 4], c[(r + 1) % 4], e, e);
        }
    char path[] = "/tmp/facet_test_mould_jig_XXXXXX";
    int fd = mkstemp(path);
    assert_true(fd >= 0);
    FILE *out = fdopen(fd, "w");
    assert_non_null(out);
    assert_int_equal(fwrite(text, 1, length, out), length);
    assert_int_equal(fclose(out), 0);
    free(text);
    struct facet_error err;
    int rc = surface_fixture_open(path, s, &err);
    unlink(path);
    if (rc != FACET_OK)
        fail_msg("%s", err.message);
}

/* The option nu x nv at 3 mm as built, every panel of it SP and built on
 * a fit, and its families as the evaluation finds them (mould.h, with the
 * evaluation's own options) into *f. */
static void evaluate(const struct surface *s, int nu, int nv,
                     struct panelization *panels, struct mould_families *f)
{
    struct option_params base, params;
    option_params_defaults(&base);
    params = option_params_at(&base, nu, nv, 3);
    /* The zero test at 0.02 1/m: above the curvature estimator's error on
     * these meshes' rims (a cone's zero read as 0.0065: issue 29 item 1,
     * not this test's subject), far below the least curvature of any of
     * these surfaces (1/12 1/m). */
    params.classify.curvature_tol = 0.02;
    struct option_totals totals;
    struct facet_error err;
    if (option_evaluate(s, &params, NULL, panels, &totals, &err) != FACET_OK)
        fail_msg("%s", err.message);
    for (size_t n = 0; n < panels->npanels; n++) {
        const struct panel *p = &panels->panels[n];
        if (p->type != TYPE_SP || p->sp_fit.shape == PANEL_SP_NONE)
            fail_msg("panel (%d, %d): type %s (k1 %g, k2 %g, eps %g), %s "
                     "a fit (misfit %d: cylinder %g, cone %g m)", p->i,
                     p->j, panel_type_name(p->type), p->k1, p->k2,
                     p->curvature_tol,
                     p->sp_fit.shape == PANEL_SP_NONE ? "without" : "with",
                     p->misfit, p->best_cylinder, p->best_cone);
    }
    struct mould_options mould = option_mould_options(&params);
    if (mould_families_build(&s->mesh, &s->uv, panels, &mould, f, &err) !=
        FACET_OK)
        fail_msg("%s", err.message);
    /* The evaluation's own families are these. */
    assert_int_equal(totals.moulds_of[TYPE_SP], f->count[TYPE_SP]);
    for (size_t n = 0; n < panels->npanels; n++)
        assert_int_equal(panels->panels[n].mould, f->family[n]);
}

/* The brute force on one surface's families: every member's samples
 * within the tolerance of the analytic surface a its representative lies
 * on, where they are (the jig laid as the surface is). */
static void assert_members_on_surface(const struct surface *s,
                                      const struct panelization *panels,
                                      const struct analytic *a)
{
    for (size_t n = 0; n < panels->npanels; n++) {
        double x[MOULD_SAMPLES][3], worst = 0;
        assert_true(mould_sample_panel(&s->mesh, &s->uv, panels, n, x));
        for (int k = 0; k < MOULD_SAMPLES; k++)
            worst = fmax(worst, analytic_distance(a, x[k]));
        if (!(worst <= TOLERANCE))
            fail_msg("panel %zu: %.4f mm off its representative's surface",
                     n, worst * 1e3);
    }
}

/* x moved by the rigid placement q: turned by q[0], q[1], q[2] (rad)
 * about the x, y, z axes through centre, then moved by q[3..5] (m). */
static void placed(const double x[3], const double centre[3],
                   const double q[6], double out[3])
{
    double p[3] = {x[0] - centre[0], x[1] - centre[1], x[2] - centre[2]};
    for (int axis = 0; axis < 3; axis++) {
        double c = cos(q[axis]), s = sin(q[axis]);
        int i = (axis + 1) % 3, j = (axis + 2) % 3;
        double pi = c * p[i] - s * p[j], pj = s * p[i] + c * p[j];
        p[i] = pi;
        p[j] = pj;
    }
    for (int k = 0; k < 3; k++)
        out[k] = p[k] + centre[k] + q[3 + k];
}

static double placed_worst(const double (*x)[3],
                           const double centre[3], const double q[6],
                           const struct analytic *a)
{
    double worst = 0;
    for (int k = 0; k < MOULD_SAMPLES; k++) {
        double p[3];
        placed(x[k], centre, q, p);
        worst = fmax(worst, analytic_distance(a, p));
    }
    return worst;
}

/* The frame of analytic surface a at angle direction u (unit, across the
 * y axis) and distance rho from its axis: its ruling r, normal n and
 * tangent t as the columns of frame, and its point there into point. */
static void surface_frame(const struct analytic *a, const double u[3],
                          double rho, double frame[3][3], double point[3])
{
    double alpha = a->cone ? a->half_angle : 0;
    double c = cos(alpha), s = sin(alpha);
    double height = a->cone ? rho * c / s : 0;
    for (int k = 0; k < 3; k++) {
        double y = k == 1;
        frame[k][0] = c * y + s * u[k];            /* ruling */
        frame[k][1] = -s * y + c * u[k];           /* normal */
        point[k] = (k == 0 ? a->x0 : 0) + rho * u[k] + height * y;
    }
    /* tangent = ruling x normal */
    double r[3] = {frame[0][0], frame[1][0], frame[2][0]};
    double n[3] = {frame[0][1], frame[1][1], frame[2][1]};
    frame[0][2] = r[1] * n[2] - r[2] * n[1];
    frame[1][2] = r[2] * n[0] - r[0] * n[2];
    frame[2][2] = r[0] * n[1] - r[1] * n[0];
}

/* The bending curvature across the rulings of own at distance rho from
 * its axis (1/m). */
static double bending(const struct analytic *own, double rho)
{
    return own->cone ? cos(own->half_angle) / rho : 1 / own->radius;
}

/* The least largest distance of samples x, of a panel on surface own,
 * from surface a over rigid placements, by a pattern search (each of
 * three turns and three shifts stepped both ways, the step halved when
 * none helps) from the placement that lays the panel's centroid's
 * ruling, normal and tangent on a's where a bends as own does there, and
 * from 12 turns about that. A search, not a proof: it answers an upper
 * bound on the least distance, which the assertions below need above the
 * tolerance, and it finds the panel on its own surface within it (checked
 * in expect_two_jigs). */
static double least_on(const double x[MOULD_SAMPLES][3],
                       const struct analytic *a, const struct analytic *own)
{
    double centre[3] = {0, 0, 0};
    for (int k = 0; k < MOULD_SAMPLES; k++)
        for (int c = 0; c < 3; c++)
            centre[c] += x[k][c] / MOULD_SAMPLES;
    double u[3] = {centre[0] - own->x0, 0, centre[2]};
    double rho = sqrt(u[0] * u[0] + u[2] * u[2]);
    u[0] /= rho;
    u[2] /= rho;
    /* The centroid's own surface point: rho at its height on a cone. */
    double own_rho = own->cone ? centre[1] * tan(own->half_angle)
                               : own->radius;
    double to_rho = a->cone ? cos(a->half_angle) / bending(own, own_rho)
                            : a->radius;
    double from[3][3], to[3][3], p0[3], p1[3];
    surface_frame(own, u, own_rho, from, p0);
    surface_frame(a, u, to_rho, to, p1);
    double y[MOULD_SAMPLES][3], moved[3] = {0, 0, 0};
    for (int k = 0; k < MOULD_SAMPLES; k++) {
        double d[3], local[3];
        for (int c = 0; c < 3; c++)
            d[c] = x[k][c] - p0[c];
        for (int c = 0; c < 3; c++)
            local[c] = from[0][c] * d[0] + from[1][c] * d[1] +
                       from[2][c] * d[2];
        for (int c = 0; c < 3; c++) {
            y[k][c] = p1[c] + to[c][0] * local[0] + to[c][1] * local[1] +
                      to[c][2] * local[2];
            moved[c] += y[k][c] / MOULD_SAMPLES;
        }
    }
    double best = INFINITY;
    for (int start = 0; start < 13; start++) {
        double q[6] = {0, 0, 0, 0, 0, 0};
        if (start > 0)
            q[start % 3] = (start <= 6 ? 0.05 : -0.05) * (1 + start % 2);
        double here = placed_worst((const double (*)[3])y, moved, q, a);
        double step[6] = {0.02, 0.02, 0.02, 0.05, 0.05, 0.05};
        for (int round = 0; round < 200 && step[3] > 1e-7; round++) {
            int improved = 0;
            for (int c = 0; c < 6; c++)
                for (int sign = -1; sign <= 1; sign += 2) {
                    double trial[6];
                    memcpy(trial, q, sizeof trial);
                    trial[c] += sign * step[c];
                    double d = placed_worst((const double (*)[3])y, moved,
                                            trial, a);
                    if (d < here) {
                        here = d;
                        memcpy(q, trial, sizeof q);
                        improved = 1;
                    }
                }
            if (!improved)
                for (int c = 0; c < 6; c++)
                    step[c] /= 2;
        }
        best = fmin(best, here);
    }
    return best;
}

/* Two surfaces need two jigs: each on its own has one (the evaluation's
 * families); taken as one building (mould_families_build_parts), the
 * families are two, each panel with its own surface's; the members lie on
 * their representative's surface; and no placement the search finds lays
 * a panel of one surface on the other within the tolerance, while it
 * finds each on its own. */
static void expect_two_jigs(const struct analytic *patch, int nu, int nv,
                            int mu, int mv)
{
    struct surface s[2];
    struct panelization panels[2];
    struct mould_part parts[2];
    for (int k = 0; k < 2; k++) {
        struct mould_families own;
        write_surface(&patch[k], nu, nv, mu, mv, &s[k]);
        evaluate(&s[k], nu, nv, &panels[k], &own);
        assert_int_equal(own.count[TYPE_SP], 1);
        mould_families_free(&own);
        parts[k] = (struct mould_part){&s[k].mesh, &s[k].uv, &panels[k]};
    }
    struct option_params base;
    option_params_defaults(&base);
    struct option_params params = option_params_at(&base, nu, nv, 3);
    params.classify.curvature_tol = 0.02;
    struct mould_options mould = option_mould_options(&params);
    struct mould_families f;
    struct facet_error err;
    if (mould_families_build_parts(parts, 2, &mould, 1, &f, &err) != FACET_OK)
        fail_msg("%s", err.message);
    assert_int_equal(f.count[TYPE_SP], 2);
    size_t first[2] = {0, panels[0].npanels};
    for (int k = 0; k < 2; k++)
        for (size_t n = 0; n < panels[k].npanels; n++) {
            size_t r = f.representative[f.family[first[k] + n]];
            assert_int_equal(r >= first[1], k);
            double x[MOULD_SAMPLES][3], worst = 0;
            assert_true(mould_sample_panel(&s[k].mesh, &s[k].uv, &panels[k],
                                           n, x));
            for (int j = 0; j < MOULD_SAMPLES; j++)
                worst = fmax(worst, analytic_distance(&patch[k], x[j]));
            assert_true(worst <= TOLERANCE);
            double home = least_on(x, &patch[k], &patch[k]);
            double least = least_on(x, &patch[1 - k], &patch[k]);
            printf("panel %zu of surface %d: %.4f mm on its own, %.4f mm "
                   "on the other's at best found\n", n, k, home * 1e3,
                   least * 1e3);
            assert_true(home <= TOLERANCE);
            if (!(least > TOLERANCE))
                fail_msg("panel %zu of surface %d lies within %.4f mm of "
                         "the other", n, k, least * 1e3);
        }
    mould_families_free(&f);
    for (int k = 0; k < 2; k++) {
        panelization_free(&panels[k]);
        surface_close(&s[k]);
    }
}

/* A cylinder of radius 10 m, 100 degrees around and 6 m long, in 5 x 2
 * panels of widths 1.4 to 4.9 m: one jig, where the shapes need one mould
 * a column. */
static void test_cylinder_widths_one_jig(void **state)
{
    (void)state;
    struct analytic a = {0, 0, 10, 6, 0, 0, 0, -50 * PI / 180,
                         50 * PI / 180};
    struct surface s;
    write_surface(&a, 5, 2, 24, 4, &s);
    struct panelization panels;
    struct mould_families f;
    evaluate(&s, 5, 2, &panels, &f);
    assert_int_equal(f.count[TYPE_SP], 1);
    assert_int_equal(f.largest, 10);
    assert_members_on_surface(&s, &panels, &a);
    /* The panels' widths differ: no two columns are congruent. */
    struct mould_options shape = {TOLERANCE, 1, 0, NULL};
    struct mould_families by_shape;
    struct facet_error err;
    assert_int_equal(mould_families_build(&s.mesh, &s.uv, &panels, &shape,
                                          &by_shape, &err), FACET_OK);
    assert_int_equal(by_shape.count[TYPE_SP], 5);
    mould_families_free(&by_shape);
    mould_families_free(&f);
    panelization_free(&panels);
    surface_close(&s);
}

/* The same cylinder on a coarse mesh: 10 x 2 panels of one mesh quad
 * across each (0.6 to 2.8 m wide), whose facets sag 4.5 to 98 mm, far
 * over the tolerance. Each panel is built on its cylinder fitted to the
 * smooth surface (sp_fit.h), radius 10 m, so the built panels are all
 * pieces of one cylinder: one jig. Held to the facets instead, each
 * panel's sag counted against every jig and no two shared one. */
static void test_coarse_mesh_one_jig(void **state)
{
    (void)state;
    struct analytic a = {0, 0, 10, 6, 0, 0, 0, -50 * PI / 180,
                         50 * PI / 180};
    struct surface s;
    write_surface(&a, 4, 2, 2, 1, &s);
    struct panelization panels;
    struct mould_families f;
    evaluate(&s, 4, 2, &panels, &f);
    for (size_t n = 0; n < panels.npanels; n++) {
        const struct panel_sp_fit *fit = &panels.panels[n].sp_fit;
        /* the truth the count rests on: every fit is the cylinder */
        if (fit->shape != PANEL_SP_CYLINDER || !(fabs(fit->radius - 10) < 1e-3))
            fail_msg("panel %zu: fitted %s of radius %g m, not the "
                     "cylinder of 10 m", n,
                     fit->shape == PANEL_SP_CYLINDER ? "cylinder" : "cone",
                     fit->radius);
    }
    assert_int_equal(f.count[TYPE_SP], 1);
    assert_int_equal(f.largest, 8);
    mould_families_free(&f);
    panelization_free(&panels);
    surface_close(&s);
}

/* Cylinders of radii 8 and 12 m, 3 x 2 panels each of widths 2.2 to 6
 * m: two jigs. */
static void test_cylinder_two_radii(void **state)
{
    (void)state;
    struct analytic patch[2] = {
        {0, 0, 8, 6, 0, 0, 0, -45 * PI / 180, 45 * PI / 180},
        {0, 40, 12, 6, 0, 0, 0, -30 * PI / 180, 30 * PI / 180},
    };
    expect_two_jigs(patch, 3, 2, 32, 4);
}

/* Cone bands of half-angles 10 and 45 degrees, 4 m of slant each, 3
 * panels around of widths 1.2 to 3.5 m: the bands' middles at rho =
 * cos(a) / 0.24 so that the panels bend alike there; their bending
 * changes along the rulings at rates 0.24^2 tan(a) apart. Two jigs. */
static void test_cones_two_half_angles(void **state)
{
    (void)state;
    double k = 0.24;  /* cos(a) / rho at the band's middle (1/m) */
    double a1 = 10 * PI / 180, a2 = 45 * PI / 180;
    double l1 = cos(a1) / k / sin(a1), l2 = cos(a2) / k / sin(a2);
    struct analytic patch[2] = {
        {1, 0, 0, 0, a1, l1 - 2, l1 + 2, -0.9, 0.9},
        {1, 60, 0, 0, a2, l2 - 2, l2 + 2, -1.2, 1.2},
    };
    expect_two_jigs(patch, 3, 1, 32, 8);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_cylinder_widths_one_jig),
        cmocka_unit_test(test_coarse_mesh_one_jig),
        cmocka_unit_test(test_cylinder_two_radii),
        cmocka_unit_test(test_cones_two_half_angles),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
