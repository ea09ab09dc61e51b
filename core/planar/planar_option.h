/*
 * planar_option.h: a planarized option, an option like any other: the
 * panels of a UV grid whose corners were moved off the design surface
 * until every quad is planar (planarize.h), evaluated by the code every
 * option is evaluated by.
 *
 * The grid is evaluated as a classified option first (option_evaluate:
 * its panels, widths and joint length); its corners (quad_grid.h) are
 * planarized; then every full panel (untrimmed, four corners on the
 * surface) becomes its moved quad:
 *   - corners the moved nodes; normal the unit normal to both diagonals,
 *     on the side of the panel's own; centroid, area and diameter the
 *     quad's (the two triangles c0 c1 c2 and c0 c2 c3; the area is the
 *     length of half the diagonals' cross product, exact for a planar
 *     quad);
 *   - deviation its distance to the design surface: the largest distance
 *     to the mesh (nearest.h) over a PLANAR_OPTION_LATTICE^2 lattice of
 *     the quad, its corners among them; P_dist the area times the mean
 *     squared distance over that lattice; corner_planarity quad.h's;
 *   - type FP when the quad is within the planarity tolerance, DP
 *     otherwise (not planar: it must be formed);
 *   - per panel (panelization's corner_distance, corner_moved) the
 *     largest distance of its corners from the mesh and how far they
 *     moved.
 * A trimmed panel, or one with a corner off the surface, keeps its
 * classified self (its corners, where it shares them, were not moved
 * with the grid's; its joints with the moved quads measure the gap).
 * Then option_evaluate_typed builds, joins, moulds and prices the panels:
 * the very code of every option, no second pricing.
 *
 * The totals say planarized 1, the closeness reached (largest and mean
 * corner distance, m) and the planarity reached (largest relative), and
 * planar_over: the quads over the tolerance or with a corner beyond the
 * budget, a limit like gaps_over (classify.h's LIMIT_PLANARIZE), so an
 * option that missed is infeasible, and ranked so, never called planar.
 *
 * Units: metres. Pure computation, no I/O.
 */
#ifndef FACET_PLANAR_OPTION_H
#define FACET_PLANAR_OPTION_H

#include "core/base/error.h"
#include "core/evaluate/option.h"
#include "core/planar/nearest.h"
#include "core/planar/planarize.h"
#include "core/surface/surface.h"

/* The lattice a moved quad is sampled on for its distance to the
 * surface, per side, corners included. */
#define PLANAR_OPTION_LATTICE 5

/* Evaluates the planarized option of params' grid on the prepared
 * surface, its mesh indexed by index (nearest_index_build), planarized
 * with o: fills *panels (released with panelization_free), *totals and
 * *result (the planarization, released with planarize_result_free), all
 * caller-owned and released also after a failure. Returns FACET_OK
 * (feasible or not: totals->planar_over, result->feasible), FACET_EINPUT
 * for a bad grid or a grid without a full quad, FACET_EWORK, FACET_ESTOP
 * when o->stop fired. */
int planar_option_evaluate(const struct surface *surface,
                           const struct nearest_index *index,
                           const struct option_params *params,
                           const struct planarize_options *o,
                           struct panelization *panels,
                           struct option_totals *totals,
                           struct planarize_result *result,
                           struct facet_error *err);

#endif
