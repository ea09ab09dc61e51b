/*
 * optimize_nsga2.c: NSGA-II (nsga2.h) over the design space. Variables:
 * nu and nv (integers), and the threshold: the index of its step when the
 * space has a step (an integer), else the value in mm (real, evaluated to
 * a thousandth of a millimetre), absent when the threshold is fixed.
 * Generations go through the shared search batches, so design points the
 * run already has are not evaluated again, and a resumed run replays the
 * algorithm from generation 0 over its stored options (no evaluation) and
 * carries on exactly where the first pass stopped.
 */
#include <math.h>
#include <stdbool.h>
#include <stdlib.h>
#include <string.h>

#include "core/classify/classify.h"
#include "core/search/nsga2.h"
#include "core/search/optimize_internal.h"

struct nsga2_context {
    struct search *search;
    int generation;       /* generation being evaluated */
    int stopped;          /* the stop hook fired between generations */
    size_t nvars;
    int stepped;          /* threshold is a step index */
};

static void point_of_vars(const struct nsga2_context *c, const double *vars,
                          struct design_point *p)
{
    const struct design_space *space = &c->search->settings->space;
    p->nu = (int)lround(vars[0]);
    p->nv = (int)lround(vars[1]);
    if (c->nvars < 3)
        p->threshold_mm = space->t_min_mm;
    else if (c->stepped)
        p->threshold_mm = fmin(space->t_min_mm + lround(vars[2]) *
                                                      space->t_step_mm,
                               space->t_max_mm);
    else
        p->threshold_mm = design_point_threshold_on_grid(vars[2]);
}

static int evaluate(void *context, size_t count, const double *vars,
                    double *objectives, double *violation,
                    struct facet_error *err)
{
    struct nsga2_context *c = context;
    struct search *s = c->search;
    const struct optimize_settings *settings = s->settings;
    struct design_point *points = calloc(count ? count : 1, sizeof *points);
    size_t *index = malloc((count ? count : 1) * sizeof *index);
    int rc = FACET_OK;
    if (points == NULL || index == NULL)
        rc = facet_error_set(err, FACET_EWORK, "out of memory");
    for (size_t k = 0; rc == FACET_OK && k < count; k++)
        point_of_vars(c, vars + k * c->nvars, &points[k]);
    if (rc == FACET_OK)
        rc = search_batch(s, points, count, c->generation, index, NULL,
                          err);
    size_t m = (size_t)settings->nobjectives;
    for (size_t k = 0; rc == FACET_OK && k < count; k++) {
        const struct option_totals *t = &s->known[index[k]].totals;
        for (size_t j = 0; j < m; j++)
            objectives[k * m + j] = objective_value(t,
                                                    &settings->objectives[j]);
        double limit = settings->base.classify.max_panel_area;
        violation[k] = classify_violation(t, limit);
    }
    free(points);
    free(index);
    return rc;
}

static int on_generation(void *context,
                         const struct nsga2_population *population,
                         struct facet_error *err)
{
    struct nsga2_context *c = context;
    c->generation = (int)population->generation + 1;
    const struct optimize_hooks *hooks = c->search->hooks;
    if (hooks->should_stop != NULL && hooks->should_stop(hooks->context)) {
        c->stopped = 1;
        return facet_error_set(err, FACET_EWORK, "stopped");
    }
    return FACET_OK;
}

int run_nsga2(struct search *s, enum optimize_outcome *outcome,
              struct facet_error *err)
{
    const struct optimize_settings *settings = s->settings;
    const struct design_space *space = &settings->space;
    struct nsga2_context c = {s, 0, 0, 2, space->t_step_mm > 0};
    double lower[3] = {space->u_min, space->v_min, space->t_min_mm};
    double upper[3] = {space->u_max, space->v_max, space->t_max_mm};
    bool is_integer[3] = {true, true, c.stepped};
    if (space->t_max_mm > space->t_min_mm) {
        c.nvars = 3;
        if (c.stepped) {
            lower[2] = 0;
            upper[2] = (double)(design_space_size(space) /
                                (uint64_t)((space->u_max - space->u_min + 1) *
                                           (space->v_max - space->v_min + 1)) -
                                1);
        }
    }
    struct nsga2_problem problem = {
        c.nvars, lower, upper, is_integer, (size_t)settings->nobjectives,
        evaluate, &c,
    };
    struct nsga2_settings ga;
    nsga2_settings_default(&ga, c.nvars);
    ga.population = (size_t)settings->population;
    ga.generations = (size_t)settings->generations;
    ga.seed = shard_island_seed(settings->seed, &settings->shard);
    struct nsga2_population result;
    int rc = nsga2_run(&problem, &ga, NULL, on_generation, &c, &result, err);
    if (c.stopped || rc == FACET_ESTOP)
        rc = search_stopped(outcome, err);
    nsga2_free(&result);
    return rc;
}
