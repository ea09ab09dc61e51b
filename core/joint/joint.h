/*
 * joint.h: the gap and the kink at every joint between neighbouring panels.
 *
 * Where flat or single-curved panels replace a curved surface, two
 * neighbouring panels no longer meet exactly: their edges open a gap
 * (Eigensatz et al. 2010's divergence) and meet at an angle, the kink a
 * viewer sees in reflections. A joint is the side two panels' UV cells
 * share (neighbours in i or in j), each counted once, where the surface
 * reaches it.
 *
 * Each panel as built (sp_fit.h) has its own version of the shared edge,
 * and every point x of the edge on the design surface (the side's samples,
 * cell_sides.h) has a place on it:
 *   - FP, a full cell: the nearest point of the quad's edge, the segment
 *     between the two shared corners projected onto the panel's best-fit
 *     plane (panel->centroid, panel->normal). At a corner that is the
 *     corner's projection;
 *   - FP, a trimmed cell (or one with a corner off the surface): x projected
 *     onto the plane, as the trimmed outline is cut (panel_geometry.h);
 *   - SP, fitted: the nearest point of the fitted cylinder or cone;
 *   - DP (and an SP misfit): x itself, the panel follows the surface.
 * The gap is the largest distance between the two places of the same
 * point, over the samples on the surface (m). Between samples the edge is
 * not looked at; CELL_SIDE_SEGMENTS + 1 samples per side, and for a joint
 * between two FP quads its two ends (joint.c says why that is exact to
 * micrometres); a joint between two full DP panels is not sampled, its
 * gap and kink are 0 (both panels follow the surface).
 *
 * The kink is the angle between the two panels' unit normals at the
 * edge's middle sample (the on-surface sample nearest the middle when it
 * is off): FP the plane's normal; SP the fitted surface's normal at the
 * middle's place; DP the surface normal there (interpolated vertex
 * normals). All normals are on the side of the surface's face normals, so
 * a smooth DP-DP joint has no kink. In radians, 0..pi.
 *
 * Ownership: joints_measure fills a caller-owned struct; joints_free
 * releases its arrays.
 */
#ifndef FACET_JOINT_H
#define FACET_JOINT_H

#include <stddef.h>
#include <stdint.h>

#include "core/base/error.h"
#include "core/base/stop.h"
#include "core/fit/sp_fit.h"
#include "core/joint/cell_sides.h"
#include "core/panel/panel.h"

struct joint_edge {
    uint32_t panel[2];   /* the panels either side (indices into the
                            panelization): the lower i, resp. j, first */
    size_t side;         /* the cell side (cell_sides.h numbering) */
    double gap;          /* m */
    double kink;         /* rad */
};

struct joints {
    size_t nedges;
    struct joint_edge *edges;
    size_t npanels;
    double *worst_gap;   /* npanels: the largest gap at the panel's
                            joints (m); 0 for a panel without one */
    double *worst_kink;  /* npanels: likewise (rad) */
    double max_gap, mean_gap;    /* over the joints (m); 0 when none */
    double max_kink, mean_kink;  /* rad */
    size_t gaps_over;    /* joints whose gap exceeds the gap limit */
    size_t kinks_over;   /* joints whose kink exceeds the kink limit */
};

/* The place of surface point x (m) on panel as built (built, its
 * built_panel): the nearest point of its fitted cylinder or cone; x
 * projected onto its plane for FP; x itself for DP. What a joint measures
 * a gap between, but for a full FP quad's side, which joints_measure
 * takes as the straight edge between its corners. */
void joint_place(const struct panel *panel, const struct built_panel *built,
                 const double x[3], double out[3]);

/* Panel's unit normal as built at surface point x, whose surface normal
 * is surface_normal (on its side): the fitted surface's, the plane's (FP)
 * or surface_normal itself (DP). */
void joint_normal(const struct panel *panel, const struct built_panel *built,
                  const double x[3], const double surface_normal[3],
                  double out[3]);

/* Measures the joints of panels (classified), built as built says (from
 * built_option_fit on the same sides), with the surface sampled along
 * the cell sides in sides; counts the gaps above max_gap (m) and the kinks
 * above max_kink (rad). Fills *out (release with joints_free, also after a
 * failure). Returns FACET_OK or FACET_EWORK when out of memory. */
int joints_measure(const struct panelization *panels,
                   const struct built_option *built,
                   const struct cell_sides *sides, double max_gap,
                   double max_kink, struct joints *out,
                   struct facet_error *err);

/* joints_measure, asking stop at every row of cells: also FACET_ESTOP
 * (stop.h), with *out released. */
int joints_measure_stoppable(const struct panelization *panels,
                             const struct built_option *built,
                             const struct cell_sides *sides, double max_gap,
                             double max_kink, const struct facet_stop *stop,
                             struct joints *out, struct facet_error *err);

void joints_free(struct joints *joints);

#endif
