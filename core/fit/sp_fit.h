/*
 * sp_fit.h: single-curved panels as they would be built.
 *
 * Classification calls a panel SP from the signs of its curvatures; this
 * module checks that a panel so typed can be made: a circular cylinder or
 * a circular cone (developable.h) must fit its surface within the flatness
 * threshold t. For every SP panel of a classified panelization:
 *
 *   - its samples are the mesh points inside its UV cell (a point on a cell
 *     line belongs to the panels on both sides) and the surface sampled
 *     along its four sides (cell_sides.h), ends included once;
 *   - a cylinder is fitted by least squares (developable_fit_cylinder) to
 *     the points inside, the corners and the sides' midpoints, the axis
 *     starting along the mean ruling of the points inside: at each
 *     mesh point the principal direction of the smaller |curvature|,
 *     averaged as the major axis of their outer products (directions have
 *     no sign); a panel with no point inside starts from the longest
 *     extent of its samples;
 *   - sp_deviation is the largest distance of the samples from the fitted
 *     surface. The mesh points inside are vertices, on the designer's
 *     surface; the side samples lie on the facets, which sag from it.
 *     Measured there (smooth 0), a panel of a true cylinder reads up to
 *     that sag: right on a fine mesh, whose sag is far below t, but a
 *     coarse mesh makes misfits of panels that fit (a strip on a cylinder
 *     of R = 7.567 m whose facets sag 4.1 mm: "best cylinder 3.8 mm" at
 *     t = 3 mm, 95 % of its area DP at 20 x 35). With smooth 1 the side
 *     samples are taken on the smooth surface through the vertices
 *     instead (cell_sides.h's smooth points, second-order exact on a
 *     quadric), so the fit and its deviation are the designer's surface's.
 *     The caller asks for it when the facets sag more than
 *     FACET_SAG_FRACTION of t (coarse_mesh.h), and only then, so that a
 *     fine mesh's results stay those measured on its facets (which are
 *     the surface there, to far below t). The vertices and not a
 *     reconstruction alone would leave a panel smaller than its facets
 *     with no sample inside and its edges unmeasured;
 *   - when the cylinder misses by more than t, a cone is fitted, from the
 *     cylinder (the cone whose rulings meet at infinity) and from the apex
 *     where the rulings of the points inside converge, the one nearer the
 *     samples (largest distance) kept;
 *   - when neither is within t (rounding allowed as classify.h's threshold
 *     rule), the panel is built DP: a misfit, whose best cylinder and cone
 *     deviations say why (built_panel_reason).
 * Precision: a fit stops when its next step would move the surface by
 * under 0.1 um at the samples (developable.c), so sp_deviation, and the
 * gaps measured on the fitted surfaces, hold to 1 um, and the kinks to
 * 1e-5 rad (a fitted surface's normal at a panel's edge moves more than
 * the surface does at the samples: starting the cylinder fits from a
 * Gauss-Newton step moved gaps by up to 0.97 um and kinks by up to 3.3e-6
 * rad over the paper's space; test_joint pins the fit to a plain
 * least-squares minimiser, and the results on a turned and a mirrored
 * surface to the results on the surface). A misfit's best cone is the
 * exception: on a double-curved panel the least-squares cone may creep
 * along a valley for all of the fit's iterations without converging, and
 * where it stops then depends on the path the fit took (starting the
 * cylinder fits from a Gauss-Newton step moved such cones by up to 0.4 mm
 * over the paper's space); its verdict, no cone within t, did not move.
 * Other panels are built as typed: FP the planar quad of their corners on
 * the best-fit plane (joint.h), DP moulded to the surface.
 */
#ifndef FACET_SP_FIT_H
#define FACET_SP_FIT_H

#include <stddef.h>
#include <stdint.h>

#include "core/base/error.h"
#include "core/base/stop.h"
#include "core/fit/developable.h"
#include "core/joint/cell_sides.h"
#include "core/panel/panel.h"
#include "core/surface/curvature.h"
#include "core/surface/mesh.h"

/* The mesh points with their UV, gathered once per surface: each distinct
 * (vertex, UV) pair of the panels' parameterization, so that a vertex on a
 * UV seam is a sample of the panels on both sides of it. */
struct fit_points {
    size_t npoints;
    const double *uv;          /* npoints x 2, borrowed from the prep */
    uint32_t *vertex;          /* npoints: the mesh vertex of each */
    double *ruling;            /* npoints x 3: unit principal direction of
                                  the smaller |curvature| at it */
};

/* Builds *out from prep (the panel_prep of the surface; it must outlive
 * *out). Release with fit_points_free, also after a failure. Returns
 * FACET_OK or FACET_EWORK when out of memory. */
int fit_points_build(const struct panel_prep *prep, struct fit_points *out,
                     struct facet_error *err);

void fit_points_free(struct fit_points *points);

struct built_panel {
    enum panel_type type;      /* as built: the classified type, except DP
                                  for an SP panel no cylinder or cone fits */
    int fitted;                /* 1: built SP on the surface fit */
    int misfit;                /* 1: typed SP, but no cylinder or cone fits
                                  within t: built DP */
    struct developable fit;    /* the cylinder or cone, when fitted */
    double sp_deviation;       /* largest distance of the samples from fit
                                  (m); for a misfit the smaller of the best
                                  cylinder's and cone's; NaN for a panel
                                  not typed SP */
    double best_cylinder;      /* the fitted cylinder's deviation (m); NaN
                                  when not tried or none fits the samples */
    double best_cone;          /* the fitted cone's (m), NaN likewise */
    double bending_radius;     /* the smallest radius the panel is bent to
                                  on fit (m), over its samples: a
                                  cylinder's radius; on a cone rho / cos a
                                  at the sample nearest the apex (rho its
                                  distance from the axis, a the
                                  half-angle); NaN when not fitted */
};

struct built_option {
    size_t npanels;            /* as the panelization */
    struct built_panel *panels;
    size_t sp_fitted;          /* SP panels built on a cylinder or cone */
    size_t sp_misfits;         /* SP panels no cylinder or cone fits within
                                  t, built DP */
    double threshold;          /* t (m) the fits were held to */
    int smooth;                /* 1: side samples on the smooth surface
                                  through the vertices, 0: on the facets */
};

/* Builds every panel of panels (classified) as above, from the mesh, the
 * surface's fit points and the cell sides of this
 * panelization, with flatness threshold threshold (m), the side samples
 * taken on the smooth surface when smooth is 1, on the facets when 0.
 * Fills *out (release with built_option_free, also after a failure).
 * Returns FACET_OK or FACET_EWORK when out of memory. */
int built_option_fit(const struct mesh *mesh, const struct fit_points *points,
                     const struct panelization *panels,
                     const struct cell_sides *sides, double threshold,
                     int smooth, struct built_option *out,
                     struct facet_error *err);

/* built_option_fit, asking stop every few hundred SP panels fitted: also
 * FACET_ESTOP (stop.h), with *out released. */
int built_option_fit_stoppable(const struct mesh *mesh,
                               const struct fit_points *points,
                               const struct panelization *panels,
                               const struct cell_sides *sides,
                               double threshold, int smooth,
                               const struct facet_stop *stop,
                               struct built_option *out,
                               struct facet_error *err);

void built_option_free(struct built_option *built);

/* What a fabricator reads of b's fit (panel.h's panel_sp_fit), seen from
 * centroid (the panel's, m): shape NONE, its numbers NaN, when b is not
 * built on a fit. */
void built_panel_describe(const struct built_panel *b,
                          const double centroid[3],
                          struct panel_sp_fit *out);

/* The panel built on the fit that fit describes (built_panel_describe's
 * inverse): type SP, fitted, on the same cylinder or cone (up to
 * rounding: a cone's base is its apex), sp_deviation deviation (m) and
 * fit's bending radius; best_cylinder and best_cone NaN (not kept). Returns
 * 0, or -1 and leaves *out alone when fit describes no surface (shape
 * NONE) or lacks a number a panel is developed and scheduled by (a fit
 * stored before schema v13 has no bending radius). */
int built_panel_of_fit(const struct panel_sp_fit *fit, double deviation,
                       struct built_panel *out);

/* The fits of one panel grid, kept across the thresholds it is evaluated
 * at. A grid's panels (panels_build) are the same at every threshold; only
 * their types change. A panel's samples, its cylinder and its cones do not
 * depend on the threshold, only the verdict "within t" does, so they are
 * fitted once, the first time the panel is SP (the cones the first time the
 * cylinder misses), and judged at each threshold. The grid's sides are
 * sampled once, all of them (cell_sides_sample_every).
 *
 * Use: grid_fits_init on the grid's panels (classified or not), then for
 * each threshold, with the panels classified at it, grid_fits_option in
 * place of cell_sides_sample + built_option_fit; joints_measure takes the
 * sides it returns. grid_fits_free when the grid is done. One grid_fits
 * serves one thread. The results are those of cell_sides_sample +
 * built_option_fit to sp_fit.h's precision: only where a side's sample
 * lies on a mesh edge can it differ in its last bits (cell_sides.h);
 * test_joint pins the two to each other over the paper's space. */
struct panel_fits;
struct buckets;
struct grid_fits {
    const struct mesh *mesh;           /* borrowed, as points */
    const struct fit_points *points;
    int nu, nv;
    size_t npanels;
    struct cell_sides sides;           /* every side sampled */
    struct buckets *buckets;           /* each panel's fit points */
    struct panel_fits *fits;           /* npanels: the fits done so far */
    unsigned char *sampled;            /* nsides: the last option's sides */
    int smooth;                        /* the samples fits holds were
                                          taken with */
};

/* Prepares *out for the grid of panels, over the surface mesh with UV
 * lookup index and curvature (as cell_sides_sample) and the surface's fit
 * points (mesh, points: borrowed, to outlive *out). Release with
 * grid_fits_free, also after a failure. Returns FACET_OK or FACET_EWORK
 * when out of memory. */
int grid_fits_init(const struct mesh *mesh, const struct uv_index *index,
                   const struct curvature *curvature,
                   const struct fit_points *points,
                   const struct panelization *panels, struct grid_fits *out,
                   struct facet_error *err);

/* grid_fits_init asking stop as it samples the sides
 * (cell_sides_sample_every_stoppable): also FACET_ESTOP. */
int grid_fits_init_stoppable(const struct mesh *mesh,
                             const struct uv_index *index,
                             const struct curvature *curvature,
                             const struct fit_points *points,
                             const struct panelization *panels,
                             const struct facet_stop *stop,
                             struct grid_fits *out, struct facet_error *err);

/* built_option_fit for panels (the grid's, classified at threshold, m,
 * samples smooth or not) from grid's fits, fitting those not yet done
 * (all of them again when smooth differs from the last call's); fills
 * *out (release with
 * built_option_free) and *sides with the grid's sides as cell_sides_sample
 * would have marked them for these panels: for joints_measure; it borrows
 * grid's arrays until the next grid_fits_option or grid_fits_free (do not
 * cell_sides_free it). Returns FACET_OK or FACET_EWORK when out of
 * memory. */
int grid_fits_option(struct grid_fits *grid,
                     const struct panelization *panels, double threshold,
                     int smooth, struct built_option *out,
                     struct cell_sides *sides, struct facet_error *err);

/* grid_fits_option asking stop every few hundred SP panels fitted: also
 * FACET_ESTOP, with *out released; the fits kept so far stay whole. */
int grid_fits_option_stoppable(struct grid_fits *grid,
                               const struct panelization *panels,
                               double threshold, int smooth,
                               const struct facet_stop *stop,
                               struct built_option *out,
                               struct cell_sides *sides,
                               struct facet_error *err);

void grid_fits_free(struct grid_fits *grid);

/* Why a misfit is built DP, in one line into text (size bytes), e.g. "no
 * cylinder or cone within t = 3.0 mm: best cylinder 4.2 mm, best cone 3.9
 * mm"; the empty string for any other panel. */
void built_panel_reason(const struct built_option *built, size_t panel,
                        char *text, size_t size);

#endif
