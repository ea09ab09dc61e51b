/*
 * triangulate.c: ear clipping of one polygon in its Newell plane, with a fan
 * as the fallback. See triangulate.h.
 *
 * The polygon is projected onto the coordinate plane most nearly parallel
 * to it (dropping the axis where the Newell normal is largest) and mirrored
 * if need be so that it runs counter-clockwise there. Ear clipping then
 * walks the ring of remaining corners: a corner is an ear when it turns
 * left and no other remaining corner lies in (or on) the triangle it would
 * cut off. When a full lap finds no ear, a corner with exactly zero turn is
 * cut off (a zero-area triangle, harmless); when there is none, the rest is
 * fanned.
 */
#include "core/obj/triangulate.h"

#include <assert.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/base/vec3.h"

void triangulate_scratch_free(struct triangulate_scratch *scratch)
{
    free(scratch->plane);
    free(scratch->prev);
    free(scratch->next);
    memset(scratch, 0, sizeof *scratch);
}

static int scratch_reserve(struct triangulate_scratch *scratch, size_t n,
                           struct facet_error *err)
{
    if (n <= scratch->capacity)
        return FACET_OK;
    size_t capacity = scratch->capacity ? scratch->capacity : 64;
    while (capacity < n)
        capacity *= 2;
    double *plane = realloc(scratch->plane, capacity * 2 * sizeof *plane);
    if (plane != NULL)
        scratch->plane = plane;
    uint32_t *prev = realloc(scratch->prev, capacity * sizeof *prev);
    if (prev != NULL)
        scratch->prev = prev;
    uint32_t *next = realloc(scratch->next, capacity * sizeof *next);
    if (next != NULL)
        scratch->next = next;
    if (plane == NULL || prev == NULL || next == NULL)
        return facet_error_set(err, FACET_EWORK,
            "out of memory triangulating a polygon of %zu corners", n);
    scratch->capacity = capacity;
    return FACET_OK;
}

/* Newell normal of the polygon: twice its vector area. */
static void newell_normal(const double *point, size_t n, double normal[3])
{
    normal[0] = normal[1] = normal[2] = 0;
    for (size_t i = 0; i < n; i++) {
        const double *a = point + 3 * i;
        const double *b = point + 3 * (i + 1 == n ? 0 : i + 1);
        normal[0] += (a[1] - b[1]) * (a[2] + b[2]);
        normal[1] += (a[2] - b[2]) * (a[0] + b[0]);
        normal[2] += (a[0] - b[0]) * (a[1] + b[1]);
    }
}

/* The two coordinates to keep so that the projection of a polygon with this
 * normal is as large as possible and counter-clockwise. */
static void projection_axes(const double normal[3], int *first, int *second)
{
    double ax = fabs(normal[0]), ay = fabs(normal[1]), az = fabs(normal[2]);
    int drop = (ax > ay && ax > az) ? 0 : (ay > az ? 1 : 2);
    *first = (drop + 1) % 3;
    *second = (drop + 2) % 3;
    if (normal[drop] < 0) {
        int swap = *first;
        *first = *second;
        *second = swap;
    }
}

/* Twice the signed area of the 2D triangle a, b, c (positive when it turns
 * left). */
static double turn(const double *a, const double *b, const double *c)
{
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

static void put_triangle(uint32_t *triangle, size_t *count, uint32_t a,
                         uint32_t b, uint32_t c)
{
    uint32_t *t = triangle + 3 * (*count)++;
    t[0] = a;
    t[1] = b;
    t[2] = c;
}

static void fan(uint32_t *triangle, size_t n)
{
    size_t count = 0;
    for (size_t k = 1; k + 1 < n; k++)
        put_triangle(triangle, &count, 0, (uint32_t)k, (uint32_t)(k + 1));
}

void triangulate_quad(const double *a, const double *b, const double *c,
                      const double *d, uint32_t *triangle)
{
    const double *corner[4] = {a, b, c, d};
    double edge[4][3], normal[3], diagonal_ac[3], diagonal_bd[3];
    for (int i = 0; i < 4; i++)
        for (int k = 0; k < 3; k++)
            edge[i][k] = corner[(i + 1) % 4][k] - corner[i][k];
    for (int k = 0; k < 3; k++) {
        diagonal_ac[k] = c[k] - a[k];
        diagonal_bd[k] = d[k] - b[k];
    }
    vec3_cross(diagonal_ac, diagonal_bd, normal);  /* the quad's Newell normal */
    int reflex = 0, nreflex = 0;
    for (int i = 0; i < 4; i++) {
        double turn3[3];
        vec3_cross(edge[(i + 3) % 4], edge[i], turn3);
        if (!(turn3[0] * normal[0] + turn3[1] * normal[1] +
              turn3[2] * normal[2] > 0)) {
            reflex = i;
            nreflex++;
        }
    }
    uint32_t k = nreflex == 1 ? (uint32_t)reflex : 0;
    size_t count = 0;
    put_triangle(triangle, &count, k, (k + 1) % 4, (k + 2) % 4);
    put_triangle(triangle, &count, k, (k + 2) % 4, (k + 3) % 4);
}

/* Whether q lies inside or on the 2D triangle a, b, c (counter-clockwise). */
static int inside_or_on(const double *q, const double *a, const double *b,
                        const double *c)
{
    return turn(a, b, q) >= 0 && turn(b, c, q) >= 0 && turn(c, a, q) >= 0;
}

static int same_point(const double *a, const double *b)
{
    return a[0] == b[0] && a[1] == b[1];
}

/* Whether corner i of the ring is an ear: it turns left and no other corner
 * of the ring (other than copies of the ear's own corners) lies in or on the
 * triangle it would cut off. */
static int is_ear(const struct triangulate_scratch *s, uint32_t i)
{
    uint32_t p = s->prev[i], q = s->next[i];
    const double *a = s->plane + 2 * p, *b = s->plane + 2 * i,
                 *c = s->plane + 2 * q;
    if (!(turn(a, b, c) > 0))
        return 0;
    for (uint32_t r = s->next[q]; r != p; r = s->next[r]) {
        const double *x = s->plane + 2 * r;
        if (same_point(x, a) || same_point(x, b) || same_point(x, c))
            continue;
        if (inside_or_on(x, a, b, c))
            return 0;
    }
    return 1;
}

int triangulate_polygon(const double *point, size_t n, uint32_t *triangle,
                        struct triangulate_scratch *scratch,
                        struct facet_error *err)
{
    assert(n >= 3 && n < UINT32_MAX);
    if (n == 3) {
        triangle[0] = 0;
        triangle[1] = 1;
        triangle[2] = 2;
        return FACET_OK;
    }
    if (n == 4) {
        triangulate_quad(point, point + 3, point + 6, point + 9, triangle);
        return FACET_OK;
    }
    if (n > TRIANGULATE_MAX_EAR_CORNERS) {
        fan(triangle, n);
        return FACET_OK;
    }

    double normal[3];
    int first, second;
    newell_normal(point, n, normal);
    if (normal[0] == 0 && normal[1] == 0 && normal[2] == 0) {
        fan(triangle, n);  /* no plane at all */
        return FACET_OK;
    }
    projection_axes(normal, &first, &second);

    int rc = scratch_reserve(scratch, n, err);
    if (rc != FACET_OK)
        return rc;
    struct triangulate_scratch *s = scratch;
    for (size_t i = 0; i < n; i++) {
        s->plane[2 * i] = point[3 * i + first];
        s->plane[2 * i + 1] = point[3 * i + second];
        s->prev[i] = (uint32_t)(i == 0 ? n - 1 : i - 1);
        s->next[i] = (uint32_t)(i + 1 == n ? 0 : i + 1);
    }

    /* A convex polygon is a fan; that is the common case, and quick. */
    size_t nreflex = 0;
    for (size_t i = 0; i < n; i++)
        if (!(turn(s->plane + 2 * s->prev[i], s->plane + 2 * i,
                   s->plane + 2 * s->next[i]) > 0))
            nreflex++;
    if (nreflex == 0) {
        fan(triangle, n);
        return FACET_OK;
    }

    size_t count = 0, remaining = n, failures = 0;
    uint32_t i = 0;
    while (remaining > 3) {
        int cut = is_ear(s, i);
        if (!cut && failures >= remaining) {
            /* A full lap without an ear: look for a corner with no turn. */
            uint32_t j = i;
            do {
                if (turn(s->plane + 2 * s->prev[j], s->plane + 2 * j,
                         s->plane + 2 * s->next[j]) == 0) {
                    cut = 1;
                    i = j;
                    break;
                }
                j = s->next[j];
            } while (j != i);
            if (!cut)
                break;
        }
        if (cut) {
            uint32_t p = s->prev[i], q = s->next[i];
            put_triangle(triangle, &count, p, i, q);
            s->next[p] = q;
            s->prev[q] = p;
            remaining--;
            failures = 0;
            i = q;
        } else {
            failures++;
            i = s->next[i];
        }
    }

    /* Three corners left, or ear clipping is stuck: fan what is left. */
    uint32_t hub = i;
    for (uint32_t j = s->next[hub]; s->next[j] != hub; j = s->next[j])
        put_triangle(triangle, &count, hub, j, s->next[j]);
    return FACET_OK;
}
