/*
 * test_tui_map_seams.c: the seam joints a building's panel map marks
 * (map_model.h's map_seams, issue 31 item 1), on buildings whose seams
 * are known by construction:
 *   - two planes hinged at 30 degrees (a: z = 0, x from 0 to 2; b bent up
 *     from the line x = 2), grid lines along the hinge not aligned (a's
 *     3 rows, b's 5): the seam is a's last column and b's first, every
 *     row of them and no other cell; flat panels are their planes, so the
 *     gap and the kink added to the crease are 0 (level 0, '=');
 *   - a cylinder (R 3 m) cut into two halves along two rulings, three flat
 *     panels of 60 degrees a half: the seams are each half's first and
 *     last column, the middle one at none; each seam joint has the closed
 *     form's gap (|R cos 30 - d| x 2 sin 30) and 60 degrees added, so it
 *     is over a gap limit of 1 mm and a kink limit of 59 degrees ('!',
 *     the highest level, as an inside joint over the limit) and under one
 *     of 61 (level 2, '=').
 * The panels come from project_option_evaluate and the joints from
 * project_option_seam_joints, as the workbench's map has them.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/evaluate/option.h"
#include "core/project/project_option.h"
#include "core/project/project_seams.h"
#include "tests/support/seam_shapes.h"
#include "tests/support/surface_fixture.h"
#include "tui/map_model.h"

#define PI 3.14159265358979323846

/* The hinge of the header: b bent up 30 degrees, 1.5 m wide. */
static const struct hinge hinge_30 = {PI / 6, 1.5, 0, 0};

static void open_formula(surface_formula f, const void *shape, int ns,
                         int nt, struct surface *s)
{
    struct facet_error err;
    if (surface_fixture_formula(f, shape, ns, nt, FORMULA_TRIANGLES, s,
                                &err) != FACET_OK)
        fail_msg("formula mesh: %s", err.message);
}

/* A building of two faces with its seams kept, evaluated at grids with
 * joints measured and the limits max_gap (m) and max_kink (rad); its seam
 * joints into *joints, *n. */
static void building(struct project *project, struct project_surface *face,
                     const struct surface_grid grids[2], double max_gap,
                     double max_kink, struct project_option *option,
                     struct building_seam_joint **joints, size_t *n)
{
    memset(project, 0, sizeof *project);
    project->nsurfaces = 2;
    project->surfaces = face;
    struct facet_error err;
    assert_int_equal(project_seams_keep(project, SEAM_WELD_DEFAULT, NULL,
                                        &err), FACET_OK);
    assert_non_null(project->seams);
    assert_int_equal(project->seams->nseams, 1);
    struct option_params base;
    option_params_defaults(&base);
    struct option_params params = option_params_at(&base, 1, 1, 1000);
    params.unmeasured = 0;
    params.classify.max_gap = max_gap;
    params.classify.max_kink = max_kink;
    assert_int_equal(project_option_evaluate(project, grids, &params, 1,
                                             option, &err), FACET_OK);
    assert_int_equal(project_option_seam_joints(project, option, joints, n,
                                                &err), FACET_OK);
    assert_int_equal(*n, option->seam_joints);
}

static void building_free(struct project *project,
                          struct project_surface *face,
                          struct project_option *option,
                          struct building_seam_joint *joints)
{
    free(joints);
    project_option_free(option);
    project_seams_free(project->seams);
    free(project->seams);
    for (int k = 0; k < 2; k++)
        surface_close(&face[k].surface);
}

/* 1 when panel k of p is in a column of columns[0..n). */
static int in_column(const struct panelization *p, size_t k,
                     const int *columns, int n)
{
    for (int c = 0; c < n; c++)
        if (p->panels[k].i == columns[c])
            return 1;
    return 0;
}

/* Surface s's seams mark exactly the panels of the given columns, each
 * with gap and added kink within tol of gap and added (m, rad); and in a
 * picture of a character per cell, exactly their characters, at level. */
static void check_surface(const struct project_option *option,
                          const struct building_seam_joint *joints, size_t n,
                          size_t s, const int *columns, int ncolumns,
                          double gap, double added, double tol,
                          enum map_colour colour, double limit, int level)
{
    const struct panelization *p = &option->surfaces[s].panels;
    struct map_seams seams;
    assert_int_equal(map_seams_of_surface(joints, n, s, p->npanels, &seams),
                     0);
    size_t marked = 0;
    for (size_t k = 0; k < p->npanels; k++) {
        int want = in_column(p, k, columns, ncolumns);
        assert_int_equal(!isnan(seams.gap[k]), want);
        assert_int_equal(!isnan(seams.added[k]), want);
        if (!want)
            continue;
        marked++;
        assert_true(fabs(seams.gap[k] - gap) <= tol);
        assert_true(fabs(seams.added[k] - added) <= tol);
    }
    assert_int_equal(marked, (size_t)(ncolumns * p->nv));
    assert_true(seams.joints >= marked);
    double bound[MAP_LEVELS];
    map_level_bounds(limit, 0, bound);
    for (int r = 0; r < p->nv; r++)
        for (int c = 0; c < p->nu; c++) {
            int at = 0;
            for (int k = 0; k < ncolumns; k++)
                at |= c == columns[k];
            int got = map_seam_cell_level(p, &seams, p->nu, p->nv, c, r,
                                          colour, bound);
            assert_int_equal(got, at ? level : -1);
            /* by type a character shows its panels, never a seam */
            assert_int_equal(map_seam_cell_level(p, &seams, p->nu, p->nv,
                                                 c, r, MAP_BY_TYPE, bound),
                             -1);
        }
    /* fitted into one character, the share's worst seam joint */
    assert_int_equal(map_seam_cell_level(p, &seams, 1, 1, 0, 0, colour,
                                         bound), level);
    map_seams_free(&seams);
}

static void test_hinge(void **state)
{
    (void)state;
    struct project_surface face[2];
    memset(face, 0, sizeof face);
    open_formula(seam_plane_a, NULL, 8, 6, &face[0].surface);
    open_formula(seam_plane_b, &hinge_30, 6, 10, &face[1].surface);
    const struct surface_grid grids[2] = {{4, 3}, {3, 5}};
    struct project project;
    struct project_option option;
    struct building_seam_joint *joints;
    size_t n;
    building(&project, face, grids, 0.001, PI / 180, &option, &joints, &n);
    /* a's 3 rows meet b's 5: a joint wherever two of their rows overlap,
     * 3 + 5 - 1 when no row lines meet (thirds against fifths) */
    assert_int_equal(n, 7);
    int last = 3, first = 0;
    check_surface(&option, joints, n, 0, &last, 1, 0, 0, 1e-9, MAP_BY_GAP,
                  1, 0);
    check_surface(&option, joints, n, 1, &first, 1, 0, 0, 1e-9, MAP_BY_KINK,
                  1, 0);
    assert_int_equal(map_seam_glyph(0), '=');
    building_free(&project, face, &option, joints);
}

static void test_cylinder(void **state)
{
    (void)state;
    struct half from[2] = {{0}, {PI}};
    struct project_surface face[2];
    memset(face, 0, sizeof face);
    for (int k = 0; k < 2; k++)
        open_formula(seam_half_cylinder, &from[k], 12, 2, &face[k].surface);
    const struct surface_grid grids[2] = {{3, 1}, {3, 1}};
    double beta = PI / 12, alpha = PI / 3, r = 3;
    double d = r * cos(beta / 2) * (cos(beta / 2) + cos(1.5 * beta)) / 2;
    double gap = fabs(r * cos(alpha / 2) - d) * 2 * sin(alpha / 2);
    const int ends[2] = {0, 2};
    struct project project;
    struct project_option option;
    struct building_seam_joint *joints;
    size_t n;
    building(&project, face, grids, 0.001, 59 * PI / 180, &option, &joints,
             &n);
    assert_int_equal(n, 2);
    for (size_t s = 0; s < 2; s++) {
        /* gap 0.25 m over 1 mm, 60 degrees added over 59: the top */
        check_surface(&option, joints, n, s, ends, 2, gap, alpha, 1e-6,
                      MAP_BY_GAP, 1, MAP_LEVELS - 1);
        check_surface(&option, joints, n, s, ends, 2, gap, alpha, 1e-6,
                      MAP_BY_KINK, 59, MAP_LEVELS - 1);
        /* under a limit of 61: above 3/4 of it, level 2 */
        check_surface(&option, joints, n, s, ends, 2, gap, alpha, 1e-6,
                      MAP_BY_KINK, 61, 2);
    }
    assert_int_equal(map_seam_glyph(MAP_LEVELS - 1), '!');
    assert_int_equal(map_seam_glyph(2), '=');
    building_free(&project, face, &option, joints);
}

/* A joint list naming another surface, or a panel out of range, marks
 * nothing; a colouring other than gap or kink has no seam measure. */
static void test_other_surfaces(void **state)
{
    (void)state;
    struct building_seam_joint j[2];
    memset(j, 0, sizeof j);
    j[0].a = 1, j[0].b = 2, j[0].joint.panel_a = 0, j[0].joint.panel_b = 1;
    j[1].a = 0, j[1].b = 1, j[1].joint.panel_a = 7, j[1].joint.panel_b = 0;
    j[1].joint.gap = 0.002, j[1].joint.added = 0.1;
    struct map_seams seams;
    assert_int_equal(map_seams_of_surface(j, 2, 0, 4, &seams), 0);
    for (size_t k = 0; k < 4; k++)
        assert_true(isnan(map_seam_measure(&seams, k, MAP_BY_GAP)));
    assert_int_equal(seams.joints, 0);
    map_seams_free(&seams);
    assert_int_equal(map_seams_of_surface(j, 2, 1, 4, &seams), 0);
    assert_int_equal(seams.joints, 2);
    assert_true(fabs(map_seam_measure(&seams, 0, MAP_BY_GAP) - 2) < 1e-12);
    assert_true(fabs(map_seam_measure(&seams, 0, MAP_BY_KINK) -
                     0.1 * 180 / PI) < 1e-12);
    assert_true(isnan(map_seam_measure(&seams, 0, MAP_BY_MOVE)));
    assert_true(isnan(map_seam_measure(&seams, 2, MAP_BY_GAP)));
    assert_true(fabs(map_seams_largest(&seams, MAP_BY_GAP) - 2) < 1e-12);
    map_seams_free(&seams);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_hinge),
        cmocka_unit_test(test_cylinder),
        cmocka_unit_test(test_other_surfaces),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
