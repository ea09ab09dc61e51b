/*
 * test_sp_fit_pinned.c: the SP fits as built, pinned to the bit.
 *
 * The fits are made cheaper only where every stored number stays the
 * same: each SP panel's built type, fitted and misfit flags, its fitted
 * surface, sp_deviation, best_cylinder and best_cone, and each option's
 * sp_fitted and sp_misfits. This hashes all of them (FNV-1a over their
 * bytes) for grids of the paper's roof and space, fitted the three ways a
 * run fits them (built_option_fit on the option's sides, grid_fits_option
 * at one threshold, and at several on one grid), and compares the hash
 * with the one the code gave before it was made faster (c377b7e; the
 * panels it fits changed with the zero test of issue 29, see below).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "core/classify/classify.h"
#include "core/surface/coarse_mesh.h"
#include "core/fit/sp_fit.h"
#include "core/joint/cell_sides.h"
#include "core/surface/surface.h"
#include "tests/support/as_built_reference.h"
#include "tests/support/surface_fixture.h"

/* The hash of c377b7e's fits, with the classes of issue 29's zero test
 * (a curvature whose sign the estimate does not know is zero): more
 * panels classed SP, 14,848 fitted and 2,414 misfits before it, 14,962 and
 * 2,595 since. Checked against Table 1 on example.c's formula at these
 * 24 grids: of the 397 panel classes that changed, 335 are now the
 * formula's and 14 were it before (6 of them near the smoothstep, now SP
 * where the formula's k2 is within 15 % of eps). */
#define PINNED_ROOF 0xf43984ba3f227d11u

static void hash_bytes(uint64_t *h, const void *data, size_t size)
{
    const unsigned char *p = data;
    for (size_t k = 0; k < size; k++) {
        *h ^= p[k];
        *h *= 1099511628211u;
    }
}

static void hash_double(uint64_t *h, double x)
{
    if (isnan(x))
        x = NAN;                 /* one NaN, whatever its payload */
    hash_bytes(h, &x, sizeof x);
}

/* Field by field, so that padding is no part of it. */
static void hash_fit(uint64_t *h, const struct developable *d)
{
    int shape = (int)d->shape;
    hash_bytes(h, &shape, sizeof shape);
    for (int x = 0; x < 3; x++) {
        hash_double(h, d->axis[x]);
        hash_double(h, d->base[x]);
    }
    hash_double(h, d->radius);
    hash_double(h, d->slope);
}

static void hash_built(uint64_t *h, const struct built_option *b)
{
    for (size_t k = 0; k < b->npanels; k++) {
        const struct built_panel *p = &b->panels[k];
        int flags[3] = {(int)p->type, p->fitted, p->misfit};
        hash_bytes(h, flags, sizeof flags);
        hash_fit(h, &p->fit);
        hash_double(h, p->sp_deviation);
        hash_double(h, p->best_cylinder);
        hash_double(h, p->best_cone);
    }
    uint64_t counts[2] = {b->sp_fitted, b->sp_misfits};
    hash_bytes(h, counts, sizeof counts);
}

/* The nu x nv grid of s at thresholds t[0..nt) (m), into *h; the counts
 * of SP panels, misfits and cones fitted into tally. */
static void hash_grid(const struct surface *s, int nu, int nv,
                      const double *t, int nt, uint64_t *h, size_t tally[2])
{
    struct facet_error err;
    struct panelization panels;
    struct grid_fits grid;
    if (panels_build_fast(&s->panels, PANEL_EXTREMES, nu, nv, &panels,
                          &err) != FACET_OK ||
        grid_fits_init(&s->mesh, &s->uv, &s->curvature, &s->fit, &panels,
                       &grid, &err) != FACET_OK)
        fail_msg("%s", err.message);
    for (int x = 0; x < nt; x++) {
        /* The roof's facets sag 0.23 mm (median): under a quarter of
         * every t here, so its fits stay measured on the facets, and the
         * pin stays the pin (coarse_mesh.h). */
        assert_false(facet_sag_matters(s->facet_sag, t[x]));
        as_built_classify_at(&panels, t[x]);
        struct cell_sides sides, view;
        struct built_option alone, kept;
        if (cell_sides_sample(&s->mesh, &s->uv, &s->curvature, &panels,
                              &sides, &err) != FACET_OK ||
            built_option_fit(&s->mesh, &s->fit, &panels, &sides, t[x],
                             facet_sag_matters(s->facet_sag, t[x]), &alone,
                             &err) != FACET_OK ||
            grid_fits_option(&grid, &panels, t[x],
                             facet_sag_matters(s->facet_sag, t[x]), &kept,
                             &view, &err) != FACET_OK)
            fail_msg("%s", err.message);
        hash_built(h, &alone);
        hash_built(h, &kept);
        tally[0] += alone.sp_fitted;
        tally[1] += alone.sp_misfits;
        built_option_free(&alone);
        built_option_free(&kept);
        cell_sides_free(&sides);
    }
    grid_fits_free(&grid);
    panelization_free(&panels);
}

static void test_roof_pinned(void **state)
{
    (void)state;
    struct surface s;
    struct facet_error err;
    if (surface_fixture_example("roof", 224, &s, &err) != FACET_OK)
        fail_msg("%s", err.message);
    uint64_t h = 14695981039346656037u;
    size_t tally[2] = {0, 0};
    const double paper = 0.003;
    for (int nu = 20; nu <= 40; nu += 4)
        for (int nv = 35; nv <= 50; nv += 5)
            hash_grid(&s, nu, nv, &paper, 1, &h, tally);
    const double steps[] = {0.005, 0.002, 0.0035, 0.001, 0.003};
    hash_grid(&s, 29, 44, steps, 5, &h, tally);
    hash_grid(&s, 37, 49, steps, 5, &h, tally);
    printf("SP fits pinned: %zu fitted, %zu misfits, hash %016llx\n",
           tally[0], tally[1], (unsigned long long)h);
    assert_true(tally[0] > 0 && tally[1] > 0);
    assert_true(h == PINNED_ROOF);
    surface_close(&s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_roof_pinned),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
