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

/* A sampled panel as the congruence test takes it. */
struct mould_shape {
    double point[MOULD_SAMPLES][3];  /* mould_sample_panel's (m) */
    double radius[MOULD_SAMPLES];    /* each point's distance from the
                                        points' centroid (m) */
};

/* Sets shape->radius from shape->point. */
void mould_shape_measure(struct mould_shape *shape);

/* How two sampled panels were found congruent. */
struct mould_fit {
    double deviation;  /* largest distance of a moved sample (m) */
    int relabeling;    /* r of mould_relabeling */
    int mirrored;      /* the fit is a mirror image */
};

/* Whether panel a's samples, moved rigidly under some relabeling, lie
 * within limit (m) of panel b's: tries the relabelings in order 0..7, the
 * proper fit first, then, when mirror, the mirrored one, and stops at the
 * first fit within limit, returned in *fit (may be NULL). A relabeling is
 * skipped without fitting when a sample's distance from the centroid, or
 * the distance between two corners, differs between the panels by more
 * than 2 limit, which no fit within limit allows (a fit moves each sample
 * and so the centroid by at most limit). Returns 1 when a fit is within
 * limit, else 0. */
int mould_congruent(const struct mould_shape *a, const struct mould_shape *b,
                    int mirror, double limit, struct mould_fit *fit);

#endif
