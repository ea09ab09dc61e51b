/*
 * module.c: panel modules and the grids they give. See module.h.
 */
#include "core/project/module.h"

#include <assert.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/base/numparse.h"

/* Values on [min, max] in steps of step (module.h). */
static size_t steps(double min, double max, double step)
{
    return (size_t)floor((max - min) / step + 1e-9) + 1;
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

/* Parses "MIN[:MAX[:STEP]]" from [text, end) into min, max, step. */
static int parse_range(const char *text, const char *end, double out[3])
{
    double v[3];
    int n;
    if (numparse_colon_list(text, end, v, 3, &n) != NUMPARSE_OK)
        return -1;
    out[0] = v[0];
    out[1] = n >= 2 ? v[1] : v[0];
    out[2] = n == 3 ? v[2] : MODULE_DEFAULT_STEP;
    /* Below MODULE_MIN a module is no panel, and it would round to 0 at
     * the 1e-9 m to which module values are kept (value_at). */
    if (!(out[0] >= MODULE_MIN) || !(out[1] >= out[0]) ||
        !(out[2] >= MODULE_MIN) || !isfinite(out[1]) || !isfinite(out[2]))
        return -1;
    if ((out[1] - out[0]) / out[2] >= MODULE_MAX_VALUES)
        return -1;
    return 0;
}

static const char *trim_end(const char *start, const char *end)
{
    while (end > start && (end[-1] == ' ' || end[-1] == '\t'))
        end--;
    return end;
}

static const char *trim_start(const char *start)
{
    while (*start == ' ' || *start == '\t')
        start++;
    return start;
}

int module_parse(const char *text, const char *what,
                 struct module_range *out, struct facet_error *err)
{
    const char *x = strchr(text, 'x');
    double w[3], h[3];
    if (x == NULL || strchr(x + 1, 'x') != NULL ||
        parse_range(trim_start(text), trim_end(text, x), w) != 0 ||
        parse_range(trim_start(x + 1), trim_end(x + 1, x + strlen(x)),
                    h) != 0)
        return facet_error_set(err, FACET_EINPUT,
            "%s: '%s' is not a module range (WMIN:WMAX x HMIN:HMAX in "
            "metres, each optionally :STEP, such as 1.2:2.0x1.0:1.6; "
            "modules and steps of at least %g m, min <= max, at most %d "
            "values a range)", what, text, MODULE_MIN, MODULE_MAX_VALUES);
    out->width_min = w[0];
    out->width_max = w[1];
    out->width_step = w[2];
    out->height_min = h[0];
    out->height_max = h[1];
    out->height_step = h[2];
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
