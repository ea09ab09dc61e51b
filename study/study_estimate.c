/*
 * study_estimate.c: a new run's time from the earlier runs. See
 * study_estimate.h.
 */
#include "study_estimate.h"

#include <stdlib.h>
#include <string.h>

/* The work of one option of a run over space: its mean grid, or 1 for a
 * project's option. */
static double option_work(const struct design_space *space, int project)
{
    return project ? 1 : design_space_mean_panels(space);
}

int study_rate_measure(struct store *store, const char *surface_path,
                       struct study_rate *rate, struct facet_error *err)
{
    memset(rate, 0, sizeof *rate);
    struct run_info *runs;
    size_t n;
    int rc = store_run_list(store, &runs, &n, err);
    if (rc != FACET_OK)
        return rc;
    for (int same = 1; same >= 0 && rate->runs == 0; same--) {
        double work = 0, seconds = 0;
        for (size_t k = 0; k < n; k++) {
            const struct run_info *r = &runs[k];
            if (r->elapsed <= 0 || r->options <= 0 ||
                (same && (surface_path == NULL ||
                          strcmp(r->surface_path, surface_path) != 0)))
                continue;
            struct design_space space = {r->u_min, r->u_max, r->v_min,
                                         r->v_max, 0, 0, 0};
            work += (double)r->options *
                    option_work(&space, r->module_w_max > 0);
            seconds += r->elapsed;
            rate->runs++;
        }
        if (seconds > 0)
            rate->work_per_second = work / seconds;
    }
    free(runs);
    return FACET_OK;
}

void study_estimate(const struct study_rate *rate,
                    const struct optimize_settings *settings, int project,
                    int64_t *options, double *seconds)
{
    *options = optimize_total(settings);
    *seconds = rate->work_per_second > 0
                   ? (double)*options *
                         option_work(&settings->space, project) /
                         rate->work_per_second
                   : -1;
}
