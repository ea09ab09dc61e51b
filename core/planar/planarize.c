/*
 * planarize.c: Gauss-Newton on planarity, closeness and fairness, one
 * CHOLMOD analysis for every step (planarize.h).
 */
#include "planarize.h"

#include <assert.h>
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/base/quad.h"
#include "core/base/vec3.h"
#include "core/planar/sparse_solver.h"

/* The weights of planarize.h's sum; closeness has weight 1. Planarity's
 * grows from the first to the last a hundredfold at a time (see solve). */
#define WEIGHT_PLANARITY_FIRST 1.0
#define WEIGHT_PLANARITY 1e6
#define WEIGHT_FAIRNESS 0.1
/* Of the squared distance each corner moved from its start: the grid
 * stays the designer's, its joints where they were drawn. */
#define WEIGHT_ANCHOR 0.01
/* The least Levenberg-Marquardt damping, beside a diagonal of about 1. */
#define MU_LEAST 1e-4

static const int corner_offset[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};

void planarize_options_defaults(struct planarize_options *o)
{
    memset(o, 0, sizeof *o);
    o->closeness = PLANARIZE_CLOSENESS_DEFAULT;
    o->planarity = PLANARIZE_PLANARITY_DEFAULT;
    o->max_iterations = 100;
}

/* The unknowns: the nodes that are a quad's corner, numbered, and the
 * terms that tie them. */
struct problem {
    const struct quad_grid *grid;
    int nvars;
    int *var_of;          /* per node: its unknown, or -1 */
    int *node_of;         /* per unknown: its node */
    int (*quad)[4];       /* nquads x the unknowns of its corners */
    size_t nquads;
    int (*triple)[3];     /* three consecutive corners of a grid line */
    size_t ntriples;
    /* The upper triangle's pattern, in 3 x 3 blocks: the neighbours of
     * unknown b below or at it are nbr[nbr_start[b] .. nbr_start[b + 1]),
     * ascending, b itself last. */
    int *nbr_start;
    int *nbr;
    /* Where each term's blocks are in that pattern, found once so that
     * each step fills the matrix without a search: the rank (block_rank)
     * of block (min, max) of the quad's corners a, b, and of the
     * triple's. */
    int (*quad_rank)[4][4];
    int (*triple_rank)[3][3];
};

static void problem_free(struct problem *p)
{
    free(p->var_of);
    free(p->node_of);
    free(p->quad);
    free(p->triple);
    free(p->nbr_start);
    free(p->nbr);
    free(p->quad_rank);
    free(p->triple_rank);
}

static int compare_int(const void *a, const void *b)
{
    int x = *(const int *)a, y = *(const int *)b;
    return (x > y) - (x < y);
}

/* A pair (a, b), a <= b, of unknowns a term ties. */
struct pair {
    int a, b;
};

static int compare_pair(const void *x, const void *y)
{
    const struct pair *p = x, *q = y;
    if (p->b != q->b)
        return (p->b > q->b) - (p->b < q->b);
    return (p->a > q->a) - (p->a < q->a);
}

static void add_pair(struct pair *pairs, size_t *n, int a, int b)
{
    pairs[*n].a = a < b ? a : b;
    pairs[*n].b = a < b ? b : a;
    (*n)++;
}

static int block_rank(const struct problem *p, int a, int b);

static int problem_build(const struct quad_grid *g, struct problem *p,
                         struct facet_error *err)
{
    memset(p, 0, sizeof *p);
    p->grid = g;
    size_t nodes = (size_t)(g->nu + 1) * (g->nv + 1);
    p->var_of = malloc(nodes * sizeof *p->var_of);
    p->quad = malloc(g->nquads * sizeof *p->quad);
    if (p->var_of == NULL || p->quad == NULL)
        return facet_error_set(err, FACET_EWORK, "out of memory");
    for (size_t k = 0; k < nodes; k++)
        p->var_of[k] = -1;
    for (int j = 0; j < g->nv; j++)
        for (int i = 0; i < g->nu; i++)
            if (g->quad[(size_t)j * g->nu + i])
                for (int c = 0; c < 4; c++)
                    p->var_of[(size_t)(j + corner_offset[c][1]) * (g->nu + 1) +
                              i + corner_offset[c][0]] = 0;
    p->node_of = malloc(nodes * sizeof *p->node_of);
    if (p->node_of == NULL)
        return facet_error_set(err, FACET_EWORK, "out of memory");
    for (size_t k = 0; k < nodes; k++)
        if (p->var_of[k] == 0) {
            p->node_of[p->nvars] = (int)k;
            p->var_of[k] = p->nvars++;
        }
    for (int j = 0; j < g->nv; j++)
        for (int i = 0; i < g->nu; i++)
            if (g->quad[(size_t)j * g->nu + i]) {
                for (int c = 0; c < 4; c++)
                    p->quad[p->nquads][c] =
                        p->var_of[(size_t)(j + corner_offset[c][1]) *
                                  (g->nu + 1) + i + corner_offset[c][0]];
                p->nquads++;
            }
    /* Fairness along both families of grid lines, wherever three
     * consecutive nodes are unknowns. */
    p->triple = malloc(2 * nodes * sizeof *p->triple);
    if (p->triple == NULL)
        return facet_error_set(err, FACET_EWORK, "out of memory");
    for (int j = 0; j <= g->nv; j++)
        for (int i = 0; i <= g->nu; i++)
            for (int axis = 0; axis < 2; axis++) {
                int di = axis == 0, dj = axis == 1;
                if (i + 2 * di > g->nu || j + 2 * dj > g->nv)
                    continue;
                int v[3];
                for (int k = 0; k < 3; k++)
                    v[k] = p->var_of[(size_t)(j + k * dj) * (g->nu + 1) + i +
                                     k * di];
                if (v[0] < 0 || v[1] < 0 || v[2] < 0)
                    continue;
                memcpy(p->triple[p->ntriples++], v, sizeof v);
            }
    /* The pattern: every pair a term ties, and each unknown with itself. */
    size_t most = 10 * p->nquads + 6 * p->ntriples + (size_t)p->nvars;
    struct pair *pairs = malloc(most * sizeof *pairs);
    p->nbr_start = calloc((size_t)p->nvars + 1, sizeof *p->nbr_start);
    if (pairs == NULL || p->nbr_start == NULL) {
        free(pairs);
        return facet_error_set(err, FACET_EWORK, "out of memory");
    }
    size_t n = 0;
    for (size_t q = 0; q < p->nquads; q++)
        for (int a = 0; a < 4; a++)
            for (int b = a + 1; b < 4; b++)
                add_pair(pairs, &n, p->quad[q][a], p->quad[q][b]);
    for (size_t t = 0; t < p->ntriples; t++)
        for (int a = 0; a < 3; a++)
            for (int b = a + 1; b < 3; b++)
                add_pair(pairs, &n, p->triple[t][a], p->triple[t][b]);
    for (int v = 0; v < p->nvars; v++)
        add_pair(pairs, &n, v, v);
    qsort(pairs, n, sizeof *pairs, compare_pair);
    size_t kept = 0;
    for (size_t k = 0; k < n; k++)
        if (kept == 0 || pairs[k].a != pairs[kept - 1].a ||
            pairs[k].b != pairs[kept - 1].b)
            pairs[kept++] = pairs[k];
    p->nbr = malloc(kept * sizeof *p->nbr);
    if (p->nbr == NULL) {
        free(pairs);
        return facet_error_set(err, FACET_EWORK, "out of memory");
    }
    for (size_t k = 0; k < kept; k++) {
        p->nbr[k] = pairs[k].a;
        p->nbr_start[pairs[k].b + 1]++;
    }
    for (int v = 0; v < p->nvars; v++)
        p->nbr_start[v + 1] += p->nbr_start[v];
    free(pairs);
    p->quad_rank = malloc(p->nquads * sizeof *p->quad_rank);
    p->triple_rank = malloc(p->ntriples * sizeof *p->triple_rank);
    if (p->quad_rank == NULL || p->triple_rank == NULL)
        return facet_error_set(err, FACET_EWORK, "out of memory");
    for (size_t q = 0; q < p->nquads; q++)
        for (int a = 0; a < 4; a++)
            for (int b = 0; b < 4; b++) {
                int lo = p->quad[q][a], hi = p->quad[q][b];
                p->quad_rank[q][a][b] = lo < hi ? block_rank(p, lo, hi)
                                                : block_rank(p, hi, lo);
            }
    for (size_t t = 0; t < p->ntriples; t++)
        for (int a = 0; a < 3; a++)
            for (int b = 0; b < 3; b++) {
                int lo = p->triple[t][a], hi = p->triple[t][b];
                p->triple_rank[t][a][b] = lo < hi ? block_rank(p, lo, hi)
                                                  : block_rank(p, hi, lo);
            }
    return FACET_OK;
}

/* Where block (a, b), a <= b, starts in unknown b's neighbours. */
static int block_rank(const struct problem *p, int a, int b)
{
    const int *list = &p->nbr[p->nbr_start[b]];
    int n = p->nbr_start[b + 1] - p->nbr_start[b];
    const int *hit = bsearch(&a, list, (size_t)n, sizeof *list, compare_int);
    assert(hit != NULL);
    return (int)(hit - list);
}

/* The upper triangle of the 3N x 3N matrix, CHOLMOD's symmetric form:
 * column 3 b + y holds rows 3 a + x of each neighbour a < b, then rows
 * 3 b .. 3 b + y. */
static cholmod_sparse *pattern_make(const struct problem *p,
                                    const struct sparse_solver *cm,
                                    cholmod_common *c)
{
    size_t n = 3 * (size_t)p->nvars;
    size_t nnz = 0;
    for (int b = 0; b < p->nvars; b++) {
        size_t below = (size_t)(p->nbr_start[b + 1] - p->nbr_start[b] - 1);
        nnz += 3 * (3 * below) + 6;
    }
    cholmod_sparse *A = cm->allocate_sparse(n, n, nnz, 1, 1, 1, CHOLMOD_REAL,
                                           c);
    if (A == NULL)
        return NULL;
    int *Ap = A->p, *Ai = A->i;
    size_t at = 0;
    for (int b = 0; b < p->nvars; b++)
        for (int y = 0; y < 3; y++) {
            Ap[3 * b + y] = (int)at;
            for (int k = p->nbr_start[b]; k < p->nbr_start[b + 1]; k++) {
                int a = p->nbr[k];
                for (int x = 0; x < (a == b ? y + 1 : 3); x++)
                    Ai[at++] = 3 * a + x;
            }
        }
    Ap[n] = (int)at;
    assert(at == nnz);
    return A;
}

/* Adds w to entry (3 a + x, 3 b + y) of A, taking the upper triangle;
 * rank is block (min(a, b), max(a, b))'s (block_rank). */
static void matrix_add(cholmod_sparse *A, int rank, int a, int x, int b,
                       int y, double w)
{
    if (a > b || (a == b && x > y)) {
        int t = a; a = b; b = t;
        t = x; x = y; y = t;
    }
    const int *Ap = A->p;
    ((double *)A->x)[Ap[3 * b + y] + 3 * rank + x] += w;
}

/* The rank of unknown v's own block: last among its neighbours. */
static int diagonal_rank(const struct problem *p, int v)
{
    return p->nbr_start[v + 1] - p->nbr_start[v] - 1;
}

/* Quad q's signed planarity (m) at x, and its derivative by each corner
 * coordinate into g (the normal's length held fixed: exact where the
 * residual is zero, where Gauss-Newton ends). */
static double quad_residual(const double *x, const int v[4], double g[4][3])
{
    const double *c[4];
    for (int k = 0; k < 4; k++)
        c[k] = &x[3 * v[k]];
    double d1[3], d2[3], e[3], n[3], a[3], b[3];
    vec3_sub(c[2], c[0], d1);
    vec3_sub(c[3], c[1], d2);
    vec3_sub(c[1], c[0], e);
    vec3_cross(d1, d2, n);
    double length = vec3_length(n);
    if (!(length > 0)) {
        memset(g, 0, 12 * sizeof(double));
        return 0;
    }
    vec3_cross(d2, e, a);  /* d volume / d d1 */
    vec3_cross(e, d1, b);  /* d volume / d d2 */
    for (int k = 0; k < 3; k++) {
        g[0][k] = (-a[k] - n[k]) / length;
        g[1][k] = (n[k] - b[k]) / length;
        g[2][k] = a[k] / length;
        g[3][k] = b[k] / length;
    }
    return vec3_dot(n, e) / length;
}

/* Each unknown's nearest point on the mesh at x: foot (3 N), and the
 * closeness energy, the sum of the squared distances. */
static double feet_find(const struct nearest_index *index, int nvars,
                        const double *x, double *foot, double *normal)
{
    double sum = 0;
    for (int v = 0; v < nvars; v++) {
        struct nearest_hit hit;
        nearest_point(index, &x[3 * v], &hit);
        memcpy(&foot[3 * v], hit.point, sizeof hit.point);
        double d[3];
        vec3_sub(&x[3 * v], hit.point, d);
        /* Off the surface the direction to the foot is the normal of the
         * distance's level set, also at an edge or a boundary; on it, the
         * triangle's. */
        if (hit.distance > 1e-12 && vec3_normalize(d))
            memcpy(&normal[3 * v], d, sizeof d);
        else
            memcpy(&normal[3 * v],
                   &index->mesh->face_normal[3 * (size_t)hit.triangle],
                   3 * sizeof(double));
        sum += hit.distance * hit.distance;
    }
    return sum;
}

/* The closeness energy at x alone. */
static double closeness_of(const struct nearest_index *index, int nvars,
                           const double *x)
{
    double sum = 0;
    for (int v = 0; v < nvars; v++) {
        struct nearest_hit hit;
        nearest_point(index, &x[3 * v], &hit);
        sum += hit.distance * hit.distance;
    }
    return sum;
}

/* The whole energy at x whose feet are known (closeness given). */
static double energy(const struct problem *p, const double *x,
                     const double *x0, double closeness, double w_p)
{
    double sum = closeness;
    for (size_t q = 0; q < p->nquads; q++) {
        double g[4][3];
        double r = quad_residual(x, p->quad[q], g);
        sum += w_p * r * r;
    }
    for (size_t k = 0; k < 3 * (size_t)p->nvars; k++)
        sum += WEIGHT_ANCHOR * (x[k] - x0[k]) * (x[k] - x0[k]);
    for (size_t t = 0; t < p->ntriples; t++) {
        const int *v = p->triple[t];
        for (int k = 0; k < 3; k++) {
            double d = (x[3 * v[0] + k] - x0[3 * v[0] + k]) -
                       2 * (x[3 * v[1] + k] - x0[3 * v[1] + k]) +
                       (x[3 * v[2] + k] - x0[3 * v[2] + k]);
            sum += WEIGHT_FAIRNESS * d * d;
        }
    }
    return sum;
}

/* The Gauss-Newton system at x into A (values) and rhs (minus half the
 * gradient), damped by mu on the diagonal. */
static void system_fill(const struct problem *p, cholmod_sparse *A,
                        double *rhs, const double *x, const double *x0,
                        const double *foot, const double *normal, double w_p,
                        double mu)
{
    const int *Ap = A->p;
    memset(A->x, 0, (size_t)Ap[A->ncol] * sizeof(double));
    memset(rhs, 0, 3 * (size_t)p->nvars * sizeof *rhs);
    for (size_t q = 0; q < p->nquads; q++) {
        const int *v = p->quad[q];
        double g[4][3];
        double r = quad_residual(x, v, g);
        for (int a = 0; a < 4; a++)
            for (int xa = 0; xa < 3; xa++) {
                rhs[3 * v[a] + xa] -= w_p * g[a][xa] * r;
                for (int b = 0; b < 4; b++)
                    for (int xb = 0; xb < 3; xb++) {
                        /* Each pair once: the upper triangle. */
                        if (v[a] > v[b] || (v[a] == v[b] && xa > xb))
                            continue;
                        matrix_add(A, p->quad_rank[q][a][b], v[a], xa, v[b],
                                   xb, w_p * g[a][xa] * g[b][xb]);
                    }
            }
    }
    for (int v = 0; v < p->nvars; v++) {
        const double *n = &normal[3 * v];
        for (int xa = 0; xa < 3; xa++) {
            rhs[3 * v + xa] -= x[3 * v + xa] - foot[3 * v + xa] +
                               WEIGHT_ANCHOR * (x[3 * v + xa] - x0[3 * v + xa]);
            for (int xb = xa; xb < 3; xb++)
                matrix_add(A, diagonal_rank(p, v), v, xa, v, xb,
                           n[xa] * n[xb] +
                           (xa == xb ? WEIGHT_ANCHOR + mu : 0));
        }
    }
    static const double D[3] = {1, -2, 1};
    for (size_t t = 0; t < p->ntriples; t++) {
        const int *v = p->triple[t];
        for (int k = 0; k < 3; k++) {
            double d = 0;
            for (int s = 0; s < 3; s++)
                d += D[s] * (x[3 * v[s] + k] - x0[3 * v[s] + k]);
            for (int a = 0; a < 3; a++) {
                rhs[3 * v[a] + k] -= WEIGHT_FAIRNESS * D[a] * d;
                for (int b = 0; b < 3; b++)
                    if (v[a] <= v[b])
                        matrix_add(A, p->triple_rank[t][a][b], v[a], k,
                                   v[b], k, WEIGHT_FAIRNESS * D[a] * D[b]);
            }
        }
    }
}

/* The per-node and per-quad measures of out->grid and its summary. */
static void measure(const struct nearest_index *index,
                    const struct planarize_options *o,
                    const struct quad_grid *start,
                    struct planarize_result *out)
{
    const struct quad_grid *g = &out->grid;
    size_t nodes = (size_t)(g->nu + 1) * (g->nv + 1);
    out->ncorners = 0;
    out->max_distance = out->mean_distance = out->max_moved = 0;
    double sum = 0;
    for (size_t k = 0; k < nodes; k++) {
        const double *x = &g->node[3 * k];
        out->distance[k] = out->moved[k] = NAN;
        if (isnan(x[0]))
            continue;
        struct nearest_hit hit;
        nearest_point(index, x, &hit);
        out->distance[k] = hit.distance;
        out->moved[k] = vec3_distance(x, &start->node[3 * k]);
        out->max_distance = fmax(out->max_distance, hit.distance);
        out->max_moved = fmax(out->max_moved, out->moved[k]);
        sum += hit.distance;
        out->ncorners++;
    }
    out->mean_distance = out->ncorners ? sum / out->ncorners : NAN;
    out->nquads = out->over = 0;
    out->max_planarity = out->max_relative = 0;
    for (int j = 0; j < g->nv; j++)
        for (int i = 0; i < g->nu; i++) {
            size_t q = (size_t)j * g->nu + i;
            out->planarity[q] = out->relative[q] = NAN;
            if (!g->quad[q])
                continue;
            double c[4][3];
            quad_grid_corners(g, i, j, c);
            double planarity = quad_planarity(c);
            double diagonal = quad_diagonal(c);
            out->planarity[q] = planarity;
            out->relative[q] = diagonal > 0 ? planarity / diagonal : 0;
            out->max_planarity = fmax(out->max_planarity, planarity);
            out->max_relative = fmax(out->max_relative, out->relative[q]);
            if (out->relative[q] > o->planarity)
                out->over++;
            out->nquads++;
        }
    out->feasible = out->over == 0 && out->max_distance <= o->closeness;
}

/* The result's arrays, and its grid a copy of start with the nodes of
 * no quad NaN. */
static int result_start(const struct quad_grid *start, const int *var_of,
                        struct planarize_result *out, struct facet_error *err)
{
    memset(out, 0, sizeof *out);
    struct quad_grid *g = &out->grid;
    g->nu = start->nu;
    g->nv = start->nv;
    g->nquads = start->nquads;
    size_t nodes = (size_t)(g->nu + 1) * (g->nv + 1);
    size_t quads = (size_t)g->nu * g->nv;
    g->node = malloc(3 * nodes * sizeof *g->node);
    g->quad = malloc(quads);
    out->distance = malloc(nodes * sizeof *out->distance);
    out->moved = malloc(nodes * sizeof *out->moved);
    out->planarity = malloc(quads * sizeof *out->planarity);
    out->relative = malloc(quads * sizeof *out->relative);
    if (g->node == NULL || g->quad == NULL || out->distance == NULL ||
        out->moved == NULL || out->planarity == NULL || out->relative == NULL)
        return facet_error_set(err, FACET_EWORK, "out of memory");
    memcpy(g->quad, start->quad, quads);
    for (size_t k = 0; k < nodes; k++)
        for (int x = 0; x < 3; x++)
            g->node[3 * k + x] = var_of[k] >= 0 ? start->node[3 * k + x] : NAN;
    return FACET_OK;
}

/* The iterations themselves, over the problem's unknowns x (3 N, from
 * the start), with CHOLMOD's functions cm and its state c. */
static int solve(const struct nearest_index *index, const struct problem *p,
                 const struct planarize_options *o, double *x,
                 const struct sparse_solver *cm, cholmod_common *c,
                 int *iterations, int *converged,
                 struct facet_error *err)
{
    size_t n = 3 * (size_t)p->nvars;
    double *x0 = malloc(n * sizeof *x0);
    double *trial = malloc(n * sizeof *trial);
    double *foot = malloc(n * sizeof *foot);
    double *normal = malloc(n * sizeof *normal);
    double *trial_foot = malloc(n * sizeof *trial_foot);
    double *trial_normal = malloc(n * sizeof *trial_normal);
    cholmod_sparse *A = pattern_make(p, cm, c);
    cholmod_dense *B = cm->zeros(n, 1, CHOLMOD_REAL, c);
    cholmod_factor *L = NULL;
    int rc = FACET_OK;
    if (x0 == NULL || trial == NULL || foot == NULL || normal == NULL ||
        trial_foot == NULL || trial_normal == NULL || A == NULL ||
        B == NULL) {
        rc = facet_error_set(err, FACET_EWORK, "out of memory");
        goto done;
    }
    memcpy(x0, x, n * sizeof *x);
    L = cm->analyze(A, c);
    if (L == NULL) {
        rc = facet_error_set(err, FACET_EWORK,
                             "the sparse solver (CHOLMOD) failed: status %d",
                             c->status);
        goto done;
    }
    /* A step is done when no corner moves by more than still, or the sum
     * falls by less than a thousandth; a weight is done after a done
     * step, or after steps_per_weight steps. */
    double still = fmax(1e-3 * o->closeness, 1e-6);
    const int steps_per_weight = 8;
    double w_p = WEIGHT_PLANARITY_FIRST;
    int at_weight = 0;
    double mu = MU_LEAST;
    double closeness = feet_find(index, p->nvars, x, foot, normal);
    double e = energy(p, x, x0, closeness, w_p);
    *iterations = 0;
    *converged = 0;
    while (*iterations < o->max_iterations) {
        if ((rc = facet_stop_check(o->stop, err)))
            goto done;
        system_fill(p, A, B->x, x, x0, foot, normal, w_p, mu);
        c->status = CHOLMOD_OK;
        if (!cm->factorize(A, L, c) || c->status != CHOLMOD_OK) {
            /* Not positive definite to rounding: more damping. */
            if (c->status == CHOLMOD_NOT_POSDEF && mu < 1e6) {
                mu *= 100;
                continue;
            }
            rc = facet_error_set(err, FACET_EWORK,
                "the sparse solver (CHOLMOD) failed: status %d", c->status);
            goto done;
        }
        cholmod_dense *step = cm->solve(CHOLMOD_A, L, B, c);
        if (step == NULL) {
            rc = facet_error_set(err, FACET_EWORK,
                "the sparse solver (CHOLMOD) failed: status %d", c->status);
            goto done;
        }
        const double *dx = step->x;
        double largest = 0;
        for (size_t k = 0; k < n; k++)
            trial[k] = x[k] + dx[k];
        for (int v = 0; v < p->nvars; v++) {
            double d2 = dx[3 * v] * dx[3 * v] + dx[3 * v + 1] * dx[3 * v + 1] +
                        dx[3 * v + 2] * dx[3 * v + 2];
            largest = fmax(largest, d2);
        }
        largest = sqrt(largest);
        cm->free_dense(&step, c);
        double trial_closeness = feet_find(index, p->nvars, trial, trial_foot,
                                           trial_normal);
        double trial_e = energy(p, trial, x0, trial_closeness, w_p);
        (*iterations)++;
        at_weight++;
        int done_step = largest < still;
        if (trial_e <= e || done_step) {
            done_step = done_step || e - trial_e <= 1e-3 * e;
            memcpy(x, trial, n * sizeof *x);
            memcpy(foot, trial_foot, n * sizeof *foot);
            memcpy(normal, trial_normal, n * sizeof *normal);
            e = trial_e;
            mu = fmax(mu / 3, MU_LEAST);
        } else {
            mu *= 10;
            /* No step lowers the sum: as far as this weight goes. */
            done_step = mu > 1e4;
        }
        if (done_step || at_weight >= steps_per_weight) {
            if (w_p >= WEIGHT_PLANARITY) {
                *converged = done_step;
                if (done_step)
                    break;
            } else {
                w_p *= 100;
                at_weight = 0;
                mu = MU_LEAST;
                e = energy(p, x, x0, closeness_of(index, p->nvars, x), w_p);
            }
        }
        if (o->progress != NULL)
            o->progress(o->progress_context, *iterations, o->max_iterations);
    }
done:
    cm->free_factor(&L, c);
    cm->free_dense(&B, c);
    cm->free_sparse(&A, c);
    free(x0);
    free(trial);
    free(foot);
    free(normal);
    free(trial_foot);
    free(trial_normal);
    return rc;
}

int planarize(const struct mesh *mesh, const struct nearest_index *index,
              const struct quad_grid *start,
              const struct planarize_options *o,
              struct planarize_result *out, struct facet_error *err)
{
    memset(out, 0, sizeof *out);
    assert(index->mesh == mesh);
    if (!(o->closeness >= 0) || !isfinite(o->closeness))
        return facet_error_set(err, FACET_EINPUT,
            "the closeness budget must be a finite distance of 0 or more");
    if (!(o->planarity > 0) || !isfinite(o->planarity))
        return facet_error_set(err, FACET_EINPUT,
            "the planarity tolerance must be a finite number above 0");
    if (o->max_iterations < 1)
        return facet_error_set(err, FACET_EINPUT,
                               "planarizing needs at least one iteration");
    if (start->nquads == 0)
        return facet_error_set(err, FACET_EINPUT,
                               "the grid has no quad to planarize");
    struct problem p;
    int rc = problem_build(start, &p, err);
    if (rc == FACET_OK)
        rc = result_start(start, p.var_of, out, err);
    double *x = NULL;
    if (rc == FACET_OK) {
        x = malloc(3 * (size_t)p.nvars * sizeof *x);
        if (x == NULL)
            rc = facet_error_set(err, FACET_EWORK, "out of memory");
    }
    if (rc == FACET_OK) {
        for (int v = 0; v < p.nvars; v++)
            memcpy(&x[3 * v], &start->node[3 * (size_t)p.node_of[v]],
                   3 * sizeof *x);
        /* The start grid's planarity, to report beside the result's. */
        measure(index, o, start, out);
        out->start_max_relative = out->max_relative;
        struct sparse_solver cm;
        rc = sparse_solver_open(&cm, err);
        if (rc == FACET_OK) {
            cholmod_common c;
            cm.start(&c);
            c.print = 0;      /* core prints nothing: errors come back */
            c.error_handler = NULL;
            /* CHOLMOD's own nested dissection: 1.94 GFlop a factorization
             * of the roof's 100 x 100 grid against AMD's 2.28 (METIS's
             * 2.07). CHOLMOD's default tries METIS only where AMD's
             * flops per entry of L pass 500, here 389, and keeps AMD. */
            c.nmethods = 1;
            c.method[0].ordering = CHOLMOD_NESDIS;
            rc = solve(index, &p, o, x, &cm, &c, &out->iterations,
                       &out->converged, err);
            cm.finish(&c);
        }
        sparse_solver_close(&cm);
    }
    if (rc == FACET_OK) {
        for (int v = 0; v < p.nvars; v++)
            memcpy(&out->grid.node[3 * (size_t)p.node_of[v]], &x[3 * v],
                   3 * sizeof *x);
        measure(index, o, start, out);
    }
    free(x);
    problem_free(&p);
    return rc;
}

void planarize_result_free(struct planarize_result *r)
{
    quad_grid_free(&r->grid);
    free(r->distance);
    free(r->moved);
    free(r->planarity);
    free(r->relative);
    memset(r, 0, sizeof *r);
}
