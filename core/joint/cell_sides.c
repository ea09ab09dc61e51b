/*
 * cell_sides.c: the surface along every cell side. See cell_sides.h.
 *
 * Consecutive samples along a grid line lie in the same mesh triangle or a
 * few triangles on, so each is first looked for by walking there and only
 * then through the UV lookup: a few barycentric tests per sample.
 */
#include "core/joint/cell_sides.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/base/vec3.h"

/* The barycentric tolerance of panels_build's corner lookup, so that a side's
 * ends are the panels' corners. */
#define LOCATE_TOLERANCE 1e-9

/* How far inside a triangle (least barycentric coordinate) a point must
 * lie to be its alone. Nearer an edge, the point may be held by the
 * triangle on the other side too (within rounding, or within
 * LOCATE_TOLERANCE), and which one a walk reaches depends on where it came
 * from. */
#define INSIDE_MARGIN 1e-12

/* fmin(a, b) without the library call, as far as a comparison with a
 * number tells: the smaller, the other where one is NaN (the two may
 * differ in the sign of a zero). */
static double least_of(double a, double b)
{
    if (isnan(a))
        return b;
    if (isnan(b))
        return a;
    return b < a ? b : a;
}

/* The triangle holding (u, v), found by walking from hint across the edge
 * the point lies beyond (a few steps, as consecutive samples are close),
 * else by the lookup; UINT32_MAX when none holds it. A point the walk finds
 * near an edge is looked up as well, so that its triangle, and so its
 * sample to the last bit, is the lookup's whichever sides were sampled
 * before it (cell_sides.h: a side's samples depend on the side alone). */
static uint32_t locate_near(const struct mesh *mesh,
                            const struct uv_index *index, uint32_t hint,
                            double u, double v, double b[3])
{
    uint32_t t = hint;
    for (int step = 0; step < 4 && t != UINT32_MAX; step++) {
        if (!uv_index_barycentric(index, t, u, v, b))
            break;
        double least = least_of(b[0], least_of(b[1], b[2]));
        if (least > INSIDE_MARGIN)
            return t;
        if (least >= -LOCATE_TOLERANCE)
            break;
        /* Across the edge opposite the most negative coordinate: edge e
         * of triangle t runs from corner e to corner e + 1. */
        int k = b[0] < b[1] ? (b[0] < b[2] ? 0 : 2) : (b[1] < b[2] ? 1 : 2);
        uint32_t next = mesh->neighbour[3 * (size_t)t + (size_t)(k + 1) % 3];
        t = next == MESH_NONE ? UINT32_MAX : next;
    }
    return uv_index_locate(index, u, v, LOCATE_TOLERANCE, b);
}

/* The point of triangle t at barycentric b, by its affine map. */
static void point_at(const struct mesh *mesh, uint32_t t, const double b[3],
                     double point[3])
{
    const uint32_t *tri = mesh->triangle + 3 * (size_t)t;
    for (int x = 0; x < 3; x++)
        point[x] = b[0] * mesh->position[3 * (size_t)tri[0] + x] +
                   b[1] * mesh->position[3 * (size_t)tri[1] + x] +
                   b[2] * mesh->position[3 * (size_t)tri[2] + x];
}

/* The point of triangle t at barycentric b on the smooth surface through
 * its vertices (cell_sides.h: Phong, shape factor 1/2), given its point
 * on the facet x. */
static void smooth_at(const struct mesh *mesh,
                      const struct curvature *curvature, uint32_t t,
                      const double b[3], const double x[3], double out[3])
{
    const uint32_t *tri = mesh->triangle + 3 * (size_t)t;
    memcpy(out, x, 3 * sizeof *out);
    for (int k = 0; k < 3; k++) {
        const double *p = mesh->position + 3 * (size_t)tri[k];
        const double *n = curvature->surface_normal + 3 * (size_t)tri[k];
        double d[3];
        vec3_sub(p, x, d);
        double h = 0.5 * b[k] * vec3_dot(d, n);
        for (int c = 0; c < 3; c++)
            out[c] += h * n[c];
    }
}

/* The unit surface normal in triangle t at barycentric b, point x: each
 * corner's surface normal n_i carried halfway to x by its shape operator,
 * n_i - 1/2 S_i (x - p_i) with S_i = k1 d1 d1^T + k2 d2 d2^T (the normal
 * turns by -k along a principal direction), blended by b. The vertex
 * normals interpolated alone bulge out by as much as the corners' tangent
 * extrapolations fall in (the interpolation error of a smooth field is
 * +1/2 sum b_i d_i^T H d_i, the extrapolations' -1/2), so the half step
 * leaves the normal field right to second order, as the smooth surface
 * (smooth_at) is; on the side of the face normal. */
static void normal_at(const struct mesh *mesh,
                      const struct curvature *curvature, uint32_t t,
                      const double b[3], const double x[3], double normal[3])
{
    const uint32_t *tri = mesh->triangle + 3 * (size_t)t;
    memset(normal, 0, 3 * sizeof *normal);
    for (int k = 0; k < 3; k++) {
        size_t v = tri[k];
        const double *n = curvature->surface_normal + 3 * v;
        const double *d1 = curvature->dir1 + 3 * v;
        const double *d2 = curvature->dir2 + 3 * v;
        double d[3];
        vec3_sub(x, mesh->position + 3 * v, d);
        double s1 = 0.5 * curvature->k1[v] * vec3_dot(d, d1);
        double s2 = 0.5 * curvature->k2[v] * vec3_dot(d, d2);
        for (int c = 0; c < 3; c++)
            normal[c] += b[k] * (n[c] - s1 * d1[c] - s2 * d2[c]);
    }
    const double *face = mesh->face_normal + 3 * (size_t)t;
    if (!vec3_normalize(normal))
        memcpy(normal, face, 3 * sizeof *normal);
    if (vec3_dot(normal, face) < 0)
        for (int c = 0; c < 3; c++)
            normal[c] = -normal[c];
}

/* 1 when panel follows the surface over its whole cell: typed DP, not
 * trimmed, every corner on the surface. */
static int full_dp(const struct panel *panel)
{
    return panel->type == TYPE_DP && !panel->trimmed && panel->ncorners == 4;
}

/* What a sampling takes: which sides, and which of their arrays. */
enum sample_what {
    SAMPLE_MARKED,     /* the sides cell_sides_mark marks, in full */
    SAMPLE_EVERY,      /* every side, in full */
    SAMPLE_FITS,       /* the SP panels' sides, their points (and smooth
                          points when asked) alone */
};

/* 1 when the side between the panels a and b (indices, -1 for none) is to
 * be sampled; with fits_only, for the SP fits alone. */
static int needs_samples_for(const struct panelization *panels, int32_t a,
                             int32_t b, int fits_only)
{
    const struct panel *pa = a >= 0 ? &panels->panels[a] : NULL;
    const struct panel *pb = b >= 0 ? &panels->panels[b] : NULL;
    if ((pa != NULL && pa->type == TYPE_SP) ||
        (pb != NULL && pb->type == TYPE_SP))
        return 1;
    if (fits_only || pa == NULL || pb == NULL)
        return 0;
    return !(cell_sides_flat_quad(pa) && cell_sides_flat_quad(pb)) &&
           !(full_dp(pa) && full_dp(pb));
}

/* cell_sides_mark, with fits_only the SP panels' sides alone. */
static void mark(const struct panelization *panels, int fits_only,
                 unsigned char *sampled)
{
    int nu = panels->nu, nv = panels->nv;
    struct cell_sides shape = {.nu = nu, .nv = nv};
    for (int j = 0; j < nv; j++)
        for (int i = 0; i <= nu; i++)
            sampled[cell_side_u(&shape, i, j)] =
                (unsigned char)needs_samples_for(
                    panels, i > 0 ? panels->cell_panel[j * nu + i - 1] : -1,
                    i < nu ? panels->cell_panel[j * nu + i] : -1, fits_only);
    for (int j = 0; j <= nv; j++)
        for (int i = 0; i < nu; i++)
            sampled[cell_side_v(&shape, i, j)] =
                (unsigned char)needs_samples_for(
                    panels, j > 0 ? panels->cell_panel[(j - 1) * nu + i] : -1,
                    j < nv ? panels->cell_panel[j * nu + i] : -1, fits_only);
}

void cell_sides_mark(const struct panelization *panels,
                     unsigned char *sampled)
{
    mark(panels, 0, sampled);
}

/* cell_sides_sample, cell_sides_sample_every or cell_sides_sample_fits
 * as what says (smooth: SAMPLE_FITS's smooth points wanted). */
static int sample(const struct mesh *mesh, const struct uv_index *index,
                  const struct curvature *curvature,
                  const struct panelization *panels, enum sample_what what,
                  int smooth, const struct facet_stop *stop,
                  struct cell_sides *out, struct facet_error *err)
{
    int full = what != SAMPLE_FITS;
    int with_smooth = full || smooth;
    memset(out, 0, sizeof *out);
    int nu = panels->nu, nv = panels->nv;
    out->nu = nu;
    out->nv = nv;
    out->nsides = (size_t)(nu + 1) * (size_t)nv +
                  (size_t)nu * (size_t)(nv + 1);
    size_t nsamples = out->nsides * CELL_SIDE_SAMPLES;
    out->point = malloc(nsamples * 3 * sizeof *out->point);
    out->smooth = with_smooth ? malloc(nsamples * 3 * sizeof *out->smooth)
                              : NULL;
    out->normal = full ? malloc((out->nsides + 1) * 3 * sizeof *out->normal)
                       : NULL;
    out->middle = malloc(out->nsides + 1);
    out->on = malloc(nsamples);
    out->sampled = calloc(out->nsides + 1, 1);
    if (out->point == NULL || (with_smooth && out->smooth == NULL) ||
        (full && out->normal == NULL) || out->on == NULL ||
        out->sampled == NULL || out->middle == NULL) {
        cell_sides_free(out);
        return facet_error_set(err, FACET_EWORK,
                               "out of memory sampling %zu cell sides",
                               out->nsides);
    }
    if (what == SAMPLE_EVERY)
        memset(out->sampled, 1, out->nsides);
    else
        mark(panels, what == SAMPLE_FITS, out->sampled);
    double du = (panels->umax - panels->umin) / nu;
    double dv = (panels->vmax - panels->vmin) / nv;
    /* Along each grid line in turn, so that the walk from sample to sample
     * stays in neighbouring triangles (and in the cache); the first sample
     * of a side is the last of the one before it on the line. */
    uint32_t hint = UINT32_MAX;
    for (int line = 0; line < (nu + 1) + (nv + 1); line++) {
        int rc = facet_stop_check(stop, err);
        if (rc != FACET_OK) {
            cell_sides_free(out);
            return rc;
        }
        int along_v = line <= nu;
        int count = along_v ? nv : nu;
        for (int step = 0; step < count; step++) {
            int i = along_v ? line : step;
            int j = along_v ? step : line - (nu + 1);
            size_t s = along_v ? cell_side_u(out, i, j) : cell_side_v(out, i, j);
            size_t before = step == 0 ? SIZE_MAX
                            : along_v ? cell_side_u(out, i, j - 1)
                                      : cell_side_v(out, i - 1, j);
            if (!out->sampled[s])
                continue;
            if (before != SIZE_MAX && !out->sampled[before])
                before = SIZE_MAX;
            uint32_t triangle[CELL_SIDE_SAMPLES];
            double bary[CELL_SIDE_SAMPLES][3];
            int middle = -1;
            for (int k = 0; k < CELL_SIDE_SAMPLES; k++) {
                size_t at = s * CELL_SIDE_SAMPLES + (size_t)k;
                triangle[k] = UINT32_MAX;
                if (k == 0 && before != SIZE_MAX) {
                    size_t from = before * CELL_SIDE_SAMPLES +
                                  CELL_SIDE_SEGMENTS;
                    out->on[at] = out->on[from];
                    memcpy(out->point + 3 * at, out->point + 3 * from,
                           3 * sizeof *out->point);
                    if (with_smooth)
                        memcpy(out->smooth + 3 * at, out->smooth + 3 * from,
                               3 * sizeof *out->smooth);
                } else {
                    double f = (double)k / CELL_SIDE_SEGMENTS;
                    double u = panels->umin + (i + (along_v ? 0 : f)) * du;
                    double v = panels->vmin + (j + (along_v ? f : 0)) * dv;
                    triangle[k] = locate_near(mesh, index, hint, u, v,
                                              bary[k]);
                    out->on[at] = triangle[k] != UINT32_MAX;
                    if (triangle[k] == UINT32_MAX) {
                        for (int x = 0; x < 3; x++) {
                            out->point[3 * at + x] = NAN;
                            if (with_smooth)
                                out->smooth[3 * at + x] = NAN;
                        }
                        continue;
                    }
                    hint = triangle[k];
                    point_at(mesh, triangle[k], bary[k], out->point + 3 * at);
                    if (with_smooth)
                        smooth_at(mesh, curvature, triangle[k], bary[k],
                                  out->point + 3 * at, out->smooth + 3 * at);
                }
                if (k > 0 && out->on[at] &&
                    (middle < 0 || abs(2 * k - CELL_SIDE_SEGMENTS) <
                                       abs(2 * middle - CELL_SIDE_SEGMENTS)))
                    middle = k;
            }
            /* The normal at the middle, or at the sample nearest it on the
             * surface. Never the first sample: it is copied from the side
             * before when that was sampled (no triangle at hand), so
             * whether it could serve would depend on the other sides. */
            out->middle[s] = (signed char)middle;
            if (!full)
                continue;
            if (middle < 0) {
                for (int x = 0; x < 3; x++)
                    out->normal[3 * s + x] = NAN;
                continue;
            }
            normal_at(mesh, curvature, triangle[middle], bary[middle],
                      out->point + 3 * (s * CELL_SIDE_SAMPLES +
                                        (size_t)middle),
                      out->normal + 3 * s);
        }
    }
    return FACET_OK;
}

int cell_sides_sample(const struct mesh *mesh, const struct uv_index *index,
                      const struct curvature *curvature,
                      const struct panelization *panels,
                      struct cell_sides *out, struct facet_error *err)
{
    return sample(mesh, index, curvature, panels, SAMPLE_MARKED, 0, NULL, out,
                  err);
}

int cell_sides_sample_stoppable(const struct mesh *mesh,
                                const struct uv_index *index,
                                const struct curvature *curvature,
                                const struct panelization *panels,
                                const struct facet_stop *stop,
                                struct cell_sides *out,
                                struct facet_error *err)
{
    return sample(mesh, index, curvature, panels, SAMPLE_MARKED, 0, stop, out,
                  err);
}

int cell_sides_sample_every(const struct mesh *mesh,
                            const struct uv_index *index,
                            const struct curvature *curvature,
                            const struct panelization *panels,
                            struct cell_sides *out, struct facet_error *err)
{
    return sample(mesh, index, curvature, panels, SAMPLE_EVERY, 0, NULL, out,
                  err);
}

int cell_sides_sample_every_stoppable(const struct mesh *mesh,
                                      const struct uv_index *index,
                                      const struct curvature *curvature,
                                      const struct panelization *panels,
                                      const struct facet_stop *stop,
                                      struct cell_sides *out,
                                      struct facet_error *err)
{
    return sample(mesh, index, curvature, panels, SAMPLE_EVERY, 0, stop, out,
                  err);
}

int cell_sides_sample_fits_stoppable(const struct mesh *mesh,
                                     const struct uv_index *index,
                                     const struct curvature *curvature,
                                     const struct panelization *panels,
                                     int smooth,
                                     const struct facet_stop *stop,
                                     struct cell_sides *out,
                                     struct facet_error *err)
{
    return sample(mesh, index, curvature, panels, SAMPLE_FITS, smooth, stop,
                  out, err);
}

int cell_sides_flat_quad(const struct panel *panel)
{
    return panel->type == TYPE_FP && !panel->trimmed && panel->ncorners == 4;
}

void cell_sides_free(struct cell_sides *sides)
{
    free(sides->sampled);
    free(sides->middle);
    free(sides->point);
    free(sides->smooth);
    free(sides->normal);
    free(sides->on);
    memset(sides, 0, sizeof *sides);
}
