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
#include <string.h>

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

/* (Sums are kept in locals, not in out, which the compiler must assume
 * may alias p: in registers, the same sums in the same order.) */
static void centroid_of(const double (*p)[3], size_t n, double out[3])
{
    double g0 = 0, g1 = 0, g2 = 0;
    for (size_t k = 0; k < n; k++) {
        g0 += p[k][0];
        g1 += p[k][1];
        g2 += p[k][2];
    }
    out[0] = g0 / (double)n;
    out[1] = g1 / (double)n;
    out[2] = g2 / (double)n;
}

/* The cross-covariance m of a[order[k]] - ca and b[k] - cb, k < n (order
 * NULL: the identity). Points already centred come with a centroid of 0,
 * which subtracts nothing. */
static void covariance(const double (*a)[3], const double ca[3],
                       const double (*b)[3], const double cb[3],
                       const int *order, size_t n, double m[9])
{
    /* In locals, as centroid_of: the inner loop of every fit. */
    double m0 = 0, m1 = 0, m2 = 0, m3 = 0, m4 = 0, m5 = 0, m6 = 0, m7 = 0,
           m8 = 0;
    const double a0 = ca[0], a1 = ca[1], a2 = ca[2];
    const double b0 = cb[0], b1 = cb[1], b2 = cb[2];
    for (size_t k = 0; k < n; k++) {
        const double *p = a[order != NULL ? (size_t)order[k] : k];
        double x0 = p[0] - a0, x1 = p[1] - a1, x2 = p[2] - a2;
        double y0 = b[k][0] - b0, y1 = b[k][1] - b1, y2 = b[k][2] - b2;
        m0 += x0 * y0;
        m1 += x0 * y1;
        m2 += x0 * y2;
        m3 += x1 * y0;
        m4 += x1 * y1;
        m5 += x1 * y2;
        m6 += x2 * y0;
        m7 += x2 * y1;
        m8 += x2 * y2;
    }
    m[0] = m0;
    m[1] = m1;
    m[2] = m2;
    m[3] = m3;
    m[4] = m4;
    m[5] = m5;
    m[6] = m6;
    m[7] = m7;
    m[8] = m8;
}

/* The largest |r (a[order[k]] - ca) - (b[k] - cb)|, k < n. The largest
 * square is found first and its root taken once: the root is monotonic,
 * so this is the largest root, to the bit. Once a distance exceeds stop,
 * returns it instead (stop INFINITY: never): a fit that fails need not be
 * measured to its end. */
static double deviation(const double (*a)[3], const double ca[3],
                        const double (*b)[3], const double cb[3],
                        const int *order, size_t n, const double r[9],
                        double stop)
{
    double worst = 0;
    for (size_t k = 0; k < n; k++) {
        const double *p = a[order != NULL ? (size_t)order[k] : k];
        double x[3], d[3];
        vec3_sub(p, ca, x);
        for (int i = 0; i < 3; i++)
            d[i] = r[3 * i] * x[0] + r[3 * i + 1] * x[1] +
                   r[3 * i + 2] * x[2] - (b[k][i] - cb[i]);
        double square = vec3_dot(d, d);
        if (square > worst) {
            worst = square;
            if (sqrt(square) > stop)
                return sqrt(square);
        }
    }
    return sqrt(worst);
}

double mould_fit_points(const double (*a)[3], const double (*b)[3],
                        const int *order, size_t n, int mirrored,
                        double rotation[9], double translation[3])
{
    assert(n > 0);
    double ca[3], cb[3];
    centroid_of(a, n, ca);
    centroid_of(b, n, cb);
    double m[9], r[9];
    covariance(a, ca, b, cb, order, n, m);
    best_rotation(m, mirrored, r);
    double worst = deviation(a, ca, b, cb, order, n, r, INFINITY);
    if (rotation != NULL)
        for (int i = 0; i < 9; i++)
            rotation[i] = r[i];
    if (translation != NULL)
        for (int i = 0; i < 3; i++)
            translation[i] = cb[i] - (r[3 * i] * ca[0] + r[3 * i + 1] * ca[1] +
                                      r[3 * i + 2] * ca[2]);
    return worst;
}

/* The sample at corner c of the cell, (0,0), (1,0), (1,1), (0,1). */
static int corner_sample(int c)
{
    const int s = MOULD_SIDE - 1;
    return mould_sample_index(c == 1 || c == 2 ? s : 0, c >= 2 ? s : 0);
}

void mould_labels_make(struct mould_labels *labels)
{
    for (int r = 0; r < MOULD_RELABELINGS; r++) {
        int *order = labels->order[r];
        mould_relabeling(r, order);
        for (int c = 0; c < 4; c++)
            for (int d = 0; d < 4; d++)
                if (corner_sample(d) == order[corner_sample(c)])
                    labels->corner[r][c] = d;
    }
}

/* Centres n points (out[k] = p[k] - their centroid); returns the sum of
 * the centred points' squares. */
static double centre(const double (*p)[3], size_t n, double (*out)[3])
{
    double g[3], sum = 0;
    centroid_of(p, n, g);
    for (size_t k = 0; k < n; k++) {
        double x[3];
        vec3_sub(p[k], g, x);
        out[k][0] = x[0];
        out[k][1] = x[1];
        out[k][2] = x[2];
        sum += vec3_dot(x, x);
    }
    return sum;
}

void mould_shape_measure(const double point[MOULD_SAMPLES][3],
                         struct mould_shape *shape)
{
    shape->spread = centre(point, MOULD_SAMPLES, shape->centred);
    for (int k = 0; k < MOULD_SAMPLES; k++)
        shape->radius[k] = vec3_length(shape->centred[k]);
    double corner[4][3];
    for (int c = 0; c < 4; c++)
        memcpy(corner[c], point[corner_sample(c)], sizeof corner[c]);
    shape->corner_spread = centre((const double (*)[3])corner, 4,
                                  shape->corner);
    /* |p - q| and |q - p| are the same double: one root a pair. */
    for (int c = 0; c < 4; c++) {
        shape->corner_distance[c][c] = 0;
        for (int d = c + 1; d < 4; d++)
            shape->corner_distance[c][d] = shape->corner_distance[d][c] =
                vec3_distance(point[corner_sample(c)],
                              point[corner_sample(d)]);
    }
}

/* Whether two distances, x of one panel and y of the other, agree as a
 * fit within limit needs: to 2 limit, plus their rounding. */
static int distances_agree(double x, double y, double limit)
{
    return fabs(x - y) <= 2 * limit + 1e-12 * (x + y);
}

/* 1 when the distances of a's samples from their centroid, and between
 * its corners, taken under relabeling r, match b's (distances_agree). */
static int distances_match(const struct mould_labels *labels, int r,
                           const struct mould_shape *a,
                           const struct mould_shape *b, double limit)
{
    const int *order = labels->order[r], *corner = labels->corner[r];
    for (int k = 0; k < MOULD_SAMPLES; k++)
        if (!distances_agree(a->radius[order[k]], b->radius[k], limit))
            return 0;
    for (int i = 0; i < 4; i++)
        for (int j = i + 1; j < 4; j++)
            if (!distances_agree(a->corner_distance[corner[i]][corner[j]],
                                 b->corner_distance[i][j], limit))
                return 0;
    return 1;
}

/* 1 when the symmetric 4 x 4 matrix x is positive definite, shown by
 * the pivots of its LDL^T factorization (the rounding of which the
 * caller's margin covers); 0 when not, or not shown. */
static int positive_definite(const double x[4][4])
{
    double l[4][4], d[4];
    for (int j = 0; j < 4; j++) {
        double pivot = x[j][j];
        for (int k = 0; k < j; k++)
            pivot -= l[j][k] * l[j][k] * d[k];
        if (!(pivot > 0))
            return 0;
        d[j] = pivot;
        for (int i = j + 1; i < 4; i++) {
            double y = x[i][j];
            for (int k = 0; k < j; k++)
                y -= l[i][k] * l[j][k] * d[k];
            l[i][j] = y / pivot;
        }
    }
    return 1;
}

/* 1 when no rigid move (proper, or mirrored) of n centred points with
 * cross-covariance m onto their partners, the two sets' sums of squares
 * adding to spread, leaves a root mean square distance within limit
 * (mould_congruent says how). */
static int out_of_reach(const double m[9], double spread, size_t n,
                        double limit, int mirrored)
{
    double mu = (spread - (double)n * limit * limit) / 2 - 1e-9 * spread;
    if (!(mu > 0))
        return 0;  /* N is traceless: its largest eigenvalue is >= 0 */
    const double *S = m;  /* S[3 i + j] = sum a_i b_j */
    double N[4][4] = {
        {S[0] + S[4] + S[8], S[5] - S[7], S[6] - S[2], S[1] - S[3]},
        {S[5] - S[7], S[0] - S[4] - S[8], S[1] + S[3], S[6] + S[2]},
        {S[6] - S[2], S[1] + S[3], -S[0] + S[4] - S[8], S[5] + S[7]},
        {S[1] - S[3], S[6] + S[2], S[5] + S[7], -S[0] - S[4] + S[8]},
    };
    double sign = mirrored ? -1 : 1, x[4][4];
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++)
            x[i][j] = (i == j ? mu : 0) - sign * N[i][j];
    return positive_definite(x);
}

int mould_congruent(const struct mould_labels *labels,
                    const struct mould_shape *a, const struct mould_shape *b,
                    int mirror, double limit, struct mould_fit *fit)
{
    static const double zero[3] = {0, 0, 0};
    for (int r = 0; r < MOULD_RELABELINGS; r++) {
        if (!distances_match(labels, r, a, b, limit))
            continue;
        const int *order = labels->order[r];
        /* The cheapest bound first: most fits that fail, fail on the
         * corners. */
        double corner[9], m[9];
        int m_done = 0;
        covariance((const double (*)[3])a->corner, zero,
                   (const double (*)[3])b->corner, zero, labels->corner[r],
                   4, corner);
        for (int mirrored = 0; mirrored <= (mirror != 0); mirrored++) {
            if (out_of_reach(corner, a->corner_spread + b->corner_spread, 4,
                             limit, mirrored))
                continue;
            if (!m_done) {
                covariance((const double (*)[3])a->centred, zero,
                           (const double (*)[3])b->centred, zero, order,
                           MOULD_SAMPLES, m);
                m_done = 1;
            }
            if (out_of_reach(m, a->spread + b->spread, MOULD_SAMPLES, limit,
                             mirrored))
                continue;
            double rotation[9];
            best_rotation(m, mirrored, rotation);
            double d = deviation((const double (*)[3])a->centred, zero,
                                 (const double (*)[3])b->centred, zero,
                                 order, MOULD_SAMPLES, rotation, limit);
            if (d <= limit) {
                if (fit != NULL)
                    *fit = (struct mould_fit){d, r, mirrored};
                return 1;
            }
        }
    }
    return 0;
}
