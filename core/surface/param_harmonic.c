/*
 * param_harmonic.c: the mean-value map of a disk with capped holes. See
 * param_harmonic.h.
 */
#include "core/surface/param_harmonic.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/base/vec3.h"

#define PI 3.14159265358979323846

/* The surface the solve runs on: the mesh, and a fan of triangles over
 * every hole around one extra vertex. */
struct capped {
    size_t nvertices;
    double *position;          /* #V x 3 */
    size_t ntriangles;
    uint32_t *triangle;        /* #T x 3 */
    const uint32_t *outer;     /* the outer loop's vertices, in order */
    size_t nouter;
};

static void capped_free(struct capped *c)
{
    free(c->position);
    free(c->triangle);
}

static double loop_length(const double *position, const uint32_t *loop,
                          size_t count)
{
    double length = 0;
    for (size_t k = 0; k < count; k++)
        length += vec3_distance(position + 3 * (size_t)loop[k],
                                position + 3 * (size_t)loop[(k + 1) % count]);
    return length;
}

/* Copies mesh into *c and caps every loop but the longest. */
static int cap_holes(const struct mesh *mesh, struct capped *c)
{
    memset(c, 0, sizeof *c);
    size_t outer = 0;
    double longest = -1;
    for (size_t l = 0; l < mesh->nloops; l++) {
        double length = loop_length(mesh->position,
                                    mesh->loop_vertices + mesh->loop_start[l],
                                    mesh->loop_start[l + 1] -
                                        mesh->loop_start[l]);
        if (length > longest) {
            longest = length;
            outer = l;
        }
    }
    size_t holes = mesh->nloops - 1;
    size_t hole_edges = (mesh->loop_start[mesh->nloops] - mesh->loop_start[0]) -
                        (mesh->loop_start[outer + 1] - mesh->loop_start[outer]);
    c->nvertices = mesh->nvertices + holes;
    c->ntriangles = mesh->ntriangles + hole_edges;
    c->position = malloc(sizeof(double) * 3 * (c->nvertices ? c->nvertices : 1));
    c->triangle = malloc(sizeof(uint32_t) * 3 * (c->ntriangles ? c->ntriangles : 1));
    if (c->position == NULL || c->triangle == NULL)
        return FACET_EWORK;
    memcpy(c->position, mesh->position, sizeof(double) * 3 * mesh->nvertices);
    memcpy(c->triangle, mesh->triangle,
           sizeof(uint32_t) * 3 * mesh->ntriangles);
    size_t vertex = mesh->nvertices, triangle = mesh->ntriangles;
    for (size_t l = 0; l < mesh->nloops; l++) {
        const uint32_t *loop = mesh->loop_vertices + mesh->loop_start[l];
        size_t count = mesh->loop_start[l + 1] - mesh->loop_start[l];
        if (l == outer) {
            c->outer = loop;
            c->nouter = count;
            continue;
        }
        double *centre = c->position + 3 * vertex;
        centre[0] = centre[1] = centre[2] = 0;
        for (size_t k = 0; k < count; k++)
            for (int x = 0; x < 3; x++)
                centre[x] += mesh->position[3 * (size_t)loop[k] + x] /
                             (double)count;
        /* The cap's winding does not matter: the weights take angles
         * unsigned, and the caps are dropped after the solve. */
        for (size_t k = 0; k < count; k++) {
            uint32_t *t = c->triangle + 3 * triangle++;
            t[0] = loop[(k + 1) % count];
            t[1] = loop[k];
            t[2] = (uint32_t)vertex;
        }
        vertex++;
    }
    return FACET_OK;
}

static double edge_length(const struct capped *c, uint32_t a, uint32_t b)
{
    return vec3_distance(c->position + 3 * (size_t)a,
                         c->position + 3 * (size_t)b);
}

/* The angle of triangle t at its corner k (radians), kept off 0 and pi so
 * that a flat corner of a cap (its centre in line with a hole's edge)
 * still has a finite weight. */
static double corner_angle(const struct capped *c, size_t t, int k)
{
    const uint32_t *tri = c->triangle + 3 * t;
    const double *a = c->position + 3 * (size_t)tri[k];
    const double *b = c->position + 3 * (size_t)tri[(k + 1) % 3];
    const double *p = c->position + 3 * (size_t)tri[(k + 2) % 3];
    double ab[3], ap[3], n[3];
    vec3_sub(b, a, ab);
    vec3_sub(p, a, ap);
    vec3_cross(ab, ap, n);
    double angle = atan2(vec3_length(n), vec3_dot(ab, ap));
    return fmin(angle, PI - 1e-6);
}

/* Places the outer loop on a rectangle when it has four clear corners
 * (vertices where the surface's angle is under 135 degrees), keeping the
 * sides' lengths, and on a circle by arc length otherwise. */
static void place_boundary(const struct capped *c, const double *angle_sum,
                           double *vertex_uv)
{
    const uint32_t *loop = c->outer;
    size_t count = c->nouter;
    double perimeter = loop_length(c->position, loop, count);

    /* The four sharpest boundary vertices, in loop order. */
    size_t corner[4];
    int ncorners = 0;
    for (int n = 0; n < 4; n++) {
        size_t best = count;
        for (size_t k = 0; k < count; k++) {
            int taken = 0;
            for (int x = 0; x < ncorners; x++)
                taken |= corner[x] == k;
            if (!taken && (best == count ||
                           angle_sum[loop[k]] < angle_sum[loop[best]]))
                best = k;
        }
        if (best == count || angle_sum[loop[best]] > 0.75 * PI)
            break;
        corner[ncorners++] = best;
    }

    if (ncorners == 4 && count >= 4) {
        for (int x = 0; x < 4; x++)
            for (int y = x + 1; y < 4; y++)
                if (corner[y] < corner[x]) {
                    size_t swap = corner[x];
                    corner[x] = corner[y];
                    corner[y] = swap;
                }
        double side[4] = {0, 0, 0, 0};
        for (int s = 0; s < 4; s++)
            for (size_t k = corner[s]; k != corner[(s + 1) % 4];
                 k = (k + 1) % count)
                side[s] += edge_length(c, loop[k], loop[(k + 1) % count]);
        double width = (side[0] + side[2]) / 2;
        double height = (side[1] + side[3]) / 2;
        static const double start[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
        for (int s = 0; s < 4; s++) {
            double along = 0;
            const double *from = start[s], *to = start[(s + 1) % 4];
            for (size_t k = corner[s]; k != corner[(s + 1) % 4];
                 k = (k + 1) % count) {
                double f = side[s] > 0 ? along / side[s] : 0;
                vertex_uv[2 * loop[k]] = width * (from[0] + f * (to[0] - from[0]));
                vertex_uv[2 * loop[k] + 1] =
                    height * (from[1] + f * (to[1] - from[1]));
                along += edge_length(c, loop[k], loop[(k + 1) % count]);
            }
        }
        return;
    }
    double along = 0, radius = perimeter / (2 * PI);
    for (size_t k = 0; k < count; k++) {
        double a = perimeter > 0 ? 2 * PI * along / perimeter : 0;
        vertex_uv[2 * loop[k]] = radius * cos(a);
        vertex_uv[2 * loop[k] + 1] = radius * sin(a);
        along += edge_length(c, loop[k], loop[(k + 1) % count]);
    }
}

/* The mean-value system, in compressed rows: row i holds w_ij for every
 * neighbour j. */
struct mean_value_system {
    size_t n;
    uint32_t *row_start;   /* n + 1 */
    uint32_t *column;      /* neighbour vertex */
    double *weight;        /* w_ij > 0 */
    double *diagonal;      /* sum of the row's weights */
};

static void system_free(struct mean_value_system *s)
{
    free(s->row_start);
    free(s->column);
    free(s->weight);
    free(s->diagonal);
}

struct weight_entry {
    uint32_t row, column;
    double weight;
};

static int compare_entries(const void *a, const void *b)
{
    const struct weight_entry *x = a, *y = b;
    if (x->row != y->row)
        return x->row < y->row ? -1 : 1;
    return x->column < y->column ? -1 : x->column > y->column;
}

/* Floater's weights w_ij = (tan(a/2) + tan(b/2)) / |x_i - x_j|, a and b the
 * angles at i of the two triangles beside edge ij: one entry per triangle
 * corner and side, sorted and summed per (i, j). */
static int build_system(const struct capped *c, struct mean_value_system *s)
{
    size_t n = c->nvertices, nentries = 6 * c->ntriangles;
    memset(s, 0, sizeof *s);
    s->n = n;
    struct weight_entry *entry = malloc((nentries ? nentries : 1) *
                                        sizeof *entry);
    s->row_start = calloc(n + 1, sizeof *s->row_start);
    s->diagonal = calloc(n ? n : 1, sizeof *s->diagonal);
    s->column = malloc((nentries ? nentries : 1) * sizeof *s->column);
    s->weight = malloc((nentries ? nentries : 1) * sizeof *s->weight);
    if (!entry || !s->row_start || !s->diagonal || !s->column || !s->weight) {
        free(entry);
        return FACET_EWORK;
    }
    size_t used = 0;
    for (size_t t = 0; t < c->ntriangles; t++)
        for (int k = 0; k < 3; k++) {
            uint32_t i = c->triangle[3 * t + k];
            double half = tan(corner_angle(c, t, k) / 2);
            for (int side = 1; side <= 2; side++) {
                uint32_t j = c->triangle[3 * t + (k + side) % 3];
                double length = edge_length(c, i, j);
                entry[used++] = (struct weight_entry){
                    i, j, length > 0 ? half / length : 0};
            }
        }
    qsort(entry, used, sizeof *entry, compare_entries);
    size_t out = 0;
    for (size_t e = 0; e < used; e++) {
        if (out > 0 && entry[e].row == entry[out - 1].row &&
            entry[e].column == entry[out - 1].column) {
            entry[out - 1].weight += entry[e].weight;
            continue;
        }
        entry[out++] = entry[e];
    }
    for (size_t e = 0; e < out; e++) {
        s->row_start[entry[e].row + 1]++;
        s->column[e] = entry[e].column;
        s->weight[e] = entry[e].weight;
        s->diagonal[entry[e].row] += entry[e].weight;
    }
    for (size_t v = 0; v < n; v++)
        s->row_start[v + 1] += s->row_start[v];
    free(entry);
    return FACET_OK;
}

/* y = A x: (A x)_i = d_i x_i - sum over free neighbours w_ij x_j; the rows
 * of fixed (boundary) vertices are the identity. */
static void apply(const struct mean_value_system *s,
                  const unsigned char *fixed, const double *x, double *y)
{
    for (size_t i = 0; i < s->n; i++) {
        if (fixed[i]) {
            y[i] = x[i];
            continue;
        }
        double sum = s->diagonal[i] * x[i];
        for (uint32_t e = s->row_start[i]; e < s->row_start[i + 1]; e++)
            if (!fixed[s->column[e]])
                sum -= s->weight[e] * x[s->column[e]];
        y[i] = sum;
    }
}

static double dot_n(const double *a, const double *b, size_t n)
{
    double sum = 0;
    for (size_t i = 0; i < n; i++)
        sum += a[i] * b[i];
    return sum;
}

/* Solves A x = b by BiCGSTAB with a Jacobi preconditioner (the mean-value
 * matrix is not symmetric). x holds the initial guess. Returns 0 when it
 * converged to a relative residual under 1e-10, 1 when it did not, -1
 * when out of memory, 2 when stop fired (asked every iteration: a few
 * matrix products, milliseconds even on millions of vertices, where the
 * whole solve can take minutes). */
static int solve(const struct mean_value_system *s, const unsigned char *fixed,
                 const double *b, double *x, const struct facet_stop *stop)
{
    size_t n = s->n;
    double *work = malloc(sizeof(double) * 8 * (n ? n : 1));
    if (work == NULL)
        return -1;
    double *r = work, *r0 = r + n, *p = r0 + n, *v = p + n, *sv = v + n;
    double *ph = sv + n, *shat = ph + n, *t = shat + n;
    apply(s, fixed, x, r);
    for (size_t i = 0; i < n; i++)
        r[i] = b[i] - r[i];
    memcpy(r0, r, sizeof(double) * n);
    memset(p, 0, sizeof(double) * n);
    memset(v, 0, sizeof(double) * n);
    double rho = 1, alpha = 1, omega = 1;
    double norm_b = sqrt(dot_n(b, b, n));
    if (norm_b == 0)
        norm_b = 1;
    int status = 1;
    for (int iteration = 0; iteration < 20000; iteration++) {
        if (facet_stop_requested(stop)) {
            status = 2;
            break;
        }
        if (sqrt(dot_n(r, r, n)) <= 1e-10 * norm_b) {
            status = 0;
            break;
        }
        double rho_next = dot_n(r0, r, n);
        if (rho_next == 0)
            break;
        double beta = (rho_next / rho) * (alpha / omega);
        rho = rho_next;
        for (size_t i = 0; i < n; i++)
            p[i] = r[i] + beta * (p[i] - omega * v[i]);
        for (size_t i = 0; i < n; i++)
            ph[i] = fixed[i] || s->diagonal[i] == 0 ? p[i]
                                                    : p[i] / s->diagonal[i];
        apply(s, fixed, ph, v);
        double r0v = dot_n(r0, v, n);
        if (r0v == 0)
            break;
        alpha = rho / r0v;
        for (size_t i = 0; i < n; i++)
            sv[i] = r[i] - alpha * v[i];
        for (size_t i = 0; i < n; i++)
            shat[i] = fixed[i] || s->diagonal[i] == 0 ? sv[i]
                                                      : sv[i] / s->diagonal[i];
        apply(s, fixed, shat, t);
        double tt = dot_n(t, t, n);
        omega = tt > 0 ? dot_n(t, sv, n) / tt : 0;
        for (size_t i = 0; i < n; i++) {
            x[i] += alpha * ph[i] + omega * shat[i];
            r[i] = sv[i] - omega * t[i];
        }
        if (omega == 0) {
            status = sqrt(dot_n(r, r, n)) <= 1e-10 * norm_b ? 0 : 1;
            break;
        }
    }
    free(work);
    return status;
}

/* Whether mesh is a disk with holes: one piece, manifold, with a boundary,
 * and Euler characteristic 2 - loops (no handle). */
static int is_holed_disk(const struct mesh *mesh, char *why, size_t size)
{
    if (mesh->ncomponents != 1 || mesh->nloops == 0 ||
        mesh->nonmanifold_edges > 0) {
        snprintf(why, size, "not a disk (%zu pieces, %zu boundary loops%s)",
                 mesh->ncomponents, mesh->nloops,
                 mesh->nonmanifold_edges > 0 ? ", non-manifold edges" : "");
        return 0;
    }
    size_t boundary_edges = mesh->loop_start[mesh->nloops];
    size_t edges = (3 * mesh->ntriangles + boundary_edges) / 2;
    long euler = (long)mesh->nvertices - (long)edges + (long)mesh->ntriangles;
    if (euler != 2 - (long)mesh->nloops) {
        snprintf(why, size, "not a disk with holes (Euler characteristic "
                 "%ld with %zu boundary loops: it has handles)", euler,
                 mesh->nloops);
        return 0;
    }
    return 1;
}

int param_harmonic(const struct mesh *mesh, const struct facet_stop *stop,
                   double **vertex_uv_out, size_t *holes, char *why,
                   size_t size)
{
    *vertex_uv_out = NULL;
    *holes = 0;
    if (!is_holed_disk(mesh, why, size))
        return FACET_EINPUT;
    struct capped c;
    struct mean_value_system system;
    memset(&system, 0, sizeof system);
    double *vertex_uv = NULL, *angle_sum = NULL, *b = NULL, *x = NULL;
    unsigned char *fixed = NULL;
    int rc = cap_holes(mesh, &c);
    if (rc != FACET_OK)
        goto done;
    rc = FACET_EWORK;
    size_t n = c.nvertices;
    vertex_uv = calloc(2 * (n ? n : 1), sizeof(double));
    angle_sum = calloc(n ? n : 1, sizeof(double));
    b = malloc(sizeof(double) * (n ? n : 1));
    x = malloc(sizeof(double) * (n ? n : 1));
    fixed = calloc(n ? n : 1, 1);
    if (!vertex_uv || !angle_sum || !b || !x || !fixed)
        goto done;
    /* The corners are judged on the surface itself, not its caps (which
     * touch only the holes). */
    for (size_t t = 0; t < mesh->ntriangles; t++)
        for (int k = 0; k < 3; k++)
            angle_sum[c.triangle[3 * t + k]] += corner_angle(&c, t, k);
    place_boundary(&c, angle_sum, vertex_uv);
    for (size_t k = 0; k < c.nouter; k++)
        fixed[c.outer[k]] = 1;
    if (build_system(&c, &system) != FACET_OK)
        goto done;

    for (int axis = 0; axis < 2; axis++) {
        for (size_t i = 0; i < n; i++) {
            if (fixed[i]) {
                b[i] = x[i] = vertex_uv[2 * i + axis];
                continue;
            }
            double sum = 0;
            for (uint32_t e = system.row_start[i]; e < system.row_start[i + 1];
                 e++)
                if (fixed[system.column[e]])
                    sum += system.weight[e] *
                           vertex_uv[2 * system.column[e] + axis];
            b[i] = sum;
            x[i] = 0;
        }
        int solved = solve(&system, fixed, b, x, stop);
        if (solved < 0)
            goto done;
        if (solved == 2) {
            rc = FACET_ESTOP;
            goto done;
        }
        if (solved > 0) {
            snprintf(why, size, "the harmonic parameterization did not "
                     "converge");
            rc = FACET_EINPUT;
            goto done;
        }
        for (size_t i = 0; i < n; i++)
            vertex_uv[2 * i + axis] = x[i];
    }
    /* Dropping the caps: their centres are the last vertices. */
    *holes = mesh->nloops - 1;
    *vertex_uv_out = vertex_uv;
    vertex_uv = NULL;
    rc = FACET_OK;
done:
    system_free(&system);
    capped_free(&c);
    free(vertex_uv);
    free(angle_sum);
    free(b);
    free(x);
    free(fixed);
    return rc;
}
