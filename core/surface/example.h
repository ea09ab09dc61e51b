/*
 * example.h: the example surfaces Facet ships, generated, not stored.
 *
 * Each example is a parametric surface S(s, t) on the unit square, sampled on
 * a regular grid and triangulated, with vt = (s, t) its surface parameters,
 * as a CAD export of a NURBS face carries them. Lengths are metres.
 *
 *   plane, cylinder, dome, hypar, torus, wave, roof: example.c's header
 *   gives each surface's exact formula, the oracle tests compare against.
 *
 * roof is the case-study stand-in: a free-form roof of about 1,240 m^2 with
 * flat, single-curved and double-curved regions.
 *
 * skin is a whole building of 180 faces (example_skin.h), a project rather
 * than one surface: example_write writes it by that name, but it is not in
 * example_names, whose entries are single surfaces with example_point.
 */
#ifndef FACET_EXAMPLE_H
#define FACET_EXAMPLE_H

#include <stdio.h>

#include "core/base/error.h"

/* The example names, NULL-terminated, in the order --help lists them. */
extern const char *const example_names[];

/* One line describing the named example, or NULL if there is no such name. */
const char *example_describe(const char *name);

/* Evaluates the named example at surface parameters (s, t) in [0,1]^2 into
 * p (m). Returns 0, or -1 for an unknown name. */
int example_point(const char *name, double s, double t, double p[3]);

/* Writes the named example as OBJ text to out, sampled on res x res quads
 * (res 0 picks the example's default; for skin, per face). Returns
 * FACET_OK, FACET_EINPUT for an unknown name or a res outside 1..4096
 * (skin: 1..SKIN_MAX_RES), FACET_EWORK for a write error. */
int example_write(const char *name, int res, FILE *out,
                  struct facet_error *err);

#endif
