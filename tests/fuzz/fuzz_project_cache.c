/*
 * fuzz_project_cache.c: any bytes as the payload of a prepared building's
 * cache (core/project/project_cache.h), read as `facet optimize`, a
 * resume and the workbench's map read one beside the database.
 *
 * The header is made here around the bytes, with the key the reader is
 * given and the payload's own checksum (cache_checksum.h) as its checksum: a fuzzer never
 * guesses a checksum, and without it every input would stop there. So the
 * reader's own checks (every length against the bytes left, every index
 * against what it indexes, every coordinate finite) are what is fuzzed,
 * as a file made by hand with a right checksum would meet them. A
 * building read is then prepared the rest of the way, as the study does.
 *
 * Must hold, besides no crash, hang or leak: every refusal is one line
 * naming the file; a building read has surfaces, each with its mesh, UV
 * and curvature, and triangles that add up to the building's.
 */
#define _GNU_SOURCE  /* fmemopen */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/project/cache_checksum.h"
#include "core/project/project_cache.h"
#include "fuzz.h"

#define NAME "fuzz.cache"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static const char key[65] =
        "0123456789abcdef0123456789abcdef0123456789abcdef0123456789abcdef";
    size_t total = PROJECT_CACHE_HEADER + size;
    unsigned char *file = malloc(total + 1);
    if (file == NULL)
        return 0;
    struct cache_checksum h;
    cache_checksum_init(&h);
    cache_checksum_update(&h, data, size);
    char checksum[65];
    cache_checksum_hex(&h, checksum);
    uint32_t version = PROJECT_CACHE_VERSION, order = 0x01020304u;
    uint64_t payload = size;
    memcpy(file, "FACETPRE", 8);
    memcpy(file + 8, &version, 4);
    memcpy(file + 12, &order, 4);
    memcpy(file + 16, &payload, 8);
    memcpy(file + 24, key, 64);
    memcpy(file + 88, checksum, 64);
    if (size > 0)
        memcpy(file + PROJECT_CACHE_HEADER, data, size);
    FILE *in = fmemopen(file, total, "rb");
    if (in == NULL) {
        free(file);
        return 0;
    }
    const char *paths[2] = {"a.obj", "b.obj"};
    struct project p;
    struct facet_error err;
    int rc = project_cache_read_file(in, total, NAME, key, paths, 2, UNITS_M,
                                     &p, &err);
    if (rc != FACET_OK &&
        (err.message[0] == '\0' || strchr(err.message, '\n') != NULL ||
         strstr(err.message, NAME) == NULL)) {
        fprintf(stderr, "fuzz_project_cache: a bad refusal: '%s'\n",
                err.message);
        abort();
    }
    if (rc == FACET_OK) {
        size_t triangles = 0;
        for (size_t i = 0; i < p.nsurfaces; i++) {
            const struct surface *s = &p.surfaces[i].surface;
            if (s->mesh.ntriangles == 0 || s->param.uv == NULL ||
                s->curvature.k1 == NULL)
                abort();
            triangles += s->mesh.ntriangles;
        }
        if (p.nsurfaces == 0 || triangles != p.ntriangles)
            abort();
        rc = project_prepare_rest_stoppable(&p, NULL, &err);
        if (rc != FACET_OK &&
            (err.message[0] == '\0' || strchr(err.message, '\n') != NULL))
            abort();
    }
    project_close(&p);
    fclose(in);
    free(file);
    return 0;
}
