/*
 * test_joint.c: panels as built (core/fit) and the gaps and kinks at their
 * joints (core/joint) against exact answers.
 *
 * Each surface is generated here as S(s, t) on a fine grid with vt = (s,
 * t) and goes the real way: OBJ, mesh, UV lookup, curvature, panels_build_fast,
 * classify_panels, then the fit and the joints. Tolerances come from the
 * mesh's chord error, the sag of a facet from the true surface, stated in
 * each test:
 *   - a plane: every gap and kink 0 (also trimmed panels);
 *   - a cylinder of radius R in FP panels: the kink across the rulings is
 *     Theta / nu, the gap there 2 delta sin(alpha) (derived in
 *     test_cylinder_fp_gap_and_kink), along the rulings both 0;
 *   - the cylinder in SP panels fits a cylinder within its chord error
 *     (plus the least-squares fit's own offset, see the test);
 *     a cone's panels fit a cone (apex and half-angle checked);
 *   - spherical panels forced to SP fit no cylinder or cone within t;
 *   - mirrored and rotated, the roof's results are the same;
 *   - the fast cylinder fit is the plain least-squares fit (a second
 *     minimiser) to 1 um.
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

#include "core/classify/classify.h"
#include "core/surface/coarse_mesh.h"
#include "core/fit/sp_fit.h"
#include "core/evaluate/evaluate.h"
#include "core/joint/joint.h"
#include "core/joint/joint_length.h"
#include "core/surface/example.h"
#include "core/surface/surface.h"
#include "tests/support/surface_fixture.h"

#define PI 3.14159265358979323846

/* A parametric surface: S(s, t) for (s, t) in [0, 1]^2 (m). */
typedef void (*surface_fn)(double s, double t, double p[3]);

/* A rigid motion x -> m x + shift, or a mirror when det m = -1. */
struct motion {
    double m[9];
    double shift[3];
};

static const struct motion identity = {{1, 0, 0, 0, 1, 0, 0, 0, 1},
                                       {0, 0, 0}};

/* Opens and prepares the OBJ written at path (UV from its vt), then
 * removes the file. */
static void open_written(const char *path, struct surface *out)
{
    struct facet_error err;
    struct mesh_options options = {UNITS_M, NULL, NULL};
    int rc = surface_open(path, &options, out, &err);
    if (rc == FACET_OK)
        rc = surface_prepare(out, 0, PARAM_VT, &err);
    unlink(path);
    if (rc != FACET_OK)
        fail_msg("%s", err.message);
}

/* Writes S on ns x nt quads (two triangles each, wound along S_s x S_t),
 * moved by motion, to a temporary OBJ and opens and prepares it. keep
 * (NULL: all) says which triangles to write, by the UV of their centroid:
 * a trimmed surface. */
static void open_surface(surface_fn f, int ns, int nt,
                         const struct motion *motion,
                         int (*keep)(double s, double t), struct surface *out)
{
    char path[] = "/tmp/facet_test_joint_XXXXXX";
    int fd = mkstemp(path);
    assert_true(fd >= 0);
    FILE *obj = fdopen(fd, "w");
    assert_non_null(obj);
    for (int j = 0; j <= nt; j++)
        for (int i = 0; i <= ns; i++) {
            double p[3], q[3];
            f((double)i / ns, (double)j / nt, p);
            for (int r = 0; r < 3; r++)
                q[r] = motion->m[3 * r] * p[0] + motion->m[3 * r + 1] * p[1] +
                       motion->m[3 * r + 2] * p[2] + motion->shift[r];
            fprintf(obj, "v %.17g %.17g %.17g\n", q[0], q[1], q[2]);
        }
    for (int j = 0; j <= nt; j++)
        for (int i = 0; i <= ns; i++)
            fprintf(obj, "vt %.17g %.17g\n", (double)i / ns, (double)j / nt);
    for (int j = 0; j < nt; j++)
        for (int i = 0; i < ns; i++) {
            int a = j * (ns + 1) + i + 1, b = a + 1, c = b + ns + 1,
                d = a + ns + 1;
            double s0 = (double)i / ns, t0 = (double)j / nt;
            double ds = 1.0 / ns, dt = 1.0 / nt;
            if (keep == NULL || keep(s0 + 2 * ds / 3, t0 + dt / 3))
                fprintf(obj, "f %d/%d %d/%d %d/%d\n", a, a, b, b, c, c);
            if (keep == NULL || keep(s0 + ds / 3, t0 + 2 * dt / 3))
                fprintf(obj, "f %d/%d %d/%d %d/%d\n", a, a, c, c, d, d);
        }
    fclose(obj);
    open_written(path, out);
}

/* One option of s, nu x nv, threshold t, built and measured. */
struct option {
    struct panelization panels;
    struct option_totals totals;
    struct fit_points points;
    struct cell_sides sides;
    struct built_option built;
    struct joints joints;
};

/* Panels and classes of an nu x nv grid at threshold t. */
static void panelize(const struct surface *s, int nu, int nv, double t,
                     struct option *o)
{
    struct facet_error err;
    memset(o, 0, sizeof *o);
    struct classify_options options;
    classify_defaults(&options);
    options.threshold = t;
    if (panels_build_fast(&s->panels, PANEL_EXTREMES, nu, nv, &o->panels,
                          &err) != FACET_OK)
        fail_msg("%s", err.message);
    classify_panels(&o->panels, &options, &o->totals);
}

/* The panels as built and their joints (gap limit 6 mm, kink 1 degree). */
static void build(const struct surface *s, double t, struct option *o)
{
    struct facet_error err;
    if (fit_points_build(&s->panels, &o->points, &err) != FACET_OK ||
        cell_sides_sample(&s->mesh, &s->uv, &s->curvature, &o->panels,
                          &o->sides, &err) != FACET_OK ||
        built_option_fit(&s->mesh, &o->points, &o->panels, &o->sides, t,
                         facet_sag_matters(s->facet_sag, t), &o->built,
                         &err) != FACET_OK ||
        joints_measure(&o->panels, &o->built, &o->sides, 0.006, PI / 180,
                       &o->joints, &err) != FACET_OK)
        fail_msg("%s", err.message);
}

static void option_free(struct option *o)
{
    joints_free(&o->joints);
    built_option_free(&o->built);
    cell_sides_free(&o->sides);
    fit_points_free(&o->points);
    panelization_free(&o->panels);
}

/* 1 when joint e lies on a u line (between panels i - 1 and i). */
static int across_u(const struct option *o, size_t e)
{
    return o->joints.edges[e].side <
           (size_t)(o->panels.nu + 1) * (size_t)o->panels.nv;
}

/* ---- A plane ---------------------------------------------------------- */

static void tilted_plane(double s, double t, double p[3])
{
    p[0] = 20 * s;
    p[1] = 15 * t;
    p[2] = 0.3 * p[0] - 0.2 * p[1] + 1;
}

static int cut_corner(double s, double t)
{
    return s + t <= 1.37;
}

static void check_plane(int (*keep)(double, double), size_t edges)
{
    struct surface s;
    open_surface(tilted_plane, 40, 30, &identity, keep, &s);
    struct option o;
    panelize(&s, 4, 3, 0.003, &o);
    build(&s, 0.003, &o);
    if (edges > 0)
        assert_int_equal(o.joints.nedges, edges);
    assert_true(o.joints.nedges > 0);
    size_t trimmed = 0;
    for (size_t n = 0; n < o.panels.npanels; n++) {
        assert_int_equal(o.built.panels[n].type, TYPE_FP);
        trimmed += (size_t)o.panels.panels[n].trimmed;
    }
    if (keep != NULL)
        assert_true(trimmed >= 3);
    /* Rounding only: coordinates of 20 m to 1e-16. */
    assert_true(o.joints.max_gap < 1e-9);
    assert_true(o.joints.max_kink < 1e-9);
    assert_int_equal(o.joints.gaps_over, 0);
    assert_int_equal(o.joints.kinks_over, 0);
    option_free(&o);
    surface_close(&s);
}

static void test_plane(void **state)
{
    (void)state;
    /* 4 x 3 panels: 3 x 3 joints across u, 4 x 2 across v. */
    check_plane(NULL, 17);
}

static void test_trimmed_plane(void **state)
{
    (void)state;
    check_plane(cut_corner, 0);
}

/* ---- A cylinder: R = 6 m, 90 degrees, 4 m long -------------------------- */

#define CYL_R 6.0
#define CYL_THETA (PI / 2)
#define CYL_LENGTH 4.0
#define CYL_NS 403   /* facets around, not a multiple of the panels
                        so that corners and samples fall inside facets */
#define CYL_NT 9

static void cylinder(double s, double t, double p[3])
{
    double a = -CYL_THETA / 2 + CYL_THETA * s;
    p[0] = CYL_R * sin(a);
    p[1] = CYL_LENGTH * t;
    p[2] = CYL_R * cos(a);
}

/* The cylinder in nu x nv panels at threshold t, built and measured. */
static void cylinder_option(int nu, int nv, double t, struct surface *s,
                            struct option *o)
{
    open_surface(cylinder, CYL_NS, CYL_NT, &identity, NULL, s);
    panelize(s, nu, nv, t, o);
    build(s, t, o);
}

/* The sag of one facet of the cylinder mesh from the true cylinder (m). */
static double cylinder_chord_error(void)
{
    return CYL_R * (1 - cos(CYL_THETA / CYL_NS / 2));
}

/*
 * Every panel FP (t = 20 mm, above the panels' 12.3 mm deviation). A
 * panel spans an arc of half-angle alpha = Theta / (2 nu). Its best-fit
 * plane is normal to the arc's middle radius (the direction of least
 * spread) through the arc's centroid, at R sin(alpha) / alpha from the
 * axis. A shared corner, on the cylinder at R from the axis and at angle
 * alpha from both panels' middle radii, lies R cos(alpha) along each
 * normal, so delta = R (sin(alpha)/alpha - cos(alpha)) below both planes.
 * Projected onto them it moves by delta along each panel's normal; the two
 * normals are 2 alpha apart, so the two places of the corner are 2 delta
 * sin(alpha) apart. The shared edge is a ruling, parallel to both planes,
 * so every point of it is as far: gap = 2 delta sin(alpha) (1.93 mm for R
 * = 6 m, 10 panels over 90 degrees); kink = 2 alpha = Theta / nu. Along the
 * rulings two panels share one plane: gap and kink 0.
 *
 * The mesh's facets sag by e = R (1 - cos(Theta / (2 ns))) = 0.012 mm,
 * and ns is no multiple of nu, so corners and panel edges fall inside
 * facets: each plane may sit up to e off the arc's, which moves a
 * projected corner by up to e, so the gap is held to 2 e; and it may tilt
 * by up to 2 e over the panel's width w = 2 R sin(alpha), so the kink is
 * held to 4 e / w (5e-5 rad).
 */
static void test_cylinder_fp_gap_and_kink(void **state)
{
    (void)state;
    int nu = 10, nv = 2;
    struct surface s;
    struct option o;
    cylinder_option(nu, nv, 0.02, &s, &o);
    double alpha = CYL_THETA / (2 * nu);
    double delta = CYL_R * (sin(alpha) / alpha - cos(alpha));
    double gap = 2 * delta * sin(alpha), kink = CYL_THETA / nu;
    double e = cylinder_chord_error();
    double tilt = 4 * e / (2 * CYL_R * sin(alpha));
    assert_true(fabs(gap - 0.00193) < 0.00001);  /* the 1.9 mm */
    assert_int_equal(o.panels.npanels, (size_t)(nu * nv));
    assert_int_equal(o.totals.count[TYPE_FP], o.panels.npanels);
    assert_int_equal(o.joints.nedges,
                     (size_t)((nu - 1) * nv + nu * (nv - 1)));
    double worst_gap_error = 0, worst_kink_error = 0;
    for (size_t n = 0; n < o.joints.nedges; n++) {
        const struct joint_edge *edge = &o.joints.edges[n];
        double want_gap = across_u(&o, n) ? gap : 0;
        double want_kink = across_u(&o, n) ? kink : 0;
        worst_gap_error = fmax(worst_gap_error, fabs(edge->gap - want_gap));
        worst_kink_error = fmax(worst_kink_error,
                                fabs(edge->kink - want_kink));
    }
    printf("cylinder FP: gap across the rulings %.6f mm (exact %.6f mm, "
           "worst error %.2e mm, tolerance %.2e mm); kink %.9f deg "
           "(exact %.9f, worst error %.2e rad, tolerance %.2e)\n",
           o.joints.max_gap * 1e3, gap * 1e3, worst_gap_error * 1e3,
           2 * e * 1e3, o.joints.max_kink * 180 / PI, kink * 180 / PI,
           worst_kink_error, tilt);
    assert_true(worst_gap_error <= 2 * e);
    assert_true(worst_kink_error <= tilt);
    assert_true(fabs(o.joints.mean_kink -
                     kink * (nu - 1) * nv / (double)o.joints.nedges) <= tilt);
    /* Every panel touches a joint across the rulings. */
    for (size_t n = 0; n < o.panels.npanels; n++) {
        assert_true(fabs(o.joints.worst_gap[n] - gap) <= 2 * e);
        assert_true(fabs(o.joints.worst_kink[n] - kink) <= tilt);
    }
    /* 9 degrees is over a 1 degree limit; 1.93 mm is under 6 mm. */
    assert_int_equal(o.joints.kinks_over, (size_t)((nu - 1) * nv));
    assert_int_equal(o.joints.gaps_over, 0);
    option_free(&o);
    surface_close(&s);
}

/*
 * The same cylinder at t = 3 mm: every panel is SP and must fit a
 * cylinder. The samples lie on the mesh, whose vertices are on the
 * cylinder and whose facets sag by up to e: the exact cylinder is within e
 * of every sample. The least-squares fit does not minimise the largest
 * distance, so its deviation is held to e plus how far the fitted surface
 * lies from the exact cylinder over the panel, and that to 2 e (checked
 * at 9 x 9 points of the exact surface in each cell; a narrow arc does not
 * pin its radius and axis apart, only the surface).
 * Neighbouring panels fit the true cylinder to within 2 e: the gap between
 * them is at most 4 e and the kink at most 4 e / w over the panel width w.
 */
static void test_cylinder_sp_fit(void **state)
{
    (void)state;
    int nu = 10, nv = 2;
    struct surface s;
    struct option o;
    cylinder_option(nu, nv, 0.003, &s, &o);
    double e = cylinder_chord_error();
    double w = 2 * CYL_R * sin(CYL_THETA / (2 * nu));
    assert_int_equal(o.totals.count[TYPE_SP], o.panels.npanels);
    assert_int_equal(o.built.sp_fitted, o.panels.npanels);
    assert_int_equal(o.built.sp_misfits, 0);
    double worst = 0, off = 0;
    for (size_t n = 0; n < o.panels.npanels; n++) {
        const struct built_panel *b = &o.built.panels[n];
        const struct panel *panel = &o.panels.panels[n];
        assert_int_equal(b->type, TYPE_SP);
        assert_true(b->fitted);
        assert_int_equal(b->fit.shape, DEVELOPABLE_CYLINDER);
        worst = fmax(worst, b->sp_deviation);
        for (int a = 0; a <= 8; a++)
            for (int c = 0; c <= 8; c++) {
                double p[3];
                cylinder((panel->i + a / 8.0) / nu, (panel->j + c / 8.0) / nv,
                         p);
                off = fmax(off, fabs(developable_distance(&b->fit, p)));
            }
    }
    printf("cylinder SP: largest sp_deviation %.4e mm, fit off the exact "
           "cylinder by %.2e mm (chord error e %.4e mm); gap max %.2e mm, "
           "kink max %.2e rad\n", worst * 1e3, off * 1e3, e * 1e3,
           o.joints.max_gap * 1e3, o.joints.max_kink);
    assert_true(worst <= e + off);
    assert_true(off <= 2 * e);
    assert_true(o.joints.max_gap <= 4 * e);
    assert_true(o.joints.max_kink <= 4 * e / w);
    option_free(&o);
    surface_close(&s);
}

/* ---- A cone: apex at the origin, axis z, half-angle 30 degrees ----------- */

#define CONE_HALF_ANGLE (PI / 6)
#define CONE_NS 245
#define CONE_NT 43

/* 90 degrees around, slant 4 m to 8 m from the apex. */
static void cone(double s, double t, double p[3])
{
    double phi = PI / 2 * s, slant = 4 + 4 * t;
    p[0] = slant * sin(CONE_HALF_ANGLE) * cos(phi);
    p[1] = slant * sin(CONE_HALF_ANGLE) * sin(phi);
    p[2] = slant * cos(CONE_HALF_ANGLE);
}

/*
 * 3 x 2 panels (30 degrees around, 2 m of slant): a cylinder cannot follow
 * a radius that changes by half along the panel, so each panel must fit a
 * cone, within the mesh's chord error e = r (1 - cos(pi / 4 / ns)) at the
 * widest radius r = 4 m, with its apex at the origin and its half-angle
 * 30 degrees. How close the apex is found is held to e over the sine of
 * the angle the panel's rulings span: e / sin(15 degrees / 2), a few
 * millimetres.
 */
static void test_cone_sp_fit(void **state)
{
    (void)state;
    struct surface s;
    open_surface(cone, CONE_NS, CONE_NT, &identity, NULL, &s);
    struct option o;
    panelize(&s, 3, 2, 0.003, &o);
    build(&s, 0.003, &o);
    double r = 8 * sin(CONE_HALF_ANGLE);
    double e = r * (1 - cos(PI / 2 / CONE_NS / 2));
    assert_int_equal(o.totals.count[TYPE_SP], o.panels.npanels);
    assert_int_equal(o.built.sp_fitted, o.panels.npanels);
    for (size_t n = 0; n < o.panels.npanels; n++) {
        const struct built_panel *b = &o.built.panels[n];
        assert_true(b->fitted);
        assert_int_equal(b->fit.shape, DEVELOPABLE_CONE);
        assert_true(b->best_cylinder > 0.003);
        assert_true(b->sp_deviation <= e);
        double apex[3];
        for (int k = 0; k < 3; k++)
            apex[k] = b->fit.base[k] -
                      b->fit.radius / b->fit.slope * b->fit.axis[k];
        double half = atan(fabs(b->fit.slope));
        printf("cone panel %zu: sp_deviation %.2e mm (chord error %.2e "
               "mm), best cylinder %.1f mm, apex off by %.2e m, "
               "half-angle %.6f deg\n", n, b->sp_deviation * 1e3, e * 1e3,
               b->best_cylinder * 1e3,
               sqrt(apex[0] * apex[0] + apex[1] * apex[1] +
                    apex[2] * apex[2]), half * 180 / PI);
        assert_true(sqrt(apex[0] * apex[0] + apex[1] * apex[1] +
                         apex[2] * apex[2]) <= e / sin(PI / 24));
        assert_true(fabs(half - CONE_HALF_ANGLE) <= e / 2);
    }
    option_free(&o);
    surface_close(&s);
}

/* ---- A spherical cap ----------------------------------------------------- */

static void dome(double s, double t, double p[3])
{
    example_point("dome", s, t, p);
}

/*
 * The dome (a sphere of radius 20 m) in 4 x 4 panels of 5 m: round, so DP,
 * and DP panels follow the surface: every gap and kink between them is 0.
 * Forced to SP, no panel fits a cylinder or cone within 3 mm: a cylinder
 * or cone is straight along its rulings, where the sphere sags by w^2 /
 * (8 R) = 156 mm over a panel of width w = 5 m, so the best miss by
 * several centimetres; each is built DP and says why.
 */
static void test_sphere_fits_no_cylinder(void **state)
{
    (void)state;
    struct surface s;
    open_surface(dome, 80, 80, &identity, NULL, &s);
    struct option o;
    panelize(&s, 4, 4, 0.003, &o);
    build(&s, 0.003, &o);
    assert_int_equal(o.totals.count[TYPE_DP], o.panels.npanels);
    /* Every joint counted, none sampled (two full DP panels). */
    assert_int_equal(o.joints.nedges, 3 * 4 + 4 * 3);
    for (size_t n = 0; n < o.joints.nedges; n++)
        assert_false(o.sides.sampled[o.joints.edges[n].side]);
    assert_true(o.joints.max_gap == 0);
    assert_true(o.joints.max_kink < 1e-12);
    joints_free(&o.joints);
    built_option_free(&o.built);
    cell_sides_free(&o.sides);
    fit_points_free(&o.points);
    for (size_t n = 0; n < o.panels.npanels; n++)
        o.panels.panels[n].type = TYPE_SP;
    build(&s, 0.003, &o);
    assert_int_equal(o.built.sp_fitted, 0);
    assert_int_equal(o.built.sp_misfits, o.panels.npanels);
    for (size_t n = 0; n < o.panels.npanels; n++) {
        const struct built_panel *b = &o.built.panels[n];
        assert_int_equal(b->type, TYPE_DP);
        assert_true(b->misfit);
        assert_true(b->best_cylinder > 0.01);
        assert_true(isnan(b->best_cone) || b->best_cone > 0.01);
        char reason[160];
        built_panel_reason(&o.built, n, reason, sizeof reason);
        assert_true(strncmp(reason, "no cylinder or cone within t = 3.0 mm: "
                            "best cylinder ", 52) == 0);
        if (n == 0)
            printf("sphere forced SP, panel 0: %s\n", reason);
    }
    /* A fitted or unforced panel has no reason. */
    o.built.panels[0].misfit = 0;
    char reason[160];
    built_panel_reason(&o.built, 0, reason, sizeof reason);
    assert_string_equal(reason, "");
    option_free(&o);
    surface_close(&s);
}

/* ---- Symmetry: the roof mirrored and rotated ----------------------------- */

static void roof(double s, double t, double p[3])
{
    example_point("roof", s, t, p);
}

/*
 * The roof (flat, single- and double-curved: FP, SP, DP and their joints)
 * in 24 x 32 panels on 160 x 160 quads, as generated, mirrored in x and turned by an angle
 * about an oblique axis and moved: the same panels must be built the same
 * way, with the same gaps, kinks and SP deviations. A fit stops when its
 * next step would move the surface by less than 0.1 um at the samples
 * (developable.c's FIT_STEP), so two placements of one panel may end that
 * far apart: a deviation or a gap by a few tenths of a micrometre, a
 * normal by that over the panel's 1.2 m. The test allows 1 um and 1e-6
 * rad; flat and DP panels agree to rounding.
 */
#define SYMMETRY_LENGTH 1e-6
#define SYMMETRY_ANGLE 1e-6
static void test_symmetry(void **state)
{
    (void)state;
    double c = cos(0.7), s = sin(0.7);
    /* A rotation by 0.7 rad about (1, 1, 1) / sqrt 3, then a mirror. */
    double k = (1 - c) / 3, w = s / sqrt(3);
    struct motion turned = {{c + k, k - w, k + w, k + w, c + k, k - w,
                             k - w, k + w, c + k},
                            {120, -40, 7}};
    struct motion mirrored = turned;
    for (int r = 0; r < 3; r++)
        mirrored.m[3 * r] = -mirrored.m[3 * r];
    const struct motion *motions[3] = {&identity, &turned, &mirrored};
    struct surface surface[3];
    struct option o[3];
    for (int m = 0; m < 3; m++) {
        open_surface(roof, 160, 160, motions[m], NULL, &surface[m]);
        panelize(&surface[m], 24, 32, 0.003, &o[m]);
        build(&surface[m], 0.003, &o[m]);
    }
    assert_true(o[0].totals.count[TYPE_FP] > 0);
    assert_true(o[0].built.sp_fitted > 0);
    assert_true(o[0].built.sp_misfits > 0);
    assert_true(o[0].totals.count[TYPE_DP] > 0);
    for (int m = 1; m < 3; m++) {
        assert_int_equal(o[m].joints.nedges, o[0].joints.nedges);
        assert_int_equal(o[m].built.sp_fitted, o[0].built.sp_fitted);
        assert_int_equal(o[m].built.sp_misfits, o[0].built.sp_misfits);
        double deviation = 0, gap = 0, kink = 0;
        for (size_t n = 0; n < o[0].panels.npanels; n++) {
            const struct built_panel *a = &o[0].built.panels[n];
            const struct built_panel *b = &o[m].built.panels[n];
            assert_int_equal(a->type, b->type);
            assert_int_equal(isnan(a->sp_deviation), isnan(b->sp_deviation));
            if (!isnan(a->sp_deviation))
                deviation = fmax(deviation,
                                 fabs(a->sp_deviation - b->sp_deviation));
        }
        for (size_t n = 0; n < o[0].joints.nedges; n++) {
            const struct joint_edge *a = &o[0].joints.edges[n];
            const struct joint_edge *b = &o[m].joints.edges[n];
            assert_int_equal(a->side, b->side);
            gap = fmax(gap, fabs(a->gap - b->gap));
            kink = fmax(kink, fabs(a->kink - b->kink));
        }
        printf("roof %s: sp_deviation, gap and kink differ by at most "
               "%.2e m, %.2e m, %.2e rad; max gap %.6f mm, kink %.6f deg\n",
               m == 1 ? "turned" : "mirrored", deviation, gap, kink,
               o[m].joints.max_gap * 1e3, o[m].joints.max_kink * 180 / PI);
        assert_true(deviation <= SYMMETRY_LENGTH);
        assert_true(gap <= SYMMETRY_LENGTH);
        assert_true(kink <= SYMMETRY_ANGLE);
    }
    for (int m = 0; m < 3; m++) {
        option_free(&o[m]);
        surface_close(&surface[m]);
    }
}

/* ---- The fast fit pinned to the plain least-squares fit ----------------- */

/* The cylinder d moved by p: its base across the axis by p[0], p[1] along
 * e1, e2, its axis tilted by p[2], p[3] along them, its radius by p[4]. */
static void cylinder_moved(const struct developable *d, const double e1[3],
                           const double e2[3], const double p[5],
                           struct developable *out)
{
    *out = *d;
    double length = 0;
    for (int k = 0; k < 3; k++) {
        out->base[k] += p[0] * e1[k] + p[1] * e2[k];
        out->axis[k] += p[2] * e1[k] + p[3] * e2[k];
        length += out->axis[k] * out->axis[k];
    }
    for (int k = 0; k < 3; k++)
        out->axis[k] /= sqrt(length);
    out->radius += p[4];
}

static double squares(const struct developable *d, const double *x, size_t n)
{
    double sum = 0;
    for (size_t k = 0; k < n; k++) {
        double f = developable_distance(d, x + 3 * k);
        sum += f * f;
    }
    return sum;
}

/* Solves the 5 x 5 system a x = b by Gaussian elimination with partial
 * pivoting (a and b are overwritten). */
static void solve5(double a[5][5], double b[5], double x[5])
{
    for (int c = 0; c < 5; c++) {
        int pivot = c;
        for (int r = c + 1; r < 5; r++)
            if (fabs(a[r][c]) > fabs(a[pivot][c]))
                pivot = r;
        for (int k = 0; k < 5; k++) {
            double t = a[c][k];
            a[c][k] = a[pivot][k];
            a[pivot][k] = t;
        }
        double t = b[c];
        b[c] = b[pivot];
        b[pivot] = t;
        for (int r = c + 1; r < 5; r++) {
            double f = a[r][c] / a[c][c];
            for (int k = c; k < 5; k++)
                a[r][k] -= f * a[c][k];
            b[r] -= f * b[c];
        }
    }
    for (int r = 4; r >= 0; r--) {
        x[r] = b[r];
        for (int k = r + 1; k < 5; k++)
            x[r] -= a[r][k] * x[k];
        x[r] /= a[r][r];
    }
}

/* The plain least-squares cylinder from start: Gauss-Newton on the
 * distances with a Jacobian by central differences of
 * developable_distance, each step halved until the sum of squares drops,
 * for as long as it drops (a second method: none of developable.c's
 * linearisation, damping or stopping rule). */
static void plain_cylinder_fit(const double *x, size_t n,
                               const struct developable *start,
                               struct developable *out)
{
    struct developable d = *start;
    for (int iteration = 0; iteration < 500; iteration++) {
        double e1[3], e2[3], pick[3] = {1, 0, 0};
        if (fabs(d.axis[0]) > 0.6) {
            pick[0] = 0;
            pick[1] = 1;
        }
        e1[0] = d.axis[1] * pick[2] - d.axis[2] * pick[1];
        e1[1] = d.axis[2] * pick[0] - d.axis[0] * pick[2];
        e1[2] = d.axis[0] * pick[1] - d.axis[1] * pick[0];
        double l = sqrt(e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2]);
        for (int k = 0; k < 3; k++)
            e1[k] /= l;
        e2[0] = d.axis[1] * e1[2] - d.axis[2] * e1[1];
        e2[1] = d.axis[2] * e1[0] - d.axis[0] * e1[2];
        e2[2] = d.axis[0] * e1[1] - d.axis[1] * e1[0];
        double jtj[5][5] = {{0}}, jtr[5] = {0}, h = 1e-6;
        for (size_t k = 0; k < n; k++) {
            double row[5], f = developable_distance(&d, x + 3 * k);
            for (int c = 0; c < 5; c++) {
                double p[5] = {0}, m[5] = {0};
                struct developable dp, dm;
                p[c] = h;
                m[c] = -h;
                cylinder_moved(&d, e1, e2, p, &dp);
                cylinder_moved(&d, e1, e2, m, &dm);
                row[c] = (developable_distance(&dp, x + 3 * k) -
                          developable_distance(&dm, x + 3 * k)) / (2 * h);
            }
            for (int r = 0; r < 5; r++) {
                jtr[r] -= row[r] * f;
                for (int c = 0; c < 5; c++)
                    jtj[r][c] += row[r] * row[c];
            }
        }
        double step[5], cost = squares(&d, x, n);
        solve5(jtj, jtr, step);
        struct developable trial;
        int better = 0;
        for (int halving = 0; halving < 40 && !better; halving++) {
            cylinder_moved(&d, e1, e2, step, &trial);
            better = squares(&trial, x, n) < cost;
            for (int c = 0; c < 5; c++)
                step[c] /= 2;
        }
        if (!better)
            break;
        d = trial;
    }
    *out = d;
}

/*
 * The cylinder fit starts from a Gauss-Newton step and stops when its next
 * step would move the surface by under 0.1 um (developable.c), which is
 * what makes it fast on a panel, a patch so small that its normal
 * equations are ill-conditioned. Pinned here to the plain least-squares
 * fit: on patches of the roof the size of a 37 x 49 option's panels (7 x
 * 7 points of the exact surface, single- and double-curved, so residuals
 * of up to millimetres; the flat ones fit no cylinder), the plain fit
 * started from the fast one's, moved by 0.2 mm and 0.05 degrees, must end
 * no lower in its sum of squares (but by what a last step of 0.3 um at
 * every point would gain: 1e-13 m^2 a point) and with the same
 * largest distance to 1 um, the tolerance the deviations are documented
 * to. The fit starts from the patch's two longest extents, the better
 * kept: one of them is near the rulings, as the mean ruling sp_fit starts
 * from is. (From the longest extent alone, which on the roof's
 * double-curved parts lies across the rulings, a third of the fits end
 * where the plain fit, moved by as little, finds a sum of squares 30
 * times lower: Gauss-Newton can come to rest where the residuals bend
 * the sum of squares down, as the fit did before it started from a
 * Gauss-Newton step.)
 */
static void test_fast_fit_is_the_least_squares_fit(void **state)
{
    (void)state;
    int fitted = 0;
    double worst = 0;
    for (int patch = 0; patch < 24; patch++) {
        double s0 = (patch % 6) / 6.0 + 0.02, t0 = (patch / 6) / 4.0 + 0.03;
        double x[49 * 3];
        size_t n = 0;
        for (int a = 0; a < 7; a++)
            for (int c = 0; c < 7; c++, n++)
                example_point("roof", s0 + a / 6.0 / 37, t0 + c / 6.0 / 49,
                              x + 3 * n);
        double mean[3], value[3], vector[3][3];
        developable_principal_axes(x, n, mean, value, vector);
        struct developable fast, other, plain, start;
        int have = developable_fit_cylinder(x, n, vector[2], &fast) == 0;
        if (developable_fit_cylinder(x, n, vector[1], &other) == 0 &&
            (!have || squares(&other, x, n) < squares(&fast, x, n))) {
            fast = other;
            have = 1;
        }
        if (!have)
            continue;
        fitted++;
        double e1[3] = {vector[0][0], vector[0][1], vector[0][2]};
        double e2[3] = {vector[1][0], vector[1][1], vector[1][2]};
        double moved[5] = {2e-4, -2e-4, PI / 180 / 20, 0, 2e-4};
        cylinder_moved(&fast, e1, e2, moved, &start);
        plain_cylinder_fit(x, n, &start, &plain);
        double fast_cost = squares(&fast, x, n);
        double plain_cost = squares(&plain, x, n);
        double difference = fabs(developable_max_distance(&fast, x, n) -
                                 developable_max_distance(&plain, x, n));
        worst = fmax(worst, difference);
        if (!(fast_cost <= plain_cost + (double)n * 1e-13 &&
              difference <= 1e-6))
            fail_msg("patch %d: fast fit sum of squares %.12e, plain "
                     "%.12e; largest distances differ by %.3e m", patch,
                     fast_cost, plain_cost, difference);
    }
    printf("fast cylinder fits against the plain least squares: %d "
           "patches, largest distances differ by at most %.2e m\n", fitted,
           worst);
    assert_true(fitted >= 12);
}

/* ---- A grid's fits kept across thresholds (grid_fits) ----------------- */

struct grid_tally {
    size_t options, sp, fitted, misfits, cones;
    double deviation, gap, kink;   /* largest differences (m, m, rad) */
};

/* The nu x nv grid of s classified at each threshold of t (m, in that
 * order, so that some panels turn SP, and some cylinders miss, only at a
 * later one), built and measured with one grid_fits and each option on its
 * own (cell_sides_sample + built_option_fit): the same verdict for every
 * panel, the same counts and joints, and every number the same to the bit
 * (a side's samples do not depend on which other sides are sampled:
 * cell_sides.h), so that a run that keeps a grid's fits gives what each
 * option alone gives, however its options are split among shards. */
/* 1 when a and b are the same double, NaN equal to NaN. */
static int same_number(double a, double b)
{
    return (isnan(a) && isnan(b)) || memcmp(&a, &b, sizeof a) == 0;
}

/* 1 when a and b are the same surface to the bit, field by field (the
 * struct's padding is no part of it). */
static int same_fit(const struct developable *a, const struct developable *b)
{
    int same = a->shape == b->shape && same_number(a->radius, b->radius) &&
               same_number(a->slope, b->slope);
    for (int x = 0; x < 3; x++)
        same = same && same_number(a->axis[x], b->axis[x]) &&
               same_number(a->base[x], b->base[x]);
    return same;
}

/* The sides sampled for the fits alone (cell_sides_sample_fits_stoppable,
 * what an option whose joints are not measured takes) against all of
 * them (alone_sides, cell_sides_sample's): the sides of every SP panel and
 * no other, each with the same samples to the bit, no normals, smooth
 * points only when asked; and unless alone is NULL, the panels fitted on
 * them (from points, at threshold t with smooth) the same as alone's to
 * the bit. */
static void compare_fit_sides(const struct surface *s,
                              const struct fit_points *points,
                              const struct panelization *panels, double t,
                              int smooth,
                              const struct cell_sides *alone_sides,
                              const struct built_option *alone)
{
    struct facet_error err;
    struct cell_sides sides;
    struct built_option built;
    if (cell_sides_sample_fits_stoppable(&s->mesh, &s->uv, &s->curvature,
                                         panels, smooth, NULL, &sides,
                                         &err) != FACET_OK ||
        built_option_fit(&s->mesh, points, panels, &sides, t, smooth, &built,
                         &err) != FACET_OK)
        fail_msg("%s", err.message);
    assert_null(sides.normal);
    assert_true(smooth ? sides.smooth != NULL : sides.smooth == NULL);
    assert_int_equal(sides.nsides, alone_sides->nsides);
    /* Which sides: those of an SP panel. */
    unsigned char *of_sp = calloc(sides.nsides + 1, 1);
    assert_non_null(of_sp);
    for (size_t k = 0; k < panels->npanels; k++) {
        const struct panel *panel = &panels->panels[k];
        if (panel->type != TYPE_SP)
            continue;
        of_sp[cell_side_u(&sides, panel->i, panel->j)] = 1;
        of_sp[cell_side_u(&sides, panel->i + 1, panel->j)] = 1;
        of_sp[cell_side_v(&sides, panel->i, panel->j)] = 1;
        of_sp[cell_side_v(&sides, panel->i, panel->j + 1)] = 1;
    }
    for (size_t side = 0; side < sides.nsides; side++) {
        if (sides.sampled[side] != of_sp[side])
            fail_msg("side %zu: sampled %d for the fits, of an SP panel %d",
                     side, sides.sampled[side], of_sp[side]);
        if (!sides.sampled[side])
            continue;
        assert_true(alone_sides->sampled[side]);
        size_t at = side * CELL_SIDE_SAMPLES;
        assert_memory_equal(sides.on + at, alone_sides->on + at,
                            CELL_SIDE_SAMPLES);
        assert_int_equal(sides.middle[side], alone_sides->middle[side]);
        for (size_t x = 3 * at; x < 3 * (at + CELL_SIDE_SAMPLES); x++) {
            assert_true(same_number(sides.point[x], alone_sides->point[x]));
            if (smooth)
                assert_true(same_number(sides.smooth[x],
                                        alone_sides->smooth[x]));
        }
    }
    free(of_sp);
    for (size_t k = 0; alone != NULL && k < panels->npanels; k++) {
        const struct built_panel *a = &alone->panels[k];
        const struct built_panel *b = &built.panels[k];
        if (a->type != b->type || a->fitted != b->fitted ||
            a->misfit != b->misfit ||
            !same_number(a->best_cylinder, b->best_cylinder) ||
            !same_number(a->sp_deviation, b->sp_deviation) ||
            !same_number(a->best_cone, b->best_cone) ||
            !same_number(a->bending_radius, b->bending_radius) ||
            !same_fit(&a->fit, &b->fit))
            fail_msg("panel %zu: fitted on the fits' sides, not as on all "
                     "sides", k);
    }
    if (alone != NULL) {
        assert_int_equal(built.sp_fitted, alone->sp_fitted);
        assert_int_equal(built.sp_misfits, alone->sp_misfits);
    }
    built_option_free(&built);
    cell_sides_free(&sides);
}

static void compare_grid_fits(const struct surface *s, int nu, int nv,
                              const double *t, int nt,
                              struct grid_tally *tally)
{
    struct facet_error err;
    struct fit_points points;
    struct option o;
    struct grid_fits grid;
    panelize(s, nu, nv, t[0], &o);
    if (fit_points_build(&s->panels, &points, &err) != FACET_OK ||
        grid_fits_init(&s->mesh, &s->uv, &s->curvature, &points, &o.panels,
                       &grid, &err) != FACET_OK)
        fail_msg("%s", err.message);
    for (int x = 0; x < nt; x++) {
        struct classify_options options;
        classify_defaults(&options);
        options.threshold = t[x];
        classify_panels(&o.panels, &options, &o.totals);
        struct cell_sides alone_sides, sides;
        struct built_option alone, built;
        struct joints alone_joints, joints;
        if (cell_sides_sample(&s->mesh, &s->uv, &s->curvature, &o.panels,
                              &alone_sides, &err) != FACET_OK ||
            built_option_fit(&s->mesh, &points, &o.panels, &alone_sides,
                             t[x], facet_sag_matters(s->facet_sag, t[x]),
                             &alone, &err) != FACET_OK ||
            joints_measure(&o.panels, &alone, &alone_sides, 0.006, PI / 180,
                           &alone_joints, &err) != FACET_OK ||
            grid_fits_option(&grid, &o.panels, t[x],
                             facet_sag_matters(s->facet_sag, t[x]), &built,
                             &sides, &err) != FACET_OK ||
            joints_measure(&o.panels, &built, &sides, 0.006, PI / 180,
                           &joints, &err) != FACET_OK)
            fail_msg("%s", err.message);
        tally->options++;
        int smooth = facet_sag_matters(s->facet_sag, t[x]);
        compare_fit_sides(s, &points, &o.panels, t[x], smooth, &alone_sides,
                          &alone);
        compare_fit_sides(s, &points, &o.panels, t[x], !smooth, &alone_sides,
                          NULL);
        assert_int_equal(built.sp_fitted, alone.sp_fitted);
        assert_int_equal(built.sp_misfits, alone.sp_misfits);
        for (size_t k = 0; k < o.panels.npanels; k++) {
            const struct built_panel *a = &alone.panels[k];
            const struct built_panel *b = &built.panels[k];
            if (a->type != b->type || a->fitted != b->fitted ||
                a->misfit != b->misfit)
                fail_msg("%d x %d at t = %g mm, panel %zu: built %d fitted "
                         "%d misfit %d alone, %d %d %d with the grid's "
                         "fits", nu, nv, t[x] * 1e3, k, a->type, a->fitted,
                         a->misfit, b->type, b->fitted, b->misfit);
            if (o.panels.panels[k].type != TYPE_SP)
                continue;
            tally->sp++;
            tally->fitted += (size_t)a->fitted;
            tally->misfits += (size_t)a->misfit;
            tally->cones += (size_t)!isnan(a->best_cone);
            double d = fabs(a->best_cylinder - b->best_cylinder);
            d = fmax(d, fabs(a->sp_deviation - b->sp_deviation));
            d = fmax(d, fabs(a->best_cone - b->best_cone));
            if (!same_number(a->best_cylinder, b->best_cylinder) ||
                !same_number(a->sp_deviation, b->sp_deviation) ||
                !same_number(a->best_cone, b->best_cone) ||
                !same_fit(&a->fit, &b->fit))
                fail_msg("%d x %d at t = %g mm, panel %zu: fits differ "
                         "(deviations by %.3e m)", nu, nv, t[x] * 1e3, k, d);
            if (!isnan(d))
                tally->deviation = fmax(tally->deviation, d);
        }
        assert_int_equal(joints.nedges, alone_joints.nedges);
        assert_int_equal(joints.gaps_over, alone_joints.gaps_over);
        assert_int_equal(joints.kinks_over, alone_joints.kinks_over);
        for (size_t e = 0; e < joints.nedges; e++) {
            assert_int_equal(joints.edges[e].side, alone_joints.edges[e].side);
            double gap = fabs(joints.edges[e].gap - alone_joints.edges[e].gap);
            double kink =
                fabs(joints.edges[e].kink - alone_joints.edges[e].kink);
            if (!same_number(joints.edges[e].gap, alone_joints.edges[e].gap) ||
                !same_number(joints.edges[e].kink,
                             alone_joints.edges[e].kink))
                fail_msg("%d x %d at t = %g mm, joint %zu: gaps differ by "
                         "%.3e m, kinks by %.3e rad", nu, nv, t[x] * 1e3, e,
                         gap, kink);
            tally->gap = fmax(tally->gap, gap);
            tally->kink = fmax(tally->kink, kink);
        }
        joints_free(&joints);
        joints_free(&alone_joints);
        built_option_free(&built);
        built_option_free(&alone);
        cell_sides_free(&alone_sides);
    }
    grid_fits_free(&grid);
    fit_points_free(&points);
    option_free(&o);
}

static void print_tally(const char *what, const struct grid_tally *t)
{
    printf("grid fits against each option alone, %s: %zu options, %zu SP "
           "panels (%zu fitted, %zu misfits, %zu with cones tried); "
           "largest differences %.2e m in deviation, %.2e m in gap, %.2e "
           "rad in kink\n", what, t->options, t->sp, t->fitted, t->misfits,
           t->cones, t->deviation, t->gap, t->kink);
}

/* The thresholds compared: out of order, so that the grid's fits are
 * made at several of them. */
static const double grid_thresholds[] = {0.005, 0.002, 0.0035, 0.001,
                                         0.003};

/* On the example roof (single- and double-curved, trimmed nowhere). */
static void test_grid_fits_example(void **state)
{
    (void)state;
    char path[] = "/tmp/facet_test_joint_XXXXXX";
    int fd = mkstemp(path);
    assert_true(fd >= 0);
    FILE *obj = fdopen(fd, "w");
    struct facet_error err;
    assert_int_equal(example_write("roof", 96, obj, &err), FACET_OK);
    fclose(obj);
    struct surface s;
    open_written(path, &s);
    struct grid_tally tally;
    memset(&tally, 0, sizeof tally);
    int grids[][2] = {{20, 35}, {23, 41}, {37, 49}};
    for (int g = 0; g < 3; g++)
        compare_grid_fits(&s, grids[g][0], grids[g][1], grid_thresholds,
                          5, &tally);
    print_tally("example roof", &tally);
    assert_true(tally.fitted > 0 && tally.misfits > 0 && tally.cones > 0);
    surface_close(&s);
}

/* On real surfaces from ../shared/data (FACET_DATA): irregular
 * triangles, trimmed boundaries, a conical roof. */
static void test_grid_fits_real_surfaces(void **state)
{
    (void)state;
    const char *files[] = {"conical1.obj", "barrel.obj", "hemisphere.obj",
                           "botanic-garden-bubble-0.obj", "igloo.obj"};
    struct grid_tally tally;
    memset(&tally, 0, sizeof tally);
    for (size_t f = 0; f < sizeof files / sizeof *files; f++) {
        char path[1024];
        if (!surface_fixture_data(files[f], path, sizeof path))
            skip();
        struct surface s;
        struct facet_error err;
        if (surface_fixture_open(path, &s, &err) != FACET_OK)
            fail_msg("%s: %s", path, err.message);
        int grids[][2] = {{8, 11}, {15, 13}};
        for (int g = 0; g < 2; g++)
            compare_grid_fits(&s, grids[g][0], grids[g][1], grid_thresholds,
                              5, &tally);
        surface_close(&s);
    }
    print_tally("real surfaces", &tally);
    assert_true(tally.fitted > 0 && tally.misfits > 0);
}

/* ---- Joint length (joint_length.h) -------------------------------------- */

/* The joint length of s at nu x nv. */
static double joints_of(const struct surface *s, int nu, int nv)
{
    struct option o;
    panelize(s, nu, nv, 0.003, &o);
    double length = joint_length(&s->joints, &s->mesh, &s->uv, &o.panels);
    panelization_free(&o.panels);
    return length;
}

/* The tilted plane is the parallelogram of sides W = |(20, 0, 6)| along u
 * and H = |(0, 15, -3)| along v: (nu - 1) H + (nv - 1) W + 2 (W + H). At
 * 4 x 3 the grid lines run along mesh edges (40 x 30 quads), at 7 x 5
 * through the triangles. */
static void test_joint_length_plane(void **state)
{
    (void)state;
    struct surface s;
    open_surface(tilted_plane, 40, 30, &identity, NULL, &s);
    double w = sqrt(20.0 * 20 + 6 * 6), h = sqrt(15.0 * 15 + 3 * 3);
    static const int grid[][2] = {{4, 3}, {7, 5}, {1, 1}, {13, 2}};
    for (size_t g = 0; g < sizeof grid / sizeof grid[0]; g++) {
        int nu = grid[g][0], nv = grid[g][1];
        double expect = (nu - 1) * h + (nv - 1) * w + 2 * (w + h);
        assert_float_equal(joints_of(&s, nu, nv), expect, 1e-9 * expect);
    }
    assert_float_equal(s.joints.outline, 2 * (w + h), 1e-9);
    surface_close(&s);
}

/* The cylinder (R 6 m, 90 degrees, 4 m): lines of constant angle are
 * straight, L each; lines of constant height are arcs R theta, which the
 * mesh follows as CYL_NS chords. */
static void test_joint_length_cylinder(void **state)
{
    (void)state;
    struct surface s;
    open_surface(cylinder, CYL_NS, CYL_NT, &identity, NULL, &s);
    double arc = CYL_R * CYL_THETA;
    double chords = CYL_NS * 2 * CYL_R * sin(CYL_THETA / CYL_NS / 2);
    int nu = 5, nv = 3;
    double on_mesh = (nu - 1) * CYL_LENGTH + (nv - 1) * chords +
                     2 * (CYL_LENGTH + chords);
    double smooth = (nu - 1) * CYL_LENGTH + (nv - 1) * arc +
                    2 * (CYL_LENGTH + arc);
    double length = joints_of(&s, nu, nv);
    assert_float_equal(length, on_mesh, 1e-9 * on_mesh);
    /* Short of the smooth arcs by the chords' shortfall, no more. */
    assert_true(length < smooth);
    assert_true(smooth - length <= (nv + 1) * (arc - chords) * (1 + 1e-6));
    surface_close(&s);
}

/* A disc of radius DISC_R, rings of DISC_M vertices, UV its plan. */
#define DISC_R 5.0
#define DISC_RINGS 6
#define DISC_M 96

static void open_disc(struct surface *out)
{
    char path[] = "/tmp/facet_test_disc_XXXXXX";
    int fd = mkstemp(path);
    assert_true(fd >= 0);
    FILE *obj = fdopen(fd, "w");
    assert_non_null(obj);
    fprintf(obj, "v 0 0 0\nvt 0.5 0.5\n");
    for (int r = 1; r <= DISC_RINGS; r++)
        for (int k = 0; k < DISC_M; k++) {
            double a = 2 * PI * k / DISC_M, rho = DISC_R * r / DISC_RINGS;
            double x = rho * cos(a), y = rho * sin(a);
            fprintf(obj, "v %.17g %.17g 0\nvt %.17g %.17g\n", x, y,
                    0.5 + x / (2 * DISC_R), 0.5 + y / (2 * DISC_R));
        }
    for (int k = 0; k < DISC_M; k++) {
        int a = 2 + k, b = 2 + (k + 1) % DISC_M;
        fprintf(obj, "f 1/1 %d/%d %d/%d\n", a, a, b, b);
    }
    for (int r = 1; r < DISC_RINGS; r++)
        for (int k = 0; k < DISC_M; k++) {
            int a = 2 + (r - 1) * DISC_M + k;
            int b = 2 + (r - 1) * DISC_M + (k + 1) % DISC_M;
            int c = b + DISC_M, d = a + DISC_M;
            fprintf(obj, "f %d/%d %d/%d %d/%d\nf %d/%d %d/%d %d/%d\n", a, a,
                    d, d, c, c, a, a, c, c, b, b);
        }
    fclose(obj);
    open_written(path, out);
}

/* The disc's outline is 2 pi r within the polygon's chord error; at 2 x 2
 * the two grid lines are diameters through boundary vertices, 2 r each. */
static void test_joint_length_disc(void **state)
{
    (void)state;
    struct surface s;
    open_disc(&s);
    double polygon = DISC_M * 2 * DISC_R * sin(PI / DISC_M);
    double circle = 2 * PI * DISC_R;
    assert_float_equal(joints_of(&s, 1, 1), polygon, 1e-9 * circle);
    assert_true(circle - polygon < circle * PI * PI / (6.0 * DISC_M * DISC_M));
    assert_float_equal(joints_of(&s, 2, 2), polygon + 4 * DISC_R,
                       1e-9 * circle);
    surface_close(&s);
}

/* ---- The cost terms (classify_price_terms through option_evaluate) ------ */

/* On the plane every panel is FP (no mould): the cost is the area at the
 * FP price, plus panels x panel cost, plus the joint length x joint cost,
 * all known in closed form. */
static void test_cost_terms_plane(void **state)
{
    (void)state;
    struct surface s;
    open_surface(tilted_plane, 40, 30, &identity, NULL, &s);
    struct option_params base;
    option_params_defaults(&base);
    base.classify.panel_cost = 250;
    base.classify.joint_cost = 40;
    base.classify.mould_cost[TYPE_SP] = 3000;
    base.classify.mould_cost[TYPE_DP] = 20000;
    struct option_params params = option_params_at(&base, 7, 5, 3);
    struct panelization panels;
    struct option_totals totals;
    struct facet_error err;
    if (option_evaluate(&s, &params, NULL, &panels, &totals, &err) != FACET_OK)
        fail_msg("%s", err.message);
    double w = sqrt(20.0 * 20 + 6 * 6), h = sqrt(15.0 * 15 + 3 * 3);
    double area = w * h * sqrt(1 - pow(-18 / (w * h), 2));
    double joints = 6 * h + 4 * w + 2 * (w + h);
    assert_int_equal(totals.panels, 35);
    assert_int_equal(totals.count[TYPE_FP], 35);
    assert_int_equal(totals.moulds, 0);
    assert_float_equal(totals.joint_length, joints, 1e-9 * joints);
    assert_true(totals.panel_cost == 35 * 250.0);
    assert_true(totals.joint_cost == totals.joint_length * 40);
    assert_true(totals.mould_cost == 0);
    double expect = area * 701 + 35 * 250.0 + joints * 40;
    assert_float_equal(totals.cost, expect, 1e-9 * expect);
    assert_true(totals.cost == totals.area_cost + totals.panel_cost +
                               totals.joint_cost);
    for (size_t n = 0; n < panels.npanels; n++)
        assert_int_equal(panels.panels[n].mould, -1);
    panelization_free(&panels);
    /* The terms at 0 are the paper's model: area alone, to the bit. */
    params = option_params_at(&base, 7, 5, 3);
    memset(params.classify.mould_cost, 0, sizeof params.classify.mould_cost);
    params.classify.panel_cost = params.classify.joint_cost = 0;
    if (option_evaluate(&s, &params, NULL, &panels, &totals, &err) != FACET_OK)
        fail_msg("%s", err.message);
    assert_true(totals.cost == totals.area_of[TYPE_FP] * 701);
    panelization_free(&panels);
    surface_close(&s);
}

/* Every panel of the cylinder at 5 x 3 is the same single-curved panel:
 * one mould for all 15, priced once. */
static void test_cost_terms_cylinder_moulds(void **state)
{
    (void)state;
    struct surface s;
    open_surface(cylinder, CYL_NS, CYL_NT, &identity, NULL, &s);
    struct option_params base;
    option_params_defaults(&base);
    base.classify.mould_cost[TYPE_SP] = 3000;
    base.classify.mould_cost[TYPE_DP] = 20000;
    struct option_params params = option_params_at(&base, 5, 3, 1);
    struct panelization panels;
    struct option_totals totals;
    struct facet_error err;
    if (option_evaluate(&s, &params, NULL, &panels, &totals, &err) != FACET_OK)
        fail_msg("%s", err.message);
    assert_int_equal(totals.count[TYPE_SP], 15);
    assert_int_equal(totals.moulds_of[TYPE_SP], 1);
    assert_int_equal(totals.moulds_of[TYPE_DP], 0);
    assert_int_equal(totals.largest_family, 15);
    assert_int_equal(totals.singleton_families, 0);
    assert_true(totals.mould_cost == 3000);
    assert_true(totals.cost == totals.area_cost + 3000);
    for (size_t n = 0; n < panels.npanels; n++)
        assert_int_equal(panels.panels[n].mould, 0);
    panelization_free(&panels);
    /* A negative cost is refused, naming the term. */
    params.classify.joint_cost = -1;
    assert_int_equal(option_evaluate(&s, &params, NULL, &panels, &totals, &err),
                     FACET_EINPUT);
    assert_non_null(strstr(err.message, "joint cost"));
    panelization_free(&panels);
    surface_close(&s);
}

/* "SP,DP" mould costs: two amounts, FP set to 0; anything else refused
 * naming the caller's field. */
static void test_mould_costs_parse(void **state)
{
    (void)state;
    double cost[TYPE_COUNT] = {9, 9, 9};
    struct facet_error err;
    assert_int_equal(classify_mould_costs_parse("2000,15000", "moulds", cost,
                                                &err), FACET_OK);
    assert_true(cost[TYPE_FP] == 0 && cost[TYPE_SP] == 2000 &&
                cost[TYPE_DP] == 15000);
    static const char *const bad[] = {"2000", "1,2,3", "-1,5", "a,b", "1,",
                                      "nan,1", "1,2e10"};
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++) {
        assert_int_equal(classify_mould_costs_parse(bad[k], "moulds", cost,
                                                    &err), FACET_EINPUT);
        assert_non_null(strstr(err.message, "moulds"));
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_plane),
        cmocka_unit_test(test_trimmed_plane),
        cmocka_unit_test(test_cylinder_fp_gap_and_kink),
        cmocka_unit_test(test_cylinder_sp_fit),
        cmocka_unit_test(test_cone_sp_fit),
        cmocka_unit_test(test_sphere_fits_no_cylinder),
        cmocka_unit_test(test_symmetry),
        cmocka_unit_test(test_fast_fit_is_the_least_squares_fit),
        cmocka_unit_test(test_grid_fits_example),
        cmocka_unit_test(test_grid_fits_real_surfaces),
        cmocka_unit_test(test_joint_length_plane),
        cmocka_unit_test(test_joint_length_cylinder),
        cmocka_unit_test(test_joint_length_disc),
        cmocka_unit_test(test_cost_terms_plane),
        cmocka_unit_test(test_cost_terms_cylinder_moulds),
        cmocka_unit_test(test_mould_costs_parse),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
