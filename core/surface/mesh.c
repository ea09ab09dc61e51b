/*
 * mesh.c: building the surface model from an OBJ file. See mesh.h.
 *
 * Steps, each O(n) or O(n log n): select the triangles of the chosen object
 * or group; weld OBJ vertices with identical coordinates (after scaling) by
 * hashing; compact to the vertices the selection uses; drop triangles whose
 * corners weld together; copy per-corner UV and normals; face normals and
 * areas; edge adjacency by sorting half-edges; vertex-to-triangle
 * incidence; boundary loops; components; area and bounding box. The
 * caller's stop is asked every STOP_EVERY triangles and between the steps
 * (the sort of the half-edges, the longest step that cannot be cut, takes
 * about half a second for ten million triangles).
 */
#include "core/surface/mesh.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/base/vec3.h"
#include "core/base/units.h"

/* Triangles welded or copied between two questions to the stop: a few
 * milliseconds of work. */
#define STOP_EVERY ((size_t)1 << 16)

/* Whether the stop fires at triangle n of a loop (every STOP_EVERY). */
static int stop_at(const struct facet_stop *stop, size_t n)
{
    return n % STOP_EVERY == STOP_EVERY - 1 && facet_stop_requested(stop);
}

double mesh_units_scale(enum mesh_units u)
{
    switch (u) {
    case UNITS_CM: return 0.01;
    case UNITS_MM: return UNITS_METRES_PER_MM;
    case UNITS_IN: return 0.0254;
    case UNITS_FT: return 0.3048;
    default:       return 1.0;
    }
}

const char *mesh_units_name(enum mesh_units u)
{
    switch (u) {
    case UNITS_CM: return "cm";
    case UNITS_MM: return "mm";
    case UNITS_IN: return "in";
    case UNITS_FT: return "ft";
    default:       return "m";
    }
}

int mesh_units_parse(const char *text, const char *what,
                     enum mesh_units *out, struct facet_error *err)
{
    static const enum mesh_units all[] = {UNITS_M, UNITS_CM, UNITS_MM,
                                          UNITS_IN, UNITS_FT};
    for (size_t k = 0; k < sizeof all / sizeof all[0]; k++)
        if (strcmp(text, mesh_units_name(all[k])) == 0) {
            *out = all[k];
            return FACET_OK;
        }
    return facet_error_set(err, FACET_EINPUT,
        "%s: units '%s' unknown (choose m, cm, mm, in or ft)", what, text);
}

void mesh_free(struct mesh *mesh)
{
    free(mesh->position);
    free(mesh->source_vertex);
    free(mesh->triangle);
    free(mesh->source_face);
    free(mesh->face_normal);
    free(mesh->face_area);
    free(mesh->uv);
    free(mesh->corner_normal);
    free(mesh->neighbour);
    free(mesh->vertex_start);
    free(mesh->vertex_triangles);
    free(mesh->on_boundary);
    free(mesh->loop_start);
    free(mesh->loop_vertices);
    free(mesh->component);
    memset(mesh, 0, sizeof *mesh);
}

/* Finds name in a table; returns its index or -1. */
static long find_name(const struct obj_name *names, size_t count,
                      const char *name)
{
    for (size_t i = 1; i < count; i++)
        if (strcmp(names[i].text, name) == 0)
            return (long)i;
    return -1;
}

static int unknown_name(const char *kind, const char *name,
                        const struct obj_name *names, size_t count,
                        struct facet_error *err)
{
    char list[240];
    obj_names_list(names, count, list, sizeof list);
    if (count <= 1)
        return facet_error_set(err, FACET_EINPUT,
            "no %s named '%s' (the file has no %s names)", kind, name, kind);
    return facet_error_set(err, FACET_EINPUT,
        "no %s named '%s' (the file has: %s)", kind, name, list);
}

/* 64-bit hash of three doubles' bit patterns. */
static uint64_t hash_point(const double p[3])
{
    uint64_t h = 1469598103934665603ull;
    for (int k = 0; k < 3; k++) {
        double x = p[k] == 0 ? 0 : p[k];  /* -0 and 0 weld */
        uint64_t bits;
        memcpy(&bits, &x, sizeof bits);
        h ^= bits;
        h *= 1099511628211ull;
        h ^= h >> 29;
    }
    return h;
}

struct half_edge {
    uint32_t low, high;  /* vertex pair, low < high */
    uint32_t triangle;
    uint8_t corner;      /* edge from corner to corner + 1 */
};

static int compare_half_edges(const void *a, const void *b)
{
    const struct half_edge *x = a, *y = b;
    if (x->low != y->low)
        return x->low < y->low ? -1 : 1;
    if (x->high != y->high)
        return x->high < y->high ? -1 : 1;
    if (x->triangle != y->triangle)
        return x->triangle < y->triangle ? -1 : 1;
    return x->corner < y->corner ? -1 : x->corner > y->corner;
}

static uint32_t find_root(uint32_t *parent, uint32_t x)
{
    while (parent[x] != x) {
        parent[x] = parent[parent[x]];
        x = parent[x];
    }
    return x;
}

/* Adjacency from sorted half-edges: two half-edges on one vertex pair are
 * neighbours; three or more make a non-manifold edge with no neighbours. */
static int build_adjacency(struct mesh *m)
{
    size_t nhalf = 3 * m->ntriangles;
    struct half_edge *edges = malloc((nhalf ? nhalf : 1) * sizeof *edges);
    m->neighbour = malloc((nhalf ? nhalf : 1) * sizeof *m->neighbour);
    if (edges == NULL || m->neighbour == NULL) {
        free(edges);
        return FACET_EWORK;
    }
    for (size_t t = 0; t < m->ntriangles; t++)
        for (int k = 0; k < 3; k++) {
            uint32_t a = m->triangle[3 * t + k];
            uint32_t b = m->triangle[3 * t + (k + 1) % 3];
            struct half_edge *e = &edges[3 * t + k];
            e->low = a < b ? a : b;
            e->high = a < b ? b : a;
            e->triangle = (uint32_t)t;
            e->corner = (uint8_t)k;
            m->neighbour[3 * t + k] = MESH_NONE;
        }
    qsort(edges, nhalf, sizeof *edges, compare_half_edges);
    for (size_t s = 0; s < nhalf;) {
        size_t e = s + 1;
        while (e < nhalf && edges[e].low == edges[s].low &&
               edges[e].high == edges[s].high)
            e++;
        if (e - s == 2) {
            m->neighbour[3 * (size_t)edges[s].triangle + edges[s].corner] =
                edges[s + 1].triangle;
            m->neighbour[3 * (size_t)edges[s + 1].triangle +
                         edges[s + 1].corner] = edges[s].triangle;
        } else if (e - s > 2) {
            m->nonmanifold_edges++;
        }
        s = e;
    }
    free(edges);
    return FACET_OK;
}

static int build_incidence(struct mesh *m)
{
    m->vertex_start = calloc(m->nvertices + 1, sizeof *m->vertex_start);
    m->vertex_triangles = malloc((3 * m->ntriangles + 1) *
                                 sizeof *m->vertex_triangles);
    m->on_boundary = calloc(m->nvertices ? m->nvertices : 1, 1);
    if (!m->vertex_start || !m->vertex_triangles || !m->on_boundary)
        return FACET_EWORK;
    for (size_t k = 0; k < 3 * m->ntriangles; k++)
        m->vertex_start[m->triangle[k] + 1]++;
    for (size_t v = 0; v < m->nvertices; v++)
        m->vertex_start[v + 1] += m->vertex_start[v];
    uint32_t *fill = malloc((m->nvertices + 1) * sizeof *fill);
    if (fill == NULL)
        return FACET_EWORK;
    memcpy(fill, m->vertex_start, (m->nvertices + 1) * sizeof *fill);
    for (size_t t = 0; t < m->ntriangles; t++)
        for (int k = 0; k < 3; k++)
            m->vertex_triangles[fill[m->triangle[3 * t + k]]++] = (uint32_t)t;
    free(fill);
    for (size_t t = 0; t < m->ntriangles; t++)
        for (int k = 0; k < 3; k++)
            if (m->neighbour[3 * t + k] == MESH_NONE) {
                m->on_boundary[m->triangle[3 * t + k]] = 1;
                m->on_boundary[m->triangle[3 * t + (k + 1) % 3]] = 1;
            }
    return FACET_OK;
}

/* Boundary loops: follow boundary half-edges (those with no neighbour)
 * from head to tail. At a vertex where several loops touch, the next edge
 * is any unused boundary edge leaving it, so every edge is used once and
 * the walk always ends. */
static int build_loops(struct mesh *m)
{
    size_t nhalf = 3 * m->ntriangles;
    /* Boundary half-edges leaving each vertex, compressed. */
    uint32_t *start = calloc(m->nvertices + 1, sizeof *start);
    if (start == NULL)
        return FACET_EWORK;
    size_t nboundary = 0;
    for (size_t h = 0; h < nhalf; h++)
        if (m->neighbour[h] == MESH_NONE) {
            start[m->triangle[h] + 1]++;
            nboundary++;
        }
    for (size_t v = 0; v < m->nvertices; v++)
        start[v + 1] += start[v];
    uint32_t *leaving = malloc((nboundary + 1) * sizeof *leaving);
    uint32_t *fill = malloc((m->nvertices + 1) * sizeof *fill);
    unsigned char *used = calloc(nboundary + 1, 1);
    m->loop_vertices = malloc((nboundary + 1) * sizeof *m->loop_vertices);
    m->loop_start = malloc((nboundary + 2) * sizeof *m->loop_start);
    if (!leaving || !fill || !used || !m->loop_vertices || !m->loop_start) {
        free(start);
        free(leaving);
        free(fill);
        free(used);
        return FACET_EWORK;
    }
    memcpy(fill, start, (m->nvertices + 1) * sizeof *fill);
    for (size_t h = 0; h < nhalf; h++)
        if (m->neighbour[h] == MESH_NONE)
            leaving[fill[m->triangle[h]]++] = (uint32_t)h;

    size_t written = 0;
    m->nloops = 0;
    for (size_t b = 0; b < nboundary; b++) {
        if (used[b])
            continue;
        m->loop_start[m->nloops++] = (uint32_t)written;
        size_t current = b;
        for (;;) {
            used[current] = 1;
            uint32_t h = leaving[current];
            uint32_t from = m->triangle[h];
            size_t t = h / 3;
            uint32_t to = m->triangle[3 * t + (h % 3 + 1) % 3];
            m->loop_vertices[written++] = from;
            size_t next = nboundary;
            for (uint32_t k = start[to]; k < start[to + 1]; k++)
                if (!used[k]) {
                    next = k;
                    break;
                }
            if (next == nboundary)
                break;
            current = next;
        }
    }
    m->loop_start[m->nloops] = (uint32_t)written;
    free(start);
    free(leaving);
    free(fill);
    free(used);
    return FACET_OK;
}

static int build_components(struct mesh *m)
{
    uint32_t *parent = malloc((m->ntriangles + 1) * sizeof *parent);
    m->component = malloc((m->ntriangles + 1) * sizeof *m->component);
    if (parent == NULL || m->component == NULL) {
        free(parent);
        return FACET_EWORK;
    }
    for (size_t t = 0; t < m->ntriangles; t++)
        parent[t] = (uint32_t)t;
    for (size_t h = 0; h < 3 * m->ntriangles; h++) {
        uint32_t other = m->neighbour[h];
        if (other == MESH_NONE)
            continue;
        uint32_t a = find_root(parent, (uint32_t)(h / 3));
        uint32_t b = find_root(parent, other);
        if (a != b)
            parent[a < b ? b : a] = a < b ? a : b;
    }
    m->ncomponents = 0;
    for (size_t t = 0; t < m->ntriangles; t++) {
        uint32_t root = find_root(parent, (uint32_t)t);
        if (root == t)
            m->component[t] = (uint32_t)m->ncomponents++;
        else
            m->component[t] = m->component[root];
    }
    free(parent);
    return FACET_OK;
}

int mesh_build(const struct obj_file *obj, const struct mesh_options *options,
               struct mesh *out, struct facet_error *err)
{
    return mesh_build_stoppable(obj, options, NULL, out, err);
}

int mesh_build_stoppable(const struct obj_file *obj,
                         const struct mesh_options *options,
                         const struct facet_stop *stop, struct mesh *out,
                         struct facet_error *err)
{
    memset(out, 0, sizeof *out);
    long object = 0, group = 0;
    if (options->object != NULL &&
        (object = find_name(obj->objects, obj->nobjects, options->object)) < 0)
        return unknown_name("object", options->object, obj->objects,
                            obj->nobjects, err);
    if (options->group != NULL &&
        (group = find_name(obj->groups, obj->ngroups, options->group)) < 0)
        return unknown_name("group", options->group, obj->groups,
                            obj->ngroups, err);
    uint32_t *list = malloc((obj->ntriangles + 1) * sizeof *list);
    if (list == NULL)
        return facet_error_set(err, FACET_EWORK, "out of memory (mesh)");
    size_t selected = 0;
    for (size_t t = 0; t < obj->ntriangles; t++) {
        if ((options->object && obj->triangle_object[t] != (uint32_t)object) ||
            (options->group && obj->triangle_group[t] != (uint32_t)group))
            continue;
        list[selected++] = (uint32_t)t;
    }
    if (selected == 0) {
        free(list);
        if (options->object || options->group)
            return facet_error_set(err, FACET_EINPUT,
                "the selected %s has no faces",
                options->object ? "object" : "group");
        return facet_error_set(err, FACET_EINPUT, "the file has no faces");
    }
    int rc = mesh_build_triangles(obj, options->units, list, selected,
                                  stop, out, err);
    free(list);
    return rc;
}

int mesh_build_triangles(const struct obj_file *obj, enum mesh_units units,
                         const uint32_t *list, size_t selected,
                         const struct facet_stop *stop, struct mesh *out,
                         struct facet_error *err)
{
    memset(out, 0, sizeof *out);
    if (selected == 0)
        return facet_error_set(err, FACET_EINPUT, "no faces");
    double scale = mesh_units_scale(units);

    /* Weld: one mesh vertex per distinct scaled position among the
     * selected corners, found by hashing each corner's position (the
     * table's size follows the selection, not the file, so that the
     * hundred surfaces of a project cost one file's work in all). */
    size_t ncorners = 3 * selected;
    size_t capacity = 16;
    while (capacity < 2 * ncorners)
        capacity *= 2;
    uint32_t *table = malloc(capacity * sizeof *table);
    uint32_t *welded = malloc(ncorners * sizeof *welded);
    out->position = malloc((3 * ncorners + 3) * sizeof *out->position);
    out->source_vertex = malloc((ncorners + 1) * sizeof *out->source_vertex);
    if (!welded || !table || !out->position || !out->source_vertex) {
        free(welded);
        free(table);
        return facet_error_set(err, FACET_EWORK, "out of memory (mesh)");
    }
    for (size_t i = 0; i < capacity; i++)
        table[i] = MESH_NONE;
    for (size_t n = 0; n < selected; n++) {
        if (stop_at(stop, n)) {
            free(welded);
            free(table);
            return facet_stop_error(err);
        }
        size_t t = list[n];
        for (int k = 0; k < 3; k++) {
            uint32_t v = obj->corner[3 * t + k].v;
            double p[3];
            for (int x = 0; x < 3; x++)
                p[x] = obj->position[3 * (size_t)v + x] * scale;
            size_t slot = hash_point(p) & (capacity - 1);
            while (table[slot] != MESH_NONE) {
                const double *q = out->position + 3 * (size_t)table[slot];
                if (q[0] == p[0] && q[1] == p[1] && q[2] == p[2])
                    break;
                slot = (slot + 1) & (capacity - 1);
            }
            if (table[slot] == MESH_NONE) {
                table[slot] = (uint32_t)out->nvertices;
                memcpy(out->position + 3 * out->nvertices, p, sizeof p);
                out->source_vertex[out->nvertices++] = v;
            }
            welded[3 * n + k] = table[slot];
        }
    }
    free(table);
    /* Give back what the welding did not use. */
    double *shrunk = realloc(out->position,
                             (3 * out->nvertices + 3) * sizeof *shrunk);
    if (shrunk != NULL)
        out->position = shrunk;
    uint32_t *shrunk_source = realloc(out->source_vertex,
        (out->nvertices + 1) * sizeof *shrunk_source);
    if (shrunk_source != NULL)
        out->source_vertex = shrunk_source;

    out->triangle = malloc(3 * selected * sizeof *out->triangle);
    out->source_face = malloc(selected * sizeof *out->source_face);
    out->face_normal = malloc(3 * selected * sizeof *out->face_normal);
    out->face_area = malloc(selected * sizeof *out->face_area);
    out->uv = malloc(6 * selected * sizeof *out->uv);
    out->corner_normal = malloc(9 * selected * sizeof *out->corner_normal);
    if (!out->triangle || !out->source_face || !out->face_normal ||
        !out->face_area || !out->uv || !out->corner_normal) {
        free(welded);
        return facet_error_set(err, FACET_EWORK, "out of memory (mesh)");
    }
    out->has_uv = obj->ntexcoords > 0;
    out->has_normals = obj->nnormals > 0;
    for (int k = 0; k < 3; k++) {
        out->bbox_min[k] = INFINITY;
        out->bbox_max[k] = -INFINITY;
    }
    for (size_t m = 0; m < selected; m++) {
        if (stop_at(stop, m)) {
            free(welded);
            return facet_stop_error(err);
        }
        size_t t = list[m];
        const struct obj_corner *c = obj->corner + 3 * t;
        uint32_t a = welded[3 * m], b = welded[3 * m + 1];
        uint32_t d = welded[3 * m + 2];
        if (a == b || b == d || a == d) {
            out->ndegenerate++;
            continue;
        }
        size_t n = out->ntriangles++;
        out->triangle[3 * n] = a;
        out->triangle[3 * n + 1] = b;
        out->triangle[3 * n + 2] = d;
        out->source_face[n] = obj->triangle_face[t];
        for (int k = 0; k < 3; k++) {
            if (c[k].vt == OBJ_NONE) {
                out->has_uv = 0;
            } else {
                out->uv[6 * n + 2 * k] = obj->texcoord[2 * (size_t)c[k].vt];
                out->uv[6 * n + 2 * k + 1] =
                    obj->texcoord[2 * (size_t)c[k].vt + 1];
            }
            double *normal = out->corner_normal + 9 * n + 3 * k;
            if (c[k].vn == OBJ_NONE) {
                out->has_normals = 0;
                normal[0] = normal[1] = normal[2] = 0;
            } else {
                const double *vn = obj->normal + 3 * (size_t)c[k].vn;
                double length = sqrt(vn[0] * vn[0] + vn[1] * vn[1] +
                                     vn[2] * vn[2]);
                for (int x = 0; x < 3; x++)
                    normal[x] = length > 0 ? vn[x] / length : 0;
            }
        }
        const double *p = out->position + 3 * (size_t)a;
        const double *q = out->position + 3 * (size_t)b;
        const double *r = out->position + 3 * (size_t)d;
        double e1[3], e2[3], cr[3];
        vec3_sub(q, p, e1);
        vec3_sub(r, p, e2);
        vec3_cross(e1, e2, cr);
        double length = vec3_length(cr);
        out->face_area[n] = 0.5 * length;
        out->area += 0.5 * length;
        for (int x = 0; x < 3; x++)
            out->face_normal[3 * n + x] = length > 0 ? cr[x] / length : 0;
    }
    free(welded);
    if (!out->has_uv) {
        free(out->uv);
        out->uv = NULL;
    }
    if (!out->has_normals) {
        free(out->corner_normal);
        out->corner_normal = NULL;
    }
    for (size_t v = 0; v < out->nvertices; v++)
        for (int k = 0; k < 3; k++) {
            out->bbox_min[k] = fmin(out->bbox_min[k], out->position[3 * v + k]);
            out->bbox_max[k] = fmax(out->bbox_max[k], out->position[3 * v + k]);
        }
    if (out->ntriangles == 0)
        return facet_error_set(err, FACET_EINPUT,
            "every triangle is degenerate (its corners weld together)");
    /* Finite coordinates can still overflow once multiplied: a surface
     * whose extent or area is not a number has no panels to give. */
    double extent = 0;
    for (int k = 0; k < 3; k++)
        extent = fmax(extent, out->bbox_max[k] - out->bbox_min[k]);
    if (!isfinite(out->area) || !isfinite(extent) || extent > 1e15)
        return facet_error_about(err, FACET_SETTING_UNITS, FACET_EINPUT,
            "the surface's size overflows (it spans %.3g m, an area of %g "
            "m^2): check the coordinates and the units", extent, out->area);

    int (*const step[4])(struct mesh *) = {build_adjacency, build_incidence,
                                           build_loops, build_components};
    for (int k = 0; k < 4; k++) {
        int rc = facet_stop_check(stop, err);
        if (rc != FACET_OK)
            return rc;
        if (step[k](out) != FACET_OK)
            return facet_error_set(err, FACET_EWORK, "out of memory (mesh)");
    }
    return FACET_OK;
}

double mesh_diagonal(const struct mesh *mesh)
{
    double sum = 0;
    for (int k = 0; k < 3; k++) {
        double d = mesh->bbox_max[k] - mesh->bbox_min[k];
        sum += d * d;
    }
    return sqrt(sum);
}

static int building_sized(double diagonal)
{
    return diagonal >= MESH_BUILDING_MIN && diagonal <= MESH_BUILDING_MAX;
}

int mesh_units_mistaken(const struct mesh *mesh, enum mesh_units given,
                        enum mesh_units *better)
{
    return mesh_units_mistaken_at(mesh_diagonal(mesh), given, better);
}

int mesh_units_mistaken_at(double diagonal, enum mesh_units given,
                           enum mesh_units *better)
{
    static const enum mesh_units all[] = {UNITS_M, UNITS_CM, UNITS_MM,
                                          UNITS_IN, UNITS_FT};
    if (!(diagonal > 0) || !isfinite(diagonal) || building_sized(diagonal))
        return 0;
    /* The typical building: the geometric middle of the sizes a building
     * has, so that no unit is preferred for its name. */
    const double typical = sqrt(MESH_BUILDING_MIN * MESH_BUILDING_MAX);
    double best = INFINITY;
    for (size_t k = 0; k < sizeof all / sizeof all[0]; k++) {
        if (all[k] == given)
            continue;
        double d = diagonal / mesh_units_scale(given) *
                   mesh_units_scale(all[k]);
        double off = fabs(log(d / typical));
        if (building_sized(d) && off < best) {
            best = off;
            *better = all[k];
        }
    }
    return best < INFINITY;
}

int mesh_units_warning(const struct mesh *mesh, enum mesh_units units,
                       char *warning, size_t size)
{
    double diagonal = mesh_diagonal(mesh);
    if (diagonal > MESH_BUILDING_MAX) {
        snprintf(warning, size,
                 "the surface is %.1f km across in %s; if the file is in "
                 "millimetres, set its units to mm", units_km(diagonal),
                 mesh_units_name(units));
        return 1;
    }
    if (diagonal > 0 && diagonal < MESH_BUILDING_MIN) {
        snprintf(warning, size,
                 "the surface is %.1f mm across in %s; if the file is in "
                 "metres, set its units to m", units_mm(diagonal),
                 mesh_units_name(units));
        return 1;
    }
    return 0;
}
