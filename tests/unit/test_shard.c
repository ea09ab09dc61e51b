/*
 * test_shard.c: a run's share of its design space (core/search/shard.h),
 * against brute force: the shards of a space partition its points, each
 * grid's thresholds stay in one shard when there are grids enough, the
 * counts the progress and the disk check take are the counts of the
 * points dealt, and the parser takes I/N and nothing else; and, for a
 * search whose points are not all distinct options (a project's
 * modules), that the shards partition its distinct options, each under
 * the number a brute-force walk gives it.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <stdlib.h>
#include <string.h>

#include "core/base/rng.h"
#include "core/search/optimize.h"
#include "core/search/shard.h"

/* Spaces of few and of many grids, one threshold and several. */
static const struct design_space spaces[] = {
    {10, 15, 12, 17, 1, 4, 1},   /* 36 grids x 4 */
    {10, 10, 12, 13, 1, 4, 1},   /* 2 grids x 4 */
    {5, 5, 7, 7, 3, 3, 0},       /* 1 point */
    {1, 7, 1, 3, 0.5, 2, 0.25},  /* 21 grids x 7 */
};

static void test_exhaustive_partition(void **state)
{
    (void)state;
    for (size_t s = 0; s < sizeof spaces / sizeof *spaces; s++) {
        const struct design_space *space = &spaces[s];
        uint64_t total = design_space_size(space);
        uint64_t steps = total / (uint64_t)((space->u_max - space->u_min + 1) *
                                            (space->v_max - space->v_min + 1));
        for (int n = 1; n <= 9; n++) {
            uint64_t dealt = 0;
            for (int i = 1; i <= n; i++) {
                struct shard shard = {i, n};
                uint64_t mine = 0;
                for (uint64_t p = 0; p < total; p++)
                    mine += (uint64_t)shard_owns(
                        &shard, shard_exhaustive_unit(space, &shard, p));
                assert_int_equal(mine, shard_exhaustive_points(space,
                                                               &shard));
                dealt += mine;
            }
            assert_int_equal(dealt, total);
            for (uint64_t p = 0; p < total; p++) {
                int owners = 0, first = 0;
                for (int i = 1; i <= n; i++) {
                    struct shard shard = {i, n};
                    if (shard_owns(&shard,
                                   shard_exhaustive_unit(space, &shard, p))) {
                        owners++;
                        first = i;
                    }
                }
                assert_int_equal(owners, 1);
                /* A grid's thresholds together when grids suffice. */
                if (total / steps >= (uint64_t)n && p % steps != 0) {
                    struct shard shard = {first, n};
                    assert_true(shard_owns(&shard, shard_exhaustive_unit(
                                                       space, &shard,
                                                       p - 1)));
                }
            }
        }
    }
}

static void test_share_counts(void **state)
{
    (void)state;
    for (int n = 1; n <= 7; n++)
        for (uint64_t count = 0; count < 30; count++) {
            uint64_t sum = 0;
            for (int i = 1; i <= n; i++) {
                struct shard shard = {i, n};
                uint64_t brute = 0;
                for (uint64_t u = 0; u < count; u++)
                    brute += (uint64_t)shard_owns(&shard, u);
                assert_int_equal(shard_share(&shard, count), brute);
                sum += brute;
            }
            assert_int_equal(sum, count);
        }
    struct shard whole = {0, 0};
    assert_int_equal(shard_share(&whole, 17), 17);
    assert_true(shard_owns(&whole, 5));
}

/* Island 1 is the unsharded run; the others differ from it and from each
 * other. */
static void test_island_seeds(void **state)
{
    (void)state;
    struct shard whole = {0, 0}, first = {1, 4};
    assert_int_equal(shard_island_seed(42, &whole), 42);
    assert_int_equal(shard_island_seed(42, &first), 42);
    for (int i = 2; i <= 4; i++) {
        struct shard a = {i, 4};
        assert_int_equal(shard_island_seed(42, &a), 42 ^ rng_mix64(i - 1));
        for (int j = 1; j < i; j++) {
            struct shard b = {j, 4};
            assert_true(shard_island_seed(42, &a) !=
                        shard_island_seed(42, &b));
        }
    }
}

static void test_parse(void **state)
{
    (void)state;
    struct shard s;
    struct facet_error err;
    assert_int_equal(shard_parse("2/8", "--shard", &s, &err), FACET_OK);
    assert_int_equal(s.index, 2);
    assert_int_equal(s.count, 8);
    assert_int_equal(shard_parse("1/1", "--shard", &s, &err), FACET_OK);
    static const char *const bad[] = {"", "2", "0/3", "4/3", "2/", "/3",
                                      "2/3x", "2:3", "-1/3", "1/100001",
                                      "two"};
    for (size_t k = 0; k < sizeof bad / sizeof *bad; k++) {
        assert_int_equal(shard_parse(bad[k], "--shard", &s, &err),
                         FACET_EINPUT);
        assert_non_null(strstr(err.message, "--shard"));
    }
    char text[16];
    s = (struct shard){3, 5};
    shard_format(&s, text, sizeof text);
    assert_string_equal(text, "3/5");
}

/* --- shards of a search whose points are not all distinct options ---
 *
 * An evaluator with a canonical hook, as a project's (several modules
 * give every surface the same grid): nu stands for its class of three
 * (1-3 -> 1, 4-6 -> 4, ...) and nv for the lowest of its pair (2k, 2k+1)
 * in the space. The truth is a brute-force walk of the space in the
 * exhaustive order, numbering each canonical point the first time it is
 * met. */

static void canonical_classes(void *context, struct design_point *p)
{
    const struct design_space *space = context;
    p->nu = (p->nu - 1) / 3 * 3 + 1;
    if (p->nu < space->u_min)
        p->nu = space->u_min;
    if (p->nv % 2 == 1 && p->nv > space->v_min)
        p->nv -= 1;
}

/* What a search with the fake evaluator met, evaluated and stored. */
struct fake_run {
    struct evaluated_option *stored;
    size_t nstored, capacity;
    size_t evaluated;
    int64_t last_done, last_total;
};

static int fake_evaluate(void *context, const struct option_params *base,
                         const struct design_point *points, size_t n,
                         int jobs, const struct facet_stop *stop,
                         struct option_totals *totals,
                         struct facet_error *err)
{
    (void)context;
    (void)stop;
    (void)base;
    (void)jobs;
    (void)err;
    for (size_t k = 0; k < n; k++) {
        memset(&totals[k], 0, sizeof totals[k]);
        totals[k].cost = points[k].nu * 1000.0 + points[k].nv +
                         points[k].threshold_mm / 100;
    }
    return FACET_OK;
}

static int fake_store(void *context, const struct evaluated_option *options,
                      size_t n, struct facet_error *err)
{
    (void)err;
    struct fake_run *r = context;
    if (r->nstored + n > r->capacity) {
        r->capacity = 2 * (r->nstored + n);
        r->stored = realloc(r->stored, r->capacity * sizeof *r->stored);
        assert_non_null(r->stored);
    }
    memcpy(r->stored + r->nstored, options, n * sizeof *options);
    r->nstored += n;
    r->evaluated += n;
    return FACET_OK;
}

static void fake_progress(void *context, const struct optimize_progress *p)
{
    struct fake_run *r = context;
    r->last_done = p->done;
    r->last_total = p->total;
}

static int by_option_number(const void *a, const void *b)
{
    const struct evaluated_option *p = a, *q = b;
    return (p->number > q->number) - (p->number < q->number);
}

static void run_fake(const struct design_space *space,
                     enum optimize_method method, struct shard shard,
                     struct fake_run *r)
{
    memset(r, 0, sizeof *r);
    struct optimize_settings settings;
    memset(&settings, 0, sizeof settings);
    settings.method = method;
    settings.space = *space;
    settings.seed = 9;
    settings.evaluations = 40;
    settings.jobs = 1;
    settings.shard = shard;
    struct option_evaluator evaluator = {(void *)space, canonical_classes,
                                         fake_evaluate};
    struct optimize_hooks hooks = {r, fake_store, fake_progress, NULL};
    enum optimize_outcome outcome;
    struct facet_error err;
    assert_int_equal(optimize_run_with(&evaluator, &settings, NULL, 0,
                                       &hooks, &outcome, &err), FACET_OK);
    assert_int_equal(outcome, OPTIMIZE_DONE);
    int64_t total;
    assert_int_equal(optimize_total_with(&evaluator, &settings, &total,
                                         &err), FACET_OK);
    /* The progress ends at its total; an exhaustive walk's is the one
     * it announced, the count of points it evaluates (a random run that
     * spends its space before its draws ends where it stops). */
    assert_int_equal(r->last_done, r->last_total);
    if (method == METHOD_EXHAUSTIVE) {
        assert_int_equal(r->last_total, total);
        assert_int_equal((int64_t)r->nstored, total);
    }
    if (r->nstored > 0)
        qsort(r->stored, r->nstored, sizeof *r->stored, by_option_number);
}

static void test_canonical_shards(void **state)
{
    (void)state;
    static const struct design_space canonical_spaces[] = {
        {1, 10, 3, 9, 1, 3, 1},    /* 4 x 4 distinct grids x 3 */
        {2, 5, 1, 2, 2, 2, 0},     /* 2 x 2 distinct grids, 1 threshold */
        {1, 7, 1, 3, 0.5, 2, 0.5}, /* 3 x 2 distinct grids x 4 */
    };
    for (size_t s = 0; s < sizeof canonical_spaces / sizeof *canonical_spaces;
         s++) {
        const struct design_space *space = &canonical_spaces[s];
        /* Brute force: the distinct canonical points in walk order. */
        struct design_point truth[4096];
        size_t ntruth = 0;
        uint64_t steps = design_space_size(space) /
                         (uint64_t)((space->u_max - space->u_min + 1) *
                                    (space->v_max - space->v_min + 1));
        for (int u = space->u_min; u <= space->u_max; u++)
            for (int v = space->v_min; v <= space->v_max; v++)
                for (uint64_t t = 0; t < steps; t++) {
                    struct design_point p = {u, v, space->t_min_mm +
                                             (double)t * space->t_step_mm};
                    canonical_classes((void *)space, &p);
                    size_t k = 0;
                    while (k < ntruth &&
                           !(truth[k].nu == p.nu && truth[k].nv == p.nv &&
                             truth[k].threshold_mm == p.threshold_mm))
                        k++;
                    if (k == ntruth)
                        truth[ntruth++] = p;
                }
        struct fake_run whole;
        run_fake(space, METHOD_EXHAUSTIVE, (struct shard){0, 0}, &whole);
        assert_int_equal(whole.nstored, ntruth);
        for (size_t k = 0; k < ntruth; k++) {
            assert_int_equal(whole.stored[k].number, (int64_t)k + 1);
            assert_int_equal(whole.stored[k].point.nu, truth[k].nu);
            assert_int_equal(whole.stored[k].point.nv, truth[k].nv);
            assert_true(whole.stored[k].point.threshold_mm ==
                        truth[k].threshold_mm);
        }
        for (int method = METHOD_EXHAUSTIVE; method <= METHOD_RANDOM;
             method++) {
            struct fake_run unsharded;
            run_fake(space, (enum optimize_method)method,
                     (struct shard){0, 0}, &unsharded);
            for (int n = 1; n <= 6; n++) {
                /* Every option in exactly one shard, under its unsharded
                 * number and point; no shard evaluates another's. */
                unsigned char *owner = calloc(unsharded.nstored + 1, 1);
                size_t evaluated = 0;
                for (int i = 1; i <= n; i++) {
                    struct fake_run part;
                    run_fake(space, (enum optimize_method)method,
                             (struct shard){i, n}, &part);
                    evaluated += part.evaluated;
                    for (size_t k = 0; k < part.nstored; k++) {
                        int64_t number = part.stored[k].number;
                        assert_true(number >= 1 &&
                                    number <= (int64_t)unsharded.nstored);
                        const struct evaluated_option *w =
                            &unsharded.stored[number - 1];
                        assert_int_equal(w->number, number);
                        assert_int_equal(part.stored[k].point.nu,
                                         w->point.nu);
                        assert_int_equal(part.stored[k].point.nv,
                                         w->point.nv);
                        assert_true(part.stored[k].point.threshold_mm ==
                                    w->point.threshold_mm);
                        assert_int_equal(owner[number], 0);
                        owner[number] = (unsigned char)i;
                    }
                    free(part.stored);
                }
                assert_int_equal(evaluated, unsharded.nstored);
                for (size_t k = 1; k <= unsharded.nstored; k++)
                    assert_true(owner[k] != 0);
                free(owner);
            }
            free(unsharded.stored);
        }
        free(whole.stored);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_exhaustive_partition),
        cmocka_unit_test(test_share_counts),
        cmocka_unit_test(test_island_seeds),
        cmocka_unit_test(test_parse),
        cmocka_unit_test(test_canonical_shards),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
