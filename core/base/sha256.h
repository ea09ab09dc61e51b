/*
 * sha256.h: the SHA-256 digest (FIPS 180-4) of a file, so that a run
 * records exactly which surface it was computed from and a resume can
 * refuse a surface that has changed since.
 */
#ifndef FACET_SHA256_H
#define FACET_SHA256_H

#include <stddef.h>
#include <stdint.h>

#include "core/base/error.h"
#include "core/base/stop.h"

struct sha256 {
    uint32_t state[8];
    uint64_t length;          /* bytes hashed so far */
    unsigned char block[64];  /* bytes not yet hashed */
    size_t used;
};

void sha256_init(struct sha256 *h);
void sha256_update(struct sha256 *h, const void *bytes, size_t n);
/* Finishes the digest into hex (64 lowercase hex digits and a NUL). */
void sha256_hex(struct sha256 *h, char hex[65]);

/* The digest of the file at path, as hex. FACET_EINPUT when it cannot be
 * read. */
int sha256_file(const char *path, char hex[65], struct facet_error *err);

/* sha256_file, asking stop (stop.h) every few megabytes: FACET_ESTOP when
 * it fires. */
int sha256_file_stoppable(const char *path, const struct facet_stop *stop,
                          char hex[65], struct facet_error *err);

#endif
