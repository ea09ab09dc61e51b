/*
 * numrange.c: ranges A:B[:STEP] and pairs LEFT x RIGHT. See numrange.h.
 */
#include "core/base/numrange.h"

#include <assert.h>
#include <float.h>
#include <limits.h>
#include <math.h>
#include <string.h>

#include "core/base/numparse.h"

/* Reads one number of the spec's kind at text into *value, as numparse
 * does (NUMPARSE_RANGE sets *stop but not *value). */
static int read_number(const char *text, const char *end, int whole,
                       double *value, const char **stop)
{
    if (!whole)
        return numparse_double(text, end, value, stop);
    long long number;
    int rc = numparse_whole(text, end, 0, LLONG_MAX, &number, stop);
    if (rc == NUMPARSE_OK)
        *value = (double)number;
    return rc;
}

static const char *form_of(const struct numrange_spec *spec)
{
    if (spec->whole)
        return spec->stepped ? "N, A:B or A:B:STEP of whole numbers"
                             : "N or a range A:B of whole numbers";
    return spec->stepped ? "a number, A:B or A:B:STEP"
                         : "a number or a range A:B";
}

static int out_of_range(const char *text, int length,
                        const struct numrange_spec *spec, const char *what,
                        struct facet_error *err)
{
    if (spec->whole)
        return facet_error_set(err, FACET_EINPUT,
            "%s: '%.*s' is out of range (%.0f to %.0f)", what, length, text,
            spec->least, spec->most);
    if (spec->most == DBL_MAX)
        return facet_error_set(err, FACET_EINPUT,
            "%s: '%.*s' is out of range (at least %g)", what, length, text,
            spec->least);
    return facet_error_set(err, FACET_EINPUT,
        "%s: '%.*s' is out of range (%g to %g)", what, length, text,
        spec->least, spec->most);
}

static int bad_step(const char *text, int length, double step,
                    const struct numrange_spec *spec, const char *what,
                    struct facet_error *err)
{
    if (step > spec->most)
        return facet_error_set(err, FACET_EINPUT,
            "%s: the step of '%.*s' must be at most %g", what, length, text,
            spec->most);
    if (spec->step_least > 0)
        return facet_error_set(err, FACET_EINPUT,
            "%s: the step of '%.*s' must be at least %g", what, length,
            text, spec->step_least);
    return facet_error_set(err, FACET_EINPUT,
        "%s: the step of '%.*s' must be above 0", what, length, text);
}

int numrange_parse(const char *text, const char *end,
                   const struct numrange_spec *spec, const char *what,
                   struct numrange *out, struct facet_error *err)
{
    assert(!spec->whole || spec->least >= 0);
    int length = (int)(end - text), parts = 0, over = 0;
    double v[3] = {0, 0, 0};
    /* The whole text is read before any value is judged: '1e999:x' is
     * not a range, before it is a range too large. */
    for (const char *p = text;;) {
        const char *stop;
        int rc = read_number(p, end, spec->whole, &v[parts], &stop);
        if (rc == NUMPARSE_SYNTAX)
            return facet_error_set(err, FACET_EINPUT, "%s: '%.*s' is not %s",
                                   what, length, text, form_of(spec));
        over |= rc == NUMPARSE_RANGE;
        parts++;
        if (stop == end)
            break;
        if (*stop != ':' || parts == (spec->stepped ? 3 : 2))
            return facet_error_set(err, FACET_EINPUT, "%s: '%.*s' is not %s",
                                   what, length, text, form_of(spec));
        p = stop + 1;
    }
    /* + 0.0 makes a -0 the 0 it means: no "-0" in a table. */
    double min = v[0] + 0.0, max = (parts >= 2 ? v[1] : v[0]) + 0.0;
    if (over || !(min >= spec->least && min <= spec->most) ||
        !(max >= spec->least && max <= spec->most))
        return out_of_range(text, length, spec, what, err);
    if (max < min)
        return facet_error_set(err, FACET_EINPUT, "%s: %g:%g runs backwards",
                               what, min, max);
    double step = parts == 3 ? v[2] + 0.0 : spec->step_default;
    if (parts == 3 && (!(step > 0) || step < spec->step_least ||
                       step > spec->most))
        return bad_step(text, length, step, spec, what, err);
    double values = numrange_count(min, max, step, spec->slack);
    if (spec->values_max > 0 && !(values <= spec->values_max))
        return facet_error_set(err, FACET_EINPUT,
            "%s: '%.*s' is %.*g steps (at most %.0f: take a larger step%s)",
            what, length, text, values < 1e15 ? 15 : 3, values,
            spec->values_max, spec->stepped && spec->step_default == 0
                ? ", or a continuous range A:B" : "");
    *out = (struct numrange){min, max, step};
    return FACET_OK;
}

double numrange_count(double min, double max, double step, double slack)
{
    if (!(step > 0) || !(max > min))
        return 1;
    return floor((max - min) / step + slack) + 1;
}

static int blank(char c)
{
    return c == ' ' || c == '\t';
}

int numrange_pair_split(const char *text, const char *end,
                        struct numrange_pair *out)
{
    const char *x = NULL;
    for (const char *p = text; p < end; p++)
        if (*p == 'x' || *p == 'X') {
            if (x != NULL)
                return -1;
            x = p;
        }
    if (x == NULL)
        return -1;
    struct numrange_pair pair = {text, x, x + 1, end};
    while (pair.left < pair.left_end && blank(*pair.left))
        pair.left++;
    while (pair.left_end > pair.left && blank(pair.left_end[-1]))
        pair.left_end--;
    while (pair.right < pair.right_end && blank(*pair.right))
        pair.right++;
    while (pair.right_end > pair.right && blank(pair.right_end[-1]))
        pair.right_end--;
    if (pair.left == pair.left_end || pair.right == pair.right_end)
        return -1;
    *out = pair;
    return 0;
}

/* One side of a grid: 1 if it is a whole number from 1 to max, 0 if it
 * is a whole number out of that range, -1 if it is none. */
static int grid_side(const char *text, const char *end, int max, int *out)
{
    long long number;
    const char *stop;
    int rc = numparse_whole(text, end, 0, LLONG_MAX, &number, &stop);
    if (rc == NUMPARSE_SYNTAX || stop != end)
        return -1;
    if (rc == NUMPARSE_RANGE || number < 1 || number > max)
        return 0;
    *out = (int)number;
    return 1;
}

int numrange_grid(const char *text, int max, const char *what, int *nu,
                  int *nv, struct facet_error *err)
{
    struct numrange_pair pair;
    int u = 0, v = 0, su = -1, sv = -1;
    if (numrange_pair_split(text, text + strlen(text), &pair) == 0) {
        su = grid_side(pair.left, pair.left_end, max, &u);
        sv = grid_side(pair.right, pair.right_end, max, &v);
    }
    if (su < 0 || sv < 0)
        return facet_error_set(err, FACET_EINPUT,
            "%s: '%s' is not NUxNV (e.g. 37x49)", what, text);
    if (su == 0 || sv == 0)
        return facet_error_set(err, FACET_EINPUT,
            "%s: '%s' is out of range (each side 1 to %d)", what, text, max);
    *nu = u;
    *nv = v;
    return FACET_OK;
}
