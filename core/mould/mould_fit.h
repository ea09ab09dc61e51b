/*
 * mould_fit.h: moving one panel's samples onto another's.
 *
 * The rigid move between two panels is the least-squares fit of their
 * corresponding samples (mould_sample.h): the rotation and translation
 * that minimise the sum of squared distances (Kabsch's problem, solved
 * through the eigenvectors of M^T M, M the samples' cross-covariance).
 * Their deviation is the largest distance of a moved sample from its
 * partner.
 *
 * Which sample corresponds to which is fixed by a relabeling of the cell:
 * one of the 8 ways of laying a quad onto another, 4 turns times 2 corner
 * orders (the dihedral group of the square, acting on the lattice).
 *
 * Proper and mirrored. A fit is proper when its rotation has det = +1: a
 * move a rigid panel can make, including being turned over (installed with
 * its other face out), which is a proper move paired with the reversed
 * corner order. It is mirrored when det = -1: the panel's mirror image, a
 * different shape unless the panel is symmetric. A mould makes a shape,
 * and a formed panel can be installed either face out (the offset of one
 * face from the other, a sheet's thickness, changes the shape by far less
 * than a tolerance), so a proper fit under any of the 8 relabelings means
 * one mould; a mirrored fit means one mould only when mirror images are
 * allowed to share (mould.h).
 */
#ifndef FACET_MOULD_FIT_H
#define FACET_MOULD_FIT_H

#include <stddef.h>

#include "core/mould/mould_sample.h"

#define MOULD_RELABELINGS 8

/* The lattice under relabeling r (0..7): sample k of one panel corresponds
 * to sample order[k] of the other. r = 0..3 turn the cell by r quarter
 * turns and keep the corner order's sense; r = 4..7 reverse it (the same
 * turns after swapping u and v). */
void mould_relabeling(int r, int order[MOULD_SAMPLES]);

/* The least-squares rigid move of a[order[k]] onto b[k], k < n (order NULL:
 * the identity), proper (det +1) or, when mirrored, improper (det -1):
 *   a, b         n x 3 points (m)
 *   rotation     3 x 3, row-major, receives R (may be NULL)
 *   translation  receives t, so that R a + t ~ b (m; may be NULL)
 * Returns the largest distance |R a[order[k]] + t - b[k]| (m). Points all
 * on one line leave the rotation about it free; any is as good. */
double mould_fit_points(const double (*a)[3], const double (*b)[3],
                        const int *order, size_t n, int mirrored,
                        double rotation[9], double translation[3]);

/* The 8 relabelings as the congruence test takes them, made once
 * (mould_labels_make) and shared by every test. */
struct mould_labels {
    int order[MOULD_RELABELINGS][MOULD_SAMPLES];  /* mould_relabeling's */
    int corner[MOULD_RELABELINGS][4];             /* the same on the
        corners, numbered (0,0), (1,0), (1,1), (0,1) of the cell: corner c
        of one panel corresponds to corner corner[r][c] of the other */
};

void mould_labels_make(struct mould_labels *labels);

/* A sampled panel as the congruence test takes it: its samples and what
 * every test of it would otherwise recompute. */
struct mould_shape {
    double centred[MOULD_SAMPLES][3];  /* each sample (mould_sample_panel's)
                                          less the samples' centroid
                                          (m), as mould_fit_points centres
                                          them */
    double radius[MOULD_SAMPLES];      /* each centred point's length (m) */
    double spread;                     /* the sum of their squares (m^2) */
    double corner[4][3];               /* the corners less their own
                                          centroid (m) */
    double corner_spread;              /* the sum of their squares (m^2) */
    double corner_distance[4][4];      /* between corners (m) */
};

/* Sets *shape from a panel's samples (mould_sample_panel's). */
void mould_shape_measure(const double point[MOULD_SAMPLES][3],
                         struct mould_shape *shape);

/* How two sampled panels were found congruent. */
struct mould_fit {
    double deviation;  /* largest distance of a moved sample (m) */
    int relabeling;    /* r of mould_relabeling */
    int mirrored;      /* the fit is a mirror image */
};

/* Whether panel a's samples, moved rigidly under some relabeling, lie
 * within limit (m) of panel b's: tries the relabelings in order 0..7, the
 * proper fit first, then, when mirror, the mirrored one, and stops at the
 * first fit within limit, returned in *fit (may be NULL). The deviation of
 * each fit is mould_fit_points's, to the bit.
 *
 * A fit is skipped, as one that cannot be within limit, when:
 *   - a sample's distance from the centroid, or the distance between two
 *     corners, differs between the panels by more than 2 limit (a fit
 *     within limit moves each sample, and so the centroid, by at most
 *     limit);
 *   - the least root mean square distance any rigid move of that kind
 *     (proper or mirrored) leaves between the 4 corners, or between the
 *     25 samples (tried in that order), exceeds limit: the largest distance is at
 *     least the root mean square one, which is at least that least one.
 *     The least sum of squares is |a|^2 + |b|^2 - 2 lambda, lambda the
 *     largest eigenvalue of Horn's 4 x 4 matrix of the cross-covariance
 *     (its negative, mirrored); lambda < mu is shown without computing
 *     lambda, by a Cholesky factorization of mu I - N, with a margin
 *     (1e-9 of |a|^2 + |b|^2) that covers its rounding and the fit's a
 *     million times over.
 * So the skips change no answer, only the time. Returns 1 when a fit is
 * within limit, else 0. */
int mould_congruent(const struct mould_labels *labels,
                    const struct mould_shape *a, const struct mould_shape *b,
                    int mirror, double limit, struct mould_fit *fit);

#endif
