/*
 * mould_fit.c: the least-squares rigid move between two point sets, and
 * congruence of two sampled panels. See mould_fit.h.
 *
 * The move of a onto b maximises sum b_k . R a_k over the centred points,
 * that is trace(R M) with M = sum a_k b_k^T. Writing M = U D V^T with U
 * and V rotations (det +1) and D = diag(s1, s2, s3), s1 >= s2 >= |s3| (s3
 * takes the sign that keeps U and V proper), the best proper R is V U^T
 * and the best improper one V diag(1, 1, -1) U^T (Umeyama 1991). V's
 * columns are eigenvectors of M^T M (sym3_eigen, largest two; the third is
 * their cross product), U's first two are M v / |M v|, its third the cross
 * product of those: the two large singular directions are well conditioned
 * whatever the panel's flatness, and the third follows from them.
 */
#include "core/mould/mould_fit.h"

#include <assert.h>
#include <math.h>

#include "core/base/sym3.h"
#include "core/base/vec3.h"

void mould_relabeling(int r, int order[MOULD_SAMPLES])
{
    assert(r >= 0 && r < MOULD_RELABELINGS);
    const int s = MOULD_SIDE - 1;
    for (int b = 0; b <= s; b++)
        for (int a = 0; a <= s; a++) {
            int x = r < 4 ? a : b, y = r < 4 ? b : a, tx, ty;
            switch (r % 4) {
            case 0: tx = x; ty = y; break;
            case 1: tx = y; ty = s - x; break;
            case 2: tx = s - x; ty = s - y; break;
            default: tx = s - y; ty = x; break;
            }
            order[mould_sample_index(a, b)] = mould_sample_index(tx, ty);
        }
}

/* A unit vector perpendicular to the unit vector u. */
static void perpendicular(const double u[3], double out[3])
{
    double axis[3] = {0, 0, 0};
    int k = fabs(u[0]) < fabs(u[1]) ? (fabs(u[0]) < fabs(u[2]) ? 0 : 2)
                                    : (fabs(u[1]) < fabs(u[2]) ? 1 : 2);
    axis[k] = 1;
    vec3_cross(u, axis, out);
    vec3_normalize(out);
}

/* The rotation (row-major) maximising trace(R M) for the cross-covariance
 * m (row-major, m[3 i + j] = sum a_i b_j), with det = +1, or -1 when
 * mirrored. */
static void best_rotation(const double m[9], int mirrored, double r[9])
{
    double mtm[9];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            mtm[3 * i + j] = m[i] * m[j] + m[3 + i] * m[3 + j] +
                             m[6 + i] * m[6 + j];
    double value[3], vector[3][3];
    sym3_eigen(mtm, value, vector);
    double v[3][3], u[3][3];
    for (int x = 0; x < 3; x++) {
        v[0][x] = vector[2][x];
        v[1][x] = vector[1][x];
    }
    vec3_cross(v[0], v[1], v[2]);
    for (int c = 0; c < 2; c++)
        for (int x = 0; x < 3; x++)
            u[c][x] = m[3 * x] * v[c][0] + m[3 * x + 1] * v[c][1] +
                      m[3 * x + 2] * v[c][2];
    if (!vec3_normalize(u[0])) {
        /* All points coincide: any rotation fits; take the identity's. */
        u[0][0] = v[0][0];
        u[0][1] = v[0][1];
        u[0][2] = v[0][2];
    }
    double along = vec3_dot(u[0], u[1]);
    for (int x = 0; x < 3; x++)
        u[1][x] -= along * u[0][x];
    if (!(vec3_length(u[1]) > 1e-12 * sqrt(fabs(value[2]))) ||
        !vec3_normalize(u[1]))
        perpendicular(u[0], u[1]);
    vec3_cross(u[0], u[1], u[2]);
    double sign[3] = {1, 1, mirrored ? -1 : 1};
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            r[3 * i + j] = sign[0] * v[0][i] * u[0][j] +
                           sign[1] * v[1][i] * u[1][j] +
                           sign[2] * v[2][i] * u[2][j];
}

static void centroid_of(const double (*p)[3], size_t n, double out[3])
{
    out[0] = out[1] = out[2] = 0;
    for (size_t k = 0; k < n; k++)
        for (int x = 0; x < 3; x++)
            out[x] += p[k][x];
    for (int x = 0; x < 3; x++)
        out[x] /= (double)n;
}

double mould_fit_points(const double (*a)[3], const double (*b)[3],
                        const int *order, size_t n, int mirrored,
                        double rotation[9], double translation[3])
{
    assert(n > 0);
    double ca[3], cb[3];
    centroid_of(a, n, ca);
    centroid_of(b, n, cb);
    double m[9] = {0};
    for (size_t k = 0; k < n; k++) {
        const double *p = a[order != NULL ? (size_t)order[k] : k];
        double x[3], y[3];
        vec3_sub(p, ca, x);
        vec3_sub(b[k], cb, y);
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++)
                m[3 * i + j] += x[i] * y[j];
    }
    double r[9];
    best_rotation(m, mirrored, r);
    double worst = 0;
    for (size_t k = 0; k < n; k++) {
        const double *p = a[order != NULL ? (size_t)order[k] : k];
        double x[3], d[3];
        vec3_sub(p, ca, x);
        for (int i = 0; i < 3; i++)
            d[i] = r[3 * i] * x[0] + r[3 * i + 1] * x[1] +
                   r[3 * i + 2] * x[2] - (b[k][i] - cb[i]);
        worst = fmax(worst, vec3_length(d));
    }
    if (rotation != NULL)
        for (int i = 0; i < 9; i++)
            rotation[i] = r[i];
    if (translation != NULL)
        for (int i = 0; i < 3; i++)
            translation[i] = cb[i] - (r[3 * i] * ca[0] + r[3 * i + 1] * ca[1] +
                                      r[3 * i + 2] * ca[2]);
    return worst;
}

void mould_shape_measure(struct mould_shape *shape)
{
    double g[3];
    centroid_of((const double (*)[3])shape->point, MOULD_SAMPLES, g);
    for (int k = 0; k < MOULD_SAMPLES; k++)
        shape->radius[k] = vec3_distance(shape->point[k], g);
}

/* Whether two distances, x of one panel and y of the other, agree as a
 * fit within limit needs: to 2 limit, plus their rounding. */
static int distances_agree(double x, double y, double limit)
{
    return fabs(x - y) <= 2 * limit + 1e-12 * (x + y);
}

/* 1 when the distances of a's samples from their centroid, and between
 * its corners, taken under order, match b's (distances_agree). */
static int distances_match(const struct mould_shape *a,
                           const struct mould_shape *b,
                           const int order[MOULD_SAMPLES], double limit)
{
    for (int k = 0; k < MOULD_SAMPLES; k++)
        if (!distances_agree(a->radius[order[k]], b->radius[k], limit))
            return 0;
    const int s = MOULD_SIDE - 1;
    const int corner[4] = {
        mould_sample_index(0, 0), mould_sample_index(s, 0),
        mould_sample_index(s, s), mould_sample_index(0, s),
    };
    for (int i = 0; i < 4; i++)
        for (int j = i + 1; j < 4; j++)
            if (!distances_agree(
                    vec3_distance(a->point[order[corner[i]]],
                                  a->point[order[corner[j]]]),
                    vec3_distance(b->point[corner[i]], b->point[corner[j]]),
                    limit))
                return 0;
    return 1;
}

int mould_congruent(const struct mould_shape *a, const struct mould_shape *b,
                    int mirror, double limit, struct mould_fit *fit)
{
    for (int r = 0; r < MOULD_RELABELINGS; r++) {
        int order[MOULD_SAMPLES];
        mould_relabeling(r, order);
        if (!distances_match(a, b, order, limit))
            continue;
        for (int mirrored = 0; mirrored <= (mirror != 0); mirrored++) {
            double d = mould_fit_points(
                (const double (*)[3])a->point, (const double (*)[3])b->point,
                order, MOULD_SAMPLES, mirrored, NULL, NULL);
            if (d <= limit) {
                if (fit != NULL)
                    *fit = (struct mould_fit){d, r, mirrored};
                return 1;
            }
        }
    }
    return 0;
}
