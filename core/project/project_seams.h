/*
 * project_seams.h: every seam of a building, found once, and its joints
 * measured for an option (issue 31 item 1).
 *
 * The seams depend on the surfaces alone, not on an option's grids: they
 * are found once a project is prepared (its curvature gives the crease),
 * for every pair of surfaces i < j whose boxes come within the welding
 * tolerance of each other, as seam.h finds them from i. An option's
 * panels then give each seam its joints (seam_joints.h), and the
 * building's seam totals combine them: the largest gap, kink added to the
 * crease and crease; the mean gap and added kink over every seam joint;
 * the joints over the limits; the seams' length.
 *
 * Units: metres and radians. The caller owns both structs; release with
 * project_seams_free.
 */
#ifndef FACET_PROJECT_SEAMS_H
#define FACET_PROJECT_SEAMS_H

#include <stddef.h>

#include "core/base/error.h"
#include "core/base/stop.h"
#include "core/panel/panel.h"
#include "core/project/project.h"
#include "core/project/project_option.h"
#include "core/project/seam.h"
#include "core/project/seam_joints.h"

/* Seam samples at most this far apart along a boundary: several to a
 * panel side of any facade module (0.3 m and up). */
#define PROJECT_SEAM_SPACING 0.05

struct project_seam {
    size_t a, b;          /* the surfaces, a < b (project order) */
    struct seam seam;     /* seen from a */
};

struct project_seams {
    double weld;          /* the welding tolerance they were found at (m) */
    size_t nseams;
    struct project_seam *seams;  /* owned; only pairs that meet */
};

/* The seams of project (prepared) at welding tolerance weld (m, >= 0),
 * asking stop between pairs, into *out. Returns FACET_OK, FACET_EINPUT
 * for a bad weld, FACET_EWORK when out of memory, FACET_ESTOP. */
int project_seams_find(const struct project *project, double weld,
                       const struct facet_stop *stop,
                       struct project_seams *out, struct facet_error *err);

void project_seams_free(struct project_seams *seams);

/* Finds the seams of project (prepared) at weld (m, >= 0), as
 * project_seams_find, and keeps them in project->seams (replacing any),
 * so that every option evaluated over it measures them with its joints
 * (project_option.h): what a building's run does once, after preparing
 * it. A project of one surface has no seam: it keeps none (its options'
 * seam numbers stay not measured, as a single surface's). Same returns as
 * project_seams_find; project->seams is NULL after a failure. */
int project_seams_keep(struct project *project, double weld,
                       const struct facet_stop *stop,
                       struct facet_error *err);

/* A building option's joints at its seams, over all of them. */
struct seam_totals {
    size_t nseams;        /* seams between surfaces */
    double length;        /* their length (m) */
    size_t njoints;       /* pairs of panels meeting along them */
    double max_gap;       /* m; 0 when none */
    double mean_gap;
    double max_added;     /* the kink panels add to the crease (rad) */
    double mean_added;
    double max_crease;    /* the design's own (rad) */
    size_t gaps_over;     /* joints whose gap exceeds the gap limit */
    size_t kinks_over;    /* whose added kink exceeds the kink limit */
};

/* Measures every seam of seams between project's surfaces, each with its
 * panels panels[i] (surface i's, classified and built), gaps over max_gap
 * (m) and added kinks over max_kink (rad) counted (INFINITY: none), into
 * *out. Returns FACET_OK or FACET_EWORK. */
int project_seams_measure(const struct project *project,
                          const struct project_seams *seams,
                          const struct panelization *const *panels,
                          double max_gap, double max_kink,
                          struct seam_totals *out, struct facet_error *err);

/* One seam joint of a building: the seam (its index in seams), its two
 * surfaces and the joint between their panels (seam_joints.h). */
struct building_seam_joint {
    size_t seam;
    size_t a, b;
    struct seam_joint joint;
};

/* Every seam joint of seams between project's surfaces with their panels
 * panels[i], seam by seam, into *out (malloc'ed, free(); NULL when none)
 * and *n: the joints project_seams_measure sums, one by one (the seams
 * schedule of an export). Returns FACET_OK or FACET_EWORK. */
int project_seams_joints(const struct project *project,
                         const struct project_seams *seams,
                         const struct panelization *const *panels,
                         struct building_seam_joint **out, size_t *n,
                         struct facet_error *err);

/* Every seam joint of option, evaluated over project: project_seams_joints
 * over the seams project keeps (project->seams) with the option's
 * surfaces' panels in order, into *out (malloc'ed, free(); NULL when
 * none, as for a project that keeps no seams) and *n. What an export's
 * seams schedule and the workbench's map of a building both read.
 * Returns FACET_OK or FACET_EWORK. */
int project_option_seam_joints(const struct project *project,
                               const struct project_option *option,
                               struct building_seam_joint **out, size_t *n,
                               struct facet_error *err);

#endif
