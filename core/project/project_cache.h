/*
 * project_cache.h: a prepared building kept in a file, checked before it
 * is used, never trusted.
 *
 * Preparing a building (project_prepare: each surface's UV and vertex
 * curvature, then the sums every grid starts from) takes most of a short
 * run on a large skin, and every run, resume and map of the same files
 * did it again. The cache keeps, per surface, its mesh in metres (every
 * array of struct mesh), its parameterization and its vertex curvature,
 * and (format 3) what follows from those alone and took most of a second
 * start to remake (about 3 s of CPU on the skin): the UV lookup's buckets,
 * the facets' sag, the panel sums, the joints' prep and the u and v
 * lengths, each as the preparation made it, so that a building read back
 * is the same to the bit as one prepared anew. Only the fit points, cheap,
 * are remade (project_prepare_rest_stoppable, surface_prepare_rest).
 *
 * The file (native byte order and doubles, which the header checks):
 *
 *   header, 152 bytes:
 *     "FACETPRE"           8 bytes, the magic
 *     version              uint32, PROJECT_CACHE_VERSION
 *     byte order           uint32, 0x01020304 as written
 *     payload bytes        uint64, what follows the header
 *     key                  64 hex digits: project_cache_key
 *     checksum             64 hex digits: the payload's, SHA-256 of its
 *                          32 MB pieces' SHA-256s (cache_checksum.h)
 *   payload:
 *     nsurfaces            uint64
 *     per surface          its name, key, file, first face, mesh,
 *                          parameterization and curvature, then its
 *                          prepared sums (facets' sag, u and v lengths,
 *                          the lookup's cell starts and triangles, the
 *                          panel points and corners and triangle sums,
 *                          the joints' outline and per axis its reach,
 *                          order, least coordinates and triangles), every
 *                          array preceded by a presence byte, then zeros
 *                          to the next multiple of 8 bytes from the
 *                          file's start (project_cache.c)
 *
 * Reading maps the file and uses its arrays where they lie (aligned by
 * that padding): the skin's 1 GB is neither copied nor faulted into
 * fresh memory, which took most of a second run's start (version 1 read
 * them into buffers). A cache of an earlier format is refused as
 * another version and rebuilt. It checks, in order, before anything read is used:
 * the file's size against the header's, the magic, the version and byte
 * order, the key (the files' SHA-256s, the settings that shape a
 * preparation and the code that made it: anything else is stale or
 * foreign), the checksum over the whole payload (its pieces on the
 * threads, the stop asked every few milliseconds of it), every length
 * against the bytes left in the file, then every index (triangle
 * corners, neighbours, the triangles round a vertex, the loops, the
 * components, the surface's file) against what it indexes and every
 * coordinate, UV and curvature (curvature.h promises every value finite)
 * for being finite; then the prepared sums against the mesh, UV and
 * curvature just checked: the lookup's grid is remade from the UV (never
 * read) and its cell starts must run from 0 up to its count of entries,
 * each naming a triangle; each corner's panel point must be numbered as
 * first met and lie at that corner's UV, position and curvature; every
 * triangle sum, the sag, the lengths and the reaches finite; along each
 * axis the joints' order must name triangles, each at its corners' UV
 * and vertices, in order of their least coordinate. A damaged, truncated,
 * stale or foreign file is refused with one line saying which; never a
 * wrong building. The mapping is private: a stage that wrote into an
 * array would change its own copy, never the file. Facet never changes
 * a cache in place (it renames a new one over it, and the mapped one
 * lives on until unmapped); a cache cut short by another program while a
 * run has it mapped would end that run with SIGBUS.
 *
 * Writing goes to a temporary file beside the cache, renamed over it when
 * whole: a reader sees the old cache or the new one, never half of one.
 * No fsync: a file cut short by a crash fails its checksum and is rebuilt.
 *
 * Ownership: project_cache_read fills a caller-owned struct project
 * (release with project_close, also after a failure), which owns the
 * mapping (struct project's cache_bytes); the writer only reads the
 * project.
 */
#ifndef FACET_PROJECT_CACHE_H
#define FACET_PROJECT_CACHE_H

#include <stddef.h>
#include <stdio.h>

#include "core/base/error.h"
#include "core/project/project.h"

#define PROJECT_CACHE_VERSION 3
#define PROJECT_CACHE_HEADER 152  /* bytes */

/* What shapes a preparation besides the files' bytes. */
struct project_cache_settings {
    enum mesh_units units;    /* what one OBJ unit is */
    int flip_normals;         /* curvature's sign */
    enum param_method uv;     /* the UV asked for (PARAM_AUTO: the first
                                 that applies) */
    const char *code;         /* what prepared it: a Facet built otherwise
                                 may prepare otherwise, so its identity is
                                 part of the key (study: the SHA-256 of
                                 the running program) */
};

/* The key of a building read from nfiles files whose SHA-256s (hex) are
 * digest[0 .. nfiles), in order, prepared with settings: the SHA-256 (hex)
 * of the format version, the settings, the code and the digests. */
void project_cache_key(const char (*digest)[65], size_t nfiles,
                       const struct project_cache_settings *settings,
                       char key[65]);

/* The cache's path beside the database db_path: in its folder,
 * "facet-prepared-" and 16 hex digits, the first 8 of the SHA-256 of the
 * files' paths (as given: make them absolute first), the last 8 of the
 * SHA-256 of the paths and the settings but the code, into out (size
 * bytes). One name per building and settings, so that a building whose
 * files change, or a Facet rebuilt, replaces its cache instead of adding
 * one, and every database of the folder (a node's shards) shares it; the
 * caches of one building's other settings share its first half
 * (project_cache_prune). FACET_EINPUT when it does not fit. */
int project_cache_path(const char *db_path, const char *const *paths,
                       size_t npaths,
                       const struct project_cache_settings *settings,
                       char *out, size_t size, struct facet_error *err);

/* How many caches of one building's files (of different settings, or
 * of another format version) project_cache_prune keeps beside each other,
 * the one just written among them: a building studied in metres and
 * millimetres, or with its normals both ways, keeps both without
 * preparing either again, and no more pile up. */
#define PROJECT_CACHE_KEEP 3

/* Removes, beside the cache at path (just written), the caches of the
 * same building's files (the same first half of the name) but the keep
 * - 1 most recently written, keep >= 1. Only what Facet wrote: a regular
 * file named as a cache is (not a symbolic link, never followed) that
 * begins with a cache's magic; anything else is left alone. FACET_OK;
 * FACET_EWORK when the folder cannot be listed (the caller goes on: a
 * cache left is only disk). */
int project_cache_prune(const char *path, int keep, struct facet_error *err);

/* Writes project (prepared, read from files whose key is key) to path,
 * through a temporary file renamed over it. FACET_EWORK naming the file
 * and the reason when it cannot (a read-only folder, a full disk): the
 * caller goes on without a cache. */
int project_cache_write(const struct project *project, const char key[65],
                        const char *path, struct facet_error *err);

/* Reads the cache at path into *out as project_open would have read the
 * files paths[0 .. npaths) in units, with each surface's parameterization
 * and curvature set as project_prepare sets them; the caller then runs
 * project_prepare_rest_stoppable. key is the key the files and settings
 * give now (project_cache_key). FACET_OK; FACET_EINPUT with one line
 * naming path and saying why it is not used (missing, truncated, damaged,
 * stale, foreign, another version); FACET_EWORK when out of memory. */
int project_cache_read(const char *path, const char key[65],
                       const char *const *paths, size_t npaths,
                       enum mesh_units units, struct project *out,
                       struct facet_error *err);

/* project_cache_read without the key: every other check made, the key
 * the file holds copied into key, for a caller that hashes the files
 * while the cache is read and compares the keys after (a file of another
 * key must then be closed unused: project_cache_stale says so). stop
 * (stop.h) is asked every few milliseconds of checking: FACET_ESTOP when
 * it fires, *out released. */
int project_cache_read_unkeyed(const char *path, char key[65],
                               const char *const *paths, size_t npaths,
                               enum mesh_units units,
                               const struct facet_stop *stop,
                               struct project *out, struct facet_error *err);

/* Forgets the arrays of project's surfaces that lie in the cache it was
 * read from and unmaps it; nothing when it was not read from one.
 * project_close calls it first. */
void project_cache_release(struct project *project);

/* The FACET_EINPUT project_cache_read gives a cache of another key. */
int project_cache_stale(const char *path, struct facet_error *err);

/* project_cache_read of file, size bytes from its current position,
 * named name in messages (the fuzz target reads from memory). */
int project_cache_read_file(FILE *file, unsigned long long size,
                            const char *name, const char key[65],
                            const char *const *paths, size_t npaths,
                            enum mesh_units units, struct project *out,
                            struct facet_error *err);

#endif
