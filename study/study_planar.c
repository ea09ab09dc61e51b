/*
 * study_planar.c: a run's planarized options (issue 33): beside the
 * classified options of the grids on its Pareto front, each grid's
 * planarized option (core/planar/planar_option.h), stored as any option
 * with its panels, and the run ranked again so that the front shows
 * where planarizing beats classifying.
 *
 * Why the front's grids and not every grid the search evaluates: one
 * planarization is a sparse Gauss-Newton solve of tens of steps (the
 * roof's 100 x 100 grid: 10 s, DESIGN.md), a classified option a few
 * milliseconds; a search of 10^4 grids would take a day. The front's
 * grids are where a cheaper option matters; at most STUDY_PLANARIZE_MAX
 * of them, the knee's first, then by crowding distance (the most spread,
 * the front's ends first), as a large front's panels are stored.
 */
#include "study_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/base/units.h"
#include "core/planar/planar_option.h"

void study_planarize_options(const struct run_info *run,
                             struct planarize_options *o)
{
    planarize_options_defaults(o);
    o->closeness = units_m_of_mm(run->planarize_closeness_mm);
}

int study_planar_evaluate(const struct run_info *run,
                          const struct surface *surface,
                          const struct option_params *params,
                          const struct facet_stop *stop,
                          struct panelization *panels,
                          struct option_totals *totals,
                          struct facet_error *err)
{
    struct nearest_index index;
    struct planarize_result result;
    memset(&index, 0, sizeof index);
    memset(&result, 0, sizeof result);
    memset(panels, 0, sizeof *panels);
    struct planarize_options o;
    study_planarize_options(run, &o);
    o.stop = stop;
    int rc = nearest_index_build(&surface->mesh, &index, err);
    if (rc == FACET_OK)
        rc = planar_option_evaluate(surface, &index, params, &o, panels,
                                    totals, &result, err);
    planarize_result_free(&result);
    nearest_index_free(&index);
    return rc;
}

/* Whether rows[0..n) hold a planarized option of grid nu x nv. */
static int planarized_already(const struct option_row *rows, size_t n,
                              int nu, int nv)
{
    for (size_t k = 0; k < n; k++)
        if (rows[k].totals.planarized && rows[k].nu == nu &&
            rows[k].nv == nv)
            return 1;
    return 0;
}

int study_planarize_front(struct store *store, const struct run_info *run,
                          const struct surface *surface,
                          const struct optimize_settings *settings,
                          const struct study_hooks *hooks, int *stopped,
                          struct facet_error *err)
{
    *stopped = 0;
    if (!(run->planarize_closeness_mm > 0))
        return FACET_OK;
    study_stage(hooks, "planarizing the front's grids");
    struct option_row *rows = NULL;
    size_t n = 0;
    int rc = store_options_get(store, run->id, &rows, &n, err);
    if (rc != FACET_OK)
        return rc;
    int64_t next = 1;
    for (size_t k = 0; k < n; k++)
        if (rows[k].number >= next)
            next = rows[k].number + 1;
    /* The front's classified options, the knee first. */
    struct option_row *front = malloc((n ? n : 1) * sizeof *front);
    size_t nfront = 0;
    if (front == NULL) {
        free(rows);
        return facet_error_set(err, FACET_EWORK, "out of memory");
    }
    for (size_t k = 0; k < n; k++)
        if (rows[k].rank == 1 && !rows[k].totals.planarized)
            front[nfront++] = rows[k];
    qsort(front, nfront, sizeof *front, study_knee_then_spread);
    struct facet_stop stop = study_stop(hooks);
    struct option_params full = settings->base;
    full.unmeasured = 0;
    size_t done = 0;
    for (size_t f = 0; rc == FACET_OK && f < nfront &&
                       done < STUDY_PLANARIZE_MAX; f++) {
        const struct option_row *from = &front[f];
        /* One planarized option per grid: its threshold the front's
         * option's it came from (first in the order above), which types
         * only the panels it leaves unmoved. */
        if (planarized_already(rows, n, from->nu, from->nv))
            continue;
        int earlier = 0;
        for (size_t g = 0; g < f; g++)
            earlier |= front[g].nu == from->nu && front[g].nv == from->nv;
        if (earlier)
            continue;
        struct option_params params =
            option_params_at(&full, from->nu, from->nv, from->threshold_mm);
        struct panelization panels;
        struct option_row row;
        memset(&row, 0, sizeof row);
        rc = study_planar_evaluate(run, surface, &params, &stop, &panels,
                                   &row.totals, err);
        if (rc == FACET_ESTOP) {
            facet_error_clear(err);
            panelization_free(&panels);
            *stopped = 1;
            rc = FACET_OK;
            break;
        }
        row.number = next++;
        row.nu = from->nu;
        row.nv = from->nv;
        row.threshold_mm = from->threshold_mm;
        row.module_w = row.module_h = NAN;
        row.modules = TOTALS_UNKNOWN;
        if (rc == FACET_OK)
            rc = store_options_put(store, run->id, &row, 1, err);
        /* Always with its panels: they cannot be made again by
         * classifying the grid (study_option_panels planarizes again). */
        if (rc == FACET_OK)
            rc = store_panels_put(store, run->id, row.number, &panels, err);
        panelization_free(&panels);
        done++;
    }
    free(front);
    free(rows);
    if (rc == FACET_OK && done > 0) {
        study_stage(hooks, "ranking options");
        rc = study_rank(store, run->id, err);
    }
    return rc;
}
