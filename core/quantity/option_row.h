/*
 * option_row.h: one design option of a run as Facet keeps it: its design
 * point, its totals and its Pareto ranking. A plain struct; the store
 * reads and writes it (store/store.h), core/quantity/quantity.h says
 * where each of its numbers is and how it is shown.
 */
#ifndef FACET_OPTION_ROW_H
#define FACET_OPTION_ROW_H

#include <stddef.h>
#include <stdint.h>

#include "core/classify/classify.h"

/* One design option of a run: its variables and metrics. */
struct option_row {
    int64_t number;            /* No. within the run, 1-based */
    int generation;            /* nsga2 generation, 0 otherwise */
    int nu, nv;                /* grid */
    double threshold_mm;       /* flatness threshold (mm) */
    struct option_totals totals;
    int rank;                  /* Pareto rank, 1 = on the front; 0 until
                                  ranked */
    double crowding;           /* crowding distance (INFINITY at the ends) */
    int knee;                  /* 1 for the run's knee option */
    /* A project's option (schema v8), NaN and TOTALS_UNKNOWN for a single
     * surface's: the module (m) it was met as, and how many modules of
     * the run's range give the same grid on every surface. Its nu and nv
     * are then the module's width and height indices in the range. */
    double module_w, module_h;
    size_t modules;
};

#endif
