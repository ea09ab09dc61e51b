/*
 * map_model.h: the arithmetic of the small and large panel maps, without
 * curses: the surface's true size along u and v, the largest picture of
 * it at its true aspect that fits a box of characters, and what one
 * character of such a picture shows when it covers several panels (or
 * part of one). The panel map's fit view and Compare's mini-maps draw
 * through it, so every map of one surface has one scale and one aspect.
 */
#ifndef FACET_TUI_MAP_MODEL_H
#define FACET_TUI_MAP_MODEL_H

#include <stddef.h>

#include "core/panel/panel.h"

/* A terminal character is about twice as tall as it is wide. */
#define MAP_CELL_ASPECT 2.0

/* The surface's extent in m along u (*width) and v (*height): the mean
 * over the grid's rows of the summed lengths of the panels' edges along
 * u, and likewise along v (corners off the surface left out). Falls back
 * to the UV box's sides when no edge has both corners on the surface. */
void map_surface_size(const struct panelization *p, double *width,
                      double *height);

/* The largest picture, *cols x *rows characters within max_cols x
 * max_rows, that shows a surface width x height (m) at its true aspect,
 * a character being cell_aspect times as tall as it is wide; at least
 * 1 x 1. */
void map_fit_box(double width, double height, int max_cols, int max_rows,
                 double cell_aspect, int *cols, int *rows);

/* What a map colours its panels by. */
enum map_colour {
    MAP_BY_TYPE,    /* FP, SP, DP */
    MAP_BY_CLASS,   /* the eight classes */
    MAP_BY_MOULD,   /* the mould family (panel->mould) */
    MAP_BY_GAP,     /* the worst gap at its joints, in MAP_LEVELS levels */
    MAP_BY_KINK,    /* the worst kink, likewise */
    MAP_BY_MOVE,    /* how far a planarized option's corners moved
                       (panelization's corner_moved), likewise; a
                       classified option has no such colouring */
    MAP_COLOURS
};

/* The levels a map by gap or kink colours by, low to high. */
#define MAP_LEVELS 4

/* 1 when colour maps a measure in MAP_LEVELS levels (gap, kink, move). */
int map_by_level(enum map_colour colour);

/* The worst gap (mm) or kink (degrees) of q, a panel of p, by colour
 * (MAP_BY_GAP or MAP_BY_KINK), or the farthest its corners moved (mm,
 * MAP_BY_MOVE); NaN for a panel never measured (stored before schema v7)
 * and, by move, for a panel not moved (a classified option's, a trimmed
 * one). */
double map_panel_measure(const struct panelization *p, const struct panel *q,
                         enum map_colour colour);

/* The upper bounds of the levels: with a limit (> 0, the run's gap or
 * kink limit), half of it, three quarters, the limit itself, and beyond
 * (the joints that make the option infeasible); without one, the
 * quarters of largest (the option's worst; all level 0 when it is 0). */
void map_level_bounds(double limit, double largest,
                      double bound[MAP_LEVELS]);

/* The level of value under bound: the first whose bound it does not
 * exceed; -1 for NaN. */
int map_level(double value, const double bound[MAP_LEVELS]);

/* An FP panel's value by mould: it needs none. */
#define MAP_NO_MOULD (-2)

/* The families map_cell_value weighs in one character, the first met:
 * more in one character are left out of its choice. */
#define MAP_MOULDS_PER_CHAR 32

/* What character (c, r) of a cols x rows picture of the whole grid shows
 * (r counted from v's top row, as a map reads): the panel type, class or
 * mould family (by colour) that covers most of the character's share of
 * the grid, every panel weighted by the part of its cell inside the
 * share; ties go to the later type (the dearer) or class, or the later
 * family met. By mould, FP panels count as one value, MAP_NO_MOULD. -1
 * when cells without a panel cover more of it than any value does. By
 * gap, kink or move, the highest level (under bound, map_level_bounds) of any
 * panel in the share, so that no bad joint hides in a fitted view; -1
 * when none was measured. bound is read only by gap or kink (else NULL). */
int map_cell_value(const struct panelization *p, int cols, int rows, int c,
                   int r, enum map_colour colour, const double *bound);

/* The panels of p in mould family family (0 for none). */
size_t map_family_size(const struct panelization *p, int family);

/* The character (*c, *r) of a cols x rows picture that the centre of
 * cell (i, j) falls in (r from v's top). */
void map_cell_of(const struct panelization *p, int cols, int rows, int i,
                 int j, int *c, int *r);

/* The surface a project option's map shows after step (+1 the next, -1
 * the previous) from current, of n (n >= 1): clamped to 0 .. n-1, never
 * wrapping round (the header's "surface K of N" is a place in the
 * building's order, and the last surface is not followed by the first). */
int map_surface_step(int current, int n, int step);

/* The header of surface k (0-based) of n, name with grid nu x nv:
 * "surface K of N: NAME (NU x NV)", K counted from 1. */
void map_surface_title(char *out, size_t size, int k, int n,
                       const char *name, int nu, int nv);

#endif
