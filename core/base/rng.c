/*
 * rng.c: xoshiro256** seeded by splitmix64. See rng.h.
 *
 * Written from the published descriptions of both generators; the output
 * sequence is pinned by tests/unit/test_nsga2.c.
 */
#include "core/base/rng.h"

#define GOLDEN_GAMMA 0x9E3779B97F4A7C15u

uint64_t rng_mix64(uint64_t x)
{
    x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9u;
    x = (x ^ (x >> 27)) * 0x94D049BB133111EBu;
    return x ^ (x >> 31);
}

void rng_seed(struct rng *rng, uint64_t seed)
{
    /* splitmix64: add the golden gamma, then mix. Its outputs are distinct
     * for four consecutive steps, so the state is never all zero. */
    uint64_t s = seed;
    for (int k = 0; k < 4; k++) {
        s += GOLDEN_GAMMA;
        rng->state[k] = rng_mix64(s);
    }
}

void rng_seed_stream(struct rng *rng, uint64_t seed, uint64_t stream)
{
    rng_seed(rng, seed ^ rng_mix64(stream + GOLDEN_GAMMA));
}

static uint64_t rotate_left(uint64_t x, int k)
{
    return (x << k) | (x >> (64 - k));
}

uint64_t rng_next(struct rng *rng)
{
    uint64_t *s = rng->state;
    uint64_t result = rotate_left(s[1] * 5, 7) * 9;
    uint64_t t = s[1] << 17;
    s[2] ^= s[0];
    s[3] ^= s[1];
    s[1] ^= s[2];
    s[0] ^= s[3];
    s[2] ^= t;
    s[3] = rotate_left(s[3], 45);
    return result;
}

double rng_uniform(struct rng *rng)
{
    return (double)(rng_next(rng) >> 11) * 0x1.0p-53;
}

uint64_t rng_below(struct rng *rng, uint64_t bound)
{
    if (bound == 0)
        return 0;
    /* 2^64 mod bound values at the bottom would be drawn once too often;
     * reject them. threshold = (2^64 - bound) mod bound = 2^64 mod bound. */
    uint64_t threshold = (0 - bound) % bound;
    for (;;) {
        uint64_t x = rng_next(rng);
        if (x >= threshold)
            return x % bound;
    }
}

int64_t rng_between(struct rng *rng, int64_t low, int64_t high)
{
    if (high < low)
        return low;
    uint64_t span = (uint64_t)high - (uint64_t)low;
    uint64_t offset = span == UINT64_MAX ? rng_next(rng)
                                         : rng_below(rng, span + 1);
    return (int64_t)((uint64_t)low + offset);
}
