/*
 * planar_obj.h: a planarized grid (core/planar/planarize.h) as Wavefront
 * OBJ, for CAD and for checking.
 *
 * One vertex per corner of a quad, in the order of the grid's nodes (j,
 * then i), at its moved place (m, to 17 significant digits, so that a
 * reader measures what Facet measured); one face per quad, `f` of its
 * four corners in quad_grid.h's order (i, j), (i + 1, j), (i + 1, j + 1),
 * (i, j + 1), in the group `g quad_I_J`. The header comment says what
 * was asked and reached: the budget, the tolerance, the closeness and
 * planarity reached, and whether the grid is feasible; an infeasible
 * grid's file says so in its first line.
 */
#ifndef FACET_PLANAR_OBJ_H
#define FACET_PLANAR_OBJ_H

#include <stdio.h>

#include "core/base/error.h"
#include "core/planar/planarize.h"

/* Writes r, planarized with o from the surface named source, to out.
 * Returns FACET_OK, or FACET_EWORK when out of memory (nothing written). */
int planar_obj_write(FILE *out, const char *source,
                     const struct planarize_options *o,
                     const struct planarize_result *r,
                     struct facet_error *err);

#endif
