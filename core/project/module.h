/*
 * module.h: the building-level design variable, a panel module.
 *
 * A facade engineer sizes panels by a module: w metres wide (along u) and
 * h metres high (along v), the same on every surface of a building. Each
 * surface then gets the grid that fits the module best along its own u and
 * v lengths Lu, Lv (project_lengths.h):
 *
 *   nu = max(1, round(Lu / w)),   nv = max(1, round(Lv / h)),
 *
 * round to the nearest integer, halves up (12.5 -> 13: a panel a little
 * smaller than the module rather than larger), at most MODULE_MAX_COUNT.
 * The panels of a surface are then Lu / nu wide on average, within a
 * factor 2/3 .. 2 of w (at nu = 1 a narrow surface is one panel wide).
 *
 * The design space is a range of widths and one of heights, each walked
 * in steps (not a count: modules are ordered in round sizes, and a step
 * keeps 1.2, 1.3, ... whatever the range): min, min + step, ... up to max,
 * max included when it falls on a step (within 1e-9 of a step), each
 * value rounded to the nanometre so that 1.2 + 3 x 0.1 is 1.5. The
 * modules are every (w, h) of the two, widths outermost.
 */
#ifndef FACET_MODULE_H
#define FACET_MODULE_H

#include <stddef.h>

#include "core/base/error.h"

#define MODULE_DEFAULT_STEP 0.1  /* m */
#define MODULE_MAX_VALUES 10000  /* values along one range */
#define MODULE_MAX_COUNT 100000  /* panels along one side of a surface */
#define MODULE_MIN 0.001         /* m: the least module and step */

struct module_range {
    double width_min, width_max, width_step;     /* m */
    double height_min, height_max, height_step;  /* m */
};

/* Parses "WMIN:WMAX x HMIN:HMAX" (metres) into *out: "1.2:2.0x1.0:1.6",
 * a pair of ranges in numrange.h's syntax (blanks around the x allowed,
 * and X for x). Each range may give its step after a second colon
 * ("1.2:2.0:0.2", else MODULE_DEFAULT_STEP) or be one value ("1.5x1.2").
 * Values and steps must be at least MODULE_MIN, min <= max, at most
 * MODULE_MAX_VALUES values a range. FACET_EINPUT otherwise, the message
 * naming what (the caller's name for the setting) and, for a bad range,
 * which ("--module width: '0:1' is out of range (at least 0.001)"). */
int module_parse(const char *text, const char *what,
                 struct module_range *out, struct facet_error *err);

/* The grid counts of a surface of lengths lu, lv (m) for a module w x h
 * (m, positive), as above, into *nu and *nv. */
void module_grid(double lu, double lv, double w, double h, int *nu,
                 int *nv);

/* How many widths, heights, and modules (their product) range holds. */
size_t module_widths(const struct module_range *range);
size_t module_heights(const struct module_range *range);
size_t module_count(const struct module_range *range);

/* Module index (0 .. module_count - 1) into *w and *h (m): width
 * index / module_heights, height index % module_heights. */
void module_at(const struct module_range *range, size_t index, double *w,
               double *h);

#endif
