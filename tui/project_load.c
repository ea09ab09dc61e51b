/*
 * project_load.c: a project run's building prepared in a thread. See
 * project_load.h.
 */
#include "project_load.h"

#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

struct tui_project_load {
    pthread_t thread;
    pthread_mutex_t lock;
    char db_path[1024];
    struct timespec started;
    struct study_project_view view;  /* the thread's until finished */
    struct tui_project_load_state state;  /* under lock */
};

static void on_stage(void *context, const char *what)
{
    struct tui_project_load *load = context;
    pthread_mutex_lock(&load->lock);
    snprintf(load->state.stage, sizeof load->state.stage, "%s", what);
    pthread_mutex_unlock(&load->lock);
}

static void *work(void *context)
{
    struct tui_project_load *load = context;
    struct facet_error err;
    facet_error_clear(&err);
    struct store *store = NULL;
    int rc = store_open(load->db_path, &store, &err);
    struct run_info run;
    if (rc == FACET_OK)
        rc = store_run_get(store, load->state.run, &run, &err);
    if (rc == FACET_OK) {
        struct study_hooks hooks = {load, on_stage, NULL, NULL, NULL, NULL,
                                    on_stage};
        rc = study_project_view_open(store, &run, &hooks, &load->view,
                                     &err);
    }
    if (store != NULL)
        store_close(store);
    pthread_mutex_lock(&load->lock);
    load->state.finished = 1;
    load->state.rc = rc;
    load->state.err = err;
    pthread_mutex_unlock(&load->lock);
    return NULL;
}

int tui_project_load_start(const char *db_path, int64_t run,
                           struct tui_project_load **out,
                           struct facet_error *err)
{
    *out = NULL;
    struct tui_project_load *load = calloc(1, sizeof *load);
    if (load == NULL)
        return facet_error_set(err, FACET_EWORK, "out of memory");
    snprintf(load->db_path, sizeof load->db_path, "%s", db_path);
    load->state.run = run;
    snprintf(load->state.stage, sizeof load->state.stage, "starting");
    clock_gettime(CLOCK_MONOTONIC, &load->started);
    pthread_mutex_init(&load->lock, NULL);
    if (pthread_create(&load->thread, NULL, work, load) != 0) {
        pthread_mutex_destroy(&load->lock);
        free(load);
        return facet_error_set(err, FACET_EWORK,
                               "could not start a thread to open the "
                               "project");
    }
    *out = load;
    return FACET_OK;
}

void tui_project_load_state(struct tui_project_load *load,
                            struct tui_project_load_state *out)
{
    pthread_mutex_lock(&load->lock);
    *out = load->state;
    pthread_mutex_unlock(&load->lock);
    struct timespec now;
    clock_gettime(CLOCK_MONOTONIC, &now);
    out->seconds = (double)(now.tv_sec - load->started.tv_sec) +
                   (double)(now.tv_nsec - load->started.tv_nsec) * 1e-9;
}

const struct study_project_view *
tui_project_load_view(struct tui_project_load *load)
{
    pthread_mutex_lock(&load->lock);
    int ready = load->state.finished && load->state.rc == FACET_OK;
    pthread_mutex_unlock(&load->lock);
    return ready ? &load->view : NULL;
}

void tui_project_load_free(struct tui_project_load *load)
{
    if (load == NULL)
        return;
    pthread_join(load->thread, NULL);
    pthread_mutex_destroy(&load->lock);
    study_project_view_close(&load->view);
    free(load);
}
