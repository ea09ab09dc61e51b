/*
 * test_shard.c: a run's share of its design space (core/search/shard.h),
 * against brute force: the shards of a space partition its points, each
 * grid's thresholds stay in one shard when there are grids enough, the
 * counts the progress and the disk check take are the counts of the
 * points dealt, and the parser takes I/N and nothing else.
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

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_exhaustive_partition),
        cmocka_unit_test(test_share_counts),
        cmocka_unit_test(test_island_seeds),
        cmocka_unit_test(test_parse),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
