/*
 * surface_table.h: a project option's rows per surface, as `facet show`
 * and `facet options --surfaces` print them: a table (surface name, grid,
 * panels per type, cost, the moulds it starts and uses, its largest
 * deviation, gap and kink) or a JSON array of the same.
 */
#ifndef FACET_SURFACE_TABLE_H
#define FACET_SURFACE_TABLE_H

#include <stddef.h>
#include <stdio.h>

#include "core/out/json.h"
#include "store/store.h"

/* The table of rows[0..n), surfaces[k] naming rows[k], each line after
 * fitted to out's width. */
void surface_table_print(FILE *out, const struct surface_row *surfaces,
                         const struct option_surface_row *rows, size_t n);

/* The same as a JSON array of objects: name, nu, nv, panels, fp_count,
 * sp_count, dp_count, area (m^2), cost (USD), moulds (started),
 * moulds_used, max_deviation (m), max_gap (mm), max_kink (degrees),
 * feasible; null where not measured. */
void surface_table_json(struct json_writer *w,
                        const struct surface_row *surfaces,
                        const struct option_surface_row *rows, size_t n);

#endif
