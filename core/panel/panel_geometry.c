/*
 * panel_geometry.c: keeping the pieces of every panel and tracing its
 * outline. See panel_geometry.h.
 *
 * The pieces come from panels_walk_pieces, so there is one clipping
 * implementation. Two walks: the first counts the pieces of each panel, the
 * second stores them grouped by panel. Then, panel by panel:
 *   1. merge piece vertices whose UV agree to within the tolerance (the
 *      same point cut from two triangles differs by rounding);
 *   2. drop what collapses (pieces of a triangle that only touches a cell
 *      line keep fewer than three distinct vertices);
 *   3. the outline's edges are the piece edges not cancelled by the same
 *      edge the other way round in a neighbouring piece: cell border, mesh
 *      boundary, UV seam. Chained head to tail they form the loops.
 * No tolerance enters step 3: it works on the merged vertex numbers.
 */
#include "core/panel/panel_geometry.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/base/vec3.h"

/* The raw pieces as the walk gives them, grouped by panel. */
struct raw {
    const struct mesh *mesh;
    const int *cell_panel;
    size_t *piece_count;         /* npanels: pieces (first walk) */
    size_t *vertex_count;        /* npanels: piece vertices (first walk) */
    size_t *piece_cursor;        /* npanels: next free piece (second walk) */
    size_t *vertex_cursor;       /* npanels: next free vertex */
    size_t *piece_vertex_start;  /* raw pieces + 1 */
    uint32_t *piece_triangle;    /* raw pieces */
    double *uv;                  /* raw vertices x 2 */
    double *position;            /* raw vertices x 3 */
};

static void count_piece(void *context, size_t cell, uint32_t triangle,
                        const struct panel_piece_vertex *piece, int count)
{
    struct raw *r = context;
    (void)triangle;
    (void)piece;
    int n = r->cell_panel[cell];
    if (n < 0)
        return;
    r->piece_count[n]++;
    r->vertex_count[n] += (size_t)count;
}

static void store_piece(void *context, size_t cell, uint32_t triangle,
                        const struct panel_piece_vertex *piece, int count)
{
    struct raw *r = context;
    int n = r->cell_panel[cell];
    if (n < 0)
        return;
    size_t p = r->piece_cursor[n]++;
    size_t v = r->vertex_cursor[n];
    r->vertex_cursor[n] += (size_t)count;
    r->piece_vertex_start[p] = v;
    r->piece_vertex_start[p + 1] = v + (size_t)count;
    r->piece_triangle[p] = triangle;
    for (int k = 0; k < count; k++) {
        r->uv[2 * (v + k)] = piece[k].u;
        r->uv[2 * (v + k) + 1] = piece[k].v;
        panel_piece_point(r->mesh, triangle, &piece[k],
                          &r->position[3 * (v + k)]);
    }
}

/* Two numbers and a third to break ties, sorted in that order: a raw
 * vertex under its tolerance bucket, for merging (first, second: the
 * bucket's qu, qv; k: the raw vertex), or a directed edge between merged
 * vertices, for tracing outlines (first, second: its start and end; k 0).
 * One sort serves both. */
struct sort_key {
    int64_t first, second;
    size_t k;
};

/* Whether x sorts before y: by first, second, then k (a total order, so
 * every sort gives the same order). */
static inline int key_before(const struct sort_key *x,
                             const struct sort_key *y)
{
    if (x->first != y->first)
        return x->first < y->first;
    if (x->second != y->second)
        return x->second < y->second;
    return x->k < y->k;
}

/* Sorts keys[0..n) by key_before. qsort's call through a pointer per
 * comparison was a fifth of the panels' widths in the paper study (issue
 * 27): a quicksort of its own, median of three, insertion below 16. */
static void sort_keys(struct sort_key *keys, size_t n)
{
    while (n > 16) {
        size_t mid = n / 2;
        struct sort_key t;
        if (key_before(&keys[mid], &keys[0])) {
            t = keys[mid]; keys[mid] = keys[0]; keys[0] = t;
        }
        if (key_before(&keys[n - 1], &keys[mid])) {
            t = keys[mid]; keys[mid] = keys[n - 1]; keys[n - 1] = t;
            if (key_before(&keys[mid], &keys[0])) {
                t = keys[mid]; keys[mid] = keys[0]; keys[0] = t;
            }
        }
        struct sort_key pivot = keys[mid];
        size_t i = 0, j = n - 1;
        for (;;) {
            while (key_before(&keys[i], &pivot))
                i++;
            while (key_before(&pivot, &keys[j]))
                j--;
            if (i >= j)
                break;
            t = keys[i]; keys[i] = keys[j]; keys[j] = t;
            i++;
            j--;
        }
        /* [0, j] <= pivot <= [j + 1, n): the smaller side first, the
         * larger by the loop, so the stack stays O(log n). */
        size_t left = j + 1;
        if (left < n - left) {
            sort_keys(keys, left);
            keys += left;
            n -= left;
        } else {
            sort_keys(keys + left, n - left);
            n = left;
        }
    }
    for (size_t i = 1; i < n; i++) {
        struct sort_key x = keys[i];
        size_t j = i;
        for (; j > 0 && key_before(&x, &keys[j - 1]); j--)
            keys[j] = keys[j - 1];
        keys[j] = x;
    }
}

/* The first key at or after (qu, qv) in keys[0..n), searched forward from
 * *from, which it leaves there: the keys are sorted, so a caller whose
 * (qu, qv) never decreases walks each key once in all, where a binary
 * search a vertex was a third of the merge (issue 27). */
static size_t lower_bound_from(const struct sort_key *keys, size_t n,
                               int64_t qu, int64_t qv, size_t *from)
{
    size_t lo = *from;
    while (lo < n &&
           (keys[lo].first < qu ||
            (keys[lo].first == qu && keys[lo].second < qv)))
        lo++;
    *from = lo;
    return lo;
}

/* How many of edges[0..n) (sorted) are (a, b). */
static size_t edge_count(const struct sort_key *edges, size_t n, int64_t a,
                         int64_t b)
{
    size_t lo = 0, hi = n;
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        if (edges[mid].first < a ||
            (edges[mid].first == a && edges[mid].second < b))
            lo = mid + 1;
        else
            hi = mid;
    }
    size_t count = 0;
    while (lo + count < n && edges[lo + count].first == a &&
           edges[lo + count].second == b)
        count++;
    return count;
}

/* Working memory reused from panel to panel, sized for the largest. */
struct scratch {
    struct sort_key *keys;    /* panel's raw vertices */
    size_t *root;             /* raw vertex -> its cluster's first member
                                 in sorted order */
    size_t *number;           /* cluster root -> merged number */
    size_t *merged;           /* raw vertex -> merged number in the panel */
    size_t *first;            /* merged number -> first raw vertex */
    struct sort_key *edges;   /* panel's piece edges */
    struct sort_key *boundary;  /* edges left uncancelled */
    unsigned char *used;      /* boundary edges already in a loop */
    size_t *bucket;           /* merged number + 1 -> where its edges
                                 start among the panel's edges */
    size_t *same;             /* raw vertex -> the first raw vertex equal
                                 to it, SIZE_MAX if none */
    size_t *slot;             /* hash table of raw vertices by UV, at
                                 least twice their count, a power of 2 */
};

/* The hash table's size for n raw vertices: a power of 2, at least 2n. */
static size_t hash_slots(size_t n)
{
    size_t slots = 16;
    while (slots < 2 * n)
        slots *= 2;
    return slots;
}

/* Merges the raw vertices [v0, v1) of one panel whose UV agree within
 * tolerance and whose positions agree within reach (m): merged[k - v0]
 * becomes a number 0.. in order of first occurrence and first[] the first
 * raw vertex (less v0) of each number; returns how many numbers there are.
 * The UV alone is not enough: where the UV squeezes the surface (a
 * harmonic map far from its outer boundary shrinks a tube's far end by
 * e^(-length/radius)), points a whole facet apart agree in UV to far
 * below a cell's 1e-9, and merging them dropped real triangles from the
 * export while the schedule counted their area. */
static size_t merge_vertices(const struct raw *r, size_t v0, size_t v1,
                             double umin, double vmin, double tolerance,
                             double reach, struct scratch *s)
{
    size_t m = v1 - v0;
    /* A raw vertex equal in UV and position to an earlier one (a mesh
     * vertex cut from each triangle around it: two in three of them in
     * the paper study) joins that one's cluster whatever the order: the
     * earlier is seen first in its bucket and is within any tolerance.
     * So only the first of equal ones is sorted and sought, the others
     * take its cluster after, to the same clusters (issue 27). */
    size_t slots = hash_slots(m);
    memset(s->slot, 0xff, slots * sizeof *s->slot);
    size_t unique = 0;
    for (size_t k = 0; k < m; k++) {
        const double *uv = &r->uv[2 * (v0 + k)];
        const double *p = &r->position[3 * (v0 + k)];
        s->root[k] = SIZE_MAX;
        s->number[k] = SIZE_MAX;
        s->same[k] = SIZE_MAX;
        uint64_t bits[2];
        memcpy(bits, uv, sizeof bits);
        size_t h = (size_t)((bits[0] * UINT64_C(0x9E3779B97F4A7C15) ^
                             bits[1] * UINT64_C(0xC2B2AE3D27D4EB4F)) >> 32) &
                   (slots - 1);
        for (;; h = (h + 1) & (slots - 1)) {
            size_t o = s->slot[h];
            if (o == SIZE_MAX) {
                s->slot[h] = k;
                break;
            }
            const double *ouv = &r->uv[2 * (v0 + o)];
            const double *q = &r->position[3 * (v0 + o)];
            /* Differences, as the merge tests them: no inf merged. */
            if (ouv[0] - uv[0] == 0 && ouv[1] - uv[1] == 0 &&
                q[0] - p[0] == 0 && q[1] - p[1] == 0 && q[2] - p[2] == 0) {
                s->same[k] = o;
                break;
            }
        }
        if (s->same[k] != SIZE_MAX)
            continue;
        s->keys[unique].first = (int64_t)floor((uv[0] - umin) / tolerance);
        s->keys[unique].second = (int64_t)floor((uv[1] - vmin) / tolerance);
        s->keys[unique].k = k;
        unique++;
    }
    m = unique;
    sort_keys(s->keys, m);
    /* Each vertex joins the cluster of a vertex already seen within
     * tolerance in its own or a neighbouring bucket, or starts one. A
     * root's label is itself, so labels never chain. */
    /* Where the bucket rows qu - 1, qu and qu + 1 start from qv - 1:
     * (qu + d, qv - 1) grows with x. */
    size_t from[3] = {0, 0, 0};
    for (size_t x = 0; x < m; x++) {
        size_t k = s->keys[x].k;
        const double *uv = &r->uv[2 * (v0 + k)];
        size_t root = k;
        for (int64_t d = -1; d <= 1 && root == k; d++) {
            size_t y = lower_bound_from(s->keys, m, s->keys[x].first + d,
                                        s->keys[x].second - 1, &from[d + 1]);
            for (; y < m && s->keys[y].first == s->keys[x].first + d &&
                   s->keys[y].second <= s->keys[x].second + 1; y++) {
                size_t other = s->keys[y].k;
                if (s->root[other] == SIZE_MAX)
                    continue;
                const double *o = &r->uv[2 * (v0 + other)];
                const double *p = &r->position[3 * (v0 + k)];
                const double *q = &r->position[3 * (v0 + other)];
                if (fabs(o[0] - uv[0]) <= tolerance &&
                    fabs(o[1] - uv[1]) <= tolerance &&
                    fabs(p[0] - q[0]) <= reach &&
                    fabs(p[1] - q[1]) <= reach &&
                    fabs(p[2] - q[2]) <= reach) {
                    root = s->root[other];
                    break;
                }
            }
        }
        s->root[k] = root;
    }
    m = v1 - v0;
    for (size_t k = 0; k < m; k++)
        if (s->same[k] != SIZE_MAX)
            s->root[k] = s->root[s->same[k]];
    /* Number the clusters in order of first occurrence, so that output
     * vertices follow the pieces. */
    size_t count = 0;
    for (size_t k = 0; k < m; k++) {
        size_t root = s->root[k];
        if (s->number[root] == SIZE_MAX) {
            s->number[root] = count;
            s->first[count++] = k;
        }
        s->merged[k] = s->number[root];
    }
    return count;
}

void panel_geometry_free(struct panel_geometry *g)
{
    free(g->position);
    free(g->uv);
    free(g->panel_vertex);
    free(g->panel_piece);
    free(g->piece_start);
    free(g->corner);
    free(g->piece_triangle);
    free(g->panel_loop);
    free(g->loop_start);
    free(g->outline);
    free(g->outline_plane);
    memset(g, 0, sizeof *g);
}

static void raw_free(struct raw *r)
{
    free(r->piece_count);
    free(r->vertex_count);
    free(r->piece_cursor);
    free(r->vertex_cursor);
    free(r->piece_vertex_start);
    free(r->piece_triangle);
    free(r->uv);
    free(r->position);
}

static void scratch_free(struct scratch *s)
{
    free(s->keys);
    free(s->root);
    free(s->number);
    free(s->merged);
    free(s->first);
    free(s->edges);
    free(s->boundary);
    free(s->used);
    free(s->bucket);
    free(s->same);
    free(s->slot);
}

/* Traces the outline loops of panel n from its kept pieces, appending to
 * g->loop_start, g->outline and g->nloops. */
static void trace_outline(struct panel_geometry *g, size_t n,
                          struct scratch *s)
{
    /* The piece edges sorted by start then end: bucketed by their start
     * (the panel's own vertices, numbered from base), each bucket sorted
     * by its end. A sort of them all and a binary search for every
     * edge's reverse was a quarter of the panels' widths (issue 27);
     * the order is the same, so the loops are. */
    size_t base = g->panel_vertex[n];
    size_t nvertices = g->panel_vertex[n + 1] - base;
    size_t *bucket = s->bucket;
    memset(bucket, 0, (nvertices + 1) * sizeof *bucket);
    size_t nedges = 0;
    for (size_t p = g->panel_piece[n]; p < g->panel_piece[n + 1]; p++)
        for (size_t c = g->piece_start[p]; c < g->piece_start[p + 1]; c++) {
            bucket[g->corner[c] - base + 1]++;
            nedges++;
        }
    for (size_t v = 0; v < nvertices; v++)
        bucket[v + 1] += bucket[v];
    /* bucket[v] is now where vertex v's edges start; s->root serves as
     * the cursor while they are placed. */
    size_t *cursor = s->root;
    memcpy(cursor, bucket, nvertices * sizeof *cursor);
    for (size_t p = g->panel_piece[n]; p < g->panel_piece[n + 1]; p++) {
        size_t c0 = g->piece_start[p], c1 = g->piece_start[p + 1];
        for (size_t c = c0; c < c1; c++) {
            struct sort_key *edge = &s->edges[cursor[g->corner[c] - base]++];
            edge->first = (int64_t)g->corner[c];
            edge->second = (int64_t)g->corner[c + 1 < c1 ? c + 1 : c0];
            edge->k = 0;
        }
    }
    for (size_t v = 0; v < nvertices; v++)
        sort_keys(s->edges + bucket[v], bucket[v + 1] - bucket[v]);
    /* An edge is on the outline as often as it is not matched the other
     * way round by a neighbouring piece. */
    size_t nboundary = 0;
    for (size_t e = 0; e < nedges;) {
        size_t same = 1;
        while (e + same < nedges &&
               s->edges[e + same].first == s->edges[e].first &&
               s->edges[e + same].second == s->edges[e].second)
            same++;
        size_t to = (size_t)s->edges[e].second - base;
        size_t reverse = edge_count(s->edges + bucket[to],
                                    bucket[to + 1] - bucket[to],
                                    s->edges[e].second, s->edges[e].first);
        for (size_t k = reverse; k < same; k++)
            s->boundary[nboundary++] = s->edges[e];
        e += same;
    }
    memset(s->used, 0, nboundary);
    /* Boundary edges are sorted by start: chain each to an unused edge
     * starting where it ends, closing a loop as soon as it returns to its
     * first vertex (at a pinch, the other way out starts another loop). */
    size_t *out = g->outline + g->loop_start[g->nloops];
    for (size_t e0 = 0; e0 < nboundary; e0++) {
        if (s->used[e0])
            continue;
        size_t length = 0, e = e0;
        for (;;) {
            s->used[e] = 1;
            out[length++] = (size_t)s->boundary[e].first;
            int64_t to = s->boundary[e].second;
            if (to == s->boundary[e0].first)
                break;
            size_t lo = 0, hi = nboundary;
            while (lo < hi) {
                size_t mid = lo + (hi - lo) / 2;
                if (s->boundary[mid].first < to)
                    lo = mid + 1;
                else
                    hi = mid;
            }
            while (lo < nboundary && s->boundary[lo].first == to &&
                   s->used[lo])
                lo++;
            if (lo >= nboundary || s->boundary[lo].first != to)
                break;  /* open chain: only a non-manifold mesh does this */
            e = lo;
        }
        if (length < 3)
            continue;  /* a back-and-forth sliver, not a boundary */
        out += length;
        g->loop_start[g->nloops + 1] = g->loop_start[g->nloops] + length;
        g->nloops++;
    }
}

int panel_geometry_build(const struct mesh *mesh,
                         const struct uv_index *index,
                         const struct panelization *panels,
                         struct panel_geometry *out,
                         struct facet_error *err)
{
    return panel_geometry_build_stoppable(mesh, index, panels, NULL, out,
                                          err);
}

/* Panels merged between two questions to the stop: milliseconds. */
#define STOP_EVERY_PANELS 4096

int panel_geometry_is_moved(const struct panelization *panels, size_t n)
{
    const struct panel *p = &panels->panels[n];
    return isfinite(panel_corner_moved(panels, n)) && !p->trimmed &&
           p->ncorners == 4;
}

/* The normal of triangle (a, b, c), not unit, into n. */
static void triangle_normal(const double *a, const double *b,
                            const double *c, double n[3])
{
    double ab[3], ac[3];
    vec3_sub(b, a, ab);
    vec3_sub(c, a, ac);
    vec3_cross(ab, ac, n);
}

/* Appends panel n, moved (panel_geometry_is_moved), as its quad: four
 * vertices at its corners with its cell's corners' UV, two triangles and
 * one loop through them, wound as the surface faces (the side of the
 * panel's normal, which planar_option.h keeps on the patch's side). The
 * quad is cut along the diagonal whose triangles face the same way: a
 * quad the planarization left with a reflex corner (a hypar's, far off
 * its surface) is cut through that corner, so the triangles' areas add up
 * to its own, never overlap. */
static void moved_quad(struct panel_geometry *out,
                       const struct panelization *panels, size_t n)
{
    const struct panel *p = &panels->panels[n];
    static const int step[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    double du = (panels->umax - panels->umin) / panels->nu;
    double dv = (panels->vmax - panels->vmin) / panels->nv;
    double normal[3] = {0, 0, 0};
    for (int c = 0; c < 4; c++) {
        const double *a = p->corner[c], *b = p->corner[(c + 1) % 4];
        normal[0] += (a[1] - b[1]) * (a[2] + b[2]);
        normal[1] += (a[2] - b[2]) * (a[0] + b[0]);
        normal[2] += (a[0] - b[0]) * (a[1] + b[1]);
    }
    int reverse = vec3_dot(normal, p->normal) < 0;
    size_t base = out->nvertices;
    size_t start = out->piece_start[out->npieces];
    size_t point = out->loop_start[out->nloops];
    for (int c = 0; c < 4; c++) {
        int k = reverse ? 3 - c : c;
        memcpy(&out->position[3 * (base + c)], p->corner[k],
               3 * sizeof(double));
        out->uv[2 * (base + c)] = panels->umin + (p->i + step[k][0]) * du;
        out->uv[2 * (base + c) + 1] = panels->vmin + (p->j + step[k][1]) * dv;
        out->outline[point + c] = base + c;
    }
    const double *x = &out->position[3 * base];
    double n0[3], n1[3];
    triangle_normal(x, x + 3, x + 6, n0);
    triangle_normal(x, x + 6, x + 9, n1);
    /* Cut along 0-2, or along 1-3 when 0-2 folds the quad. */
    static const size_t cut[2][6] = {{0, 1, 2, 0, 2, 3}, {1, 2, 3, 1, 3, 0}};
    int other = vec3_dot(n0, n1) < 0;
    for (int t = 0; t < 2; t++) {
        for (int c = 0; c < 3; c++)
            out->corner[start + 3 * t + (size_t)c] =
                base + cut[other][3 * t + c];
        out->piece_triangle[out->npieces] = PANEL_GEOMETRY_NO_TRIANGLE;
        out->npieces++;
        out->piece_start[out->npieces] = start + 3 * (size_t)t + 3;
    }
    out->nvertices += 4;
    out->panel_vertex[n + 1] = out->nvertices;
    out->panel_piece[n + 1] = out->npieces;
    out->nloops++;
    out->loop_start[out->nloops] = point + 4;
    out->panel_loop[n + 1] = out->nloops;
}

int panel_geometry_build_stoppable(const struct mesh *mesh,
                                   const struct uv_index *index,
                                   const struct panelization *panels,
                                   const struct facet_stop *stop,
                                   struct panel_geometry *out,
                                   struct facet_error *err)
{
    memset(out, 0, sizeof *out);
    if (panels->nu < 1 || panels->nv < 1 || panels->umin != index->umin ||
        panels->vmin != index->vmin || panels->umax != index->umax ||
        panels->vmax != index->vmax)
        return facet_error_set(err, FACET_EINPUT,
            "panel geometry: the %dx%d panelization was not built over this "
            "surface's UV", panels->nu, panels->nv);

    size_t np = panels->npanels;
    struct raw r;
    memset(&r, 0, sizeof r);
    r.mesh = mesh;
    r.cell_panel = panels->cell_panel;
    r.piece_count = calloc(np + 1, sizeof *r.piece_count);
    r.vertex_count = calloc(np + 1, sizeof *r.vertex_count);
    r.piece_cursor = calloc(np + 1, sizeof *r.piece_cursor);
    r.vertex_cursor = calloc(np + 1, sizeof *r.vertex_cursor);
    out->npanels = np;
    out->panel_vertex = calloc(np + 1, sizeof *out->panel_vertex);
    out->panel_piece = calloc(np + 1, sizeof *out->panel_piece);
    out->panel_loop = calloc(np + 1, sizeof *out->panel_loop);
    if (!r.piece_count || !r.vertex_count || !r.piece_cursor ||
        !r.vertex_cursor || !out->panel_vertex || !out->panel_piece ||
        !out->panel_loop) {
        raw_free(&r);
        return facet_error_set(err, FACET_EWORK,
                               "out of memory (panel geometry)");
    }
    panels_walk_pieces(mesh, index, panels->nu, panels->nv, count_piece, &r);
    if (facet_stop_requested(stop)) {
        raw_free(&r);
        return facet_stop_error(err);
    }

    /* A moved quad takes 4 vertices, 2 pieces and a loop of its own,
     * whatever its patch had. */
    size_t moved = 0;
    for (size_t n = 0; n < np; n++)
        moved += panel_geometry_is_moved(panels, n);
    size_t raw_pieces = 0, raw_vertices = 0, largest = 0;
    for (size_t n = 0; n < np; n++) {
        r.piece_cursor[n] = raw_pieces;
        r.vertex_cursor[n] = raw_vertices;
        raw_pieces += r.piece_count[n];
        raw_vertices += r.vertex_count[n];
        if (r.vertex_count[n] > largest)
            largest = r.vertex_count[n];
    }
    r.piece_vertex_start = calloc(raw_pieces + 1,
                                  sizeof *r.piece_vertex_start);
    r.piece_triangle = malloc((raw_pieces + 1) * sizeof *r.piece_triangle);
    r.uv = malloc((raw_vertices + 1) * 2 * sizeof *r.uv);
    r.position = malloc((raw_vertices + 1) * 3 * sizeof *r.position);
    /* Every output array is at most its raw size (merging only shrinks)
     * and a moved quad's. */
    size_t most_vertices = raw_vertices + 4 * moved;
    size_t most_pieces = raw_pieces + 2 * moved;
    out->position = malloc((most_vertices + 1) * 3 * sizeof *out->position);
    out->uv = malloc((most_vertices + 1) * 2 * sizeof *out->uv);
    out->piece_start = calloc(most_pieces + 1, sizeof *out->piece_start);
    out->corner = malloc((raw_vertices + 6 * moved + 1) *
                         sizeof *out->corner);
    out->piece_triangle = malloc((most_pieces + 1) *
                                 sizeof *out->piece_triangle);
    out->loop_start = calloc(most_vertices + 1, sizeof *out->loop_start);
    out->outline = malloc((most_vertices + 1) * sizeof *out->outline);
    struct scratch s = {
        malloc((largest + 1) * sizeof *s.keys),
        malloc((largest + 1) * sizeof *s.root),
        malloc((largest + 1) * sizeof *s.number),
        malloc((largest + 1) * sizeof *s.merged),
        malloc((largest + 1) * sizeof *s.first),
        malloc((largest + 1) * sizeof *s.edges),
        malloc((largest + 1) * sizeof *s.boundary),
        malloc(largest + 1),
        malloc((largest + 2) * sizeof *s.bucket),
        malloc((largest + 1) * sizeof *s.same),
        malloc(hash_slots(largest) * sizeof *s.slot),
    };
    if (!r.piece_vertex_start || !r.piece_triangle || !r.uv ||
        !r.position || !out->position || !out->uv || !out->piece_start ||
        !out->corner || !out->piece_triangle || !out->loop_start ||
        !out->outline || !s.keys || !s.root || !s.number || !s.merged ||
        !s.first || !s.edges || !s.boundary || !s.used || !s.bucket ||
        !s.same || !s.slot) {
        raw_free(&r);
        scratch_free(&s);
        return facet_error_set(err, FACET_EWORK,
                               "out of memory (panel geometry)");
    }
    panels_walk_pieces(mesh, index, panels->nu, panels->nv, store_piece, &r);

    /* The tolerance: far above rounding in the UV's own magnitude, far
     * below any feature a cell can hold. */
    double du = (panels->umax - panels->umin) / panels->nu;
    double dv = (panels->vmax - panels->vmin) / panels->nv;
    double magnitude = fmax(fmax(fabs(panels->umin), fabs(panels->umax)),
                            fmax(fabs(panels->vmin), fabs(panels->vmax)));
    double tolerance = fmax(1e-9 * fmax(du, dv),
                            64 * DBL_EPSILON * magnitude);

    /* Raw pieces and their vertices lie panel after panel, so
     * piece_vertex_start is a prefix array over all of them. */
    size_t p0 = 0;
    for (size_t n = 0; n < np; n++) {
        if (n % STOP_EVERY_PANELS == 0 && facet_stop_requested(stop)) {
            raw_free(&r);
            scratch_free(&s);
            return facet_stop_error(err);
        }
        size_t p1 = p0 + r.piece_count[n];
        if (panel_geometry_is_moved(panels, n)) {
            moved_quad(out, panels, n);
            p0 = p1;
            continue;
        }
        size_t v0 = r.piece_vertex_start[p0];
        size_t v1 = r.piece_vertex_start[p1];
        size_t base = out->nvertices;
        /* The same point cut from two triangles differs in position by
         * rounding in the coordinates' magnitude; 1e-9 of the panel's
         * diameter is far above that and far below a facet. */
        double magnitude3 = 0;
        for (size_t k = v0; k < v1; k++)
            for (int c = 0; c < 3; c++)
                magnitude3 = fmax(magnitude3, fabs(r.position[3 * k + c]));
        double reach = fmax(1e-9 * panels->panels[n].diameter,
                            64 * DBL_EPSILON * magnitude3);
        size_t count = merge_vertices(&r, v0, v1, panels->umin, panels->vmin,
                                      tolerance, reach, &s);
        for (size_t k = 0; k < count; k++) {
            memcpy(&out->position[3 * (base + k)],
                   &r.position[3 * (v0 + s.first[k])], 3 * sizeof(double));
            memcpy(&out->uv[2 * (base + k)], &r.uv[2 * (v0 + s.first[k])],
                   2 * sizeof(double));
        }
        out->nvertices += count;
        out->panel_vertex[n + 1] = out->nvertices;

        for (size_t p = p0; p < p1; p++) {
            /* The piece's corners, merged, without repeats. */
            size_t start = out->piece_start[out->npieces], length = 0;
            for (size_t c = r.piece_vertex_start[p];
                 c < r.piece_vertex_start[p + 1]; c++) {
                size_t id = base + s.merged[c - v0];
                if (length == 0 || out->corner[start + length - 1] != id)
                    out->corner[start + length++] = id;
            }
            while (length > 1 &&
                   out->corner[start + length - 1] == out->corner[start])
                length--;
            if (length < 3)
                continue;  /* collapsed: it only touched a cell line */
            out->piece_triangle[out->npieces] = r.piece_triangle[p];
            out->npieces++;
            out->piece_start[out->npieces] = start + length;
        }
        out->panel_piece[n + 1] = out->npieces;

        trace_outline(out, n, &s);
        out->panel_loop[n + 1] = out->nloops;
        p0 = p1;
    }
    raw_free(&r);
    scratch_free(&s);

    size_t npoints = out->loop_start[out->nloops];
    out->outline_plane = malloc((npoints + 1) * 3 *
                                sizeof *out->outline_plane);
    if (out->outline_plane == NULL)
        return facet_error_set(err, FACET_EWORK,
                               "out of memory (panel geometry)");
    for (size_t n = 0; n < np; n++)
        for (size_t k = out->loop_start[out->panel_loop[n]];
             k < out->loop_start[out->panel_loop[n + 1]]; k++)
            panel_geometry_project(&panels->panels[n],
                                   &out->position[3 * out->outline[k]],
                                   &out->outline_plane[3 * k]);
    return FACET_OK;
}

void panel_geometry_project(const struct panel *panel, const double x[3],
                            double out[3])
{
    double d[3];
    vec3_sub(x, panel->centroid, d);
    double along = vec3_dot(d, panel->normal);
    for (int c = 0; c < 3; c++)
        out[c] = x[c] - along * panel->normal[c];
}

double panel_geometry_piece_area(const struct panel_geometry *g, size_t p)
{
    size_t c0 = g->piece_start[p], c1 = g->piece_start[p + 1];
    const double *a = &g->position[3 * g->corner[c0]];
    double area = 0;
    for (size_t c = c0 + 1; c + 1 < c1; c++) {
        double ab[3], ac[3], n[3];
        vec3_sub(&g->position[3 * g->corner[c]], a, ab);
        vec3_sub(&g->position[3 * g->corner[c + 1]], a, ac);
        vec3_cross(ab, ac, n);
        area += 0.5 * vec3_length(n);
    }
    return area;
}

double panel_geometry_loop_area(const struct panel_geometry *g, size_t l,
                                const double normal[3])
{
    size_t k0 = g->loop_start[l], k1 = g->loop_start[l + 1];
    if (k1 - k0 < 3)
        return 0;
    /* Newell's sum about the first point, dotted with the normal. */
    const double *o = &g->outline_plane[3 * k0];
    double sum[3] = {0, 0, 0};
    for (size_t k = k0 + 1; k + 1 < k1; k++) {
        double a[3], b[3], n[3];
        vec3_sub(&g->outline_plane[3 * k], o, a);
        vec3_sub(&g->outline_plane[3 * (k + 1)], o, b);
        vec3_cross(a, b, n);
        for (int c = 0; c < 3; c++)
            sum[c] += n[c];
    }
    return 0.5 * vec3_dot(sum, normal);
}
