/*
 * study_prepared.c: reading a building from its cache or its files. See
 * study_prepared.h.
 */
#include "study/study_prepared.h"

#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "core/base/sha256.h"
#include "core/project/project_cache.h"
#include "study_internal.h"

/* What prepared the building: the running program's SHA-256, or, where
 * it cannot be read, its version and build time. */
static void code_identity(char *out, size_t size)
{
    struct facet_error ignored;
    char digest[65];
    if (sha256_file("/proc/self/exe", digest, &ignored) == FACET_OK)
        snprintf(out, size, "program %s", digest);
    else
        snprintf(out, size, "version %s built %s %s", FACET_VERSION,
                 __DATE__, __TIME__);
}

static void note(const struct study_hooks *hooks, const char *text)
{
    if (hooks != NULL && hooks->note != NULL)
        hooks->note(hooks->context, text);
}

/* What reading a project parses: its files into the project. */
struct project_parse {
    const struct study_prepare *want;
    struct project *project;
};

static int parse(void *context, const struct facet_stop *stop,
                 struct facet_error *err)
{
    const struct project_parse *p = context;
    return project_open_stoppable(p->want->files, p->want->nfiles,
                                  p->want->units, stop, p->project, err);
}

/* What reading the cache parses, beside the files' hashes: the building,
 * the key it was made for, and why it is not used (rc not FACET_OK). */
struct cache_read {
    const struct study_prepare *want;
    const char *path;
    struct project *project;
    char found[65];
    struct facet_error why;
    int rc;
};

/* A cache refused is no error of the run: its reason is kept apart, and
 * the parse succeeds so that the files' hashes still decide the run's. */
static int cache_parse(void *context, const struct facet_stop *stop,
                       struct facet_error *err)
{
    struct cache_read *c = context;
    c->rc = project_cache_read_unkeyed(c->path, c->found, c->want->files,
                                       c->want->nfiles, c->want->units, stop,
                                       c->project, &c->why);
    if (c->rc == FACET_EWORK || c->rc == FACET_ESTOP) {
        *err = c->why;
        return c->rc;
    }
    return FACET_OK;
}

static int hash_files(const struct study_prepare *want,
                      const struct facet_stop *stop, char (*digest)[65],
                      struct facet_error *err)
{
    for (size_t i = 0; i < want->nfiles; i++) {
        if (want->known != NULL) {
            memcpy(digest[i], want->known[i], 65);
            continue;
        }
        int rc = sha256_file_stoppable(want->files[i], stop, digest[i], err);
        if (rc != FACET_OK)
            return rc;
    }
    return FACET_OK;
}

/* The cache's path into path, or 0 when the building has none (no
 * database, a path too long). */
static int cache_path(const struct study_prepare *want,
                      const struct project_cache_settings *settings,
                      char *path, size_t size)
{
    if (want->db_path == NULL)
        return 0;
    char (*absolute)[PATH_MAX] = calloc(want->nfiles, sizeof *absolute);
    const char **names = calloc(want->nfiles, sizeof *names);
    int ok = absolute != NULL && names != NULL;
    for (size_t i = 0; ok && i < want->nfiles; i++)
        names[i] = realpath(want->files[i], absolute[i]) ? absolute[i]
                                                         : want->files[i];
    struct facet_error ignored;
    ok = ok && project_cache_path(want->db_path, names, want->nfiles,
                                  settings, path, size, &ignored) == FACET_OK;
    free(absolute);
    free(names);
    return ok;
}

int study_project_prepared(const struct study_prepare *want,
                           const struct study_hooks *hooks,
                           struct project *project, char (*digest)[65],
                           struct facet_error *err)
{
    memset(project, 0, sizeof *project);
    struct facet_stop stop = study_stop(hooks);
    /* The program is hashed only for a cache's key: a building read
     * without a database has no cache. */
    char code[128] = "";
    if (want->db_path != NULL)
        code_identity(code, sizeof code);
    struct project_cache_settings settings = {want->units, want->flip_normals,
                                              want->uv, code};
    char path[4200];
    int cached = cache_path(want, &settings, path, sizeof path);
    int hashed = 0, rc = FACET_OK;
    char key[65];
    if (cached && access(path, F_OK) == 0) {
        /* The files are hashed while the cache is read (study_read_hashed,
         * as when the files themselves are read): the key is compared
         * once both are done, and a cache of another is closed unused. */
        study_stage(hooks, "reading the prepared building");
        struct cache_read context = {want, path, project, "", {0}, FACET_OK};
        if (want->known != NULL) {
            rc = hash_files(want, &stop, digest, err);
            if (rc == FACET_OK)
                rc = cache_parse(&context, &stop, err);
        } else {
            rc = study_read_hashed(want->files, want->nfiles, digest,
                                   cache_parse, &context, &stop, err);
        }
        if (rc != FACET_OK)
            return rc;  /* a file that cannot be read, a stop, no memory */
        hashed = 1;
        project_cache_key((const char (*)[65])digest, want->nfiles,
                          &settings, key);
        if (context.rc == FACET_OK && strcmp(context.found, key) != 0)
            context.rc = project_cache_stale(path, &context.why);
        if (context.rc == FACET_OK) {
            if (!want->units_named)
                rc = project_units_check(project, err);
            if (rc == FACET_OK)
                rc = project_prepare_rest_stoppable(project, &stop, err);
            if (rc == FACET_OK) {
                char line[4400];
                snprintf(line, sizeof line, "reused the prepared building "
                         "%.4200s", path);
                note(hooks, line);
            }
            return rc;
        }
        project_close(project);
        rc = FACET_OK;
        char line[sizeof context.why.message + 64];
        snprintf(line, sizeof line, "%s; preparing it again",
                 context.why.message);
        note(hooks, line);
    }
    study_stage(hooks, "reading the project");
    struct project_parse context = {want, project};
    if (hashed || want->known != NULL) {
        /* digest holds the files' hashes already when a refused cache was
         * read beside them: not hashed twice. */
        if (!hashed)
            rc = hash_files(want, &stop, digest, err);
        if (rc == FACET_OK)
            rc = parse(&context, &stop, err);
    } else {
        rc = study_read_hashed(want->files, want->nfiles, digest, parse,
                               &context, &stop, err);
    }
    if (rc == FACET_OK && !want->units_named)
        rc = project_units_check(project, err);
    if (rc == FACET_OK) {
        study_stage(hooks, "preparing the project's surfaces (UV, curvature)");
        rc = project_prepare_stoppable(project, want->flip_normals, want->uv,
                                       &stop, err);
    }
    if (rc != FACET_OK || !cached)
        return rc;
    study_stage(hooks, "keeping the prepared building");
    project_cache_key((const char (*)[65])digest, want->nfiles, &settings,
                      key);
    struct facet_error why;
    if (project_cache_write(project, key, path, &why) != FACET_OK) {
        char line[sizeof why.message + 64];
        snprintf(line, sizeof line, "%s; the prepared building is not kept",
                 why.message);
        note(hooks, line);
    } else {
        /* The same files' caches of other settings or builds: bounded. A
         * folder that cannot be listed leaves them, which costs only
         * disk. */
        project_cache_prune(path, PROJECT_CACHE_KEEP, &why);
    }
    return FACET_OK;
}
