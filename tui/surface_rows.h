/*
 * surface_rows.h: the per-surface rows of a project option (the Surfaces
 * screen, screen_surfaces.c) as text, without curses: one line per
 * surface of what option_surfaces holds for it, under one header, in 79
 * characters (80x24 shows them whole). The unit tests pin the columns.
 *
 *   surface        grid panels   FP   SP   DP      cost  moulds   dev   gap  kink
 *                                                 USD st/used    mm    mm   deg
 *
 * grid nu x nv; FP, SP, DP the panels of each type; cost USD, whole
 * dollars with thousands separators; moulds "STARTED/USED" (the families
 * it starts, which add up to the building's, and those its panels use,
 * some started on an earlier surface: project_option.h); the largest
 * deviation (mm), gap (mm) and kink (degrees) on it, 2 decimals, "-"
 * where the store has none (a joint never measured).
 */
#ifndef FACET_TUI_SURFACE_ROWS_H
#define FACET_TUI_SURFACE_ROWS_H

#include <stddef.h>

#include "store/store.h"

/* The width of a header or row. */
#define SURFACE_ROW_WIDTH 79

/* The header's two lines: the columns' names, then their units, each
 * SURFACE_ROW_WIDTH characters. */
void surface_rows_header(char *names, char *units, size_t size);

/* Surface name's row r (its name cut to fit, the cut marked "~"). */
void surface_rows_line(char *out, size_t size, const char *name,
                       const struct option_surface_row *r);

#endif
