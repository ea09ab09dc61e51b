/*
 * metric.c: metric names and values, and objective lists. See metric.h.
 */
#include "core/search/metric.h"

#include "core/classify/option.h"

#include <stdio.h>
#include <string.h>

static const char *const names[METRIC_COUNT] = {
    "cost", "planarity", "dp_area", "fp_area", "sp_area", "panels",
    "fp_count", "sp_count", "dp_count", "max_deviation", "max_panel_area",
    "p_dist", "moulds", "sp_moulds", "dp_moulds", "joint_length",
    "max_gap", "max_kink", "sp_misfits",
};

const char *metric_name(enum metric metric)
{
    return (unsigned)metric < METRIC_COUNT ? names[metric] : NULL;
}

double metric_value(const struct option_totals *t, enum metric metric)
{
    switch (metric) {
    case METRIC_COST:           return t->cost;
    case METRIC_PLANARITY:      return t->planarity;
    case METRIC_DP_AREA:        return t->area_of[TYPE_DP];
    case METRIC_FP_AREA:        return t->area_of[TYPE_FP];
    case METRIC_SP_AREA:        return t->area_of[TYPE_SP];
    case METRIC_PANELS:         return (double)t->panels;
    case METRIC_FP_COUNT:       return (double)t->count[TYPE_FP];
    case METRIC_SP_COUNT:       return (double)t->count[TYPE_SP];
    case METRIC_DP_COUNT:       return (double)t->count[TYPE_DP];
    case METRIC_MAX_DEVIATION:  return t->max_deviation;
    case METRIC_MAX_PANEL_AREA: return t->max_panel_area;
    case METRIC_P_DIST:         return t->p_dist;
    case METRIC_MOULDS:         return totals_count(t->moulds);
    case METRIC_SP_MOULDS:      return totals_count(t->moulds_of[TYPE_SP]);
    case METRIC_DP_MOULDS:      return totals_count(t->moulds_of[TYPE_DP]);
    case METRIC_JOINT_LENGTH:   return t->joint_length;
    case METRIC_MAX_GAP:        return t->max_gap_mm;
    case METRIC_MAX_KINK:       return t->max_kink_deg;
    case METRIC_SP_MISFITS:     return (double)t->sp_misfits;
    default:                    return 0;
    }
}

unsigned metric_measures(enum metric metric)
{
    switch (metric) {
    case METRIC_MOULDS:
    case METRIC_SP_MOULDS:
    case METRIC_DP_MOULDS:      return OPTION_MEASURE_MOULDS;
    case METRIC_JOINT_LENGTH:   return OPTION_MEASURE_JOINT_LENGTH;
    case METRIC_MAX_GAP:
    case METRIC_MAX_KINK:       return OPTION_MEASURE_JOINTS;
    case METRIC_SP_MISFITS:     return OPTION_MEASURE_FITS;
    default:                    return 0;
    }
}

double objective_value(const struct option_totals *totals,
                       const struct objective *o)
{
    double value = metric_value(totals, o->metric);
    return o->maximise ? -value : value;
}

int objectives_parse(const char *text, const char *what,
                     struct objective *objectives, int *count,
                     struct facet_error *err)
{
    char list[512] = "";
    for (int m = 0; m < METRIC_COUNT; m++) {
        strcat(list, m ? ", " : "");
        strcat(list, names[m]);
    }
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
        int found = -1;
        for (int m = 0; m < METRIC_COUNT; m++)
            if (strlen(names[m]) == length && strncmp(names[m], p, length) == 0)
                found = m;
        if (found < 0)
            return facet_error_set(err, FACET_EINPUT,
                "%s: unknown metric '%.*s' (choose from %s)", what,
                (int)length, p, list);
        for (int k = 0; k < *count; k++)
            if ((int)objectives[k].metric == found)
                return facet_error_set(err, FACET_EINPUT,
                    "%s: '%s' is named twice", what, names[found]);
        if (*count >= OBJECTIVES_MAX)
            return facet_error_set(err, FACET_EINPUT,
                "%s: at most %d objectives", what, OBJECTIVES_MAX);
        objectives[*count].metric = (enum metric)found;
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
                                metric_name(objectives[k].metric));
}
