/*
 * shard.h: a run's deterministic share of its design space, so that one
 * search can be spread over machines (each shard its own database) and
 * merged back into the run one machine would have made.
 *
 *   exhaustive  the points in their exhaustive order (u outermost, then v,
 *               then threshold) are dealt out by grid: grid g (0-based, in
 *               that order) belongs to shard g mod N + 1, with all of its
 *               thresholds, so each grid is panelized once. A space of
 *               fewer grids than shards is dealt point by point instead
 *               (point p to shard p mod N + 1). Of a project, whose
 *               modules that give every surface the same grid are one
 *               option, the grids dealt are its distinct options' (the
 *               canonical grids, in the order the walk first meets
 *               them: optimize_total_with), so no two shards evaluate
 *               one option.
 *   random      the unsharded run's sequence of distinct points (drawn with
 *               the run's seed; every shard draws it all) is dealt point by
 *               point: the k-th (0-based) to shard k mod N + 1.
 *   nsga2       an island: a whole NSGA-II run with the population and
 *               generations of the run and its own seed,
 *               seed XOR rng_mix64(I - 1); rng_mix64(0) is 0, so shard 1
 *               searches with the run's seed itself.
 *
 * For exhaustive and random, every point of the unsharded run is in
 * exactly one shard, and an option keeps the number it has in the
 * unsharded run: the shards' union is that run, option for option. The
 * deal depends on the settings alone (never on the machine or the number
 * of threads), so a shard resumed elsewhere evaluates the same share.
 */
#ifndef FACET_SHARD_H
#define FACET_SHARD_H

#include <stddef.h>
#include <stdint.h>

#include "core/base/error.h"

struct design_space;

/* Shard index of count (1 <= index <= count); count 0: the whole run. */
struct shard {
    int index, count;
};

/* The most shards a run may be cut into. */
#define SHARD_COUNT_MAX 100000

/* Parses "I/N" (1 <= I <= N <= SHARD_COUNT_MAX) into *out. FACET_EINPUT
 * naming the field what (the caller's name for it) otherwise. */
int shard_parse(const char *text, const char *what, struct shard *out,
                struct facet_error *err);

/* Whether shard takes the unit numbered unit (0-based): a whole run takes
 * every unit. */
int shard_owns(const struct shard *shard, uint64_t unit);

/* The unit the exhaustive point numbered point (0-based, in the exhaustive
 * order) is dealt by: its grid, or itself when the space has fewer grids
 * than shards. */
uint64_t shard_exhaustive_unit(const struct design_space *space,
                               const struct shard *shard, uint64_t point);

/* The same deal over a list of grids, each with steps thresholds: what
 * a space whose grids are not all distinct options (a project's modules
 * that give every surface the same grid, core/project/project_search.h)
 * is dealt by, its distinct grids numbered in the order the exhaustive
 * walk first meets them. Grid g's thresholds are points g x steps ..
 * g x steps + steps - 1; the unit of point is its grid, or itself when
 * there are fewer grids than shards. */
uint64_t shard_grid_unit(uint64_t grids, uint64_t steps,
                         const struct shard *shard, uint64_t point);
/* How many of the grids x steps points shard evaluates. */
uint64_t shard_grid_points(uint64_t grids, uint64_t steps,
                           const struct shard *shard);

/* How many of count units numbered 0..count-1 shard takes. */
uint64_t shard_share(const struct shard *shard, uint64_t count);

/* How many points of the exhaustive space shard evaluates. */
uint64_t shard_exhaustive_points(const struct design_space *space,
                                 const struct shard *shard);

/* The seed of shard's NSGA-II island in a run seeded with seed. */
uint64_t shard_island_seed(uint64_t seed, const struct shard *shard);

/* Writes "I/N" into text (size bytes), "" for a whole run. */
void shard_format(const struct shard *shard, char *text, size_t size);

#endif
