/*
 * format.c: numbers as the workbench writes them. See format.h.
 */
#include "format.h"

#include <assert.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "core/base/text.h"

void tui_fmt_number(char *out, size_t size, double value, int decimals,
                    int thousands)
{
    quantity_number_text(out, size, value, decimals, thousands);
}

void tui_fmt_elapsed(char *out, size_t size, double seconds)
{
    if (!isfinite(seconds) || seconds < 0)
        snprintf(out, size, "-");
    else if (seconds < 10)
        snprintf(out, size, "%.2f s", seconds);
    else if (seconds < 60)
        snprintf(out, size, "%.1f s", seconds);
    else if (seconds < 3600)
        snprintf(out, size, "%dm%02ds", (int)seconds / 60,
                 (int)seconds % 60);
    else
        snprintf(out, size, "%dh%02dm", (int)(seconds / 3600),
                 (int)fmod(seconds / 60, 60));
}

void tui_fmt_started(char *out, size_t size, const char *iso)
{
    /* "YYYY-MM-DDTHH:MM:SSZ" -> "YYYY-MM-DD HH:MM" */
    if (strlen(iso) >= 16 && iso[10] == 'T')
        snprintf(out, size, "%.10s %.5s", iso, iso + 11);
    else
        snprintf(out, size, "%s", iso[0] ? iso : "-");
}

const struct tui_column tui_option_columns[] = {
    {"number", 7, 0},
    {"rank", 1, 1},
    {"planarity", 9, 0},
    {"dp_area", 8, 0},
    {"cost", 10, 0},
    {"fp_area", 8, 0},
    {"sp_area", 8, 0},
    {"nu", 3, 0},
    {"nv", 3, 0},
    {"threshold_mm", 5, 0},
    {"feasible", 3, 0},
    {"rank", 4, 0},
    /* hidden until the column chooser shows them */
    {"area", 8, 0},
    {"panels", 6, 0},
    {"dp_count", 5, 0},
    {"max_panel_area", 7, 0},
    {"max_deviation", 7, 0},
    {"p_dist", 9, 0},
    {"moulds", 6, 0},
    {"sp_moulds", 6, 0},
    {"dp_moulds", 6, 0},
    {"joint_length", 7, 0},
    {"mould_cost", 10, 0},
    {"max_gap", 7, 0},
    {"max_kink", 8, 0},
    {"sp_misfits", 6, 0},
    {"min_panel_width", 6, 0},
    {"slivers", 7, 0},
    {"crowding", 8, 0},  /* "boundary" at a front's end */
    {"generation", 4, 0},
};
const int tui_option_column_default_count = 12;
const int tui_option_column_count =
    (int)(sizeof tui_option_columns / sizeof tui_option_columns[0]);

const char *const tui_metric_columns[] = {
    "number", "cost", "planarity", "dp_area", "fp_area", "sp_area", "area",
    "nu", "nv", "threshold_mm", "panels", "fp_count", "sp_count",
    "dp_count", "max_deviation", "max_panel_area", "p_dist", "feasible",
    "rank", "crowding", "knee", "generation", "moulds", "sp_moulds",
    "dp_moulds", "joint_length", "largest_family", "single_moulds",
    "area_cost", "panel_cost", "joint_cost", "mould_cost", "max_gap",
    "mean_gap", "max_kink", "mean_kink", "gaps_over", "kinks_over",
    "sp_misfits", "sp_fitted", "sp_min_radius", "min_panel_area",
    "min_panel_width", "slivers",
};
const int tui_metric_column_count =
    (int)(sizeof tui_metric_columns / sizeof tui_metric_columns[0]);

const struct quantity *tui_column_of(const struct tui_column *c)
{
    const struct quantity *column = quantity_named(c->column);
    assert(column != NULL);
    return column;
}

const char *tui_column_title(const struct tui_column *c)
{
    return c->pareto_mark ? "P" : tui_column_of(c)->heading;
}

const char *tui_column_unit(const struct tui_column *c)
{
    return c->pareto_mark ? "" : tui_column_of(c)->unit;
}

void tui_fmt_value(char *out, size_t size, const struct quantity *c,
                   double value)
{
    const char *words = strcmp(c->name, "crowding") == 0
                            ? tui_crowding_words(value) : NULL;
    if (words != NULL)
        snprintf(out, size, "%s", words);
    else
        quantity_text(out, size, c, value, c->decimals);
}

const char *tui_crowding_words(double crowding)
{
    return isinf(crowding) && crowding > 0 ? "boundary" : NULL;
}

void tui_fmt_violation(char *out, size_t size, const struct option_totals *t,
                       const struct run_info *run)
{
    double term[LIMIT_COUNT];
    unsigned broken = classify_broken_limits(t, run->max_panel_area, term);
    size_t used = 0;
    out[0] = '\0';
    for (int k = 0; k < LIMIT_COUNT && used < size; k++) {
        if (!(broken & 1u << k))
            continue;
        const char *sep = used ? ", " : "";
        size_t n = (size_t)term[k];  /* a count but for the area */
        const char *s = n == 1 ? "" : "s";
        switch ((enum classify_limit)k) {
        case LIMIT_PANEL_AREA:
            used += (size_t)snprintf(out + used, size - used,
                                     "%spanel %.2f m^2 > %.2f m^2 limit",
                                     sep, t->max_panel_area,
                                     run->max_panel_area);
            break;
        case LIMIT_PANEL_WIDTH:
            used += (size_t)snprintf(out + used, size - used,
                                     "%s%zu sliver%s < %.2f m limit", sep,
                                     n, s, run->min_panel_width);
            break;
        case LIMIT_GAP:
            used += (size_t)snprintf(out + used, size - used,
                                     "%s%zu gap%s > %g mm limit", sep, n, s,
                                     run->max_gap_mm);
            break;
        case LIMIT_KINK:
            used += (size_t)snprintf(out + used, size - used,
                                     "%s%zu kink%s > %g deg limit", sep, n,
                                     s, run->max_kink_deg);
            break;
        case LIMIT_PLANARIZE:
            used += (size_t)snprintf(out + used, size - used,
                                     "%s%zu quad%s not planar or > %g mm "
                                     "off the surface", sep, n, s,
                                     run->planarize_closeness_mm);
            break;
        case LIMIT_COUNT:
            break;
        }
    }
    if (used == 0)
        snprintf(out, size, "over a limit");
}

const struct quantity *tui_shown_column(const struct quantity *c,
                                             const struct option_row *option)
{
    return isnan(option->module_w) ? c
                                   : quantity_of_project(c->name);
}

/* terms[0 .. n) (USD, >= 0) rounded to whole dollars that add up to
 * total rounded (largest remainder); a term that is not finite stays as
 * it is. */
static void round_terms(const double *terms, int n, double total,
                        double *rounded)
{
    double sum = 0, remainder[8];
    assert(n <= 8);
    for (int k = 0; k < n; k++) {
        rounded[k] = isfinite(terms[k]) ? floor(terms[k]) : terms[k];
        remainder[k] = isfinite(terms[k]) ? terms[k] - rounded[k] : -1;
        if (isfinite(terms[k]))
            sum += rounded[k];
    }
    /* the total as tui_fmt_number shows it: printf rounds half to even */
    double missing = rint(total) - sum;
    while (missing >= 1) {
        int most = -1;
        for (int k = 0; k < n; k++)
            if (remainder[k] >= 0 &&
                (most < 0 || remainder[k] > remainder[most]))
                most = k;
        if (most < 0)
            break;
        rounded[most] += 1;
        remainder[most] = -1;  /* once each: a dollar at most */
        missing -= 1;
    }
}

void tui_fmt_cost_sum(char *out, size_t size, const struct option_totals *t,
                      int width)
{
    static const char *const name[6] = {"FP", "SP", "DP", "panels",
                                        "joints", "moulds"};
    double term[6] = {t->cost_of[TYPE_FP], t->cost_of[TYPE_SP],
                      t->cost_of[TYPE_DP], t->panel_cost, t->joint_cost,
                      t->mould_cost};
    double grouped[4] = {t->area_cost, t->panel_cost, t->joint_cost,
                         t->mould_cost};
    double shown[6], shown_grouped[4];
    round_terms(term, 6, t->cost, shown);
    round_terms(grouped, 4, t->cost, shown_grouped);
    char total[32];
    tui_fmt_number(total, sizeof total, t->cost, 0, 1);
    for (int form = 0; form < 3; form++) {
        int n = form == 0 ? 6 : form == 1 ? 4 : 0;
        const double *v = form == 0 ? shown : shown_grouped;
        size_t used = (size_t)snprintf(out, size, "cost %s USD", total);
        int first = 1;
        for (int k = 0; k < n && used < size; k++) {
            /* the types of the area always; a term beyond it when priced */
            int type = form == 0 && k < 3;
            if (!isfinite(v[k]) || (!type && v[k] == 0))
                continue;
            char number[32];
            tui_fmt_number(number, sizeof number, v[k], 0, 1);
            used += (size_t)snprintf(out + used, size - used, " %s %s %s",
                                     first ? "=" : "+",
                                     form == 1 && k == 0 ? "area"
                                     : name[form == 0 ? k : k + 2],
                                     number);
            first = 0;
        }
        if ((int)used <= width || form == 2)
            return;
    }
}

void tui_fmt_fields(char *out, size_t size, int width,
                    const char *const *fields, int n)
{
    tui_fmt_list(out, size, width, fields, n, " | ", " | ");
}

void tui_fmt_list(char *out, size_t size, int width,
                  const char *const *fields, int n, const char *lead,
                  const char *sep)
{
    assert(n >= 1 && size > 0);
    for (int kept = n; kept >= 1; kept--) {
        size_t used = 0;
        out[0] = '\0';
        for (int k = 0; k < kept && used < size; k++)
            used += (size_t)snprintf(out + used, size - used, "%s%s",
                                     k == 0 ? "" : k == 1 ? lead : sep,
                                     fields[k]);
        if ((int)text_columns(out) <= width || kept == 1)
            break;
    }
    /* the title alone too wide: cut it, at a character's start */
    out[text_cut(out, width)] = '\0';
}

void tui_fmt_grid(char *out, size_t size, const struct option_row *option)
{
    if (isnan(option->module_w))
        snprintf(out, size, "%d x %d", option->nu, option->nv);
    else
        snprintf(out, size, "module %.2f x %.2f m", option->module_w,
                 option->module_h);
}

void tui_fmt_cell(char *out, size_t size, const struct tui_column *c,
                  const struct option_row *option)
{
    const struct quantity *column =
        tui_shown_column(tui_column_of(c), option);
    /* A project's module, to 0.1 m in the narrow U or V column (the side
     * pane and o give it whole). */
    int module = column != tui_column_of(c);
    double value = quantity_value(column, option);
    char text[64];
    if (module) {
        quantity_text(text, sizeof text, column, value, 1);
        if ((int)strlen(text) > c->width)
            quantity_text(text, sizeof text, column, value, 0);
    } else if (c->pareto_mark)
        text[0] = '\0';  /* the caller draws the glyph */
    else if (column->writer == WRITTEN_BY_RANKING && option->rank <= 0)
        snprintf(text, sizeof text, "-");  /* not ranked yet */
    else if (strcmp(column->name, "crowding") == 0 &&
             tui_crowding_words(value) != NULL)
        /* a front's end, as the detail pane says it, never "inf" */
        snprintf(text, sizeof text, "%s", tui_crowding_words(value));
    else
        quantity_text(text, sizeof text, column, value,
                          column->list_decimals);
    snprintf(out, size, "%*s", c->width, text);
}
