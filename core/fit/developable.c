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

#include <math.h>
#include <string.h>

#include "core/base/linalg.h"
#include "core/base/vec3.h"

#define FIT_MAX_ITERATIONS 30

/* A fit has converged when a step lowers the sum of squares by less than
 * this fraction of it: its root mean square then moves by 5e-5 of itself,
 * well under a micrometre on a panel whose samples are millimetres off. */
#define FIT_CONVERGED 1e-4

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

double developable_max_distance(const struct developable *d,
                                const double *points, size_t n)
{
    double worst = 0;
    for (size_t k = 0; k < n; k++)
        worst = fmax(worst, fabs(developable_distance(d, points + 3 * k)));
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
    frame(d->axis, e1, e2);
    double cost = linearize(d, points, n, np, e1, e2, jtj, jtr);
    double lambda = 1e-6;
    for (int iteration = 0; iteration < FIT_MAX_ITERATIONS; iteration++) {
        int accepted = 0;
        double previous = cost;
        while (!accepted && lambda < 1e12) {
            double a[36], b[6], step[6] = {0};
            memcpy(a, jtj, sizeof a);
            for (int r = 0; r < np; r++) {
                a[r * 6 + r] += lambda * jtj[r * 6 + r];
                b[r] = -jtr[r];
            }
            struct developable trial;
            double te1[3], te2[3], tjtj[36], tjtr[6];
            if (linalg_cholesky_solve(np, 6, a, b, 1e-14, step)) {
                /* The decrease the linearisation predicts for the step
                 * (b.step - step.jtj.step / 2): when even that is below
                 * convergence for a step barely damped, the fit is done
                 * without trying it. */
                double predicted = 0;
                for (int r = 0; r < np; r++) {
                    double row = 0;
                    for (int c = 0; c < np; c++)
                        row += jtj[r > c ? r * 6 + c : c * 6 + r] * step[c];
                    predicted += step[r] * (b[r] - 0.5 * row);
                }
                if (lambda <= 1e-3 && predicted <= FIT_CONVERGED * cost)
                    break;
                apply_step(d, e1, e2, step, np, centroid, &trial);
                frame(trial.axis, te1, te2);
                double trial_cost = linearize(&trial, points, n, np, te1,
                                              te2, tjtj, tjtr);
                if (isfinite(trial_cost) && trial_cost < cost) {
                    *d = trial;
                    cost = trial_cost;
                    memcpy(e1, te1, sizeof te1);
                    memcpy(e2, te2, sizeof te2);
                    memcpy(jtj, tjtj, sizeof tjtj);
                    memcpy(jtr, tjtr, sizeof tjtr);
                    lambda = fmax(lambda * 0.1, 1e-12);
                    accepted = 1;
                    continue;
                }
            }
            lambda *= 10;
        }
        if (!accepted || previous - cost <= FIT_CONVERGED * previous)
            break;
    }
    if (!isfinite(d->radius) || !isfinite(d->slope) || !(d->radius > 0))
        return -1;
    return 0;
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

int developable_fit_cone(const double *points, size_t n,
                         const struct developable *start,
                         struct developable *out)
{
    if (n < 6)
        return -1;
    struct developable d = *start;
    d.shape = DEVELOPABLE_CONE;
    if (refine(&d, points, n, 6) != 0)
        return -1;
    *out = d;
    return 0;
}
