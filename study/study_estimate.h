/*
 * study_estimate.h: how long a new run will take, from the earlier runs of
 * its file: what the TUI's New-run form shows under its fields and what
 * `facet optimize` says before a space of hours.
 *
 * Time goes with panels, not options (an option of 2000 x 2000 panels
 * takes a thousand times one of 60 x 60), so a run's work is its options
 * times the mean grid of its space (design_space_mean_panels), and the
 * rate is the earlier runs' work over their seconds. A project run's
 * option counts as one panel's work on both sides: its rate is by option.
 */
#ifndef FACET_STUDY_ESTIMATE_H
#define FACET_STUDY_ESTIMATE_H

#include "core/search/optimize.h"
#include "store/store.h"

struct study_rate {
    double work_per_second;   /* 0: no earlier run to time by */
    int runs;                 /* the runs it was taken from */
};

/* The rate of store's finished runs (some seconds and options), those of
 * surface_path (NULL: none) where there are any, else all of them, into
 * *rate. Returns FACET_OK or the store's error (*rate then unknown). */
int study_rate_measure(struct store *store, const char *surface_path,
                       struct study_rate *rate, struct facet_error *err);

/* What a run of settings (a project's when project) would take: *options
 * at most (optimize_total) and *seconds at rate (-1 when rate is
 * unknown). */
void study_estimate(const struct study_rate *rate,
                    const struct optimize_settings *settings, int project,
                    int64_t *options, double *seconds);

#endif
