/*
 * project.c: reading a project's files into surfaces. See project.h.
 *
 * Per file: read it (obj_load), find what names its surfaces, check the
 * rules of project.h in one pass over its triangles, bucket the triangles
 * by surface (a counting sort), build each surface's mesh from its bucket
 * (mesh_build_triangles), then free the file before the next is read.
 */
#include "core/project/project.h"

#include <assert.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/base/parallel.h"
#include "core/obj/obj.h"
#include "core/project/project_cache.h"
#include "core/project/project_lengths.h"
#include "core/project/project_seams.h"
#include "core/project/project_locate.h"

#define PROJECT_THREADS_MAX 8  /* surfaces prepared at once */

const char *project_key_name(enum project_key key)
{
    switch (key) {
    case PROJECT_OBJECT: return "object";
    case PROJECT_GROUP:  return "group";
    default:             return "file";
    }
}

/* The file's base name without its directory and a final ".obj". */
static char *file_stem(const char *path)
{
    const char *slash = strrchr(path, '/');
    const char *base = slash != NULL ? slash + 1 : path;
    size_t n = strlen(base);
    if (n > 4 && (strcmp(base + n - 4, ".obj") == 0 ||
                  strcmp(base + n - 4, ".OBJ") == 0))
        n -= 4;
    char *stem = malloc(n + 1);
    if (stem != NULL) {
        memcpy(stem, base, n);
        stem[n] = '\0';
    }
    return stem;
}

static int out_of_memory(struct facet_error *err)
{
    return facet_error_set(err, FACET_EWORK, "out of memory (project)");
}

/* One file's surfaces: what names them, and per name its triangles. */
struct buckets {
    enum project_key key;
    const uint32_t *id;        /* #T: the triangle's name, or NULL (file) */
    size_t nnames;
    const struct obj_name *names;
    size_t *start;             /* nnames + 1 */
    uint32_t *list;            /* #T triangles, name after name */
    size_t *first_face;        /* nnames: f statement of its first face */
};

static void buckets_free(struct buckets *b)
{
    free(b->start);
    free(b->list);
    free(b->first_face);
}

/* The rules of project.h over the file's triangles, then the buckets. */
static int bucket(const char *path, const struct obj_file *obj,
                  struct buckets *b, struct facet_error *err)
{
    memset(b, 0, sizeof *b);
    if (obj->nobjects > 1) {
        b->key = PROJECT_OBJECT;
        b->id = obj->triangle_object;
        b->nnames = obj->nobjects;
        b->names = obj->objects;
    } else if (obj->ngroups > 1) {
        b->key = PROJECT_GROUP;
        b->id = obj->triangle_group;
        b->nnames = obj->ngroups;
        b->names = obj->groups;
    } else {
        b->key = PROJECT_FILE;
        b->nnames = 1;
    }
    const char *kind = project_key_name(b->key);
    b->start = calloc(b->nnames + 1, sizeof *b->start);
    b->first_face = malloc(b->nnames * sizeof *b->first_face);
    b->list = malloc((obj->ntriangles + 1) * sizeof *b->list);
    if (b->start == NULL || b->first_face == NULL || b->list == NULL)
        return out_of_memory(err);

    /* Per-face UV: every corner has a vt, or none has. */
    size_t with_vt = 0, without_vt = SIZE_MAX;
    for (size_t t = 0; t < obj->ntriangles; t++) {
        const struct obj_corner *c = obj->corner + 3 * t;
        if (c[0].vt != OBJ_NONE && c[1].vt != OBJ_NONE &&
            c[2].vt != OBJ_NONE)
            with_vt++;
        else if (without_vt == SIZE_MAX)
            without_vt = t;
    }
    if (with_vt > 0 && without_vt != SIZE_MAX) {
        uint32_t name = b->id != NULL ? b->id[without_vt] : 0;
        size_t line = locate_face(path, obj->triangle_face[without_vt]);
        return facet_error_set(err, FACET_EINPUT,
            "%s:%zu: %s '%s': a face without vt (texture coordinates) in a "
            "file whose faces carry their own UV; export every face with "
            "its texture coordinates", path, line, kind,
            b->key == PROJECT_FILE ? path : b->names[name].text);
    }

    /* Runs: a name's faces come together, once. */
    for (size_t i = 0; i < b->nnames; i++)
        b->first_face[i] = SIZE_MAX;
    uint32_t current = UINT32_MAX;
    for (size_t t = 0; t < obj->ntriangles; t++) {
        uint32_t name = b->id != NULL ? b->id[t] : 0;
        b->start[name + 1]++;
        if (name == current)
            continue;
        current = name;
        if (b->first_face[name] == SIZE_MAX) {
            b->first_face[name] = obj->triangle_face[t];
            continue;
        }
        size_t line = locate_face(path, obj->triangle_face[t]);
        size_t first = locate_face(path, b->first_face[name]);
        if (name == 0)
            return facet_error_set(err, FACET_EINPUT,
                "%s:%zu: a face outside any %s (the first was at line %zu); "
                "give every face an %s name", path, line, kind, first,
                kind);
        return facet_error_set(err, FACET_EINPUT,
            "%s:%zu: %s '%s' again, after other faces (its first face is at "
            "line %zu): two faces with one name would become one surface; "
            "give each face its own name", path, line, kind,
            b->names[name].text, first);
    }
    if (b->key != PROJECT_FILE && b->start[1] > 0) {
        size_t line = locate_face(path, b->first_face[0]);
        return facet_error_set(err, FACET_EINPUT,
            "%s:%zu: a face outside any %s; give every face an %s name",
            path, line, kind, kind);
    }
    for (size_t i = 1; i < b->nnames; i++)
        if (b->start[i + 1] == 0) {
            size_t line = locate_name(path, b->key == PROJECT_OBJECT ?
                                      "o" : "g", b->names[i].text);
            return facet_error_set(err, FACET_EINPUT,
                "%s:%zu: %s '%s' has no faces", path, line, kind,
                b->names[i].text);
        }
    if (obj->ntriangles == 0)
        return facet_error_set(err, FACET_EINPUT, "%s: no faces", path);

    for (size_t i = 0; i < b->nnames; i++)
        b->start[i + 1] += b->start[i];
    size_t *fill = malloc(b->nnames * sizeof *fill);
    if (fill == NULL)
        return out_of_memory(err);
    memcpy(fill, b->start, b->nnames * sizeof *fill);
    for (size_t t = 0; t < obj->ntriangles; t++)
        b->list[fill[b->id != NULL ? b->id[t] : 0]++] = (uint32_t)t;
    free(fill);
    return FACET_OK;
}

static int add_surface(struct project *p, size_t *capacity,
                       struct project_surface **out)
{
    if (p->nsurfaces == *capacity) {
        size_t want = *capacity ? 2 * *capacity : 16;
        struct project_surface *grown =
            realloc(p->surfaces, want * sizeof *grown);
        if (grown == NULL)
            return FACET_EWORK;
        p->surfaces = grown;
        *capacity = want;
    }
    *out = &p->surfaces[p->nsurfaces++];
    memset(*out, 0, sizeof **out);
    return FACET_OK;
}

size_t project_count_named(const struct obj_file *obj)
{
    if (obj->nobjects > 1)
        return obj->nobjects - 1;
    return obj->ngroups > 1 ? obj->ngroups - 1 : 0;
}

/* Adds the surfaces of the file path, read into *obj, and frees *obj. */
static int add_file(struct project *p, size_t *capacity, const char *path,
                    struct obj_file *obj_read, enum mesh_units units,
                    const struct facet_stop *stop, struct facet_error *err)
{
    struct obj_file obj = *obj_read;
    memset(obj_read, 0, sizeof *obj_read);
    struct buckets b;
    int rc = bucket(path, &obj, &b, err);
    for (size_t i = 0; rc == FACET_OK && i < b.nnames; i++) {
        size_t count = b.start[i + 1] - b.start[i];
        if (count == 0)
            continue;  /* the unnamed entry of a file that names them */
        struct project_surface *s;
        if (add_surface(p, capacity, &s) != FACET_OK) {
            rc = out_of_memory(err);
            break;
        }
        s->file = path;
        s->key = b.key;
        s->name = b.key == PROJECT_FILE ? file_stem(path)
                                        : strdup(b.names[i].text);
        s->face = b.first_face[i];
        char label[1024];
        snprintf(label, sizeof label, "%s: %s '%s'", path,
                 project_key_name(b.key), s->name ? s->name : "");
        struct mesh mesh;
        if (s->name == NULL) {
            rc = out_of_memory(err);
            break;
        }
        rc = mesh_build_triangles(&obj, units, b.list + b.start[i], count,
                                  stop, &mesh, err);
        if (rc == FACET_ESTOP) {
            mesh_free(&mesh);
            break;
        }
        if (rc != FACET_OK) {
            char message[sizeof err->message];
            snprintf(message, sizeof message, "%s", err->message);
            rc = facet_error_set(err, rc, "%s: %s", label, message);
            mesh_free(&mesh);
            break;
        }
        rc = surface_from_mesh(label, units, &mesh, &s->surface, err);
        p->ntriangles += s->surface.mesh.ntriangles;
        p->area += s->surface.mesh.area;
    }
    buckets_free(&b);
    obj_free(&obj);
    return rc;
}

static int read_file(struct project *p, size_t *capacity, const char *path,
                     enum mesh_units units, const struct facet_stop *stop,
                     struct facet_error *err)
{
    struct obj_file obj;
    int rc = obj_load_stoppable(path, stop, &obj, err);
    if (rc != FACET_OK) {
        obj_free(&obj);
        return rc;
    }
    return add_file(p, capacity, path, &obj, units, stop, err);
}

static int compare_names(const void *a, const void *b)
{
    const struct project_surface *const *x = a, *const *y = b;
    int c = strcmp((*x)->name, (*y)->name);
    if (c != 0)
        return c;
    return *x < *y ? -1 : *x > *y;
}

/* Two files of the project naming a surface alike. */
static int check_unique(const struct project *p, struct facet_error *err)
{
    if (p->nsurfaces < 2)
        return FACET_OK;
    const struct project_surface **order =
        malloc(p->nsurfaces * sizeof *order);
    if (order == NULL)
        return out_of_memory(err);
    for (size_t i = 0; i < p->nsurfaces; i++)
        order[i] = &p->surfaces[i];
    qsort(order, p->nsurfaces, sizeof *order, compare_names);
    int rc = FACET_OK;
    for (size_t i = 1; i < p->nsurfaces; i++)
        if (strcmp(order[i - 1]->name, order[i]->name) == 0) {
            const struct project_surface *a = order[i - 1], *b = order[i];
            rc = facet_error_set(err, FACET_EINPUT,
                "%s:%zu: %s '%s' is also in %s (line %zu): each surface of "
                "a project needs its own name", b->file,
                locate_face(b->file, b->face), project_key_name(b->key),
                b->name, a->file, locate_face(a->file, a->face));
            break;
        }
    free(order);
    return rc;
}

int project_files_check(size_t npaths, struct facet_error *err)
{
    if (npaths <= PROJECT_FILES_MAX)
        return FACET_OK;
    return facet_error_set(err, FACET_EINPUT,
        "%zu surface files: a project is read from at most %d (name its "
        "surfaces as objects in fewer OBJ files)", npaths,
        PROJECT_FILES_MAX);
}

int project_open(const char *const *paths, size_t npaths,
                 enum mesh_units units, struct project *out,
                 struct facet_error *err)
{
    return project_open_stoppable(paths, npaths, units, NULL, out, err);
}

int project_open_stoppable(const char *const *paths, size_t npaths,
                           enum mesh_units units,
                           const struct facet_stop *stop,
                           struct project *out, struct facet_error *err)
{
    memset(out, 0, sizeof *out);
    assert(npaths >= 1);
    int checked = project_files_check(npaths, err);
    if (checked != FACET_OK)
        return checked;
    out->files = calloc(npaths, sizeof *out->files);
    if (out->files == NULL)
        return out_of_memory(err);
    for (size_t i = 0; i < npaths; i++) {
        if ((out->files[i] = strdup(paths[i])) == NULL)
            return out_of_memory(err);
        out->nfiles++;
    }
    size_t capacity = 0;
    for (size_t i = 0; i < npaths; i++) {
        int rc = read_file(out, &capacity, out->files[i], units, stop, err);
        if (rc != FACET_OK)
            return rc;
    }
    return check_unique(out, err);
}

int project_from_obj(const char *path, struct obj_file *obj,
                     enum mesh_units units, struct project *out,
                     struct facet_error *err)
{
    memset(out, 0, sizeof *out);
    out->files = calloc(1, sizeof *out->files);
    if (out->files == NULL || (out->files[0] = strdup(path)) == NULL) {
        obj_free(obj);
        return out_of_memory(err);
    }
    out->nfiles = 1;
    size_t capacity = 0;
    return add_file(out, &capacity, out->files[0], obj, units, NULL, err);
}

/* One thread's share of project_prepare: surfaces first, first + step,
 * ..., in order, stopping at the first that fails. */
struct prepare_job {
    struct project *project;
    size_t first, step;
    int flip_normals;
    enum param_method method;
    int rest_only;                    /* UV and curvature already set */
    const struct facet_stop *stop;
    struct parallel_failure failure;  /* the surface that failed */
};

static void prepare_run(void *argument)
{
    struct prepare_job *job = argument;
    parallel_failure_clear(&job->failure);
    for (size_t i = job->first; i < job->project->nsurfaces; i += job->step) {
        struct project_surface *s = &job->project->surfaces[i];
        /* A cache of format 3 holds the u and v lengths beside the sums. */
        int cached = job->rest_only && surface_prepared_in_cache(&s->surface);
        int rc = job->rest_only
            ? surface_prepare_rest(&s->surface, job->stop, &job->failure.err)
            : surface_prepare_stoppable(&s->surface, job->flip_normals,
                                        job->method, job->stop,
                                        &job->failure.err);
        if (rc != FACET_OK) {
            job->failure.piece = i;
            job->failure.rc = rc;
            return;
        }
        if (!cached)
            surface_uv_lengths(&s->surface.mesh, s->surface.param.uv,
                               &s->u_length, &s->v_length);
    }
}

int project_prepare(struct project *project, int flip_normals,
                    enum param_method method, struct facet_error *err)
{
    return project_prepare_stoppable(project, flip_normals, method, NULL,
                                     err);
}

/* Deals the surfaces round the threads: the whole preparation, or (rest_only)
 * what follows the UV and curvature. */
static int prepare_all(struct project *project, int flip_normals,
                       enum param_method method, int rest_only,
                       const struct facet_stop *stop, struct facet_error *err)
{
    /* Surfaces are independent: dealt round the threads, so that large
     * and small ones mix. The error reported is the first surface's in
     * project order that fails, whatever the threads' timing. */
    struct prepare_job jobs[PROJECT_THREADS_MAX];
    int n = parallel_jobs(parallel_cpus(PROJECT_THREADS_MAX),
                          project->nsurfaces);
    for (int k = 0; k < n; k++)
        jobs[k] = (struct prepare_job){project, (size_t)k, (size_t)n,
                                       flip_normals, method, rest_only,
                                       stop, {0}};
    parallel_run(jobs, sizeof jobs[0], n, prepare_run);
    /* A stop heard by any thread is the answer: the surface that failed
     * first in project order may only have been cut short by it. */
    for (int k = 0; k < n; k++)
        if (jobs[k].failure.rc == FACET_ESTOP)
            return facet_stop_error(err);
    return parallel_first_failure(&jobs[0].failure, sizeof jobs[0], n, err);
}

int project_prepare_stoppable(struct project *project, int flip_normals,
                              enum param_method method,
                              const struct facet_stop *stop,
                              struct facet_error *err)
{
    return prepare_all(project, flip_normals, method, 0, stop, err);
}

int project_prepare_rest_stoppable(struct project *project,
                                   const struct facet_stop *stop,
                                   struct facet_error *err)
{
    return prepare_all(project, 0, PARAM_AUTO, 1, stop, err);
}

int project_units_check(const struct project *project,
                        struct facet_error *err)
{
    if (project->nsurfaces == 0)
        return FACET_OK;
    double low[3], high[3];
    for (int k = 0; k < 3; k++) {
        low[k] = INFINITY;
        high[k] = -INFINITY;
    }
    for (size_t i = 0; i < project->nsurfaces; i++) {
        const struct mesh *m = &project->surfaces[i].surface.mesh;
        for (int k = 0; k < 3; k++) {
            low[k] = fmin(low[k], m->bbox_min[k]);
            high[k] = fmax(high[k], m->bbox_max[k]);
        }
    }
    double sum = 0;
    for (int k = 0; k < 3; k++)
        sum += (high[k] - low[k]) * (high[k] - low[k]);
    /* Every surface was read in the one unit the project was opened in. */
    enum mesh_units units = project->surfaces[0].surface.units;
    char what[512];
    if (project->nfiles == 1)
        snprintf(what, sizeof what, "%.400s (the building of its %zu "
                 "surfaces)", project->files[0], project->nsurfaces);
    else
        snprintf(what, sizeof what, "the building of %.400s and %zu more "
                 "files", project->files[0], project->nfiles - 1);
    return surface_units_check_size(what, sqrt(sum), units, err);
}

const struct project_surface *project_find(const struct project *project,
                                           const char *name)
{
    for (size_t i = 0; i < project->nsurfaces; i++)
        if (strcmp(project->surfaces[i].name, name) == 0)
            return &project->surfaces[i];
    return NULL;
}

void project_close(struct project *project)
{
    project_cache_release(project);
    for (size_t i = 0; i < project->nsurfaces; i++) {
        free(project->surfaces[i].name);
        surface_close(&project->surfaces[i].surface);
    }
    free(project->surfaces);
    for (size_t i = 0; i < project->nfiles; i++)
        free(project->files[i]);
    free(project->files);
    if (project->seams != NULL) {
        project_seams_free(project->seams);
        free(project->seams);
    }
    memset(project, 0, sizeof *project);
}
