/*
 * front.c: ranks, crowding, hypervolume and knee of a run. See front.h.
 */
#include "core/search/front.h"

#include <assert.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/classify/classify.h"
#include "core/search/pareto.h"
#include "core/search/ties.h"

void front_free(struct front *front)
{
    free(front->rank);
    free(front->crowding);
    memset(front, 0, sizeof *front);
}

int front_analyse(const struct evaluated_option *options, size_t n,
                  const struct objective *objectives, int nobjectives,
                  double max_panel_area, struct front *out,
                  struct facet_error *err)
{
    /* ideal and nadir below hold OBJECTIVES_MAX: the run's objectives
     * were parsed against that limit (objectives_parse). */
    assert(nobjectives >= 1 && nobjectives <= OBJECTIVES_MAX);
    memset(out, 0, sizeof *out);
    out->n = n;
    out->knee = SIZE_MAX;
    out->hypervolume = NAN;
    size_t m = (size_t)nobjectives;
    out->rank = calloc(n ? n : 1, sizeof *out->rank);
    out->crowding = calloc(n ? n : 1, sizeof *out->crowding);
    double *value = malloc((n ? n : 1) * m * sizeof *value);
    double *violation = malloc((n ? n : 1) * sizeof *violation);
    double *feasible_front = malloc((n ? n : 1) * m * sizeof *value);
    int rc = FACET_OK;
    if (!out->rank || !out->crowding || !value || !violation ||
        !feasible_front)
        rc = facet_error_set(err, FACET_EWORK, "out of memory (front)");
    if (rc != FACET_OK || n == 0)
        goto done;

    /* Infeasible options are ranked after every feasible one, by how far
     * they are from feasible (classify_violation). */
    double ideal[OBJECTIVES_MAX], nadir[OBJECTIVES_MAX];
    for (size_t j = 0; j < m; j++) {
        ideal[j] = INFINITY;
        nadir[j] = -INFINITY;
    }
    for (size_t i = 0; i < n; i++) {
        const struct option_totals *t = &options[i].totals;
        violation[i] = classify_violation(t, max_panel_area);
        for (size_t j = 0; j < m; j++)
            value[i * m + j] = objective_value(t, &objectives[j]);
    }
    /* Values equal within the run's tolerance (ties.h) are made equal
     * once, here, so that the ranks, the crowding, the knee and the
     * hypervolume's ideal and nadir all see the same ties. */
    rc = ties_merge(value, n, m, value, err);
    if (rc != FACET_OK)
        goto done;
    for (size_t i = 0; i < n; i++)
        for (size_t j = 0; j < m; j++)
            if (violation[i] == 0) {
                ideal[j] = fmin(ideal[j], value[i * m + j]);
                nadir[j] = fmax(nadir[j], value[i * m + j]);
            }
    rc = pareto_rank(value, n, m, violation, out->rank, NULL, err);
    if (rc == FACET_OK)
        rc = pareto_crowding(value, n, m, out->rank, out->crowding, err);
    if (rc != FACET_OK)
        goto done;

    size_t nfront = 0;
    for (size_t i = 0; i < n; i++)
        if (out->rank[i] == 1) {
            out->pareto++;
            if (violation[i] == 0)
                memcpy(feasible_front + m * nfront++, value + m * i,
                       m * sizeof *value);
        }
    /* The hypervolume is in the objectives normalised over the run's
     * feasible options: 0 at the best value any option reached, 1 at the
     * worst, reference point 1.1. */
    if (nfront > 0)
        rc = pareto_hypervolume_normalized(feasible_front, nfront, m, ideal,
                                           nadir, &out->hypervolume, err);
    if (rc == FACET_OK)
        rc = pareto_knee(value, n, m, out->rank, &out->knee, err);
done:
    free(value);
    free(violation);
    free(feasible_front);
    return rc;
}
