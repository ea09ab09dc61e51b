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
#include "core/project/project_seams.h"

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

/* The seam joints of one surface of a building (project_seams.h), as its
 * map draws them: a seam joint lies on the surface's boundary, in the
 * panel of the surface it joins to a panel of another surface, so the map
 * marks that panel's cell. Per panel of the surface, the largest gap (m)
 * and kink added to the design's crease (rad: what the kink limit holds
 * at a seam) over the seam joints it is part of; NaN for a panel at no
 * seam. Owned; map_seams_free. */
struct map_seams {
    size_t npanels;
    double *gap;
    double *added;
    size_t joints;     /* seam joints with a panel of this surface */
};

/* The seams of surface (project order) from the building's seam joints
 * joints[0..n) (project_option_seam_joints), into *out for a surface of
 * npanels panels. Returns 0, or -1 when out of memory (*out then
 * empty). */
int map_seams_of_surface(const struct building_seam_joint *joints, size_t n,
                         size_t surface, size_t npanels,
                         struct map_seams *out);

void map_seams_free(struct map_seams *seams);

/* Panel k's seam measure by colour: its largest seam gap (mm) by gap,
 * its largest kink added at a seam (degrees) by kink; NaN for a panel at
 * no seam, a seams of NULL, and any other colouring (a seam joint has no
 * type, class, family or corner move of its own). */
double map_seam_measure(const struct map_seams *seams, size_t k,
                        enum map_colour colour);

/* The largest map_seam_measure over the surface's panels, NaN when none
 * is at a seam: what the levels without a limit are quarters of, with the
 * surface's own worst. */
double map_seams_largest(const struct map_seams *seams,
                         enum map_colour colour);

/* The highest level (under bound) of a seam joint in character (c, r)'s
 * share of the grid of p (as map_cell_value), -1 when no panel of the
 * share is at a seam or the colouring is not by gap or kink: a seam joint
 * over the limit shows in a fitted view as an inside joint's does. */
int map_seam_cell_level(const struct panelization *p,
                        const struct map_seams *seams, int cols, int rows,
                        int c, int r, enum map_colour colour,
                        const double *bound);

/* The mark of a seam joint at level (0 .. MAP_LEVELS-1): '=' along a
 * seam, '!' at the highest level (over the limit, or without one the top
 * quarter), so that the worst seam joints read without colour too. */
char map_seam_glyph(int level);

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
