/*
 * param_grid.c: recovering the (i, j) of a structured quad grid. See
 * param_grid.h.
 *
 * The quads come back from the triangles: the two triangles of one OBJ
 * face (mesh->source_face) share its diagonal; in a file of triangles
 * only, two triangles whose longest edges are the one they share. From a corner quad, a walk
 * across quad edges gives each next quad the coordinates its shared edge
 * implies; the mesh is a structured grid when no vertex gets two different
 * (i, j) and the vertices fill the rectangle (NU + 1) x (NV + 1) once each.
 */
#include "core/surface/param_grid.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/base/vec3.h"

struct quads {
    size_t count;
    uint32_t *corner;          /* count x 4 vertices, in the faces' winding */
    uint32_t *of_triangle;     /* #T: the quad a triangle belongs to */
};

static void quads_free(struct quads *q)
{
    free(q->corner);
    free(q->of_triangle);
}

/* Adds the quad of triangle t and its neighbour n across t's edge k (from
 * corner k to k + 1), in t's winding. */
static void add_quad(const struct mesh *mesh, struct quads *q, size_t t,
                     int k, uint32_t n)
{
    const uint32_t *a = mesh->triangle + 3 * t;
    const uint32_t *b = mesh->triangle + 3 * (size_t)n;
    uint32_t d = b[0];
    for (int x = 0; x < 3; x++)
        if (b[x] != a[k] && b[x] != a[(k + 1) % 3])
            d = b[x];
    uint32_t *c = q->corner + 4 * q->count;
    c[0] = a[k];
    c[1] = d;
    c[2] = a[(k + 1) % 3];
    c[3] = a[(k + 2) % 3];
    q->of_triangle[t] = q->of_triangle[n] = (uint32_t)q->count;
    q->count++;
}

/* The corner where triangle t's longest edge starts. */
static int longest_edge(const struct mesh *mesh, size_t t)
{
    const uint32_t *tri = mesh->triangle + 3 * t;
    int best = 0;
    double longest = -1;
    for (int k = 0; k < 3; k++) {
        double length = vec3_distance(mesh->position + 3 * (size_t)tri[k],
                                      mesh->position +
                                          3 * (size_t)tri[(k + 1) % 3]);
        if (length > longest) {
            longest = length;
            best = k;
        }
    }
    return best;
}

/* A file of triangles only (an export that split its quads): each
 * triangle pairs with the neighbour across its longest edge when that is
 * the neighbour's longest edge too, the diagonal of the quad they split.
 * Returns the triangles left unpaired. */
static size_t pair_triangles(const struct mesh *mesh, struct quads *q)
{
    size_t unpaired = 0;
    for (size_t t = 0; t < mesh->ntriangles; t++) {
        int k = longest_edge(mesh, t);
        uint32_t n = mesh->neighbour[3 * t + k];
        if (n == MESH_NONE) {
            unpaired++;
            continue;
        }
        const uint32_t *a = mesh->triangle + 3 * t;
        const uint32_t *b = mesh->triangle + 3 * (size_t)n;
        int m = longest_edge(mesh, n);
        if (b[m] != a[(k + 1) % 3] || b[(m + 1) % 3] != a[k]) {
            unpaired++;
            continue;
        }
        if (n > t)
            add_quad(mesh, q, t, k, n);
    }
    return unpaired;
}

/* The quads: the two triangles of each four-cornered face, or, in a file
 * of triangles only, the pairs pair_triangles finds (*paired set).
 * Returns FACET_OK, or FACET_EINPUT (why set) when they are not all
 * quads. */
static int find_quads(const struct mesh *mesh, struct quads *q, int *paired,
                      char *why, size_t size)
{
    memset(q, 0, sizeof *q);
    *paired = 0;
    size_t nt = mesh->ntriangles;
    q->corner = malloc(sizeof(uint32_t) * 4 * (nt / 2 + 1));
    q->of_triangle = malloc(sizeof(uint32_t) * (nt ? nt : 1));
    if (q->corner == NULL || q->of_triangle == NULL)
        return FACET_EWORK;
    size_t other = 0, single = 0, faces = 0;
    for (size_t t = 0; t < nt;) {
        size_t end = t + 1;
        while (end < nt && mesh->source_face[end] == mesh->source_face[t])
            end++;
        faces++;
        single += end - t == 1;
        /* The edge of t that the second triangle lies across. */
        int k = 0;
        while (end - t == 2 && k < 3 &&
               mesh->neighbour[3 * t + k] != (uint32_t)(t + 1))
            k++;
        if (end - t != 2 || k == 3)
            other++;
        else
            add_quad(mesh, q, t, k, (uint32_t)(t + 1));
        t = end;
    }
    if (single == faces && faces > 0) {
        q->count = 0;
        *paired = 1;
        size_t unpaired = pair_triangles(mesh, q);
        if (unpaired > 0) {
            snprintf(why, size, "not a quad mesh (%zu of its %zu triangles "
                     "do not pair into quads along their longest edges)",
                     unpaired, nt);
            return FACET_EINPUT;
        }
        return FACET_OK;
    }
    if (other > 0) {
        snprintf(why, size, "not a quad mesh (%zu faces are not quads)",
                 other);
        return FACET_EINPUT;
    }
    return FACET_OK;
}

/* Which of quad's corners vertex is, or -1. */
static int corner_of(const uint32_t *quad, uint32_t vertex)
{
    for (int k = 0; k < 4; k++)
        if (quad[k] == vertex)
            return k;
    return -1;
}

/* side_quad[4 q + s]: the quad across side s (corners s, s + 1) of quad q,
 * or MESH_NONE on the boundary. */
static uint32_t *quad_neighbours(const struct mesh *mesh,
                                 const struct quads *q)
{
    uint32_t *side_quad = malloc(sizeof(uint32_t) * 4 * (q->count + 1));
    if (side_quad == NULL)
        return NULL;
    for (size_t k = 0; k < 4 * q->count; k++)
        side_quad[k] = MESH_NONE;
    for (size_t t = 0; t < mesh->ntriangles; t++) {
        uint32_t quad = q->of_triangle[t];
        const uint32_t *c = q->corner + 4 * (size_t)quad;
        for (int m = 0; m < 3; m++) {
            uint32_t n = mesh->neighbour[3 * t + m];
            if (n == MESH_NONE || q->of_triangle[n] == quad)
                continue;
            uint32_t a = mesh->triangle[3 * t + m];
            uint32_t b = mesh->triangle[3 * t + (m + 1) % 3];
            for (int s = 0; s < 4; s++)
                if ((c[s] == a && c[(s + 1) % 4] == b) ||
                    (c[s] == b && c[(s + 1) % 4] == a))
                    side_quad[4 * (size_t)quad + s] = q->of_triangle[n];
        }
    }
    return side_quad;
}

/* The lattice: (i, j) per vertex, by a breadth-first walk over the quads
 * from quad start with its corner k at (0, 0) and the next corners, in
 * the face's winding, at (1, 0), (1, 1), (0, 1). Returns 0, or 1 (why
 * set) when two quads disagree on a vertex. */
static int walk(const struct mesh *mesh, const struct quads *q,
                const uint32_t *side_quad, size_t start, int k, long *ij,
                unsigned char *known, uint32_t *queue, unsigned char *queued,
                char *why, size_t size)
{
    static const long unit[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    const uint32_t *s = q->corner + 4 * start;
    for (int x = 0; x < 4; x++) {
        uint32_t v = s[(k + x) % 4];
        ij[2 * v] = unit[x][0];
        ij[2 * v + 1] = unit[x][1];
        known[v] = 1;
    }
    size_t head = 0, tail = 0;
    queue[tail++] = (uint32_t)start;
    queued[start] = 1;
    while (head < tail) {
        uint32_t quad = queue[head++];
        const uint32_t *c = q->corner + 4 * (size_t)quad;
        for (int side = 0; side < 4; side++) {
            uint32_t next = side_quad[4 * (size_t)quad + side];
            if (next == MESH_NONE)
                continue;
            uint32_t a = c[side], b = c[(side + 1) % 4];
            uint32_t a_back = c[(side + 3) % 4];  /* a's other neighbour */
            /* The next quad's corners beside a and b, away from this one,
             * lie one step further along a_back -> a. */
            const uint32_t *o = q->corner + 4 * (size_t)next;
            int ka = corner_of(o, a), kb = corner_of(o, b);
            if (ka < 0 || kb < 0) {
                snprintf(why, size, "two quads share an edge but not its "
                         "vertices");
                return 1;
            }
            uint32_t far[2] = {
                o[(ka + 1) % 4] == b ? o[(ka + 3) % 4] : o[(ka + 1) % 4],
                o[(kb + 1) % 4] == a ? o[(kb + 3) % 4] : o[(kb + 1) % 4]};
            uint32_t near[2] = {a, b};
            long step[2] = {ij[2 * a] - ij[2 * a_back],
                            ij[2 * a + 1] - ij[2 * a_back + 1]};
            for (int x = 0; x < 2; x++) {
                long want_i = ij[2 * near[x]] + step[0];
                long want_j = ij[2 * near[x] + 1] + step[1];
                uint32_t v = far[x];
                if (known[v] && (ij[2 * v] != want_i ||
                                 ij[2 * v + 1] != want_j)) {
                    snprintf(why, size, "the quads do not close into a "
                             "rectangular grid (at OBJ vertex %u)",
                             mesh->source_vertex[v] + 1);
                    return 1;
                }
                ij[2 * v] = want_i;
                ij[2 * v + 1] = want_j;
                known[v] = 1;
            }
            if (!queued[next]) {
                queued[next] = 1;
                queue[tail++] = next;
            }
        }
    }
    return 0;
}

/* The four rotations that keep the winding, of a lattice a x b cells:
 * rotation r of (i, j). */
static void rotate(int r, long a, long b, long i, long j, long *ri, long *rj)
{
    switch (r) {
    case 0: *ri = i;     *rj = j;     break;
    case 1: *ri = j;     *rj = a - i; break;
    case 2: *ri = a - i; *rj = b - j; break;
    default: *ri = b - j; *rj = i;    break;
    }
}

/* The checks a structured grid passes before the walk, for a message that
 * says what is wrong: a disk, four corners, no vertex in more quads than a
 * grid's. count[v]: the quads of vertex v. */
static int check_valence(const struct mesh *mesh, const uint32_t *count,
                         char *why, size_t size)
{
    if (mesh->ncomponents != 1 || mesh->nloops != 1 ||
        mesh->nonmanifold_edges > 0) {
        snprintf(why, size, "not a disk (%zu pieces, %zu boundary loops)",
                 mesh->ncomponents, mesh->nloops);
        return 1;
    }
    size_t corners = 0, crowded = 0;
    for (size_t v = 0; v < mesh->nvertices; v++) {
        corners += count[v] == 1;
        crowded += count[v] > 4 || (mesh->on_boundary[v] && count[v] > 2);
    }
    if (crowded > 0) {
        snprintf(why, size, "%zu vertices are in more quads than a grid's "
                 "(4 inside, 2 on the boundary)", crowded);
        return 1;
    }
    if (corners != 4) {
        snprintf(why, size, "%zu corners (boundary vertices of one quad), "
                 "not 4", corners);
        return 1;
    }
    return 0;
}

int param_grid(const struct mesh *mesh, double **vertex_uv_out, int *nu,
               int *nv, int *paired, char *why, size_t size)
{
    *vertex_uv_out = NULL;
    *nu = *nv = 0;
    size_t n = mesh->nvertices;
    struct quads q;
    uint32_t *side_quad = NULL, *queue = NULL, *at = NULL, *count = NULL;
    long *ij = NULL;
    unsigned char *known = NULL, *queued = NULL;
    double *vertex_uv = NULL;
    int rc = find_quads(mesh, &q, paired, why, size);
    if (rc != FACET_OK)
        goto done;
    rc = FACET_EWORK;
    count = calloc(n ? n : 1, sizeof *count);
    side_quad = quad_neighbours(mesh, &q);
    queue = malloc(sizeof(uint32_t) * (q.count + 1));
    ij = malloc(sizeof(long) * 2 * (n ? n : 1));
    known = calloc(n ? n : 1, 1);
    queued = calloc(q.count + 1, 1);
    if (!count || !side_quad || !queue || !ij || !known || !queued)
        goto done;
    for (size_t x = 0; x < 4 * q.count; x++)
        count[q.corner[x]]++;
    rc = FACET_EINPUT;
    if (check_valence(mesh, count, why, size))
        goto done;

    /* Start from the first corner in vertex order, in its one quad. */
    size_t start = 0;
    int k = -1;
    for (size_t v = 0; v < n && k < 0; v++) {
        if (count[v] != 1)
            continue;
        start = q.of_triangle[mesh->vertex_triangles[mesh->vertex_start[v]]];
        k = corner_of(q.corner + 4 * start, (uint32_t)v);
    }
    if (k < 0 || walk(mesh, &q, side_quad, start, k, ij, known, queue, queued,
                      why, size))
        goto done;

    long imin = 0, imax = 0, jmin = 0, jmax = 0;
    for (size_t v = 0; v < n; v++) {
        if (!known[v]) {
            snprintf(why, size, "OBJ vertex %u is in no quad",
                     mesh->source_vertex[v] + 1);
            goto done;
        }
        if (ij[2 * v] < imin) imin = ij[2 * v];
        if (ij[2 * v] > imax) imax = ij[2 * v];
        if (ij[2 * v + 1] < jmin) jmin = ij[2 * v + 1];
        if (ij[2 * v + 1] > jmax) jmax = ij[2 * v + 1];
    }
    long a = imax - imin, b = jmax - jmin;
    if ((size_t)((a + 1) * (b + 1)) != n || (size_t)(a * b) != q.count) {
        snprintf(why, size, "the quads do not fill a rectangle (%zu quads "
                 "in a %ld x %ld box)", q.count, a, b);
        goto done;
    }
    rc = FACET_EWORK;
    at = malloc(sizeof(uint32_t) * n);
    if (at == NULL)
        goto done;
    for (size_t x = 0; x < n; x++)
        at[x] = MESH_NONE;
    rc = FACET_EINPUT;
    for (size_t v = 0; v < n; v++) {
        ij[2 * v] -= imin;
        ij[2 * v + 1] -= jmin;
        size_t cell = (size_t)(ij[2 * v + 1] * (a + 1) + ij[2 * v]);
        if (at[cell] != MESH_NONE) {
            snprintf(why, size, "two vertices take one grid place");
            goto done;
        }
        at[cell] = (uint32_t)v;
    }

    /* u along the file's rows: the rotation whose step along u is the
     * smaller one in the file's vertex order, and forward. */
    int best = 0, best_key = 8;
    for (int r = 0; r < 4; r++) {
        long origin = 0, along_u = 0, along_v = 0;
        for (size_t v = 0; v < n; v++) {
            long ri, rj;
            rotate(r, a, b, ij[2 * v], ij[2 * v + 1], &ri, &rj);
            long src = (long)mesh->source_vertex[v];
            if (ri == 0 && rj == 0) origin = src;
            if (ri == 1 && rj == 0) along_u = src;
            if (ri == 0 && rj == 1) along_v = src;
        }
        long du = along_u - origin, dv = along_v - origin;
        int key = 4 * (labs(du) > labs(dv)) + 2 * (du < 0) + (dv < 0);
        if (key < best_key) {
            best_key = key;
            best = r;
        }
    }
    long ra = best % 2 ? b : a, rb = best % 2 ? a : b;
    for (size_t v = 0; v < n; v++) {
        long ri, rj;
        rotate(best, a, b, ij[2 * v], ij[2 * v + 1], &ri, &rj);
        ij[2 * v] = ri;
        ij[2 * v + 1] = rj;
        at[rj * (ra + 1) + ri] = (uint32_t)v;
    }

    /* Scale: the mean edge length along u and along v (m), so that the UV
     * box has the surface's proportions. */
    double along_u = 0, along_v = 0;
    for (long j = 0; j <= rb; j++)
        for (long i = 0; i <= ra; i++) {
            const double *p = mesh->position + 3 * (size_t)at[j * (ra + 1) + i];
            if (i < ra)
                along_u += vec3_distance(
                    p, mesh->position + 3 * (size_t)at[j * (ra + 1) + i + 1]);
            if (j < rb)
                along_v += vec3_distance(
                    p, mesh->position + 3 * (size_t)at[(j + 1) * (ra + 1) + i]);
        }
    double su = along_u / (double)(ra * (rb + 1));
    double sv = along_v / (double)(rb * (ra + 1));
    if (!(su > 0) || !(sv > 0)) {
        snprintf(why, size, "the grid's edges have no length");
        goto done;
    }
    rc = FACET_EWORK;
    vertex_uv = malloc(sizeof(double) * 2 * n);
    if (vertex_uv == NULL)
        goto done;
    for (size_t v = 0; v < n; v++) {
        vertex_uv[2 * v] = (double)ij[2 * v] * su;
        vertex_uv[2 * v + 1] = (double)ij[2 * v + 1] * sv;
    }
    *vertex_uv_out = vertex_uv;
    vertex_uv = NULL;
    *nu = (int)ra;
    *nv = (int)rb;
    rc = FACET_OK;
done:
    quads_free(&q);
    free(count);
    free(side_quad);
    free(queue);
    free(at);
    free(ij);
    free(known);
    free(queued);
    free(vertex_uv);
    return rc;
}
