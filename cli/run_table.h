/*
 * run_table.h: a run's options as the paper's Table 2 (No., total
 * planarity, DP area, total cost, FP area, SP area, U, V, threshold, a
 * mark for the Pareto options), sorted like the paper's: by total cost,
 * cheapest first. Printed by `facet optimize` at the end of a run.
 */
#ifndef FACET_RUN_TABLE_H
#define FACET_RUN_TABLE_H

#include <stdio.h>

#include "store/store.h"

/* Prints the run's summary line and its table: every Pareto option, then
 * the best-ranked others, rows in all (0 = every option; a front longer
 * than rows is cut, its cheapest first, and says so), fitted to the
 * terminal unless wide is set (text_table.h); then a note when the front
 * sits on a bound of the design space. */
int run_table_print(FILE *out, struct store *store, const char *db,
                    int64_t run, long rows, int wide,
                    struct facet_error *err);

#endif
