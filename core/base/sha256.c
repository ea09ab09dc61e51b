/*
 * sha256.c: SHA-256 as FIPS 180-4 defines it. See sha256.h.
 */
#include "core/base/sha256.h"

#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "core/obj/infile.h"

static const uint32_t round_constant[64] = {
    0x428a2f98, 0x71374491, 0xb5c0fbcf, 0xe9b5dba5, 0x3956c25b, 0x59f111f1,
    0x923f82a4, 0xab1c5ed5, 0xd807aa98, 0x12835b01, 0x243185be, 0x550c7dc3,
    0x72be5d74, 0x80deb1fe, 0x9bdc06a7, 0xc19bf174, 0xe49b69c1, 0xefbe4786,
    0x0fc19dc6, 0x240ca1cc, 0x2de92c6f, 0x4a7484aa, 0x5cb0a9dc, 0x76f988da,
    0x983e5152, 0xa831c66d, 0xb00327c8, 0xbf597fc7, 0xc6e00bf3, 0xd5a79147,
    0x06ca6351, 0x14292967, 0x27b70a85, 0x2e1b2138, 0x4d2c6dfc, 0x53380d13,
    0x650a7354, 0x766a0abb, 0x81c2c92e, 0x92722c85, 0xa2bfe8a1, 0xa81a664b,
    0xc24b8b70, 0xc76c51a3, 0xd192e819, 0xd6990624, 0xf40e3585, 0x106aa070,
    0x19a4c116, 0x1e376c08, 0x2748774c, 0x34b0bcb5, 0x391c0cb3, 0x4ed8aa4a,
    0x5b9cca4f, 0x682e6ff3, 0x748f82ee, 0x78a5636f, 0x84c87814, 0x8cc70208,
    0x90befffa, 0xa4506ceb, 0xbef9a3f7, 0xc67178f2,
};

static uint32_t rotate_right(uint32_t x, int n)
{
    return (x >> n) | (x << (32 - n));
}

static void compress(uint32_t state[8], const unsigned char block[64])
{
    uint32_t w[64];
    for (int t = 0; t < 16; t++)
        w[t] = (uint32_t)block[4 * t] << 24 | (uint32_t)block[4 * t + 1] << 16 |
               (uint32_t)block[4 * t + 2] << 8 | (uint32_t)block[4 * t + 3];
    for (int t = 16; t < 64; t++) {
        uint32_t s0 = rotate_right(w[t - 15], 7) ^
                      rotate_right(w[t - 15], 18) ^ (w[t - 15] >> 3);
        uint32_t s1 = rotate_right(w[t - 2], 17) ^
                      rotate_right(w[t - 2], 19) ^ (w[t - 2] >> 10);
        w[t] = w[t - 16] + s0 + w[t - 7] + s1;
    }
    uint32_t a = state[0], b = state[1], c = state[2], d = state[3];
    uint32_t e = state[4], f = state[5], g = state[6], h = state[7];
    for (int t = 0; t < 64; t++) {
        uint32_t s1 = rotate_right(e, 6) ^ rotate_right(e, 11) ^
                      rotate_right(e, 25);
        uint32_t choose = (e & f) ^ (~e & g);
        uint32_t t1 = h + s1 + choose + round_constant[t] + w[t];
        uint32_t s0 = rotate_right(a, 2) ^ rotate_right(a, 13) ^
                      rotate_right(a, 22);
        uint32_t majority = (a & b) ^ (a & c) ^ (b & c);
        uint32_t t2 = s0 + majority;
        h = g;
        g = f;
        f = e;
        e = d + t1;
        d = c;
        c = b;
        b = a;
        a = t1 + t2;
    }
    state[0] += a;
    state[1] += b;
    state[2] += c;
    state[3] += d;
    state[4] += e;
    state[5] += f;
    state[6] += g;
    state[7] += h;
}

void sha256_init(struct sha256 *h)
{
    static const uint32_t initial[8] = {
        0x6a09e667, 0xbb67ae85, 0x3c6ef372, 0xa54ff53a,
        0x510e527f, 0x9b05688c, 0x1f83d9ab, 0x5be0cd19,
    };
    memcpy(h->state, initial, sizeof initial);
    h->length = 0;
    h->used = 0;
}

/* The SHA extensions of x86-64 (Goldmont, Zen, Ice Lake and later) hash
 * about ten times faster than the plain C above: a run that reuses a
 * prepared building (core/project/project_cache.h) hashes its OBJ files
 * and hundreds of megabytes of cache before its first option. The same
 * function, to the bit: test_sha256's vectors run through whichever path
 * the machine has. */
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <cpuid.h>
#include <immintrin.h>

static int have_sha_extensions(void)
{
    unsigned a, b, c, d;
    if (!__get_cpuid(1, &a, &b, &c, &d) || !(c & (1u << 19)) ||
        !(c & (1u << 9)))
        return 0;  /* SSE4.1 and SSSE3 */
    if (!__get_cpuid_count(7, 0, &a, &b, &c, &d))
        return 0;
    return (b >> 29) & 1;  /* SHA */
}

__attribute__((target("sha,sse4.1,ssse3")))
static void compress_sha_extensions(uint32_t state[8],
                                    const unsigned char *data, size_t blocks)
{
    const __m128i order = _mm_set_epi64x(0x0c0d0e0f08090a0bULL,
                                         0x0405060700010203ULL);
    __m128i tmp = _mm_loadu_si128((const __m128i *)&state[0]);
    __m128i state1 = _mm_loadu_si128((const __m128i *)&state[4]);
    tmp = _mm_shuffle_epi32(tmp, 0xB1);                  /* CDAB */
    state1 = _mm_shuffle_epi32(state1, 0x1B);            /* EFGH */
    __m128i state0 = _mm_alignr_epi8(tmp, state1, 8);    /* ABEF */
    state1 = _mm_blend_epi16(state1, tmp, 0xF0);         /* CDGH */
    for (; blocks > 0; blocks--, data += 64) {
        __m128i abef = state0, cdgh = state1, w[4];
        for (int i = 0; i < 16; i++) {
            __m128i x;
            if (i < 4)
                x = _mm_shuffle_epi8(
                    _mm_loadu_si128((const __m128i *)(data + 16 * i)), order);
            else
                x = _mm_sha256msg2_epu32(
                    _mm_add_epi32(
                        _mm_sha256msg1_epu32(w[i & 3], w[(i + 1) & 3]),
                        _mm_alignr_epi8(w[(i + 3) & 3], w[(i + 2) & 3], 4)),
                    w[(i + 3) & 3]);
            w[i & 3] = x;
            __m128i message = _mm_add_epi32(
                x, _mm_loadu_si128((const __m128i *)&round_constant[4 * i]));
            state1 = _mm_sha256rnds2_epu32(state1, state0, message);
            message = _mm_shuffle_epi32(message, 0x0E);
            state0 = _mm_sha256rnds2_epu32(state0, state1, message);
        }
        state0 = _mm_add_epi32(state0, abef);
        state1 = _mm_add_epi32(state1, cdgh);
    }
    tmp = _mm_shuffle_epi32(state0, 0x1B);               /* FEBA */
    state1 = _mm_shuffle_epi32(state1, 0xB1);            /* DCHG */
    state0 = _mm_blend_epi16(tmp, state1, 0xF0);         /* DCBA */
    state1 = _mm_alignr_epi8(state1, tmp, 8);            /* HGFE */
    _mm_storeu_si128((__m128i *)&state[0], state0);
    _mm_storeu_si128((__m128i *)&state[4], state1);
}
#endif

/* Hashes blocks whole 64-byte blocks of data into state. */
static void compress_blocks(uint32_t state[8], const unsigned char *data,
                            size_t blocks)
{
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
    /* Asking the CPU costs more than a few blocks: long runs only. */
    if (blocks >= 16 && have_sha_extensions()) {
        compress_sha_extensions(state, data, blocks);
        return;
    }
#endif
    for (size_t k = 0; k < blocks; k++)
        compress(state, data + 64 * k);
}

void sha256_update(struct sha256 *h, const void *bytes, size_t n)
{
    const unsigned char *p = bytes;
    h->length += n;
    if (h->used > 0) {
        size_t take = 64 - h->used < n ? 64 - h->used : n;
        memcpy(h->block + h->used, p, take);
        h->used += take;
        p += take;
        n -= take;
        if (h->used < 64)
            return;
        compress(h->state, h->block);
        h->used = 0;
    }
    size_t whole = n / 64;
    compress_blocks(h->state, p, whole);
    p += 64 * whole;
    n -= 64 * whole;
    memcpy(h->block, p, n);
    h->used = n;
}

void sha256_hex(struct sha256 *h, char hex[65])
{
    uint64_t bits = h->length * 8;
    unsigned char pad = 0x80;
    sha256_update(h, &pad, 1);
    unsigned char zero = 0;
    while (h->used != 56)
        sha256_update(h, &zero, 1);
    unsigned char length[8];
    for (int k = 0; k < 8; k++)
        length[k] = (unsigned char)(bits >> (56 - 8 * k));
    sha256_update(h, length, 8);
    for (int k = 0; k < 8; k++)
        snprintf(hex + 8 * k, 9, "%08x", h->state[k]);
}

int sha256_file(const char *path, char hex[65], struct facet_error *err)
{
    return sha256_file_stoppable(path, NULL, hex, err);
}

/* Bytes hashed between two questions to the stop: about 10 ms of work. */
#define STOP_EVERY_BYTES ((size_t)4 << 20)

int sha256_file_stoppable(const char *path, const struct facet_stop *stop,
                          char hex[65], struct facet_error *err)
{
    int fd;
    struct stat st;
    int rc = infile_open(path, &fd, &st, err);
    if (rc != FACET_OK)
        return rc;
    FILE *in = fdopen(fd, "rb");
    if (in == NULL) {
        close(fd);
        return facet_error_set(err, FACET_EWORK, "%s: cannot read: %s", path,
                               strerror(errno));
    }
    struct sha256 h;
    sha256_init(&h);
    unsigned char buffer[1 << 16];
    size_t n, since_asked = 0;
    int stopped = 0;
    while ((n = fread(buffer, 1, sizeof buffer, in)) > 0) {
        sha256_update(&h, buffer, n);
        since_asked += n;
        if (since_asked >= STOP_EVERY_BYTES) {
            since_asked = 0;
            if ((stopped = facet_stop_requested(stop)) != 0)
                break;
        }
    }
    int failed = ferror(in);
    fclose(in);
    if (stopped)
        return facet_stop_error(err);
    if (failed)
        return facet_error_set(err, FACET_EINPUT, "%s: read error", path);
    sha256_hex(&h, hex);
    return FACET_OK;
}
