/*
 * project_cache.c: writing and reading a prepared building. See
 * project_cache.h for the format and the checks.
 *
 * The file is mapped and its arrays used where they lie (aligned by the
 * writer's padding), each length checked against the bytes left; the
 * payload is hashed first, in chunks between which the stop is asked;
 * nothing read is handed out before the checksum and the indices have
 * been checked.
 */
#include "core/project/project_cache.h"

#include <assert.h>
#include <dirent.h>
#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/base/parallel.h"
#include "core/base/sha256.h"
#include "core/project/cache_checksum.h"
#include "core/panel/panel_internal.h"

/* The prepared sums are written as they lie in memory and checked as
 * arrays of doubles (and of numbers, for the joints' triangles): a
 * layout with padding or other fields must change the format, not be
 * written as it comes. */
_Static_assert(sizeof(struct panel_prep_point) == 5 * sizeof(double),
               "panel_prep_point: the cache's layout");
_Static_assert(sizeof(struct panel_prep_triangle) == 14 * sizeof(double),
               "panel_prep_triangle: the cache's layout");
_Static_assert(sizeof(struct joint_triangle) ==
               3 * sizeof(double) + 4 * sizeof(uint32_t),
               "joint_triangle: the cache's layout");

#define MAGIC "FACETPRE"
#define PROJECT_CACHE_PREFIX "facet-prepared-"
#define BYTE_ORDER_MARK 0x01020304u
#define NAME_MAX_BYTES 4096
/* Every array starts at a multiple of this from the file's start (the
 * header's size is one): read in place, its doubles are aligned. */
#define ARRAY_ALIGN 8
/* Threads the checksum is checked on, at most. */
#define CHECK_THREADS 8
#define PROJECT_CACHE_STALE \
    "stale (made from other files, settings or another build of Facet)"

/* ---- the key and the name ---- */

static void hash_settings(struct sha256 *h,
                          const struct project_cache_settings *s)
{
    char text[512];
    int n = snprintf(text, sizeof text,
                     "facet prepared building %d\nunits %s\nflip %d\nuv %d\n"
                     "code %.300s\n", PROJECT_CACHE_VERSION,
                     mesh_units_name(s->units), s->flip_normals != 0,
                     (int)s->uv, s->code != NULL ? s->code : "");
    sha256_update(h, text, (size_t)n < sizeof text ? (size_t)n
                                                    : sizeof text - 1);
}

void project_cache_key(const char (*digest)[65], size_t nfiles,
                       const struct project_cache_settings *settings,
                       char key[65])
{
    struct sha256 h;
    sha256_init(&h);
    hash_settings(&h, settings);
    for (size_t i = 0; i < nfiles; i++) {
        sha256_update(&h, "file ", 5);
        sha256_update(&h, digest[i], 64);
        sha256_update(&h, "\n", 1);
    }
    sha256_hex(&h, key);
}

int project_cache_path(const char *db_path, const char *const *paths,
                       size_t npaths,
                       const struct project_cache_settings *settings,
                       char *out, size_t size, struct facet_error *err)
{
    struct sha256 h;
    sha256_init(&h);
    /* Named without the program's identity (the key holds it): a rebuilt
     * Facet finds the cache of the same files and settings stale and
     * writes over it, rather than leaving one more beside it per build. */
    struct project_cache_settings named = *settings;
    named.code = NULL;
    hash_settings(&h, &named);
    /* The building's files alone name the first half: its caches of
     * other settings share it, so that project_cache_prune finds them. */
    struct sha256 b;
    sha256_init(&b);
    for (size_t i = 0; i < npaths; i++) {
        sha256_update(&h, paths[i], strlen(paths[i]) + 1);
        sha256_update(&b, paths[i], strlen(paths[i]) + 1);
    }
    char name[65], building[65];
    sha256_hex(&h, name);
    sha256_hex(&b, building);
    /* Beside the database, in its folder: every database there (a
     * node's shards, a copy) shares it. */
    const char *slash = strrchr(db_path, '/');
    int folder = slash != NULL ? (int)(slash - db_path) + 1 : 0;
    int n = snprintf(out, size, "%.*s" PROJECT_CACHE_PREFIX "%.8s%.8s",
                     folder, db_path, building, name);
    if (n < 0 || (size_t)n >= size)
        return facet_error_set(err, FACET_EINPUT,
            "%.200s: path too long for its prepared building's cache",
            db_path);
    return FACET_OK;
}

/* ---- old caches ---- */

/* One cache of the same building found beside the one kept. */
struct older {
    char name[256];
    struct timespec modified;
};

/* Newest first; ties by name, so that which is kept does not depend on
 * the order the folder lists them in. */
static int newer_first(const void *a, const void *b)
{
    const struct older *x = a, *y = b;
    if (x->modified.tv_sec != y->modified.tv_sec)
        return x->modified.tv_sec > y->modified.tv_sec ? -1 : 1;
    if (x->modified.tv_nsec != y->modified.tv_nsec)
        return x->modified.tv_nsec > y->modified.tv_nsec ? -1 : 1;
    return strcmp(x->name, y->name);
}

static int is_hex(const char *s, size_t n)
{
    for (size_t i = 0; i < n; i++)
        if (!((s[i] >= '0' && s[i] <= '9') || (s[i] >= 'a' && s[i] <= 'f')))
            return 0;
    return s[n] == '\0';
}

/* Whether name, in the folder open as dirfd, is a regular file (not a
 * link to one) that begins with a cache's magic: what Facet wrote. */
static int facet_wrote(int dirfd, const char *name, struct timespec *when)
{
    struct stat st;
    if (fstatat(dirfd, name, &st, AT_SYMLINK_NOFOLLOW) != 0 ||
        !S_ISREG(st.st_mode))
        return 0;
    int fd = openat(dirfd, name, O_RDONLY | O_NOFOLLOW | O_CLOEXEC);
    if (fd < 0)
        return 0;
    char magic[8];
    int ours = read(fd, magic, sizeof magic) == (ssize_t)sizeof magic &&
               memcmp(magic, MAGIC, sizeof magic) == 0;
    close(fd);
    *when = st.st_mtim;
    return ours;
}

int project_cache_prune(const char *path, int keep, struct facet_error *err)
{
    assert(keep >= 1);
    const char *slash = strrchr(path, '/');
    const char *base = slash != NULL ? slash + 1 : path;
    size_t prefix = strlen(PROJECT_CACHE_PREFIX);
    if (strncmp(base, PROJECT_CACHE_PREFIX, prefix) != 0 ||
        !is_hex(base + prefix, 16))
        return facet_error_set(err, FACET_EINPUT,
            "%.300s: not a prepared building's cache name", path);
    char folder[4096];
    int n = snprintf(folder, sizeof folder, "%.*s",
                     slash != NULL ? (int)(slash - path) + 1 : 2,
                     slash != NULL ? path : "./");
    if (n < 0 || (size_t)n >= sizeof folder)
        return facet_error_set(err, FACET_EINPUT, "%.300s: path too long",
                               path);
    DIR *dir = opendir(folder);
    if (dir == NULL)
        return facet_error_set(err, FACET_EWORK, "%.300s: %s", folder,
                               strerror(errno));
    struct older *found = NULL;
    size_t count = 0, capacity = 0;
    int rc = FACET_OK;
    struct dirent *entry;
    while ((entry = readdir(dir)) != NULL) {
        const char *name = entry->d_name;
        /* The same building: the same first 8 hex digits, another
         * settings' last 8. */
        if (strncmp(name, base, prefix + 8) != 0 ||
            !is_hex(name + prefix, 16) || strcmp(name, base) == 0 ||
            strlen(name) >= sizeof found->name)
            continue;
        struct timespec when;
        if (!facet_wrote(dirfd(dir), name, &when))
            continue;
        if (count == capacity) {
            size_t grown = capacity ? 2 * capacity : 8;
            struct older *more = realloc(found, grown * sizeof *found);
            if (more == NULL) {
                rc = facet_error_set(err, FACET_EWORK, "out of memory");
                break;
            }
            found = more;
            capacity = grown;
        }
        snprintf(found[count].name, sizeof found[count].name, "%s", name);
        found[count].modified = when;
        count++;
    }
    if (rc == FACET_OK && count > (size_t)keep - 1) {
        qsort(found, count, sizeof *found, newer_first);
        for (size_t i = (size_t)keep - 1; i < count; i++)
            unlinkat(dirfd(dir), found[i].name, 0);
    }
    closedir(dir);
    free(found);
    return rc;
}

/* ---- writing ---- */

struct writer {
    FILE *file;
    struct cache_checksum hash;
    uint64_t bytes;
    int failed;
};

static void put(struct writer *w, const void *data, size_t n)
{
    if (w->failed || n == 0)
        return;
    if (fwrite(data, 1, n, w->file) != n) {
        w->failed = 1;
        return;
    }
    cache_checksum_update(&w->hash, data, n);
    w->bytes += n;
}

static void put_u8(struct writer *w, unsigned v)
{
    unsigned char b = (unsigned char)v;
    put(w, &b, 1);
}

static void put_u32(struct writer *w, uint32_t v) { put(w, &v, sizeof v); }
static void put_u64(struct writer *w, uint64_t v) { put(w, &v, sizeof v); }
static void put_f64(struct writer *w, double v) { put(w, &v, sizeof v); }

/* An array of count elements of size bytes: a presence byte, then the
 * elements when data is not NULL. */
static void put_array(struct writer *w, const void *data, size_t count,
                      size_t size)
{
    put_u8(w, data != NULL);
    if (data == NULL)
        return;
    static const unsigned char zeros[ARRAY_ALIGN] = {0};
    put(w, zeros, (ARRAY_ALIGN - w->bytes % ARRAY_ALIGN) % ARRAY_ALIGN);
    put(w, data, count * size);
}

static void put_mesh(struct writer *w, const struct mesh *m)
{
    size_t V = m->nvertices, T = m->ntriangles;
    put_u64(w, V);
    put_u64(w, T);
    put_array(w, m->position, 3 * V, sizeof *m->position);
    put_array(w, m->source_vertex, V, sizeof *m->source_vertex);
    put_array(w, m->triangle, 3 * T, sizeof *m->triangle);
    put_array(w, m->source_face, T, sizeof *m->source_face);
    put_array(w, m->face_normal, 3 * T, sizeof *m->face_normal);
    put_array(w, m->face_area, T, sizeof *m->face_area);
    put_u8(w, m->has_uv != 0);
    put_array(w, m->uv, 6 * T, sizeof *m->uv);
    put_u8(w, m->has_normals != 0);
    put_array(w, m->corner_normal, 9 * T, sizeof *m->corner_normal);
    put_array(w, m->neighbour, 3 * T, sizeof *m->neighbour);
    put_u64(w, m->nonmanifold_edges);
    put_u64(w, m->ndegenerate);
    put_array(w, m->vertex_start, V + 1, sizeof *m->vertex_start);
    put_u64(w, m->vertex_start != NULL ? m->vertex_start[V] : 0);
    put_array(w, m->vertex_triangles,
              m->vertex_start != NULL ? m->vertex_start[V] : 0,
              sizeof *m->vertex_triangles);
    put_array(w, m->on_boundary, V, sizeof *m->on_boundary);
    put_u64(w, m->nloops);
    put_array(w, m->loop_start, m->nloops + 1, sizeof *m->loop_start);
    put_u64(w, m->loop_start != NULL ? m->loop_start[m->nloops] : 0);
    put_array(w, m->loop_vertices,
              m->loop_start != NULL ? m->loop_start[m->nloops] : 0,
              sizeof *m->loop_vertices);
    put_u64(w, m->ncomponents);
    put_array(w, m->component, T, sizeof *m->component);
    put_f64(w, m->area);
    for (int k = 0; k < 3; k++)
        put_f64(w, m->bbox_min[k]);
    for (int k = 0; k < 3; k++)
        put_f64(w, m->bbox_max[k]);
}

static void put_param(struct writer *w, const struct parameterization *p,
                      const struct mesh *m)
{
    size_t T = m->ntriangles;
    put_u32(w, (uint32_t)p->method);
    /* The file's vt taken as they are is the mesh's UV again: said, not
     * written twice (on the skin, 100 MB less to write, read and hash). */
    int same = p->uv != NULL && m->uv != NULL &&
               memcmp(p->uv, m->uv, 6 * T * sizeof *p->uv) == 0;
    put_u8(w, same);
    if (!same)
        put_array(w, p->uv, 6 * T, sizeof *p->uv);
    put_u64(w, p->report.triangles);
    put_u64(w, p->report.degenerate);
    put_u64(w, p->report.flipped);
    put_u64(w, p->report.overlapping);
    put_f64(w, p->report.uv_area);
    put_f64(w, p->report.umin);
    put_f64(w, p->report.vmin);
    put_f64(w, p->report.umax);
    put_f64(w, p->report.vmax);
    put(w, p->reason, sizeof p->reason);
    put_u32(w, (uint32_t)p->grid_nu);
    put_u32(w, (uint32_t)p->grid_nv);
    put_u64(w, p->holes);
}

static void put_curvature(struct writer *w, const struct curvature *c)
{
    size_t V = c->nvertices;
    put_u64(w, V);
    put_array(w, c->k1, V, sizeof *c->k1);
    put_array(w, c->k2, V, sizeof *c->k2);
    put_array(w, c->dir1, 3 * V, sizeof *c->dir1);
    put_array(w, c->dir2, 3 * V, sizeof *c->dir2);
    put_array(w, c->normal, 3 * V, sizeof *c->normal);
    put_array(w, c->surface_normal, 3 * V, sizeof *c->surface_normal);
    put_array(w, c->k1_error, V, sizeof *c->k1_error);
    put_array(w, c->k2_error, V, sizeof *c->k2_error);
}

/* Format 3: what surface_prepare_rest made from the mesh, UV and
 * curvature (its lookup's buckets, the facets' sag, the panel sums, the
 * joints' prep) and the u and v lengths, so that a second start does not
 * make them again (on the skin, about 3 s of CPU). The lookup's box and
 * grid are not written: the reader remakes them from the UV
 * (uv_index_frame). */
static void put_prepared(struct writer *w, const struct project_surface *ps)
{
    const struct surface *s = &ps->surface;
    size_t T = s->mesh.ntriangles;
    put_f64(w, s->facet_sag);
    put_f64(w, ps->u_length);
    put_f64(w, ps->v_length);
    const struct uv_index *x = &s->uv;
    size_t cells = (size_t)x->ncells_u * (size_t)x->ncells_v;
    put_u64(w, cells);
    put_u64(w, x->cell_start[cells]);
    put_array(w, x->cell_start, cells + 1, sizeof *x->cell_start);
    put_array(w, x->cell_triangles, x->cell_start[cells],
              sizeof *x->cell_triangles);
    const struct panel_prep *p = &s->panels;
    put_u64(w, p->npoints);
    put_array(w, p->point_uv, 2 * p->npoints, sizeof *p->point_uv);
    put_array(w, p->point, p->npoints, sizeof *p->point);
    put_array(w, p->corner, 3 * T, sizeof *p->corner);
    put_array(w, p->triangle, T, sizeof *p->triangle);
    const struct joint_prep *j = &s->joints;
    put_f64(w, j->outline);
    for (int axis = 0; axis < 2; axis++) {
        put_f64(w, j->reach[axis]);
        put_array(w, j->order[axis], T, sizeof *j->order[axis]);
        put_array(w, j->least[axis], T, sizeof *j->least[axis]);
        put_array(w, j->triangle[axis], T, sizeof *j->triangle[axis]);
    }
}

static void put_payload(struct writer *w, const struct project *p)
{
    put_u64(w, p->nsurfaces);
    for (size_t i = 0; i < p->nsurfaces; i++) {
        const struct project_surface *ps = &p->surfaces[i];
        size_t file = 0;
        while (file + 1 < p->nfiles && p->files[file] != ps->file)
            file++;
        size_t n = strlen(ps->name);
        put_u64(w, n);
        put(w, ps->name, n);
        put_u32(w, (uint32_t)ps->key);
        put_u32(w, (uint32_t)file);
        put_u64(w, ps->face);
        put_mesh(w, &ps->surface.mesh);
        put_param(w, &ps->surface.param, &ps->surface.mesh);
        put_curvature(w, &ps->surface.curvature);
        put_prepared(w, ps);
    }
}

static void header_bytes(unsigned char out[PROJECT_CACHE_HEADER],
                         uint32_t version, uint64_t payload,
                         const char key[65], const char checksum[65])
{
    uint32_t order = BYTE_ORDER_MARK;
    memcpy(out, MAGIC, 8);
    memcpy(out + 8, &version, 4);
    memcpy(out + 12, &order, 4);
    memcpy(out + 16, &payload, 8);
    memcpy(out + 24, key, 64);
    memcpy(out + 88, checksum, 64);
}

int project_cache_write(const struct project *project, const char key[65],
                        const char *path, struct facet_error *err)
{
    for (size_t i = 0; i < project->nsurfaces; i++)
        if (!project->surfaces[i].surface.prepared)
            return facet_error_set(err, FACET_EWORK,
                "%.300s: the building is not prepared", path);
    char temporary[4200];
    int n = snprintf(temporary, sizeof temporary, "%s.tmp.%ld", path,
                     (long)getpid());
    if (n < 0 || (size_t)n >= sizeof temporary)
        return facet_error_set(err, FACET_EWORK, "%.300s: path too long",
                               path);
    FILE *file = fopen(temporary, "wb");
    if (file == NULL)
        return facet_error_set(err, FACET_EWORK, "%.300s: %s", temporary,
                               strerror(errno));
    static const char zeros[65] = "0000000000000000000000000000000000000000"
                                  "000000000000000000000000";
    unsigned char header[PROJECT_CACHE_HEADER];
    header_bytes(header, PROJECT_CACHE_VERSION, 0, key, zeros);
    struct writer w;
    memset(&w, 0, sizeof w);
    w.file = file;
    int failed = fwrite(header, 1, sizeof header, file) != sizeof header;
    cache_checksum_init(&w.hash);
    if (!failed) {
        put_payload(&w, project);
        failed = w.failed;
    }
    if (!failed) {
        char checksum[65];
        cache_checksum_hex(&w.hash, checksum);
        header_bytes(header, PROJECT_CACHE_VERSION, w.bytes, key, checksum);
        failed = fseek(file, 0, SEEK_SET) != 0 ||
                 fwrite(header, 1, sizeof header, file) != sizeof header;
    }
    int saved = errno;
    failed |= fflush(file) != 0;
    if (failed)
        saved = errno;
    if (fclose(file) != 0 && !failed) {
        failed = 1;
        saved = errno;
    }
    if (!failed && rename(temporary, path) != 0) {
        failed = 1;
        saved = errno;
    }
    if (failed) {
        unlink(temporary);
        return facet_error_set(err, FACET_EWORK, "%.300s: %s", path,
                               saved != 0 ? strerror(saved) : "write failed");
    }
    return FACET_OK;
}

/* ---- reading ---- */

/* The payload, read in place: every array the project gets points into
 * the file's bytes (mapped, or a copy for read_file), which the project
 * then owns (project_cache_release). */
struct reader {
    const unsigned char *base;  /* the file's first byte */
    uint64_t at;                /* the next byte's offset from base */
    uint64_t end;               /* the payload's end's */
    const char *why;            /* the first thing found wrong, or NULL */
};

static int get(struct reader *r, void *data, size_t n)
{
    if (r->why != NULL)
        return 0;
    if (n > r->end - r->at) {
        r->why = "truncated or damaged (a length runs past its end)";
        return 0;
    }
    if (n > 0)
        memcpy(data, r->base + r->at, n);
    r->at += n;
    return 1;
}

static unsigned get_u8(struct reader *r)
{
    unsigned char b = 0;
    get(r, &b, 1);
    return b;
}

static uint32_t get_u32(struct reader *r)
{
    uint32_t v = 0;
    get(r, &v, sizeof v);
    return v;
}

static uint64_t get_u64(struct reader *r)
{
    uint64_t v = 0;
    get(r, &v, sizeof v);
    return v;
}

static double get_f64(struct reader *r)
{
    double v = 0;
    get(r, &v, sizeof v);
    return v;
}

/* Points *out at an array written by put_array, where it lies in the
 * file (NULL when it was absent). Its padding must be zeros and its
 * count must fit in the bytes left: nothing is allocated. */
static void get_array(struct reader *r, void *out, uint64_t count,
                      size_t size)
{
    void **array = out;
    *array = NULL;
    if (get_u8(r) == 0 || r->why != NULL)
        return;
    unsigned char pad[ARRAY_ALIGN];
    size_t n = (size_t)((ARRAY_ALIGN - r->at % ARRAY_ALIGN) % ARRAY_ALIGN);
    static const unsigned char zeros[ARRAY_ALIGN] = {0};
    if (get(r, pad, n) && memcmp(pad, zeros, n) != 0)
        r->why = "damaged (an array's padding)";
    if (r->why != NULL)
        return;
    if (count > (r->end - r->at) / size) {
        r->why = "truncated or damaged (a length runs past its end)";
        return;
    }
    *array = (void *)(r->base + r->at);
    r->at += count * size;
}

/* A count read from the file that must itself be plausible: at most the
 * bytes left (every element takes at least one) and below 2^32. */
static uint64_t get_count(struct reader *r)
{
    uint64_t n = get_u64(r);
    if (r->why == NULL && (n > r->end - r->at || n >= UINT32_MAX)) {
        r->why = "damaged (a count past its end)";
        return 0;
    }
    return n;
}

static void get_mesh(struct reader *r, struct mesh *m)
{
    memset(m, 0, sizeof *m);
    uint64_t V = get_count(r), T = get_count(r);
    m->nvertices = (size_t)V;
    m->ntriangles = (size_t)T;
    get_array(r, &m->position, 3 * V, sizeof *m->position);
    get_array(r, &m->source_vertex, V, sizeof *m->source_vertex);
    get_array(r, &m->triangle, 3 * T, sizeof *m->triangle);
    get_array(r, &m->source_face, T, sizeof *m->source_face);
    get_array(r, &m->face_normal, 3 * T, sizeof *m->face_normal);
    get_array(r, &m->face_area, T, sizeof *m->face_area);
    m->has_uv = (int)get_u8(r);
    get_array(r, &m->uv, 6 * T, sizeof *m->uv);
    m->has_normals = (int)get_u8(r);
    get_array(r, &m->corner_normal, 9 * T, sizeof *m->corner_normal);
    get_array(r, &m->neighbour, 3 * T, sizeof *m->neighbour);
    m->nonmanifold_edges = (size_t)get_u64(r);
    m->ndegenerate = (size_t)get_u64(r);
    get_array(r, &m->vertex_start, V + 1, sizeof *m->vertex_start);
    uint64_t incident = get_count(r);
    get_array(r, &m->vertex_triangles, incident,
              sizeof *m->vertex_triangles);
    get_array(r, &m->on_boundary, V, sizeof *m->on_boundary);
    m->nloops = (size_t)get_count(r);
    get_array(r, &m->loop_start, (uint64_t)m->nloops + 1,
              sizeof *m->loop_start);
    uint64_t looped = get_count(r);
    get_array(r, &m->loop_vertices, looped, sizeof *m->loop_vertices);
    m->ncomponents = (size_t)get_count(r);
    get_array(r, &m->component, T, sizeof *m->component);
    m->area = get_f64(r);
    for (int k = 0; k < 3; k++)
        m->bbox_min[k] = get_f64(r);
    for (int k = 0; k < 3; k++)
        m->bbox_max[k] = get_f64(r);
    if (r->why != NULL)
        return;
    /* What every later stage indexes by must be there and agree. */
    if (m->position == NULL || m->triangle == NULL ||
        m->face_normal == NULL || m->face_area == NULL ||
        m->neighbour == NULL || m->vertex_start == NULL ||
        m->vertex_triangles == NULL || m->on_boundary == NULL ||
        m->loop_start == NULL || m->component == NULL ||
        (m->has_uv && m->uv == NULL) ||
        (m->has_normals && m->corner_normal == NULL) ||
        m->vertex_start[0] != 0 || m->vertex_start[V] != incident ||
        m->loop_start[0] != 0 || m->loop_start[m->nloops] != looped ||
        (looped > 0 && m->loop_vertices == NULL))
        r->why = "damaged (its mesh is incomplete)";
}

static void get_param(struct reader *r, struct parameterization *p,
                      const struct mesh *m)
{
    memset(p, 0, sizeof *p);
    size_t T = m->ntriangles;
    p->method = (enum param_method)get_u32(r);
    int same = (int)get_u8(r);
    /* The mesh's UV taken as it is: the same bytes, shared in place. */
    if (same)
        p->uv = m->uv;
    else
        get_array(r, &p->uv, 6 * (uint64_t)T, sizeof *p->uv);
    p->report.triangles = (size_t)get_u64(r);
    p->report.degenerate = (size_t)get_u64(r);
    p->report.flipped = (size_t)get_u64(r);
    p->report.overlapping = (size_t)get_u64(r);
    p->report.uv_area = get_f64(r);
    p->report.umin = get_f64(r);
    p->report.vmin = get_f64(r);
    p->report.umax = get_f64(r);
    p->report.vmax = get_f64(r);
    get(r, p->reason, sizeof p->reason);
    p->reason[sizeof p->reason - 1] = '\0';
    p->grid_nu = (int)get_u32(r);
    p->grid_nv = (int)get_u32(r);
    p->holes = (size_t)get_u64(r);
    if (r->why == NULL && (p->uv == NULL || p->method < PARAM_VT ||
                           p->method > PARAM_HARMONIC))
        r->why = "damaged (its UV is incomplete)";
}

static void get_curvature(struct reader *r, struct curvature *c,
                          const struct mesh *m)
{
    memset(c, 0, sizeof *c);
    uint64_t V = get_count(r);
    c->nvertices = (size_t)V;
    get_array(r, &c->k1, V, sizeof *c->k1);
    get_array(r, &c->k2, V, sizeof *c->k2);
    get_array(r, &c->dir1, 3 * V, sizeof *c->dir1);
    get_array(r, &c->dir2, 3 * V, sizeof *c->dir2);
    get_array(r, &c->normal, 3 * V, sizeof *c->normal);
    get_array(r, &c->surface_normal, 3 * V, sizeof *c->surface_normal);
    get_array(r, &c->k1_error, V, sizeof *c->k1_error);
    get_array(r, &c->k2_error, V, sizeof *c->k2_error);
    if (r->why == NULL &&
        (V != m->nvertices || c->k1 == NULL || c->k2 == NULL ||
         c->dir1 == NULL || c->dir2 == NULL || c->normal == NULL ||
         c->surface_normal == NULL || c->k1_error == NULL ||
         c->k2_error == NULL))
        r->why = "damaged (its curvature is incomplete)";
}

static int all_below(const uint32_t *a, size_t n, uint64_t limit,
                     int none_allowed)
{
    for (size_t i = 0; i < n; i++)
        if (a[i] >= limit && !(none_allowed && a[i] == MESH_NONE))
            return 0;
    return 1;
}

static int all_finite(const double *a, size_t n)
{
    for (size_t i = 0; i < n; i++)
        if (!isfinite(a[i]))
            return 0;
    return 1;
}

static int non_decreasing(const uint32_t *a, size_t n)
{
    for (size_t i = 1; i < n; i++)
        if (a[i] < a[i - 1])
            return 0;
    return 1;
}

/* The indices and numbers later stages trust, once the checksum held:
 * a file made by hand with a right checksum is still refused, not read
 * out of bounds. */
static const char *check_surface(const struct surface *s)
{
    const struct mesh *m = &s->mesh;
    size_t V = m->nvertices, T = m->ntriangles;
    if (T == 0 || V == 0)
        return "damaged (a surface without triangles)";
    if (!all_below(m->triangle, 3 * T, V, 0) ||
        !all_below(m->neighbour, 3 * T, T, 1) ||
        !non_decreasing(m->vertex_start, V + 1) ||
        !all_below(m->vertex_triangles, m->vertex_start[V], T, 0) ||
        !non_decreasing(m->loop_start, m->nloops + 1) ||
        !all_below(m->loop_vertices, m->loop_start[m->nloops], V, 0) ||
        !all_below(m->component, T, m->ncomponents, 0))
        return "damaged (an index out of range)";
    if (!all_finite(m->position, 3 * V) ||
        !all_finite(s->param.uv, 6 * T) ||
        (m->uv != NULL && !all_finite(m->uv, 6 * T)))
        return "damaged (a coordinate is not a number)";
    /* A NaN or infinite curvature would classify a panel as no surface
     * bends: refused as a coordinate is. */
    const struct curvature *c = &s->curvature;
    if (!all_finite(c->k1, V) || !all_finite(c->k2, V) ||
        !all_finite(c->dir1, 3 * V) || !all_finite(c->dir2, 3 * V) ||
        !all_finite(c->normal, 3 * V) ||
        !all_finite(c->surface_normal, 3 * V) ||
        !all_finite(c->k1_error, V) || !all_finite(c->k2_error, V))
        return "damaged (a curvature is not a number)";
    return NULL;
}

/* One surface's fields as read, before they become the project's; only
 * the name is allocated, the arrays lie in the file's bytes. */
struct read_surface {
    char *name;
    uint32_t key, file;
    uint64_t face;
    struct mesh mesh;
    struct parameterization param;
    struct curvature curvature;
    /* Format 3's prepared sections (put_prepared), their arrays in the
     * file's bytes; uv's box and grid are remade (check_prepared). */
    double facet_sag, u_length, v_length;
    uint64_t cells, entries;
    struct uv_index uv;
    struct panel_prep panels;
    struct joint_prep joints;
};

static void get_prepared(struct reader *r, struct read_surface *s)
{
    uint64_t T = s->mesh.ntriangles;
    s->facet_sag = get_f64(r);
    s->u_length = get_f64(r);
    s->v_length = get_f64(r);
    s->cells = get_count(r);
    s->entries = get_count(r);
    get_array(r, &s->uv.cell_start, s->cells + 1, sizeof *s->uv.cell_start);
    get_array(r, &s->uv.cell_triangles, s->entries,
              sizeof *s->uv.cell_triangles);
    struct panel_prep *p = &s->panels;
    p->npoints = (size_t)get_count(r);
    get_array(r, &p->point_uv, 2 * (uint64_t)p->npoints, sizeof *p->point_uv);
    get_array(r, &p->point, p->npoints, sizeof *p->point);
    get_array(r, &p->corner, 3 * T, sizeof *p->corner);
    get_array(r, &p->triangle, T, sizeof *p->triangle);
    struct joint_prep *j = &s->joints;
    j->ntriangles = (size_t)T;
    j->outline = get_f64(r);
    for (int axis = 0; axis < 2; axis++) {
        j->reach[axis] = get_f64(r);
        get_array(r, &j->order[axis], T, sizeof *j->order[axis]);
        get_array(r, &j->least[axis], T, sizeof *j->least[axis]);
        get_array(r, &j->triangle[axis], T, sizeof *j->triangle[axis]);
    }
    if (r->why == NULL &&
        (s->uv.cell_start == NULL || s->uv.cell_triangles == NULL ||
         p->point_uv == NULL || p->point == NULL || p->corner == NULL ||
         p->triangle == NULL || j->order[0] == NULL || j->order[1] == NULL ||
         j->least[0] == NULL || j->least[1] == NULL ||
         j->triangle[0] == NULL || j->triangle[1] == NULL))
        r->why = "damaged (its prepared sums are incomplete)";
}

static int finite_length(double x)
{
    return isfinite(x) && x >= 0;
}

/* The prepared sections against the mesh, UV and curvature they were
 * made from (checked already, check_surface): every count, index and
 * number, so that a file made by hand with a right checksum is refused
 * rather than read out of bounds or into a wrong lookup. The lookup's box
 * and grid are remade from the UV here (s->uv gets them). */
static const char *check_prepared(struct read_surface *s)
{
    const struct mesh *m = &s->mesh;
    size_t V = m->nvertices, T = m->ntriangles;
    if (!finite_length(s->facet_sag) || !finite_length(s->u_length) ||
        !finite_length(s->v_length))
        return "damaged (a length is not a number)";

    /* The lookup: the cells the UV gives, each listing triangles. */
    struct facet_error ignored;
    uint32_t *cell_start = s->uv.cell_start,
             *cell_triangles = s->uv.cell_triangles;
    if (uv_index_frame(s->param.uv, T, &s->uv, &ignored) != FACET_OK)
        return "damaged (a coordinate is not a number)";
    s->uv.cell_start = cell_start;
    s->uv.cell_triangles = cell_triangles;
    if (s->cells != (uint64_t)s->uv.ncells_u * (uint64_t)s->uv.ncells_v ||
        cell_start[0] != 0 || cell_start[s->cells] != s->entries ||
        !non_decreasing(cell_start, (size_t)s->cells + 1))
        return "damaged (its UV lookup's cells)";
    if (!all_below(cell_triangles, (size_t)s->entries, T, 0))
        return "damaged (an index out of range)";

    /* The panel sums: each corner's point, numbered as first met (as
     * panel_prep_build numbers them: every point is some corner's), at
     * that corner's UV, position and curvature. */
    const struct panel_prep *p = &s->panels;
    size_t n = p->npoints, met = 0;
    if (n == 0 || n > 3 * T)
        return "damaged (its count of panel points)";
    const double *uv = s->param.uv;
    for (size_t c = 0; c < 3 * T; c++) {
        uint32_t q = p->corner[c];
        if (q > met || q >= n)
            return "damaged (an index out of range)";
        met += q == met;
        const struct panel_prep_point *P = &p->point[q];
        size_t v = m->triangle[c];
        const double *x = m->position + 3 * v;
        if (p->point_uv[2 * (size_t)q] != uv[2 * c] ||
            p->point_uv[2 * (size_t)q + 1] != uv[2 * c + 1] ||
            P->position[0] != x[0] || P->position[1] != x[1] ||
            P->position[2] != x[2] || P->k1 != s->curvature.k1[v] ||
            P->k2 != s->curvature.k2[v])
            return "damaged (a panel point is not its corner's)";
    }
    if (met != n)
        return "damaged (its count of panel points)";
    if (!all_finite((const double *)p->triangle,
                    T * (sizeof *p->triangle / sizeof(double))))
        return "damaged (a panel sum is not a number)";

    /* The joints' prep: along each axis every triangle's corners as the
     * UV and the mesh give them, in order of their least coordinate. */
    const struct joint_prep *j = &s->joints;
    if (!finite_length(j->outline))
        return "damaged (a length is not a number)";
    for (int axis = 0; axis < 2; axis++) {
        if (!finite_length(j->reach[axis]))
            return "damaged (a length is not a number)";
        for (size_t i = 0; i < T; i++) {
            uint32_t t = j->order[axis][i];
            if (t >= T)
                return "damaged (an index out of range)";
            const struct joint_triangle *J = &j->triangle[axis][i];
            double least = J->x[0];
            for (int k = 0; k < 3; k++) {
                size_t c = 3 * (size_t)t + (size_t)k;
                if (J->x[k] != uv[2 * c + (size_t)axis] ||
                    J->vertex[k] != m->triangle[c])
                    return "damaged (a joint triangle is not its mesh's)";
                least = fmin(least, J->x[k]);
            }
            if (J->outline > 7 || j->least[axis][i] != least ||
                (i > 0 && !(j->least[axis][i - 1] <= least)))
                return "damaged (its joints' order)";
        }
    }
    (void)V;
    return NULL;
}

static void get_surface(struct reader *r, struct read_surface *s,
                        size_t npaths)
{
    memset(s, 0, sizeof *s);
    uint64_t n = get_u64(r);
    if (r->why == NULL && (n == 0 || n > NAME_MAX_BYTES)) {
        r->why = "damaged (a surface's name)";
        return;
    }
    if (r->why != NULL)
        return;
    s->name = malloc((size_t)n + 1);
    if (s->name == NULL) {
        r->why = "too large to read (out of memory)";
        return;
    }
    get(r, s->name, (size_t)n);
    s->name[n] = '\0';
    if (r->why == NULL && strlen(s->name) != n)
        r->why = "damaged (a surface's name)";
    s->key = get_u32(r);
    s->file = get_u32(r);
    s->face = get_u64(r);
    if (r->why == NULL && (s->key > PROJECT_GROUP || s->file >= npaths))
        r->why = "damaged (a surface's file)";
    if (r->why != NULL)
        return;
    get_mesh(r, &s->mesh);
    get_param(r, &s->param, &s->mesh);
    get_curvature(r, &s->curvature, &s->mesh);
    get_prepared(r, s);
}

/* Makes out the project of the surfaces read, as project_open makes it:
 * the same paths, names, labels, checks and warnings, the same sums in
 * the same order. Takes the surfaces' names and structs over. */
static int build(struct read_surface *read, size_t n,
                 const char *const *paths, size_t npaths,
                 enum mesh_units units, struct project *out,
                 struct facet_error *err)
{
    out->files = calloc(npaths, sizeof *out->files);
    out->surfaces = calloc(n ? n : 1, sizeof *out->surfaces);
    if (out->files == NULL || out->surfaces == NULL)
        return facet_error_set(err, FACET_EWORK, "out of memory");
    for (size_t i = 0; i < npaths; i++) {
        if ((out->files[i] = strdup(paths[i])) == NULL)
            return facet_error_set(err, FACET_EWORK, "out of memory");
        out->nfiles++;
    }
    for (size_t i = 0; i < n; i++) {
        struct project_surface *ps = &out->surfaces[i];
        struct read_surface *rs = &read[i];
        out->nsurfaces++;
        ps->name = rs->name;
        rs->name = NULL;
        ps->file = out->files[rs->file];
        ps->key = (enum project_key)rs->key;
        ps->face = (size_t)rs->face;
        char label[1024];
        snprintf(label, sizeof label, "%s: %s '%s'", ps->file,
                 project_key_name(ps->key), ps->name);
        int rc = surface_from_mesh(label, units, &rs->mesh, &ps->surface,
                                   err);
        ps->surface.param = rs->param;
        memset(&rs->param, 0, sizeof rs->param);
        ps->surface.curvature = rs->curvature;
        memset(&rs->curvature, 0, sizeof rs->curvature);
        /* The prepared sums, pointed at the surface where it now lies. */
        struct surface *s = &ps->surface;
        s->uv = rs->uv;
        s->panels = rs->panels;
        s->panels.mesh = &s->mesh;
        s->panels.index = &s->uv;
        s->panels.curvature = &s->curvature;
        s->joints = rs->joints;
        s->facet_sag = rs->facet_sag;
        ps->u_length = rs->u_length;
        ps->v_length = rs->v_length;
        if (rc != FACET_OK)
            return rc;
        out->ntriangles += ps->surface.mesh.ntriangles;
        out->area += ps->surface.mesh.area;
    }
    return FACET_OK;
}

static int refuse(const char *name, const char *why,
                  struct facet_error *err)
{
    return facet_error_set(err, FACET_EINPUT,
                           "%.300s: prepared building not used: %s", name,
                           why);
}

/* Whether p lies in the bytes [base, base + size). */
static int inside(const void *p, const unsigned char *base, size_t size)
{
    const unsigned char *c = p;
    return c != NULL && c >= base && c < base + size;
}

/* Forgets, in surface s, every array that lies in the bytes [base, base +
 * size): they are the file's, not the surface's to free. */
static void detach(struct surface *s, const unsigned char *base,
                   size_t size)
{
    struct mesh *m = &s->mesh;
    if (inside(m->position, base, size)) m->position = NULL;
    if (inside(m->source_vertex, base, size)) m->source_vertex = NULL;
    if (inside(m->triangle, base, size)) m->triangle = NULL;
    if (inside(m->source_face, base, size)) m->source_face = NULL;
    if (inside(m->face_normal, base, size)) m->face_normal = NULL;
    if (inside(m->face_area, base, size)) m->face_area = NULL;
    if (inside(m->uv, base, size)) m->uv = NULL;
    if (inside(m->corner_normal, base, size)) m->corner_normal = NULL;
    if (inside(m->neighbour, base, size)) m->neighbour = NULL;
    if (inside(m->vertex_start, base, size)) m->vertex_start = NULL;
    if (inside(m->vertex_triangles, base, size)) m->vertex_triangles = NULL;
    if (inside(m->on_boundary, base, size)) m->on_boundary = NULL;
    if (inside(m->loop_start, base, size)) m->loop_start = NULL;
    if (inside(m->loop_vertices, base, size)) m->loop_vertices = NULL;
    if (inside(m->component, base, size)) m->component = NULL;
    if (inside(s->param.uv, base, size)) s->param.uv = NULL;
    struct curvature *c = &s->curvature;
    if (inside(c->k1, base, size)) c->k1 = NULL;
    if (inside(c->k2, base, size)) c->k2 = NULL;
    if (inside(c->dir1, base, size)) c->dir1 = NULL;
    if (inside(c->dir2, base, size)) c->dir2 = NULL;
    if (inside(c->normal, base, size)) c->normal = NULL;
    if (inside(c->surface_normal, base, size)) c->surface_normal = NULL;
    if (inside(c->k1_error, base, size)) c->k1_error = NULL;
    if (inside(c->k2_error, base, size)) c->k2_error = NULL;
    struct uv_index *x = &s->uv;
    if (inside(x->cell_start, base, size)) x->cell_start = NULL;
    if (inside(x->cell_triangles, base, size)) x->cell_triangles = NULL;
    struct panel_prep *p = &s->panels;
    if (inside(p->point_uv, base, size)) p->point_uv = NULL;
    if (inside(p->point, base, size)) p->point = NULL;
    if (inside(p->corner, base, size)) p->corner = NULL;
    if (inside(p->triangle, base, size)) p->triangle = NULL;
    struct joint_prep *j = &s->joints;
    for (int axis = 0; axis < 2; axis++) {
        if (inside(j->order[axis], base, size)) j->order[axis] = NULL;
        if (inside(j->least[axis], base, size)) j->least[axis] = NULL;
        if (inside(j->triangle[axis], base, size)) j->triangle[axis] = NULL;
    }
}

void project_cache_release(struct project *project)
{
    if (project->cache_bytes == NULL)
        return;
    for (size_t i = 0; i < project->nsurfaces; i++)
        detach(&project->surfaces[i].surface, project->cache_bytes,
               project->cache_size);
    munmap(project->cache_bytes, project->cache_size);
    project->cache_bytes = NULL;
    project->cache_size = 0;
}

/* The payload's checksum (cache_checksum.h) against the header's, its
 * pieces hashed on the threads, each asking stop every few milliseconds:
 * FACET_OK (*why set when it does not match), FACET_ESTOP or FACET_EWORK. */
static int check_sum(const unsigned char *payload, uint64_t size,
                     const unsigned char expected[64],
                     const struct facet_stop *stop, const char **why,
                     struct facet_error *err)
{
    char checksum[65];
    int rc = cache_checksum_of(payload, size, parallel_cpus(CHECK_THREADS),
                               stop, checksum, err);
    if (rc == FACET_OK && memcmp(checksum, expected, 64) != 0)
        *why = "damaged (its checksum does not match)";
    return rc;
}

/* One thread's share of the surfaces' checks: first, first + step, ...,
 * stopping at the first found wrong. */
struct check_job {
    struct read_surface *read;
    size_t n, first, step;
    const struct facet_stop *stop;
    size_t failed;             /* the surface found wrong, or n */
    const char *why;           /* what was */
    int rc;                    /* FACET_ESTOP when the stop fired */
    struct facet_error err;
};

static void check_run(void *argument)
{
    struct check_job *job = argument;
    job->failed = job->n;
    job->why = NULL;
    job->rc = FACET_OK;
    for (size_t i = job->first; i < job->n; i += job->step) {
        if ((job->rc = facet_stop_check(job->stop, &job->err)) != FACET_OK)
            return;
        struct surface probe;
        memset(&probe, 0, sizeof probe);
        probe.mesh = job->read[i].mesh;
        probe.param = job->read[i].param;
        probe.curvature = job->read[i].curvature;
        job->why = check_surface(&probe);
        if (job->why == NULL)
            job->why = check_prepared(&job->read[i]);
        if (job->why != NULL) {
            job->failed = i;
            return;
        }
    }
}

/* Checks the n surfaces read, dealt round the threads (they are
 * independent): FACET_OK, *why set to what the first surface found wrong
 * says (the same whatever the threads' timing), or FACET_ESTOP. */
static int check_all(struct read_surface *read, size_t n,
                     const struct facet_stop *stop, const char **why,
                     struct facet_error *err)
{
    struct check_job jobs[CHECK_THREADS];
    int count = parallel_jobs(parallel_cpus(CHECK_THREADS), n);
    for (int k = 0; k < count; k++) {
        memset(&jobs[k], 0, sizeof jobs[k]);
        jobs[k].read = read;
        jobs[k].n = n;
        jobs[k].first = (size_t)k;
        jobs[k].step = (size_t)count;
        jobs[k].stop = stop;
    }
    parallel_run(jobs, sizeof jobs[0], count, check_run);
    size_t first = n;
    for (int k = 0; k < count; k++) {
        if (jobs[k].rc != FACET_OK) {
            *err = jobs[k].err;
            return jobs[k].rc;
        }
        if (jobs[k].failed < first) {
            first = jobs[k].failed;
            *why = jobs[k].why;
        }
    }
    return FACET_OK;
}

/* Reads the file's bytes (size of them, mapped; out takes them over, or
 * they are unmapped here) named name: with want_key, refused unless its
 * key is that; without, its key is copied into found_key. */
static int read_bytes(unsigned char *bytes, size_t size, const char *name,
                      const char *want_key, char found_key[65],
                      const char *const *paths, size_t npaths,
                      enum mesh_units units, const struct facet_stop *stop,
                      struct project *out, struct facet_error *err)
{
    memset(out, 0, sizeof *out);
    /* Owned by out from here: project_close releases them, whatever
     * follows. */
    out->cache_bytes = bytes;
    out->cache_size = size;
    const unsigned char *header = bytes;
    int rc = FACET_OK;
    const char *why = NULL;
    char version_why[128];
    uint32_t version = 0, order = 0;
    uint64_t payload = 0;
    if (size < PROJECT_CACHE_HEADER) {
        why = "truncated (shorter than its header)";
    } else {
        memcpy(&version, header + 8, 4);
        memcpy(&order, header + 12, 4);
        memcpy(&payload, header + 16, 8);
    }
    if (why == NULL && memcmp(header, MAGIC, 8) != 0)
        why = "not a prepared building's cache";
    else if (why == NULL && order != BYTE_ORDER_MARK)
        why = "written on a machine of another byte order";
    else if (why == NULL && version != PROJECT_CACHE_VERSION) {
        snprintf(version_why, sizeof version_why,
                 "format version %u, this Facet reads %d", (unsigned)version,
                 PROJECT_CACHE_VERSION);
        why = version_why;
    } else if (why == NULL && want_key != NULL &&
               memcmp(header + 24, want_key, 64) != 0)
        why = PROJECT_CACHE_STALE;
    if (why == NULL && want_key == NULL) {
        memcpy(found_key, header + 24, 64);
        found_key[64] = '\0';
    }
    if (why == NULL && payload != size - PROJECT_CACHE_HEADER)
        why = payload > size - PROJECT_CACHE_HEADER
            ? "truncated (shorter than its header says)"
            : "damaged (longer than its header says)";
    /* The checksum before anything is parsed: a damaged file is told as
     * damaged, and what is parsed is what was written (or forged). */
    if (why == NULL)
        rc = check_sum(bytes + PROJECT_CACHE_HEADER, payload, header + 88,
                       stop, &why, err);

    struct reader r = {bytes, PROJECT_CACHE_HEADER,
                       PROJECT_CACHE_HEADER + payload, why};
    struct read_surface *read = NULL;
    size_t got = 0;
    if (rc == FACET_OK && r.why == NULL) {
        uint64_t n = get_count(&r);
        /* A surface takes far more than 64 bytes: a count beyond that is
         * not allocated for. */
        if (r.why == NULL && (n == 0 || n > (r.end - r.at) / 64))
            r.why = "damaged (its count of surfaces)";
        read = r.why == NULL ? calloc((size_t)n, sizeof *read) : NULL;
        if (r.why == NULL && read == NULL)
            r.why = "too large to read (out of memory)";
        for (; r.why == NULL && got < n; got++)
            get_surface(&r, &read[got], npaths);
        if (r.why == NULL && r.at != r.end)
            r.why = "damaged (bytes past its end)";
        if (r.why == NULL)
            rc = check_all(read, got, stop, &r.why, err);
    }
    if (rc == FACET_OK) {
        rc = r.why != NULL ? refuse(name, r.why, err)
                           : build(read, got, paths, npaths, units, out, err);
        if (rc == FACET_EINPUT && r.why == NULL)  /* no mesh its files give */
            rc = refuse(name, "damaged (a surface refused as a mesh)", err);
    }
    for (size_t i = 0; read != NULL && i < got; i++)
        free(read[i].name);  /* the arrays are the file's */
    free(read);
    if (rc != FACET_OK)
        project_close(out);
    return rc;
}

/* size bytes of memory for a cache, which project_cache_release unmaps. */
static unsigned char *map_anonymous(size_t size)
{
    void *p = mmap(NULL, size ? size : 1, PROT_READ | PROT_WRITE,
                   MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    return p == MAP_FAILED ? NULL : p;
}

int project_cache_read_file(FILE *file, unsigned long long size,
                            const char *name, const char key[65],
                            const char *const *paths, size_t npaths,
                            enum mesh_units units, struct project *out,
                            struct facet_error *err)
{
    memset(out, 0, sizeof *out);
    if (size > SIZE_MAX / 2)
        return refuse(name, "too large to read (out of memory)", err);
    unsigned char *bytes = map_anonymous((size_t)size);
    if (bytes == NULL)
        return refuse(name, "too large to read (out of memory)", err);
    if (fread(bytes, 1, (size_t)size, file) != (size_t)size) {
        munmap(bytes, size ? (size_t)size : 1);
        return refuse(name, "truncated (shorter than its header says)", err);
    }
    return read_bytes(bytes, size ? (size_t)size : 1, name, key, NULL, paths,
                      npaths, units, NULL, out, err);
}

static int read_path(const char *path, const char *want_key,
                     char found_key[65], const char *const *paths,
                     size_t npaths, enum mesh_units units,
                     const struct facet_stop *stop, struct project *out,
                     struct facet_error *err)
{
    memset(out, 0, sizeof *out);
    int fd = open(path, O_RDONLY | O_CLOEXEC);
    if (fd < 0)
        return refuse(path, errno == ENOENT ? "none yet" : strerror(errno),
                      err);
    struct stat st;
    if (fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        close(fd);
        return refuse(path, "not a regular file", err);
    }
    if ((unsigned long long)st.st_size < PROJECT_CACHE_HEADER) {
        close(fd);
        return refuse(path, "truncated (shorter than its header)", err);
    }
    /* Mapped, not read: the arrays are used where they lie, so that the
     * skin's 400 MB are neither copied nor faulted into fresh memory a
     * page at a time. Private and writable: a stage that wrote into an
     * array would write into its own copy of the page, never the file. */
    size_t size = (size_t)st.st_size;
    void *bytes = mmap(NULL, size, PROT_READ | PROT_WRITE, MAP_PRIVATE, fd,
                       0);
    int saved = errno;
    close(fd);
    if (bytes == MAP_FAILED)
        return refuse(path, strerror(saved), err);
    madvise(bytes, size, MADV_WILLNEED);
    return read_bytes(bytes, size, path, want_key, found_key, paths, npaths,
                      units, stop, out, err);
}

int project_cache_read(const char *path, const char key[65],
                       const char *const *paths, size_t npaths,
                       enum mesh_units units, struct project *out,
                       struct facet_error *err)
{
    return read_path(path, key, NULL, paths, npaths, units, NULL, out, err);
}

int project_cache_read_unkeyed(const char *path, char key[65],
                               const char *const *paths, size_t npaths,
                               enum mesh_units units,
                               const struct facet_stop *stop,
                               struct project *out, struct facet_error *err)
{
    return read_path(path, NULL, key, paths, npaths, units, stop, out, err);
}

int project_cache_stale(const char *path, struct facet_error *err)
{
    return refuse(path, PROJECT_CACHE_STALE, err);
}
