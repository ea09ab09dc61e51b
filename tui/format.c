/*
 * format.c: numbers as the workbench writes them. See format.h.
 */
#include "format.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "core/base/numformat.h"

void tui_fmt_number(char *out, size_t size, double value, int decimals,
                    int thousands)
{
    if (size == 0)
        return;
    if (thousands && !(fabs(value) >= 1e18)) {
        number_grouped(out, size, value, decimals);
        return;
    }
    if (isnan(value))
        snprintf(out, size, "-");
    else if (isinf(value))
        snprintf(out, size, value > 0 ? "inf" : "-inf");
    else
        snprintf(out, size, "%.*f", decimals, value);
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
    {"number", "No.", "", 7, 0, 0, COLUMN_NUMBER, 1},
    {"rank", "P", "", 1, 0, 0, COLUMN_PARETO, 1},
    {"planarity", "planarity", "m", 9, 3, 0, COLUMN_NUMBER, 1},
    {"dp_area", "DP area", "m^2", 8, 1, 0, COLUMN_NUMBER, 1},
    {"cost", "cost", "USD", 10, 0, 1, COLUMN_NUMBER, 1},
    {"fp_area", "FP area", "m^2", 8, 1, 0, COLUMN_NUMBER, 1},
    {"sp_area", "SP area", "m^2", 8, 1, 0, COLUMN_NUMBER, 1},
    {"nu", "U", "", 3, 0, 0, COLUMN_NUMBER, 1},
    {"nv", "V", "", 3, 0, 0, COLUMN_NUMBER, 1},
    {"threshold_mm", "t", "mm", 5, 2, 0, COLUMN_NUMBER, 1},
    {"feasible", "ok", "", 3, 0, 0, COLUMN_YESNO, 1},
    {"rank", "rank", "", 4, 0, 0, COLUMN_NUMBER, 1},
    /* hidden until the column chooser shows them */
    {"area", "area", "m^2", 8, 1, 0, COLUMN_NUMBER, 1},
    {"panels", "panels", "", 6, 0, 0, COLUMN_NUMBER, 1},
    {"dp_count", "DP n", "", 5, 0, 0, COLUMN_NUMBER, 1},
    {"max_panel_area", "max pan", "m^2", 7, 2, 0, COLUMN_NUMBER, 1},
    {"max_deviation", "max dev", "mm", 7, 2, 0, COLUMN_NUMBER, 1000},
    {"p_dist", "P_dist", "m^4", 9, 4, 0, COLUMN_NUMBER, 1},
    {"crowding", "crowd", "", 6, 3, 0, COLUMN_NUMBER, 1},
    {"generation", "gen", "", 4, 0, 0, COLUMN_NUMBER, 1},
};
const int tui_option_column_default_count = 12;
const int tui_option_column_count =
    (int)(sizeof tui_option_columns / sizeof tui_option_columns[0]);

const struct tui_column tui_metric_columns[] = {
    {"number", "No.", "", 7, 0, 0, COLUMN_NUMBER, 1},
    {"cost", "cost", "USD", 12, 0, 1, COLUMN_NUMBER, 1},
    {"planarity", "planarity", "m", 10, 4, 0, COLUMN_NUMBER, 1},
    {"dp_area", "DP area", "m^2", 10, 2, 0, COLUMN_NUMBER, 1},
    {"fp_area", "FP area", "m^2", 10, 2, 0, COLUMN_NUMBER, 1},
    {"sp_area", "SP area", "m^2", 10, 2, 0, COLUMN_NUMBER, 1},
    {"area", "area", "m^2", 10, 2, 0, COLUMN_NUMBER, 1},
    {"nu", "U", "", 5, 0, 0, COLUMN_NUMBER, 1},
    {"nv", "V", "", 5, 0, 0, COLUMN_NUMBER, 1},
    {"threshold_mm", "threshold", "mm", 8, 2, 0, COLUMN_NUMBER, 1},
    {"panels", "panels", "", 7, 0, 0, COLUMN_NUMBER, 1},
    {"fp_count", "FP panels", "", 7, 0, 0, COLUMN_NUMBER, 1},
    {"sp_count", "SP panels", "", 7, 0, 0, COLUMN_NUMBER, 1},
    {"dp_count", "DP panels", "", 7, 0, 0, COLUMN_NUMBER, 1},
    {"max_deviation", "max deviation", "mm", 10, 2, 0, COLUMN_NUMBER, 1000},
    {"max_panel_area", "max panel area", "m^2", 10, 2, 0, COLUMN_NUMBER, 1},
    {"p_dist", "P_dist", "m^4", 12, 6, 0, COLUMN_NUMBER, 1},
    {"feasible", "feasible", "", 4, 0, 0, COLUMN_YESNO, 1},
    {"rank", "rank", "", 5, 0, 0, COLUMN_NUMBER, 1},
    {"crowding", "crowding", "", 8, 3, 0, COLUMN_NUMBER, 1},
    {"knee", "knee", "", 4, 0, 0, COLUMN_YESNO, 1},
    {"generation", "generation", "", 5, 0, 0, COLUMN_NUMBER, 1},
};
const int tui_metric_column_count =
    (int)(sizeof tui_metric_columns / sizeof tui_metric_columns[0]);

const struct tui_column *tui_metric_column(const char *column)
{
    for (int k = 0; k < tui_metric_column_count; k++)
        if (strcmp(tui_metric_columns[k].column, column) == 0)
            return &tui_metric_columns[k];
    return NULL;
}

void tui_fmt_value(char *out, size_t size, const struct tui_column *c,
                   double value)
{
    if (c->kind == COLUMN_YESNO)
        snprintf(out, size, "%s", isnan(value) ? "-" : value != 0 ? "yes"
                                                                  : "no");
    else if (c->kind == COLUMN_PARETO)
        snprintf(out, size, "%s", value == 1 ? "*" : "");
    else
        tui_fmt_number(out, size, value * c->scale, c->decimals,
                       c->thousands);
}

void tui_fmt_cell(char *out, size_t size, const struct tui_column *c,
                  const struct option_row *option)
{
    char text[64];
    double value = store_option_value(option, c->column);
    if (c->kind == COLUMN_NUMBER && strcmp(c->column, "rank") == 0 &&
        value == 0)
        snprintf(text, sizeof text, "-");  /* not ranked yet */
    else
        tui_fmt_value(text, sizeof text, c, value);
    if (c->kind == COLUMN_PARETO)
        text[0] = '\0';  /* the caller draws the glyph */
    snprintf(out, size, "%*s", c->width, text);
}
