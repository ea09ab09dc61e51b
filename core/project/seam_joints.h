/*
 * seam_joints.h: the gaps and kinks of the panels as built where two
 * surfaces of a building meet (issue 31 item 1).
 *
 * Along a seam (seam.h) each sample x on a's boundary has a panel of a,
 * the cell of a's grid its UV falls in, and across it the point y of b's
 * boundary with the panel of b there. Each panel has its own version of
 * the seam, as inside a surface (joint.h): x placed on a's panel as built,
 * y on b's (joint_place), and
 *
 *   gap   = |place_a(x) - place_b(y)|, what the design's own |x - y|
 *           (within the welding tolerance) becomes;
 *   kink  = the angle between the two panels' normals as built there
 *           (joint_normal, each on its own surface's side, b's turned as
 *           the seam turns it);
 *   added = |kink - crease|: what the panels add to the design's own
 *           angle between the two surfaces. A ridge the design holds is
 *           not a fabrication defect; the kink limit holds this part.
 *
 * A seam joint is one pair (panel of a, panel of b) that meet along the
 * seam: its gap, kink and added kink are the largest over its samples.
 * Joints with a gap above max_gap and an added kink above max_kink are
 * counted (m, rad; a limit of INFINITY: none over).
 *
 * The panels are read as stored: a panel's type as built and, for SP, its
 * fitted cylinder or cone (panel.h's sp_fit, sp_fit.h's built_panel_of_fit),
 * so a building's stored option measures the same as the evaluation that
 * made it. Pure computation; the caller owns everything.
 */
#ifndef FACET_SEAM_JOINTS_H
#define FACET_SEAM_JOINTS_H

#include <stddef.h>
#include <stdint.h>

#include "core/base/error.h"
#include "core/panel/panel.h"
#include "core/project/seam.h"
#include "core/surface/mesh.h"
#include "core/surface/uv_index.h"

/* One surface at a seam: its mesh, its UV (the index its panels were
 * built over) and its panels, classified and built. Borrowed. */
struct seam_side {
    const struct mesh *mesh;
    const struct uv_index *uv;
    const struct panelization *panels;
};

struct seam_joints {
    size_t njoints;          /* (panel of a, panel of b) pairs */
    double max_gap;          /* m; 0 when no joint */
    double mean_gap;         /* over the joints */
    double max_kink;         /* rad: the panels' own angle */
    double max_added;        /* rad: the part they add to the crease */
    double mean_added;
    double max_crease;       /* rad: the design's, over the samples */
    size_t gaps_over;        /* joints whose gap exceeds max_gap */
    size_t kinks_over;       /* joints whose added kink exceeds max_kink */
};

/* One seam joint: a panel of a and one of b meeting along the seam, its
 * numbers the largest over its samples (m, rad). */
struct seam_joint {
    int32_t panel_a, panel_b;  /* in a's and b's panelizations */
    double gap;
    double kink;               /* the panels' own angle */
    double added;              /* what they add to the crease */
    double crease;             /* the design's */
};

/* The joints along seam (found from a to b), in the order of a's panel,
 * then b's, into *out (malloc'ed, free(); NULL when none) and *n: the
 * joints seam_joints_measure sums. Returns FACET_OK, or FACET_EWORK when
 * out of memory. */
int seam_joints_list(const struct seam *seam, const struct seam_side *a,
                     const struct seam_side *b, struct seam_joint **out,
                     size_t *n, struct facet_error *err);

/* Measures the joints along seam (found from a to b) between a's panels
 * and b's into *out. Returns FACET_OK, or FACET_EWORK when out of memory. */
int seam_joints_measure(const struct seam *seam, const struct seam_side *a,
                        const struct seam_side *b, double max_gap,
                        double max_kink, struct seam_joints *out,
                        struct facet_error *err);

#endif
