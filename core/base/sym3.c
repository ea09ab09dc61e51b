/*
 * sym3.c: cyclic Jacobi for symmetric 3x3 matrices. See sym3.h.
 */
#include "core/base/sym3.h"

#include <math.h>
#include <string.h>

void sym3_eigen(const double a[9], double value[3], double vector[3][3])
{
    double m[3][3], v[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++)
            m[r][c] = 0.5 * (a[3 * r + c] + a[3 * c + r]);

    for (int sweep = 0; sweep < 50; sweep++) {
        double off = fabs(m[0][1]) + fabs(m[0][2]) + fabs(m[1][2]);
        double scale = fabs(m[0][0]) + fabs(m[1][1]) + fabs(m[2][2]);
        if (off == 0 || off <= 1e-300 || off < 1e-17 * scale)
            break;
        for (int p = 0; p < 2; p++)
            for (int q = p + 1; q < 3; q++) {
                if (m[p][q] == 0)
                    continue;
                /* Rotation that zeroes m[p][q]. */
                double theta = (m[q][q] - m[p][p]) / (2 * m[p][q]);
                double t = (theta >= 0 ? 1.0 : -1.0) /
                           (fabs(theta) + sqrt(theta * theta + 1));
                double c = 1 / sqrt(t * t + 1), s = t * c;
                for (int k = 0; k < 3; k++) {
                    double mkp = m[k][p], mkq = m[k][q];
                    m[k][p] = c * mkp - s * mkq;
                    m[k][q] = s * mkp + c * mkq;
                }
                for (int k = 0; k < 3; k++) {
                    double mpk = m[p][k], mqk = m[q][k];
                    m[p][k] = c * mpk - s * mqk;
                    m[q][k] = s * mpk + c * mqk;
                }
                for (int k = 0; k < 3; k++) {
                    double vkp = v[k][p], vkq = v[k][q];
                    v[k][p] = c * vkp - s * vkq;
                    v[k][q] = s * vkp + c * vkq;
                }
            }
    }

    int order[3] = {0, 1, 2};
    for (int x = 0; x < 3; x++)
        for (int y = x + 1; y < 3; y++)
            if (m[order[y]][order[y]] < m[order[x]][order[x]]) {
                int swap = order[x];
                order[x] = order[y];
                order[y] = swap;
            }
    for (int k = 0; k < 3; k++) {
        value[k] = m[order[k]][order[k]];
        for (int r = 0; r < 3; r++)
            vector[k][r] = v[r][order[k]];
    }
}
