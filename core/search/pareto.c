/*
 * pareto.c: non-dominated sorting, crowding distance, survivor selection,
 * hypervolume and knee. See pareto.h for the contracts and complexities.
 *
 * Every sort here is a stable merge sort of index arrays whose comparators
 * end with the index, so results never depend on a library sort's order of
 * equal elements (qsort is neither stable nor given a context in C11).
 */
#include "core/search/pareto.h"

#include <assert.h>
#include <limits.h>
#include <math.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "core/search/ties.h"

/* ---- sorting index arrays ------------------------------------------------ */

/* Orders two indices: negative, zero or positive, like strcmp. */
typedef int (*index_compare)(const void *context, size_t a, size_t b);

/* Stable merge sort of items[0..n) by compare; scratch holds n / 2 + 1
 * entries. */
static void sort_indices(size_t *items, size_t n, size_t *scratch,
                         index_compare compare, const void *context)
{
    if (n < 16) {
        for (size_t i = 1; i < n; i++) {
            size_t item = items[i], j = i;
            while (j > 0 && compare(context, item, items[j - 1]) < 0) {
                items[j] = items[j - 1];
                j--;
            }
            items[j] = item;
        }
        return;
    }
    size_t half = n / 2;
    sort_indices(items, half, scratch, compare, context);
    sort_indices(items + half, n - half, scratch, compare, context);
    if (compare(context, items[half - 1], items[half]) <= 0)
        return;
    memcpy(scratch, items, half * sizeof *items);
    size_t i = 0, j = half, k = 0;
    while (i < half && j < n) {
        if (compare(context, items[j], scratch[i]) < 0)
            items[k++] = items[j++];
        else
            items[k++] = scratch[i++];
    }
    while (i < half)
        items[k++] = scratch[i++];
}

/* Objective vectors for the comparators: n x m row-major. */
struct point_set {
    const double *objectives;
    size_t m;
    size_t axis;          /* for compare_axis */
    const double *value;  /* for compare_value: one value per index */
    const int *rank;      /* for compare_rank */
};

static int compare_doubles(double a, double b)
{
    return (a > b) - (a < b);
}

static int compare_index(size_t a, size_t b)
{
    return (a > b) - (a < b);
}

/* Lexicographic on the objectives, without the index tie-break. */
static int compare_point(const struct point_set *set, size_t a, size_t b)
{
    const double *pa = set->objectives + a * set->m;
    const double *pb = set->objectives + b * set->m;
    for (size_t j = 0; j < set->m; j++) {
        int c = compare_doubles(pa[j], pb[j]);
        if (c != 0)
            return c;
    }
    return 0;
}

static int compare_lex(const void *context, size_t a, size_t b)
{
    int c = compare_point(context, a, b);
    return c != 0 ? c : compare_index(a, b);
}

/* By one objective, then lexicographic, then index. */
static int compare_axis(const void *context, size_t a, size_t b)
{
    const struct point_set *set = context;
    int c = compare_doubles(set->objectives[a * set->m + set->axis],
                            set->objectives[b * set->m + set->axis]);
    return c != 0 ? c : compare_lex(context, a, b);
}

/* By value[index], then index. */
static int compare_value(const void *context, size_t a, size_t b)
{
    const struct point_set *set = context;
    int c = compare_doubles(set->value[a], set->value[b]);
    return c != 0 ? c : compare_index(a, b);
}

/* By rank[index], then index. */
static int compare_rank(const void *context, size_t a, size_t b)
{
    const struct point_set *set = context;
    int c = (set->rank[a] > set->rank[b]) - (set->rank[a] < set->rank[b]);
    return c != 0 ? c : compare_index(a, b);
}

/* ---- input checks -------------------------------------------------------- */

static int check_objectives(const double *objectives, size_t n, size_t m,
                            struct facet_error *err)
{
    if (m == 0)
        return facet_error_set(err, FACET_EINPUT, "pareto: no objectives");
    for (size_t i = 0; i < n; i++)
        for (size_t j = 0; j < m; j++)
            if (isnan(objectives[i * m + j]))
                return facet_error_set(err, FACET_EINPUT,
                                       "pareto: objective %zu of point %zu "
                                       "is NaN", j, i);
    return FACET_OK;
}

static int check_violation(const double *violation, size_t n,
                           struct facet_error *err)
{
    if (violation == NULL)
        return FACET_OK;
    for (size_t i = 0; i < n; i++)
        if (!(violation[i] >= 0))
            return facet_error_set(err, FACET_EINPUT,
                                   "pareto: violation of point %zu is %g, "
                                   "not >= 0", i, violation[i]);
    return FACET_OK;
}

/* The input of the functions that rank: objectives, violation, and few
 * enough points for an int rank. */
static int check_ranked(const double *objectives, size_t n, size_t m,
                        const double *violation, struct facet_error *err)
{
    int rc = check_objectives(objectives, n, m, err);
    if (rc == FACET_OK)
        rc = check_violation(violation, n, err);
    if (rc == FACET_OK && n >= INT_MAX)
        rc = facet_error_set(err, FACET_EINPUT,
                             "pareto: %zu points are too many to rank", n);
    return rc;
}

static int out_of_memory(struct facet_error *err, const char *what)
{
    return facet_error_set(err, FACET_EWORK, "pareto: out of memory (%s)",
                           what);
}

/* The objectives with every tie class merged into its lowest value
 * (ties.h), in a new array the caller frees; NULL when out of memory.
 * Every function below works on these, so that values equal within the
 * tolerance are equal in every comparison. */
static double *merge_ties(const double *objectives, size_t n, size_t m)
{
    double *merged = malloc((n * m + 1) * sizeof *merged);
    if (merged == NULL)
        return NULL;
    if (ties_merge(objectives, n, m, merged, NULL) != FACET_OK) {
        free(merged);
        return NULL;
    }
    return merged;
}

/* ---- non-dominated sorting of distinct points ---------------------------- */
/*
 * The rankers below see u distinct points given by their indices in
 * lexicographic order: point[k] for k in [0, u). A point earlier in that
 * order can dominate a later one, never the reverse, and an earlier point
 * no worse in objectives 1..m-1 does dominate (it is no worse in objective
 * 0 and differs somewhere). So rank[k] = 1 + max rank of earlier points
 * that are no worse in objectives 1..m-1, and the ranks of earlier points
 * are final when a point is reached.
 */

/* m = 2. low[f] is the lowest second objective in front f so far; it is
 * non-decreasing in f, and front f dominates a point exactly when
 * low[f] <= its second objective, so a binary search finds its front.
 * Returns the number of fronts, or -1 when out of memory. */
static int rank_two(const struct point_set *set, const size_t *point,
                    size_t u, int *rank)
{
    assert(set->m == 2 && u < INT_MAX);
    double *low = malloc((u + 1) * sizeof *low);
    if (low == NULL)
        return -1;
    size_t fronts = 0;
    for (size_t k = 0; k < u; k++) {
        double y = set->objectives[point[k] * 2 + 1];
        size_t lo = 0, hi = fronts;
        while (lo < hi) {
            size_t mid = lo + (hi - lo) / 2;
            if (low[mid] <= y)
                lo = mid + 1;
            else
                hi = mid;
        }
        if (lo == fronts)
            fronts++;
        low[lo] = y;
        rank[k] = (int)lo + 1;
    }
    free(low);
    return (int)fronts;
}

/* Working arrays of the m = 3 divide and conquer. Positions are indices
 * into the lexicographic order. */
struct sweep3 {
    size_t u;
    uint32_t *y;       /* dense rank (1-based) of objective 1, by position */
    uint32_t *z;       /* dense rank (1-based) of objective 2, by position */
    int *rank;         /* by position */
    size_t *order;     /* positions; each solved range sorted by (y, pos) */
    size_t *scratch;   /* u entries */
    int *fenwick;      /* prefix maxima of rank over z, 1-based */
    size_t nz;         /* number of distinct z */
};

static void fenwick_raise(struct sweep3 *s, size_t at, int value)
{
    for (; at <= s->nz; at += at & (0 - at))
        if (s->fenwick[at] < value)
            s->fenwick[at] = value;
}

static int fenwick_max(const struct sweep3 *s, size_t at)
{
    int best = 0;
    for (; at > 0; at -= at & (0 - at))
        if (s->fenwick[at] > best)
            best = s->fenwick[at];
    return best;
}

/* Undoes fenwick_raise(s, at, ...): every entry on its path was 0. */
static void fenwick_clear(struct sweep3 *s, size_t at)
{
    for (; at <= s->nz; at += at & (0 - at))
        s->fenwick[at] = 0;
}

static bool before_yz(const struct sweep3 *s, size_t a, size_t b)
{
    return s->y[a] < s->y[b] || (s->y[a] == s->y[b] && a < b);
}

/* Ranks positions [lo, hi), given that order[lo..hi) holds them sorted by
 * (y, position) and that every contribution from positions below lo is
 * already in rank. Leaves order[lo..hi) sorted the same way. */
static void solve3(struct sweep3 *s, size_t lo, size_t hi)
{
    if (hi - lo <= 24) {
        for (size_t i = lo; i < hi; i++)
            for (size_t j = lo; j < i; j++)
                if (s->y[j] <= s->y[i] && s->z[j] <= s->z[i] &&
                    s->rank[j] >= s->rank[i])
                    s->rank[i] = s->rank[j] + 1;
        return;
    }
    size_t mid = lo + (hi - lo) / 2;

    /* Stable split of the sorted range into its two halves. */
    size_t nl = 0, nr = 0;
    for (size_t k = lo; k < hi; k++) {
        size_t p = s->order[k];
        if (p < mid)
            s->order[lo + nl++] = p;
        else
            s->scratch[nr++] = p;
    }
    memcpy(s->order + mid, s->scratch, nr * sizeof *s->order);

    solve3(s, lo, mid);

    /* Left half (final ranks) into right half: sweep by y, left first on
     * ties, querying the best rank with z <= the right point's z. */
    size_t i = lo;
    for (size_t k = mid; k < hi; k++) {
        size_t q = s->order[k];
        for (; i < mid && s->y[s->order[i]] <= s->y[q]; i++)
            fenwick_raise(s, s->z[s->order[i]], s->rank[s->order[i]]);
        int best = fenwick_max(s, s->z[q]);
        if (best >= s->rank[q])
            s->rank[q] = best + 1;
    }
    for (size_t k = lo; k < i; k++)
        fenwick_clear(s, s->z[s->order[k]]);

    solve3(s, mid, hi);

    /* Merge the halves back into (y, position) order. */
    memcpy(s->scratch, s->order + lo, (mid - lo) * sizeof *s->order);
    size_t a = 0, b = mid, out = lo;
    while (a < mid - lo && b < hi) {
        if (before_yz(s, s->order[b], s->scratch[a]))
            s->order[out++] = s->order[b++];
        else
            s->order[out++] = s->scratch[a++];
    }
    while (a < mid - lo)
        s->order[out++] = s->scratch[a++];
}

/* Dense 1-based ranks of values[0..u) into dense; sorted receives the
 * positions sorted by (value, position). Returns the number of distinct
 * values. */
static size_t dense_ranks(const double *values, size_t u, size_t *sorted,
                          size_t *scratch, uint32_t *dense)
{
    struct point_set by = {.value = values};
    for (size_t k = 0; k < u; k++)
        sorted[k] = k;
    sort_indices(sorted, u, scratch, compare_value, &by);
    size_t distinct = 0;
    for (size_t k = 0; k < u; k++) {
        if (k == 0 || values[sorted[k]] != values[sorted[k - 1]])
            distinct++;
        dense[sorted[k]] = (uint32_t)distinct;
    }
    return distinct;
}

/* m = 3: divide and conquer over the lexicographic order (the first
 * objective), the classic 3-D dominance scheme: ranks flow from the left
 * half to the right half through a sweep on objective 1 with a Fenwick
 * tree of maxima over objective 2. Returns fronts or -1 (out of memory). */
static int rank_three(const struct point_set *set, const size_t *point,
                      size_t u, int *rank)
{
    assert(set->m == 3 && u < INT_MAX);
    struct sweep3 s = {.u = u};
    double *values = malloc(u * sizeof *values);
    s.y = malloc(u * sizeof *s.y);
    s.z = malloc(u * sizeof *s.z);
    s.order = malloc(u * sizeof *s.order);
    s.scratch = malloc(u * sizeof *s.scratch);
    s.fenwick = calloc(u + 1, sizeof *s.fenwick);
    int fronts = -1;
    if (values == NULL || s.y == NULL || s.z == NULL || s.order == NULL ||
        s.scratch == NULL || s.fenwick == NULL)
        goto done;

    for (size_t k = 0; k < u; k++)
        values[k] = set->objectives[point[k] * 3 + 2];
    s.nz = dense_ranks(values, u, s.order, s.scratch, s.z);
    for (size_t k = 0; k < u; k++)
        values[k] = set->objectives[point[k] * 3 + 1];
    dense_ranks(values, u, s.order, s.scratch, s.y);

    s.rank = rank;
    for (size_t k = 0; k < u; k++)
        rank[k] = 1;
    if (u > 0)
        solve3(&s, 0, u);
    fronts = 0;
    for (size_t k = 0; k < u; k++)
        if (rank[k] > fronts)
            fronts = rank[k];
done:
    free(values);
    free(s.y);
    free(s.z);
    free(s.order);
    free(s.scratch);
    free(s.fenwick);
    return fronts;
}

/* m >= 4: Efficient Non-dominated Sort, binary search variant. Each front
 * is a linked list of its points in the order they joined; a point goes
 * to the first front none of whose points dominates it. Returns fronts or
 * -1 (out of memory). */
static int rank_many(const struct point_set *set, const size_t *point,
                     size_t u, int *rank)
{
    assert(set->m >= 4 && u < INT_MAX);
    size_t *head = malloc((u + 1) * sizeof *head);
    size_t *tail = malloc((u + 1) * sizeof *tail);
    size_t *next = malloc((u + 1) * sizeof *next);
    if (head == NULL || tail == NULL || next == NULL) {
        free(head);
        free(tail);
        free(next);
        return -1;
    }
    size_t m = set->m, fronts = 0;
    for (size_t k = 0; k < u; k++) {
        const double *q = set->objectives + point[k] * m;
        size_t lo = 0, hi = fronts;
        while (lo < hi) {
            size_t f = lo + (hi - lo) / 2;
            bool dominated = false;
            for (size_t p = head[f]; p != SIZE_MAX && !dominated; p = next[p]) {
                const double *a = set->objectives + point[p] * m;
                size_t j = 1;
                while (j < m && a[j] <= q[j])
                    j++;
                dominated = j == m;
            }
            if (dominated)
                lo = f + 1;
            else
                hi = f;
        }
        if (lo == fronts) {
            head[fronts++] = k;
        } else {
            next[tail[lo]] = k;
        }
        tail[lo] = k;
        next[k] = SIZE_MAX;
        rank[k] = (int)lo + 1;
    }
    free(head);
    free(tail);
    free(next);
    return (int)fronts;
}

/* Ranks the points subset[0..count) (indices into objectives) among
 * themselves, plus offset: their first front gets rank offset + 1.
 * Reorders subset. Returns the number of fronts, or -1 when out of
 * memory. */
static int rank_subset(const double *objectives, size_t m, size_t *subset,
                       size_t count, int offset, int *rank)
{
    /* Ranks are ints: pareto_rank refuses n >= INT_MAX. */
    assert(m >= 1 && count < INT_MAX && offset >= 0 &&
           count <= (size_t)(INT_MAX - offset));
    if (count == 0)
        return 0;
    struct point_set set = {.objectives = objectives, .m = m};
    size_t *scratch = malloc((count / 2 + 1) * sizeof *scratch);
    size_t *point = malloc(count * sizeof *point);
    int *unique_rank = malloc(count * sizeof *unique_rank);
    int fronts = -1;
    if (scratch == NULL || point == NULL || unique_rank == NULL)
        goto done;

    sort_indices(subset, count, scratch, compare_lex, &set);
    size_t u = 0;
    for (size_t k = 0; k < count; k++)
        if (k == 0 || compare_point(&set, subset[k], subset[k - 1]) != 0)
            point[u++] = subset[k];

    if (m == 1) {
        for (size_t k = 0; k < u; k++)
            unique_rank[k] = (int)k + 1;
        fronts = (int)u;
    } else if (m == 2) {
        fronts = rank_two(&set, point, u, unique_rank);
    } else if (m == 3) {
        fronts = rank_three(&set, point, u, unique_rank);
    } else {
        fronts = rank_many(&set, point, u, unique_rank);
    }
    if (fronts < 0)
        goto done;

    /* Copies take the rank of their distinct point. */
    size_t group = 0;
    for (size_t k = 0; k < count; k++) {
        if (k > 0 && compare_point(&set, subset[k], subset[k - 1]) != 0)
            group++;
        rank[subset[k]] = offset + unique_rank[group];
    }
done:
    free(scratch);
    free(point);
    free(unique_rank);
    return fronts;
}

/* pareto_rank on checked objectives whose ties are merged. */
static int rank_merged(const double *objectives, size_t n, size_t m,
                       const double *violation, int *rank, int *nfronts,
                       struct facet_error *err)
{
    if (nfronts != NULL)
        *nfronts = 0;
    if (n == 0)
        return FACET_OK;

    size_t *subset = malloc(n * sizeof *subset);
    size_t *scratch = malloc((n / 2 + 1) * sizeof *scratch);
    if (subset == NULL || scratch == NULL) {
        free(subset);
        free(scratch);
        return out_of_memory(err, "ranks");
    }
    /* Feasible points first, ranked on objectives; then the infeasible,
     * one front per distinct violation, after the feasible fronts. */
    size_t feasible = 0;
    for (size_t i = 0; i < n; i++)
        if (violation == NULL || violation[i] == 0)
            subset[feasible++] = i;
    size_t infeasible = feasible;
    for (size_t i = 0; i < n; i++)
        if (violation != NULL && violation[i] != 0)
            subset[infeasible++] = i;

    int fronts = rank_subset(objectives, m, subset, feasible, 0, rank);
    if (fronts >= 0 && infeasible > feasible) {
        struct point_set by = {.value = violation};
        size_t *rest = subset + feasible;
        size_t count = infeasible - feasible;
        sort_indices(rest, count, scratch, compare_value, &by);
        for (size_t k = 0; k < count; k++) {
            if (k == 0 || violation[rest[k]] != violation[rest[k - 1]])
                fronts++;
            rank[rest[k]] = fronts;
        }
    }
    free(subset);
    free(scratch);
    if (fronts < 0)
        return out_of_memory(err, "ranks");
    if (nfronts != NULL)
        *nfronts = fronts;
    return FACET_OK;
}

int pareto_rank(const double *objectives, size_t n, size_t m,
                const double *violation, int *rank, int *nfronts,
                struct facet_error *err)
{
    int rc = check_ranked(objectives, n, m, violation, err);
    if (rc != FACET_OK)
        return rc;
    double *merged = merge_ties(objectives, n, m);
    if (merged == NULL)
        return out_of_memory(err, "ranks");
    rc = rank_merged(merged, n, m, violation, rank, nfronts, err);
    free(merged);
    return rc;
}

/* ---- crowding distance --------------------------------------------------- */

/* Crowding distance of one front, members[0..count) (reordered). Writes
 * crowding[i] for each member i, and copy[i] (if copy is not NULL): false
 * for the lowest index of each group of identical points, true for the
 * others. work holds count entries, scratch count / 2 + 1. */
static void crowd_front(const double *objectives, size_t m, size_t *members,
                        size_t count, double *crowding, bool *copy,
                        size_t *work, size_t *scratch)
{
    struct point_set set = {.objectives = objectives, .m = m};
    sort_indices(members, count, scratch, compare_lex, &set);
    size_t distinct = 0;
    for (size_t k = 0; k < count; k++) {
        bool first = k == 0 ||
                     compare_point(&set, members[k], members[k - 1]) != 0;
        if (first)
            work[distinct++] = members[k];
        if (copy != NULL)
            copy[members[k]] = !first;
    }

    for (size_t k = 0; k < distinct; k++)
        crowding[work[k]] = distinct <= 2 ? INFINITY : 0.0;
    if (distinct > 2) {
        for (size_t axis = 0; axis < m; axis++) {
            set.axis = axis;
            sort_indices(work, distinct, scratch, compare_axis, &set);
            double low = objectives[work[0] * m + axis];
            double high = objectives[work[distinct - 1] * m + axis];
            double range = high - low;
            crowding[work[0]] = INFINITY;
            crowding[work[distinct - 1]] = INFINITY;
            if (!(range > 0) || isinf(range))
                continue;
            for (size_t k = 1; k + 1 < distinct; k++) {
                double gap = objectives[work[k + 1] * m + axis] -
                             objectives[work[k - 1] * m + axis];
                crowding[work[k]] += gap / range;
            }
        }
    }

    /* Copies follow their distinct point (members is in lexicographic
     * order, so each copy comes right after it). */
    size_t lead = members[0];
    for (size_t k = 1; k < count; k++) {
        if (compare_point(&set, members[k], lead) == 0)
            crowding[members[k]] = crowding[lead];
        else
            lead = members[k];
    }
}

/* Indices 0..n-1 sorted by (rank, index) into order; scratch n / 2 + 1. */
static void order_by_rank(const int *rank, size_t n, size_t *order,
                          size_t *scratch)
{
    struct point_set by = {.rank = rank};
    for (size_t i = 0; i < n; i++)
        order[i] = i;
    sort_indices(order, n, scratch, compare_rank, &by);
}

int pareto_crowding(const double *objectives, size_t n, size_t m,
                    const int *rank, double *crowding,
                    struct facet_error *err)
{
    int rc = check_objectives(objectives, n, m, err);
    if (rc != FACET_OK)
        return rc;
    for (size_t i = 0; i < n; i++)
        if (rank[i] < 1)
            return facet_error_set(err, FACET_EINPUT,
                                   "pareto: rank of point %zu is %d, not >= 1",
                                   i, rank[i]);
    if (n == 0)
        return FACET_OK;
    size_t *order = malloc(n * sizeof *order);
    size_t *work = malloc(n * sizeof *work);
    size_t *scratch = malloc((n / 2 + 1) * sizeof *scratch);
    double *merged = merge_ties(objectives, n, m);
    if (order == NULL || work == NULL || scratch == NULL || merged == NULL) {
        free(order);
        free(work);
        free(scratch);
        free(merged);
        return out_of_memory(err, "crowding");
    }
    order_by_rank(rank, n, order, scratch);
    for (size_t start = 0; start < n;) {
        size_t end = start + 1;
        while (end < n && rank[order[end]] == rank[order[start]])
            end++;
        crowd_front(merged, m, order + start, end - start, crowding,
                    NULL, work, scratch);
        start = end;
    }
    free(order);
    free(work);
    free(scratch);
    free(merged);
    return FACET_OK;
}

/* ---- survivor selection -------------------------------------------------- */

/* Copies of a point, by larger crowding (that of their point), then
 * lower index. */
struct truncation {
    const double *crowding;
};

static int compare_copies(const void *context, size_t a, size_t b)
{
    const struct truncation *t = context;
    int c = ties_compare_normalised(t->crowding[b], t->crowding[a]);
    return c != 0 ? c : compare_index(a, b);
}

/* The pruning of one front: its distinct points, linked in the order of
 * each objective, and their crowding distances over the points left. */
struct pruning {
    const double *objectives;
    size_t m;
    size_t d;              /* distinct points */
    const size_t *point;   /* d indices into objectives */
    size_t *prev, *next;   /* m x d: neighbours by objective, or SIZE_MAX */
    double *range;         /* m: each objective's range over the front */
    double *distance;      /* d */
    bool *alive;           /* d */
};

static double pruning_distance(const struct pruning *p, size_t k)
{
    double sum = 0;
    for (size_t j = 0; j < p->m; j++) {
        size_t a = p->prev[j * p->d + k], b = p->next[j * p->d + k];
        if (a == SIZE_MAX || b == SIZE_MAX)
            return INFINITY;
        if (!(p->range[j] > 0) || isinf(p->range[j]))
            continue;
        sum += (p->objectives[p->point[b] * p->m + j] -
                p->objectives[p->point[a] * p->m + j]) / p->range[j];
    }
    return sum;
}

/* Keeps all but excess of the distinct points point[0..d) of a front
 * (excess < d), marking them in chosen: removes, one at a time, the point
 * of least crowding distance (the highest index among equals), then
 * updates the distances of its neighbours, whose gaps it widened
 * (Kukkonen and Deb 2006). Ranges stay those of the whole front. Returns
 * 0, or -1 when out of memory. */
static int prune_front(const double *objectives, size_t n, size_t m,
                       const size_t *point, size_t d, size_t excess,
                       bool *chosen)
{
    struct pruning p = {.objectives = objectives, .m = m, .d = d,
                        .point = point};
    size_t *position = malloc(n * sizeof *position);
    size_t *sorted = malloc(d * sizeof *sorted);
    size_t *scratch = malloc((d / 2 + 1) * sizeof *scratch);
    p.prev = malloc(m * d * sizeof *p.prev);
    p.next = malloc(m * d * sizeof *p.next);
    p.range = malloc(m * sizeof *p.range);
    p.distance = malloc(d * sizeof *p.distance);
    p.alive = malloc(d * sizeof *p.alive);
    int rc = -1;
    if (position == NULL || sorted == NULL || scratch == NULL ||
        p.prev == NULL || p.next == NULL || p.range == NULL ||
        p.distance == NULL || p.alive == NULL)
        goto done;

    for (size_t k = 0; k < d; k++) {
        position[point[k]] = k;
        p.alive[k] = true;
    }
    struct point_set set = {.objectives = objectives, .m = m};
    for (size_t j = 0; j < m; j++) {
        memcpy(sorted, point, d * sizeof *sorted);
        set.axis = j;
        sort_indices(sorted, d, scratch, compare_axis, &set);
        p.range[j] = objectives[sorted[d - 1] * m + j] -
                     objectives[sorted[0] * m + j];
        for (size_t r = 0; r < d; r++) {
            size_t k = position[sorted[r]];
            p.prev[j * d + k] = r > 0 ? position[sorted[r - 1]] : SIZE_MAX;
            p.next[j * d + k] = r + 1 < d ? position[sorted[r + 1]]
                                          : SIZE_MAX;
        }
    }
    for (size_t k = 0; k < d; k++)
        p.distance[k] = pruning_distance(&p, k);

    for (size_t e = 0; e < excess; e++) {
        size_t worst = SIZE_MAX;
        for (size_t k = 0; k < d; k++) {
            if (!p.alive[k])
                continue;
            int c = worst == SIZE_MAX
                        ? -1
                        : ties_compare_normalised(p.distance[k],
                                                  p.distance[worst]);
            if (c < 0 || (c == 0 && point[k] > point[worst]))
                worst = k;
        }
        p.alive[worst] = false;
        for (size_t j = 0; j < m; j++) {
            size_t a = p.prev[j * d + worst], b = p.next[j * d + worst];
            if (a != SIZE_MAX)
                p.next[j * d + a] = b;
            if (b != SIZE_MAX)
                p.prev[j * d + b] = a;
        }
        for (size_t j = 0; j < m; j++) {
            size_t a = p.prev[j * d + worst], b = p.next[j * d + worst];
            if (a != SIZE_MAX)
                p.distance[a] = pruning_distance(&p, a);
            if (b != SIZE_MAX)
                p.distance[b] = pruning_distance(&p, b);
        }
    }
    for (size_t k = 0; k < d; k++)
        if (p.alive[k])
            chosen[point[k]] = true;
    rc = 0;
done:
    free(position);
    free(sorted);
    free(scratch);
    free(p.prev);
    free(p.next);
    free(p.range);
    free(p.distance);
    free(p.alive);
    return rc;
}

/* Chooses needed (< count) of the front members[0..count) (reordered),
 * marking them in chosen: distinct points first, pruned by crowding when
 * there are too many, then copies. crowding and copy have n entries,
 * work count, scratch count / 2 + 1. */
static int select_in_front(const double *objectives, size_t n, size_t m,
                           size_t *members, size_t count, size_t needed,
                           bool *chosen, double *crowding, bool *copy,
                           size_t *work, size_t *scratch,
                           struct facet_error *err)
{
    crowd_front(objectives, m, members, count, crowding, copy, work,
                scratch);
    size_t d = 0, copies = 0;
    for (size_t k = 0; k < count; k++) {
        if (copy[members[k]])
            members[copies++] = members[k];  /* copies to the front */
        else
            work[d++] = members[k];
    }
    if (needed < d) {
        if (prune_front(objectives, n, m, work, d, d - needed, chosen) != 0)
            return out_of_memory(err, "selection");
        return FACET_OK;
    }
    for (size_t k = 0; k < d; k++)
        chosen[work[k]] = true;
    struct truncation by = {.crowding = crowding};
    sort_indices(members, copies, scratch, compare_copies, &by);
    for (size_t k = 0; k < needed - d; k++)
        chosen[members[k]] = true;
    return FACET_OK;
}

int pareto_select(const double *objectives, size_t n, size_t m,
                  const double *violation, size_t keep, size_t *selected,
                  struct facet_error *err)
{
    if (keep > n)
        return facet_error_set(err, FACET_EINPUT,
                               "pareto: cannot keep %zu of %zu points", keep,
                               n);
    int rc = check_ranked(objectives, n, m, violation, err);
    if (rc != FACET_OK)
        return rc;
    int *rank = malloc((n + 1) * sizeof *rank);
    double *crowding = malloc((n + 1) * sizeof *crowding);
    bool *copy = malloc((n + 1) * sizeof *copy);
    bool *chosen = calloc(n + 1, sizeof *chosen);
    size_t *order = malloc((n + 1) * sizeof *order);
    size_t *work = malloc((n + 1) * sizeof *work);
    size_t *scratch = malloc((n / 2 + 1) * sizeof *scratch);
    double *merged = merge_ties(objectives, n, m);
    if (rank == NULL || crowding == NULL || copy == NULL || chosen == NULL ||
        order == NULL || work == NULL || scratch == NULL || merged == NULL) {
        rc = out_of_memory(err, "selection");
        goto done;
    }
    /* Ranks, crowding and pruning all see the merged objectives. */
    objectives = merged;
    rc = rank_merged(objectives, n, m, violation, rank, NULL, err);
    if (rc != FACET_OK)
        goto done;
    order_by_rank(rank, n, order, scratch);

    size_t taken = 0, start = 0;
    while (taken < keep) {
        size_t end = start + 1;
        while (end < n && rank[order[end]] == rank[order[start]])
            end++;
        size_t size = end - start;
        if (taken + size > keep) {
            rc = select_in_front(objectives, n, m, order + start, size,
                                 keep - taken, chosen, crowding, copy, work,
                                 scratch, err);
            if (rc != FACET_OK)
                goto done;
            break;
        }
        for (size_t k = start; k < end; k++)
            chosen[order[k]] = true;
        taken += size;
        start = end;
    }
    size_t out = 0;
    for (size_t i = 0; i < n; i++)
        if (chosen[i])
            selected[out++] = i;
done:
    free(rank);
    free(crowding);
    free(copy);
    free(chosen);
    free(order);
    free(work);
    free(scratch);
    free(merged);
    return rc;
}

/* ---- hypervolume ----------------------------------------------------------
 * The helpers take count x dims points that all strictly dominate
 * reference, and return 0, or -1 when out of memory.
 */

static int volume_of(const double *points, size_t count, size_t dims,
                     const double *reference, double *volume);

/* 2-D: sort by x, and add one horizontal strip per new lowest y. */
static int volume_two(const double *points, size_t count,
                      const double *reference, double *volume)
{
    assert(count >= 1);
    size_t *order = malloc(count * sizeof *order);
    size_t *scratch = malloc((count / 2 + 1) * sizeof *scratch);
    if (order == NULL || scratch == NULL) {
        free(order);
        free(scratch);
        return -1;
    }
    struct point_set set = {.objectives = points, .m = 2};
    for (size_t k = 0; k < count; k++)
        order[k] = k;
    sort_indices(order, count, scratch, compare_lex, &set);
    double sum = 0, lowest = reference[1];
    for (size_t k = 0; k < count; k++) {
        const double *p = points + order[k] * 2;
        if (p[1] < lowest) {
            sum += (reference[0] - p[0]) * (lowest - p[1]);
            lowest = p[1];
        }
    }
    *volume = sum;
    free(order);
    free(scratch);
    return 0;
}

/* The 2-D staircase of the 3-D sweep: mutually non-dominated (x, y) with
 * x increasing (so y decreasing), and the area they dominate up to the
 * reference. */
struct staircase {
    double *x, *y;
    size_t count;
    double area;
    double reference_x, reference_y;
};

/* Adds (px, py) to the staircase, updating its area: the new point's box
 * below the left neighbour's y and left of the first point it does not
 * dominate, minus what the points it removes covered there. */
static void staircase_add(struct staircase *s, double px, double py)
{
    size_t lo = 0, hi = s->count;
    while (lo < hi) {  /* first point with x >= px */
        size_t mid = lo + (hi - lo) / 2;
        if (s->x[mid] < px)
            lo = mid + 1;
        else
            hi = mid;
    }
    size_t a = lo;
    if (a > 0 && s->y[a - 1] <= py)
        return;
    if (a < s->count && s->x[a] == px && s->y[a] <= py)
        return;
    double top = a > 0 ? s->y[a - 1] : s->reference_y;
    size_t b = a;
    while (b < s->count && s->y[b] >= py)
        b++;
    double right = b < s->count ? s->x[b] : s->reference_x;
    double covered = 0;
    for (size_t j = a; j < b; j++) {
        double next_x = j + 1 < b ? s->x[j + 1] : right;
        covered += (next_x - s->x[j]) * (top - s->y[j]);
    }
    s->area += (right - px) * (top - py) - covered;
    /* Replace [a, b) by the new point. */
    size_t tail = s->count - b;
    memmove(s->x + a + 1, s->x + b, tail * sizeof *s->x);
    memmove(s->y + a + 1, s->y + b, tail * sizeof *s->y);
    s->x[a] = px;
    s->y[a] = py;
    s->count = a + 1 + tail;
}

/* 3-D: sweep up the third objective; between consecutive heights the
 * cross-section is the staircase of the points below. */
static int volume_three(const double *points, size_t count,
                        const double *reference, double *volume)
{
    size_t *order = malloc(count * sizeof *order);
    size_t *scratch = malloc((count / 2 + 1) * sizeof *scratch);
    struct staircase s = {.x = malloc(count * sizeof(double)),
                          .y = malloc(count * sizeof(double)),
                          .reference_x = reference[0],
                          .reference_y = reference[1]};
    int rc = -1;
    if (order == NULL || scratch == NULL || s.x == NULL || s.y == NULL)
        goto done;
    struct point_set set = {.objectives = points, .m = 3, .axis = 2};
    for (size_t k = 0; k < count; k++)
        order[k] = k;
    sort_indices(order, count, scratch, compare_axis, &set);
    double sum = 0;
    for (size_t k = 0; k < count; k++) {
        const double *p = points + order[k] * 3;
        staircase_add(&s, p[0], p[1]);
        double next = k + 1 < count ? points[order[k + 1] * 3 + 2]
                                    : reference[2];
        sum += s.area * (next - p[2]);
    }
    *volume = sum;
    rc = 0;
done:
    free(order);
    free(scratch);
    free(s.x);
    free(s.y);
    return rc;
}

/* dims >= 4: slices between consecutive values of the last objective,
 * each the (dims - 1)-volume of the points below it. */
static int volume_sliced(const double *points, size_t count, size_t dims,
                         const double *reference, double *volume)
{
    assert(dims >= 4 && count >= 1);
    size_t *order = malloc(count * sizeof *order);
    size_t *scratch = malloc((count / 2 + 1) * sizeof *scratch);
    double *slice = malloc(count * (dims - 1) * sizeof *slice);
    int rc = -1;
    if (order == NULL || scratch == NULL || slice == NULL)
        goto done;
    struct point_set set = {.objectives = points, .m = dims,
                            .axis = dims - 1};
    for (size_t k = 0; k < count; k++)
        order[k] = k;
    sort_indices(order, count, scratch, compare_axis, &set);
    double sum = 0;
    for (size_t k = 0; k < count; k++) {
        const double *p = points + order[k] * dims;
        memcpy(slice + k * (dims - 1), p, (dims - 1) * sizeof *slice);
        double next = k + 1 < count ? points[order[k + 1] * dims + dims - 1]
                                    : reference[dims - 1];
        if (next > p[dims - 1]) {
            double area;
            if (volume_of(slice, k + 1, dims - 1, reference, &area) != 0)
                goto done;
            sum += area * (next - p[dims - 1]);
        }
    }
    *volume = sum;
    rc = 0;
done:
    free(order);
    free(scratch);
    free(slice);
    return rc;
}

static int volume_of(const double *points, size_t count, size_t dims,
                     const double *reference, double *volume)
{
    *volume = 0;
    if (count == 0)
        return 0;
    if (dims == 1) {
        double low = points[0];
        for (size_t k = 1; k < count; k++)
            if (points[k] < low)
                low = points[k];
        *volume = reference[0] - low;
        return 0;
    }
    if (dims == 2)
        return volume_two(points, count, reference, volume);
    if (dims == 3)
        return volume_three(points, count, reference, volume);
    return volume_sliced(points, count, dims, reference, volume);
}

int pareto_hypervolume(const double *objectives, size_t n, size_t m,
                       const double *reference, double *volume,
                       struct facet_error *err)
{
    *volume = 0;
    int rc = check_objectives(objectives, n, m, err);
    if (rc != FACET_OK)
        return rc;
    for (size_t j = 0; j < m; j++)
        if (isnan(reference[j]))
            return facet_error_set(err, FACET_EINPUT,
                                   "pareto: reference objective %zu is NaN",
                                   j);
    double *inside = malloc((n + 1) * m * sizeof *inside);
    if (inside == NULL)
        return out_of_memory(err, "hypervolume");
    size_t count = 0;
    for (size_t i = 0; i < n; i++) {
        const double *p = objectives + i * m;
        size_t j = 0;
        while (j < m && p[j] < reference[j])
            j++;
        if (j == m)
            memcpy(inside + m * count++, p, m * sizeof *p);
    }
    if (volume_of(inside, count, m, reference, volume) != 0)
        rc = out_of_memory(err, "hypervolume");
    free(inside);
    return rc;
}

void pareto_normalize(const double *objectives, size_t n, size_t m,
                      const double *ideal, const double *nadir, double *out)
{
    assert(m >= 1 || n == 0);
    for (size_t i = 0; i < n; i++)
        for (size_t j = 0; j < m; j++) {
            double range = nadir[j] - ideal[j];
            out[i * m + j] = range != 0
                ? (objectives[i * m + j] - ideal[j]) / range : 0.0;
        }
}

int pareto_hypervolume_normalized(const double *objectives, size_t n,
                                  size_t m, const double *ideal,
                                  const double *nadir, double *volume,
                                  struct facet_error *err)
{
    *volume = 0;
    if (m == 0)
        return facet_error_set(err, FACET_EINPUT, "pareto: no objectives");
    double *scaled = malloc((n * m + 1) * sizeof *scaled);
    double *reference = malloc(m * sizeof *reference);
    int rc;
    if (scaled == NULL || reference == NULL) {
        rc = out_of_memory(err, "hypervolume");
    } else {
        pareto_normalize(objectives, n, m, ideal, nadir, scaled);
        for (size_t j = 0; j < m; j++)
            reference[j] = PARETO_NORMALIZED_REFERENCE;
        rc = pareto_hypervolume(scaled, n, m, reference, volume, err);
    }
    free(scaled);
    free(reference);
    return rc;
}

/* ---- knee ---------------------------------------------------------------- */

int pareto_knee(const double *objectives, size_t n, size_t m,
                const int *rank, size_t *knee, struct facet_error *err)
{
    int rc = check_objectives(objectives, n, m, err);
    if (rc != FACET_OK)
        return rc;
    double *low = malloc(m * sizeof *low);
    double *high = malloc(m * sizeof *high);
    double *merged = merge_ties(objectives, n, m);
    if (low == NULL || high == NULL || merged == NULL) {
        free(low);
        free(high);
        free(merged);
        return out_of_memory(err, "knee");
    }
    objectives = merged;
    size_t first = SIZE_MAX;
    for (size_t i = 0; i < n; i++) {
        if (rank[i] != 1)
            continue;
        for (size_t j = 0; j < m; j++) {
            double f = objectives[i * m + j];
            if (first == SIZE_MAX || f < low[j])
                low[j] = f;
            if (first == SIZE_MAX || f > high[j])
                high[j] = f;
        }
        if (first == SIZE_MAX)
            first = i;
    }
    if (first == SIZE_MAX) {
        free(low);
        free(high);
        free(merged);
        return facet_error_set(err, FACET_EINPUT,
                               "pareto: no point of rank 1 for a knee");
    }
    double best = INFINITY;
    *knee = first;
    for (size_t i = 0; i < n; i++) {
        if (rank[i] != 1)
            continue;
        double distance = 0;
        for (size_t j = 0; j < m; j++) {
            double range = high[j] - low[j];
            double d = range > 0 ? (objectives[i * m + j] - low[j]) / range
                                 : 0.0;
            distance += d * d;
        }
        /* Options at the same distance but for rounding (mirror images)
         * go to the lower index. */
        if (best == INFINITY || ties_compare_normalised(distance, best) < 0) {
            best = distance;
            *knee = i;
        }
    }
    free(low);
    free(high);
    free(merged);
    return FACET_OK;
}
