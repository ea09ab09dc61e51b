/*
 * test_joint_normal.c: the surface normal a joint's kink reads, against
 * the analytic normal.
 *
 * The surface: the parabolic cylinder z = x^2 / 8 over 10 x 8 m (x -5..5,
 * y -4..4), 60 x 40 quads with vt. Its normal at (x, y) is (-x/4, 0, 1)
 * normalized. The vertex normals of the quadric fit were up to 0.048
 * degrees off it (the cubic term of its changing curvature taken into the
 * fit's gradient), and interpolated between vertices, so that at 7 x 5
 * panels and t = 1 mm the largest kink next to a DP panel read 0.15
 * degrees where the truth was 0.12. Here every measured joint's surface
 * normal must be within 0.001 degrees of the analytic normal at its point
 * (the joints are inside the surface; on its boundary the fit, a cubic
 * already, is good to 0.005 degrees), and every
 * joint's kink within 0.001 degrees of the kink with the analytic normal on
 * its DP side(s) (the FP and SP sides as built: plane and fitted surface).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "core/base/vec3.h"
#include "core/classify/classify.h"
#include "core/fit/sp_fit.h"
#include "core/joint/cell_sides.h"
#include "core/joint/joint.h"
#include "core/surface/coarse_mesh.h"
#include "core/surface/surface.h"
#include "tests/support/surface_fixture.h"
#include "tests/support/temp_dir.h"

#define NX 60
#define NY 40
#define PI 3.14159265358979323846
#define DEGREE (PI / 180)
#define TOLERANCE (0.001 * DEGREE)

static void write_parabola(const char *path)
{
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    for (int j = 0; j <= NY; j++)
        for (int i = 0; i <= NX; i++) {
            double x = -5 + 10.0 * i / NX, y = -4 + 8.0 * j / NY;
            fprintf(f, "v %.17g %.17g %.17g\nvt %.17g %.17g\n", x, y,
                    x * x / 8, (double)i / NX, (double)j / NY);
        }
    for (int j = 0; j < NY; j++)
        for (int i = 0; i < NX; i++) {
            int a = j * (NX + 1) + i + 1;
            fprintf(f, "f %d/%d %d/%d %d/%d %d/%d\n", a, a, a + 1, a + 1,
                    a + NX + 2, a + NX + 2, a + NX + 1, a + NX + 1);
        }
    assert_int_equal(fclose(f), 0);
}

/* The analytic unit normal of z = x^2/8 (up: the faces wind so) at the
 * surface point nearest x: a joint's sample lies on a facet, a sag below
 * the surface, and the surface point it stands for is its foot along the
 * normal (at the same x the normal differs by the sag times the slope
 * times the curvature: 6e-5 rad at 60 x 40 quads). The foot X solves
 * (X - x) + (X^2/8 - z) X/4 = 0, by Newton's method from x. */
static void analytic_normal(const double x[3], double n[3])
{
    double X = x[0];
    for (int it = 0; it < 50; it++) {
        double g = (X - x[0]) + (X * X / 8 - x[2]) * X / 4;
        double dg = 1 + (3 * X * X / 8 - x[2]) / 4;
        double step = g / dg;
        X -= step;
        if (fabs(step) < 1e-15)
            break;
    }
    n[0] = -X / 4;
    n[1] = 0;
    n[2] = 1;
    vec3_normalize(n);
}

static double angle(const double a[3], const double b[3])
{
    double c[3];
    vec3_cross(a, b, c);
    return atan2(vec3_length(c), vec3_dot(a, b));
}

/* Panel p's normal at x as built, its DP surface's the analytic one. */
static void built_normal(const struct panel *p, const struct built_panel *b,
                         const double x[3], double n[3])
{
    double truth[3];
    analytic_normal(x, truth);
    if (b->fitted) {
        developable_nearest(&b->fit, x, NULL, n);
        if (vec3_dot(n, truth) < 0)
            for (int k = 0; k < 3; k++)
                n[k] = -n[k];
    } else if (b->type == TYPE_FP) {
        memcpy(n, p->normal, 3 * sizeof *n);
    } else {
        memcpy(n, truth, 3 * sizeof *n);
    }
}

static void test_parabola_kinks(void **state)
{
    (void)state;
    char dir[256], path[512];
    assert_int_equal(temp_dir_make(dir, sizeof dir, "joint_normal"), 0);
    snprintf(path, sizeof path, "%s/parabola.obj", dir);
    write_parabola(path);
    struct surface s;
    struct facet_error err;
    if (surface_fixture_open(path, &s, &err) != FACET_OK)
        fail_msg("%s", err.message);

    struct panelization panels;
    struct classify_options options;
    struct option_totals totals;
    struct cell_sides sides;
    struct built_option built;
    struct joints joints;
    if (panels_build_fast(&s.panels, PANEL_EXTREMES, 7, 5, &panels, &err) !=
        FACET_OK)
        fail_msg("%s", err.message);
    classify_defaults(&options);
    options.threshold = 0.001;
    classify_panels(&panels, &options, &totals);
    if (cell_sides_sample(&s.mesh, &s.uv, &s.curvature, &panels, &sides,
                          &err) != FACET_OK ||
        built_option_fit(&s.mesh, &s.fit, &panels, &sides, options.threshold,
                         facet_sag_matters(s.facet_sag, options.threshold),
                         &built, &err) != FACET_OK ||
        joints_measure(&panels, &built, &sides, 1, PI, &joints, &err) !=
            FACET_OK)
        fail_msg("%s", err.message);

    /* Each joint's surface normal against the analytic one, and its kink
     * against the kink with the analytic normal on its DP side(s). */
    double worst_kink = 0, max_truth = 0, worst_normal = 0;
    size_t next_to_dp = 0, normals = 0;
    for (size_t e = 0; e < joints.nedges; e++) {
        const struct joint_edge *edge = &joints.edges[e];
        if (!sides.sampled[edge->side])
            continue;  /* between two full DP panels (0) or two FP quads */
        const double *x = sides.point +
                          3 * (edge->side * CELL_SIDE_SAMPLES +
                               (size_t)sides.middle[edge->side]);
        double n[2][3];
        int dp = 0;
        for (int k = 0; k < 2; k++) {
            uint32_t p = edge->panel[k];
            built_normal(&panels.panels[p], &built.panels[p], x, n[k]);
            dp += built.panels[p].type == TYPE_DP;
        }
        double surface[3];
        analytic_normal(x, surface);
        double off = angle(sides.normal + 3 * edge->side, surface);
        worst_normal = fmax(worst_normal, off);
        normals++;
        double truth = angle(n[0], n[1]);
        max_truth = fmax(max_truth, truth);
        if (dp > 0)
            next_to_dp++;
        worst_kink = fmax(worst_kink, fabs(edge->kink - truth));
    }
    printf("z = x^2/8, 60 x 40 quads, 7 x 5 panels, t = 1 mm: %zu joint "
           "normals within %.5f deg of the analytic; %zu joints next to DP "
           "panels; max_kink %.4f deg, truth %.4f deg; every kink within "
           "%.5f deg\n", normals, worst_normal / DEGREE, next_to_dp,
           joints.max_kink / DEGREE, max_truth / DEGREE,
           worst_kink / DEGREE);
    assert_true(normals > 0 && next_to_dp > 0);
    assert_true(worst_normal < TOLERANCE);
    assert_true(worst_kink < TOLERANCE);
    assert_true(fabs(joints.max_kink - max_truth) < TOLERANCE);

    joints_free(&joints);
    built_option_free(&built);
    cell_sides_free(&sides);
    panelization_free(&panels);
    surface_close(&s);
    temp_dir_remove(dir);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_parabola_kinks),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
