/*
 * developable.c: cylinders and cones, and their fit. See developable.h.
 *
 * The fit minimises the sum of squared distances with Levenberg-Marquardt
 * over the parameters of the form radius + slope * h: two offsets of the
 * base across the axis, two tilts of the axis, the radius and (for a cone)
 * the slope. After every step the base is moved along the axis to the
 * plane through the points' centroid, so that radius is the radius where
 * the points are and the parameters stay of the panel's scale.
 */
#include "core/fit/developable.h"

#include <assert.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/base/linalg.h"
#include "core/base/sym3.h"
#include "core/base/vec3.h"

#define FIT_MAX_ITERATIONS 100
#define PI 3.14159265358979323846

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
    /* vec3_normalize(u), its length computed once for both. */
    *rho = vec3_length(u);
    if (!(*rho > 0) || !isfinite(*rho)) {
        double e2[3];
        vec3_frame(d->axis, u, e2);
        return;
    }
    for (int k = 0; k < 3; k++)
        u[k] /= *rho;
}

double developable_distance(const struct developable *d, const double x[3])
{
    double q[3];
    vec3_sub(x, d->base, q);
    double h = vec3_dot(q, d->axis);
    double rho = sqrt(fmax(vec3_dot(q, q) - h * h, 0));
    return (rho - d->radius - d->slope * h) / sqrt(1 + d->slope * d->slope);
}

void developable_nearest(const struct developable *d, const double x[3],
                         double point[3], double normal[3])
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

double developable_describe(const struct developable *d, const double x[3],
                            double axis_point[3], double direction[3],
                            double apex[3])
{
    double q[3];
    vec3_sub(x, d->base, q);
    double h = vec3_dot(q, d->axis);
    for (int k = 0; k < 3; k++)
        axis_point[k] = d->base[k] + h * d->axis[k];
    int cone = d->shape == DEVELOPABLE_CONE && d->slope != 0;
    double sign = 1;
    if (cone) {
        /* The apex is at h0 = -radius / slope; x's nappe lies where
         * radius + slope h > 0, on the side of h0 that slope's sign
         * gives. */
        sign = d->slope > 0 ? 1 : -1;
    } else {
        int big = 0;
        for (int k = 1; k < 3; k++)
            if (fabs(d->axis[k]) > fabs(d->axis[big]))
                big = k;
        sign = d->axis[big] < 0 ? -1 : 1;
    }
    for (int k = 0; k < 3; k++)
        direction[k] = sign * d->axis[k];
    if (apex != NULL)
        for (int k = 0; k < 3; k++)
            apex[k] = cone ? d->base[k] - d->radius / d->slope * d->axis[k]
                           : NAN;
    return cone ? atan(fabs(d->slope)) : 0;
}

/* The distance from the axis of a point at q from the base, h along the
 * axis: sqrt(q.q - h^2), 0 where rounding makes that negative (or it is
 * NaN). fmax(q.q - h^2, 0) without the library call; the two differ at
 * most in the sign of a zero, which no caller can tell (they take the
 * absolute value of what it is in, or add it to sums that start at +0,
 * which adding a zero of either sign leaves as they are). */
static double off_axis(const double q[3], double h)
{
    double s = vec3_dot(q, q) - h * h;
    return sqrt(s > 0 ? s : 0);
}

double developable_max_distance(const struct developable *d,
                                const double *points, size_t n)
{
    /* developable_distance point by point, its divisor computed once and
     * the largest kept without the library's fmax: worst is never NaN
     * (a NaN distance leaves it, as fmax does) and never -0. */
    double worst = 0, norm = sqrt(1 + d->slope * d->slope);
    for (size_t k = 0; k < n; k++) {
        double q[3];
        vec3_sub(points + 3 * k, d->base, q);
        double h = vec3_dot(q, d->axis);
        double distance = fabs((off_axis(q, h) - d->radius - d->slope * h) /
                               norm);
        if (distance > worst)
            worst = distance;
    }
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

void developable_principal_axes(const double *points, size_t n,
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

/* Points are linearised a chunk of this many at a time: first each
 * point's residual and row of the Jacobian (independent of the other
 * points, so that their square roots and divisions overlap), then their
 * sums, in the points' order as one pass adds them. */
#define LINEARIZE_CHUNK 32

/* linearize for np parameters (5 or 6), a constant where it is inlined
 * (always, so that the loops hold no test of np): the sums are kept in
 * locals, each added to in the points' order, so that they come out as
 * summed point by point into jtj and jtr. */
__attribute__((always_inline))
static inline double linearize_np(const struct developable *d,
                                  const double *points, size_t n,
                                  const int np, const double e1[3],
                                  const double e2[3], double jtj[36],
                                  double jtr[6])
{
    double w = 1 / sqrt(1 + d->slope * d->slope), sum = 0;
    double b0 = 0, b1 = 0, b2 = 0, b3 = 0, b4 = 0, b5 = 0;
    double a00 = 0;
    double a10 = 0, a11 = 0;
    double a20 = 0, a21 = 0, a22 = 0;
    double a30 = 0, a31 = 0, a32 = 0, a33 = 0;
    double a40 = 0, a41 = 0, a42 = 0, a43 = 0, a44 = 0;
    double a50 = 0, a51 = 0, a52 = 0, a53 = 0, a54 = 0, a55 = 0;
    for (size_t from = 0; from < n; from += LINEARIZE_CHUNK) {
        size_t m = n - from < LINEARIZE_CHUNK ? n - from : LINEARIZE_CHUNK;
        double f[LINEARIZE_CHUNK], row[6][LINEARIZE_CHUNK];
        for (size_t k = 0; k < m; k++) {
            double q[3];
            vec3_sub(points + 3 * (from + k), d->base, q);
            double x = vec3_dot(q, e1), y = vec3_dot(q, e2);
            double h = vec3_dot(q, d->axis), rho = sqrt(x * x + y * y);
            double ux = rho > 0 ? x / rho : 1, uy = rho > 0 ? y / rho : 0;
            double g = rho - d->radius - d->slope * h;
            f[k] = g * w;
            row[0][k] = -ux * w;
            row[1][k] = -uy * w;
            row[2][k] = (-h * ux - d->slope * x) * w;
            row[3][k] = (-h * uy - d->slope * y) * w;
            row[4][k] = -w;
            if (np == 6)
                row[5][k] = -h * w - g * d->slope * w * w * w;
        }
        for (size_t k = 0; k < m; k++) {
            double r0 = row[0][k], r1 = row[1][k], r2 = row[2][k];
            double r3 = row[3][k], r4 = row[4][k], fk = f[k];
            sum += fk * fk;
            b0 += r0 * fk;
            b1 += r1 * fk;
            b2 += r2 * fk;
            b3 += r3 * fk;
            b4 += r4 * fk;
            a00 += r0 * r0;
            a10 += r1 * r0;
            a11 += r1 * r1;
            a20 += r2 * r0;
            a21 += r2 * r1;
            a22 += r2 * r2;
            a30 += r3 * r0;
            a31 += r3 * r1;
            a32 += r3 * r2;
            a33 += r3 * r3;
            a40 += r4 * r0;
            a41 += r4 * r1;
            a42 += r4 * r2;
            a43 += r4 * r3;
            a44 += r4 * r4;
            if (np == 6) {
                double r5 = row[5][k];
                b5 += r5 * fk;
                a50 += r5 * r0;
                a51 += r5 * r1;
                a52 += r5 * r2;
                a53 += r5 * r3;
                a54 += r5 * r4;
                a55 += r5 * r5;
            }
        }
    }
    memset(jtj, 0, 36 * sizeof *jtj);
    memset(jtr, 0, 6 * sizeof *jtr);
    jtr[0] = b0;
    jtr[1] = b1;
    jtr[2] = b2;
    jtr[3] = b3;
    jtr[4] = b4;
    jtj[0] = a00;
    jtj[6] = a10;
    jtj[7] = a11;
    jtj[12] = a20;
    jtj[13] = a21;
    jtj[14] = a22;
    jtj[18] = a30;
    jtj[19] = a31;
    jtj[20] = a32;
    jtj[21] = a33;
    jtj[24] = a40;
    jtj[25] = a41;
    jtj[26] = a42;
    jtj[27] = a43;
    jtj[28] = a44;
    if (np == 6) {
        jtr[5] = b5;
        jtj[30] = a50;
        jtj[31] = a51;
        jtj[32] = a52;
        jtj[33] = a53;
        jtj[34] = a54;
        jtj[35] = a55;
    }
    return sum;
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
    assert(np >= 4 && np <= 6);
    /* 4 (a cylinder of fixed radius) is 5's leading block: the radius's
     * row is summed and not read. */
    if (np <= 5)
        return linearize_np(d, points, n, 5, e1, e2, jtj, jtr);
    return linearize_np(d, points, n, 6, e1, e2, jtj, jtr);
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
        double rho = off_axis(q, h);
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
    if (!(fabs(theta) < PI / 3))
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

/* linalg_cholesky_solve(np, 6, a, b, 1e-14, x), its factor and solves
 * inlined: with np a constant where refine_np inlines it, their loops
 * unroll (two solves of each step were a twentieth of the study as built,
 * issue 27); the same operations in the same order, so the same bits. */
__attribute__((always_inline))
static inline int solve_np(const int np, const double a[36], const double b[6],
                           double x[6])
{
    double l[36];
    if (!linalg_cholesky_factor(np, 6, a, 1e-14, l))
        return 0;
    linalg_cholesky_apply(np, l, b, x);
    return 1;
}

/* refine for np parameters, a constant where it is inlined (always: the
 * loops over the parameters, and linearize's, then hold no test of np),
 * stopping early, when enough > 0 (m), once no point is farther than
 * enough from d, and converged when a step would move the surface by
 * under a hundredth of enough; with enough 0, as every fit but
 * developable_fit_congruent's, by FIT_STEP alone. */
__attribute__((always_inline))
static inline int refine_np(struct developable *d, const double *points,
                            size_t n, const double centroid[3],
                            const int np, double enough)
{
    double e1[3], e2[3], jtj[36], jtr[6];
    recentre(d, centroid);
    if (np == 6)
        best_line(d, points, n);
    vec3_frame(d->axis, e1, e2);
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
    /* A placement held to enough is a verdict, not a measure: its fit may
     * stop once a step would move the surface by a hundredth of that. */
    double converged = enough > 0 ? fmax(FIT_STEP, enough / 100) : FIT_STEP;
    for (int iteration = 0; iteration < FIT_MAX_ITERATIONS; iteration++) {
        double b[6], step[6] = {0};
        for (int r = 0; r < np; r++)
            b[r] = -jtr[r];
        /* Converged when the undamped (Gauss-Newton) step would move the
         * surface at the points by less than FIT_STEP: |J step|^2 =
         * step.jtj.step. */
        if (solve_np(np, jtj, b, step) &&
            quadratic(jtj, step, np) <= (double)n * converged * converged)
            break;
        double a[36];
        memcpy(a, jtj, sizeof a);
        for (int r = 0; r < np; r++)
            a[r * 6 + r] += lambda * jtj[r * 6 + r];
        if (!solve_np(np, a, b, step)) {
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
        vec3_frame(trial.axis, te1, te2);
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
            /* Near enough: the largest distance is at least the root
             * mean square one. */
            if (enough > 0 && cost <= (double)n * enough * enough &&
                developable_max_distance(d, points, n) <= enough)
                break;
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

/* Levenberg-Marquardt on d over np parameters (5: cylinder, 6: cone; 4:
 * a cylinder of d's radius, 5 with d a cone: a cone of d's slope, for
 * developable_fit_congruent), centroid the points' (centroid_of, which
 * the callers need too). Each
 * trial step is linearised where it lands, so that an accepted step (the
 * usual case) costs one pass over the points. Returns 0, or -1 when the
 * surface leaves the finite. */
static int refine(struct developable *d, const double *points, size_t n,
                  const double centroid[3], int np, double enough)
{
    assert(np >= 4 && np <= 6);
    if (np == 4)
        return refine_np(d, points, n, centroid, 4, enough);
    if (np == 5)
        return refine_np(d, points, n, centroid, 5, enough);
    return refine_np(d, points, n, centroid, 6, enough);
}

int developable_fit_cylinder(const double *points, size_t n,
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
    vec3_frame(axis, e1, e2);
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
    if (refine(&d, points, n, centroid, 5, 0) != 0)
        return -1;
    *out = d;
    return 0;
}

#define CONE_FAR 20

int developable_cone_start(const double *points, size_t n, const double *at,
                           const double *ruling, size_t nrulings,
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
    developable_principal_axes(w, n, mean, value, vector);
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

int developable_fit_cone(const double *points, size_t n,
                         const struct developable *start,
                         struct developable *out)
{
    if (n < 6)
        return -1;
    struct developable d = *start;
    d.shape = DEVELOPABLE_CONE;
    double centroid[3], apex[3], extent = 0;
    centroid_of(points, n, centroid);
    if (refine(&d, points, n, centroid, 6, 0) != 0)
        return -1;
    /* A cone whose apex lies among the points is no panel one can roll
     * (its curvature grows without bound there), and the fit that finds
     * one is a nearly flat cone wandering about a nearly flat patch. */
    for (size_t k = 0; k < n; k++)
        extent = fmax(extent, vec3_distance(points + 3 * k, centroid));
    for (int x = 0; x < 3; x++)
        apex[x] = d.base[x] - d.radius / d.slope * d.axis[x];
    if (!(vec3_distance(apex, centroid) > extent))
        return -1;
    *out = d;
    return 0;
}

int developable_fit_congruent(const double *points, size_t n,
                              const struct developable *start,
                              double enough, struct developable *out)
{
    if (n < 5)
        return -1;
    struct developable d = *start;
    int np = 5;
    if (d.shape == DEVELOPABLE_CYLINDER) {
        d.slope = 0;
        np = 4;
    }
    if (!vec3_normalize(d.axis))
        return -1;
    double centroid[3];
    centroid_of(points, n, centroid);
    if (refine(&d, points, n, centroid, np, enough) != 0)
        return -1;
    *out = d;
    return 0;
}
