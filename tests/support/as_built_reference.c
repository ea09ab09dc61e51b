/*
 * as_built_reference.c: panels as built, the straightforward way. See
 * as_built_reference.h. The code of core/fit/developable.c,
 * core/joint/cell_sides.c, core/fit/sp_fit.c (built_option_fit) and
 * core/joint/joint.c (joints_measure) as of
 * commit 1e0eced, renamed; leave it as it is.
 */
#include "tests/support/as_built_reference.h"

#include <assert.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/base/linalg.h"
#include "core/base/sym3.h"
#include "core/base/vec3.h"
#include "core/classify/classify.h"
#include "core/joint/joint.h"
#include "core/panel/panel_geometry.h"

#define FIT_MAX_ITERATIONS 100
#define REFERENCE_PI 3.14159265358979323846

/* A fit has converged when its next (Gauss-Newton) step would move the
 * surface by less than this at the points (root mean square, m): a tenth
 * of a micrometre, so that deviations of millimetres come out the same to
 * a micrometre however the surface is placed. Converging by distance rather than by parameters
 * ends a fit whose parameters wander along a valley that hardly moves the
 * surface (the apex of a nearly cylindrical cone). */
#define FIT_STEP 1e-7

/* The least damping of a Levenberg-Marquardt step, relative to the
 * diagonal of the normal equations. */
#define LAMBDA_FLOOR 1e-12

/* Two unit vectors completing axis to an orthonormal frame. */
static void frame(const double axis[3], double e1[3], double e2[3])
{
    double pick[3] = {0, 0, 0};
    int k = 0;
    for (int x = 1; x < 3; x++)
        if (fabs(axis[x]) < fabs(axis[k]))
            k = x;
    pick[k] = 1;
    vec3_cross(axis, pick, e1);
    vec3_normalize(e1);
    vec3_cross(axis, e1, e2);
}

/* The point's height along the axis h, its distance from it rho and the
 * unit direction u from the axis to it (any direction across the axis when
 * the point is on it). */
static void cylindrical(const struct developable *d, const double x[3],
                        double *h, double *rho, double u[3])
{
    double q[3];
    vec3_sub(x, d->base, q);
    *h = vec3_dot(q, d->axis);
    for (int k = 0; k < 3; k++)
        u[k] = q[k] - *h * d->axis[k];
    *rho = vec3_length(u);
    if (!vec3_normalize(u)) {
        double e2[3];
        frame(d->axis, u, e2);
    }
}

double reference_developable_distance(const struct developable *d,
                                      const double x[3])
{
    double q[3];
    vec3_sub(x, d->base, q);
    double h = vec3_dot(q, d->axis);
    double rho = sqrt(fmax(vec3_dot(q, q) - h * h, 0));
    return (rho - d->radius - d->slope * h) / sqrt(1 + d->slope * d->slope);
}

void reference_developable_nearest(const struct developable *d,
                                   const double x[3], double point[3],
                                   double normal[3])
{
    double h, rho, u[3];
    cylindrical(d, x, &h, &rho, u);
    double w = 1 / sqrt(1 + d->slope * d->slope);
    double f = (rho - d->radius - d->slope * h) * w;
    double foot_h = h + f * w * d->slope, foot_rho = rho - f * w;
    for (int k = 0; k < 3; k++) {
        if (point != NULL)
            point[k] = d->base[k] + foot_h * d->axis[k] + foot_rho * u[k];
        if (normal != NULL)
            normal[k] = (u[k] - d->slope * d->axis[k]) * w;
    }
}

double reference_developable_max_distance(const struct developable *d,
                                const double *points, size_t n)
{
    double worst = 0;
    for (size_t k = 0; k < n; k++)
        worst = fmax(worst,
                     fabs(reference_developable_distance(d, points + 3 * k)));
    return worst;
}

/* Moves d's base along its axis into the plane through centroid, keeping
 * the surface. */
static void recentre(struct developable *d, const double centroid[3])
{
    double q[3];
    vec3_sub(centroid, d->base, q);
    double t = vec3_dot(q, d->axis);
    for (int k = 0; k < 3; k++)
        d->base[k] += t * d->axis[k];
    d->radius += d->slope * t;
}

static void centroid_of(const double *points, size_t n, double out[3])
{
    out[0] = out[1] = out[2] = 0;
    for (size_t k = 0; k < n; k++)
        for (int x = 0; x < 3; x++)
            out[x] += points[3 * k + x];
    for (int x = 0; x < 3; x++)
        out[x] /= (double)n;
}

void reference_developable_principal_axes(const double *points, size_t n,
                                double mean[3], double value[3],
                                double vector[3][3])
{
    double cov[9] = {0};
    centroid_of(points, n, mean);
    for (size_t k = 0; k < n; k++)
        for (int r = 0; r < 3; r++)
            for (int c = 0; c < 3; c++)
                cov[3 * r + c] += (points[3 * k + r] - mean[r]) *
                                  (points[3 * k + c] - mean[c]);
    sym3_eigen(cov, value, vector);
}

/* d moved by step (base across the axis by step[0], step[1] along e1, e2;
 * axis tilted by step[2], step[3]; radius by step[4]; slope by step[5]
 * when np is 6). */
static void apply_step(const struct developable *d, const double e1[3],
                       const double e2[3], const double *step, int np,
                       const double centroid[3], struct developable *out)
{
    *out = *d;
    for (int k = 0; k < 3; k++) {
        out->base[k] += step[0] * e1[k] + step[1] * e2[k];
        out->axis[k] += step[2] * e1[k] + step[3] * e2[k];
    }
    vec3_normalize(out->axis);
    out->radius += step[4];
    if (np == 6)
        out->slope += step[5];
    recentre(out, centroid);
}

/* The sum of squared distances of points from d, and the normal
 * equations of its linearisation in the parameters of apply_step (frame
 * e1, e2 of d's axis) into jtj (6 x 6, lower triangle of the leading np x
 * np block) and jtr. In that frame a point sits at X = q.e1, Y = q.e2 and
 * h = q.axis from the base (q = x - base), at rho = |(X, Y)| from the
 * axis. */
static double linearize(const struct developable *d, const double *points,
                        size_t n, int np, const double e1[3],
                        const double e2[3], double jtj[36], double jtr[6])
{
    memset(jtj, 0, 36 * sizeof *jtj);
    memset(jtr, 0, 6 * sizeof *jtr);
    double w = 1 / sqrt(1 + d->slope * d->slope), sum = 0;
    for (size_t k = 0; k < n; k++) {
        double q[3];
        vec3_sub(points + 3 * k, d->base, q);
        double x = vec3_dot(q, e1), y = vec3_dot(q, e2);
        double h = vec3_dot(q, d->axis), rho = sqrt(x * x + y * y);
        double ux = rho > 0 ? x / rho : 1, uy = rho > 0 ? y / rho : 0;
        double g = rho - d->radius - d->slope * h, f = g * w;
        double row[6] = {
            -ux * w, -uy * w,
            (-h * ux - d->slope * x) * w,
            (-h * uy - d->slope * y) * w,
            -w,
            -h * w - g * d->slope * w * w * w,
        };
        sum += f * f;
        for (int r = 0; r < np; r++) {
            jtr[r] += row[r] * f;
            for (int c = 0; c <= r; c++)
                jtj[r * 6 + c] += row[r] * row[c];
        }
    }
    return sum;
}

/* Sets d's radius and slope to the best for its axis: in the half-plane
 * through the axis each point is (h, rho), and the cone is the line rho =
 * radius + slope h there, at distance (rho - radius - slope h) / sqrt(1 +
 * slope^2) from it; the line minimising the sum of squares of those is the
 * principal axis of the points (h, rho) (total least squares). Solving
 * these two exactly at every step keeps a cone fit from crawling along the
 * valley where slope and axis trade off. Leaves d alone when the line is
 * steeper than 60 degrees from the axis (the points give no cone). */
static void best_line(struct developable *d, const double *points, size_t n)
{
    double mh = 0, mr = 0, hh = 0, hr = 0, rr = 0;
    for (size_t k = 0; k < n; k++) {
        double q[3];
        vec3_sub(points + 3 * k, d->base, q);
        double h = vec3_dot(q, d->axis);
        double rho = sqrt(fmax(vec3_dot(q, q) - h * h, 0));
        mh += h;
        mr += rho;
        hh += h * h;
        hr += h * rho;
        rr += rho * rho;
    }
    mh /= (double)n;
    mr /= (double)n;
    hh = hh / (double)n - mh * mh;
    hr = hr / (double)n - mh * mr;
    rr = rr / (double)n - mr * mr;
    double value[2], theta;
    linalg_sym2_eigen(hh, hr, rr, value, &theta);
    if (!(fabs(theta) < REFERENCE_PI / 3))
        return;
    d->slope = tan(theta);
    d->radius = mr - d->slope * mh;
}

/* x.m.x for the symmetric m (6 x 6, lower triangle of the leading np x np
 * block). */
static double quadratic(const double m[36], const double x[6], int np)
{
    double sum = 0;
    for (int r = 0; r < np; r++)
        for (int c = 0; c < np; c++)
            sum += x[r] * x[c] * m[r > c ? r * 6 + c : c * 6 + r];
    return sum;
}

/* Levenberg-Marquardt on d over np parameters (5: cylinder, 6: cone).
 * Each trial step is linearised where it lands, so that an accepted step
 * (the usual case) costs one pass over the points. Returns 0, or -1 when
 * the surface leaves the finite. */
static int refine(struct developable *d, const double *points, size_t n,
                  int np)
{
    double centroid[3], e1[3], e2[3], jtj[36], jtr[6];
    centroid_of(points, n, centroid);
    recentre(d, centroid);
    if (np == 6)
        best_line(d, points, n);
    frame(d->axis, e1, e2);
    double cost = linearize(d, points, n, np, e1, e2, jtj, jtr);
    /* Damping as Nielsen's: scaled by how well the linearisation
     * predicted the last decrease, doubling its growth on each miss. It
     * starts at its floor, a Gauss-Newton step: a panel is a small patch
     * of its cylinder, where moving the axis towards the points and
     * shrinking the radius by as much hardly moves the surface, so the
     * normal equations are ill-conditioned (1e-7 and worse), and even a
     * damping of 1e-6 of their diagonal cuts the step along that valley
     * short, taking twice the iterations to converge to the same fit. A
     * step that does not pay raises the damping as before. */
    double lambda = np == 6 ? 1e-6 : LAMBDA_FLOOR, grow = 2;
    for (int iteration = 0; iteration < FIT_MAX_ITERATIONS; iteration++) {
        double b[6], step[6] = {0};
        for (int r = 0; r < np; r++)
            b[r] = -jtr[r];
        /* Converged when the undamped (Gauss-Newton) step would move the
         * surface at the points by less than FIT_STEP: |J step|^2 =
         * step.jtj.step. */
        if (linalg_cholesky_solve(np, 6, jtj, b, 1e-14, step) &&
            quadratic(jtj, step, np) <= (double)n * FIT_STEP * FIT_STEP)
            break;
        double a[36];
        memcpy(a, jtj, sizeof a);
        for (int r = 0; r < np; r++)
            a[r * 6 + r] += lambda * jtj[r * 6 + r];
        if (!linalg_cholesky_solve(np, 6, a, b, 1e-14, step)) {
            lambda *= grow;
            grow *= 2;
            if (lambda > 1e12)
                break;
            continue;
        }
        double along = 0, moved = quadratic(jtj, step, np);
        for (int r = 0; r < np; r++)
            along += b[r] * step[r];
        struct developable trial;
        double te1[3], te2[3], tjtj[36], tjtr[6];
        apply_step(d, e1, e2, step, np, centroid, &trial);
        if (np == 6)
            best_line(&trial, points, n);
        frame(trial.axis, te1, te2);
        double trial_cost = linearize(&trial, points, n, np, te1, te2, tjtj,
                                      tjtr);
        /* The decrease the linearisation promises: 2 b.step - |J step|^2. */
        double promised = 2 * along - moved;
        if (isfinite(trial_cost) && trial_cost < cost && promised > 0) {
            double rho = (cost - trial_cost) / promised;
            double t = 2 * rho - 1;
            lambda *= fmax(1.0 / 3, 1 - t * t * t);
            lambda = fmax(lambda, LAMBDA_FLOOR);
            grow = 2;
            *d = trial;
            cost = trial_cost;
            memcpy(e1, te1, sizeof te1);
            memcpy(e2, te2, sizeof te2);
            memcpy(jtj, tjtj, sizeof tjtj);
            memcpy(jtr, tjtr, sizeof tjtr);
        } else {
            lambda *= grow;
            grow *= 2;
            if (lambda > 1e12)
                break;
        }
    }
    if (!isfinite(d->radius) || !isfinite(d->slope) || !(d->radius > 0))
        return -1;
    return 0;
}

int reference_developable_fit_cylinder(const double *points, size_t n,
                             const double axis_guess[3],
                             struct developable *out)
{
    if (n < 5)
        return -1;
    double axis[3] = {axis_guess[0], axis_guess[1], axis_guess[2]};
    if (!vec3_normalize(axis))
        return -1;
    double centroid[3], e1[3], e2[3];
    centroid_of(points, n, centroid);
    frame(axis, e1, e2);
    /* The algebraic circle X^2 + Y^2 + D X + E Y + F = 0 of the points
     * projected along the axis (Kasa): linear, and exact for points on a
     * cylinder about that axis. */
    double a[9] = {0}, b[3] = {0}, s[3];
    for (size_t k = 0; k < n; k++) {
        double q[3];
        vec3_sub(points + 3 * k, centroid, q);
        double row[3] = {vec3_dot(q, e1), vec3_dot(q, e2), 1};
        double rhs = -(row[0] * row[0] + row[1] * row[1]);
        for (int r = 0; r < 3; r++) {
            b[r] += row[r] * rhs;
            for (int c = 0; c <= r; c++)
                a[r * 3 + c] += row[r] * row[c];
        }
    }
    if (!linalg_cholesky_solve(3, 3, a, b, 1e-12, s))
        return -1;
    double cx = -s[0] / 2, cy = -s[1] / 2;
    double r2 = cx * cx + cy * cy - s[2];
    if (!(r2 > 0) || !isfinite(r2))
        return -1;
    struct developable d;
    d.shape = DEVELOPABLE_CYLINDER;
    memcpy(d.axis, axis, sizeof d.axis);
    for (int k = 0; k < 3; k++)
        d.base[k] = centroid[k] + cx * e1[k] + cy * e2[k];
    d.radius = sqrt(r2);
    d.slope = 0;
    if (refine(&d, points, n, 5) != 0)
        return -1;
    *out = d;
    return 0;
}

#define CONE_FAR 20

int reference_developable_cone_start(const double *points, size_t n,
                                     const double *at, const double *ruling,
                                     size_t nrulings,
                                     struct developable *out)
{
    if (nrulings < 2)
        return -1;
    /* The apex minimises sum |(I - r r^T)(apex - p)|^2. */
    double a[9] = {0}, b[3] = {0}, apex[3];
    for (size_t k = 0; k < nrulings; k++) {
        const double *r = ruling + 3 * k, *p = at + 3 * k;
        for (int x = 0; x < 3; x++)
            for (int y = 0; y < 3; y++) {
                double m = (x == y) - r[x] * r[y];
                a[3 * x + y] += m;
                b[x] += m * p[y];
            }
    }
    if (!linalg_cholesky_solve(3, 3, a, b, 1e-6, apex))
        return -1;
    /* The directions to the points lie on a circle of the unit sphere; the
     * axis is the normal of its plane (least spread), pointing to them. */
    double mean[3], value[3], vector[3][3];
    double *w = malloc(n * 3 * sizeof *w);
    if (w == NULL)
        return -1;
    for (size_t k = 0; k < n; k++) {
        vec3_sub(points + 3 * k, apex, w + 3 * k);
        if (!vec3_normalize(w + 3 * k)) {
            free(w);
            return -1;
        }
    }
    reference_developable_principal_axes(w, n, mean, value, vector);
    free(w);
    double axis[3] = {vector[0][0], vector[0][1], vector[0][2]};
    if (vec3_dot(axis, mean) < 0)
        for (int x = 0; x < 3; x++)
            axis[x] = -axis[x];
    double cosine = vec3_dot(axis, mean);
    if (!(cosine > 0 && cosine < 1))
        return -1;
    double centroid[3], q[3], extent = 0;
    centroid_of(points, n, centroid);
    for (size_t k = 0; k < n; k++)
        extent = fmax(extent, vec3_distance(points + 3 * k, centroid));
    vec3_sub(centroid, apex, q);
    /* Rulings that meet farther off than CONE_FAR extents of the points
     * are parallel to within the estimate's noise: the cylinder start
     * covers that cone, and a start there only creeps back to it. */
    if (vec3_length(q) > CONE_FAR * extent)
        return -1;
    double h = vec3_dot(q, axis);
    out->shape = DEVELOPABLE_CONE;
    memcpy(out->axis, axis, sizeof out->axis);
    for (int x = 0; x < 3; x++)
        out->base[x] = apex[x] + h * axis[x];
    out->slope = sqrt(1 - cosine * cosine) / cosine;
    out->radius = h * out->slope;
    return isfinite(out->radius) && out->radius > 0 ? 0 : -1;
}

int reference_developable_fit_cone(const double *points, size_t n,
                         const struct developable *start,
                         struct developable *out)
{
    if (n < 6)
        return -1;
    struct developable d = *start;
    d.shape = DEVELOPABLE_CONE;
    if (refine(&d, points, n, 6) != 0)
        return -1;
    /* A cone whose apex lies among the points is no panel one can roll
     * (its curvature grows without bound there), and the fit that finds
     * one is a nearly flat cone wandering about a nearly flat patch. */
    double centroid[3], apex[3], extent = 0;
    centroid_of(points, n, centroid);
    for (size_t k = 0; k < n; k++)
        extent = fmax(extent, vec3_distance(points + 3 * k, centroid));
    for (int x = 0; x < 3; x++)
        apex[x] = d.base[x] - d.radius / d.slope * d.axis[x];
    if (!(vec3_distance(apex, centroid) > extent))
        return -1;
    *out = d;
    return 0;
}

/* The barycentric tolerance of panels_build's corner lookup, so that a side's
 * ends are the panels' corners. */
#define LOCATE_TOLERANCE 1e-9

/* How far inside a triangle (least barycentric coordinate) a point must
 * lie to be its alone. Nearer an edge, the point may be held by the
 * triangle on the other side too (within rounding, or within
 * LOCATE_TOLERANCE), and which one a walk reaches depends on where it came
 * from. */
#define INSIDE_MARGIN 1e-12

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
        double least = fmin(b[0], fmin(b[1], b[2]));
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

/* The unit surface normal in triangle t at barycentric b, point x: each
 * corner's surface normal carried halfway to x by its shape operator,
 * blended by b, on the side of the face normal (cell_sides.h). */
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

/* 1 when the side between the panels a and b (indices, -1 for none) is to
 * be sampled. */
static int needs_samples(const struct panelization *panels, int32_t a,
                         int32_t b)
{
    const struct panel *pa = a >= 0 ? &panels->panels[a] : NULL;
    const struct panel *pb = b >= 0 ? &panels->panels[b] : NULL;
    if ((pa != NULL && pa->type == TYPE_SP) ||
        (pb != NULL && pb->type == TYPE_SP))
        return 1;
    if (pa == NULL || pb == NULL)
        return 0;
    return !(cell_sides_flat_quad(pa) && cell_sides_flat_quad(pb)) &&
           !(full_dp(pa) && full_dp(pb));
}

void reference_cell_sides_mark(const struct panelization *panels,
                     unsigned char *sampled)
{
    int nu = panels->nu, nv = panels->nv;
    struct cell_sides shape = {.nu = nu, .nv = nv};
    for (int j = 0; j < nv; j++)
        for (int i = 0; i <= nu; i++)
            sampled[cell_side_u(&shape, i, j)] = (unsigned char)needs_samples(
                panels, i > 0 ? panels->cell_panel[j * nu + i - 1] : -1,
                i < nu ? panels->cell_panel[j * nu + i] : -1);
    for (int j = 0; j <= nv; j++)
        for (int i = 0; i < nu; i++)
            sampled[cell_side_v(&shape, i, j)] = (unsigned char)needs_samples(
                panels, j > 0 ? panels->cell_panel[(j - 1) * nu + i] : -1,
                j < nv ? panels->cell_panel[j * nu + i] : -1);
}

/* reference_cell_sides_sample (every: all sides, as
 * cell_sides_sample_every). */
static int sample(const struct mesh *mesh, const struct uv_index *index,
                  const struct curvature *curvature,
                  const struct panelization *panels, int every,
                  struct cell_sides *out, struct facet_error *err)
{
    memset(out, 0, sizeof *out);
    int nu = panels->nu, nv = panels->nv;
    out->nu = nu;
    out->nv = nv;
    out->nsides = (size_t)(nu + 1) * (size_t)nv +
                  (size_t)nu * (size_t)(nv + 1);
    size_t nsamples = out->nsides * CELL_SIDE_SAMPLES;
    out->point = malloc(nsamples * 3 * sizeof *out->point);
    out->normal = malloc((out->nsides + 1) * 3 * sizeof *out->normal);
    out->middle = malloc(out->nsides + 1);
    out->on = malloc(nsamples);
    out->sampled = calloc(out->nsides + 1, 1);
    if (out->point == NULL || out->normal == NULL || out->on == NULL ||
        out->sampled == NULL || out->middle == NULL) {
        cell_sides_free(out);
        return facet_error_set(err, FACET_EWORK,
                               "out of memory sampling %zu cell sides",
                               out->nsides);
    }
    if (every)
        memset(out->sampled, 1, out->nsides);
    else
        reference_cell_sides_mark(panels, out->sampled);
    double du = (panels->umax - panels->umin) / nu;
    double dv = (panels->vmax - panels->vmin) / nv;
    /* Along each grid line in turn, so that the walk from sample to sample
     * stays in neighbouring triangles (and in the cache); the first sample
     * of a side is the last of the one before it on the line. */
    uint32_t hint = UINT32_MAX;
    for (int line = 0; line < (nu + 1) + (nv + 1); line++) {
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
                } else {
                    double f = (double)k / CELL_SIDE_SEGMENTS;
                    double u = panels->umin + (i + (along_v ? 0 : f)) * du;
                    double v = panels->vmin + (j + (along_v ? f : 0)) * dv;
                    triangle[k] = locate_near(mesh, index, hint, u, v,
                                              bary[k]);
                    out->on[at] = triangle[k] != UINT32_MAX;
                    if (triangle[k] == UINT32_MAX) {
                        for (int x = 0; x < 3; x++)
                            out->point[3 * at + x] = NAN;
                        continue;
                    }
                    hint = triangle[k];
                    point_at(mesh, triangle[k], bary[k], out->point + 3 * at);
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

int reference_cell_sides_sample(const struct mesh *mesh,
                                const struct uv_index *index,
                      const struct curvature *curvature,
                      const struct panelization *panels,
                      struct cell_sides *out, struct facet_error *err)
{
    return sample(mesh, index, curvature, panels, 0, out, err);
}


/* Of a panel's side samples, every FIT_SIDE_STRIDE-th joins the fit (the
 * corners and side midpoints); all count in its deviation. */
#define FIT_SIDE_STRIDE 4

/* A point within this fraction of a cell of a cell line lies on it. */
#define ON_LINE 1e-9

/* The cells a point at grid coordinate x (in cells from the first line)
 * lies in along one axis of count cells: those whose closed interval
 * holds it, to ON_LINE, so that a point on a cell line belongs to both
 * sides. Returns how many (1 or 2) into cell[]. */
static int cells_along(double x, int count, int cell[2])
{
    int i = x > 0 ? (x < count ? (int)x : count - 1) : 0;
    double f = x - i;
    cell[0] = i;
    if (f <= ON_LINE && i > 0) {
        cell[1] = i - 1;
        return 2;
    }
    if (f >= 1 - ON_LINE && i < count - 1) {
        cell[1] = i + 1;
        return 2;
    }
    return 1;
}

/* The panels holding fit point p (the panels of the cells it lies in),
 * only the SP ones unless any, into out; returns how many. */
static int point_panels(const struct fit_points *points, size_t p,
                        const struct panelization *panels, double du,
                        double dv, int any, int32_t out[4])
{
    int ci[2], cj[2];
    int ni = cells_along((points->uv[2 * p] - panels->umin) / du, panels->nu,
                         ci);
    int nj = cells_along((points->uv[2 * p + 1] - panels->vmin) / dv,
                         panels->nv, cj);
    int n = 0;
    for (int a = 0; a < ni; a++)
        for (int b = 0; b < nj; b++) {
            int32_t panel = panels->cell_panel[cj[b] * panels->nu + ci[a]];
            if (panel >= 0 && (any || panels->panels[panel].type == TYPE_SP))
                out[n++] = panel;
        }
    return n;
}

/* Appends sample k of side s to xyz at *n when it is on the surface. */
static void add_sample(const struct cell_sides *sides, size_t s, int k,
                       double *xyz, size_t *n)
{
    size_t at = s * CELL_SIDE_SAMPLES + (size_t)k;
    if (!sides->on[at])
        return;
    memcpy(xyz + 3 * *n, sides->point + 3 * at, 3 * sizeof *xyz);
    (*n)++;
}

/* The fit points of panels, bucketed: those of panel k are member[start[k]
 * .. start[k + 1]), in the order of the points; only the SP panels' unless
 * any. largest: the most of one panel. */
struct reference_buckets {
    size_t *start;             /* npanels + 2 */
    uint32_t *member;
    size_t largest;
};

static void buckets_free(struct reference_buckets *b)
{
    free(b->start);
    free(b->member);
    memset(b, 0, sizeof *b);
}

/* Fills *out (release with buckets_free); returns 0, or -1 when out of
 * memory. */
static int buckets_build(const struct fit_points *points,
                         const struct panelization *panels, int any,
                         struct reference_buckets *out)
{
    memset(out, 0, sizeof *out);
    size_t np = panels->npanels;
    double du = (panels->umax - panels->umin) / panels->nu;
    double dv = (panels->vmax - panels->vmin) / panels->nv;
    out->start = calloc(np + 2, sizeof *out->start);
    /* Count, then place. The count keeps the points some panel holds in
     * held, and the panel of those only one holds (all but the points on
     * cell lines) in held_by (-1 for the others), so that the placing looks
     * again only at the points on cell lines (most of a surface is in FP
     * and DP panels, most points inside a cell). */
    uint32_t *held = malloc((points->npoints + 1) * sizeof *held);
    int32_t *held_by = malloc((points->npoints + 1) * sizeof *held_by);
    if (out->start == NULL || held == NULL || held_by == NULL)
        goto out_of_memory;
    size_t *start = out->start;
    size_t nheld = 0;
    for (size_t p = 0; p < points->npoints; p++) {
        int32_t holder[4];
        int n = point_panels(points, p, panels, du, dv, any, holder);
        for (int k = 0; k < n; k++)
            start[holder[k] + 2]++;
        if (n > 0) {
            held_by[nheld] = n == 1 ? holder[0] : -1;
            held[nheld++] = (uint32_t)p;
        }
    }
    for (size_t k = 0; k < np; k++) {
        out->largest = start[k + 2] > out->largest ? start[k + 2]
                                                   : out->largest;
        start[k + 2] += start[k + 1];
    }
    out->member = malloc((start[np + 1] + 1) * sizeof *out->member);
    if (out->member == NULL)
        goto out_of_memory;
    for (size_t x = 0; x < nheld; x++) {
        if (held_by[x] >= 0) {
            out->member[start[held_by[x] + 1]++] = held[x];
            continue;
        }
        int32_t holder[4];
        int n = point_panels(points, held[x], panels, du, dv, any, holder);
        for (int k = 0; k < n; k++)
            out->member[start[holder[k] + 1]++] = held[x];
    }
    free(held);
    free(held_by);
    return 0;

out_of_memory:
    free(held);
    free(held_by);
    buckets_free(out);
    return -1;
}

/* A panel's samples and its fit's start. */
struct reference_samples {
    double *xyz;               /* n x 3: the first nfit join the fit */
    double *ruling;            /* nrulings x 3: of the first nrulings */
    size_t n, nfit, nrulings;
    double axis[3];            /* the cylinder's start */
};

/* Gathers panel k's samples into *out (its arrays of room for the
 * largest bucket and four sides). */
static void gather(const struct mesh *mesh, const struct fit_points *points,
                   const struct panel *panel,
                   const struct reference_buckets *buckets,
                   size_t k, const struct cell_sides *sides,
                   struct reference_samples *out)
{
    double *xyz = out->xyz;
    /* Mean ruling of the points inside, and the samples. */
    double outer[9] = {0};
    size_t n = 0;
    for (size_t m = buckets->start[k]; m < buckets->start[k + 1]; m++) {
        size_t p = buckets->member[m];
        const double *r = points->ruling + 3 * p;
        for (int a = 0; a < 3; a++)
            for (int c = 0; c < 3; c++)
                outer[3 * a + c] += r[a] * r[c];
        memcpy(xyz + 3 * n, mesh->position + 3 * (size_t)points->vertex[p],
               3 * sizeof *xyz);
        memcpy(out->ruling + 3 * n, r, 3 * sizeof *out->ruling);
        n++;
    }
    out->nrulings = n;
    /* Every FIT_SIDE_STRIDE-th sample of the sides (corners included,
     * once) joins the fit; the others only the deviation. The first
     * two sides start at a corner, the last two end at one. */
    int i = panel->i, j = panel->j;
    size_t around[4] = {
        cell_side_v(sides, i, j), cell_side_u(sides, i + 1, j),
        cell_side_v(sides, i, j + 1), cell_side_u(sides, i, j)};
    for (int pass = 0; pass < 2; pass++) {
        for (int e = 0; e < 4; e++)
            for (int step = 0; step < CELL_SIDE_SEGMENTS; step++) {
                int at = e < 2 ? step : step + 1;
                if ((at % FIT_SIDE_STRIDE == 0) == (pass == 0))
                    add_sample(sides, around[e], at, xyz, &n);
            }
        if (pass == 0)
            out->nfit = n;
    }
    out->n = n;
    if (out->nrulings > 0) {
        double value[3], vector[3][3];
        sym3_eigen(outer, value, vector);
        memcpy(out->axis, vector[2], sizeof out->axis);
    } else {
        /* No point inside: the longest extent of the samples. */
        double mean[3], value[3], vector[3][3];
        reference_developable_principal_axes(xyz, n, mean, value, vector);
        memcpy(out->axis, vector[2], sizeof out->axis);
    }
}

/* A panel's fits, which do not depend on the threshold (only their
 * verdict does): its cylinder, and when that misses, its cones. */
struct reference_panel_fits {
    unsigned char cylinder_done, cone_done;
    unsigned char have_cylinder;
    struct developable cylinder;
    double best_cylinder;      /* NaN without a cylinder */
    struct developable cone;   /* the cone kept; zero when none */
    double best_cone;          /* NaN without a cone */
};

static void fit_cylinder(const struct reference_samples *s,
                         struct reference_panel_fits *f)
{
    f->cylinder_done = 1;
    f->best_cylinder = NAN;
    f->have_cylinder = reference_developable_fit_cylinder(
                           s->xyz, s->nfit, s->axis, &f->cylinder) == 0;
    if (f->have_cylinder)
        f->best_cylinder = reference_developable_max_distance(
            &f->cylinder, s->xyz, s->n);
}

/* From the cylinder and from where the rulings converge; the one nearer
 * the samples is kept (two least-squares cones can tie where their largest
 * distances do not). */
static void fit_cones(const struct reference_samples *s,
                      struct reference_panel_fits *f)
{
    f->cone_done = 1;
    f->best_cone = NAN;
    memset(&f->cone, 0, sizeof f->cone);
    struct developable start[2], cone;
    start[0] = f->cylinder;
    int starts = 1 + (reference_developable_cone_start(s->xyz, s->nfit, s->xyz,
                                             s->ruling, s->nrulings,
                                             &start[1]) == 0);
    for (int k = 0; k < starts; k++) {
        if (reference_developable_fit_cone(s->xyz, s->nfit, &start[k],
                                           &cone) != 0)
            continue;
        double deviation =
            reference_developable_max_distance(&cone, s->xyz, s->n);
        if (isfinite(deviation) && !(deviation >= f->best_cone)) {
            f->best_cone = deviation;
            f->cone = cone;
        }
    }
}

/* 1 when panel's fits f, at threshold, need the cones. */
static int needs_cones(const struct panel *panel,
                       const struct reference_panel_fits *f, double threshold)
{
    double limit = threshold + CLASSIFY_ROUNDING * panel->diameter;
    return f->have_cylinder && !(f->best_cylinder <= limit);
}

/* Builds the SP panel from its fits f (the cones done when needs_cones)
 * at threshold into *b. */
static void judge(const struct panel *panel,
                  const struct reference_panel_fits *f,
                  double threshold, struct built_panel *b)
{
    double limit = threshold + CLASSIFY_ROUNDING * panel->diameter;
    memset(&b->fit, 0, sizeof b->fit);
    b->best_cylinder = f->best_cylinder;
    b->best_cone = NAN;
    if (f->have_cylinder) {
        if (f->best_cylinder <= limit) {
            b->fitted = 1;
            b->fit = f->cylinder;
            b->sp_deviation = f->best_cylinder;
            return;
        }
        b->best_cone = f->best_cone;
        b->fit = f->cone;
        if (f->best_cone <= limit) {
            b->fitted = 1;
            b->sp_deviation = f->best_cone;
            return;
        }
    }
    b->type = TYPE_DP;
    b->misfit = 1;
    b->sp_deviation = fmin(b->best_cylinder, b->best_cone);
}

/* Scratch for one panel's samples: room for the largest bucket and four
 * sides. Returns 0, or -1 when out of memory. */
static int samples_alloc(size_t largest, struct reference_samples *s)
{
    memset(s, 0, sizeof *s);
    s->xyz = malloc((largest + 4 * CELL_SIDE_SAMPLES) * 3 * sizeof *s->xyz);
    s->ruling = malloc((largest + 1) * 3 * sizeof *s->ruling);
    return s->xyz != NULL && s->ruling != NULL ? 0 : -1;
}

static void samples_free(struct reference_samples *s)
{
    free(s->xyz);
    free(s->ruling);
    memset(s, 0, sizeof *s);
}

/* Builds every panel of panels into out (allocated, zeroed but for the
 * threshold and counts), fitting each SP panel k from the fits cache[k]
 * (done there as needed) or, without a cache, anew. */
static void build_panels(const struct mesh *mesh,
                         const struct fit_points *points,
                         const struct panelization *panels,
                         const struct cell_sides *sides,
                         const struct reference_buckets *buckets,
                         struct reference_panel_fits *cache, double threshold,
                         struct reference_samples *s, struct built_option *out)
{
    for (size_t k = 0; k < panels->npanels; k++) {
        const struct panel *panel = &panels->panels[k];
        struct built_panel *b = &out->panels[k];
        b->type = panel->type;
        b->sp_deviation = b->best_cylinder = b->best_cone = NAN;
        if (panel->type != TYPE_SP)
            continue;
        struct reference_panel_fits alone;
        struct reference_panel_fits *f = cache != NULL ? &cache[k] : &alone;
        if (cache == NULL)
            memset(&alone, 0, sizeof alone);
        int gathered = 0;
        if (!f->cylinder_done) {
            gather(mesh, points, panel, buckets, k, sides, s);
            gathered = 1;
            fit_cylinder(s, f);
        }
        if (!f->cone_done && needs_cones(panel, f, threshold)) {
            if (!gathered)
                gather(mesh, points, panel, buckets, k, sides, s);
            fit_cones(s, f);
        }
        judge(panel, f, threshold, b);
        if (b->fitted)
            out->sp_fitted++;
        else
            out->sp_misfits++;
    }
}

int reference_built_option_fit(const struct mesh *mesh,
                               const struct fit_points *points,
                     const struct panelization *panels,
                     const struct cell_sides *sides, double threshold,
                     struct built_option *out, struct facet_error *err)
{
    memset(out, 0, sizeof *out);
    out->npanels = panels->npanels;
    out->threshold = threshold;
    size_t np = panels->npanels;
    struct reference_buckets buckets;
    struct reference_samples s;
    memset(&s, 0, sizeof s);
    out->panels = calloc(np + 1, sizeof *out->panels);
    if (buckets_build(points, panels, 0, &buckets) != 0 ||
        out->panels == NULL || samples_alloc(buckets.largest, &s) != 0) {
        buckets_free(&buckets);
        samples_free(&s);
        built_option_free(out);
        return facet_error_set(err, FACET_EWORK,
                               "out of memory fitting %zu panels", np);
    }
    build_panels(mesh, points, panels, sides, &buckets, NULL, threshold, &s,
                 out);
    buckets_free(&buckets);
    samples_free(&s);
    return FACET_OK;
}

/* One panel's side of a joint: which of its corners are the side's first
 * and last ends. */
struct joint_side {
    const struct panel *panel;
    const struct built_panel *built;
    int first, last;              /* indices into panel->corner */
    double end[2][3];             /* those corners projected (FP quad) */
    int quad;                     /* FP with a full quad */
};

static void side_init(struct joint_side *s, const struct panel *panel,
                      const struct built_panel *built, int first, int last)
{
    s->panel = panel;
    s->built = built;
    s->first = first;
    s->last = last;
    s->quad = built->type == TYPE_FP && cell_sides_flat_quad(panel);
    if (s->quad) {
        panel_geometry_project(panel, panel->corner[first], s->end[0]);
        panel_geometry_project(panel, panel->corner[last], s->end[1]);
    }
}

/* The angle between unit vectors a and b (rad): atan2 keeps small angles
 * exact, where acos of a cosine near 1 does not. */
static double angle_between(const double a[3], const double b[3])
{
    double cross[3];
    vec3_cross(a, b, cross);
    return atan2(vec3_length(cross), vec3_dot(a, b));
}

/* The place of surface point x on the side's panel as built. */
static void place_of(const struct joint_side *s, const double x[3],
                     double out[3])
{
    if (s->built->fitted) {
        reference_developable_nearest(&s->built->fit, x, out, NULL);
    } else if (s->quad) {
        double d[3], q[3];
        vec3_sub(s->end[1], s->end[0], d);
        vec3_sub(x, s->end[0], q);
        double length2 = vec3_dot(d, d);
        double f = length2 > 0 ? vec3_dot(q, d) / length2 : 0;
        f = f < 0 ? 0 : f > 1 ? 1 : f;
        for (int k = 0; k < 3; k++)
            out[k] = s->end[0][k] + f * d[k];
    } else if (s->built->type == TYPE_FP) {
        panel_geometry_project(s->panel, x, out);
    } else {
        memcpy(out, x, 3 * sizeof *out);
    }
}

/* The side's panel normal at surface point x, whose surface normal is
 * surface_normal. */
static void normal_of(const struct joint_side *s, const double x[3],
                      const double surface_normal[3], double out[3])
{
    if (s->built->fitted) {
        reference_developable_nearest(&s->built->fit, x, NULL, out);
        if (vec3_dot(out, surface_normal) < 0)
            for (int k = 0; k < 3; k++)
                out[k] = -out[k];
    } else if (s->built->type == TYPE_FP) {
        memcpy(out, s->panel->normal, 3 * sizeof *out);
    } else {
        memcpy(out, surface_normal, 3 * sizeof *out);
    }
}

/* Measures one joint on side of sides between a and b; returns 0 when the
 * surface does not reach the side. A side between two full DP panels is
 * not sampled: both follow the surface, so the places of every point of
 * it, and its normals, are the same on both (gap and kink 0, as sampled
 * they come out exactly). A side between two flat quads is
 * measured at its ends: the places of a point of it on the two quads' edges
 * differ by an affine function of the point, whose largest value on the
 * side's curve departs from its largest at the ends by at most the curve's
 * sag times the angle between the two edges (micrometres). */
static int measure(const struct cell_sides *sides, size_t side,
                   const struct joint_side *a, const struct joint_side *b,
                   struct joint_edge *edge)
{
    edge->side = side;
    edge->gap = 0;
    if (!sides->sampled[side] && !a->quad) {
        /* Two full DP panels (cell_sides.h): both follow the surface. */
        assert(!b->quad && a->built->type == TYPE_DP &&
               b->built->type == TYPE_DP);
        edge->kink = 0;
        return 1;
    }
    if (!sides->sampled[side]) {
        assert(a->quad && b->quad);
        const double *end[2] = {a->panel->corner[a->first],
                                a->panel->corner[a->last]};
        for (int e = 0; e < 2; e++) {
            double pa[3], pb[3];
            place_of(a, end[e], pa);
            place_of(b, end[e], pb);
            edge->gap = fmax(edge->gap, vec3_distance(pa, pb));
        }
        edge->kink = angle_between(a->panel->normal, b->panel->normal);
        return 1;
    }
    int any = 0;
    for (int k = 0; k < CELL_SIDE_SAMPLES; k++) {
        size_t at = side * CELL_SIDE_SAMPLES + (size_t)k;
        if (!sides->on[at])
            continue;
        any = 1;
        double pa[3], pb[3];
        place_of(a, sides->point + 3 * at, pa);
        place_of(b, sides->point + 3 * at, pb);
        edge->gap = fmax(edge->gap, vec3_distance(pa, pb));
    }
    int middle = sides->middle[side];
    if (!any || middle < 0)
        return 0;
    const double *x = sides->point + 3 * (side * CELL_SIDE_SAMPLES +
                                          (size_t)middle);
    double na[3], nb[3];
    normal_of(a, x, sides->normal + 3 * side, na);
    normal_of(b, x, sides->normal + 3 * side, nb);
    edge->kink = angle_between(na, nb);
    return 1;
}

int reference_joints_measure(const struct panelization *panels,
                   const struct built_option *built,
                   const struct cell_sides *sides, double max_gap,
                   double max_kink, struct joints *out,
                   struct facet_error *err)
{
    memset(out, 0, sizeof *out);
    int nu = panels->nu, nv = panels->nv;
    size_t most = (size_t)(nu - 1) * (size_t)nv +
                  (size_t)nu * (size_t)(nv - 1);
    out->npanels = panels->npanels;
    out->edges = malloc((most + 1) * sizeof *out->edges);
    out->worst_gap = calloc(panels->npanels + 1, sizeof *out->worst_gap);
    out->worst_kink = calloc(panels->npanels + 1, sizeof *out->worst_kink);
    if (out->edges == NULL || out->worst_gap == NULL ||
        out->worst_kink == NULL) {
        joints_free(out);
        return facet_error_set(err, FACET_EWORK,
                               "out of memory for %zu joints", most);
    }
    /* Corners 0..3 of a panel are (i,j), (i+1,j), (i+1,j+1), (i,j+1). */
    for (int j = 0; j < nv; j++)
        for (int i = 0; i < nu; i++) {
            int32_t here = panels->cell_panel[j * nu + i];
            if (here < 0)
                continue;
            int32_t left = i > 0 ? panels->cell_panel[j * nu + i - 1] : -1;
            int32_t below = j > 0 ? panels->cell_panel[(j - 1) * nu + i] : -1;
            struct joint_side a, b;
            struct joint_edge *edge = &out->edges[out->nedges];
            if (left >= 0) {
                side_init(&a, &panels->panels[left], &built->panels[left], 1,
                          2);
                side_init(&b, &panels->panels[here], &built->panels[here], 0,
                          3);
                edge->panel[0] = (uint32_t)left;
                edge->panel[1] = (uint32_t)here;
                if (measure(sides, cell_side_u(sides, i, j), &a, &b, edge))
                    edge = &out->edges[++out->nedges];
            }
            if (below >= 0) {
                side_init(&a, &panels->panels[below], &built->panels[below],
                          3, 2);
                side_init(&b, &panels->panels[here], &built->panels[here], 0,
                          1);
                edge->panel[0] = (uint32_t)below;
                edge->panel[1] = (uint32_t)here;
                if (measure(sides, cell_side_v(sides, i, j), &a, &b, edge))
                    ++out->nedges;
            }
        }
    for (size_t e = 0; e < out->nedges; e++) {
        const struct joint_edge *edge = &out->edges[e];
        out->max_gap = fmax(out->max_gap, edge->gap);
        out->max_kink = fmax(out->max_kink, edge->kink);
        out->mean_gap += edge->gap;
        out->mean_kink += edge->kink;
        out->gaps_over += edge->gap > max_gap;
        out->kinks_over += edge->kink > max_kink;
        for (int s = 0; s < 2; s++) {
            uint32_t p = edge->panel[s];
            out->worst_gap[p] = fmax(out->worst_gap[p], edge->gap);
            out->worst_kink[p] = fmax(out->worst_kink[p], edge->kink);
        }
    }
    if (out->nedges > 0) {
        out->mean_gap /= (double)out->nedges;
        out->mean_kink /= (double)out->nedges;
    }
    return FACET_OK;
}

void as_built_classify_at(struct panelization *panels, double t)
{
    struct classify_options options;
    struct option_totals totals;
    classify_defaults(&options);
    options.sp_as_fp = 1;
    options.threshold = t;
    classify_panels(panels, &options, &totals);
}
