/*
 * curvature.h: principal curvatures at every vertex of a surface.
 *
 * Computed once per surface, independent of any panel grid. The estimator
 * fits a quadric (a degree-2 jet; degree 3 where the neighbourhood reaches
 * the boundary and spans a small arc) to each vertex's neighbourhood in a
 * local frame, over a neighbourhood scaled to the local edge length (its 2-
 * or 3-ring), with the higher terms of the osculating sphere or cylinder
 * taken out (straight across a strip one face wide, which cannot tell its
 * curvature across from its slope), and reads the shape operator off the
 * fit; see curvature.c for the details and the accuracy it reaches.
 *
 * Sign convention (DESIGN.md): curvature is negative where the surface bends
 * away from its normal, so a dome seen from outside, with the normal
 * pointing out, has k1, k2 < 0 ("convex"). The normal is the vertex normal
 * from vn when the file has normals, otherwise from the face winding;
 * flip_normals reverses it (and so every sign).
 */
#ifndef FACET_CURVATURE_H
#define FACET_CURVATURE_H

#include <stddef.h>

#include "core/base/error.h"
#include "core/base/stop.h"
#include "core/surface/mesh.h"

/* How many of its errors (k1_error, k2_error) a curvature's estimate is
 * taken to be known to, either way: the range a panel's curvature is
 * known to (panel.h) and so whether it counts as zero (classify.h). The
 * errors are the fits' standard errors, which on coarse analytic meshes
 * (tests/unit/test_classify_developable) came within a factor 3.5 of
 * the true error at every vertex of a cone and a parabolic cylinder. */
#define CURVATURE_ERROR_SIGMAS 4.0

struct curvature {
    size_t nvertices;
    double *k1;        /* #V maximum principal curvature (1/m) */
    double *k2;        /* #V minimum principal curvature (1/m), k2 <= k1 */
    double *dir1;      /* #V x 3 unit principal direction of k1 */
    double *dir2;      /* #V x 3 unit principal direction of k2 */
    double *normal;    /* #V x 3 unit vertex normal that fixes the sign */
    double *surface_normal;  /* #V x 3 the surface's unit normal as exactly
                                as the fit knows it: where the fit was a
                                quadric off the boundary, the normal of a
                                cubic jet refitted in its final frame,
                                whose gradient does not take in the cubic
                                term of a changing curvature (z = x^2/8 at
                                60 x 40 quads: the quadric's normal 0.048
                                degrees off, the cubic's 0.0005); else
                                normal (on the boundary the fit's, a cubic
                                where one-sided points allow it: within 2
                                degrees on coarse analytic meshes, half
                                the angle across on a strip one face wide,
                                tests/unit/test_curvature_boundary). On
                                normal's side; for joints and the smooth
                                surface through the vertices
                                (cell_sides.h) */
    double *k1_error;  /* #V how well k1 is known (1/m): the standard
                          error of the fit's curvature along dir1, by its
                          own residual and normal equations (curvature.c's
                          fit_error), on points all round the vertex with
                          the scatter a cubic leaves and no less than how
                          far the cubic reads it. 0 on spheres, cylinders
                          and planes, which the fit follows exactly;
                          largest where the neighbourhood is one-sided or
                          coarse and the curvature changes across it.
                          classify.h's zero test reads it */
    double *k2_error;  /* #V the same for k2, along dir2 */
};

/* Estimates curvature at every vertex of mesh into *out (caller-owned,
 * released with curvature_free, also after a failure). Returns FACET_OK,
 * FACET_EWORK when out of memory (FACET_EINPUT for 2^32 - 1 vertices or
 * more). Isolated or degenerate vertices (no neighbourhood a quadric can be
 * fitted to) get k1 = k2 = 0; one with no normal at all gets +z (-z when
 * flipped). Every value is finite. */
int curvature_at_vertices(const struct mesh *mesh, int flip_normals,
                          struct curvature *out, struct facet_error *err);

/* curvature_at_vertices on jobs threads (1 to 8; clamped), which is what
 * that does with the online CPUs: each vertex is estimated on its own, so
 * the result is the same, bit for bit, whatever jobs is. */
int curvature_at_vertices_jobs(const struct mesh *mesh, int flip_normals,
                               int jobs, struct curvature *out,
                               struct facet_error *err);

/* curvature_at_vertices, asking stop (stop.h) before each chunk of 512
 * vertices (about a millisecond of work): FACET_ESTOP when it fires. */
int curvature_at_vertices_stoppable(const struct mesh *mesh,
                                    int flip_normals,
                                    const struct facet_stop *stop,
                                    struct curvature *out,
                                    struct facet_error *err);

void curvature_free(struct curvature *curvature);

#endif
