/*
 * cmd_curvature.c: `facet curvature SURFACE.obj`, the vertex curvature
 * every panel's k1 and k2 come from, one row per vertex, so that a user can
 * hold it against their CAD's curvature analysis and a test against a
 * formula.
 *
 * Rows are the welded vertices, in the order of the first OBJ `v` welded
 * into each (`v` gives that OBJ index, 1-based as in the file), whatever
 * order the welding numbered them in; numbers are the shortest text that
 * reads back to the same double (numformat.h's number_exact).
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "classify_flags.h"
#include "command.h"
#include "core/base/numformat.h"
#include "core/surface/curvature.h"
#include "core/out/json.h"
#include "core/out/outfile.h"
#include "core/surface/surface.h"
#include "shown.h"

static const char csv_header[] =
    "v,x,y,z,k1,k2,K,H,normal_x,normal_y,normal_z,boundary\n";

/* A welded vertex and the first OBJ v welded into it. */
struct vertex_source {
    uint32_t source;
    size_t vertex;
};

static int by_source(const void *a, const void *b)
{
    uint32_t x = ((const struct vertex_source *)a)->source;
    uint32_t y = ((const struct vertex_source *)b)->source;
    return (x > y) - (x < y);
}

/* The welded vertices of m in the order of their first OBJ v (the file's
 * order): malloc'ed, nvertices of them, or NULL when out of memory. */
static size_t *file_order(const struct mesh *m)
{
    size_t n = m->nvertices ? m->nvertices : 1;
    struct vertex_source *pair = malloc(n * sizeof *pair);
    size_t *order = malloc(n * sizeof *order);
    if (pair == NULL || order == NULL) {
        free(pair);
        free(order);
        return NULL;
    }
    for (size_t v = 0; v < m->nvertices; v++)
        pair[v] = (struct vertex_source){m->source_vertex[v], v};
    qsort(pair, m->nvertices, sizeof *pair, by_source);
    for (size_t v = 0; v < m->nvertices; v++)
        order[v] = pair[v].vertex;
    free(pair);
    return order;
}

/* Writes the rows as CSV in order, every double the shortest text that
 * reads back to it. */
static void write_csv(FILE *out, const struct mesh *m,
                      const struct curvature *c, const size_t *order)
{
    fputs(csv_header, out);
    for (size_t r = 0; r < m->nvertices; r++) {
        size_t v = order[r];
        const double *p = m->position + 3 * v, *n = c->normal + 3 * v;
        double k1 = c->k1[v], k2 = c->k2[v];
        double value[10] = {p[0], p[1], p[2], k1, k2, k1 * k2, (k1 + k2) / 2,
                            n[0], n[1], n[2]};
        fprintf(out, "%lu", (unsigned long)m->source_vertex[v] + 1);
        for (int k = 0; k < 10; k++) {
            char text[NUMBER_EXACT_SIZE];
            number_exact(text, value[k]);
            fprintf(out, ",%s", text);
        }
        fprintf(out, ",%d\n", m->on_boundary ? m->on_boundary[v] : 0);
    }
}

/* Writes the rows as one JSON object, through the writer every --json of
 * Facet uses. */
static void write_json(FILE *out, const struct surface *s,
                       const struct curvature *c, int flip,
                       const size_t *order)
{
    const struct mesh *m = &s->mesh;
    struct json_writer w;
    json_init(&w, out);
    json_begin_object(&w);
    json_key(&w, "file");
    json_string(&w, s->path);
    json_key(&w, "units");
    json_string(&w, mesh_units_name(s->units));
    json_key(&w, "flip_normals");
    json_bool(&w, flip);
    json_key(&w, "vertices");
    json_begin_array(&w);
    for (size_t row = 0; row < m->nvertices; row++) {
        size_t v = order[row];
        const double *p = m->position + 3 * v, *n = c->normal + 3 * v;
        double k1 = c->k1[v], k2 = c->k2[v];
        json_begin_object(&w);
        json_key(&w, "v");
        json_integer(&w, (long long)m->source_vertex[v] + 1);
        json_key(&w, "position");
        json_begin_array(&w);
        for (int r = 0; r < 3; r++)
            json_number(&w, p[r]);
        json_end_array(&w);
        json_key(&w, "k1");
        json_number(&w, k1);
        json_key(&w, "k2");
        json_number(&w, k2);
        json_key(&w, "K");
        json_number(&w, k1 * k2);
        json_key(&w, "H");
        json_number(&w, (k1 + k2) / 2);
        json_key(&w, "normal");
        json_begin_array(&w);
        for (int r = 0; r < 3; r++)
            json_number(&w, n[r]);
        json_end_array(&w);
        json_key(&w, "boundary");
        json_bool(&w, m->on_boundary && m->on_boundary[v]);
        json_end_object(&w);
    }
    json_end_array(&w);
    json_end_object(&w);
    json_finish(&w);
}

/* The human summary: ranges of k1 and k2, inside and on the boundary. */
static void print_summary(const struct surface *s, const struct curvature *c)
{
    const struct mesh *m = &s->mesh;
    double lo[2][2] = {{INFINITY, INFINITY}, {INFINITY, INFINITY}};
    double hi[2][2] = {{-INFINITY, -INFINITY}, {-INFINITY, -INFINITY}};
    size_t count[2] = {0, 0};
    for (size_t v = 0; v < m->nvertices; v++) {
        int b = m->on_boundary ? m->on_boundary[v] != 0 : 0;
        count[b]++;
        lo[b][0] = fmin(lo[b][0], c->k1[v]);
        hi[b][0] = fmax(hi[b][0], c->k1[v]);
        lo[b][1] = fmin(lo[b][1], c->k2[v]);
        hi[b][1] = fmax(hi[b][1], c->k2[v]);
    }
    shown_line(stdout, "%-15s %s", "surface", s->path);
    printf("%-15s %zu\n", "vertices", m->nvertices);
    static const char *const where[2] = {"inside", "boundary"};
    for (int b = 0; b < 2; b++) {
        if (count[b] == 0)
            continue;
        printf("%-15s %zu vertices, k1 %.6g .. %.6g, k2 %.6g .. %.6g 1/m\n",
               where[b], count[b], lo[b][0], hi[b][0], lo[b][1], hi[b][1]);
    }
    printf("(--csv FILE or --json for every vertex)\n");
}

/* The options as given (pointing into argv), NULL or 0 when absent. */
struct curvature_args {
    const char *csv;
    int json, flip, force;
};

static const struct arg_option curvature_options[] = {
    {"csv", 0, ARG_STRING, offsetof(struct curvature_args, csv), "FILE",
     "one row per vertex: v (the OBJ index), x, y, z (m), k1, k2 (1/m), K "
     "(1/m^2), H (1/m), normal_x/y/z, boundary (1 on the boundary)", NULL},
    {"json", 0, ARG_FLAG, offsetof(struct curvature_args, json), NULL,
     "the same as one JSON object: file, units, flip_normals, vertices [{v, "
     "position, k1, k2, K, H, normal, boundary}]", NULL},
    {"flip-normals", 0, ARG_FLAG, offsetof(struct curvature_args, flip),
     NULL, "reverse the normal, and so every sign", NULL},
    {"force", 'f', ARG_FLAG, offsetof(struct curvature_args, force), NULL,
     "overwrite an existing --csv file", NULL},
    {NULL, 0, ARG_FLAG, 0, NULL, NULL, NULL},
};

static int curvature_run(int argc, char **argv, struct facet_error *err)
{
    struct surface_flags which = {NULL, NULL, NULL};
    struct curvature_args a = {NULL, 0, 0, 0};
    const struct arg_table own = {curvature_options, &a};
    const struct arg_table shared = {surface_flags_options, &which};
    const char *path;
    int rc = args_parse_one(argc, argv, &own, &shared, &path,
            "curvature: name one OBJ file (facet curvature FILE.obj)", err);
    if (rc != FACET_OK)
        return rc;
    const char *csv = a.csv;
    int json = a.json, flip = a.flip, force = a.force;
    if (csv != NULL && json)
        return facet_error_set(err, FACET_EINPUT,
            "curvature: give --csv FILE or --json, not both");
    struct mesh_options mesh_options;
    if ((rc = surface_flags_apply(&which, &mesh_options, err)) != FACET_OK)
        return rc;
    /* Refuse an existing CSV before the work, not after it. */
    if (csv != NULL && (rc = outfile_check(csv, force, err)) != FACET_OK)
        return rc;

    struct surface surface;
    struct curvature curvature;
    memset(&curvature, 0, sizeof curvature);
    rc = surface_open(path, &mesh_options, &surface, err);
    if (rc == FACET_OK && which.units == NULL)
        rc = surface_units_check(&surface, err);
    if (rc == FACET_OK)
        rc = curvature_at_vertices(&surface.mesh, flip, &curvature, err);
    if (rc == FACET_OK) {
        for (int i = 0; i < surface.nwarnings; i++)
            shown_line(stderr, "facet: warning: %s", surface.warnings[i]);
        size_t *order = csv != NULL || json ? file_order(&surface.mesh)
                                            : NULL;
        if ((csv != NULL || json) && order == NULL) {
            rc = facet_error_set(err, FACET_EWORK, "out of memory");
        } else if (csv != NULL) {
            struct outfile f;
            rc = outfile_open(&f, csv, force, err);
            if (rc == FACET_OK) {
                write_csv(f.out, &surface.mesh, &curvature, order);
                rc = outfile_commit(&f, err);
            }
        } else if (json) {
            write_json(stdout, &surface, &curvature, flip, order);
        } else {
            print_summary(&surface, &curvature);
        }
        free(order);
    }
    curvature_free(&curvature);
    surface_close(&surface);
    return rc;
}

const struct command cmd_curvature = {
    .name = "curvature",
    .usage = "SURFACE.obj [--csv FILE | --json] [--units U]\n"
             "       [--object NAME] [--group NAME] [--flip-normals] "
             "[--force]",
    .summary = "Curvature at every vertex: position, k1, k2, K, H, normal.",
    .before = "",
    .options = curvature_options,
    .shared = surface_flags_options,
    .after =
        "Without --csv or --json: the ranges of k1 and k2 inside and on the\n"
        "boundary. Every number is written so that it reads back exactly.\n",
    .run = curvature_run,
};
