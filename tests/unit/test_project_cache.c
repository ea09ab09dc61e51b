/*
 * test_project_cache.c: a prepared building kept in a file
 * (core/project/project_cache.h) and the study's use of it
 * (study/study_prepared.h).
 *
 * Truth: the preparation itself. A building read back from its cache is
 * compared, array by array with memcmp, with the same files opened and
 * prepared afresh (project_open + project_prepare), down to the sums
 * remade from the cached parts; a damaged, truncated, stale or foreign
 * cache must be refused, and the study must then give what a fresh
 * preparation gives.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/base/sha256.h"
#include "core/panel/panel_internal.h"
#include "core/project/cache_checksum.h"
#include "core/project/project.h"
#include "core/project/project_cache.h"
#include "core/surface/example_skin.h"
#include "study/study_prepared.h"
#include "tests/support/temp_dir.h"

static char dir[64];

static int make_dir(void **state)
{
    (void)state;
    return temp_dir_make(dir, sizeof dir, "project_cache");
}

static int remove_dir(void **state)
{
    (void)state;
    return temp_dir_remove(dir);
}

static void write_skin(const char *path, int res)
{
    FILE *out = fopen(path, "w");
    assert_non_null(out);
    struct facet_error err;
    assert_int_equal(skin_write(res, out, &err), FACET_OK);
    fclose(out);
}

/* Two objects without vt (their UV computed), each an n x n grid of
 * quads on a curved sheet; z's last digit of vertex moved (if >= 0) is
 * changed, keeping the file's size. */
static void write_sheets(const char *path, int n, int moved)
{
    FILE *out = fopen(path, "w");
    assert_non_null(out);
    int vertex = 0;
    for (int o = 0; o < 2; o++) {
        fprintf(out, "o sheet%d\n", o);
        for (int j = 0; j <= n; j++)
            for (int i = 0; i <= n; i++) {
                double x = o * 10.0 + 10.0 * i / n, y = 10.0 * j / n;
                double z = 0.02 * (x - 10) * (x - 10) + 0.01 * y * y;
                fprintf(out, "v %.6f %.6f %.5f%d\n", x, y, z,
                        vertex == moved ? 7 : 3);
                vertex++;
            }
        int base = o * (n + 1) * (n + 1) + 1;
        for (int j = 0; j < n; j++)
            for (int i = 0; i < n; i++) {
                int a = base + j * (n + 1) + i;
                fprintf(out, "f %d %d %d %d\n", a, a + 1, a + n + 2,
                        a + n + 1);
            }
    }
    fclose(out);
}

static void fresh(const char *path, enum mesh_units units, int flip,
                  enum param_method uv, struct project *p)
{
    struct facet_error err;
    assert_int_equal(project_open(&path, 1, units, p, &err), FACET_OK);
    assert_int_equal(project_prepare(p, flip, uv, &err), FACET_OK);
}

#define SAME(a, b, count) \
    same_bytes((a), (b), (size_t)(count) * sizeof *(a), #a)

static void same_bytes(const void *a, const void *b, size_t n,
                       const char *what)
{
    if (a == NULL || b == NULL) {
        if (a != b)
            fail_msg("%s: present in one only", what);
        return;
    }
    if (memcmp(a, b, n) != 0)
        fail_msg("%s: not the same bytes", what);
}

static void same_mesh(const struct mesh *a, const struct mesh *b)
{
    size_t V = a->nvertices, T = a->ntriangles;
    assert_int_equal(V, b->nvertices);
    assert_int_equal(T, b->ntriangles);
    SAME(a->position, b->position, 3 * V);
    SAME(a->source_vertex, b->source_vertex, V);
    SAME(a->triangle, b->triangle, 3 * T);
    SAME(a->source_face, b->source_face, T);
    SAME(a->face_normal, b->face_normal, 3 * T);
    SAME(a->face_area, b->face_area, T);
    assert_int_equal(a->has_uv, b->has_uv);
    SAME(a->uv, b->uv, 6 * T);
    assert_int_equal(a->has_normals, b->has_normals);
    SAME(a->corner_normal, b->corner_normal, 9 * T);
    SAME(a->neighbour, b->neighbour, 3 * T);
    assert_int_equal(a->nonmanifold_edges, b->nonmanifold_edges);
    assert_int_equal(a->ndegenerate, b->ndegenerate);
    SAME(a->vertex_start, b->vertex_start, V + 1);
    SAME(a->vertex_triangles, b->vertex_triangles, a->vertex_start[V]);
    SAME(a->on_boundary, b->on_boundary, V);
    assert_int_equal(a->nloops, b->nloops);
    SAME(a->loop_start, b->loop_start, a->nloops + 1);
    SAME(a->loop_vertices, b->loop_vertices, a->loop_start[a->nloops]);
    assert_int_equal(a->ncomponents, b->ncomponents);
    SAME(a->component, b->component, T);
    SAME(&a->area, &b->area, 1);
    SAME(a->bbox_min, b->bbox_min, 3);
    SAME(a->bbox_max, b->bbox_max, 3);
}

static void same_surface(const struct surface *a, const struct surface *b)
{
    assert_string_equal(a->path, b->path);
    assert_int_equal(a->units, b->units);
    assert_int_equal(a->selected, b->selected);
    assert_int_equal(a->nwarnings, b->nwarnings);
    for (int k = 0; k < a->nwarnings; k++)
        assert_string_equal(a->warnings[k], b->warnings[k]);
    assert_true(a->prepared && b->prepared);
    same_mesh(&a->mesh, &b->mesh);
    size_t V = a->mesh.nvertices, T = a->mesh.ntriangles;

    const struct parameterization *p = &a->param, *q = &b->param;
    assert_int_equal(p->method, q->method);
    SAME(p->uv, q->uv, 6 * T);
    assert_int_equal(p->report.triangles, q->report.triangles);
    assert_int_equal(p->report.degenerate, q->report.degenerate);
    assert_int_equal(p->report.flipped, q->report.flipped);
    assert_int_equal(p->report.overlapping, q->report.overlapping);
    SAME(&p->report.uv_area, &q->report.uv_area, 1);
    SAME(&p->report.umin, &q->report.umin, 1);
    SAME(&p->report.vmin, &q->report.vmin, 1);
    SAME(&p->report.umax, &q->report.umax, 1);
    SAME(&p->report.vmax, &q->report.vmax, 1);
    assert_string_equal(p->reason, q->reason);
    assert_int_equal(p->grid_nu, q->grid_nu);
    assert_int_equal(p->grid_nv, q->grid_nv);
    assert_int_equal(p->holes, q->holes);

    const struct curvature *c = &a->curvature, *d = &b->curvature;
    assert_int_equal(c->nvertices, d->nvertices);
    SAME(c->k1, d->k1, V);
    SAME(c->k2, d->k2, V);
    SAME(c->dir1, d->dir1, 3 * V);
    SAME(c->dir2, d->dir2, 3 * V);
    SAME(c->normal, d->normal, 3 * V);
    SAME(c->surface_normal, d->surface_normal, 3 * V);
    SAME(c->k1_error, d->k1_error, V);
    SAME(c->k2_error, d->k2_error, V);

    const struct uv_index *x = &a->uv, *y = &b->uv;
    assert_int_equal(x->ntriangles, y->ntriangles);
    SAME(&x->umin, &y->umin, 1);
    SAME(&x->vmin, &y->vmin, 1);
    SAME(&x->umax, &y->umax, 1);
    SAME(&x->vmax, &y->vmax, 1);
    assert_int_equal(x->ncells_u, y->ncells_u);
    assert_int_equal(x->ncells_v, y->ncells_v);
    SAME(&x->cell_u, &y->cell_u, 1);
    SAME(&x->cell_v, &y->cell_v, 1);
    size_t cells = (size_t)x->ncells_u * (size_t)x->ncells_v;
    SAME(x->cell_start, y->cell_start, cells + 1);
    SAME(x->cell_triangles, y->cell_triangles, x->cell_start[cells]);
    SAME(x->uv, y->uv, 6 * T);

    const struct panel_prep *r = &a->panels, *s = &b->panels;
    assert_int_equal(r->npoints, s->npoints);
    SAME(r->point_uv, s->point_uv, 2 * r->npoints);
    SAME(r->point, s->point, r->npoints);
    SAME(r->corner, s->corner, 3 * T);
    SAME(r->triangle, s->triangle, T);
    /* not in the file: remade from the curvature it holds */
    SAME(r->curvature_range, s->curvature_range, T);

    const struct joint_prep *j = &a->joints, *k = &b->joints;
    SAME(&j->outline, &k->outline, 1);
    assert_int_equal(j->ntriangles, k->ntriangles);
    for (int axis = 0; axis < 2; axis++) {
        SAME(j->order[axis], k->order[axis], j->ntriangles);
        SAME(j->least[axis], k->least[axis], j->ntriangles);
        SAME(j->triangle[axis], k->triangle[axis], j->ntriangles);
    }
    SAME(j->reach, k->reach, 2);

    const struct fit_points *f = &a->fit, *g = &b->fit;
    assert_int_equal(f->npoints, g->npoints);
    SAME(f->uv, g->uv, 2 * f->npoints);
    SAME(f->vertex, g->vertex, f->npoints);
    SAME(f->ruling, g->ruling, 3 * f->npoints);
    SAME(&a->facet_sag, &b->facet_sag, 1);
}

static void same_project(const struct project *a, const struct project *b)
{
    assert_int_equal(a->nfiles, b->nfiles);
    for (size_t i = 0; i < a->nfiles; i++)
        assert_string_equal(a->files[i], b->files[i]);
    assert_int_equal(a->nsurfaces, b->nsurfaces);
    assert_int_equal(a->ntriangles, b->ntriangles);
    SAME(&a->area, &b->area, 1);
    for (size_t i = 0; i < a->nsurfaces; i++) {
        const struct project_surface *p = &a->surfaces[i],
                                     *q = &b->surfaces[i];
        assert_string_equal(p->name, q->name);
        assert_string_equal(p->file, q->file);
        assert_int_equal(p->key, q->key);
        assert_int_equal(p->face, q->face);
        SAME(&p->u_length, &q->u_length, 1);
        SAME(&p->v_length, &q->v_length, 1);
        same_surface(&p->surface, &q->surface);
    }
}

static void key_of(const char *path, const struct project_cache_settings *s,
                   char key[65])
{
    char digest[1][65];
    struct facet_error err;
    assert_int_equal(sha256_file(path, digest[0], &err), FACET_OK);
    project_cache_key((const char (*)[65])digest, 1, s, key);
}

/* Writes fresh's cache to cache, reads it back and compares. */
static void round_trip(const char *obj, enum mesh_units units, int flip,
                       enum param_method uv)
{
    struct project a, b;
    fresh(obj, units, flip, uv, &a);
    struct project_cache_settings s = {units, flip, uv, "test"};
    char key[65], cache[128];
    key_of(obj, &s, key);
    snprintf(cache, sizeof cache, "%s/round.cache", dir);
    struct facet_error err;
    assert_int_equal(project_cache_write(&a, key, cache, &err), FACET_OK);
    int rc = project_cache_read(cache, key, &obj, 1, units, &b, &err);
    if (rc != FACET_OK)
        fail_msg("%s", err.message);
    /* The lookup, sums and joints' prep come from the file (format 3),
     * not made again: what is compared below is what was kept. */
    for (size_t i = 0; i < b.nsurfaces; i++)
        assert_true(surface_prepared_in_cache(&b.surfaces[i].surface));
    assert_int_equal(project_prepare_rest_stoppable(&b, NULL, &err),
                     FACET_OK);
    same_project(&a, &b);
    project_close(&a);
    project_close(&b);
}

static void test_round_trip_is_the_same_to_the_bit(void **state)
{
    (void)state;
    char skin[128], sheets[128];
    snprintf(skin, sizeof skin, "%s/skin.obj", dir);
    write_skin(skin, 3);
    round_trip(skin, UNITS_M, 0, PARAM_AUTO);   /* the file's vt */
    snprintf(sheets, sizeof sheets, "%s/sheets.obj", dir);
    write_sheets(sheets, 6, -1);
    round_trip(sheets, UNITS_M, 1, PARAM_AUTO);  /* grid UV, flipped */
    round_trip(sheets, UNITS_CM, 0, PARAM_PLANE);
    round_trip(sheets, UNITS_M, 0, PARAM_HARMONIC);
}

static long file_size(const char *path)
{
    struct stat st;
    assert_int_equal(stat(path, &st), 0);
    return (long)st.st_size;
}

static void refused(const char *cache, const char key[65], const char *obj,
                    const char *expect)
{
    struct project p;
    struct facet_error err;
    int rc = project_cache_read(cache, key, &obj, 1, UNITS_M, &p, &err);
    project_close(&p);
    if (rc != FACET_EINPUT)
        fail_msg("%s: read (rc %d) where it should be refused (%s)", cache,
                 rc, expect);
    assert_null(strchr(err.message, '\n'));
    assert_non_null(strstr(err.message, cache));
    if (expect != NULL && strstr(err.message, expect) == NULL)
        fail_msg("'%s' does not say '%s'", err.message, expect);
}

/* A copy of good at bad with byte at flipped (when >= 0), cut to size
 * bytes (when >= 0). */
static void damaged_copy(const char *good, const char *bad, long flipped,
                         long size)
{
    FILE *in = fopen(good, "rb");
    assert_non_null(in);
    long n = file_size(good);
    unsigned char *bytes = malloc((size_t)n + 1);
    assert_non_null(bytes);
    assert_int_equal(fread(bytes, 1, (size_t)n, in), (size_t)n);
    fclose(in);
    if (flipped >= 0)
        bytes[flipped] ^= 0x10;
    FILE *out = fopen(bad, "wb");
    assert_non_null(out);
    size_t keep = size >= 0 ? (size_t)size : (size_t)n;
    assert_int_equal(fwrite(bytes, 1, keep, out), keep);
    fclose(out);
    free(bytes);
}

static void test_damage_and_truncation_are_refused(void **state)
{
    (void)state;
    char obj[128], good[128], bad[128];
    snprintf(obj, sizeof obj, "%s/sheets_damage.obj", dir);
    write_sheets(obj, 4, -1);
    struct project a;
    fresh(obj, UNITS_M, 0, PARAM_AUTO, &a);
    struct project_cache_settings s = {UNITS_M, 0, PARAM_AUTO, "test"};
    char key[65];
    key_of(obj, &s, key);
    snprintf(good, sizeof good, "%s/good.cache", dir);
    snprintf(bad, sizeof bad, "%s/bad.cache", dir);
    struct facet_error err;
    assert_int_equal(project_cache_write(&a, key, good, &err), FACET_OK);
    project_close(&a);
    long n = file_size(good);
    assert_true(n > PROJECT_CACHE_HEADER + 1000);

    /* Every byte of the header, then bytes spread over the payload. */
    for (long at = 0; at < n; at += at < PROJECT_CACHE_HEADER ? 1 : 97) {
        damaged_copy(good, bad, at, -1);
        refused(bad, key, obj, NULL);
    }
    damaged_copy(good, bad, n - 1, -1);
    refused(bad, key, obj, "damaged");
    damaged_copy(good, bad, PROJECT_CACHE_HEADER + n / 2, -1);
    refused(bad, key, obj, "damaged");

    long cuts[] = {0, 1, PROJECT_CACHE_HEADER - 1, PROJECT_CACHE_HEADER,
                   PROJECT_CACHE_HEADER + 1, n / 2, n - 1};
    for (size_t k = 0; k < sizeof cuts / sizeof cuts[0]; k++) {
        damaged_copy(good, bad, -1, cuts[k]);
        refused(bad, key, obj, "truncated");
    }
    /* A byte too many. */
    FILE *out = fopen(bad, "ab");
    assert_non_null(out);
    fputc(0, out);
    fclose(out);
    damaged_copy(good, bad, -1, -1);
    out = fopen(bad, "ab");
    fputc(0, out);
    fclose(out);
    refused(bad, key, obj, "damaged");
    /* Not a cache at all, and none. */
    refused(obj, key, obj, "not a prepared building's cache");
    char none[128];
    snprintf(none, sizeof none, "%s/none.cache", dir);
    refused(none, key, obj, "none yet");

    /* The good one still reads. */
    struct project b;
    assert_int_equal(project_cache_read(good, key, (const char *[]){obj}, 1,
                                        UNITS_M, &b, &err), FACET_OK);
    project_close(&b);
}

static void test_another_key_is_stale(void **state)
{
    (void)state;
    char obj[128], cache[128];
    snprintf(obj, sizeof obj, "%s/sheets_key.obj", dir);
    write_sheets(obj, 4, -1);
    struct project a;
    fresh(obj, UNITS_M, 0, PARAM_AUTO, &a);
    struct project_cache_settings s = {UNITS_M, 0, PARAM_AUTO, "test"};
    char key[65];
    key_of(obj, &s, key);
    snprintf(cache, sizeof cache, "%s/key.cache", dir);
    struct facet_error err;
    assert_int_equal(project_cache_write(&a, key, cache, &err), FACET_OK);
    project_close(&a);

    struct project_cache_settings other[] = {
        {UNITS_MM, 0, PARAM_AUTO, "test"},
        {UNITS_M, 1, PARAM_AUTO, "test"},
        {UNITS_M, 0, PARAM_PLANE, "test"},
        {UNITS_M, 0, PARAM_AUTO, "another build"},
    };
    for (size_t k = 0; k < sizeof other / sizeof other[0]; k++) {
        char stale[65];
        key_of(obj, &other[k], stale);
        assert_string_not_equal(stale, key);
        refused(cache, stale, obj, "stale");
    }
    /* The same settings, another file's bytes (one vertex moved). */
    char moved[128], stale[65];
    snprintf(moved, sizeof moved, "%s/sheets_key_moved.obj", dir);
    write_sheets(moved, 4, 7);
    assert_int_equal(file_size(moved), file_size(obj));
    key_of(moved, &s, stale);
    refused(cache, stale, obj, "stale");
}

/* A cache whose checksum holds but whose curvature is not a number (a
 * file made by hand, or by a Facet that computed one): refused, for every
 * curvature array, since a NaN curvature classifies a panel as no truth
 * would. The project is prepared, one number spoiled, then written: the
 * writer writes what it is given, with a right checksum. */
static void test_curvature_not_a_number_is_refused(void **state)
{
    (void)state;
    char obj[128], cache[128];
    snprintf(obj, sizeof obj, "%s/sheets_nan.obj", dir);
    snprintf(cache, sizeof cache, "%s/nan.cache", dir);
    write_sheets(obj, 4, -1);
    struct project_cache_settings s = {UNITS_M, 0, PARAM_AUTO, "test"};
    char key[65];
    key_of(obj, &s, key);
    for (int which = 0; which < 8; which++)
        for (int inf = 0; inf < 2; inf++) {
            struct project a;
            fresh(obj, UNITS_M, 0, PARAM_AUTO, &a);
            struct curvature *c = &a.surfaces[1].surface.curvature;
            double *arrays[8] = {c->k1, c->k2, c->dir1, c->dir2, c->normal,
                                 c->surface_normal, c->k1_error,
                                 c->k2_error};
            arrays[which][c->nvertices / 2] = inf ? -INFINITY : NAN;
            struct facet_error err;
            assert_int_equal(project_cache_write(&a, key, cache, &err),
                             FACET_OK);
            project_close(&a);
            refused(cache, key, obj, "not a number");
        }
}

/* One way to spoil the prepared sums of a building's second surface
 * (format 3) while keeping the file's checksum right: what a file made
 * by hand, or a Facet that got them wrong, would hold. */
enum spoil {
    SPOIL_CELL_TRIANGLE,   /* a lookup cell lists triangle #T */
    SPOIL_CELL_START,      /* a cell's start past the next one's */
    SPOIL_CORNER,          /* a corner's point #points */
    SPOIL_CORNER_ORDER,    /* a corner's point not yet met */
    SPOIL_POINT,           /* a point elsewhere than its corner */
    SPOIL_SUM,             /* a triangle's second moment NaN */
    SPOIL_ORDER,           /* the joints' order names triangle #T */
    SPOIL_VERTEX,          /* a joint triangle's corner vertex #V */
    SPOIL_LEAST,           /* the joints' order out of order */
    SPOIL_REACH,           /* a reach infinite */
    SPOIL_SAG,             /* the facets' sag NaN */
    SPOIL_COUNT
};

static void spoil(struct project *p, enum spoil how)
{
    struct surface *s = &p->surfaces[1].surface;
    size_t T = s->mesh.ntriangles, V = s->mesh.nvertices;
    size_t cells = (size_t)s->uv.ncells_u * (size_t)s->uv.ncells_v;
    size_t mid = T / 2;
    switch (how) {
    case SPOIL_CELL_TRIANGLE:
        s->uv.cell_triangles[s->uv.cell_start[cells] / 2] = (uint32_t)T;
        break;
    case SPOIL_CELL_START:
        assert_true(cells >= 2);
        s->uv.cell_start[1] = s->uv.cell_start[cells] + 1;
        break;
    case SPOIL_CORNER:
        s->panels.corner[3 * mid] = (uint32_t)s->panels.npoints;
        break;
    case SPOIL_CORNER_ORDER:
        /* the first corner names the last point: in range, yet no
         * preparation numbers them so, and its fit point would be
         * another's */
        s->panels.corner[0] = (uint32_t)s->panels.npoints - 1;
        break;
    case SPOIL_POINT:
        s->panels.point[s->panels.corner[3 * mid]].position[2] += 1e-3;
        break;
    case SPOIL_SUM:
        s->panels.triangle[mid].second[4] = NAN;
        break;
    case SPOIL_ORDER:
        s->joints.order[0][mid] = (uint32_t)T;
        break;
    case SPOIL_VERTEX:
        s->joints.triangle[1][mid].vertex[2] = (uint32_t)V;
        break;
    case SPOIL_LEAST: {
        /* the first and last swapped, each whole: every triangle where
         * the mesh has it, the order alone wrong */
        size_t last = T - 1;
        uint32_t o = s->joints.order[0][0];
        double l = s->joints.least[0][0];
        struct joint_triangle t = s->joints.triangle[0][0];
        s->joints.order[0][0] = s->joints.order[0][last];
        s->joints.least[0][0] = s->joints.least[0][last];
        s->joints.triangle[0][0] = s->joints.triangle[0][last];
        s->joints.order[0][last] = o;
        s->joints.least[0][last] = l;
        s->joints.triangle[0][last] = t;
        break;
    }
    case SPOIL_REACH:
        s->joints.reach[1] = INFINITY;
        break;
    case SPOIL_SAG:
        s->facet_sag = NAN;
        break;
    case SPOIL_COUNT:
        break;
    }
}

/* A cache whose checksum holds but one of whose prepared sums (format 3)
 * is out of range, out of order or not a number: refused as damaged, for
 * each, never read (an index past its array would be read out of bounds
 * by the first option's panels, lookup or joints). The project is
 * prepared, one number spoiled, then written: the writer writes what it
 * is given, with a right checksum. */
static void test_prepared_sums_out_of_range_are_refused(void **state)
{
    (void)state;
    char obj[128], cache[128];
    snprintf(obj, sizeof obj, "%s/sheets_forged.obj", dir);
    snprintf(cache, sizeof cache, "%s/forged.cache", dir);
    write_sheets(obj, 4, -1);
    struct project_cache_settings s = {UNITS_M, 0, PARAM_AUTO, "test"};
    char key[65];
    key_of(obj, &s, key);
    for (int how = 0; how < SPOIL_COUNT; how++) {
        struct project a;
        fresh(obj, UNITS_M, 0, PARAM_AUTO, &a);
        spoil(&a, (enum spoil)how);
        struct facet_error err;
        assert_int_equal(project_cache_write(&a, key, cache, &err), FACET_OK);
        project_close(&a);
        refused(cache, key, obj, "damaged");
    }
}

/* The checksum over pieces (cache_checksum.h), against its definition
 * computed here with SHA-256 alone: each 32 MB piece's digest in hex,
 * those hashed; written in uneven lengths, checked on 1 and 3 threads;
 * for a payload of 2 pieces and a bit, of exactly 2, and of a few
 * bytes; and a byte changed in the last piece changes it. */
static void test_checksum_over_pieces(void **state)
{
    (void)state;
    size_t piece = (size_t)CACHE_CHECKSUM_PIECE;
    size_t sizes[3] = {2 * piece + 12345, 2 * piece, 100};
    unsigned char *bytes = malloc(sizes[0]);
    assert_non_null(bytes);
    for (size_t i = 0; i < sizes[0]; i++)
        bytes[i] = (unsigned char)((i * 2654435761u) >> 13);
    for (int k = 0; k < 3; k++) {
        size_t n = sizes[k];
        struct sha256 outer;
        sha256_init(&outer);
        for (size_t at = 0; at < n; at += piece) {
            struct sha256 h;
            sha256_init(&h);
            sha256_update(&h, bytes + at, n - at < piece ? n - at : piece);
            char hex[65];
            sha256_hex(&h, hex);
            sha256_update(&outer, hex, 64);
        }
        char truth[65];
        sha256_hex(&outer, truth);

        struct cache_checksum c;
        cache_checksum_init(&c);
        for (size_t at = 0, step = 1; at < n; step = step * 7 + 3) {
            size_t take = n - at < step ? n - at : step;
            cache_checksum_update(&c, bytes + at, take);
            at += take;
        }
        char written[65];
        cache_checksum_hex(&c, written);
        assert_string_equal(written, truth);
        for (int threads = 1; threads <= 3; threads += 2) {
            char checked[65];
            struct facet_error err;
            assert_int_equal(cache_checksum_of(bytes, n, threads, NULL,
                                               checked, &err), FACET_OK);
            assert_string_equal(checked, truth);
        }
        bytes[n - 1] ^= 1;
        char changed[65];
        struct facet_error err;
        assert_int_equal(cache_checksum_of(bytes, n, 2, NULL, changed, &err),
                         FACET_OK);
        assert_string_not_equal(changed, truth);
        bytes[n - 1] ^= 1;
    }
    free(bytes);
}

/* The reader asks its stop: one that fires gives FACET_ESTOP and
 * nothing read, one that does not the building. */
static int always(void *context)
{
    (void)context;
    return 1;
}

static void test_reader_asks_its_stop(void **state)
{
    (void)state;
    char obj[128], cache[128];
    snprintf(obj, sizeof obj, "%s/sheets_stop.obj", dir);
    snprintf(cache, sizeof cache, "%s/stop.cache", dir);
    write_sheets(obj, 4, -1);
    struct project a;
    fresh(obj, UNITS_M, 0, PARAM_AUTO, &a);
    struct facet_error err;
    const char key[65] = "0123456789abcdef0123456789abcdef"
                         "0123456789abcdef0123456789abcdef";
    assert_int_equal(project_cache_write(&a, key, cache, &err), FACET_OK);
    project_close(&a);
    struct facet_stop stop = {always, NULL};
    char found[65];
    const char *paths[1] = {obj};
    assert_int_equal(project_cache_read_unkeyed(cache, found, paths, 1,
                                                UNITS_M, &stop, &a, &err),
                     FACET_ESTOP);
    assert_int_equal(a.nsurfaces, 0);
    assert_null(a.cache_bytes);
    project_close(&a);
    assert_int_equal(project_cache_read_unkeyed(cache, found, paths, 1,
                                                UNITS_M, NULL, &a, &err),
                     FACET_OK);
    assert_string_equal(found, key);
    assert_int_equal(a.nsurfaces, 2);
    project_close(&a);
}

/* ---- the study's decision ---- */

struct notes {
    int reused, again, not_kept;
    char last[1024];
};

static void on_note(void *context, const char *text)
{
    struct notes *n = context;
    snprintf(n->last, sizeof n->last, "%s", text);
    assert_null(strchr(text, '\n'));
    if (strstr(text, "reused the prepared building") != NULL)
        n->reused++;
    else if (strstr(text, "preparing it again") != NULL)
        n->again++;
    else if (strstr(text, "not kept") != NULL)
        n->not_kept++;
    else
        fail_msg("an unexpected note: %s", text);
}

/* A stop asked once the study says it reads the prepared building: the
 * read hears it (FACET_ESTOP), for a resume, whose files' hashes are
 * known and so not read beside the cache (where their reading would hear
 * the stop and hide that the cache's did not), and for a first read. */
struct stop_when_reading {
    int reading, asked;
};

static void on_stage(void *context, const char *what)
{
    struct stop_when_reading *s = context;
    if (strstr(what, "reading the prepared building") != NULL)
        s->reading = 1;
}

static int stop_if_reading(void *context)
{
    struct stop_when_reading *s = context;
    if (s->reading)
        s->asked++;
    return s->reading;
}

static void test_stop_while_reading_the_cache(void **state)
{
    (void)state;
    char sub[128], obj[160], db[160];
    snprintf(sub, sizeof sub, "%s/stop", dir);
    assert_int_equal(mkdir(sub, 0700), 0);
    snprintf(obj, sizeof obj, "%s/sheets.obj", sub);
    snprintf(db, sizeof db, "%s/runs.db", sub);
    write_sheets(obj, 6, -1);
    struct study_prepare want = {db, (const char *[]){obj}, 1, NULL,
                                 UNITS_M, 1, 0, PARAM_AUTO};
    struct project p;
    char digest[1][65];
    struct facet_error err;
    /* The cache written by a first, unstopped, run. */
    assert_int_equal(study_project_prepared(&want, NULL, &p, digest, &err),
                     FACET_OK);
    project_close(&p);
    for (int known = 1; known >= 0; known--) {
        struct stop_when_reading s = {0, 0};
        struct study_hooks hooks = {&s, on_stage, NULL, stop_if_reading,
                                    NULL, NULL, NULL};
        want.known = known ? (const char (*)[65])digest : NULL;
        int rc = study_project_prepared(&want, &hooks, &p, digest, &err);
        size_t surfaces = p.nsurfaces;
        project_close(&p);
        assert_true(s.reading);
        if (rc != FACET_ESTOP)
            fail_msg("%s: a stop while the prepared building is read is "
                     "not heard (rc %d)", known ? "a resume" : "a run", rc);
        assert_non_null(strstr(err.message, "stop"));
        /* Heard by the read itself, which then hands out nothing: not
         * only by the preparation after it, once the whole cache had been
         * read and checked (the skin's 400 MB: seconds). */
        if (surfaces != 0)
            fail_msg("%s: the stop was heard only after the whole cache "
                     "was read (%zu surfaces)", known ? "a resume" : "a run",
                     surfaces);
    }
    /* Unstopped, the cache is whole and reused. */
    struct notes n;
    memset(&n, 0, sizeof n);
    struct study_hooks told = {&n, NULL, NULL, NULL, NULL, NULL, on_note};
    want.known = NULL;
    assert_int_equal(study_project_prepared(&want, &told, &p, digest, &err),
                     FACET_OK);
    project_close(&p);
    assert_int_equal(n.reused, 1);
}

/* study_project_prepared of obj with db beside, its SHA-256 known as
 * known (a resume's) or NULL (hashed); compares with a fresh preparation
 * and returns what the notes said. */
static struct notes prepared_known(const char *db, const char *obj,
                                   int flip, enum param_method uv,
                                   const char (*known)[65])
{
    struct notes n;
    memset(&n, 0, sizeof n);
    struct study_hooks hooks = {&n, NULL, NULL, NULL, NULL, NULL, on_note};
    struct study_prepare want = {db, &obj, 1, known, UNITS_M, 1, flip, uv};
    struct project p, q;
    char digest[1][65];
    struct facet_error err;
    int rc = study_project_prepared(&want, &hooks, &p, digest, &err);
    if (rc != FACET_OK)
        fail_msg("%s", err.message);
    char truth[65];
    assert_int_equal(sha256_file(obj, truth, &err), FACET_OK);
    assert_string_equal(digest[0], known != NULL ? known[0] : truth);
    fresh(obj, UNITS_M, flip, uv, &q);
    same_project(&q, &p);
    project_close(&p);
    project_close(&q);
    return n;
}

static struct notes prepared(const char *db, const char *obj, int flip,
                             enum param_method uv)
{
    return prepared_known(db, obj, flip, uv, NULL);
}

/* The cache files in db's folder (at most 2) into path[]; returns how
 * many. */
static int caches(const char *db, char path[2][256])
{
    char command[256];
    snprintf(command, sizeof command, "ls %.*s/facet-prepared-* 2>/dev/null",
             (int)(strrchr(db, '/') - db), db);
    FILE *ls = popen(command, "r");
    assert_non_null(ls);
    int n = 0;
    char line[256];
    while (fgets(line, sizeof line, ls) != NULL) {
        assert_true(n < 2);
        line[strcspn(line, "\n")] = '\0';
        snprintf(path[n++], 256, "%s", line);
    }
    pclose(ls);
    return n;
}

/* How many regular files in folder are named prefix and 8 more hex
 * digits, or exist at all (links too) under that pattern: ls. */
static int count_named(const char *folder, const char *pattern)
{
    char command[512];
    snprintf(command, sizeof command, "ls -A %s | grep -cE '^%s$'", folder,
             pattern);
    FILE *ls = popen(command, "r");
    assert_non_null(ls);
    int n = -1;
    assert_int_equal(fscanf(ls, "%d", &n), 1);
    pclose(ls);
    return n;
}

/* A building studied under five settings in turn: its caches beside the
 * database are at most PROJECT_CACHE_KEEP, the newest kept (each run's
 * own reused by the next run of its settings); another building's cache,
 * a file named as a cache without the magic and a symbolic link named as
 * one (to a real cache elsewhere) are left alone. Truth: the folder as ls
 * lists it. */
static void test_old_caches_do_not_pile_up(void **state)
{
    (void)state;
    char sub[128], other[128], obj[192], two[192], db[192];
    snprintf(sub, sizeof sub, "%s/prune", dir);
    snprintf(other, sizeof other, "%s/prune_elsewhere", dir);
    assert_int_equal(mkdir(sub, 0700), 0);
    assert_int_equal(mkdir(other, 0700), 0);
    snprintf(obj, sizeof obj, "%s/sheets.obj", sub);
    snprintf(two, sizeof two, "%s/other.obj", sub);
    snprintf(db, sizeof db, "%s/runs.db", sub);
    write_sheets(obj, 3, -1);
    write_sheets(two, 3, 5);
    struct project p;
    char digest[1][65];
    struct facet_error err;
    /* Another building's cache, beside. */
    struct study_prepare another = {db, (const char *[]){two}, 1, NULL,
                                    UNITS_M, 1, 0, PARAM_AUTO};
    assert_int_equal(study_project_prepared(&another, NULL, &p, digest,
                                            &err), FACET_OK);
    project_close(&p);
    char path[2][256];
    assert_int_equal(caches(db, path), 1);
    char another_cache[256];
    snprintf(another_cache, sizeof another_cache, "%s", path[0]);

    struct { enum mesh_units units; int flip; enum param_method uv; }
        settings[] = {{UNITS_M, 0, PARAM_AUTO}, {UNITS_MM, 0, PARAM_AUTO},
                      {UNITS_M, 1, PARAM_AUTO}, {UNITS_CM, 0, PARAM_AUTO},
                      {UNITS_M, 1, PARAM_PLANE}};
    char first[256] = "", prefix[64] = "";
    for (size_t k = 0; k < sizeof settings / sizeof settings[0]; k++) {
        struct study_prepare want = {db, (const char *[]){obj}, 1, NULL,
                                     settings[k].units, 1, settings[k].flip,
                                     settings[k].uv};
        assert_int_equal(study_project_prepared(&want, NULL, &p, digest,
                                                &err), FACET_OK);
        project_close(&p);
        char here[256];
        const char *names[1] = {obj};
        char absolute[4096];
        assert_non_null(realpath(obj, absolute));
        names[0] = absolute;
        struct project_cache_settings s = {settings[k].units,
                                           settings[k].flip,
                                           settings[k].uv, NULL};
        assert_int_equal(project_cache_path(db, names, 1, &s, here,
                                            sizeof here, &err), FACET_OK);
        struct stat st;
        assert_int_equal(lstat(here, &st), 0);
        if (k == 0) {
            snprintf(first, sizeof first, "%s", here);
            const char *base = strrchr(here, '/') + 1;
            snprintf(prefix, sizeof prefix, "%.23s", base);
            /* A file named as a cache of this building, not one; and a
             * link named as one, to a real cache elsewhere. */
            char fake[300], link[300], target[300];
            snprintf(fake, sizeof fake, "%s/%sffffffff", sub, prefix);
            FILE *out = fopen(fake, "w");
            assert_non_null(out);
            fputs("not a cache, but named as one\n", out);
            fclose(out);
            snprintf(target, sizeof target, "%s/%seeeeeeee", other, prefix);
            damaged_copy(here, target, -1, -1);
            snprintf(link, sizeof link, "%s/%seeeeeeee", sub, prefix);
            assert_int_equal(symlink(target, link), 0);
        }
        char pattern[128];
        snprintf(pattern, sizeof pattern, "%s[0-9a-f]{8}", prefix);
        int n = count_named(sub, pattern);
        /* Its own caches at most KEEP, and the fake and the link. */
        int expect = (int)k + 1 < PROJECT_CACHE_KEEP ? (int)k + 1
                                                     : PROJECT_CACHE_KEEP;
        if (n != expect + 2)
            fail_msg("after %zu settings: %d files named as this "
                     "building's caches, not %d (%d caches, the fake and "
                     "the link)", k + 1, n, expect + 2, expect);
    }
    /* The first settings' cache was the oldest: gone. The others stay. */
    struct stat st;
    assert_int_not_equal(lstat(first, &st), 0);
    assert_int_equal(lstat(another_cache, &st), 0);
    char kept[300];
    snprintf(kept, sizeof kept, "%s/%sffffffff", sub, prefix);
    assert_int_equal(lstat(kept, &st), 0);
    snprintf(kept, sizeof kept, "%s/%seeeeeeee", sub, prefix);
    assert_int_equal(lstat(kept, &st), 0);
    assert_true(S_ISLNK(st.st_mode));
    assert_int_equal(stat(kept, &st), 0);  /* its target too */
}

static void test_study_reuses_and_rebuilds(void **state)
{
    (void)state;
    char obj[128], db[128], cache[256];
    snprintf(obj, sizeof obj, "%s/sheets_study.obj", dir);
    snprintf(db, sizeof db, "%s/runs.db", dir);
    write_sheets(obj, 5, -1);

    struct notes n = prepared(db, obj, 0, PARAM_AUTO);
    assert_int_equal(n.reused + n.again + n.not_kept, 0);
    n = prepared(db, obj, 0, PARAM_AUTO);
    assert_int_equal(n.reused, 1);
    char found[2][256];
    assert_int_equal(caches(db, found), 1);
    memcpy(cache, found[0], sizeof cache);

    /* A flipped byte, then a truncation: rebuilt, the same answer, and
     * the cache made whole again. */
    damaged_copy(cache, cache, file_size(cache) / 2, -1);
    n = prepared(db, obj, 0, PARAM_AUTO);
    assert_int_equal(n.again, 1);
    assert_non_null(strstr(n.last, "damaged"));
    assert_int_equal(prepared(db, obj, 0, PARAM_AUTO).reused, 1);
    damaged_copy(cache, cache, -1, file_size(cache) - 3);
    n = prepared(db, obj, 0, PARAM_AUTO);
    assert_int_equal(n.again, 1);
    assert_non_null(strstr(n.last, "truncated"));
    assert_int_equal(prepared(db, obj, 0, PARAM_AUTO).reused, 1);

    /* The file changed, its size the same: one vertex moved. */
    long before = file_size(obj);
    write_sheets(obj, 5, 11);
    assert_int_equal(file_size(obj), before);
    n = prepared(db, obj, 0, PARAM_AUTO);
    assert_int_equal(n.again, 1);
    assert_non_null(strstr(n.last, "stale"));
    assert_int_equal(prepared(db, obj, 0, PARAM_AUTO).reused, 1);

    /* Another setting: its own cache, never the other's; and the other's
     * put in its place is refused as stale (foreign). */
    n = prepared(db, obj, 1, PARAM_AUTO);
    assert_int_equal(n.reused + n.again, 0);
    assert_int_equal(caches(db, found), 2);
    const char *other = strcmp(found[0], cache) == 0 ? found[1] : found[0];
    damaged_copy(cache, other, -1, -1);
    n = prepared(db, obj, 1, PARAM_AUTO);
    assert_int_equal(n.again, 1);
    assert_non_null(strstr(n.last, "stale"));
    assert_int_equal(prepared(db, obj, 1, PARAM_AUTO).reused, 1);
    assert_int_equal(prepared(db, obj, 0, PARAM_AUTO).reused, 1);
}

/* The study meets such a cache beside its database: one note, the
 * building prepared again from its files (the same to the bit as a fresh
 * preparation), and the cache made good for the next run. */
static void test_study_rebuilds_a_forged_cache(void **state)
{
    (void)state;
    char obj[128], db[128];
    snprintf(obj, sizeof obj, "%s/sheets_forged_study.obj", dir);
    snprintf(db, sizeof db, "%s/forged/runs.db", dir);
    char folder[128];
    snprintf(folder, sizeof folder, "%s/forged", dir);
    assert_int_equal(mkdir(folder, 0700), 0);
    write_sheets(obj, 4, -1);
    assert_int_equal(prepared(db, obj, 0, PARAM_AUTO).again, 0);
    char found[2][256];
    assert_int_equal(caches(db, found), 1);
    /* The key the study gives (its program's among it), from the file
     * it wrote. */
    char key[65];
    FILE *in = fopen(found[0], "rb");
    assert_non_null(in);
    assert_int_equal(fseek(in, 24, SEEK_SET), 0);
    assert_int_equal(fread(key, 1, 64, in), 64);
    key[64] = '\0';
    fclose(in);
    const enum spoil hows[] = {SPOIL_CELL_TRIANGLE, SPOIL_CORNER,
                               SPOIL_ORDER, SPOIL_VERTEX};
    for (size_t k = 0; k < sizeof hows / sizeof hows[0]; k++) {
        struct project a;
        fresh(obj, UNITS_M, 0, PARAM_AUTO, &a);
        spoil(&a, hows[k]);
        struct facet_error err;
        assert_int_equal(project_cache_write(&a, key, found[0], &err),
                         FACET_OK);
        project_close(&a);
        struct notes n = prepared(db, obj, 0, PARAM_AUTO);
        assert_int_equal(n.again, 1);
        assert_non_null(strstr(n.last, "damaged"));
        assert_int_equal(prepared(db, obj, 0, PARAM_AUTO).reused, 1);
    }
    /* A cache of format 2 (no prepared sums): another version, rebuilt
     * with a note. */
    uint32_t two = 2;
    FILE *io = fopen(found[0], "r+b");
    assert_non_null(io);
    assert_int_equal(fseek(io, 8, SEEK_SET), 0);
    assert_int_equal(fwrite(&two, 4, 1, io), 1);
    fclose(io);
    struct notes n = prepared(db, obj, 0, PARAM_AUTO);
    assert_int_equal(n.again, 1);
    assert_non_null(strstr(n.last, "format version 2"));
    assert_int_equal(prepared(db, obj, 0, PARAM_AUTO).reused, 1);
}

/* A resume knows its files' SHA-256s (it found them by them): the cache
 * is keyed by those, and one made from other bytes is stale. */
static void test_resume_uses_known_digests(void **state)
{
    (void)state;
    char obj[128], db[160], truth[1][65];
    snprintf(obj, sizeof obj, "%s/sheets_resume.obj", dir);
    snprintf(db, sizeof db, "%s/resume/runs.db", dir);
    char folder[160];
    snprintf(folder, sizeof folder, "%s/resume", dir);
    assert_int_equal(mkdir(folder, 0700), 0);
    write_sheets(obj, 4, -1);
    struct facet_error err;
    assert_int_equal(sha256_file(obj, truth[0], &err), FACET_OK);
    struct notes n = prepared_known(db, obj, 0, PARAM_AUTO,
                                    (const char (*)[65])truth);
    assert_int_equal(n.reused + n.again + n.not_kept, 0);
    n = prepared_known(db, obj, 0, PARAM_AUTO, (const char (*)[65])truth);
    assert_int_equal(n.reused, 1);
    n = prepared(db, obj, 0, PARAM_AUTO);  /* a new run hashes: the same */
    assert_int_equal(n.reused, 1);
    /* The bytes changed under the cache: a resume's SHA-256 is the new
     * one (it checks them), and the cache is stale. */
    write_sheets(obj, 4, 5);
    assert_int_equal(sha256_file(obj, truth[0], &err), FACET_OK);
    n = prepared_known(db, obj, 0, PARAM_AUTO, (const char (*)[65])truth);
    assert_int_equal(n.again, 1);
    assert_non_null(strstr(n.last, "stale"));
}

/* A cache that cannot be written is a note; the building is prepared. */
static void test_unwritable_cache_is_a_note(void **state)
{
    (void)state;
    char obj[128], db[160];
    snprintf(obj, sizeof obj, "%s/sheets_unwritable.obj", dir);
    write_sheets(obj, 3, -1);
    snprintf(db, sizeof db, "%s/no such folder/runs.db", dir);
    struct notes n = prepared(db, obj, 0, PARAM_AUTO);
    assert_int_equal(n.not_kept, 1);
    n = prepared(db, obj, 0, PARAM_AUTO);
    assert_int_equal(n.not_kept, 1);
    assert_int_equal(n.reused, 0);
}

/* One cache per building and settings, whatever build of Facet made it:
 * a rebuilt Facet writes over its cache (stale by the key) rather than
 * leaving another file of hundreds of MB beside it per build. Another
 * unit, flip or UV names another cache. */
static void test_one_name_across_builds(void **state)
{
    (void)state;
    const char *paths[2] = {"/data/a.obj", "/data/b.obj"};
    struct project_cache_settings one = {UNITS_M, 0, PARAM_AUTO, "build 1"};
    struct project_cache_settings two = one, cm = one, flip = one;
    two.code = "build 2";
    cm.units = UNITS_CM;
    flip.flip_normals = 1;
    char a[512], b[512], c[512], d[512];
    struct facet_error err;
    assert_int_equal(project_cache_path("/w/x.db", paths, 2, &one, a,
                                        sizeof a, &err), FACET_OK);
    assert_int_equal(project_cache_path("/w/y.db", paths, 2, &two, b,
                                        sizeof b, &err), FACET_OK);
    assert_int_equal(project_cache_path("/w/x.db", paths, 2, &cm, c,
                                        sizeof c, &err), FACET_OK);
    assert_int_equal(project_cache_path("/w/x.db", paths, 2, &flip, d,
                                        sizeof d, &err), FACET_OK);
    assert_string_equal(a, b);
    assert_true(strncmp(a, "/w/facet-prepared-", 18) == 0);
    assert_string_not_equal(a, c);
    assert_string_not_equal(a, d);
    char ka[65], kb[65];
    const char digest[1][65] = {"0123456789abcdef0123456789abcdef"
                                "0123456789abcdef0123456789abcdef"};
    project_cache_key(digest, 1, &one, ka);
    project_cache_key(digest, 1, &two, kb);
    assert_string_not_equal(ka, kb);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_round_trip_is_the_same_to_the_bit),
        cmocka_unit_test(test_damage_and_truncation_are_refused),
        cmocka_unit_test(test_another_key_is_stale),
        cmocka_unit_test(test_curvature_not_a_number_is_refused),
        cmocka_unit_test(test_prepared_sums_out_of_range_are_refused),
        cmocka_unit_test(test_study_rebuilds_a_forged_cache),
        cmocka_unit_test(test_checksum_over_pieces),
        cmocka_unit_test(test_reader_asks_its_stop),
        cmocka_unit_test(test_stop_while_reading_the_cache),
        cmocka_unit_test(test_study_reuses_and_rebuilds),
        cmocka_unit_test(test_resume_uses_known_digests),
        cmocka_unit_test(test_unwritable_cache_is_a_note),
        cmocka_unit_test(test_one_name_across_builds),
        cmocka_unit_test(test_old_caches_do_not_pile_up),
    };
    return cmocka_run_group_tests(tests, make_dir, remove_dir);
}
