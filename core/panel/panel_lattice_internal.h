/*
 * panel_lattice_internal.h: what a panel lattice holds, shared by the file
 * that builds it (panel_lattice_build.c) and the one that takes a grid's
 * panels from it (panel_lattice.c). Internal to those two; callers use
 * panel_lattice.h.
 *
 * Fine column c spans [line_u[c - 1], line_u[c]] (the outermost columns
 * reach to the UV box and beyond), fine row r likewise in v; fine cell
 * (c, r) is at r * ncolumns + c. A grid's line is one of the fine lines,
 * bit for bit (both are umin + i * ((umax - umin) / nu)), so a grid cell
 * is a block of fine cells.
 */
#ifndef FACET_PANEL_LATTICE_INTERNAL_H
#define FACET_PANEL_LATTICE_INTERNAL_H

#include <stddef.h>
#include <stdint.h>

#include "core/base/sorted.h"
#include "core/panel/panel_lattice.h"
#include "core/panel/panel_internal.h"

/* Raw moments about the lattice's origin, summed over fine cells. */
struct lattice_sums {
    long double area, uv_area;
    long double first[3], second[6], normal_sum[3];
};

/* A point of the surface a grid may sample. */
struct lattice_sample {
    double position[3];  /* m */
    double k1, k2;       /* 1/m */
};

/* Where a fine line cuts a mesh edge: across is the fine row (for a line
 * in u) or column (in v) the cut lies in. */
struct lattice_cut {
    struct lattice_sample at;
    uint32_t across;
};

/* A crossing of two fine lines. */
struct lattice_corner {
    struct lattice_sample at;
    int state;  /* -1 off the surface, 0 inside a triangle, 1 on an edge */
};

/* A mesh point on a fine line, in one of the fine cells it is a piece
 * vertex of. */
struct lattice_extra {
    uint32_t point, column, row;
};

struct panel_lattice {
    const struct panel_prep *prep;
    int side_lo[2], side_hi[2];     /* the grids: nu, nv ranges */
    double origin[3];               /* of the prefix sums (m) */
    size_t nline[2];                /* fine lines in u, v */
    double *line[2];                /* ascending, distinct */
    size_t ncolumns, nrows;         /* nline + 1 each */
    struct cell_moments *fine;      /* nrows x ncolumns */
    struct lattice_sums *prefix;    /* (nrows + 1) x (ncolumns + 1): the
                                       fine cells of lower row and column */
    uint32_t *pieces;               /* the same, pieces with area */
    uint32_t *place;                /* npoints x 2: a fine column and row
                                       the point is in */
    uint32_t *on_line;              /* npoints x 2: 1 + the fine line in u,
                                       v it lies on, or 0 */
    struct lattice_extra *extra;    /* the points on lines, by point */
    size_t nextra;
    size_t *cut_start[2];           /* nline + 1: cuts of each line */
    struct lattice_cut *cut[2];
    struct lattice_corner *corner;  /* nline[1] x nline[0] */
};

/* The number of lines below x, and whether x is one of them. */
static inline size_t line_rank(const double *line, size_t n, double x,
                               int *on)
{
    size_t lo = sorted_lower_bound(line, n, x);
    *on = lo < n && line[lo] == x;
    return lo;
}

/* to += sign x, each sum. */
static inline void sums_add(struct lattice_sums *to,
                            const struct lattice_sums *x, long double sign)
{
    to->area += sign * x->area;
    to->uv_area += sign * x->uv_area;
    for (int e = 0; e < 3; e++) {
        to->first[e] += sign * x->first[e];
        to->normal_sum[e] += sign * x->normal_sum[e];
    }
    for (int e = 0; e < 6; e++)
        to->second[e] += sign * x->second[e];
}

#endif
