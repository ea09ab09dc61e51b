/*
 * metric.h: the objectives a designer can optimise an option on.
 *
 * An objective is a quantity of an option (core/quantity/quantity.h) that
 * its row lets be one, to minimise, or, written "max:NAME", to maximise.
 * The names are the quantities', as the JSON, the store and docs/ use
 * them.
 */
#ifndef FACET_METRIC_H
#define FACET_METRIC_H

#include "core/base/error.h"
#include "core/classify/classify.h"
#include "core/quantity/quantity.h"

#define OBJECTIVES_MAX 8

struct objective {
    const struct quantity *quantity;  /* one of option_quantities, whose
                                         objective flag is set */
    int maximise;
};

/* The objective NAME (exactly; no "max:"), minimised: for a caller that
 * knows its own list. Asserts that NAME can be an objective. */
struct objective objective_named(const char *name);

/* Parses "cost,planarity,dp_area" (each optionally "max:NAME") into
 * objectives[0..*count). Returns FACET_OK or FACET_EINPUT naming the
 * field what (the caller's name for it), the unknown metric and listing
 * the valid ones, a repeated one, or more than OBJECTIVES_MAX. */
int objectives_parse(const char *text, const char *what,
                     struct objective *objectives, int *count,
                     struct facet_error *err);

/* objectives[0..count) as objectives_parse reads them, into out
 * ("cost,planarity,max:dp_area"), cut short at size. */
void objectives_format(char *out, size_t size,
                       const struct objective *objectives, int count);

/* The value to minimise for objective o: the quantity, negated when it is
 * maximised. */
double objective_value(const struct option_totals *totals,
                       const struct objective *o);

/* The measures (option.h's option_measure bits) objectives[0..count) need
 * beyond the classified panels: their quantities' stages. */
unsigned objectives_measures(const struct objective *objectives, int count);

#endif
