/*
 * study_read.c: reading input files while hashing them. See
 * study_internal.h.
 */
#include "study_internal.h"

#include "core/base/parallel.h"
#include "core/base/sha256.h"

/* One of the two threads: the hashes (parse NULL) or the parse. */
struct read_job {
    const char *const *paths;
    size_t npaths;
    char (*digest)[65];
    int (*parse)(void *context, const struct facet_stop *stop,
                 struct facet_error *err);
    void *context;
    const struct facet_stop *stop;
    int rc;
    struct facet_error err;
};

static void read_run(void *argument)
{
    struct read_job *job = argument;
    if (job->parse != NULL) {
        job->rc = job->parse(job->context, job->stop, &job->err);
        return;
    }
    job->rc = FACET_OK;
    for (size_t k = 0; job->rc == FACET_OK && k < job->npaths; k++)
        job->rc = sha256_file_stoppable(job->paths[k], job->stop,
                                        job->digest[k], &job->err);
}

int study_read_hashed(const char *const *paths, size_t npaths,
                      char (*digest)[65],
                      int (*parse)(void *context,
                                   const struct facet_stop *stop,
                                   struct facet_error *err),
                      void *context, const struct facet_stop *stop,
                      struct facet_error *err)
{
    struct read_job job[2] = {
        {paths, npaths, digest, NULL, NULL, stop, FACET_OK,
         {0, FACET_SETTING_NONE, "", ""}},
        {paths, npaths, NULL, parse, context, stop, FACET_OK,
         {0, FACET_SETTING_NONE, "", ""}},
    };
    parallel_run(job, sizeof *job, 2, read_run);
    /* A stop heard by either job is the answer: the other's error, if
     * any, may be only the stop's too. */
    for (int k = 0; k < 2; k++)
        if (job[k].rc == FACET_ESTOP)
            return facet_stop_error(err);
    for (int k = 0; k < 2; k++)
        if (job[k].rc != FACET_OK) {
            *err = job[k].err;
            return job[k].rc;
        }
    return FACET_OK;
}
