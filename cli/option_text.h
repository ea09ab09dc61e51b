/*
 * option_text.h: an evaluated option as a facade engineer reads it in a
 * terminal: the totals per type, planarity, sizes and classes as aligned
 * tables, and the panel map. Shared by `facet classify` and `facet show`.
 */
#ifndef FACET_OPTION_TEXT_H
#define FACET_OPTION_TEXT_H

#include <stdio.h>

#include "core/classify/classify.h"
#include "core/panel/panel.h"

/* The totals tables: per type, planarity and sizes, per class. */
void option_text_totals(FILE *out, const struct option_totals *totals,
                        const struct classify_options *options);

/* The panel grid, one character per panel (F, S, D, '.' for no panel), v
 * upwards; coloured by type when out is stdout on a colour terminal; a
 * note instead when the grid is wider than the terminal. */
void option_text_map(FILE *out, const struct panelization *panels);

/* The option's kind (classified or planarized) and, for a planarized
 * one (core/planar/planar_option.h), what its planarization reached
 * against budget_mm, the run's, and how far its corners moved (its
 * panels p), plainly "INFEASIBLE" when it missed. */
void option_text_kind(FILE *out, const struct option_totals *t,
                      const struct panelization *p, double budget_mm);

#endif
