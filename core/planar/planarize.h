/*
 * planarize.h: moving a quad grid's corners off the design surface, within
 * a closeness budget, until every quad is planar.
 *
 * The grid starts at its panels' corners (quad_grid.h). The corners x are
 * the unknowns of one least-squares problem with three terms:
 *
 *   planarity   w_p sum over quads of r_q^2, r_q the signed distance
 *               between the quad's diagonals (quad.h's measure, m);
 *   closeness   sum over corners of d_i^2, d_i the distance of corner i
 *               to the mesh, its nearest point (nearest.h) found again at
 *               every iteration, so a corner slides along the surface;
 *   fairness    w_f sum over every three consecutive corners of a grid
 *               line of |D2 (x - x0)|^2, D2 the second difference and x0
 *               the start: the grid keeps the design grid's own
 *               smoothness and gains no kink. (A second difference of x
 *               itself would pull every curved grid line straight and
 *               every dome's corners off it.)
 *
 * Method: Gauss-Newton (Levenberg-Marquardt damped) on that sum. Each
 * step solves one sparse symmetric positive definite system in the 3 N
 * corner coordinates, with SuiteSparse's CHOLMOD: its pattern (corners of
 * a quad, three along a grid line) never changes, so the fill-reducing
 * ordering and the symbolic analysis are made once, and each step only
 * refactors the numbers. Why not ShapeUp's local/global (project each quad
 * onto its best-fit plane, solve a fixed matrix): its fixed point is a
 * compromise between the terms, with planarity only as good as the weight
 * ratio and convergence that slows as that ratio grows; planarity to 1e-6
 * of the diagonal needs the exact residual's derivative, which
 * Gauss-Newton uses from the first step. The planarity weight w_p (1e6)
 * makes planarity come first: a grid that can be made planar near the
 * surface (a conjugate net) ends planar and on it, one that cannot ends
 * planar as near as it can, and the budget says whether that is near
 * enough. The distance's model is the squared distance to the tangent
 * plane at the foot point plus a hundredth of the squared distance to the
 * foot point itself (Pottmann and Hofer's approximation of the squared
 * distance function), so that corners slide along the surface.
 *
 * What a run reports (struct planarize_result): per corner the distance
 * to the mesh and how far it moved, per quad its planarity (m) and that
 * over its longer diagonal; the largest and the mean; the quads over the
 * planarity tolerance; the iterations; and whether the grid is feasible:
 * every quad within the planarity tolerance and every corner within the
 * closeness budget. Infeasible is a result, never called planar.
 *
 * Units: metres; planarity tolerance relative to a quad's diagonal.
 * Pure computation, no I/O, but for loading CHOLMOD at the first solve
 * (sparse_solver.h: only the process that planarizes pays for it).
 */
#ifndef FACET_PLANARIZE_H
#define FACET_PLANARIZE_H

#include <stddef.h>

#include "core/base/error.h"
#include "core/base/stop.h"
#include "core/planar/nearest.h"
#include "core/planar/quad_grid.h"
#include "core/surface/mesh.h"

struct planarize_options {
    double closeness;     /* budget: the farthest a corner may end from
                             the mesh (m, >= 0) */
    double planarity;     /* tolerance: a quad's planarity over its longer
                             diagonal (> 0) */
    int max_iterations;   /* Gauss-Newton steps at most (>= 1) */
    /* Called after each iteration (NULL: not), from the calling thread. */
    void (*progress)(void *context, int iteration, int max_iterations);
    void *progress_context;
    const struct facet_stop *stop;  /* asked every iteration; NULL never */
};

/* The defaults: 5 mm, 1e-3 (0.1 % of the diagonal), 100 iterations. */
void planarize_options_defaults(struct planarize_options *o);

#define PLANARIZE_CLOSENESS_DEFAULT 0.005
#define PLANARIZE_PLANARITY_DEFAULT 1e-3

struct planarize_result {
    struct quad_grid grid;   /* the moved corners; the same quads as the
                                start, nodes of no quad NaN */
    double *distance;        /* per node: to the mesh (m); NaN where no
                                corner of a quad */
    double *moved;           /* per node: from its start (m); NaN as above */
    double *planarity;       /* per quad (m), quad.h's; NaN where no quad */
    double *relative;        /* per quad: planarity over its longer
                                diagonal; NaN where no quad */
    size_t ncorners;         /* nodes that are a quad's corner */
    size_t nquads;
    size_t over;             /* quads over the planarity tolerance */
    double max_distance, mean_distance;   /* over the corners (m) */
    double max_moved;                     /* m */
    double max_planarity;                 /* m */
    double max_relative;
    double start_max_relative;            /* the start grid's */
    int iterations;
    int converged;           /* the last step moved no corner by more than
                                a thousandth of the budget (or 1 um) */
    int feasible;            /* over == 0 and max_distance <= closeness */
};

/* Planarizes start's quads near mesh (indexed by index) with o into *out
 * (caller-owned, released with planarize_result_free, also after a
 * failure). Returns FACET_OK (feasible or not: see out->feasible),
 * FACET_EINPUT for options out of range or a grid without quads,
 * FACET_EWORK when out of memory or when CHOLMOD cannot be loaded or
 * fails, FACET_ESTOP when
 * o->stop fired. */
int planarize(const struct mesh *mesh, const struct nearest_index *index,
              const struct quad_grid *start,
              const struct planarize_options *o,
              struct planarize_result *out, struct facet_error *err);

void planarize_result_free(struct planarize_result *r);

#endif
