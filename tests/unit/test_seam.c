/*
 * test_seam: where two surfaces meet (core/project/seam.h), against
 * closed forms (issue 31 item 1): two planes hinged at a known angle,
 * with and without aligned grid lines and either winding; a box corner;
 * a cylinder cut into two faces along its rulings (no crease); faces
 * apart by less and by more than the welding tolerance. Every mesh is
 * written from its formula (surface_fixture_formula).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/evaluate/evaluate.h"
#include "core/evaluate/option.h"
#include "core/project/project_option.h"
#include "core/project/project_seams.h"
#include "core/project/seam.h"
#include "core/project/seam_joints.h"
#include "core/surface/example_skin.h"
#include "core/surface/surface.h"
#include "tests/support/seam_shapes.h"
#include "tests/support/surface_fixture.h"

#define PI 3.14159265358979323846

static void open_formula(surface_formula f, const void *shape, int ns,
                         int nt, struct surface *s)
{
    struct facet_error err;
    if (surface_fixture_formula(f, shape, ns, nt, FORMULA_TRIANGLES, s,
                                &err) != FACET_OK)
        fail_msg("formula mesh: %s", err.message);
}

static void find(const struct surface *a, const struct surface *b,
                 double weld, struct seam *seam)
{
    struct facet_error err;
    assert_int_equal(seam_find(&a->mesh, &a->curvature, &b->mesh,
                               &b->curvature, weld, 0.05, seam, &err),
                     FACET_OK);
}

/* Two planes at angle: the seam is the hinge, 1 m, and every point's
 * crease is the angle, whatever the grids and windings. */
static void hinged(double angle, int nt_b, int reversed)
{
    struct hinge h = {angle, 1.5, 0, reversed};
    struct surface a, b;
    open_formula(seam_plane_a, NULL, 8, 4, &a);
    open_formula(seam_plane_b, &h, 5, nt_b, &b);
    struct seam seam;
    find(&a, &b, SEAM_WELD_DEFAULT, &seam);
    assert_int_equal(seam.nedges, 4);  /* a's 4 edges along the hinge */
    assert_true(fabs(seam.length - 1) < 1e-12);
    assert_true(seam.npoints >= 4 * 6);
    for (size_t k = 0; k < seam.npoints; k++) {
        assert_true(fabs(seam.points[k].at[0] - 2) < 1e-12);
        for (int d = 0; d < 3; d++)
            assert_true(fabs(seam.points[k].at[d] -
                             seam.points[k].across[d]) < 1e-12);
        assert_true(fabs(seam.points[k].crease - angle) < 1e-9);
    }
    assert_true(fabs(seam.max_crease - angle) < 1e-9);
    assert_true(seam.max_apart < 1e-12);
    seam_free(&seam);
    surface_close(&a);
    surface_close(&b);
}

static void test_hinge_aligned(void **state)
{
    (void)state;
    hinged(PI / 6, 4, 0);    /* grid lines meet */
}

static void test_hinge_not_aligned(void **state)
{
    (void)state;
    hinged(PI / 6, 7, 0);    /* b's lines fall between a's */
}

static void test_hinge_wound_the_other_way(void **state)
{
    (void)state;
    hinged(PI / 6, 7, 1);    /* b's normals point the other way */
}

static void test_right_angle(void **state)
{
    (void)state;
    hinged(PI / 2, 3, 0);
}

static void test_flat_continuation(void **state)
{
    (void)state;
    hinged(0, 6, 0);         /* one plane cut in two: no crease */
}

/* Apart by 0.5 mm: a seam at a 1 mm weld, with the distance; by 5 mm:
 * none at 1 mm, one at 10 mm. */
static void test_weld_tolerance(void **state)
{
    (void)state;
    struct surface a, b, c;
    struct hinge near = {PI / 4, 1, 0.0005, 0}, far = {PI / 4, 1, 0.005, 0};
    open_formula(seam_plane_a, NULL, 8, 4, &a);
    open_formula(seam_plane_b, &near, 5, 7, &b);
    open_formula(seam_plane_b, &far, 5, 7, &c);
    struct seam seam;
    find(&a, &b, 0.001, &seam);
    assert_true(fabs(seam.length - 1) < 1e-12);
    assert_true(fabs(seam.max_apart - 0.0005) < 1e-12);
    seam_free(&seam);
    find(&a, &c, 0.001, &seam);
    assert_int_equal(seam.npoints, 0);
    assert_int_equal(seam.nedges, 0);
    assert_true(seam.length == 0);
    seam_free(&seam);
    find(&a, &c, 0.01, &seam);
    assert_true(fabs(seam.length - 1) < 1e-12);
    assert_true(fabs(seam.max_apart - 0.005) < 1e-12);
    seam_free(&seam);
    surface_close(&a);
    surface_close(&b);
    surface_close(&c);
}

/* A box corner: floor and two walls of a unit cube, each pair at 90
 * degrees along a 1 m edge; the floor and a wall share no more. */
static void floor_z0(const void *shape, double s, double t, double p[3])
{
    (void)shape;
    p[0] = s, p[1] = t, p[2] = 0;
}

static void wall_x0(const void *shape, double s, double t, double p[3])
{
    (void)shape;
    p[0] = 0, p[1] = s, p[2] = t;
}

static void wall_y0(const void *shape, double s, double t, double p[3])
{
    (void)shape;
    p[0] = t, p[1] = 0, p[2] = s;
}

static void test_box_corner(void **state)
{
    (void)state;
    struct surface face[3];
    open_formula(floor_z0, NULL, 4, 5, &face[0]);
    open_formula(wall_x0, NULL, 6, 3, &face[1]);
    open_formula(wall_y0, NULL, 3, 4, &face[2]);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            if (i == j)
                continue;
            struct seam seam;
            find(&face[i], &face[j], SEAM_WELD_DEFAULT, &seam);
            assert_true(fabs(seam.length - 1) < 1e-12);
            for (size_t k = 0; k < seam.npoints; k++)
                assert_true(fabs(seam.points[k].crease - PI / 2) < 1e-9);
            seam_free(&seam);
        }
    for (int i = 0; i < 3; i++)
        surface_close(&face[i]);
}

/* A cylinder, radius 3 m, 4 m tall, cut into two half-cylinders along two
 * rulings: the seams are the two rulings, 8 m, and the design has no
 * crease there (the facets' own angle, 180 / 12 degrees, is not one). */
static void test_cylinder_cut_along_rulings(void **state)
{
    (void)state;
    struct half first = {0}, second = {PI};
    struct surface a, b;
    open_formula(seam_half_cylinder, &first, 12, 6, &a);
    open_formula(seam_half_cylinder, &second, 12, 5, &b);
    struct seam seam;
    find(&a, &b, SEAM_WELD_DEFAULT, &seam);
    assert_true(fabs(seam.length - 8) < 1e-9);
    print_message("cylinder: largest crease %.3g deg (truth 0; a facet "
                  "angle is 15)\n", seam.max_crease * 180 / PI);
    assert_true(seam.max_crease < 1e-6);
    seam_free(&seam);
    surface_close(&a);
    surface_close(&b);
}

static void test_bad_settings(void **state)
{
    (void)state;
    struct surface a;
    open_formula(seam_plane_a, NULL, 2, 2, &a);
    struct seam seam;
    struct facet_error err;
    const double bad[] = {-1, NAN, INFINITY};
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++) {
        assert_int_equal(seam_find(&a.mesh, &a.curvature, &a.mesh,
                                   &a.curvature, bad[k], 0.05, &seam, &err),
                         FACET_EINPUT);
        assert_int_equal(seam_find(&a.mesh, &a.curvature, &a.mesh,
                                   &a.curvature, 0.001, bad[k], &seam, &err),
                         FACET_EINPUT);
        assert_int_equal(seam.npoints, 0);
    }
    surface_close(&a);
}

/* The panels of s at nu x nv and t (mm), evaluated in full. */
static void panels_of(const struct surface *s, int nu, int nv,
                      double threshold_mm, struct panelization *panels)
{
    struct option_params base;
    option_params_defaults(&base);
    struct option_params params = option_params_at(&base, nu, nv,
                                                   threshold_mm);
    params.unmeasured = 0;
    struct option_totals totals;
    struct facet_error err;
    if (option_evaluate(s, &params, NULL, panels, &totals, &err) != FACET_OK)
        fail_msg("evaluate: %s", err.message);
}

static void measure_seam(const struct surface *a,
                         const struct panelization *pa,
                         const struct surface *b,
                         const struct panelization *pb,
                         struct seam_joints *joints)
{
    struct seam seam;
    find(a, b, SEAM_WELD_DEFAULT, &seam);
    struct seam_side side_a = {&a->mesh, &a->uv, pa};
    struct seam_side side_b = {&b->mesh, &b->uv, pb};
    struct facet_error err;
    assert_int_equal(seam_joints_measure(&seam, &side_a, &side_b, 0.001,
                                         PI / 180, joints, &err),
                     FACET_OK);
    seam_free(&seam);
}

/* Flat panels on two planes hinged at 30 degrees: each panel is its
 * plane, so the seam has no gap, its kink is the design's 30 degrees and
 * the panels add nothing; 2 panels of a meet 3 of b in 4 joints. */
static void test_hinge_joints(void **state)
{
    (void)state;
    struct hinge h = {PI / 6, 1.5, 0, 1};
    struct surface a, b;
    open_formula(seam_plane_a, NULL, 8, 4, &a);
    open_formula(seam_plane_b, &h, 5, 7, &b);
    struct panelization pa, pb;
    panels_of(&a, 2, 2, 3, &pa);
    panels_of(&b, 3, 3, 3, &pb);
    struct seam_joints j;
    measure_seam(&a, &pa, &b, &pb, &j);
    assert_int_equal(j.njoints, 4);
    assert_true(j.max_gap < 1e-12);
    assert_true(fabs(j.max_kink - PI / 6) < 1e-9);
    assert_true(j.max_added < 1e-9);
    assert_true(fabs(j.max_crease - PI / 6) < 1e-9);
    assert_int_equal(j.gaps_over, 0);
    assert_int_equal(j.kinks_over, 0);
    panelization_free(&pa);
    panelization_free(&pb);
    surface_close(&a);
    surface_close(&b);
}

/* Flat panels 60 degrees wide on a cylinder (R 3 m, facets of 15
 * degrees) cut into two halves along two rulings: at each ruling one
 * joint, whose panels' planes stand at their arcs' middles, so they add
 * a kink of 60 degrees to a crease of 0; the ruling's point x (on the
 * cylinder) lands on each plane at x.n - d from it, d the plane's distance
 * from the axis (the panel's area centroid: four facets at R cos 7.5 deg
 * from the axis, turned 7.5 and 22.5 deg from the middle), so the gap is
 * |R cos 30 - d| x |n_a - n_b|, |n_a - n_b| = 2 sin 30. */
static void test_cylinder_joints(void **state)
{
    (void)state;
    struct half first = {0}, second = {PI};
    struct surface a, b;
    open_formula(seam_half_cylinder, &first, 12, 2, &a);
    open_formula(seam_half_cylinder, &second, 12, 2, &b);
    struct panelization pa, pb;
    panels_of(&a, 3, 1, 1000, &pa);
    panels_of(&b, 3, 1, 1000, &pb);
    for (size_t k = 0; k < pa.npanels; k++)
        assert_int_equal(pa.panels[k].built, TYPE_FP);
    struct seam_joints j;
    measure_seam(&a, &pa, &b, &pb, &j);
    double beta = PI / 12, alpha = PI / 3, r = 3;
    double d = r * cos(beta / 2) * (cos(beta / 2) + cos(1.5 * beta)) / 2;
    double gap = fabs(r * cos(alpha / 2) - d) * 2 * sin(alpha / 2);
    print_message("cylinder, flat panels: gap %.9f m (truth %.9f), added "
                  "kink %.9f deg (truth 60)\n", j.max_gap, gap,
                  j.max_added * 180 / PI);
    assert_int_equal(j.njoints, 2);
    assert_true(fabs(j.max_gap - gap) < 1e-9);
    assert_true(fabs(j.mean_gap - gap) < 1e-9);
    assert_true(fabs(j.max_added - alpha) < 1e-6);
    assert_int_equal(j.gaps_over, 2);
    assert_int_equal(j.kinks_over, 2);
    panelization_free(&pa);
    panelization_free(&pb);
    surface_close(&a);
    surface_close(&b);
}

/* The same halves as single-curved panels at t = 3 mm: each is built on
 * its fitted cylinder, the design's own, so the halves meet as the
 * design does, with no gap and nothing added to its crease (to the fits'
 * precision: 3e-11 mm and 4e-12 degrees were measured). */
static void test_cylinder_joints_single_curved(void **state)
{
    (void)state;
    struct half first = {0}, second = {PI};
    struct surface a, b;
    open_formula(seam_half_cylinder, &first, 48, 4, &a);
    open_formula(seam_half_cylinder, &second, 48, 4, &b);
    struct panelization pa, pb;
    panels_of(&a, 3, 2, 3, &pa);
    panels_of(&b, 4, 2, 3, &pb);
    for (size_t k = 0; k < pa.npanels; k++)
        assert_int_equal(pa.panels[k].built, TYPE_SP);
    struct seam_joints j;
    measure_seam(&a, &pa, &b, &pb, &j);
    print_message("cylinder, single-curved panels: gap %.3g mm, added "
                  "kink %.3g deg\n", j.max_gap * 1000,
                  j.max_added * 180 / PI);
    assert_int_equal(j.njoints, 4);
    assert_true(j.max_gap < 1e-9);
    assert_true(j.max_added < 1e-9);
    assert_int_equal(j.gaps_over + j.kinks_over, 0);
    panelization_free(&pa);
    panelization_free(&pb);
    surface_close(&a);
    surface_close(&b);
}

/* A building of the box corner's three faces: three seams of 1 m at 90
 * degrees; flat panels on them add nothing, and leave no gap. */
static void test_building_box_corner(void **state)
{
    (void)state;
    struct project_surface face[3];
    memset(face, 0, sizeof face);
    open_formula(floor_z0, NULL, 4, 5, &face[0].surface);
    open_formula(wall_x0, NULL, 6, 3, &face[1].surface);
    open_formula(wall_y0, NULL, 3, 4, &face[2].surface);
    struct project project;
    memset(&project, 0, sizeof project);
    project.nsurfaces = 3;
    project.surfaces = face;
    struct project_seams seams;
    struct facet_error err;
    assert_int_equal(project_seams_find(&project, SEAM_WELD_DEFAULT, NULL,
                                        &seams, &err), FACET_OK);
    assert_int_equal(seams.nseams, 3);
    struct panelization panels[3];
    const struct panelization *of[3];
    for (int k = 0; k < 3; k++) {
        panels_of(&face[k].surface, 2, 3, 3, &panels[k]);
        of[k] = &panels[k];
    }
    struct seam_totals t;
    assert_int_equal(project_seams_measure(&project, &seams, of, 0.001,
                                           PI / 180, &t, &err), FACET_OK);
    assert_int_equal(t.nseams, 3);
    assert_true(fabs(t.length - 3) < 1e-12);
    assert_true(t.njoints >= 6);
    assert_true(t.max_gap < 1e-12);
    assert_true(t.max_added < 1e-9);
    assert_true(fabs(t.max_crease - PI / 2) < 1e-9);
    assert_int_equal(t.gaps_over + t.kinks_over, 0);
    for (int k = 0; k < 3; k++) {
        panelization_free(&panels[k]);
        surface_close(&face[k].surface);
    }
    project_seams_free(&seams);
}

/* The cylinder's halves as a building, flat 60-degree panels: one seam of
 * two rulings (8 m), two joints, each with the closed form's gap and 60
 * degrees added; both over limits of 1 mm and 1 degree. */
static void test_building_cylinder(void **state)
{
    (void)state;
    struct half first = {0}, second = {PI};
    struct project_surface half[2];
    memset(half, 0, sizeof half);
    open_formula(seam_half_cylinder, &first, 12, 2, &half[0].surface);
    open_formula(seam_half_cylinder, &second, 12, 2, &half[1].surface);
    struct project project;
    memset(&project, 0, sizeof project);
    project.nsurfaces = 2;
    project.surfaces = half;
    struct project_seams seams;
    struct facet_error err;
    assert_int_equal(project_seams_find(&project, SEAM_WELD_DEFAULT, NULL,
                                        &seams, &err), FACET_OK);
    assert_int_equal(seams.nseams, 1);
    struct panelization panels[2];
    const struct panelization *of[2] = {&panels[0], &panels[1]};
    panels_of(&half[0].surface, 3, 1, 1000, &panels[0]);
    panels_of(&half[1].surface, 3, 1, 1000, &panels[1]);
    struct seam_totals t;
    assert_int_equal(project_seams_measure(&project, &seams, of, 0.001,
                                           PI / 180, &t, &err), FACET_OK);
    double beta = PI / 12, alpha = PI / 3, r = 3;
    double d = r * cos(beta / 2) * (cos(beta / 2) + cos(1.5 * beta)) / 2;
    double gap = fabs(r * cos(alpha / 2) - d) * 2 * sin(alpha / 2);
    assert_true(fabs(t.length - 8) < 1e-9);
    assert_int_equal(t.njoints, 2);
    assert_true(fabs(t.max_gap - gap) < 1e-9);
    assert_true(fabs(t.mean_gap - gap) < 1e-9);
    assert_true(fabs(t.max_added - alpha) < 1e-6);
    assert_true(fabs(t.mean_added - alpha) < 1e-6);
    assert_int_equal(t.gaps_over, 2);
    assert_int_equal(t.kinks_over, 2);
    for (int k = 0; k < 2; k++) {
        panelization_free(&panels[k]);
        surface_close(&half[k].surface);
    }
    project_seams_free(&seams);
}

/* A building's option measures its seams with its joints
 * (project_option.h): the cylinder's halves with flat 60-degree panels,
 * 3 x 1 a face. Before the project keeps its seams, and with joints not
 * measured, no seam number is known (NaN, TOTALS_UNKNOWN: never 0); once
 * kept, the seam totals are the closed form's (one seam of 8 m, two
 * joints, the gap of test_building_cylinder, 60 degrees added to no
 * crease), and the two seam joints join the building's gaps and kinks:
 * its max and mean over every joint (the faces' own, from their totals,
 * and the seams'), its joints over the limits, and a kink limit of 61
 * degrees holding the added 60, one of 59 not. */
static void test_building_option_seams(void **state)
{
    (void)state;
    struct half first = {0}, second = {PI};
    struct project_surface half[2];
    memset(half, 0, sizeof half);
    open_formula(seam_half_cylinder, &first, 12, 2, &half[0].surface);
    open_formula(seam_half_cylinder, &second, 12, 2, &half[1].surface);
    struct project project;
    memset(&project, 0, sizeof project);
    project.nsurfaces = 2;
    project.surfaces = half;
    const struct surface_grid grids[2] = {{3, 1}, {3, 1}};
    struct option_params base;
    option_params_defaults(&base);
    struct option_params params = option_params_at(&base, 3, 1, 1000);
    params.classify.max_gap = 0.001;
    params.classify.max_kink = 61 * PI / 180;
    struct facet_error err;
    struct project_option option;

    assert_int_equal(project_option_evaluate(&project, grids, &params, 1,
                                             &option, &err), FACET_OK);
    assert_true(option.totals.seams == TOTALS_UNKNOWN);
    assert_true(isnan(option.totals.seam_max_gap));
    assert_true(option.totals.seam_kinks_over == TOTALS_UNKNOWN);
    project_option_free(&option);

    assert_int_equal(project_seams_keep(&project, SEAM_WELD_DEFAULT, NULL,
                                        &err), FACET_OK);
    assert_int_equal(project.seams->nseams, 1);
    assert_int_equal(project_option_evaluate(&project, grids, &params, 1,
                                             &option, &err), FACET_OK);
    double beta = PI / 12, alpha = PI / 3, r = 3;
    double d = r * cos(beta / 2) * (cos(beta / 2) + cos(1.5 * beta)) / 2;
    double gap = fabs(r * cos(alpha / 2) - d) * 2 * sin(alpha / 2);
    const struct option_totals *t = &option.totals;
    assert_int_equal(t->seams, 1);
    assert_true(fabs(t->seam_length - 8) < 1e-9);
    assert_int_equal(option.seam_joints, 2);
    assert_true(fabs(t->seam_max_gap - gap) < 1e-9);
    assert_true(fabs(t->seam_max_kink - alpha) < 1e-6);
    assert_true(t->seam_max_crease < 1e-6);
    assert_int_equal(t->seam_gaps_over, 2);
    assert_int_equal(t->seam_kinks_over, 0);
    /* The faces' own joints, from their totals. */
    double inside = 0, max_gap = 0;
    size_t gaps_over = 0, kinks_over = 0;
    for (int k = 0; k < 2; k++) {
        const struct project_surface_option *s = &option.surfaces[k];
        inside += (double)s->joints * s->totals.mean_gap;
        max_gap = fmax(max_gap, s->totals.max_gap);
        gaps_over += s->totals.gaps_over;
        kinks_over += s->totals.kinks_over;
    }
    assert_int_equal(option.joints, 4);  /* 2 inside each face */
    double want_mean = (inside + 2 * gap) / 6;
    assert_true(fabs(t->mean_gap - want_mean) < 1e-9 * want_mean);
    assert_true(fabs(t->max_gap - fmax(max_gap, gap)) < 1e-12);
    assert_true(fabs(t->max_kink - M_PI / 3) < 1e-5 * M_PI / 180);
    assert_int_equal(t->gaps_over, gaps_over + 2);
    assert_int_equal(t->kinks_over, kinks_over);
    assert_int_equal(t->feasible, 0);  /* gaps over 1 mm */
    project_option_free(&option);

    params.classify.max_kink = 59 * PI / 180;
    assert_int_equal(project_option_evaluate(&project, grids, &params, 1,
                                             &option, &err), FACET_OK);
    assert_int_equal(option.totals.seam_kinks_over, 2);
    kinks_over = 0;
    for (int k = 0; k < 2; k++)
        kinks_over += option.surfaces[k].totals.kinks_over;
    assert_int_equal(option.totals.kinks_over, kinks_over + 2);
    project_option_free(&option);

    params.unmeasured = OPTION_MEASURE_JOINTS;
    params.classify.max_gap = params.classify.max_kink = 0;
    assert_int_equal(project_option_evaluate(&project, grids, &params, 1,
                                             &option, &err), FACET_OK);
    assert_true(option.totals.seams == TOTALS_UNKNOWN);
    assert_true(isnan(option.totals.seam_max_crease));
    project_option_free(&option);

    project_seams_free(project.seams);
    free(project.seams);
    for (int k = 0; k < 2; k++)
        surface_close(&half[k].surface);
}

/* Face *shape of the example skin, from its formula (example_skin.h). */
static void skin_face(const void *shape, double s, double t, double p[3])
{
    skin_point(*(const int *)shape, s, t, p);
}

/* The skin is one smooth tower cut into faces (its plan a rounded
 * rectangle, bulged and twisted smoothly): no seam has a crease. Six faces
 * around two four-way corners (rows 3-4, columns 3-5), 8 x 8 quads each:
 * the ends of an edge meet the other face where its outline turns, where
 * the nearest edge of the other face may run across the seam. Before the
 * winding was read at each edge's middle, some seams here read a crease
 * of 180 degrees (the other face's normal taken backwards). */
static void test_skin_has_no_crease(void **state)
{
    (void)state;
    enum { ROWS = 2, COLUMNS = 3 };
    int index[ROWS * COLUMNS];
    struct project_surface face[ROWS * COLUMNS];
    memset(face, 0, sizeof face);
    for (int r = 0; r < ROWS; r++)
        for (int c = 0; c < COLUMNS; c++) {
            int k = r * COLUMNS + c;
            index[k] = (3 + r) * SKIN_COLUMNS + 3 + c;
            open_formula(skin_face, &index[k], 8, 8, &face[k].surface);
        }
    struct project project;
    memset(&project, 0, sizeof project);
    project.nsurfaces = ROWS * COLUMNS;
    project.surfaces = face;
    struct project_seams seams;
    struct facet_error err;
    assert_int_equal(project_seams_find(&project, SEAM_WELD_DEFAULT, NULL,
                                        &seams, &err), FACET_OK);
    /* Neighbours in a row, neighbours across rows, and the diagonals
     * that touch at a corner only (a point: no seam). */
    assert_int_equal(seams.nseams, ROWS * (COLUMNS - 1) + (ROWS - 1) * COLUMNS);
    for (size_t k = 0; k < seams.nseams; k++) {
        const struct seam *x = &seams.seams[k].seam;
        if (!(x->max_crease < PI / 180))
            fail_msg("seam of faces %zu and %zu: crease %.3f deg, want 0 "
                     "(under 1 deg)", seams.seams[k].a, seams.seams[k].b,
                     x->max_crease * 180 / PI);
    }
    for (int k = 0; k < ROWS * COLUMNS; k++)
        surface_close(&face[k].surface);
    project_seams_free(&seams);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_hinge_aligned),
        cmocka_unit_test(test_hinge_not_aligned),
        cmocka_unit_test(test_hinge_wound_the_other_way),
        cmocka_unit_test(test_right_angle),
        cmocka_unit_test(test_flat_continuation),
        cmocka_unit_test(test_weld_tolerance),
        cmocka_unit_test(test_box_corner),
        cmocka_unit_test(test_cylinder_cut_along_rulings),
        cmocka_unit_test(test_bad_settings),
        cmocka_unit_test(test_hinge_joints),
        cmocka_unit_test(test_cylinder_joints),
        cmocka_unit_test(test_cylinder_joints_single_curved),
        cmocka_unit_test(test_building_box_corner),
        cmocka_unit_test(test_building_cylinder),
        cmocka_unit_test(test_building_option_seams),
        cmocka_unit_test(test_skin_has_no_crease),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
