/*
 * cache_checksum.h: the checksum of a prepared building's cache
 * (project_cache.h), made while it is written and checked on threads
 * while it is read.
 *
 * The checksum is the SHA-256 of the payload's pieces' SHA-256s: the
 * payload cut into pieces of CACHE_CHECKSUM_PIECE bytes (the last one
 * shorter), each piece's SHA-256 in hex (64 digits), those digits
 * hashed in order. Every byte still counts (a damaged byte changes its
 * piece's digest, so the whole), and the pieces can be hashed at once:
 * on the skin's cache, about 1 GB, one thread's SHA-256 took most of a
 * second run's start. The writer hashes as it writes, one piece after
 * another, to the same result.
 *
 * No I/O; no memory beyond one digest per piece while checking.
 */
#ifndef FACET_CACHE_CHECKSUM_H
#define FACET_CACHE_CHECKSUM_H

#include <stddef.h>
#include <stdint.h>

#include "core/base/error.h"
#include "core/base/sha256.h"
#include "core/base/stop.h"

/* 32 MB: pieces enough to share among threads (a cache of a small
 * building is one piece, hashed as before), few enough that their
 * digests are nothing to hash. Part of the format. */
#define CACHE_CHECKSUM_PIECE ((uint64_t)32 << 20)

/* The checksum made as bytes come, in order. */
struct cache_checksum {
    struct sha256 pieces;  /* over the pieces' hex digests */
    struct sha256 piece;   /* over the current piece's bytes */
    uint64_t in_piece;     /* bytes of the current piece so far */
};

void cache_checksum_init(struct cache_checksum *c);
void cache_checksum_update(struct cache_checksum *c, const void *bytes,
                           size_t n);
/* The checksum of every byte given, as 64 hex digits and a NUL. */
void cache_checksum_hex(struct cache_checksum *c, char hex[65]);

/* The checksum of the size bytes at payload, its pieces hashed on up to
 * threads threads (at least 1), each asking stop (stop.h) every few
 * megabytes: FACET_OK with hex set, FACET_ESTOP when it fires,
 * FACET_EWORK when out of memory. */
int cache_checksum_of(const unsigned char *payload, uint64_t size,
                      int threads, const struct facet_stop *stop,
                      char hex[65], struct facet_error *err);

#endif
