/*
 * metric.c: objective lists. See metric.h.
 */
#include "core/search/metric.h"

#include <assert.h>
#include <stdio.h>
#include <string.h>

struct objective objective_named(const char *name)
{
    const struct quantity *q = quantity_named(name);
    assert(q != NULL && q->objective);
    return (struct objective){q, 0};
}

double objective_value(const struct option_totals *totals,
                       const struct objective *o)
{
    double value = quantity_of_totals(o->quantity, totals);
    return o->maximise ? -value : value;
}

unsigned objectives_measures(const struct objective *objectives, int count)
{
    unsigned measures = 0;
    for (int k = 0; k < count; k++)
        measures |= objectives[k].quantity->measure;
    return measures;
}

/* The names that can be objectives, "cost, planarity, ...". */
static void objective_names(char *out, size_t size)
{
    size_t len = 0;
    out[0] = '\0';
    for (int k = 0; k < OPTION_QUANTITIES && len < size; k++)
        if (option_quantities[k].objective)
            len += (size_t)snprintf(out + len, size - len, "%s%s",
                                    len ? ", " : "",
                                    option_quantities[k].name);
}

int objectives_parse(const char *text, const char *what,
                     struct objective *objectives, int *count,
                     struct facet_error *err)
{
    char list[512];
    objective_names(list, sizeof list);
    *count = 0;
    const char *p = text;
    while (*p != '\0') {
        const char *end = strchr(p, ',');
        size_t length = end ? (size_t)(end - p) : strlen(p);
        int maximise = 0;
        if (length > 4 && strncmp(p, "max:", 4) == 0) {
            maximise = 1;
            p += 4;
            length -= 4;
        } else if (length > 4 && strncmp(p, "min:", 4) == 0) {
            p += 4;
            length -= 4;
        }
        const struct quantity *found = NULL;
        for (int k = 0; k < OPTION_QUANTITIES; k++) {
            const struct quantity *q = &option_quantities[k];
            if (q->objective && strlen(q->name) == length &&
                strncmp(q->name, p, length) == 0)
                found = q;
        }
        if (found == NULL)
            return facet_error_set(err, FACET_EINPUT,
                "%s: unknown metric '%.*s' (choose from %s)", what,
                (int)length, p, list);
        for (int k = 0; k < *count; k++)
            if (objectives[k].quantity == found)
                return facet_error_set(err, FACET_EINPUT,
                    "%s: '%s' is named twice", what, found->name);
        if (*count >= OBJECTIVES_MAX)
            return facet_error_set(err, FACET_EINPUT,
                "%s: at most %d objectives", what, OBJECTIVES_MAX);
        objectives[*count].quantity = found;
        objectives[*count].maximise = maximise;
        (*count)++;
        if (end == NULL)
            break;
        p = end + 1;
    }
    if (*count == 0)
        return facet_error_set(err, FACET_EINPUT,
            "%s: name at least one metric (%s)", what, list);
    return FACET_OK;
}

void objectives_format(char *out, size_t size,
                       const struct objective *objectives, int count)
{
    size_t len = 0;
    out[0] = '\0';
    for (int k = 0; k < count && len < size; k++)
        len += (size_t)snprintf(out + len, size - len, "%s%s%s",
                                k ? "," : "",
                                objectives[k].maximise ? "max:" : "",
                                objectives[k].quantity->name);
}
