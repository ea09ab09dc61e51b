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

#include "core/base/vec3.h"
#include "core/classify/classify.h"
#include "core/mould/mould_fit.h"
#include "core/mould/mould_sample.h"

enum { DESCRIPTOR = 8 };  /* diagonal long, bulge, diagonal short, 4 sides,
                             spread: the first two are the grid's axes */

/* A representative's cell of the hash grid. */
struct bucket {
    int64_t x, y;
    int head;  /* the latest family filed here, -1 for an empty slot */
};

/* Everything one build works on. */
struct family_work {
    const struct panelization *panels;
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

/* Samples and describes every SP and DP panel (w->sampled holds which
 * it could); sets w->cell. Returns FACET_OK or FACET_EWORK. */
static int sample_panels(const struct mesh *mesh,
                         const struct uv_index *index,
                         struct family_work *w)
{
    const struct panelization *p = w->panels;
    for (size_t n = 0; n < p->npanels; n++)
        w->sampled[n] = p->panels[n].type != TYPE_FP;
    if (mould_sample_grid(mesh, index, p, w->sampled, w->point,
                          w->sampled) != FACET_OK)
        return FACET_EWORK;
    double diameter = 0, extent = 0;
    for (size_t n = 0; n < p->npanels; n++) {
        if (!w->sampled[n])
            continue;
        w->sampled[n] = 0;
        mould_shape_measure((const double (*)[3])w->point[n], &w->shape[n]);
        describe(&w->shape[n], w->descriptor[n]);
        int finite = 1;
        for (int k = 0; k < DESCRIPTOR; k++)
            finite &= isfinite(w->descriptor[n][k]);
        if (!finite || !isfinite(p->panels[n].diameter))
            continue;
        w->sampled[n] = 1;
        diameter = fmax(diameter, p->panels[n].diameter);
        extent = fmax(extent, fmax(w->descriptor[n][0], w->descriptor[n][1]));
    }
    /* Wider than any pair's allowance, with a margin for the division's
     * rounding: keys of panels within it differ by at most 1. */
    double limit = mould_limit(w->options, diameter, diameter);
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
    const struct panel *panel = &w->panels->panels[n];
    int64_t key[2];
    grid_key(w, w->descriptor[n], key);
    int count = 0;
    for (int dx = -1; dx <= 1; dx++)
        for (int dy = -1; dy <= 1; dy++) {
            size_t slot = bucket_slot(w, key[0] + dx, key[1] + dy);
            for (int f = w->bucket[slot].head; f >= 0; f = w->next[f]) {
                const struct panel *rep =
                    &w->panels->panels[out->representative[f]];
                double limit = mould_limit(w->options, rep->diameter,
                                           panel->diameter);
                if (rep->type == panel->type &&
                    descriptors_close(w->descriptor[out->representative[f]],
                                      w->descriptor[n], limit))
                    w->candidate[count++] = f;
            }
        }
    /* Few: an insertion sort. */
    for (int i = 1; i < count; i++)
        for (int k = i; k > 0 && w->candidate[k - 1] > w->candidate[k]; k--) {
            int t = w->candidate[k];
            w->candidate[k] = w->candidate[k - 1];
            w->candidate[k - 1] = t;
        }
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
    out->count[w->panels->panels[n].type]++;
    w->next[f] = -1;
    if (!w->sampled[n]) {
        out->trimmed++;
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

static void group_panels(struct family_work *w, struct mould_families *out)
{
    const struct panelization *p = w->panels;
    for (size_t n = 0; n < p->npanels; n++) {
        const struct panel *panel = &p->panels[n];
        out->family[n] = -1;
        if (panel->type == TYPE_FP)
            continue;
        int count = w->sampled[n] ? candidates(w, out, n) : 0;
        int joined = 0;
        for (int c = 0; c < count && !joined; c++) {
            int f = w->candidate[c];
            size_t r = out->representative[f];
            double limit = mould_limit(w->options, p->panels[r].diameter,
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
}

int mould_families_build(const struct mesh *mesh,
                         const struct uv_index *index,
                         const struct panelization *panels,
                         const struct mould_options *options,
                         struct mould_families *out,
                         struct facet_error *err)
{
    memset(out, 0, sizeof *out);
    if (!(options->tolerance >= 0) || !isfinite(options->tolerance))
        return facet_error_set(err, FACET_EINPUT,
            "mould tolerance %g m: must be a finite length of 0 or more",
            options->tolerance);
    if (panels->npanels > 0 &&
        (panels->umin != index->umin || panels->vmin != index->vmin ||
         panels->umax != index->umax || panels->vmax != index->vmax))
        return facet_error_set(err, FACET_EINPUT,
            "the panels were not built over this UV map");
    size_t n = panels->npanels, one = n ? n : 1;
    size_t slots = 16;
    while (slots < 2 * one)
        slots *= 2;
    struct family_work w = {
        .panels = panels, .options = options,
        .point = malloc(one * sizeof *w.point),
        .shape = malloc(one * sizeof *w.shape),
        .descriptor = malloc(one * sizeof *w.descriptor),
        .sampled = malloc(one),
        .bucket = malloc(slots * sizeof *w.bucket),
        .mask = slots - 1,
        .next = malloc(one * sizeof *w.next),
        .candidate = malloc(one * sizeof *w.candidate),
    };
    out->npanels = n;
    out->family = malloc(one * sizeof *out->family);
    out->representative = malloc(one * sizeof *out->representative);
    out->size = malloc(one * sizeof *out->size);
    int rc = FACET_OK;
    if (w.point == NULL || w.shape == NULL || w.descriptor == NULL || w.sampled == NULL ||
        w.bucket == NULL || w.next == NULL || w.candidate == NULL ||
        out->family == NULL || out->representative == NULL ||
        out->size == NULL) {
        rc = facet_error_set(err, FACET_EWORK,
                             "out of memory for the mould families of %zu "
                             "panels", n);
    } else {
        for (size_t s = 0; s < slots; s++)
            w.bucket[s].head = -1;
        mould_labels_make(&w.labels);
        if (sample_panels(mesh, index, &w) == FACET_OK)
            group_panels(&w, out);
        else
            rc = facet_error_set(err, FACET_EWORK,
                                 "out of memory for the mould samples");
    }
    free(w.point);
    free(w.shape);
    free(w.descriptor);
    free(w.sampled);
    free(w.bucket);
    free(w.next);
    free(w.candidate);
    return rc;
}

void mould_families_free(struct mould_families *families)
{
    free(families->family);
    free(families->representative);
    free(families->size);
    memset(families, 0, sizeof *families);
}
