/*
 * module.c: panel modules and the grids they give. See module.h.
 */
#include "core/project/module.h"

#include <assert.h>
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "core/base/numrange.h"

/* A module range's values counted and walked as module.h says: the
 * nanometre to which they are kept forgives a billionth of a step. */
#define MODULE_SLACK 1e-9

static size_t steps(double min, double max, double step)
{
    return (size_t)numrange_count(min, max, step, MODULE_SLACK);
}

static double value_at(double min, double step, size_t k)
{
    double value = min + (double)k * step;
    /* Past about 1.8e299 m the product overflows to infinity, a module no
     * surface can take; a double that large holds no nanometres to round
     * to anyway. */
    double rounded = round(value * 1e9) / 1e9;
    return isfinite(rounded) ? rounded : value;
}

/* Below MODULE_MIN a module is no panel, and it would round to 0 at the
 * 1e-9 m to which module values are kept (value_at). */
static const struct numrange_spec side_spec = {
    .whole = 0, .least = MODULE_MIN, .most = DBL_MAX, .stepped = 1,
    .step_least = MODULE_MIN, .step_default = MODULE_DEFAULT_STEP,
    .slack = MODULE_SLACK, .values_max = MODULE_MAX_VALUES,
};

int module_parse(const char *text, const char *what,
                 struct module_range *out, struct facet_error *err)
{
    struct numrange_pair pair;
    if (numrange_pair_split(text, text + strlen(text), &pair) != 0)
        return facet_error_set(err, FACET_EINPUT,
            "%s: '%s' is not a module range (WMIN:WMAX x HMIN:HMAX in "
            "metres, each optionally :STEP, such as 1.2:2.0x1.0:1.6)",
            what, text);
    char width[128], height[128];
    snprintf(width, sizeof width, "%s width", what);
    snprintf(height, sizeof height, "%s height", what);
    struct numrange w, h;
    int rc = numrange_parse(pair.left, pair.left_end, &side_spec, width, &w,
                            err);
    if (rc == FACET_OK)
        rc = numrange_parse(pair.right, pair.right_end, &side_spec, height,
                            &h, err);
    if (rc != FACET_OK)
        return rc;
    *out = (struct module_range){w.min, w.max, w.step, h.min, h.max, h.step};
    return FACET_OK;
}

static int count_along(double length, double module)
{
    double n = floor(length / module + 0.5);
    if (!(n >= 1))
        return 1;
    return n > MODULE_MAX_COUNT ? MODULE_MAX_COUNT : (int)n;
}

void module_grid(double lu, double lv, double w, double h, int *nu, int *nv)
{
    assert(w > 0 && h > 0);
    *nu = count_along(lu, w);
    *nv = count_along(lv, h);
}

size_t module_widths(const struct module_range *range)
{
    return steps(range->width_min, range->width_max, range->width_step);
}

size_t module_heights(const struct module_range *range)
{
    return steps(range->height_min, range->height_max, range->height_step);
}

size_t module_count(const struct module_range *range)
{
    return module_widths(range) * module_heights(range);
}

void module_at(const struct module_range *range, size_t index, double *w,
               double *h)
{
    size_t heights = module_heights(range);
    assert(index < module_widths(range) * heights);
    *w = value_at(range->width_min, range->width_step, index / heights);
    *h = value_at(range->height_min, range->height_step, index % heights);
}
