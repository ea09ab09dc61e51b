/*
 * option_csv.h: design options as CSV, one row each, the columns of the
 * quantity table (quantity.h) in its order after the run: what `facet
 * options --csv` prints and the workbench's E (export marked) writes, so
 * that the two are one layout. Every column name once (sqlite3's .import
 * takes them as they are), with its unit as the panel schedule names
 * it (quantity_csv_name: cost_usd, max_deviation_m); numbers as the shortest text that reads back
 * to the same double (numformat.h), whole numbers without a point; a
 * value not measured (NULL in the store) and crowding at a front's end
 * (infinite) an empty field.
 */
#ifndef FACET_OPTION_CSV_H
#define FACET_OPTION_CSV_H

#include <stdint.h>
#include <stdio.h>

#include "core/quantity/option_row.h"

/* The header line: "run,number,generation,...". */
void option_csv_header(FILE *out);

/* Option o of run as one line. */
void option_csv_row(FILE *out, int64_t run, const struct option_row *o);

#endif
