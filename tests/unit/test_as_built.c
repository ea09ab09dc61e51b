/*
 * test_as_built.c: panels as built, to the bit, against the
 * straightforward code (tests/support/as_built_reference.h).
 *
 * The cell sides, SP fits and joints of an option are made faster only
 * where the faster code gives every number the same to the last bit: the
 * truth here is the code as first written, kept in the test support and
 * run on the same options, not a stored snapshot of Facet's output. Over
 * the paper's space on the paper's roof (336 grids at 3 mm, and several
 * thresholds on some, so that cones are fitted), and on the real surfaces
 * of ../shared/data (irregular triangles, trimmed boundaries, a conical
 * roof), every side's samples, marks and normal, every panel's verdict,
 * fit, deviations, and every joint's gap and kink must be the same, and
 * the grid's kept fits (grid_fits) too. The reference samples the
 * facets, so the fits here are asked for on the facets (smooth 0) whatever
 * the surfaces' sag; the smooth samples are checked against the analytic
 * cylinder in test_sp_fit_smooth.
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

#include "core/classify/classify.h"
#include "core/fit/sp_fit.h"
#include "core/joint/joint.h"
#include "core/surface/surface.h"
#include "tests/support/as_built_reference.h"
#include "tests/support/surface_fixture.h"

#define PI 3.14159265358979323846

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

/* What was compared, over all options. */
struct tally {
    size_t options, sides, sp, fitted, misfits, cones, joints;
};

/* Fails unless the sides b are a's, sample by sample, where sampled. */
static void compare_sides(const char *what, const struct cell_sides *a,
                          const struct cell_sides *b, struct tally *tally)
{
    assert_int_equal(a->nsides, b->nsides);
    for (size_t s = 0; s < a->nsides; s++) {
        if (a->sampled[s] != b->sampled[s])
            fail_msg("%s: side %zu sampled %d, reference %d", what, s,
                     b->sampled[s], a->sampled[s]);
        if (!a->sampled[s])
            continue;
        tally->sides++;
        int same = a->middle[s] == b->middle[s];
        for (int x = 0; x < 3; x++)
            same = same && same_number(a->normal[3 * s + x],
                                       b->normal[3 * s + x]);
        for (int k = 0; k < CELL_SIDE_SAMPLES; k++) {
            size_t at = s * CELL_SIDE_SAMPLES + (size_t)k;
            same = same && a->on[at] == b->on[at];
            for (int x = 0; x < 3; x++)
                same = same && same_number(a->point[3 * at + x],
                                           b->point[3 * at + x]);
        }
        if (!same)
            fail_msg("%s: side %zu differs from the reference", what, s);
    }
}

/* Fails unless the panels as built b are a's, field by field. */
static void compare_built(const char *what, const struct panelization *p,
                          const struct built_option *a,
                          const struct built_option *b, struct tally *tally)
{
    assert_int_equal(a->npanels, b->npanels);
    assert_int_equal(a->sp_fitted, b->sp_fitted);
    assert_int_equal(a->sp_misfits, b->sp_misfits);
    assert_true(same_number(a->threshold, b->threshold));
    for (size_t k = 0; k < a->npanels; k++) {
        const struct built_panel *x = &a->panels[k], *y = &b->panels[k];
        if (x->type != y->type || x->fitted != y->fitted ||
            x->misfit != y->misfit || !same_fit(&x->fit, &y->fit) ||
            !same_number(x->sp_deviation, y->sp_deviation) ||
            !same_number(x->best_cylinder, y->best_cylinder) ||
            !same_number(x->best_cone, y->best_cone))
            fail_msg("%s: panel %zu differs from the reference: deviation "
                     "%.17g, reference %.17g; cylinder %.17g, %.17g; cone "
                     "%.17g, %.17g", what, k, y->sp_deviation,
                     x->sp_deviation, y->best_cylinder, x->best_cylinder,
                     y->best_cone, x->best_cone);
        if (p->panels[k].type != TYPE_SP)
            continue;
        tally->sp++;
        tally->fitted += (size_t)x->fitted;
        tally->misfits += (size_t)x->misfit;
        tally->cones += (size_t)!isnan(x->best_cone);
    }
}

/* Fails unless the joints b are a's, edge by edge. */
static void compare_joints(const char *what, const struct joints *a,
                           const struct joints *b, struct tally *tally)
{
    assert_int_equal(a->nedges, b->nedges);
    assert_int_equal(a->gaps_over, b->gaps_over);
    assert_int_equal(a->kinks_over, b->kinks_over);
    for (size_t e = 0; e < a->nedges; e++)
        if (a->edges[e].side != b->edges[e].side ||
            a->edges[e].panel[0] != b->edges[e].panel[0] ||
            a->edges[e].panel[1] != b->edges[e].panel[1] ||
            !same_number(a->edges[e].gap, b->edges[e].gap) ||
            !same_number(a->edges[e].kink, b->edges[e].kink))
            fail_msg("%s: joint %zu differs from the reference: gap %.17g, "
                     "reference %.17g; kink %.17g, %.17g", what, e,
                     b->edges[e].gap, a->edges[e].gap, b->edges[e].kink,
                     a->edges[e].kink);
    assert_true(same_number(a->max_gap, b->max_gap) &&
                same_number(a->mean_gap, b->mean_gap) &&
                same_number(a->max_kink, b->max_kink) &&
                same_number(a->mean_kink, b->mean_kink));
    for (size_t k = 0; k < a->npanels; k++)
        assert_true(same_number(a->worst_gap[k], b->worst_gap[k]) &&
                    same_number(a->worst_kink[k], b->worst_kink[k]));
    tally->joints += a->nedges;
}

/* The panels of the nu x nv grid of s, as the paper's space makes them. */
static void grid_of(const struct surface *s, int nu, int nv,
                    struct panelization *panels)
{
    struct facet_error err;
    if (panels_build_fast(&s->panels, PANEL_EXTREMES, nu, nv, panels,
                          &err) != FACET_OK)
        fail_msg("%s", err.message);
}

/* The option's sides, panels as built and joints by the reference, into
 * the given structs (release with the core/ free functions). */
static void reference_option(const struct surface *s,
                             const struct panelization *panels, double t,
                             struct cell_sides *sides,
                             struct built_option *built,
                             struct joints *joints)
{
    struct facet_error err;
    if (reference_cell_sides_sample(&s->mesh, &s->uv, &s->curvature, panels,
                                    sides, &err) != FACET_OK ||
        reference_built_option_fit(&s->mesh, &s->fit, panels, sides, t,
                                   built, &err) != FACET_OK ||
        reference_joints_measure(panels, built, sides, 0.006, PI / 180,
                                 joints, &err) != FACET_OK)
        fail_msg("%s", err.message);
}

/* The nu x nv grid of s at each threshold of t[0..nt) (m): each option on
 * its own (cell_sides_sample + built_option_fit + joints_measure) and
 * with the grid's fits kept (grid_fits), both against the reference. */
static void compare_grid(const char *name, const struct surface *s, int nu,
                         int nv, const double *t, int nt,
                         struct tally *tally)
{
    struct facet_error err;
    struct panelization panels;
    struct grid_fits grid;
    grid_of(s, nu, nv, &panels);
    int kept = nt > 1;
    if (kept && grid_fits_init(&s->mesh, &s->uv, &s->curvature, &s->fit,
                               &panels, &grid, &err) != FACET_OK)
        fail_msg("%s", err.message);
    for (int x = 0; x < nt; x++) {
        char what[160];
        snprintf(what, sizeof what, "%s, %d x %d at %g mm", name, nu, nv,
                 t[x] * 1e3);
        as_built_classify_at(&panels, t[x]);
        struct cell_sides truth_sides, sides;
        struct built_option truth, built;
        struct joints truth_joints, joints;
        reference_option(s, &panels, t[x], &truth_sides, &truth,
                         &truth_joints);
        if (cell_sides_sample(&s->mesh, &s->uv, &s->curvature, &panels,
                              &sides, &err) != FACET_OK ||
            built_option_fit(&s->mesh, &s->fit, &panels, &sides, t[x], 0,
                             &built, &err) != FACET_OK ||
            joints_measure(&panels, &built, &sides, 0.006, PI / 180,
                           &joints, &err) != FACET_OK)
            fail_msg("%s", err.message);
        tally->options++;
        compare_sides(what, &truth_sides, &sides, tally);
        compare_built(what, &panels, &truth, &built, tally);
        compare_joints(what, &truth_joints, &joints, tally);
        joints_free(&joints);
        built_option_free(&built);
        cell_sides_free(&sides);
        if (kept) {
            /* The grid's sides are all sampled; those of this option are
             * the reference's where the option samples them. */
            struct cell_sides view;
            struct tally ignored;
            memset(&ignored, 0, sizeof ignored);
            if (grid_fits_option(&grid, &panels, t[x], 0, &built, &view,
                                 &err) != FACET_OK ||
                joints_measure(&panels, &built, &view, 0.006, PI / 180,
                               &joints, &err) != FACET_OK)
                fail_msg("%s", err.message);
            compare_sides(what, &truth_sides, &view, &ignored);
            compare_built(what, &panels, &truth, &built, &ignored);
            compare_joints(what, &truth_joints, &joints, &ignored);
            joints_free(&joints);
            built_option_free(&built);
        }
        joints_free(&truth_joints);
        built_option_free(&truth);
        cell_sides_free(&truth_sides);
    }
    if (kept)
        grid_fits_free(&grid);
    panelization_free(&panels);
}

static void print_tally(const char *what, const struct tally *t)
{
    printf("as built against the reference, %s: %zu options, %zu sides, "
           "%zu SP panels (%zu fitted, %zu misfits, %zu with cones), %zu "
           "joints: all the same to the bit\n", what, t->options, t->sides,
           t->sp, t->fitted, t->misfits, t->cones, t->joints);
}

/* The paper's space on the paper's roof (224 x 224 quads, 100,352
 * triangles): u 20..40 x v 35..50 at 3 mm, every grid (every seventh
 * under the sanitizers, which are slow), and a few grids at thresholds
 * out of order, with their kept fits. */
static void test_paper_space(void **state)
{
    (void)state;
    struct surface s;
    struct facet_error err;
    if (surface_fixture_example("roof", 224, &s, &err) != FACET_OK)
        fail_msg("%s", err.message);
    struct tally tally;
    memset(&tally, 0, sizeof tally);
#if defined(__SANITIZE_ADDRESS__)
    const int stride = 7;
#else
    const int stride = 1;
#endif
    const double paper = 0.003;
    int k = 0;
    for (int nu = 20; nu <= 40; nu++)
        for (int nv = 35; nv <= 50; nv++)
            if (k++ % stride == 0)
                compare_grid("roof", &s, nu, nv, &paper, 1, &tally);
    const double steps[] = {0.005, 0.002, 0.0035, 0.001, 0.003};
    const int grids[][2] = {{20, 35}, {29, 44}, {40, 50}};
    for (int g = 0; g < 3; g++)
        compare_grid("roof", &s, grids[g][0], grids[g][1], steps, 5,
                     &tally);
    print_tally("the paper's roof", &tally);
    assert_true(tally.fitted > 0 && tally.misfits > 0 && tally.cones > 0);
    surface_close(&s);
}

/* The real surfaces of ../shared/data (FACET_DATA), at a few grids and
 * thresholds each. */
static void test_real_surfaces(void **state)
{
    (void)state;
    const char *files[] = {"conical1.obj", "barrel.obj", "hemisphere.obj",
                           "botanic-garden-bubble-0.obj", "igloo.obj",
                           "compas_hypar.obj", "rhinomesh.obj"};
    const double steps[] = {0.005, 0.002, 0.003};
    const int grids[][2] = {{8, 11}, {15, 13}, {24, 19}};
    struct tally tally;
    memset(&tally, 0, sizeof tally);
    for (size_t f = 0; f < sizeof files / sizeof *files; f++) {
        char path[1024];
        if (!surface_fixture_data(files[f], path, sizeof path))
            skip();
        struct surface s;
        struct facet_error err;
        if (surface_fixture_open(path, &s, &err) != FACET_OK)
            fail_msg("%s: %s", path, err.message);
        for (int g = 0; g < 3; g++)
            compare_grid(files[f], &s, grids[g][0], grids[g][1], steps, 3,
                         &tally);
        surface_close(&s);
    }
    print_tally("real surfaces", &tally);
    assert_true(tally.fitted > 0 && tally.misfits > 0 && tally.cones > 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_paper_space),
        cmocka_unit_test(test_real_surfaces),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
