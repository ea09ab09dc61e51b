/*
 * job.c: a study in a worker thread with its own store connection. See
 * job.h.
 */
#include "job.h"

#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/project/project.h"
#include "core/project/project_grids.h"

struct tui_job {
    pthread_t thread;
    pthread_mutex_t lock;
    char db_path[1024];
    char surface_path[1024];
    char name[128];
    char object[128], group[128];
    /* a project's files and its surfaces' own grids, the request's own
     * copies: the form that asked may close while the run works */
    char files_text[65536];
    const char *files[PROJECT_FILES_MAX];
    char override_text[8192];
    const char *override_names[SURFACE_GRID_OVERRIDES_MAX];
    struct surface_grid overrides[SURFACE_GRID_OVERRIDES_MAX];
    struct study_request request;
    int64_t resume;               /* the run to go on with, or 0 */
    struct tui_job_state state;   /* under lock */
};

static void on_stage(void *context, const char *what)
{
    struct tui_job *job = context;
    pthread_mutex_lock(&job->lock);
    snprintf(job->state.stage, sizeof job->state.stage, "%s", what);
    pthread_mutex_unlock(&job->lock);
}

static void on_progress(void *context, const struct optimize_progress *p)
{
    struct tui_job *job = context;
    pthread_mutex_lock(&job->lock);
    job->state.done = p->done;
    job->state.total = p->total;
    pthread_mutex_unlock(&job->lock);
}

static int on_should_stop(void *context)
{
    struct tui_job *job = context;
    pthread_mutex_lock(&job->lock);
    int stop = job->state.stopping;
    pthread_mutex_unlock(&job->lock);
    return stop;
}

static void on_started(void *context, int64_t run)
{
    struct tui_job *job = context;
    pthread_mutex_lock(&job->lock);
    job->state.run = run;
    pthread_mutex_unlock(&job->lock);
}

static void on_warning(void *context, const char *text)
{
    struct tui_job *job = context;
    pthread_mutex_lock(&job->lock);
    if (job->state.warning[0] == '\0')
        snprintf(job->state.warning, sizeof job->state.warning, "%s", text);
    pthread_mutex_unlock(&job->lock);
}

static void *work(void *context)
{
    struct tui_job *job = context;
    struct facet_error err;
    facet_error_clear(&err);
    struct store *store = NULL;
    int64_t run = 0;
    enum optimize_outcome outcome = OPTIMIZE_DONE;
    int rc = store_open(job->db_path, &store, &err);
    if (rc == FACET_OK) {
        struct study_hooks hooks = {job, on_stage, on_progress,
                                    on_should_stop, on_started, on_warning,
                                    on_stage};
        if (job->resume > 0) {
            run = job->resume;
            rc = study_resume(store, run, &hooks, &outcome, &err);
        } else {
            rc = study_start(store, &job->request, &hooks, &run, &outcome,
                             &err);
        }
        store_close(store);
    }
    pthread_mutex_lock(&job->lock);
    job->state.finished = 1;
    job->state.rc = rc;
    job->state.outcome = outcome;
    job->state.err = err;
    if (run > 0)
        job->state.run = run;
    pthread_mutex_unlock(&job->lock);
    return NULL;
}

/* Starts job's thread; frees job on failure. */
static int launch(struct tui_job *job, struct tui_job **out,
                  struct facet_error *err)
{
    snprintf(job->state.stage, sizeof job->state.stage, "starting");
    pthread_mutex_init(&job->lock, NULL);
    if (pthread_create(&job->thread, NULL, work, job) != 0) {
        pthread_mutex_destroy(&job->lock);
        free(job);
        return facet_error_set(err, FACET_EWORK,
                               "could not start a thread for the run");
    }
    *out = job;
    return FACET_OK;
}

int tui_job_resume(const char *db_path, int64_t run, struct tui_job **out,
                   struct facet_error *err)
{
    *out = NULL;
    struct tui_job *job = calloc(1, sizeof *job);
    if (job == NULL)
        return facet_error_set(err, FACET_EWORK, "out of memory");
    snprintf(job->db_path, sizeof job->db_path, "%s", db_path);
    job->resume = run;
    job->state.run = run;
    return launch(job, out, err);
}

/* names[0 .. n) copied one after another into text (size bytes), out[k]
 * pointing at each copy; -1 when they do not fit or n exceeds max. */
static int copy_names(const char *const *names, size_t n, size_t max,
                      char *text, size_t size, const char **out)
{
    if (n > max)
        return -1;
    size_t used = 0;
    for (size_t k = 0; k < n; k++) {
        size_t length = strlen(names[k]) + 1;
        if (length > size - used)
            return -1;
        memcpy(text + used, names[k], length);
        out[k] = text + used;
        used += length;
    }
    return 0;
}

int tui_job_start(const char *db_path, const struct study_request *request,
                  struct tui_job **out, struct facet_error *err)
{
    *out = NULL;
    struct tui_job *job = calloc(1, sizeof *job);
    if (job == NULL)
        return facet_error_set(err, FACET_EWORK, "out of memory");
    snprintf(job->db_path, sizeof job->db_path, "%s", db_path);
    snprintf(job->surface_path, sizeof job->surface_path, "%s",
             request->surface_path);
    snprintf(job->name, sizeof job->name, "%s",
             request->name ? request->name : "");
    job->request = *request;
    job->request.surface_path = job->surface_path;
    job->request.name = job->name;
    if (request->mesh.object) {
        snprintf(job->object, sizeof job->object, "%s",
                 request->mesh.object);
        job->request.mesh.object = job->object;
    }
    if (request->mesh.group) {
        snprintf(job->group, sizeof job->group, "%s", request->mesh.group);
        job->request.mesh.group = job->group;
    }
    if (copy_names(request->files, request->nfiles, PROJECT_FILES_MAX,
                   job->files_text, sizeof job->files_text, job->files) ||
        copy_names(request->override_names, request->noverrides,
                   SURFACE_GRID_OVERRIDES_MAX, job->override_text,
                   sizeof job->override_text, job->override_names)) {
        free(job);
        return facet_error_set(err, FACET_EINPUT,
                               "the project's file or surface names are "
                               "too many or too long to run from here; "
                               "facet optimize takes them");
    }
    job->request.files = request->nfiles ? job->files : NULL;
    for (size_t k = 0; k < request->noverrides; k++)
        job->overrides[k] = request->overrides[k];
    job->request.override_names =
        request->noverrides ? job->override_names : NULL;
    job->request.overrides = request->noverrides ? job->overrides : NULL;
    return launch(job, out, err);
}

void tui_job_state(struct tui_job *job, struct tui_job_state *out)
{
    pthread_mutex_lock(&job->lock);
    *out = job->state;
    pthread_mutex_unlock(&job->lock);
}

void tui_job_stop(struct tui_job *job)
{
    pthread_mutex_lock(&job->lock);
    job->state.stopping = 1;
    pthread_mutex_unlock(&job->lock);
}

void tui_job_free(struct tui_job *job)
{
    if (job == NULL)
        return;
    tui_job_stop(job);
    pthread_join(job->thread, NULL);
    pthread_mutex_destroy(&job->lock);
    free(job);
}
