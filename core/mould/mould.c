/*
 * mould.c: mould families by greedy congruence, with a descriptor to find
 * the candidates. See mould.h.
 *
 * The descriptor of a sampled panel is made of distances alone, so no
 * rigid move, mirror or relabeling changes it: the two diagonals and the
 * four sides (each sorted), the spread (root mean square distance of the
 * samples from their centroid) and the bulge (the distance of the
 * samples' centroid from the corners'). A fit within limit moves every
 * sample, and so every centroid, by at most limit, so each of these
 * differs by at most 2 limit between congruent panels: a representative
 * whose descriptor differs more is passed over without fitting, which
 * changes no family. The representatives are filed in a hash grid over
 * the longer diagonal and the bulge, with cells wider than any 2 limit, so
 * a panel's candidates are in the 3 x 3 cells around its own.
 */
#include "core/mould/mould.h"

#include <assert.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "core/base/parallel.h"
#include "core/base/vec3.h"
#include "core/classify/classify.h"
#include "core/fit/developable.h"
#include "core/mould/mould_fit.h"
#include "core/mould/mould_sample.h"

enum { DESCRIPTOR = 8 };  /* diagonal long, bulge, diagonal short, 4 sides,
                             spread: the first two are the grid's axes */

/* An SP panel on its fitted surface, as mould.h's jigs take it. */
struct jig {
    struct developable surface;  /* its cylinder or cone, based at the
                                    foot of its centroid on the axis */
    double curvature;            /* across the rulings at the centroid
                                    (1/m): 1 / radius, a cone's cos(a) /
                                    rho */
    double width;                /* its samples' extent across the axis
                                    and the centroid's normal (m) */
    double radial[3];            /* unit, from the axis to the centroid */
};

/* A representative's cell of the hash grid. */
struct bucket {
    int64_t x, y;
    int head;  /* the latest family filed here, -1 for an empty slot */
};

/* Everything one build works on. Panels are numbered across the parts:
 * part 0's, then part 1's, and so on (mould.h). */
struct family_work {
    size_t npanels;
    const struct panel **panel;            /* npanels: each panel */
    const struct mould_options *options;
    struct mould_labels labels;
    double (*point)[MOULD_SAMPLES][3];     /* npanels: the samples */
    struct mould_shape *shape;              /* npanels */
    double (*descriptor)[DESCRIPTOR];      /* npanels */
    unsigned char *sampled;                /* npanels */
    struct bucket *bucket;                 /* mask + 1 slots */
    size_t mask;
    int *next;                             /* nfamilies: the family filed
                                              before it in its cell */
    int *candidate;                        /* npanels */
    double cell;                           /* the grid's cell (m) */
    struct jig *jig;                       /* npanels */
    unsigned char *on_jig;                 /* npanels: an SP panel with
                                              its fit, sampled: matched
                                              by jig */
    int *jig_family;                       /* the jig families by their
                                              representative's curvature */
    double *jig_key;                       /* that curvature, ascending */
    size_t njigs;
    double limit_max;                      /* the largest limit of any
                                              pair (m) */
};

double mould_limit(const struct mould_options *options, double da,
                   double db)
{
    return options->tolerance + CLASSIFY_ROUNDING * fmax(da, db);
}

static void sort_ascending(double *x, int n)
{
    for (int i = 1; i < n; i++)
        for (int k = i; k > 0 && x[k - 1] > x[k]; k--) {
            double t = x[k];
            x[k] = x[k - 1];
            x[k - 1] = t;
        }
}

/* The descriptor of a measured shape: its corner distances, and its
 * centred samples for the bulge (the corners' centroid less the samples')
 * and the spread. */
static void describe(const struct mould_shape *shape, double d[DESCRIPTOR])
{
    const double (*c)[4] = shape->corner_distance;
    double diagonal[2] = {c[0][2], c[1][3]};
    sort_ascending(diagonal, 2);
    double side[4];
    for (int k = 0; k < 4; k++)
        side[k] = c[k][(k + 1) % 4];
    sort_ascending(side, 4);
    const int e = MOULD_SIDE - 1;
    const int corner[4] = {
        mould_sample_index(0, 0), mould_sample_index(e, 0),
        mould_sample_index(e, e), mould_sample_index(0, e),
    };
    double bulge[3] = {0, 0, 0};
    for (int k = 0; k < 4; k++)
        for (int x = 0; x < 3; x++)
            bulge[x] += shape->centred[corner[k]][x] / 4;
    d[0] = diagonal[1];
    d[1] = vec3_length(bulge);
    d[2] = diagonal[0];
    for (int k = 0; k < 4; k++)
        d[3 + k] = side[k];
    d[7] = sqrt(shape->spread / MOULD_SAMPLES);
}

/* How far two descriptor values x and y of panels within limit of each
 * other can be: 2 limit, plus their rounding. */
static double allowed(double limit, double x, double y)
{
    return 2 * limit + 1e-12 * (fabs(x) + fabs(y));
}

static int descriptors_close(const double a[DESCRIPTOR],
                             const double b[DESCRIPTOR], double limit)
{
    for (int k = 0; k < DESCRIPTOR; k++)
        if (fabs(a[k] - b[k]) > allowed(limit, a[k], b[k]))
            return 0;
    return 1;
}

static int compare_families(const void *a, const void *b)
{
    int x = *(const int *)a, y = *(const int *)b;
    return (x > y) - (x < y);
}

/* Candidate families into the order they were started. A jig's
 * candidates come in curvature order and may be thousands (every family
 * within the closed form's reach), so not an insertion sort. */
static void sort_families(int *family, int count)
{
    qsort(family, (size_t)count, sizeof *family, compare_families);
}

static size_t bucket_slot(const struct family_work *w, int64_t x, int64_t y)
{
    uint64_t h = (uint64_t)x * 0x9E3779B97F4A7C15u ^
                 (uint64_t)y * 0xC2B2AE3D27D4EB4Fu;
    h ^= h >> 29;
    size_t slot = (size_t)h & w->mask;
    while (w->bucket[slot].head >= 0 &&
           (w->bucket[slot].x != x || w->bucket[slot].y != y))
        slot = (slot + 1) & w->mask;
    return slot;
}

static void grid_key(const struct family_work *w, const double d[DESCRIPTOR],
                     int64_t key[2])
{
    key[0] = (int64_t)floor(d[0] / w->cell);
    key[1] = (int64_t)floor(d[1] / w->cell);
}

/* Sets *jig from panel's fitted surface (panel.h's sp_fit) and its
 * samples point; returns 0, *jig undefined, when it has none or it is not
 * finite. */
static int jig_make(const struct panel *panel,
                    double point[MOULD_SAMPLES][3], struct jig *jig)
{
    const struct panel_sp_fit *fit = &panel->sp_fit;
    struct developable *d = &jig->surface;
    if (fit->shape == PANEL_SP_CYLINDER) {
        d->shape = DEVELOPABLE_CYLINDER;
        d->radius = fit->radius;
        d->slope = 0;
    } else if (fit->shape == PANEL_SP_CONE) {
        /* direction points from the apex to the panel: the distance from
         * the axis grows along it. */
        d->shape = DEVELOPABLE_CONE;
        d->slope = tan(fit->half_angle);
        d->radius = d->slope * vec3_distance(fit->apex, fit->axis_point);
    } else {
        return 0;
    }
    memcpy(d->axis, fit->direction, sizeof d->axis);
    memcpy(d->base, fit->axis_point, sizeof d->base);
    double q[3];
    vec3_sub(panel->centroid, d->base, q);
    double h = vec3_dot(q, d->axis);
    for (int x = 0; x < 3; x++)
        jig->radial[x] = q[x] - h * d->axis[x];
    double centroid_rho = vec3_length(jig->radial);
    if (!(centroid_rho > 0) || !isfinite(centroid_rho) ||
        !(d->radius > 0) || !isfinite(d->radius) || !isfinite(d->slope))
        return 0;
    for (int x = 0; x < 3; x++)
        jig->radial[x] /= centroid_rho;
    /* The panel as built: its samples moved onto its own fitted surface,
     * which is what is bent on a jig. The design's samples would count
     * again the fit's own deviation, already the panel's sp_deviation,
     * and on a mesh whose facets sag near the tolerance that sag alone
     * kept most panels off every jig (7,541 SP jigs where shapes took
     * 2,697, bench_mould's fine grid). */
    for (int k = 0; k < MOULD_SAMPLES; k++)
        developable_nearest(d, point[k], point[k], NULL);
    double across[3];
    vec3_cross(d->axis, jig->radial, across);
    double low = INFINITY, high = -INFINITY;
    for (int k = 0; k < MOULD_SAMPLES; k++) {
        vec3_sub(point[k], d->base, q);
        double t = vec3_dot(q, across);
        low = fmin(low, t);
        high = fmax(high, t);
    }
    jig->width = high - low;
    /* A cone's normal section across its ruling at distance rho from the
     * axis bends with radius rho / cos(a), a its half-angle. */
    double radius = d->radius * sqrt(1 + d->slope * d->slope);
    jig->curvature = 1 / radius;
    return isfinite(jig->curvature) && isfinite(jig->width);
}

/* Samples and describes every SP and DP panel of part, whose first panel
 * is first in w's numbering (w->sampled holds which it could), and raises
 * *diameter and *extent to the largest diameter and grid coordinate of
 * those it could. Each part writes only its own panels' entries, so parts
 * may be sampled at once. Returns FACET_OK, FACET_EWORK or FACET_ESTOP. */
static int sample_part(const struct mould_part *part, size_t first,
                       struct family_work *w, double *diameter,
                       double *extent)
{
    const struct panelization *p = part->panels;
    unsigned char *sampled = w->sampled + first;
    for (size_t n = 0; n < p->npanels; n++) {
        sampled[n] = p->panels[n].type != TYPE_FP;
        w->on_jig[first + n] = 0;
    }
    int rc = mould_sample_grid(part->mesh, part->index, p, sampled,
                               w->point + first, sampled, w->options->stop);
    if (rc != FACET_OK)
        return rc;
    for (size_t k = 0; k < p->npanels; k++) {
        size_t n = first + k;
        if (!w->sampled[n])
            continue;
        w->sampled[n] = 0;
        mould_shape_measure((const double (*)[3])w->point[n], &w->shape[n]);
        describe(&w->shape[n], w->descriptor[n]);
        int finite = 1;
        for (int d = 0; d < DESCRIPTOR; d++)
            finite &= isfinite(w->descriptor[n][d]);
        if (!finite || !isfinite(p->panels[k].diameter))
            continue;
        w->sampled[n] = 1;
        w->on_jig[n] = w->options->jigs && p->panels[k].type == TYPE_SP &&
                       jig_make(&p->panels[k], w->point[n], &w->jig[n]);
        *diameter = fmax(*diameter, p->panels[k].diameter);
        *extent = fmax(*extent, fmax(w->descriptor[n][0], w->descriptor[n][1]));
    }
    return FACET_OK;
}

/* One thread's share of the sampling: parts first, first + step, ... */
struct sample_job {
    const struct mould_part *parts;
    const size_t *offset;        /* each part's first panel */
    size_t nparts, first, step;
    struct family_work *work;
    double diameter, extent;     /* the largest of its parts' */
    int rc;
};

static void sample_run(void *argument)
{
    struct sample_job *job = argument;
    job->diameter = 0;
    job->extent = 0;
    job->rc = FACET_OK;
    for (size_t i = job->first; i < job->nparts && job->rc == FACET_OK;
         i += job->step)
        job->rc = sample_part(&job->parts[i], job->offset[i], job->work,
                              &job->diameter, &job->extent);
}

/* Samples and describes every part's SP and DP panels on up to jobs
 * threads, and sets w->cell from the largest diameter and grid
 * coordinate over all of them (a maximum: the same whatever the threads).
 * Returns FACET_OK, FACET_EWORK or FACET_ESTOP. */
static int sample_panels(const struct mould_part *parts, size_t nparts,
                         const size_t *offset, int jobs,
                         struct family_work *w)
{
    struct sample_job job[PARALLEL_MAX];
    jobs = parallel_jobs(jobs, nparts);
    for (int k = 0; k < jobs; k++)
        job[k] = (struct sample_job){parts, offset, nparts, (size_t)k,
                                     (size_t)jobs, w, 0, 0, FACET_OK};
    parallel_run(job, sizeof job[0], jobs, sample_run);
    double diameter = 0, extent = 0;
    for (int k = 0; k < jobs; k++) {
        if (job[k].rc != FACET_OK)
            return job[k].rc;
        diameter = fmax(diameter, job[k].diameter);
        extent = fmax(extent, job[k].extent);
    }
    /* Wider than any pair's allowance, with a margin for the division's
     * rounding: keys of panels within it differ by at most 1. */
    double limit = mould_limit(w->options, diameter, diameter);
    w->limit_max = limit;
    w->cell = 1.01 * allowed(limit, extent, extent);
    if (!(w->cell > 0) || !isfinite(w->cell))
        w->cell = 1;
    return FACET_OK;
}

/* The families of the representatives near panel n, in w->candidate in
 * the order they were started; returns how many. */
static int candidates(const struct family_work *w,
                      const struct mould_families *out, size_t n)
{
    const struct panel *panel = w->panel[n];
    int64_t key[2];
    grid_key(w, w->descriptor[n], key);
    int count = 0;
    for (int dx = -1; dx <= 1; dx++)
        for (int dy = -1; dy <= 1; dy++) {
            size_t slot = bucket_slot(w, key[0] + dx, key[1] + dy);
            for (int f = w->bucket[slot].head; f >= 0; f = w->next[f]) {
                const struct panel *rep = w->panel[out->representative[f]];
                double limit = mould_limit(w->options, rep->diameter,
                                           panel->diameter);
                if (rep->type == panel->type &&
                    descriptors_close(w->descriptor[out->representative[f]],
                                      w->descriptor[n], limit))
                    w->candidate[count++] = f;
            }
        }
    sort_families(w->candidate, count);
    return count;
}

/* The largest distance panel m's samples leave from the surface of panel
 * r's jig laid on them (mould.h): a surface congruent to r's placed where
 * m's own fitted surface is (on m's axis, shifted across it to pass
 * through m's surface at m's centroid; a cone of r's half-angle on m's
 * axis, opening the way m's cone does, or either way along m's
 * cylinder's), when that leaves every sample within limit (m); else by
 * least squares from there, stopped once within limit.
 * INFINITY when no placement is found. */
static double jig_deviation(const struct family_work *w, size_t m,
                            size_t r, double limit)
{
    const struct jig *a = &w->jig[m], *b = &w->jig[r];
    const double *points = &w->point[m][0][0];
    struct developable start = a->surface;
    start.shape = b->surface.shape;
    start.slope = b->surface.slope;
    if (start.shape == DEVELOPABLE_CYLINDER) {
        start.radius = b->surface.radius;
        for (int x = 0; x < 3; x++)
            start.base[x] += (a->surface.radius - b->surface.radius) *
                             a->radial[x];
    }
    int turns = start.shape == DEVELOPABLE_CONE &&
                a->surface.shape == DEVELOPABLE_CYLINDER ? 2 : 1;
    double best = INFINITY;
    for (int turn = 0; turn < turns; turn++) {
        if (turn == 1)
            for (int x = 0; x < 3; x++)
                start.axis[x] = -start.axis[x];
        /* Two panels of one surface: the start is the placement. */
        double at_start = developable_max_distance(&start, points,
                                                   MOULD_SAMPLES);
        if (at_start <= limit)
            return at_start;
        struct developable placed;
        if (developable_fit_congruent(points, MOULD_SAMPLES, &start, limit,
                                      &placed) == 0)
            best = fmin(best, developable_max_distance(&placed, points,
                                                       MOULD_SAMPLES));
    }
    return best;
}

/* Whether two SP panels' curvatures are near enough to test them on each
 * other's jig (mould.h): |curvature difference| x width^2 / 16 <= limit,
 * the wider's width. */
static int jig_near(const struct jig *a, const struct jig *b, double limit)
{
    double width = fmax(a->width, b->width);
    return fabs(a->curvature - b->curvature) * width * width <= 16 * limit;
}

/* The jig families (mould.h) whose representatives are near panel n's
 * curvature, in w->candidate in the order they were started; returns how
 * many. */
static int jig_candidates(const struct family_work *w,
                          const struct mould_families *out, size_t n)
{
    const struct jig *jig = &w->jig[n];
    double reach = 16 * w->limit_max / (jig->width * jig->width);
    double low = jig->curvature - reach, high = jig->curvature + reach;
    size_t from = 0, to = w->njigs;
    while (from < to) {
        size_t mid = from + (to - from) / 2;
        if (w->jig_key[mid] < low)
            from = mid + 1;
        else
            to = mid;
    }
    int count = 0;
    for (size_t k = from; k < w->njigs && w->jig_key[k] <= high; k++) {
        int f = w->jig_family[k];
        size_t r = out->representative[f];
        double limit = mould_limit(w->options, w->panel[r]->diameter,
                                   w->panel[n]->diameter);
        if (jig_near(&w->jig[r], jig, limit))
            w->candidate[count++] = f;
    }
    sort_families(w->candidate, count);
    return count;
}

/* Starts a family with panel n as its representative, filed in the grid
 * when it is sampled. */
static void start_family(struct family_work *w, struct mould_families *out,
                         size_t n)
{
    int f = (int)out->nfamilies++;
    out->family[n] = f;
    out->representative[f] = n;
    out->size[f] = 1;
    out->count[w->panel[n]->type]++;
    w->next[f] = -1;
    if (!w->sampled[n]) {
        out->trimmed++;
        return;
    }
    if (w->on_jig[n]) {
        double key = w->jig[n].curvature;
        size_t at = w->njigs;
        while (at > 0 && w->jig_key[at - 1] > key)
            at--;
        memmove(w->jig_key + at + 1, w->jig_key + at,
                (w->njigs - at) * sizeof *w->jig_key);
        memmove(w->jig_family + at + 1, w->jig_family + at,
                (w->njigs - at) * sizeof *w->jig_family);
        w->jig_key[at] = key;
        w->jig_family[at] = f;
        w->njigs++;
        return;
    }
    int64_t key[2];
    grid_key(w, w->descriptor[n], key);
    size_t slot = bucket_slot(w, key[0], key[1]);
    if (w->bucket[slot].head < 0) {
        w->bucket[slot].x = key[0];
        w->bucket[slot].y = key[1];
    }
    w->next[f] = w->bucket[slot].head;
    w->bucket[slot].head = f;
}

/* Joins SP panel n, on its jig, to the first jig family whose
 * representative's jig it lies on within the limit, and that lies on its
 * own (mould.h); returns whether it found one. */
static int join_jig(struct family_work *w, struct mould_families *out,
                    size_t n)
{
    int count = jig_candidates(w, out, n);
    for (int c = 0; c < count; c++) {
        int f = w->candidate[c];
        size_t r = out->representative[f];
        double limit = mould_limit(w->options, w->panel[r]->diameter,
                                   w->panel[n]->diameter);
        out->fits++;
        double on_theirs = jig_deviation(w, n, r, limit);
        if (!(on_theirs <= limit))
            continue;
        double on_ours = jig_deviation(w, r, n, limit);
        if (!(on_ours <= limit))
            continue;
        out->family[n] = f;
        out->size[f]++;
        out->worst = fmax(out->worst, fmax(on_theirs, on_ours));
        return 1;
    }
    return 0;
}

/* Panels grouped between two questions to the stop. */
#define PANELS_BETWEEN_STOPS 256

static int group_panels(struct family_work *w, struct mould_families *out)
{
    for (size_t n = 0; n < w->npanels; n++) {
        if (n % PANELS_BETWEEN_STOPS == 0 &&
            facet_stop_requested(w->options->stop))
            return FACET_ESTOP;
        const struct panel *panel = w->panel[n];
        out->family[n] = -1;
        if (panel->type == TYPE_FP)
            continue;
        if (w->sampled[n] && w->on_jig[n]) {
            if (!join_jig(w, out, n))
                start_family(w, out, n);
            continue;
        }
        int count = w->sampled[n] ? candidates(w, out, n) : 0;
        int joined = 0;
        for (int c = 0; c < count && !joined; c++) {
            int f = w->candidate[c];
            size_t r = out->representative[f];
            double limit = mould_limit(w->options, w->panel[r]->diameter,
                                       panel->diameter);
            struct mould_fit fit;
            out->fits++;
            if (mould_congruent(&w->labels, &w->shape[r], &w->shape[n],
                                w->options->mirror, limit, &fit)) {
                assert(fit.deviation <= limit);
                out->family[n] = f;
                out->size[f]++;
                out->worst = fmax(out->worst, fit.deviation);
                joined = 1;
            }
        }
        if (!joined)
            start_family(w, out, n);
    }
    for (size_t f = 0; f < out->nfamilies; f++) {
        out->largest = out->size[f] > out->largest ? out->size[f]
                                                   : out->largest;
        out->singletons += out->size[f] == 1;
    }
    return FACET_OK;
}

int mould_families_build(const struct mesh *mesh,
                         const struct uv_index *index,
                         const struct panelization *panels,
                         const struct mould_options *options,
                         struct mould_families *out,
                         struct facet_error *err)
{
    struct mould_part part = {mesh, index, panels};
    return mould_families_build_parts(&part, 1, options, 1, out, err);
}

int mould_families_build_parts(const struct mould_part *parts,
                               size_t nparts,
                               const struct mould_options *options,
                               int jobs, struct mould_families *out,
                               struct facet_error *err)
{
    memset(out, 0, sizeof *out);
    if (!(options->tolerance >= 0) || !isfinite(options->tolerance))
        return facet_error_set(err, FACET_EINPUT,
            "mould tolerance %g m: must be a finite length of 0 or more",
            options->tolerance);
    size_t n = 0;
    for (size_t i = 0; i < nparts; i++) {
        const struct panelization *p = parts[i].panels;
        const struct uv_index *index = parts[i].index;
        if (p->npanels > 0 &&
            (p->umin != index->umin || p->vmin != index->vmin ||
             p->umax != index->umax || p->vmax != index->vmax))
            return nparts == 1
                ? facet_error_set(err, FACET_EINPUT,
                      "the panels were not built over this UV map")
                : facet_error_set(err, FACET_EINPUT,
                      "the panels of part %zu were not built over its UV "
                      "map", i + 1);
        n += p->npanels;
    }
    size_t one = n ? n : 1;
    size_t slots = 16;
    while (slots < 2 * one)
        slots *= 2;
    struct family_work w = {
        .npanels = n, .options = options,
        .panel = malloc(one * sizeof *w.panel),
        .point = malloc(one * sizeof *w.point),
        .shape = malloc(one * sizeof *w.shape),
        .descriptor = malloc(one * sizeof *w.descriptor),
        .sampled = malloc(one),
        .bucket = malloc(slots * sizeof *w.bucket),
        .mask = slots - 1,
        .next = malloc(one * sizeof *w.next),
        .candidate = malloc(one * sizeof *w.candidate),
        .jig = malloc(one * sizeof *w.jig),
        .on_jig = malloc(one),
        .jig_family = malloc(one * sizeof *w.jig_family),
        .jig_key = malloc(one * sizeof *w.jig_key),
    };
    size_t *offset = malloc((nparts ? nparts : 1) * sizeof *offset);
    out->npanels = n;
    out->family = malloc(one * sizeof *out->family);
    out->representative = malloc(one * sizeof *out->representative);
    out->size = malloc(one * sizeof *out->size);
    int rc = FACET_OK;
    if (w.panel == NULL || w.point == NULL || w.shape == NULL ||
        w.descriptor == NULL || w.sampled == NULL || w.bucket == NULL ||
        w.next == NULL || w.candidate == NULL || w.jig == NULL ||
        w.on_jig == NULL || w.jig_family == NULL || w.jig_key == NULL ||
        offset == NULL ||
        out->family == NULL || out->representative == NULL ||
        out->size == NULL) {
        rc = facet_error_set(err, FACET_EWORK,
                             "out of memory for the mould families of %zu "
                             "panels", n);
    } else {
        size_t first = 0;
        for (size_t i = 0; i < nparts; i++) {
            const struct panelization *p = parts[i].panels;
            offset[i] = first;
            for (size_t k = 0; k < p->npanels; k++)
                w.panel[first + k] = &p->panels[k];
            first += p->npanels;
        }
        for (size_t s = 0; s < slots; s++)
            w.bucket[s].head = -1;
        mould_labels_make(&w.labels);
        rc = sample_panels(parts, nparts, offset, jobs, &w);
        if (rc == FACET_OK)
            rc = group_panels(&w, out);
        if (rc == FACET_ESTOP)
            facet_stop_error(err);
        else if (rc != FACET_OK)
            rc = facet_error_set(err, FACET_EWORK,
                                 "out of memory for the mould samples");
    }
    free(offset);
    free(w.panel);
    free(w.point);
    free(w.shape);
    free(w.descriptor);
    free(w.sampled);
    free(w.bucket);
    free(w.next);
    free(w.candidate);
    free(w.jig);
    free(w.on_jig);
    free(w.jig_family);
    free(w.jig_key);
    return rc;
}

void mould_families_free(struct mould_families *families)
{
    free(families->family);
    free(families->representative);
    free(families->size);
    memset(families, 0, sizeof *families);
}
