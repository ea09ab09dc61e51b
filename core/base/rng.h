/*
 * rng.h: a small seeded pseudo-random number generator.
 *
 * xoshiro256** (Blackman and Vigna, 2018) with its 256-bit state expanded
 * from a 64-bit seed by splitmix64. Everything is integer arithmetic on
 * uint64_t, and rng_uniform converts with one exact multiplication, so a
 * given seed gives the same numbers bit for bit on every platform and
 * compiler. The state lives in a caller-owned struct rng: no globals, no
 * allocation, nothing to free. Not for cryptography.
 *
 * Streams: rng_seed_stream derives an independent-looking generator from a
 * (seed, stream) pair, so that a computation split into numbered steps
 * (NSGA-II generations) can restart at any step without replaying the ones
 * before it.
 */
#ifndef FACET_RNG_H
#define FACET_RNG_H

#include <stdint.h>

struct rng {
    uint64_t state[4];  /* xoshiro256** state; never all zero once seeded */
};

/* Seeds rng from seed: the four state words are the first four outputs of
 * splitmix64 started at seed. Every seed, including 0, is valid. */
void rng_seed(struct rng *rng, uint64_t seed);

/* Seeds rng for step `stream` of the computation seeded with seed: the
 * same as rng_seed(rng, seed ^ rng_mix64(stream + 0x9E3779B97F4A7C15)).
 * Different streams of one seed give unrelated sequences. */
void rng_seed_stream(struct rng *rng, uint64_t seed, uint64_t stream);

/* The splitmix64 finaliser: a bijective 64-bit mixing function. */
uint64_t rng_mix64(uint64_t x);

/* The next 64 random bits. */
uint64_t rng_next(struct rng *rng);

/* A uniform double in [0, 1): the top 53 bits of rng_next times 2^-53. */
double rng_uniform(struct rng *rng);

/* A uniform integer in [0, bound), without modulo bias (rejection of the
 * few values above the largest multiple of bound). bound must be > 0;
 * returns 0 for bound 0. */
uint64_t rng_below(struct rng *rng, uint64_t bound);

/* A uniform integer in [low, high] (inclusive); returns low if high < low. */
int64_t rng_between(struct rng *rng, int64_t low, int64_t high);

#endif
