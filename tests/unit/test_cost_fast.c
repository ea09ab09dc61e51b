/*
 * test_cost_fast.c: the fast paths of the cost model against the plain
 * computations they stand for, to the bit.
 *
 * Every option evaluates its joint length and its mould families through
 * paths made fast for a whole design space (issue 15, section 5): joint
 * lines measured once a batch, triangles read from packed arrays, mould
 * samples located a band at a time, congruence tests skipped by lower
 * bounds, a descriptor grid for the candidates. None may change a number.
 * The truths here are the plain computations, written from the contracts:
 *   - the joint length: joint_length_plain, every grid line against every
 *     triangle;
 *   - the samples: mould_sample_panel, one panel at a time;
 *   - the families: the greedy of mould.h with nothing skipped: each
 *     panel against every earlier representative of its type, in the
 *     order the families were started, under all 8 relabelings in order,
 *     the proper fit then (mirror) the mirrored one, by mould_fit_points;
 *   - a batch's totals (optimize_evaluate, lines shared): each option
 *     evaluated on its own (option_evaluate, sharing the lattice).
 * Over every option of small spaces of three example surfaces, at several
 * tolerances, with and without mirrors, and grids of real surfaces from
 * ../shared/data (FACET_DATA).
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
#include "core/evaluate/evaluate.h"
#include "core/joint/joint_length.h"
#include "core/mould/mould.h"
#include "core/mould/mould_fit.h"
#include "core/mould/mould_sample.h"
#include "core/panel/panel_lattice.h"
#include "core/search/optimize.h"
#include "core/surface/example.h"
#include "core/surface/surface.h"
#include "tests/support/surface_fixture.h"

static void open_example(const char *name, int res, struct surface *s)
{
    struct facet_error err;
    if (surface_fixture_example(name, res, s, &err) != FACET_OK)
        fail_msg("%s: %s", name, err.message);
}

/* Bitwise equality of two doubles (NaN equal to itself). */
static void assert_same_double(double fast, double plain, const char *what)
{
    if (memcmp(&fast, &plain, sizeof fast) != 0)
        fail_msg("%s: %.17g fast, %.17g plain", what, fast, plain);
}

/* ---- The plain families. */

struct plain_families {
    int *family;
    size_t *representative;
    size_t nfamilies, count[TYPE_COUNT], largest, singletons, trimmed;
    double worst;
};

static int all_finite(const double s[MOULD_SAMPLES][3])
{
    for (int k = 0; k < MOULD_SAMPLES; k++)
        for (int x = 0; x < 3; x++)
            if (!isfinite(s[k][x]))
                return 0;
    return 1;
}

/* The deviation of the first fit within limit, in the order of mould.h,
 * or -1. */
static double plain_congruent(const double a[MOULD_SAMPLES][3],
                              const double b[MOULD_SAMPLES][3], int mirror,
                              double limit)
{
    for (int r = 0; r < MOULD_RELABELINGS; r++) {
        int order[MOULD_SAMPLES];
        mould_relabeling(r, order);
        for (int mirrored = 0; mirrored <= mirror; mirrored++) {
            double d = mould_fit_points(a, b, order, MOULD_SAMPLES, mirrored,
                                        NULL, NULL);
            if (d <= limit)
                return d;
        }
    }
    return -1;
}

static void plain_build(const struct surface *s, const struct panelization *p,
                        const struct mould_options *options,
                        struct plain_families *out)
{
    size_t n = p->npanels ? p->npanels : 1;
    memset(out, 0, sizeof *out);
    out->family = malloc(n * sizeof *out->family);
    out->representative = malloc(n * sizeof *out->representative);
    size_t *size = calloc(n, sizeof *size);
    double (*sample)[MOULD_SAMPLES][3] = malloc(n * sizeof *sample);
    unsigned char *sampled = malloc(n);
    assert_non_null(out->family);
    assert_non_null(out->representative);
    assert_non_null(size);
    assert_non_null(sample);
    assert_non_null(sampled);
    for (size_t k = 0; k < p->npanels; k++)
        sampled[k] = p->panels[k].type != TYPE_FP &&
                     mould_sample_panel(&s->mesh, &s->uv, p, k, sample[k]) &&
                     all_finite((const double (*)[3])sample[k]) &&
                     isfinite(p->panels[k].diameter);
    for (size_t k = 0; k < p->npanels; k++) {
        const struct panel *panel = &p->panels[k];
        out->family[k] = -1;
        if (panel->type == TYPE_FP)
            continue;
        int joined = -1;
        for (size_t f = 0; sampled[k] && f < out->nfamilies && joined < 0;
             f++) {
            size_t r = out->representative[f];
            if (!sampled[r] || p->panels[r].type != panel->type)
                continue;
            double d = plain_congruent(
                (const double (*)[3])sample[r],
                (const double (*)[3])sample[k], options->mirror != 0,
                mould_limit(options, p->panels[r].diameter,
                            panel->diameter));
            if (d >= 0) {
                joined = (int)f;
                out->worst = fmax(out->worst, d);
            }
        }
        if (joined < 0) {
            joined = (int)out->nfamilies++;
            out->representative[joined] = k;
            out->count[panel->type]++;
            out->trimmed += !sampled[k];
        }
        out->family[k] = joined;
        size[joined]++;
    }
    for (size_t f = 0; f < out->nfamilies; f++) {
        out->largest = size[f] > out->largest ? size[f] : out->largest;
        out->singletons += size[f] == 1;
    }
    free(size);
    free(sample);
    free(sampled);
}

static void plain_free(struct plain_families *f)
{
    free(f->family);
    free(f->representative);
}

/* ---- One option: samples, families, joints. */

/* The samples of the grid against each panel's own. */
static void check_samples(const struct surface *s,
                          const struct panelization *p)
{
    size_t n = p->npanels ? p->npanels : 1;
    unsigned char *want = malloc(n), *got = malloc(n);
    double (*grid)[MOULD_SAMPLES][3] = malloc(n * sizeof *grid);
    assert_non_null(want);
    assert_non_null(got);
    assert_non_null(grid);
    for (size_t k = 0; k < p->npanels; k++)
        want[k] = k % 3 != 1;  /* some cells left out: their neighbours */
    assert_int_equal(mould_sample_grid(&s->mesh, &s->uv, p, want, grid, got, NULL),
                     FACET_OK);
    for (size_t k = 0; k < p->npanels; k++) {
        double one[MOULD_SAMPLES][3];
        int ok = want[k] && mould_sample_panel(&s->mesh, &s->uv, p, k, one);
        assert_int_equal(got[k], ok);
        if (ok && memcmp(one, grid[k], sizeof one) != 0)
            fail_msg("grid %dx%d panel %zu: samples differ", p->nu, p->nv,
                     k);
    }
    free(want);
    free(got);
    free(grid);
}

/* Returns the families' exact tests, to show the skips were exercised. */
static size_t check_families(const struct surface *s,
                             const struct panelization *p, double tolerance,
                             int mirror)
{
    struct mould_options options = {tolerance, mirror, 0, NULL};
    struct mould_families fast;
    struct plain_families plain;
    struct facet_error err;
    assert_int_equal(mould_families_build(&s->mesh, &s->uv, p, &options,
                                          &fast, &err),
                     FACET_OK);
    plain_build(s, p, &options, &plain);
    for (size_t k = 0; k < p->npanels; k++)
        if (fast.family[k] != plain.family[k])
            fail_msg("grid %dx%d at %g mm%s: panel %zu in family %d, "
                     "plainly %d", p->nu, p->nv, tolerance * 1e3,
                     mirror ? " with mirrors" : "", k, fast.family[k],
                     plain.family[k]);
    assert_int_equal(fast.nfamilies, plain.nfamilies);
    for (size_t f = 0; f < fast.nfamilies; f++)
        assert_int_equal(fast.representative[f], plain.representative[f]);
    for (int t = 0; t < TYPE_COUNT; t++)
        assert_int_equal(fast.count[t], plain.count[t]);
    assert_int_equal(fast.largest, plain.largest);
    assert_int_equal(fast.singletons, plain.singletons);
    assert_int_equal(fast.trimmed, plain.trimmed);
    assert_same_double(fast.worst, plain.worst, "worst member");
    size_t fits = fast.fits;
    mould_families_free(&fast);
    plain_free(&plain);
    return fits;
}

static void check_joints(const struct surface *s, const struct panelization *p,
                         const struct joint_lines *lines)
{
    double plain = joint_length_plain(&s->joints, &s->mesh, &s->uv, p);
    assert_true(plain > 0);
    assert_same_double(joint_length(&s->joints, &s->mesh, &s->uv, p), plain,
                       "joint length");
    assert_same_double(joint_length_lines(lines, &s->joints, &s->mesh, &s->uv,
                                          p),
                       plain, "joint length from the shared lines");
}

/* Every grid of u_lo..u_hi x v_lo..v_hi of s, each at the tolerances
 * tolerance[0..ntolerances) (m) with and without mirrors; the joint lines
 * of every grid measured once. Returns the exact tests made. */
static size_t check_space(const struct surface *s, int u_lo, int u_hi,
                          int v_lo, int v_hi, const double *tolerance,
                          int ntolerances)
{
    int (*grid)[2] = malloc(sizeof *grid * (size_t)(u_hi - u_lo + 1) *
                            (size_t)(v_hi - v_lo + 1));
    assert_non_null(grid);
    size_t ngrids = 0, fits = 0;
    for (int nu = u_lo; nu <= u_hi; nu++)
        for (int nv = v_lo; nv <= v_hi; nv++) {
            grid[ngrids][0] = nu;
            grid[ngrids][1] = nv;
            ngrids++;
        }
    int u_side[64], v_side[64];
    assert_true(u_hi - u_lo < 64 && v_hi - v_lo < 64);
    for (int k = 0; k <= u_hi - u_lo; k++)
        u_side[k] = u_lo + k;
    for (int k = 0; k <= v_hi - v_lo; k++)
        v_side[k] = v_lo + k;
    const int *side[2] = {u_side, v_side};
    size_t nsides[2] = {(size_t)(u_hi - u_lo + 1), (size_t)(v_hi - v_lo + 1)};
    struct joint_lines lines;
    struct facet_error err;
    assert_int_equal(joint_lines_build(&s->joints, &s->mesh, &s->uv,
                                       (const int *const *)side, nsides, 2,
                                       &lines, &err),
                     FACET_OK);
    /* Shared: fewer lines than the grids have. */
    assert_true(lines.nline[0] < (size_t)(u_hi - u_lo + 1) * (size_t)u_hi);
    for (size_t g = 0; g < ngrids; g++) {
        struct panelization p;
        assert_int_equal(panels_build_fast(&s->panels, PANEL_EXTREMES,
                                           grid[g][0], grid[g][1], &p, &err),
                         FACET_OK);
        check_joints(s, &p, &lines);
        check_samples(s, &p);
        for (int t = 0; t < ntolerances; t++) {
            struct classify_options classify;
            struct option_totals totals;
            classify_defaults(&classify);
            classify.threshold = tolerance[t];
            classify_panels(&p, &classify, &totals);
            for (int mirror = 0; mirror <= 1; mirror++)
                fits += check_families(s, &p, tolerance[t], mirror);
        }
        panelization_free(&p);
    }
    joint_lines_free(&lines);
    free(grid);
    return fits;
}

static void test_roof_space(void **state)
{
    (void)state;
    struct surface s;
    open_example("roof", 40, &s);
    const double tolerance[] = {0.001, 0.003, 0.03, 0};
    assert_true(check_space(&s, 5, 11, 7, 12, tolerance, 4) > 1000);
    surface_close(&s);
}

/* Rows of congruent cells and their mirror images: the fits that pass. */
static void test_torus_space(void **state)
{
    (void)state;
    struct surface s;
    open_example("torus", 36, &s);
    const double tolerance[] = {1e-6, 0.003};
    assert_true(check_space(&s, 6, 10, 4, 8, tolerance, 2) > 1000);
    surface_close(&s);
}

static void test_hypar_space(void **state)
{
    (void)state;
    struct surface s;
    open_example("hypar", 30, &s);
    const double tolerance[] = {0.0005, 0.005};
    assert_true(check_space(&s, 4, 9, 4, 9, tolerance, 2) > 100);
    surface_close(&s);
}

/* A batch of grids that share a lattice, its joint lines shared, against
 * each option evaluated on its own: every total the same, to the bit. */
static void test_batch_totals(void **state)
{
    (void)state;
    struct surface s;
    open_example("roof", 48, &s);
    struct facet_error err;
    struct panel_lattice *lattice;
    assert_int_equal(panel_lattice_build(&s.panels, 8, 14, 10, 15, 2,
                                         &lattice, &err),
                     FACET_OK);
    assert_non_null(lattice);
    struct option_params base;
    option_params_defaults(&base);
    struct design_point points[7 * 6 * 2];
    size_t n = 0;
    for (int nu = 8; nu <= 14; nu++)
        for (int nv = 10; nv <= 15; nv++)
            for (int t = 0; t < 2; t++)
                points[n++] = (struct design_point){nu, nv, t ? 10.0 : 3.0};
    struct option_totals batch[7 * 6 * 2];
    assert_int_equal(optimize_evaluate(&s, lattice, &base, points, n, 2,
                                       batch, &err),
                     FACET_OK);
    for (size_t k = 0; k < n; k++) {
        struct option_params params = option_params_at(
            &base, points[k].nu, points[k].nv, points[k].threshold_mm);
        struct panelization p;
        struct option_totals alone;
        const struct evaluation_shared shared = {.lattice = lattice};
        assert_int_equal(option_evaluate(&s, &params, &shared, &p, &alone,
                                         &err),
                         FACET_OK);
        assert_same_double(batch[k].joint_length, alone.joint_length,
                           "batch joint length");
        assert_same_double(batch[k].cost, alone.cost, "batch cost");
        assert_int_equal(batch[k].moulds, alone.moulds);
        for (int t = 0; t < TYPE_COUNT; t++)
            assert_int_equal(batch[k].moulds_of[t], alone.moulds_of[t]);
        assert_int_equal(batch[k].largest_family, alone.largest_family);
        assert_int_equal(batch[k].singleton_families,
                         alone.singleton_families);
        panelization_free(&p);
    }
    panel_lattice_free(lattice);
    surface_close(&s);
}

/* Grids of real surfaces (FACET_DATA): libigl's UV map of a dome with a
 * tunnel (trimmed cells along a curved outline) and a harmonic
 * parameterization of a gridshell roof. */
static void test_real_surfaces(void **state)
{
    (void)state;
    const char *files[] = {"igloo.obj", "botanic-garden-bubble-0.obj"};
    for (size_t f = 0; f < sizeof files / sizeof *files; f++) {
        char path[1024];
        if (!surface_fixture_data(files[f], path, sizeof path))
            skip();
        struct surface s;
        struct facet_error err;
        if (surface_fixture_open(path, &s, &err) != FACET_OK)
            fail_msg("%s: %s", path, err.message);
        const double tolerance[] = {0.003, 0.05};
        check_space(&s, 13, 14, 17, 18, tolerance, 2);
        surface_close(&s);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_roof_space),
        cmocka_unit_test(test_torus_space),
        cmocka_unit_test(test_hypar_space),
        cmocka_unit_test(test_batch_totals),
        cmocka_unit_test(test_real_surfaces),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
