/*
 * study_prepared.h: a building prepared once and reused: the decision to
 * read its cache (core/project/project_cache.h) or to read and prepare
 * its files and keep the result beside the database.
 *
 * The cache is a file in the database's folder, named from the files'
 * paths and the settings (project_cache_path), shared by every database
 * there, keyed by the files' SHA-256s,
 * the settings and the running program's own SHA-256 (a rebuilt Facet
 * may prepare otherwise). A cache that is missing, damaged, truncated,
 * stale or foreign is never used: the building is prepared from its
 * files, with a note saying why (hooks' note), and the cache written
 * again; a cache that cannot be written (a read-only folder, a full
 * disk) is a note too, never an error. A cache written removes the same
 * files' older caches of other settings beyond PROJECT_CACHE_KEEP
 * (project_cache_prune).
 */
#ifndef FACET_STUDY_PREPARED_H
#define FACET_STUDY_PREPARED_H

#include "core/project/project.h"
#include "study/study.h"

/* What to prepare, and where its cache lives. */
struct study_prepare {
    const char *db_path;        /* the database the cache sits beside;
                                   NULL: no cache */
    const char *const *files;   /* nfiles OBJ files, in order */
    size_t nfiles;
    const char (*known)[65];    /* their SHA-256s when the caller knows
                                   them already (a resume checked them),
                                   else NULL */
    enum mesh_units units;
    int units_named;            /* 0: refuse a building of no building's
                                   size (project_units_check) */
    int flip_normals;
    enum param_method uv;
};

/* Reads and prepares the building of want into *project (release with
 * project_close, also after a failure), from its cache when that holds
 * exactly what preparing its files would make, else from the files; and
 * the files' SHA-256s into digest[0 .. nfiles). FACET_OK, or the error
 * reading or preparing the files gives (FACET_ESTOP when hooks' stop
 * fires). */
int study_project_prepared(const struct study_prepare *want,
                           const struct study_hooks *hooks,
                           struct project *project, char (*digest)[65],
                           struct facet_error *err);

#endif
