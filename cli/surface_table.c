/*
 * surface_table.c: a project option's rows per surface, as a table or
 * JSON. See surface_table.h.
 */
#include "surface_table.h"

#include <math.h>
#include <string.h>

#include "core/base/units.h"
#include "core/base/text.h"
#include "text_table.h"

void surface_table_print(FILE *out, const struct surface_row *surfaces,
                         const struct option_surface_row *rows, size_t n)
{
    static const struct text_column heads[] = {
        {"surface", "", 8, 1, 0, 0},
        {"grid", "", 9, 0, 0, 0},
        {"panels", "", 7, 0, 9, 0},
        {"FP", "", 6, 0, 5, 0},
        {"SP", "", 6, 0, 5, 0},
        {"DP", "", 6, 0, 5, 0},
        {"cost", "USD", 13, 0, 8, 0},
        {"moulds", "started", 8, 0, 6, 0},
        {"moulds", "used", 7, 0, 6, 0},
        {"max dev", "mm", 8, 0, 7, 0},
        {"max gap", "mm", 8, 0, 4, 0},
        {"max kink", "deg", 9, 0, 4, 0},
    };
    enum { COLUMNS = sizeof heads / sizeof *heads, NAME_MOST = 40 };
    struct text_column column[COLUMNS];
    memcpy(column, heads, sizeof heads);
    for (size_t i = 0; i < n; i++) {
        int len = (int)strlen(surfaces[i].name);
        if (len > column[0].width)
            column[0].width = len < NAME_MOST ? len : NAME_MOST;
    }
    struct text_table t = {column, COLUMNS, {0}, 0, 0};
    text_table_fit(&t, text_table_width(out, 0));
    text_table_head(out, &t);
    for (size_t i = 0; i < n; i++) {
        const struct option_surface_row *r = &rows[i];
        const struct option_totals *s = &r->totals;
        char text[COLUMNS][64], name[sizeof surfaces[i].name];
        const char *cell[COLUMNS];
        text_for_terminal(surfaces[i].name, name, sizeof name);
        snprintf(text[0], sizeof text[0], "%.*s", (int)NAME_MOST, name);
        snprintf(text[1], sizeof text[1], "%d x %d", r->nu, r->nv);
        snprintf(text[2], sizeof text[2], "%zu", s->panels);
        snprintf(text[3], sizeof text[3], "%zu", s->count[TYPE_FP]);
        snprintf(text[4], sizeof text[4], "%zu", s->count[TYPE_SP]);
        snprintf(text[5], sizeof text[5], "%zu", s->count[TYPE_DP]);
        quantity_number_text(text[6], sizeof text[6], s->cost, 0, 1);
        snprintf(text[7], sizeof text[7], "%zu", s->moulds);
        snprintf(text[8], sizeof text[8], "%lld", (long long)r->moulds_used);
        quantity_number_text(text[9], sizeof text[9], s->max_deviation * 1000,
                          2, 0);
        quantity_number_text(text[10], sizeof text[10], units_mm(s->max_gap),
                             2, 0);
        quantity_number_text(text[11], sizeof text[11],
                             units_deg(s->max_kink), 2, 0);
        for (int k = 0; k < COLUMNS; k++)
            cell[k] = text[k];
        text_table_row(out, &t, cell);
    }
    text_table_foot(out, &t);
}

static void number_or_null(struct json_writer *w, const char *key,
                           double value)
{
    json_key(w, key);
    if (isfinite(value))
        json_number(w, value);
    else
        json_null(w);
}

static void count(struct json_writer *w, const char *key, long long value)
{
    json_key(w, key);
    json_integer(w, value);
}

void surface_table_json(struct json_writer *w,
                        const struct surface_row *surfaces,
                        const struct option_surface_row *rows, size_t n)
{
    json_begin_array(w);
    for (size_t i = 0; i < n; i++) {
        const struct option_surface_row *r = &rows[i];
        const struct option_totals *s = &r->totals;
        json_begin_object(w);
        json_key(w, "name");
        json_string(w, surfaces[i].name);
        count(w, "nu", r->nu);
        count(w, "nv", r->nv);
        count(w, "panels", (long long)s->panels);
        count(w, "fp_count", (long long)s->count[TYPE_FP]);
        count(w, "sp_count", (long long)s->count[TYPE_SP]);
        count(w, "dp_count", (long long)s->count[TYPE_DP]);
        number_or_null(w, "area", s->area);
        number_or_null(w, "cost", s->cost);
        count(w, "moulds", (long long)s->moulds);
        count(w, "moulds_used", (long long)r->moulds_used);
        number_or_null(w, "max_deviation", s->max_deviation);
        number_or_null(w, "max_gap", units_mm(s->max_gap));
        number_or_null(w, "max_kink", units_deg(s->max_kink));
        json_key(w, "feasible");
        json_bool(w, s->feasible);
        json_end_object(w);
    }
    json_end_array(w);
}
