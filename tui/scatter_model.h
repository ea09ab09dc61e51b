/*
 * scatter_model.h: the arithmetic of the scatter plot, without curses:
 * points of two metrics and a third, scaling to character cells, the
 * shade of the third metric, the two-metric Pareto front, and moving a
 * cursor from point to point.
 */
#ifndef FACET_TUI_SCATTER_MODEL_H
#define FACET_TUI_SCATTER_MODEL_H

#include <stddef.h>
#include <stdint.h>

struct scatter_point {
    int64_t number;   /* the option */
    double x, y, z;   /* the two axes' metrics and the shaded one */
    int rank;         /* the run's Pareto rank (1 = optimal) */
};

/* The cell (0..cells-1) of value on an axis from min to max; -1 for a
 * value that is not finite. A range without extent puts every value in
 * the middle cell. Values outside the range are clamped. */
int scatter_cell(double value, double min, double max, int cells);

/* The level (0..levels-1) of z between min and max (0 when the range has
 * no extent or z is not finite). */
int scatter_level(double z, double min, double max, int levels);

/* Round tick values for an axis from min to max: every multiple of a
 * step of 1, 2 or 5 times a power of ten that lies in [min, max], the
 * smallest such step that gives at most max_ticks of them, ascending,
 * into ticks (room for max_ticks) and the step into *step. Returns how
 * many: 0 when min or max is not finite or max_ticks < 1, 1 (min itself,
 * step 0) when the range has no extent. */
int scatter_ticks(double min, double max, int max_ticks, double *ticks,
                  double *step);

/* The least and greatest finite x (axis 0), y (1) or z (2) of points into
 * *min, *max (NaN when there is none). */
void scatter_range(const struct scatter_point *points, size_t n, int axis,
                   double *min, double *max);

/* Writes into front the indexes of the points no other point beats on
 * both x and y (both minimised; of equal points, the first), by x
 * ascending, and returns how many (0 when out of memory). front has
 * room for n. */
size_t scatter_front(const struct scatter_point *points, size_t n,
                     size_t *front);

/* The point the cursor goes to from current when moved by dx (-1, 0, 1
 * along x) or dy (along y): the nearest point on that side, distances
 * measured in units of each axis's range, with the cross-axis distance
 * weighted three times. current itself when there is none. */
size_t scatter_step(const struct scatter_point *points, size_t n,
                    size_t current, int dx, int dy);

#endif
