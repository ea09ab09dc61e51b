/*
 * shard.c: a run's share of its design space. See shard.h.
 */
#include "core/search/shard.h"

#include <stdio.h>
#include <string.h>

#include "core/base/numparse.h"
#include "core/base/rng.h"
#include "core/search/optimize.h"

int shard_parse(const char *text, const char *what, struct shard *out,
                struct facet_error *err)
{
    const char *end = text + strlen(text), *stop;
    long long index, count;
    if (numparse_whole(text, end, 1, SHARD_COUNT_MAX, &index, &stop) ==
            NUMPARSE_OK && *stop == '/' &&
        numparse_whole(stop + 1, end, 1, SHARD_COUNT_MAX, &count, &stop) ==
            NUMPARSE_OK && stop == end && index <= count) {
        out->index = (int)index;
        out->count = (int)count;
        return FACET_OK;
    }
    return facet_error_set(err, FACET_EINPUT,
        "%s: '%s' is not I/N with 1 <= I <= N <= %d (e.g. 2/8: the second "
        "of 8 shards)", what, text, SHARD_COUNT_MAX);
}

int shard_owns(const struct shard *shard, uint64_t unit)
{
    return shard->count <= 1 ||
           unit % (uint64_t)shard->count == (uint64_t)(shard->index - 1);
}

static uint64_t space_grids(const struct design_space *space)
{
    return (uint64_t)(space->u_max - space->u_min + 1) *
           (uint64_t)(space->v_max - space->v_min + 1);
}

uint64_t shard_grid_unit(uint64_t grids, uint64_t steps,
                         const struct shard *shard, uint64_t point)
{
    return grids >= (uint64_t)shard->count ? point / steps : point;
}

uint64_t shard_exhaustive_unit(const struct design_space *space,
                               const struct shard *shard, uint64_t point)
{
    uint64_t grids = space_grids(space);
    return shard_grid_unit(grids, design_space_size(space) / grids, shard,
                           point);
}

uint64_t shard_share(const struct shard *shard, uint64_t count)
{
    if (shard->count <= 1)
        return count;
    uint64_t n = (uint64_t)shard->count;
    return count / n + ((uint64_t)(shard->index - 1) < count % n);
}

uint64_t shard_grid_points(uint64_t grids, uint64_t steps,
                           const struct shard *shard)
{
    if (shard->count <= 1)
        return grids * steps;
    if (grids < (uint64_t)shard->count)
        return shard_share(shard, grids * steps);
    return shard_share(shard, grids) * steps;
}

uint64_t shard_exhaustive_points(const struct design_space *space,
                                 const struct shard *shard)
{
    uint64_t grids = space_grids(space);
    return shard_grid_points(grids, design_space_size(space) / grids,
                             shard);
}

uint64_t shard_island_seed(uint64_t seed, const struct shard *shard)
{
    if (shard->count <= 1)
        return seed;
    return seed ^ rng_mix64((uint64_t)(shard->index - 1));
}

void shard_format(const struct shard *shard, char *text, size_t size)
{
    if (shard->count <= 0)
        snprintf(text, size, "%s", "");
    else
        snprintf(text, size, "%d/%d", shard->index, shard->count);
}
