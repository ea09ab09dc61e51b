/*
 * param_harmonic.h: the mean-value (harmonic) parameterization of a
 * disk-like surface, holes included.
 *
 * The outer boundary (the longest boundary loop, in metres) goes to a
 * rectangle when it has four clear corners (boundary vertices where the
 * surface's angle is under 135 degrees), keeping the sides' lengths, and to
 * a circle by arc length otherwise. Every other loop is a hole: it is
 * capped by a fan around the mean of its vertices for the solve, so that
 * the capped surface is a disk, and the caps are dropped afterwards. The
 * inside follows Floater's mean-value weights, which are positive, so the
 * map of the capped disk onto a convex boundary never folds (Tutte,
 * Floater 2003).
 */
#ifndef FACET_PARAM_HARMONIC_H
#define FACET_PARAM_HARMONIC_H

#include <stddef.h>

#include "core/base/stop.h"
#include "core/surface/mesh.h"

/* Computes per-vertex (u, v) for mesh into *vertex_uv (#V x 2, malloc'ed,
 * the caller's to free) and the number of holes capped into *holes.
 * Returns FACET_OK; FACET_EINPUT when the surface is not a disk with holes
 * (several pieces, closed, non-manifold, a handle) or the solve did not
 * converge, with why (size bytes) saying which; FACET_EWORK when out of
 * memory; FACET_ESTOP when stop (stop.h, or NULL) fired. */
int param_harmonic(const struct mesh *mesh, const struct facet_stop *stop,
                   double **vertex_uv, size_t *holes, char *why,
                   size_t size);

#endif
