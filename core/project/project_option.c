/*
 * project_option.c: an option over every surface of a project. See
 * project_option.h.
 */
#include "core/evaluate/evaluate.h"
#include "core/project/project_option.h"

#include <assert.h>
#include <math.h>
#include <stdatomic.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "core/base/exact_sum.h"
#include "core/base/parallel.h"
#include "core/project/project_seams.h"
#include "core/quantity/quantity.h"

/* The surfaces, taken one at a time by whichever thread is free: each
 * writes only its own surface's slot, so the taking order changes
 * nothing. */
struct surface_work {
    const struct project *project;
    const struct surface_grid *grids;
    const struct option_params *params;
    const struct facet_stop *stop;
    struct project_option *out;
    atomic_size_t *next;                /* the next surface not taken */
    struct parallel_failure failure;    /* this thread's first failed
                                           surface */
};

static void surface_run(void *argument)
{
    struct surface_work *job = argument;
    parallel_failure_clear(&job->failure);
    for (;;) {
        size_t i = atomic_fetch_add(job->next, 1);
        if (i >= job->project->nsurfaces)
            return;
        const struct project_surface *s = &job->project->surfaces[i];
        struct project_surface_option *slot = &job->out->surfaces[i];
        struct option_params params = *job->params;
        params.nu = job->grids[i].nu;
        params.nv = job->grids[i].nv;
        slot->grid = job->grids[i];
        struct facet_error err;
        const struct evaluation_shared shared = {.unmoulded = 1,
                                                 .joints = &slot->joints,
                                                 .stop = job->stop};
        int rc = option_evaluate(&s->surface, &params, &shared,
                                 &slot->panels, &slot->totals, &err);
        /* Threads take surfaces in rising order, so its first failure is
         * its least. */
        if (rc != FACET_OK && job->failure.piece == SIZE_MAX) {
            job->failure.piece = i;
            job->failure.rc = rc;
            if (rc == FACET_ESTOP)
                facet_stop_error(&job->failure.err);
            else
                facet_error_set(&job->failure.err, rc, "surface %s: %s",
                                s->name, err.message);
        }
    }
}

/* Evaluates every surface without its moulds on jobs threads. Returns
 * FACET_OK or the first failed surface's error, in project order. */
static int evaluate_surfaces(const struct project *project,
                             const struct surface_grid *grids,
                             const struct option_params *params, int jobs,
                             const struct facet_stop *stop,
                             struct project_option *out,
                             struct facet_error *err)
{
    struct surface_work work[PARALLEL_MAX];
    atomic_size_t next;
    atomic_init(&next, 0);
    for (int k = 0; k < jobs; k++)
        work[k] = (struct surface_work){project, grids, params, stop, out,
                                        &next, {0}};
    parallel_run(work, sizeof work[0], jobs, surface_run);
    return parallel_first_failure(&work[0].failure, sizeof work[0], jobs,
                                  err);
}

/* Finds the building's families over every surface's panels and gives
 * each surface its own (option_moulds_set) and the families it uses. */
static int find_moulds(const struct project *project,
                       const struct option_params *params, int jobs,
                       const struct facet_stop *stop,
                       struct project_option *out, struct facet_error *err)
{
    size_t n = project->nsurfaces;
    struct mould_part *parts = malloc((n ? n : 1) * sizeof *parts);
    if (parts == NULL)
        return facet_error_set(err, FACET_EWORK,
                               "out of memory for the mould families of "
                               "%zu surfaces", n);
    for (size_t i = 0; i < n; i++) {
        const struct surface *s = &project->surfaces[i].surface;
        parts[i] = (struct mould_part){&s->mesh, &s->uv,
                                       &out->surfaces[i].panels};
    }
    struct mould_options mould = option_mould_options(params);
    mould.stop = stop;
    int rc = mould_families_build_parts(parts, n, &mould, jobs,
                                        &out->families, err);
    free(parts);
    if (rc != FACET_OK)
        return rc;
    /* used[f]: the last surface whose panels were seen in family f. */
    size_t nf = out->families.nfamilies;
    size_t *used = malloc((nf ? nf : 1) * sizeof *used);
    if (used == NULL)
        return facet_error_set(err, FACET_EWORK,
                               "out of memory for %zu mould families", nf);
    for (size_t f = 0; f < nf; f++)
        used[f] = SIZE_MAX;
    size_t first = 0;
    for (size_t i = 0; i < n; i++) {
        struct project_surface_option *s = &out->surfaces[i];
        option_moulds_set(params, &out->families, first, &s->panels,
                          &s->totals);
        for (size_t k = 0; k < s->panels.npanels; k++) {
            int f = s->panels.panels[k].mould;
            if (f < 0 || used[f] == i)
                continue;
            used[f] = i;
            s->moulds_used++;
            s->moulds_used_of[s->panels.panels[k].type]++;
        }
        first += s->panels.npanels;
    }
    free(used);
    return FACET_OK;
}

/* The building's value of q, from its surfaces' as q's combine rule says;
 * the rules that are not the surfaces' (COMBINE_RECOMPUTED) are left to
 * building_totals. */
static void combine_surfaces(const struct quantity *q,
                             struct project_option *option)
{
    void *out = quantity_field_to_set(q, &option->totals);
    struct exact_sum sum;
    exact_sum_init(&sum);
    for (size_t i = 0; i < option->nsurfaces; i++) {
        const void *in = quantity_field(q, &option->surfaces[i].totals);
        double value = q->field == FIELD_DOUBLE ? *(const double *)in : 0;
        switch (q->combine) {
        case COMBINE_SUM:
            /* A count not measured on one surface is not known for the
             * building (TOTALS_UNKNOWN, never a sum wrapped past it). */
            assert(q->field == FIELD_SIZE);
            if (*(const size_t *)in == TOTALS_UNKNOWN ||
                *(size_t *)out == TOTALS_UNKNOWN)
                *(size_t *)out = TOTALS_UNKNOWN;
            else
                *(size_t *)out += *(const size_t *)in;
            break;
        case COMBINE_EXACT_SUM:
            exact_sum_add(&sum, value);
            break;
        case COMBINE_MAX:
            *(double *)out = fmax(*(double *)out, value);
            break;
        case COMBINE_MIN:
            /* fmin ignores a NaN: the least of the surfaces that have one. */
            *(double *)out = i == 0 ? value : fmin(*(double *)out, value);
            break;
        case COMBINE_JOINT_MEAN:
            /* Each surface's mean weighted by its share of the joints: one
             * surface's mean is kept to the bit (a weight of exactly 1). */
            if (option->joints > 0)
                *(double *)out += (double)option->surfaces[i].joints /
                                  (double)option->joints * value;
            break;
        default:
            return;
        }
    }
    if (q->combine == COMBINE_EXACT_SUM)
        *(double *)out = exact_sum_value(&sum);
}

/* The building's totals from its surfaces' and its families, as
 * project_option.h says: each quantity by its combine rule (quantity.h),
 * then what is recomputed on the building, its moulds, prices and
 * feasibility. */
static void building_totals(struct project_option *option,
                            const struct option_params *params)
{
    struct option_totals *t = &option->totals;
    memset(t, 0, sizeof *t);
    option_totals_classified(t);
    option->joints = 0;
    for (size_t i = 0; i < option->nsurfaces; i++)
        option->joints += option->surfaces[i].joints;
    for (int k = 0; k < OPTION_QUANTITIES; k++)
        if (quantity_in_totals(&option_quantities[k]))
            combine_surfaces(&option_quantities[k], option);
    const struct mould_families *f = &option->families;
    for (int k = 0; k < TYPE_COUNT; k++)
        t->moulds_of[k] = f->count[k];
    t->moulds = f->nfamilies;
    t->largest_family = f->largest;
    t->singleton_families = f->singletons;
    classify_price_areas(&params->classify, t);
    classify_price_terms(&params->classify, t);
    t->feasible =
        classify_violation(t, params->classify.max_panel_area) == 0;
}

/* A limit of classify's as seam_joints.h takes it: 0 is none. */
static double limit_or_none(double limit)
{
    return limit > 0 ? limit : INFINITY;
}

/* The building's seams (project->seams) measured on its panels, when its
 * joints are: their own totals, and their joints taken into the
 * building's gaps and kinks (project_option.h), then its feasibility
 * judged again. */
static int measure_seams(const struct project *project,
                         const struct option_params *params,
                         struct project_option *option,
                         struct facet_error *err)
{
    if (project->seams == NULL ||
        (params->unmeasured & OPTION_MEASURE_JOINTS))
        return FACET_OK;
    size_t n = option->nsurfaces;
    const struct panelization **panels = malloc((n ? n : 1) *
                                                sizeof *panels);
    if (panels == NULL)
        return facet_error_set(err, FACET_EWORK,
                               "out of memory for the seams of %zu "
                               "surfaces", n);
    for (size_t i = 0; i < n; i++)
        panels[i] = &option->surfaces[i].panels;
    const struct classify_options *c = &params->classify;
    struct seam_totals s;
    int rc = project_seams_measure(project, project->seams, panels,
                                   limit_or_none(c->max_gap),
                                   limit_or_none(c->max_kink), &s, err);
    free(panels);
    if (rc != FACET_OK)
        return rc;
    struct option_totals *t = &option->totals;
    t->seams = s.nseams;
    t->seam_length = s.length;
    t->seam_max_gap = s.njoints > 0 ? s.max_gap : NAN;
    t->seam_max_kink = s.njoints > 0 ? s.max_added : NAN;
    t->seam_max_crease = s.nseams > 0 ? s.max_crease : NAN;
    t->seam_gaps_over = s.gaps_over;
    t->seam_kinks_over = s.kinks_over;
    option->seam_joints = s.njoints;
    if (s.njoints > 0) {
        /* The means over every joint, the surfaces' and the seams'. */
        double inside = (double)option->joints;
        double at_seams = (double)s.njoints;
        double all = inside + at_seams;
        t->mean_gap = (t->mean_gap * inside + s.mean_gap * at_seams) / all;
        t->mean_kink = (t->mean_kink * inside + s.mean_added * at_seams) /
                       all;
        t->max_gap = fmax(t->max_gap, s.max_gap);
        t->max_kink = fmax(t->max_kink, s.max_added);
        assert(t->gaps_over != TOTALS_UNKNOWN &&
               t->kinks_over != TOTALS_UNKNOWN);
        t->gaps_over += s.gaps_over;
        t->kinks_over += s.kinks_over;
    }
    t->feasible = classify_violation(t, c->max_panel_area) == 0;
    return FACET_OK;
}

int project_option_evaluate(const struct project *project,
                            const struct surface_grid *grids,
                            const struct option_params *params, int jobs,
                            struct project_option *out,
                            struct facet_error *err)
{
    return project_option_evaluate_stoppable(project, grids, params, jobs,
                                             NULL, out, err);
}

int project_option_evaluate_stoppable(const struct project *project,
                                      const struct surface_grid *grids,
                                      const struct option_params *params,
                                      int jobs,
                                      const struct facet_stop *stop,
                                      struct project_option *out,
                                      struct facet_error *err)
{
    memset(out, 0, sizeof *out);
    size_t n = project->nsurfaces;
    out->surfaces = calloc(n ? n : 1, sizeof *out->surfaces);
    if (out->surfaces == NULL)
        return facet_error_set(err, FACET_EWORK,
                               "out of memory for an option over %zu "
                               "surfaces", n);
    out->nsurfaces = n;
    jobs = parallel_jobs(jobs, n);
    int rc = evaluate_surfaces(project, grids, params, jobs, stop, out, err);
    if (rc == FACET_OK)
        rc = find_moulds(project, params, jobs, stop, out, err);
    if (rc == FACET_OK) {
        building_totals(out, params);
        rc = measure_seams(project, params, out, err);
    }
    return rc;
}

void project_option_free(struct project_option *option)
{
    for (size_t i = 0; i < option->nsurfaces; i++)
        panelization_free(&option->surfaces[i].panels);
    free(option->surfaces);
    mould_families_free(&option->families);
    memset(option, 0, sizeof *option);
}
