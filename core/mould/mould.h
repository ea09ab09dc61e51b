/*
 * mould.h: the mould families of a panelization.
 *
 * Mould cost often dominates the cost of a curved panel (Eigensatz et al.
 * 2010), so curved panels that are congruent within a tolerance share one
 * mould. Two panels are congruent when one, moved rigidly onto the other
 * by the least-squares fit of their samples (its corners and surface
 * points at fixed places of its cell: mould_sample.h, mould_fit.h),
 * deviates from it by at most the tolerance at every sample:
 *
 *   deviation <= tolerance + CLASSIFY_ROUNDING x d
 *
 * with d the larger of the two panels' diameters: the rounding allowance
 * of every limit a panel is held to (classify.h), so that panels equal up
 * to rounding are congruent even at a tolerance of 0. A proper move may
 * turn a panel over (install it with its other face out); a mirror image
 * shares the mould only when options->mirror is set (mould_fit.h says why).
 * The 25 samples stand for the panel's surface: between them two panels
 * of one family may differ by a little more, by what a quarter of the cell
 * hides.
 *
 * Jigs. An SP panel built on its fitted cylinder or cone (panel->sp_fit,
 * set by the evaluation: sp_fit.h) is bent on a jig of that surface, and a
 * jig bends any panel that lies on it, whatever its outline (Eigensatz et
 * al. 2010 assign panels to moulds so). With options->jigs set, two such
 * panels share a jig when each lies on the other's fitted surface:
 *
 *   the 25 samples of one as built, against the surface of the other's
 *   fit laid where the jig may lie on them, deviate by at most the limit
 *   above,
 *   and the same the other way round.
 *
 * Laid where the jig may lie: a rigid placement of the other's surface (a
 * cylinder of its radius, a cone of its half-angle; a cylinder's slide
 * along and turn about its axis, a cone's turn about its axis, change
 * nothing). The placement tried first is on the panel's own fitted axis,
 * passing through its own fitted surface at its centroid, which is the
 * panel's own surface when the two fits are one; when that leaves a
 * sample beyond the limit, the least-squares placement from there
 * (developable_fit_congruent), stopped once within the limit. Least
 * squares is not the least largest distance, and only the placement near
 * the panel's own axis is sought (a jig laid across the panel's rulings
 * might fit better and is not looked for), so a pair may share a jig that
 * is not found: the count stays an upper bound, and every member is
 * within the limit of its representative's jig, by a placement found.
 * Before the samples, a closed form: two arcs of curvatures k, k' and
 * width w, laid on one axis, are at best |k - k'| w^2 / 16 apart (half
 * the difference of their sagittas); a pair with |k - k'| w^2 / 16 above
 * the limit (k each panel's bending curvature 1 / radius at its centroid,
 * cos(a) / rho for a cone, w the wider's extent across its axis) is not
 * tested. The samples are the panel as built: its mould samples moved
 * each to the nearest point of its own fitted surface. How far the design
 * lies from that surface is the panel's sp_deviation, held to t by the
 * fit (sp_fit.h); counting it again here made the facets' sag of a coarse
 * mesh keep nearly every panel off every jig, and cost a test against
 * every family in reach for each.
 * The mirror setting does not apply: a cylinder or cone is its own mirror
 * image. A panel typed SP without a fit (a misfit typed by
 * class, options->jigs 0 as under --sp-fit no, or fits not measured) and
 * a trimmed one keep the rule by shape above, in a pool of their own; the
 * DP families are those of the shape rule, whatever the jigs.
 *
 * Families. FP panels need no mould (family -1). SP and DP panels are
 * taken in panel order (over several surfaces, mould_families_build_parts:
 * surface order, then panel order), each type on its own (a single-curved
 * mould is not a double-curved one): each panel joins the first family
 * (in the order families were started) whose representative, the
 * family's first panel, it is congruent to (an SP panel on its jig: whose
 * jig it shares, above), or starts a family. So every member lies within
 * the tolerance of its family's representative, and no representative is
 * congruent to an earlier one. A trimmed panel, whose outline the samples
 * do not see, gets a family of its own.
 *
 * The count is an upper bound. Congruence within a tolerance is not
 * transitive, so finding the fewest families is a covering problem; the
 * greedy count can exceed the least possible, never fall below it (it
 * counts one valid division into families), and trimmed panels add to it.
 *
 * Speed: each panel is tested exactly only against the representatives
 * whose rotation-invariant descriptor (diagonals, sides, spread and bulge
 * of the samples) is within what the tolerance allows, found in a hash
 * grid, so that the work grows with the panels, not with panels x
 * families. The samples of the whole grid are located a band of cells at
 * a time, a point two cells share once (mould_sample_grid), and a test
 * skips the fits that lower bounds show cannot be within the tolerance
 * (mould_congruent). None of this changes a family or a deviation:
 * tests/unit/test_cost_fast.c holds them to the plain greedy, to the bit.
 * The jigs' candidates are the families whose representative's curvature
 * is within the closed form's reach, from a list kept in curvature order.
 *
 * A building. A mould serves congruent panels of any surface of a
 * project, so one search runs over the panels of every surface (parts):
 * each part's panels are sampled on its own surface's mesh and UV, in
 * world coordinates, and then taken as one list. Sampling is a part's own
 * work and may run on several threads; the greedy itself is one pass in
 * that fixed order, so the families do not depend on the threads.
 */
#ifndef FACET_MOULD_H
#define FACET_MOULD_H

#include <stddef.h>

#include "core/base/error.h"
#include "core/base/stop.h"
#include "core/panel/panel.h"
#include "core/surface/mesh.h"
#include "core/surface/uv_index.h"

struct mould_options {
    double tolerance;  /* largest deviation within a family (m), >= 0 */
    int mirror;        /* mirror images may share a mould */
    int jigs;          /* SP panels built on their fitted surface share a
                          jig by it (above); 0 (a zeroed struct): every
                          curved panel by its shape */
    const struct facet_stop *stop;  /* asked every few hundred panels
                                       (stop.h): the build then returns
                                       FACET_ESTOP; NULL never fires */
};

struct mould_families {
    size_t npanels;            /* as the panelization */
    int *family;               /* npanels: the family of each panel,
                                  0..nfamilies-1, or -1 for an FP panel */
    size_t nfamilies;
    size_t *representative;    /* nfamilies: the panel each family's
                                  members are held to (its first) */
    size_t *size;              /* nfamilies: its members */
    size_t count[TYPE_COUNT];  /* families per type; count[TYPE_FP] = 0 */
    size_t largest;            /* members of the largest family, 0 when
                                  there is none */
    size_t singletons;         /* families of one panel */
    size_t trimmed;            /* families of a panel the lattice cannot
                                  sample (a trimmed one): each its own */
    double worst;              /* largest deviation of a member from its
                                  representative (m) */
    size_t fits;               /* exact tests made (the descriptor spares
                                  the others) */
};

/* Finds the mould families of panels, built by panels_build (or _fast, or
 * the lattice) over mesh and index (for a prepared surface s: &s->mesh,
 * &s->uv) and classified (classify_panels: the types are read).
 * Fills *out (caller-owned, released with mould_families_free, also after
 * a failure). Returns FACET_OK, FACET_EINPUT for a tolerance that is
 * negative or not finite or panels not built over index's UV box,
 * FACET_EWORK when out of memory, FACET_ESTOP when options->stop asked. */
int mould_families_build(const struct mesh *mesh,
                         const struct uv_index *index,
                         const struct panelization *panels,
                         const struct mould_options *options,
                         struct mould_families *out,
                         struct facet_error *err);

/* One surface's panels for mould_families_build_parts: panels built over
 * mesh and index (for a prepared surface s: &s->mesh, &s->uv), classified,
 * in world coordinates (m) as every part of one search must be. */
struct mould_part {
    const struct mesh *mesh;
    const struct uv_index *index;
    const struct panelization *panels;
};

/* The mould families of the panels of parts[0 .. nparts), taken as one
 * list: part 0's panels, then part 1's, and so on, so that panel k of
 * part i is number offset_i + k in *out (family, representative), offset_i
 * the panels of the parts before it. Samples the parts on up to jobs
 * threads (1..PARALLEL_MAX, parallel.h); *out does not depend on jobs.
 * With one part it is mould_families_build, to the bit. Same returns,
 * FACET_EINPUT naming the part (1-based) whose panels are not built over
 * its UV map. */
int mould_families_build_parts(const struct mould_part *parts,
                               size_t nparts,
                               const struct mould_options *options,
                               int jobs, struct mould_families *out,
                               struct facet_error *err);

void mould_families_free(struct mould_families *families);

/* The deviation two panels of diameters da and db (m) may have and be
 * congruent under options: tolerance + CLASSIFY_ROUNDING max(da, db). */
double mould_limit(const struct mould_options *options, double da,
                   double db);

#endif
