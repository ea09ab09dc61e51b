/*
 * metric.h: the option metrics a designer can optimise, rank or filter on,
 * by name, and the objectives built from them.
 *
 * Each metric is a number of struct option_totals (classify.h) under the
 * name the JSON, the store and docs/ use. An objective is a metric to
 * minimise, or, written "max:NAME", to maximise.
 */
#ifndef FACET_METRIC_H
#define FACET_METRIC_H

#include "core/classify/classify.h"
#include "core/base/error.h"

enum metric {
    METRIC_COST,            /* USD */
    METRIC_PLANARITY,       /* m */
    METRIC_DP_AREA,         /* m^2 */
    METRIC_FP_AREA,         /* m^2 */
    METRIC_SP_AREA,         /* m^2 */
    METRIC_PANELS,
    METRIC_FP_COUNT,
    METRIC_SP_COUNT,
    METRIC_DP_COUNT,
    METRIC_MAX_DEVIATION,   /* m */
    METRIC_MAX_PANEL_AREA,  /* m^2 */
    METRIC_P_DIST,          /* m^4 */
    METRIC_MOULDS,          /* SP and DP mould families */
    METRIC_SP_MOULDS,
    METRIC_DP_MOULDS,
    METRIC_JOINT_LENGTH,    /* m */
    METRIC_MAX_GAP,         /* mm: the largest gap at a joint */
    METRIC_MAX_KINK,        /* degrees: the largest kink */
    METRIC_SP_MISFITS,      /* panels classed SP no cylinder or cone fits */
    METRIC_COUNT
};

#define OBJECTIVES_MAX 8

struct objective {
    enum metric metric;
    int maximise;
};

/* "cost", "planarity", ...; NULL for a value outside the enum. */
const char *metric_name(enum metric metric);

/* The metric's value in totals. */
double metric_value(const struct option_totals *totals, enum metric metric);

/* The measures (option.h's option_measure bits) metric needs beyond the
 * classified panels: FITS for sp_misfits, JOINTS for the gap and kink,
 * MOULDS for the mould counts, JOINT_LENGTH for the joint length; 0 for
 * the rest. cost's own terms are the prices' (option_measures_needed). */
unsigned metric_measures(enum metric metric);

/* Parses "cost,planarity,dp_area" (each optionally "max:NAME") into
 * objectives[0..*count). Returns FACET_OK or FACET_EINPUT naming the
 * field what (the caller's name for it), the unknown metric and listing the valid ones, a repeated one, or more than
 * OBJECTIVES_MAX. */
int objectives_parse(const char *text, const char *what,
                     struct objective *objectives, int *count,
                     struct facet_error *err);

/* objectives[0..count) as objectives_parse reads them, into out
 * ("cost,planarity,max:dp_area"), cut short at size. */
void objectives_format(char *out, size_t size,
                       const struct objective *objectives, int count);

/* The value to minimise for objective o: the metric, negated when it is
 * maximised. */
double objective_value(const struct option_totals *totals,
                       const struct objective *o);

#endif
