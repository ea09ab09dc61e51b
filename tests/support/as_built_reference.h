/*
 * as_built_reference.h: the straightforward code of panels as built, kept
 * as the truth the faster code is pinned to.
 *
 * The cell sides (cell_sides.h), the SP fits (developable.h, sp_fit.h)
 * and the joints (joint.h) as they were written first: the normal
 * equations summed point by point through loops over a run-time parameter
 * count, the library's fmin and fmax, each fit's centroid computed where
 * it is used. The faster code in core/ must give every sample, fit,
 * deviation, verdict, gap and kink the same to the bit (test_as_built);
 * this copy is not to be made faster.
 *
 * Test support, not part of Facet: tests/ links it, the binary does not.
 * Each function is its core/ namesake's contract, prefixed reference_;
 * their results are released with the core/ free functions.
 */
#ifndef FACET_AS_BUILT_REFERENCE_H
#define FACET_AS_BUILT_REFERENCE_H

#include "core/fit/developable.h"
#include "core/fit/sp_fit.h"
#include "core/joint/cell_sides.h"
#include "core/joint/joint.h"

double reference_developable_distance(const struct developable *d,
                                      const double x[3]);
void reference_developable_nearest(const struct developable *d,
                                   const double x[3], double point[3],
                                   double normal[3]);
double reference_developable_max_distance(const struct developable *d,
                                          const double *points, size_t n);
void reference_developable_principal_axes(const double *points, size_t n,
                                          double mean[3], double value[3],
                                          double vector[3][3]);
int reference_developable_fit_cylinder(const double *points, size_t n,
                                       const double axis_guess[3],
                                       struct developable *out);
int reference_developable_cone_start(const double *points, size_t n,
                                     const double *at, const double *ruling,
                                     size_t nrulings,
                                     struct developable *out);
int reference_developable_fit_cone(const double *points, size_t n,
                                   const struct developable *start,
                                   struct developable *out);

void reference_cell_sides_mark(const struct panelization *panels,
                               unsigned char *sampled);
int reference_cell_sides_sample(const struct mesh *mesh,
                                const struct uv_index *index,
                                const struct curvature *curvature,
                                const struct panelization *panels,
                                struct cell_sides *out,
                                struct facet_error *err);

int reference_built_option_fit(const struct mesh *mesh,
                               const struct fit_points *points,
                               const struct panelization *panels,
                               const struct cell_sides *sides,
                               double threshold, struct built_option *out,
                               struct facet_error *err);

int reference_joints_measure(const struct panelization *panels,
                             const struct built_option *built,
                             const struct cell_sides *sides, double max_gap,
                             double max_kink, struct joints *out,
                             struct facet_error *err);

/* Classifies panels at threshold t (m), as the paper's space does (SP
 * typed as FP panels priced as FP: sp_as_fp), for the tests that build the
 * paper's panels as built. */
void as_built_classify_at(struct panelization *panels, double t);

#endif
