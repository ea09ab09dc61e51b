/*
 * optimize.c: the search driver: design space, the point cache, parallel
 * batch evaluation, and the exhaustive and random methods. NSGA-II's
 * generations come through the same batches (optimize_nsga2.c).
 */
#include "core/evaluate/evaluate.h"
#include "core/search/optimize.h"

#include <assert.h>
#include <math.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/base/numrange.h"
#include "core/base/parallel.h"
#include "core/fit/sp_fit.h"
#include "core/joint/joint_length.h"
#include "core/search/optimize_internal.h"
#include "core/base/rng.h"

const char *optimize_method_name(enum optimize_method method)
{
    switch (method) {
    case METHOD_EXHAUSTIVE: return "exhaustive";
    case METHOD_RANDOM:     return "random";
    default:                return "nsga2";
    }
}

int optimize_method_parse(const char *text, const char *what,
                          enum optimize_method *out,
                          struct facet_error *err)
{
    static const enum optimize_method all[] = {METHOD_EXHAUSTIVE,
                                               METHOD_RANDOM, METHOD_NSGA2};
    for (int k = 0; k < 3; k++)
        if (strcmp(text, optimize_method_name(all[k])) == 0) {
            *out = all[k];
            return FACET_OK;
        }
    return facet_error_set(err, FACET_EINPUT,
        "%s: '%s' unknown (choose exhaustive, random or nsga2)", what,
        text);
}

/* Threshold steps of an exhaustive space: t_min, t_min + step, ... up to
 * t_max, forgiving a thousandth of a step of rounding. */
#define THRESHOLD_SLACK 1e-3

static uint64_t threshold_steps(const struct design_space *s)
{
    return (uint64_t)numrange_count(s->t_min_mm, s->t_max_mm, s->t_step_mm,
                                    THRESHOLD_SLACK);
}

uint64_t design_space_size(const struct design_space *s)
{
    return (uint64_t)(s->u_max - s->u_min + 1) *
           (uint64_t)(s->v_max - s->v_min + 1) * threshold_steps(s);
}

double design_space_mean_panels(const struct design_space *s)
{
    return (s->u_min + s->u_max) / 2.0 * ((s->v_min + s->v_max) / 2.0);
}

/* The ranges of a design space as a designer types them (numrange.h). */
static const struct numrange_spec sides_spec = {
    .whole = 1, .least = 1, .most = PANEL_MAX_GRID,
};

static const struct numrange_spec threshold_spec = {
    .whole = 0, .least = 0, .most = CLASSIFY_THRESHOLD_MAX_MM, .stepped = 1,
    .slack = THRESHOLD_SLACK, .values_max = DESIGN_THRESHOLD_STEPS_MAX,
};

int design_space_parse_sides(const char *text, const char *what, int *lo,
                             int *hi, struct facet_error *err)
{
    struct numrange r;
    int rc = numrange_parse(text, text + strlen(text), &sides_spec, what, &r,
                            err);
    if (rc != FACET_OK)
        return rc;
    *lo = (int)r.min;
    *hi = (int)r.max;
    return FACET_OK;
}

int design_space_parse_threshold(const char *text, const char *what,
                                 struct design_space *space,
                                 struct facet_error *err)
{
    struct numrange r;
    int rc = numrange_parse(text, text + strlen(text), &threshold_spec, what,
                            &r, err);
    if (rc != FACET_OK)
        return rc;
    space->t_min_mm = r.min;
    space->t_max_mm = r.max;
    space->t_step_mm = r.step;
    return FACET_OK;
}

static const struct design_space_names plain_names = {"u", "v",
                                                       "threshold"};

int design_space_check(const struct design_space *s,
                       const struct design_space_names *names,
                       struct facet_error *err)
{
    if (names == NULL)
        names = &plain_names;
    if (s->u_min < 1 || s->u_max < s->u_min || s->u_max > PANEL_MAX_GRID)
        return facet_error_set(err, FACET_EINPUT,
            "%s %d:%d is not a range within 1..%d", names->u, s->u_min,
            s->u_max,
            PANEL_MAX_GRID);
    if (s->v_min < 1 || s->v_max < s->v_min || s->v_max > PANEL_MAX_GRID)
        return facet_error_set(err, FACET_EINPUT,
            "%s %d:%d is not a range within 1..%d", names->v, s->v_min,
            s->v_max,
            PANEL_MAX_GRID);
    if (!isfinite(s->t_min_mm) || !isfinite(s->t_max_mm) ||
        s->t_min_mm < 0 || s->t_max_mm < s->t_min_mm ||
        !isfinite(s->t_step_mm) || s->t_step_mm < 0)
        return facet_error_set(err, FACET_EINPUT,
            "%s %g:%g:%g is not a range of lengths (mm)",
            names->threshold, s->t_min_mm, s->t_max_mm, s->t_step_mm);
    /* Counted in floating point first: 1e6 / 1e-300 steps does not fit a
     * count, and must not wrap into one. */
    if (s->t_step_mm > 0 && s->t_max_mm > s->t_min_mm) {
        double steps = numrange_count(s->t_min_mm, s->t_max_mm, s->t_step_mm,
                                      THRESHOLD_SLACK);
        if (!(steps <= DESIGN_THRESHOLD_STEPS_MAX))
            return facet_error_set(err, FACET_EINPUT,
                "%s %g:%g:%g is %.3g steps (at most %d: take a "
                "larger step, or a continuous range A:B with nsga2)",
                names->threshold, s->t_min_mm, s->t_max_mm, s->t_step_mm, steps,
                DESIGN_THRESHOLD_STEPS_MAX);
    }
    return FACET_OK;
}

int optimize_method_check(enum optimize_method method,
                          const struct design_space *s,
                          const struct design_space_names *names,
                          struct facet_error *err)
{
    if (names == NULL)
        names = &plain_names;
    if (method == METHOD_EXHAUSTIVE && s->t_max_mm > s->t_min_mm &&
        s->t_step_mm == 0)
        return facet_error_set(err, FACET_EINPUT,
            "%s %g:%g: the exhaustive method needs a step (e.g. %g:%g:0.5)",
            names->threshold, s->t_min_mm, s->t_max_mm, s->t_min_mm,
            s->t_max_mm);
    return FACET_OK;
}

/* --- parallel evaluation --- */

/* The points of a batch in the order they are evaluated (by grid), cut
 * into groups of one grid each, which the jobs take in turn. */
struct evaluation_plan {
    const struct surface *surface;
    const struct panel_lattice *lattice;  /* or NULL */
    const struct joint_lines *lines;      /* or NULL */
    const struct option_params *base;
    const struct design_point *points;
    const size_t *order;            /* the points by grid */
    const size_t *group;            /* ngroups + 1: group g is
                                       order[group[g] .. group[g + 1]) */
    size_t ngroups;
    atomic_size_t next;             /* the next group not taken */
    struct option_totals *totals;
    struct panelization *keep;      /* NULL, or every point's panels (its
                                       own group each) */
    const struct facet_stop *stop;  /* asked before each point and inside
                                       its evaluation; NULL: never */
};

struct evaluation_job {
    struct evaluation_plan *plan;
    int rc;
    struct facet_error err;
};

/* Evaluates groups until none is left or one fails. A group's grid is
 * panelized once: its other points (only the threshold differs) have the
 * same panels, which are only classified anew. */
static void evaluation_thread(void *argument)
{
    struct evaluation_job *job = argument;
    struct evaluation_plan *plan = job->plan;
    for (;;) {
        size_t g = atomic_fetch_add(&plan->next, 1);
        if (g >= plan->ngroups)
            break;
        struct panelization panels;
        /* A grid of several thresholds keeps its SP fits and sides for
         * all of them (the same results, to the bit); a grid of one does
         * without, as it would only sample sides it does not need. */
        struct grid_fits fits;
        memset(&fits, 0, sizeof fits);
        int kept = plan->group[g + 1] - plan->group[g] > 1;
        for (size_t x = plan->group[g]; x < plan->group[g + 1]; x++) {
            size_t k = plan->order[x];
            struct option_params params = option_params_at(
                plan->base, plan->points[k].nu, plan->points[k].nv,
                plan->points[k].threshold_mm);
            struct evaluation_shared shared = {
                .lattice = plan->lattice, .lines = plan->lines,
                .fits = kept ? &fits : NULL, .stop = plan->stop};
            if (x > plan->group[g]) {
                /* Same grid, same joints: measured with its first point. */
                shared.again = 1;
                shared.joint_length =
                    plan->totals[plan->order[plan->group[g]]].joint_length;
            }
            job->rc = facet_stop_check(plan->stop, &job->err);
            if (job->rc == FACET_OK)
                job->rc = option_evaluate(plan->surface, &params, &shared,
                                          &panels, &plan->totals[k],
                                          &job->err);
            if (job->rc != FACET_OK)
                break;
        }
        grid_fits_free(&fits);
        if (plan->keep != NULL && job->rc == FACET_OK) {
            plan->keep[plan->order[plan->group[g]]] = panels;
            memset(&panels, 0, sizeof panels);
        }
        panelization_free(&panels);
        if (job->rc != FACET_OK) {
            atomic_store(&plan->next, plan->ngroups);  /* the others stop */
            break;
        }
    }
}

/* A point's place in the order of evaluation: by grid, then index. */
struct grid_key {
    int nu, nv;
    size_t index;
};

static int compare_by_grid(const void *a, const void *b)
{
    const struct grid_key *p = a, *q = b;
    if (p->nu != q->nu)
        return p->nu < q->nu ? -1 : 1;
    if (p->nv != q->nv)
        return p->nv < q->nv ? -1 : 1;
    return p->index < q->index ? -1 : p->index > q->index;
}

static int compare_ints(const void *a, const void *b)
{
    int x = *(const int *)a, y = *(const int *)b;
    return (x > y) - (x < y);
}

/* Sorts the grid sides side[0..n) and keeps each value once, first;
 * returns how many. */
static size_t distinct_sides(int *side, size_t n)
{
    qsort(side, n, sizeof *side, compare_ints);
    size_t distinct = 0;
    for (size_t k = 0; k < n; k++)
        if (distinct == 0 || side[k] != side[distinct - 1])
            side[distinct++] = side[k];
    return distinct;
}

/* The joint lines of a batch's grids: the first point of each group. */
static int batch_joint_lines(const struct surface *surface,
                             const struct design_point *points,
                             const size_t *order, const size_t *group,
                             size_t ngroups, int jobs,
                             struct joint_lines *out, struct facet_error *err)
{
    int *side[2] = {malloc(ngroups * sizeof(int)),
                    malloc(ngroups * sizeof(int))};
    if (side[0] == NULL || side[1] == NULL) {
        free(side[0]);
        free(side[1]);
        return facet_error_set(err, FACET_EWORK, "out of memory");
    }
    for (size_t g = 0; g < ngroups; g++) {
        side[0][g] = points[order[group[g]]].nu;
        side[1][g] = points[order[group[g]]].nv;
    }
    size_t nsides[2] = {distinct_sides(side[0], ngroups),
                        distinct_sides(side[1], ngroups)};
    int rc = joint_lines_build(&surface->joints, &surface->mesh,
                               &surface->uv, (const int *const *)side, nsides,
                               jobs, out, err);
    free(side[0]);
    free(side[1]);
    if (rc != FACET_OK)
        joint_lines_free(out);
    return rc;
}

/* optimize_evaluate, and with keep, optimize_evaluate_panels; the joint
 * lengths from lines (NULL: measured for the batch when a lattice says
 * its grids share lines). */
static int evaluate(const struct surface *surface,
                    const struct panel_lattice *lattice,
                    const struct joint_lines *lines,
                    const struct option_params *base,
                    const struct design_point *points, size_t n, int jobs,
                    const struct facet_stop *stop,
                    struct option_totals *totals, struct panelization *keep,
                    struct facet_error *err)
{
    if (jobs < 1)
        jobs = 1;
    if (jobs > PARALLEL_MAX)
        jobs = PARALLEL_MAX;
    /* Points that share a grid make one group, panelized once for all
     * their thresholds. Already ordered (exhaustive: thresholds innermost)
     * is kept as is. */
    size_t *order = malloc((n ? n : 1) * sizeof *order);
    size_t *group = malloc((n + 1) * sizeof *group);
    struct grid_key *key = malloc((n ? n : 1) * sizeof *key);
    if (order == NULL || group == NULL || key == NULL) {
        free(order);
        free(group);
        free(key);
        return facet_error_set(err, FACET_EWORK, "out of memory");
    }
    int sorted = 1;
    for (size_t k = 0; k < n; k++) {
        key[k] = (struct grid_key){points[k].nu, points[k].nv, k};
        if (k > 0 && compare_by_grid(&key[k - 1], &key[k]) > 0)
            sorted = 0;
    }
    if (!sorted && keep == NULL)
        qsort(key, n, sizeof *key, compare_by_grid);
    size_t ngroups = 0;
    for (size_t k = 0; k < n; k++) {
        order[k] = key[k].index;
        /* Kept panels are each point's own: one group a point. */
        if (k == 0 || keep != NULL || key[k].nu != key[k - 1].nu ||
            key[k].nv != key[k - 1].nv)
            group[ngroups++] = k;
    }
    group[ngroups] = n;
    free(key);
    /* Grids that share a lattice share lines: their joints are measured
     * once a line for the batch, unless the run's lines are given. */
    struct joint_lines batch_lines;
    memset(&batch_lines, 0, sizeof batch_lines);
    if (lines == NULL && lattice != NULL && ngroups > 1 &&
        !(base->unmeasured & OPTION_MEASURE_JOINT_LENGTH)) {
        int rc = batch_joint_lines(surface, points, order, group, ngroups,
                                   jobs, &batch_lines, err);
        if (rc != FACET_OK) {
            free(order);
            free(group);
            return rc;
        }
        lines = &batch_lines;
    }
    if ((size_t)jobs > ngroups)
        jobs = ngroups > 0 ? (int)ngroups : 1;

    if (keep != NULL && n > 0)
        memset(keep, 0, n * sizeof *keep);
    struct evaluation_plan plan = {surface, lattice, lines, base, points,
                                   order, group, ngroups, 0, totals, keep,
                                   stop};
    atomic_init(&plan.next, 0);
    struct evaluation_job job[PARALLEL_MAX];
    for (int k = 0; k < jobs; k++)
        job[k] = (struct evaluation_job){&plan, FACET_OK, {0, FACET_SETTING_NONE, "", ""}};
    parallel_run(job, sizeof job[0], jobs, evaluation_thread);
    joint_lines_free(&batch_lines);
    free(order);
    free(group);
    /* A job's own failure is the one told, before another's stop. */
    int failed = -1;
    for (int k = 0; k < jobs; k++)
        if (job[k].rc != FACET_OK &&
            (failed < 0 || job[failed].rc == FACET_ESTOP))
            failed = k;
    if (failed < 0)
        return FACET_OK;
    if (err != NULL)
        *err = job[failed].err;
    for (size_t p = 0; keep != NULL && p < n; p++)
        panelization_free(&keep[p]);
    return job[failed].rc;
}

int optimize_evaluate(const struct surface *surface,
                      const struct panel_lattice *lattice,
                      const struct option_params *base,
                      const struct design_point *points, size_t n, int jobs,
                      struct option_totals *totals, struct facet_error *err)
{
    return evaluate(surface, lattice, NULL, base, points, n, jobs, NULL,
                    totals, NULL, err);
}

int optimize_evaluate_panels(const struct surface *surface,
                             const struct panel_lattice *lattice,
                             const struct option_params *base,
                             const struct design_point *points, size_t n,
                             int jobs, const struct facet_stop *stop,
                             struct panelization *panels,
                             struct option_totals *totals,
                             struct facet_error *err)
{
    return evaluate(surface, lattice, NULL, base, points, n, jobs, stop,
                    totals, panels, err);
}

/* --- the point cache and batches --- */

/* The finest step of a threshold, per millimetre: a design space's
 * thresholds, and the points a search tells apart, are on a grid of
 * micrometres. */
#define THRESHOLD_STEPS_PER_MM 1000

/* The threshold as design points are told apart by: in steps of the
 * grid. */
static long long threshold_key(double threshold_mm)
{
    return llround(threshold_mm * THRESHOLD_STEPS_PER_MM);
}

double design_point_threshold_on_grid(double threshold_mm)
{
    return round(threshold_mm * THRESHOLD_STEPS_PER_MM) /
           THRESHOLD_STEPS_PER_MM;
}

uint64_t design_point_hash(const struct design_point *p)
{
    uint64_t h = (uint64_t)p->nu * 0x9E3779B97F4A7C15ull;
    h ^= (uint64_t)p->nv * 0xC2B2AE3D27D4EB4Full + (h << 6);
    h ^= (uint64_t)threshold_key(p->threshold_mm) * 0x165667B19E3779F9ull;
    return h ^ (h >> 31);
}

int design_point_compare(const struct design_point *a,
                         const struct design_point *b)
{
    if (a->nu != b->nu)
        return a->nu < b->nu ? -1 : 1;
    if (a->nv != b->nv)
        return a->nv < b->nv ? -1 : 1;
    long long ta = threshold_key(a->threshold_mm);
    long long tb = threshold_key(b->threshold_mm);
    return (ta > tb) - (ta < tb);
}

static int same_point(const struct design_point *a,
                      const struct design_point *b)
{
    return design_point_compare(a, b) == 0;
}

int search_init(struct search *s, const struct option_evaluator *evaluator,
                const struct optimize_settings *settings,
                const struct evaluated_option *stored, size_t nstored,
                const struct optimize_hooks *hooks, int64_t total,
                struct facet_error *err)
{
    memset(s, 0, sizeof *s);
    s->evaluator = evaluator;
    s->settings = settings;
    s->hooks = hooks;
    s->total = total;
    s->capacity = 1024;
    while (s->capacity < 2 * (nstored + 1))
        s->capacity *= 2;
    s->slot = malloc(s->capacity * sizeof *s->slot);
    s->known_capacity = nstored + 256;
    s->known = malloc(s->known_capacity * sizeof *s->known);
    s->met = calloc(s->known_capacity, 1);
    if (s->slot == NULL || s->known == NULL || s->met == NULL)
        return facet_error_set(err, FACET_EWORK, "out of memory (search)");
    for (size_t k = 0; k < s->capacity; k++)
        s->slot[k] = SIZE_MAX;
    for (size_t k = 0; k < nstored; k++) {
        s->known[s->nknown] = stored[k];
        size_t h = design_point_hash(&stored[k].point) & (s->capacity - 1);
        while (s->slot[h] != SIZE_MAX)
            h = (h + 1) & (s->capacity - 1);
        s->slot[h] = s->nknown++;
    }
    return FACET_OK;
}

void search_free(struct search *s)
{
    free(s->slot);
    free(s->known);
    free(s->met);
    memset(s, 0, sizeof *s);
}

void search_canonical(const struct search *s, struct design_point *p)
{
    if (s->evaluator->canonical != NULL)
        s->evaluator->canonical(s->evaluator->context, p);
}

/* The index into known of point p, or SIZE_MAX. */
static size_t search_find(const struct search *s, const struct design_point *p)
{
    size_t h = design_point_hash(p) & (s->capacity - 1);
    while (s->slot[h] != SIZE_MAX) {
        if (same_point(&s->known[s->slot[h]].point, p))
            return s->slot[h];
        h = (h + 1) & (s->capacity - 1);
    }
    return SIZE_MAX;
}

/* Makes room for more known options and keeps the hash under half full. */
static int search_grow(struct search *s, size_t more, struct facet_error *err)
{
    if (s->nknown + more > s->known_capacity) {
        size_t capacity = 2 * (s->nknown + more);
        struct evaluated_option *known = realloc(s->known,
                                                 capacity * sizeof *known);
        if (known != NULL)
            s->known = known;
        unsigned char *met = realloc(s->met, capacity);
        if (known == NULL || met == NULL)
            return facet_error_set(err, FACET_EWORK, "out of memory");
        memset(met + s->known_capacity, 0, capacity - s->known_capacity);
        s->met = met;
        s->known_capacity = capacity;
    }
    if (2 * (s->nknown + more) > s->capacity) {
        size_t capacity = s->capacity;
        while (2 * (s->nknown + more) > capacity)
            capacity *= 2;
        size_t *slot = malloc(capacity * sizeof *slot);
        if (slot == NULL)
            return facet_error_set(err, FACET_EWORK, "out of memory");
        for (size_t k = 0; k < capacity; k++)
            slot[k] = SIZE_MAX;
        for (size_t k = 0; k < s->nknown; k++) {
            size_t h = design_point_hash(&s->known[k].point) & (capacity - 1);
            while (slot[h] != SIZE_MAX)
                h = (h + 1) & (capacity - 1);
            slot[h] = k;
        }
        free(s->slot);
        s->slot = slot;
        s->capacity = capacity;
    }
    return FACET_OK;
}

/* The work of evaluating p, in panels (struct optimize_progress): nu x nv
 * of a single surface's grid; 1 for a project's option, whose nu and nv
 * index its module. */
static double point_work(const struct search *s, const struct design_point *p)
{
    if (s->evaluator->canonical != NULL)
        return 1;
    return (double)p->nu * (double)p->nv;
}

/* Tells the progress hook that done options, of work_done panels, are met. */
static void search_report(const struct search *s, int64_t done,
                          double work_done)
{
    if (s->hooks->progress == NULL)
        return;
    struct optimize_progress p;
    p.done = done < s->total ? done : s->total;
    p.total = s->total;
    p.work_done = work_done;
    double to_come = (double)(s->total - p.done) * s->work_each;
    p.work_total = s->work_exact > 0 ? s->work_exact : work_done + to_come;
    if (p.work_total < work_done)
        p.work_total = work_done;
    s->hooks->progress(s->hooks->context, &p);
}

static int same_grid(const struct design_point *a,
                     const struct design_point *b)
{
    return a->nu == b->nu && a->nv == b->nv;
}

/* Points evaluated and stored together: enough to keep every thread
 * busy, few enough that an interruption loses little and progress moves. */
static size_t batch_size(const struct optimize_settings *settings)
{
    size_t size = 8 * (size_t)(settings->jobs > 0 ? settings->jobs : 1);
    return size < 16 ? 16 : size;
}

static int stop_requested(const struct optimize_hooks *hooks)
{
    return hooks->should_stop != NULL && hooks->should_stop(hooks->context);
}

/* Evaluates the new options known[first .. first + n) and hands them to
 * the store hook in chunks of batch_size (a grid's thresholds kept in one
 * chunk, which panelizes it once), the stop asked before each chunk and
 * inside its evaluation: a generation of NSGA-II of fine grids takes
 * minutes, and a stop must neither wait for it nor lose the chunks
 * stored. FACET_ESTOP when the stop fired: the chunk it interrupted is
 * dropped whole, nothing of it stored. */
static int search_evaluate(struct search *s, size_t first, size_t n,
                           struct facet_error *err)
{
    if (n == 0)
        return FACET_OK;
    size_t size = batch_size(s->settings);
    struct facet_stop stop = {s->hooks->should_stop, s->hooks->context};
    struct design_point *points = malloc((n < size ? n : size) *
                                         sizeof *points);
    struct option_totals *totals = malloc((n < size ? n : size) *
                                          sizeof *totals);
    int rc = FACET_OK;
    if (points == NULL || totals == NULL)
        rc = facet_error_set(err, FACET_EWORK, "out of memory");
    double work = s->work_done;
    for (size_t at = 0; rc == FACET_OK && at < n;) {
        struct evaluated_option *chunk = s->known + first + at;
        size_t count = 0;
        while (at + count < n && count < size) {
            points[count] = chunk[count].point;
            count++;
        }
        /* A grid cut by the chunk's end goes whole into the next one,
         * unless it fills the chunk alone. */
        if (at + count < n) {
            size_t cut = count;
            while (cut > 0 && same_grid(&chunk[cut - 1].point,
                                        &chunk[count].point))
                cut--;
            if (cut > 0)
                count = cut;
        }
        if (stop_requested(s->hooks)) {
            rc = facet_stop_error(err);
            break;
        }
        rc = s->evaluator->evaluate(s->evaluator->context,
                                    &s->settings->base, points, count,
                                    s->settings->jobs, &stop, totals, err);
        for (size_t k = 0; rc == FACET_OK && k < count; k++) {
            chunk[k].totals = totals[k];
            work += point_work(s, &chunk[k].point);
        }
        if (rc == FACET_OK && s->hooks->store != NULL)
            rc = s->hooks->store(s->hooks->context, chunk, count, err);
        at += count;
        if (rc == FACET_OK && at < n)
            search_report(s, s->done + (int64_t)at, work);
    }
    free(points);
    free(totals);
    return rc;
}

int search_batch(struct search *s, const struct design_point *points,
                 size_t n, int generation, size_t *index,
                 const int64_t *numbers, struct facet_error *err)
{
    int rc = search_grow(s, n, err);
    if (rc != FACET_OK)
        return rc;
    size_t first_new = s->nknown;
    for (size_t k = 0; k < n; k++) {
        struct design_point point = points[k];
        search_canonical(s, &point);
        size_t found = search_find(s, &point);
        if (found == SIZE_MAX) {
            struct evaluated_option *o = &s->known[s->nknown];
            memset(o, 0, sizeof *o);
            o->point = point;
            o->generation = generation;
            size_t h = design_point_hash(&point) & (s->capacity - 1);
            while (s->slot[h] != SIZE_MAX)
                h = (h + 1) & (s->capacity - 1);
            s->slot[h] = found = s->nknown++;
        }
        if (!s->met[found]) {
            /* The k-th distinct point met is option k, in a resumed pass
             * as in the first: a stored option keeps the number it got. */
            s->met[found] = 1;
            s->distinct_met++;
            if (found >= first_new)
                s->known[found].number = numbers != NULL ? numbers[k]
                                                         : s->distinct_met;
        }
        index[k] = found;
    }
    size_t fresh = s->nknown - first_new;
    rc = search_evaluate(s, first_new, fresh, err);
    if (rc != FACET_OK)
        return rc;
    s->done += (int64_t)n;
    for (size_t k = 0; k < n; k++)
        s->work_done += point_work(s, &s->known[index[k]].point);
    search_report(s, s->done, s->work_done);
    return FACET_OK;
}

/* --- exhaustive and random --- */

int search_stopped(enum optimize_outcome *outcome, struct facet_error *err)
{
    *outcome = OPTIMIZE_INTERRUPTED;
    facet_error_clear(err);
    return FACET_OK;
}

/* The grids an exhaustive walk evaluates, each distinct option's once:
 * of a single surface every grid of the space, in its order (nu and nv
 * NULL: computed from the index); of an evaluator with a canonical hook
 * (a project's modules) the distinct canonical grids, in the order the
 * walk (u outermost, then v) first meets them. Thresholds do not change
 * under the hook, so a grid's thresholds are all met together, the first
 * time its grid is: grid g's are options g x steps + 1 .. (g + 1) x
 * steps, in a whole run as in every shard. */
struct exhaustive_grids {
    const struct design_space *space;
    int *nu, *nv;        /* n of them; NULL: every grid of the space */
    uint64_t n;
};

static void exhaustive_grids_free(struct exhaustive_grids *g)
{
    free(g->nu);
    free(g->nv);
    memset(g, 0, sizeof *g);
}

static int exhaustive_grids_init(const struct option_evaluator *evaluator,
                                 const struct design_space *space,
                                 struct exhaustive_grids *g,
                                 struct facet_error *err)
{
    memset(g, 0, sizeof *g);
    g->space = space;
    size_t us = (size_t)(space->u_max - space->u_min + 1);
    size_t vs = (size_t)(space->v_max - space->v_min + 1);
    if (evaluator == NULL || evaluator->canonical == NULL) {
        g->n = (uint64_t)us * vs;
        return FACET_OK;
    }
    unsigned char *seen = calloc(us * vs, 1);
    g->nu = malloc(us * vs * sizeof *g->nu);
    g->nv = malloc(us * vs * sizeof *g->nv);
    if (seen == NULL || g->nu == NULL || g->nv == NULL) {
        free(seen);
        exhaustive_grids_free(g);
        return facet_error_set(err, FACET_EWORK, "out of memory");
    }
    for (int u = space->u_min; u <= space->u_max; u++)
        for (int v = space->v_min; v <= space->v_max; v++) {
            struct design_point p = {u, v, space->t_min_mm};
            evaluator->canonical(evaluator->context, &p);
            assert(p.nu >= space->u_min && p.nu <= space->u_max &&
                   p.nv >= space->v_min && p.nv <= space->v_max);
            size_t at = (size_t)(p.nu - space->u_min) * vs +
                        (size_t)(p.nv - space->v_min);
            if (seen[at])
                continue;
            seen[at] = 1;
            g->nu[g->n] = p.nu;
            g->nv[g->n++] = p.nv;
        }
    free(seen);
    return FACET_OK;
}

/* Point number point (0-based) of the walk over g. */
static void exhaustive_point(const struct exhaustive_grids *g,
                             uint64_t point, struct design_point *p)
{
    const struct design_space *space = g->space;
    uint64_t steps = threshold_steps(space);
    uint64_t grid = point / steps;
    p->threshold_mm = space->t_min_mm + (double)(point % steps) *
                                            space->t_step_mm;
    if (p->threshold_mm > space->t_max_mm)
        p->threshold_mm = space->t_max_mm;
    if (g->nu != NULL) {
        p->nu = g->nu[grid];
        p->nv = g->nv[grid];
    } else {
        uint64_t nv = (uint64_t)(space->v_max - space->v_min + 1);
        p->nv = space->v_min + (int)(grid % nv);
        p->nu = space->u_min + (int)(grid / nv);
    }
}

/* The points of the walk over grids that shard evaluates. */
static int64_t exhaustive_total(const struct exhaustive_grids *grids,
                                const struct shard *shard)
{
    return (int64_t)shard_grid_points(grids->n,
                                      threshold_steps(grids->space), shard);
}

static int run_exhaustive(struct search *s,
                          const struct exhaustive_grids *grids,
                          enum optimize_outcome *outcome,
                          struct facet_error *err)
{
    const struct optimize_settings *settings = s->settings;
    int rc = FACET_OK;
    uint64_t steps = threshold_steps(&settings->space);
    uint64_t total = grids->n * steps;
    size_t size = batch_size(settings);
    struct design_point *points = malloc(size * sizeof *points);
    size_t *index = malloc(size * sizeof *index);
    int64_t *numbers = malloc(size * sizeof *numbers);
    if (points == NULL || index == NULL || numbers == NULL)
        rc = facet_error_set(err, FACET_EWORK, "out of memory");
    /* Option k + 1 is point k of the walk, in a shard as in the whole
     * run: a shard's options keep their numbers in the whole run. */
    uint64_t next = 0;
    while (rc == FACET_OK && next < total) {
        if (stop_requested(s->hooks)) {
            *outcome = OPTIMIZE_INTERRUPTED;
            break;
        }
        size_t n = 0;
        for (; n < size && next < total; next++)
            if (shard_owns(&settings->shard,
                           shard_grid_unit(grids->n, steps,
                                           &settings->shard, next))) {
                exhaustive_point(grids, next, &points[n]);
                numbers[n++] = (int64_t)next + 1;
            }
        if (n > 0)
            rc = search_batch(s, points, n, 0, index, numbers, err);
    }
    if (rc == FACET_ESTOP)
        rc = search_stopped(outcome, err);
    free(points);
    free(index);
    free(numbers);
    return rc;
}

/* A random point of the space; a continuous threshold is drawn to a
 * thousandth of a millimetre, the resolution points are told apart by. */
static void random_point(const struct design_space *space, struct rng *rng,
                         struct design_point *p)
{
    p->nu = space->u_min + (int)rng_below(rng, (uint64_t)(space->u_max -
                                                          space->u_min + 1));
    p->nv = space->v_min + (int)rng_below(rng, (uint64_t)(space->v_max -
                                                          space->v_min + 1));
    if (space->t_step_mm > 0) {
        uint64_t steps = threshold_steps(space);
        p->threshold_mm = space->t_min_mm +
                          (double)rng_below(rng, steps) * space->t_step_mm;
    } else {
        double t = space->t_min_mm +
                   rng_uniform(rng) * (space->t_max_mm - space->t_min_mm);
        p->threshold_mm = design_point_threshold_on_grid(t);
    }
}

/* The distinct points a random run has drawn, in every shard's share or
 * not: what tells a repeated draw. */
struct drawn_set {
    struct design_point *point;
    unsigned char *used;
    size_t capacity, count;      /* capacity a power of two */
};

static void drawn_free(struct drawn_set *d)
{
    free(d->point);
    free(d->used);
    memset(d, 0, sizeof *d);
}

/* Adds p to d: *fresh is 1 when d did not hold it. */
static int drawn_add(struct drawn_set *d, const struct design_point *p,
                     int *fresh, struct facet_error *err)
{
    if (2 * (d->count + 1) > d->capacity) {
        struct drawn_set grown = {NULL, NULL, d->capacity ? 2 * d->capacity
                                                          : 1024, 0};
        grown.point = malloc(grown.capacity * sizeof *grown.point);
        grown.used = calloc(grown.capacity, 1);
        if (grown.point == NULL || grown.used == NULL) {
            drawn_free(&grown);
            return facet_error_set(err, FACET_EWORK, "out of memory");
        }
        for (size_t k = 0; k < d->capacity; k++) {
            if (!d->used[k])
                continue;
            size_t h = design_point_hash(&d->point[k]) & (grown.capacity - 1);
            while (grown.used[h])
                h = (h + 1) & (grown.capacity - 1);
            grown.point[h] = d->point[k];
            grown.used[h] = 1;
        }
        grown.count = d->count;
        drawn_free(d);
        *d = grown;
    }
    size_t h = design_point_hash(p) & (d->capacity - 1);
    while (d->used[h]) {
        if (same_point(&d->point[h], p)) {
            *fresh = 0;
            return FACET_OK;
        }
        h = (h + 1) & (d->capacity - 1);
    }
    d->point[h] = *p;
    d->used[h] = 1;
    d->count++;
    *fresh = 1;
    return FACET_OK;
}

static int run_random(struct search *s, enum optimize_outcome *outcome,
                      struct facet_error *err)
{
    const struct optimize_settings *settings = s->settings;
    struct rng rng;
    rng_seed(&rng, settings->seed);
    size_t size = batch_size(settings);
    struct design_point *points = malloc(size * sizeof *points);
    size_t *index = malloc(size * sizeof *index);
    int64_t *numbers = malloc(size * sizeof *numbers);
    struct drawn_set drawn = {NULL, NULL, 0, 0};
    int rc = FACET_OK;
    if (points == NULL || index == NULL || numbers == NULL)
        rc = facet_error_set(err, FACET_EWORK, "out of memory");
    /* Distinct points only; give up drawing when the space seems spent.
     * The k-th distinct point drawn is option k + 1 of the whole run; a
     * shard draws them all and evaluates its share. */
    int64_t misses = 0, wanted = settings->evaluations, drawn_points = 0;
    int64_t most_misses = 100 * wanted + 1000;
    while (rc == FACET_OK && drawn_points < wanted &&
           misses < most_misses) {
        if (stop_requested(s->hooks)) {
            *outcome = OPTIMIZE_INTERRUPTED;
            break;
        }
        size_t n = 0;
        while (rc == FACET_OK && n < size && drawn_points < wanted &&
               misses < most_misses) {
            struct design_point p;
            int fresh;
            random_point(&settings->space, &rng, &p);
            /* Distinct options, not points: a project's modules that
             * are one option are drawn once. */
            search_canonical(s, &p);
            rc = drawn_add(&drawn, &p, &fresh, err);
            if (rc != FACET_OK || !fresh) {
                misses++;
                continue;
            }
            if (shard_owns(&settings->shard, (uint64_t)drawn_points)) {
                points[n] = p;
                numbers[n++] = drawn_points + 1;
            }
            drawn_points++;
        }
        if (rc == FACET_OK && n > 0)
            rc = search_batch(s, points, n, 0, index, numbers, err);
    }
    if (rc == FACET_ESTOP)
        rc = search_stopped(outcome, err);
    /* A space of fewer distinct options than the draws asked for is
     * spent: the run is done with what it drew, and its progress says so
     * rather than stopping short of a total it could never reach. */
    if (rc == FACET_OK && *outcome == OPTIMIZE_DONE && drawn_points < wanted &&
        s->done < s->total) {
        s->total = s->done;
        s->work_exact = s->work_done;
        search_report(s, s->done, s->work_done);
    }
    drawn_free(&drawn);
    free(points);
    free(index);
    free(numbers);
    return rc;
}

unsigned optimize_measures_needed(const struct optimize_settings *s)
{
    return option_measures_needed(
        &s->base.classify, objectives_measures(s->objectives, s->nobjectives));
}

int64_t optimize_total(const struct optimize_settings *settings)
{
    int64_t total = 0;
    struct facet_error ignored;
    /* Without a canonical hook the walk's grids need no memory. */
    optimize_total_with(NULL, settings, &total, &ignored);
    return total;
}

int optimize_total_with(const struct option_evaluator *evaluator,
                        const struct optimize_settings *settings,
                        int64_t *total, struct facet_error *err)
{
    struct exhaustive_grids grids;
    int rc;
    switch (settings->method) {
    case METHOD_EXHAUSTIVE:
        rc = exhaustive_grids_init(evaluator, &settings->space, &grids, err);
        *total = rc != FACET_OK ? 0
                                : exhaustive_total(&grids, &settings->shard);
        exhaustive_grids_free(&grids);
        return rc;
    case METHOD_RANDOM:
        *total = (int64_t)shard_share(&settings->shard,
                                      (uint64_t)settings->evaluations);
        return FACET_OK;
    default:
        /* The generations count the first one (nsga2.h): population x
         * generations points met, repeats included. */
        *total = (int64_t)settings->population *
                 (int64_t)settings->generations;
        return FACET_OK;
    }
}

/* The single surface's evaluation: its panels from the lattice (or
 * none), the joint lengths from the run's lines (or none). */
struct surface_evaluation {
    const struct surface *surface;
    const struct panel_lattice *lattice;
    const struct joint_lines *lines;
};

static int surface_evaluate(void *context, const struct option_params *base,
                            const struct design_point *points, size_t n,
                            int jobs, const struct facet_stop *stop,
                            struct option_totals *totals,
                            struct facet_error *err)
{
    const struct surface_evaluation *e = context;
    return evaluate(e->surface, e->lattice, e->lines, base, points, n, jobs,
                    stop, totals, NULL, err);
}

/* The work the progress weighs by (struct optimize_progress): of an
 * exhaustive walk over grids, exactly its panels (of a shard, its share);
 * of another method, the mean work of a point of the space. */
static void search_work_init(struct search *s,
                             const struct exhaustive_grids *grids)
{
    const struct design_space *space = &s->settings->space;
    int single = s->evaluator->canonical == NULL;
    s->work_each = single ? design_space_mean_panels(space) : 1;
    if (s->settings->method != METHOD_EXHAUSTIVE)
        return;
    double steps = (double)threshold_steps(space);
    double points = (double)grids->n * steps;
    /* Every grid of the space at every step: exactly the mean's worth. */
    double work = points * s->work_each;
    s->work_exact = points > 0 ? work * (double)s->total / points : 0;
}

int optimize_run_with(const struct option_evaluator *evaluator,
                      const struct optimize_settings *settings,
                      const struct evaluated_option *stored, size_t nstored,
                      const struct optimize_hooks *hooks,
                      enum optimize_outcome *outcome, struct facet_error *err)
{
    *outcome = OPTIMIZE_DONE;
    int rc = design_space_check(&settings->space, NULL, err);
    if (rc != FACET_OK)
        return rc;
    /* An exhaustive walk's grids, listed once: its total is theirs. */
    struct exhaustive_grids grids;
    memset(&grids, 0, sizeof grids);
    int64_t total;
    if (settings->method == METHOD_EXHAUSTIVE) {
        rc = exhaustive_grids_init(evaluator, &settings->space, &grids, err);
        total = rc != FACET_OK ? 0
                               : exhaustive_total(&grids, &settings->shard);
    } else {
        rc = optimize_total_with(evaluator, settings, &total, err);
    }
    struct search s;
    memset(&s, 0, sizeof s);
    if (rc == FACET_OK)
        rc = search_init(&s, evaluator, settings, stored, nstored, hooks,
                         total, err);
    if (rc == FACET_OK)
        search_work_init(&s, &grids);
    if (rc == FACET_OK) {
        if (settings->method == METHOD_EXHAUSTIVE)
            rc = run_exhaustive(&s, &grids, outcome, err);
        else if (settings->method == METHOD_RANDOM)
            rc = run_random(&s, outcome, err);
        else
            rc = run_nsga2(&s, outcome, err);
    }
    search_free(&s);
    exhaustive_grids_free(&grids);
    return rc;
}

int optimize_run(const struct surface *surface,
                 const struct panel_lattice *lattice,
                 const struct optimize_settings *settings,
                 const struct evaluated_option *stored, size_t nstored,
                 const struct optimize_hooks *hooks,
                 enum optimize_outcome *outcome, struct facet_error *err)
{
    *outcome = OPTIMIZE_DONE;
    int rc = design_space_check(&settings->space, NULL, err);
    if (rc != FACET_OK)
        return rc;
    struct surface_evaluation e = {surface, lattice, NULL};
    /* With a lattice, the run's grids share lines: measure the joints of
     * every line of the space once, for all its batches. */
    struct joint_lines lines;
    memset(&lines, 0, sizeof lines);
    if (lattice != NULL) {
        rc = optimize_joint_lines(surface, &settings->space, settings->jobs,
                                  &lines, err);
        e.lines = &lines;
    }
    struct option_evaluator evaluator = {&e, NULL, surface_evaluate};
    if (rc == FACET_OK)
        rc = optimize_run_with(&evaluator, settings, stored, nstored, hooks,
                               outcome, err);
    joint_lines_free(&lines);
    return rc;
}

/* A lattice costs about as much to build as 15 grids on their own. */
#define LATTICE_MIN_GRIDS 30

int optimize_lattice(const struct surface *surface,
                     const struct optimize_settings *settings,
                     struct panel_lattice **out, struct facet_error *err)
{
    return optimize_lattice_stoppable(surface, settings, NULL, out, err);
}

int optimize_lattice_stoppable(const struct surface *surface,
                               const struct optimize_settings *settings,
                               const struct facet_stop *stop,
                               struct panel_lattice **out,
                               struct facet_error *err)
{
    *out = NULL;
    const struct design_space *space = &settings->space;
    int rc = design_space_check(space, NULL, err);
    if (rc != FACET_OK)
        return rc;
    /* The grids the run evaluates, at most, from the settings alone. */
    double grids = (double)(space->u_max - space->u_min + 1) *
                   (double)(space->v_max - space->v_min + 1);
    double evaluations =
        settings->method == METHOD_RANDOM ? (double)settings->evaluations
        : settings->method == METHOD_NSGA2
            ? (double)settings->population * settings->generations
            : grids;
    if (evaluations < grids)
        grids = evaluations;
    if (settings->base.mode != PANEL_EXTREMES || grids < LATTICE_MIN_GRIDS)
        return FACET_OK;
    return panel_lattice_build_stoppable(&surface->panels, space->u_min,
                                         space->u_max, space->v_min,
                                         space->v_max, settings->jobs, stop,
                                         out, err);
}

int optimize_joint_lines(const struct surface *surface,
                         const struct design_space *space, int jobs,
                         struct joint_lines *out, struct facet_error *err)
{
    memset(out, 0, sizeof *out);
    size_t nsides[2] = {(size_t)(space->u_max - space->u_min + 1),
                        (size_t)(space->v_max - space->v_min + 1)};
    int *side[2] = {malloc(nsides[0] * sizeof(int)),
                    malloc(nsides[1] * sizeof(int))};
    int rc = FACET_OK;
    if (side[0] == NULL || side[1] == NULL)
        rc = facet_error_set(err, FACET_EWORK, "out of memory");
    for (size_t k = 0; rc == FACET_OK && k < nsides[0]; k++)
        side[0][k] = space->u_min + (int)k;
    for (size_t k = 0; rc == FACET_OK && k < nsides[1]; k++)
        side[1][k] = space->v_min + (int)k;
    if (rc == FACET_OK)
        rc = joint_lines_build(&surface->joints, &surface->mesh,
                               &surface->uv, (const int *const *)side,
                               nsides, jobs, out, err);
    free(side[0]);
    free(side[1]);
    return rc;
}
