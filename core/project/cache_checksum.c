/*
 * cache_checksum.c: a prepared building's checksum, piece by piece. See
 * cache_checksum.h.
 */
#include "core/project/cache_checksum.h"

#include <stdlib.h>

#include "core/base/parallel.h"

/* Bytes hashed between two looks at the stop: a few milliseconds. */
#define STOP_CHUNK ((size_t)4 << 20)
#define THREADS_MAX 8

void cache_checksum_init(struct cache_checksum *c)
{
    sha256_init(&c->pieces);
    sha256_init(&c->piece);
    c->in_piece = 0;
}

/* Ends the current piece: its digest into the pieces' hash. */
static void end_piece(struct cache_checksum *c)
{
    char hex[65];
    sha256_hex(&c->piece, hex);
    sha256_update(&c->pieces, hex, 64);
    sha256_init(&c->piece);
    c->in_piece = 0;
}

void cache_checksum_update(struct cache_checksum *c, const void *bytes,
                           size_t n)
{
    const unsigned char *b = bytes;
    while (n > 0) {
        uint64_t room = CACHE_CHECKSUM_PIECE - c->in_piece;
        size_t take = n < room ? n : (size_t)room;
        sha256_update(&c->piece, b, take);
        c->in_piece += take;
        b += take;
        n -= take;
        if (c->in_piece == CACHE_CHECKSUM_PIECE)
            end_piece(c);
    }
}

void cache_checksum_hex(struct cache_checksum *c, char hex[65])
{
    /* A last piece, shorter; an empty payload is one empty piece, as a
     * payload of a whole number of pieces has none after its last. */
    if (c->in_piece > 0 || c->pieces.length == 0)
        end_piece(c);
    sha256_hex(&c->pieces, hex);
}

/* One thread's pieces: first, first + step, ... */
struct piece_job {
    const unsigned char *payload;
    uint64_t size;
    size_t npieces, first, step;
    char (*digest)[65];
    const struct facet_stop *stop;
    int rc;
    struct facet_error err;
};

static void hash_pieces(void *argument)
{
    struct piece_job *job = argument;
    job->rc = FACET_OK;
    for (size_t i = job->first; i < job->npieces; i += job->step) {
        uint64_t from = (uint64_t)i * CACHE_CHECKSUM_PIECE;
        uint64_t to = from + CACHE_CHECKSUM_PIECE < job->size
                          ? from + CACHE_CHECKSUM_PIECE : job->size;
        struct sha256 h;
        sha256_init(&h);
        for (uint64_t at = from; at < to; at += STOP_CHUNK) {
            if ((job->rc = facet_stop_check(job->stop, &job->err)) !=
                FACET_OK)
                return;
            uint64_t n = to - at < STOP_CHUNK ? to - at : STOP_CHUNK;
            sha256_update(&h, job->payload + at, (size_t)n);
        }
        sha256_hex(&h, job->digest[i]);
    }
}

int cache_checksum_of(const unsigned char *payload, uint64_t size,
                      int threads, const struct facet_stop *stop,
                      char hex[65], struct facet_error *err)
{
    uint64_t pieces = size / CACHE_CHECKSUM_PIECE +
                      (size % CACHE_CHECKSUM_PIECE != 0 || size == 0);
    if (pieces > SIZE_MAX / 65)
        return facet_error_set(err, FACET_EWORK, "out of memory");
    size_t npieces = (size_t)pieces;
    char (*digest)[65] = malloc(npieces * sizeof *digest);
    if (digest == NULL)
        return facet_error_set(err, FACET_EWORK, "out of memory");
    struct piece_job jobs[THREADS_MAX];
    int n = parallel_jobs(threads < 1 ? 1 : threads > THREADS_MAX
                                                ? THREADS_MAX : threads,
                          npieces);
    for (int k = 0; k < n; k++)
        jobs[k] = (struct piece_job){payload, size, npieces, (size_t)k,
                                     (size_t)n, digest, stop, FACET_OK,
                                     {0}};
    parallel_run(jobs, sizeof jobs[0], n, hash_pieces);
    int rc = FACET_OK;
    for (int k = 0; k < n && rc == FACET_OK; k++)
        if (jobs[k].rc != FACET_OK) {
            rc = jobs[k].rc;
            *err = jobs[k].err;
        }
    if (rc == FACET_OK) {
        struct sha256 h;
        sha256_init(&h);
        for (size_t i = 0; i < npieces; i++)
            sha256_update(&h, digest[i], 64);
        sha256_hex(&h, hex);
    }
    free(digest);
    return rc;
}
