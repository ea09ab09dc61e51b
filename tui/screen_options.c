/*
 * screen_options.c: the Options table of one run: one row per design
 * option (No., Pareto mark, planarity, DP area, cost, FP area, SP area,
 * U, V, threshold, feasibility, rank), right-aligned with units in the
 * header; sort by any column with a secondary key, the --where filter
 * line, Pareto-only, jump to the knee, marks for Compare, and a detail
 * pane with every metric of the selected option. Rows come a page at a
 * time through table_model; the scatter and compare screens share the
 * model, so selection and filter stay linked. A running run refills live.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "app.h"
#include "format.h"
#include "input.h"
#include "keys.h"
#include "layout.h"
#include "study/study.h"
#include "study/study_export.h"

struct options_screen {
    struct tui_screen base;
    struct table_model model;    /* model.run: the run shown */
    int64_t top;                 /* first row shown */
    int rows;                    /* rows shown at the last draw */
    int column;                  /* column cursor (tui_option_columns) */
    int vis[TUI_COLUMNS_MAX];    /* the shown columns (app->columns) */
    int nvis;
    int choosing;                /* the column chooser is open */
    int choice;                  /* its cursor: a place in the order */
    int choice_top;              /* its first row shown */
    struct browse_key keys[2];   /* primary, secondary */
    int nkeys;
    int editing;                 /* the filter line is open */
    struct tui_input filter;
    int detail;                  /* the detail pane is shown */
    int exporting;               /* the marked options' CSV line is open */
    struct tui_input export_to;
    struct timespec last_refresh;
    double refresh_seconds;      /* what the last refresh of a live run
                                    took */
    int64_t runs_finished;       /* app->runs_finished when last seen */
    int64_t job_samples;         /* app->job_samples when last seen */
};

static const struct tui_key_help options_help[] = {
    {"j/k, Up/Down", "select an option"},
    {"PgUp/PgDn, g/G", "a page up / down, first / last option"},
    {"h/l, Left/Right", "move the column cursor (highlighted header)"},
    {"s, F6", "sort by the cursor's column; again: reverse it"},
    {"S", "secondary key: the cursor's column (asc, desc, off)"},
    {"< / >", "sort by the previous / next column"},
    {"I", "invert the primary sort direction"},
    {"F", "sorted, the feasible options first (the default) or mixed in "
          "by the keys alone (toggle); an infeasible row is dim, x in P"},
    {"/, F3", "filter, e.g. cost < 1.6M and dp_area <= 900 or pareto"},
    {"  Up/Down", "  (filter line) the filters entered before"},
    {"p, F4", "Pareto-optimal options only (toggle)"},
    {"K", "jump to the knee option"},
    {"n / N", "next / previous Pareto-optimal option"},
    {"Space", "mark / unmark the option for Compare"},
    {"u", "clear every mark"},
    {"c, F7", "compare the marked options (2 to 4)"},
    {"Enter, m, F8", "panel map of the option (a project's: surface by "
                     "surface, ] and [)"},
    {"o", "a project run's option: its surfaces, a row each (grid, "
          "panels, FP/SP/DP, cost, moulds, deviation, gap, kink)"},
    {"x, F5", "scatter plot (planarity vs cost)"},
    {"|, a", "parallel coordinates (brushing sets the filter)"},
    {"C, F2", "column chooser: show, hide and reorder the columns"},
    {"  j/k, Space", "  (chooser) move; show / hide the column"},
    {"  J/K, +/-", "  (chooser) move the column down / up the order"},
    {"  r, Enter/q", "  (chooser) default columns; close"},
    {"t", "statistics of the options shown: min/median/max/mean, per U, "
          "V, t, class"},
    {"T", "per generation: options and the best found so far (NSGA-II)"},
    {"L", "like this: a New run around the option (narrower space)"},
    {"E", "export the marked options (every column) as CSV"},
    {"d", "show / hide the detail pane"},
    {"r", "reload from the database"},
    {NULL, NULL},
};

/* Reads the session's column set; the cursor moves to the first shown
 * column when its own is hidden. */
static void columns_update(struct options_screen *s, struct tui_app *app)
{
    s->nvis = tui_columns_visible(&app->columns, s->vis);
    for (int v = 0; v < s->nvis; v++)
        if (s->vis[v] == s->column)
            return;
    s->column = s->vis[0];
}

/* The place of the cursor's column among the shown ones. */
static int cursor_place(const struct options_screen *s)
{
    for (int v = 0; v < s->nvis; v++)
        if (s->vis[v] == s->column)
            return v;
    return 0;
}

static int is_marked(const struct options_screen *s, int64_t number)
{
    return table_model_marked(&s->model, number);
}

/* --- drawing --- */

/* "feasible first, cost asc, then planarity desc" (feasible_first: the
 * model's, when it is to be said) */
static void sort_text(const struct options_screen *s, int feasible_first,
                      char *out, size_t size)
{
    if (s->nkeys == 0) {
        snprintf(out, size, "number asc");
        return;
    }
    size_t n = 0;
    if (feasible_first)
        n += (size_t)snprintf(out, size, "feasible first, ");
    for (int k = 0; k < s->nkeys && n < size; k++)
        n += (size_t)snprintf(out + n, size - n, "%s%s %s",
                              k ? ", then " : "", s->keys[k].column,
                              s->keys[k].descending ? "desc" : "asc");
}

/* The key index (0 primary, 1 secondary) of column c, or -1. */
static int key_of(const struct options_screen *s, int c)
{
    for (int k = 0; k < s->nkeys; k++)
        if (strcmp(s->keys[k].column, tui_option_columns[c].column) == 0)
            return k;
    return -1;
}

static void draw_header(struct options_screen *s, struct tui_app *app,
                        int y, int width)
{
    tui_fill(y, 0, width, tui_attr(ROLE_HEADER));
    tui_fill(y + 1, 0, width, tui_attr(ROLE_HEADER));
    int x = 0;
    for (int v = 0; v < s->nvis && x < width; v++) {
        int c = s->vis[v];
        const struct tui_column *col = &tui_option_columns[c];
        int key = key_of(s, c);
        /* feasibility leads a sort: the ok column is its key, down */
        int leads = key < 0 && s->nkeys > 0 &&
                    s->model.browse.feasible_first &&
                    strcmp(col->column, "feasible") == 0;
        attr_t attr = c == s->column ? tui_attr(ROLE_COLUMN)
                      : key >= 0 || leads ? tui_attr(ROLE_SORTED)
                                          : tui_attr(ROLE_HEADER);
        tui_fill(y, x, col->width, attr);
        tui_fill(y + 1, x, col->width, attr);
        const char *unit = tui_column_unit(col);
        const char *title = tui_column_title(col);
        /* a project run's U and V are its module (tui_fmt_cell) */
        if (store_run_is_project(&s->model.run) &&
            (strcmp(col->column, "nu") == 0 ||
             strcmp(col->column, "nv") == 0)) {
            title = col->column[1] == 'u' ? "W" : "H";
            unit = "m";
        }
        tui_putf(y, x, width - x, attr, "%*s", col->width, title);
        tui_putf(y + 1, x, width - x, attr, "%*s", col->width, unit);
        if (key >= 0) {
            /* the direction just left of the unit; "2" marks the
             * secondary key */
            int at = x + col->width - (int)strlen(unit) - 1 - key;
            if (at < x)
                at = x;
            tui_put(y + 1, at, 1, attr, s->keys[key].descending
                                            ? app->glyphs->down
                                            : app->glyphs->up);
            if (key == 1)
                tui_put(y + 1, at + 1, 1, attr, "2");
        } else if (leads) {
            tui_put(y + 1, x + col->width - 1, 1, attr, app->glyphs->down);
        }
        x += col->width + 1;
    }
}

static void draw_row(struct options_screen *s, struct tui_app *app, int y,
                     int width, const struct option_row *o, int selected)
{
    /* an infeasible option's row is dim, and its P column says it where
     * the terminal shows no dim (vt100) */
    int infeasible = !o->totals.feasible;
    attr_t base = selected     ? tui_attr(ROLE_SELECTION)
                  : infeasible ? tui_attr(ROLE_INFEASIBLE)
                               : A_NORMAL;
    if (selected)
        tui_fill(y, 0, width, base);
    int x = 0;
    char cell[64];
    for (int v = 0; v < s->nvis && x < width; v++) {
        int c = s->vis[v];
        const struct tui_column *col = &tui_option_columns[c];
        tui_fmt_cell(cell, sizeof cell, col, o);
        tui_put(y, x, width - x, base, cell);
        if (col->pareto_mark && o->rank == 1)
            tui_put(y, x, 1, selected ? base : tui_attr(o->knee ? ROLE_KNEE
                                                                : ROLE_PARETO),
                    o->knee ? app->glyphs->knee : app->glyphs->pareto);
        else if (col->pareto_mark && infeasible)
            tui_put(y, x, 1, base, app->glyphs->infeasible);
        if (v == 0 && is_marked(s, o->number))
            tui_put(y, x, 1, selected ? base : tui_attr(ROLE_MARKED),
                    app->glyphs->mark);
        x += col->width + 1;
    }
}

/* The selected option's metrics as short lines for the bottom pane: an
 * infeasible one names the limits it breaks (run's), the fields before
 * them dropped (the threshold, then the rank) where the line is short. */
static int detail_lines(const struct option_row *o,
                        const struct run_info *run, int width,
                        char lines[][160])
{
    const struct option_totals *t = &o->totals;
    char area[32];
    tui_fmt_number(area, sizeof area, t->area, 1, 1);
    char grid[64];
    tui_fmt_grid(grid, sizeof grid, o);
    /* A run ranks its options when it ends: until then rank and crowding
     * are NULL, never "rank 0 ... crowding 0". */
    char ranked[24];
    if (o->rank > 0)
        snprintf(ranked, sizeof ranked, "rank %d%s", o->rank,
                 o->knee ? " (knee)" : "");
    else
        snprintf(ranked, sizeof ranked, "not ranked yet");
    if (!isnan(o->module_w))
        /* o lists a project's surfaces' own grids */
        snprintf(lines[0], 160, "No. %lld: %s, t %.2f mm, %s, %s; o: "
                 "its surfaces", (long long)o->number, grid, o->threshold_mm,
                 ranked, t->feasible ? "feasible" : "infeasible");
    else if (t->feasible)
        snprintf(lines[0], 160, "No. %lld: %s, t %.2f mm, %s, "
                 "feasible, largest panel %.2f m^2", (long long)o->number,
                 grid, o->threshold_mm, ranked, t->max_panel_area);
    if (isnan(o->module_w) && !t->feasible) {
        char broken[120], threshold[32], rank[64];
        tui_fmt_violation(broken, sizeof broken, t, run);
        snprintf(threshold, sizeof threshold, ", t %.2f mm",
                 o->threshold_mm);
        snprintf(rank, sizeof rank, ", %s", ranked);
        for (int drop = 0; drop < 3; drop++) {
            char line[320];
            int n = snprintf(line, sizeof line, "No. %lld: %s%s%s, "
                             "infeasible: %s", (long long)o->number, grid,
                             drop < 1 ? threshold : "", drop < 2 ? rank : "",
                             broken);
            snprintf(lines[0], 160, "%.159s", line);
            if (n < width)
                break;
        }
    }
    tui_fmt_cost_sum(lines[1], 160, t, width);
    /* Counts and areas both with separators, each area in brackets with
     * its unit: "FP 702 425.2" read as one number. */
    char count[TYPE_COUNT + 1][32], type_area[TYPE_COUNT][32];
    tui_fmt_number(count[TYPE_COUNT], sizeof count[0], (double)t->panels, 0,
                   1);
    for (int k = 0; k < TYPE_COUNT; k++) {
        tui_fmt_number(count[k], sizeof count[k], (double)t->count[k], 0, 1);
        tui_fmt_number(type_area[k], sizeof type_area[k], t->area_of[k], 1,
                       1);
    }
    /* whole types dropped from the end where the line is short */
    char field[TYPE_COUNT + 1][80];
    const char *fields[TYPE_COUNT + 1];
    snprintf(field[0], sizeof field[0], "%s panels, %s m^2",
             count[TYPE_COUNT], area);
    for (int k = 0; k < TYPE_COUNT; k++)
        snprintf(field[k + 1], sizeof field[k + 1], "%s %s (%s m^2)",
                 panel_type_name((enum panel_type)k), count[k],
                 type_area[k]);
    for (int k = 0; k <= TYPE_COUNT; k++)
        fields[k] = field[k];
    tui_fmt_list(lines[2], 160, width, fields, TYPE_COUNT + 1, ": ", ", ");
    char crowding[32];
    const char *words = tui_crowding_words(o->crowding);
    if (o->rank <= 0)
        snprintf(crowding, sizeof crowding, "not ranked yet");
    else if (words != NULL)
        snprintf(crowding, sizeof crowding, "%s", words);
    else
        snprintf(crowding, sizeof crowding, "%.3g", o->crowding);
    /* P_dist goes where the line is short, never a cut word */
    int n = snprintf(lines[3], 160, "planarity %.4f m, max deviation %.2f "
                     "mm, P_dist %.3g m^4, crowding %s", t->planarity,
                     t->max_deviation * 1000, t->p_dist, crowding);
    if (n >= width)
        snprintf(lines[3], 160, "planarity %.4f m, max deviation %.2f mm, "
                 "crowding %s", t->planarity, t->max_deviation * 1000,
                 crowding);
    return 4;
}

static void draw_detail_side(const struct option_row *o,
                             const struct run_info *run, int y, int x,
                             int height, int width)
{
    tui_put(y, x, width, tui_attr(ROLE_HEADER), " Selected option");
    tui_fill(y, x + 16, width - 16, tui_attr(ROLE_HEADER));
    if (!o->totals.feasible && height > 1) {
        /* the limits it breaks, before its metrics */
        char broken[120];
        tui_fmt_violation(broken, sizeof broken, &o->totals, run);
        tui_putf(y + 1, x, width, A_NORMAL, " infeasible: %s", broken);
        y++;
        height--;
    }
    for (int k = 0; k < tui_metric_column_count && k + 1 < height; k++) {
        const struct quantity *c = tui_shown_column(
            quantity_named(tui_metric_columns[k]), o);
        double number = quantity_value(c, o);
        if (c->writer == WRITTEN_BY_RANKING && o->rank <= 0) {
            /* rank, crowding and knee come when the run ranks it */
            tui_putf(y + 1 + k, x, width, tui_attr(ROLE_DIM),
                     " %-15s %14s", c->label, "not ranked yet");
            continue;
        }
        if (isnan(number)) {
            /* NULL in the store: never a number, and never 0; "none"
             * where the stage ran and found nothing to measure */
            tui_putf(y + 1 + k, x, width, tui_attr(ROLE_DIM),
                     " %-15s %14s", c->label,
                     quantity_none(c, &o->totals) ? "none"
                                                  : "not measured");
            continue;
        }
        char value[64];
        tui_fmt_value(value, sizeof value, c, number);
        tui_putf(y + 1 + k, x, width, A_NORMAL, " %-15s %14s %s", c->label,
                 value, c->unit);
    }
}

/* The column chooser: every column in the table's order, shown or not,
 * over the table. */
static void draw_chooser(struct options_screen *s, struct tui_app *app,
                         int height, int width)
{
    const struct tui_column_set *set = &app->columns;
    int w = width < 52 ? width : 52, x0 = (width - w) / 2, y0 = 1;
    int rows = height - 5;
    if (rows > set->n)
        rows = set->n;
    if (rows < 1)
        rows = 1;
    s->choice_top = (int)table_model_scroll(s->choice_top, s->choice, rows,
                                            set->n);
    int top = s->choice_top;
    for (int y = 0; y < rows + 4; y++)
        tui_fill(y0 + y, x0, w, tui_attr(ROLE_NORMAL));
    tui_fill(y0, x0, w, tui_attr(ROLE_TITLE));
    tui_putf(y0, x0, w, tui_attr(ROLE_TITLE), " Columns: %d of %d shown, "
             "%d characters", s->nvis, set->n, tui_columns_width(set));
    tui_put(y0 + 1, x0, w, tui_attr(ROLE_DIM),
            " Space show/hide  J/K move  r default  Enter close");
    for (int r = 0; r < rows && top + r < set->n; r++) {
        int k = top + r;
        const struct tui_column *c = &tui_option_columns[set->order[k]];
        attr_t attr = k == s->choice ? tui_attr(ROLE_SELECTION) : A_NORMAL;
        if (k == s->choice)
            tui_fill(y0 + 2 + r, x0, w, attr);
        tui_putf(y0 + 2 + r, x0, w, attr, " %s %-10s %-4s %s",
                 set->shown[k] ? "[x]" : "[ ]",
                 c->pareto_mark ? "P (mark)" : tui_column_title(c),
                 tui_column_unit(c), c->column);
    }
    tui_fill(y0 + 2 + rows, x0, w, tui_attr(ROLE_NORMAL));
}

/* The run's title: fields that do not fit go, the least needed first
 * (the name, the method, the Pareto count), rather than a number being
 * cut at the edge ("knee 3" for knee 324). While the run works and the
 * table shows every option, its count is the table's own, so the two
 * agree. */
static void draw_title(struct options_screen *s, int width)
{
    const struct table_model *m = &s->model;
    const char *surface = strrchr(s->model.run.surface_path, '/');
    surface = surface ? surface + 1 : s->model.run.surface_path;
    int64_t options = s->model.run.options;
    if (m->count_exact && m->filter == NULL && !m->browse.pareto_only)
        options = m->count;
    char run[32], count[48], pareto[48], knee[48], number[32];
    snprintf(run, sizeof run, " Run %lld", (long long)s->model.run.id);
    tui_fmt_number(number, sizeof number, (double)options, 0, 1);
    snprintf(count, sizeof count, "%s options", number);
    snprintf(pareto, sizeof pareto, "%lld Pareto",
             (long long)s->model.run.pareto_options);
    if (s->model.run.knee > 0)
        snprintf(knee, sizeof knee, "knee %lld", (long long)s->model.run.knee);
    else
        knee[0] = '\0';
    const struct tui_field fields[] = {
        {"", run, 0},
        {" ", s->model.run.name, 4},
        {" ", surface, 3},
        {" | ", store_run_setting_text(&s->model.run, RUN_SETTING_METHOD), 2},
        {" | ", run_status_name(s->model.run.status), 0},
        {" | ", count, 0},
        {", ", pareto, 1},
        {", ", knee, 0},
    };
    char title[512];
    tui_fit_fields(title, sizeof title, width, fields,
                   (int)(sizeof fields / sizeof fields[0]));
    tui_fill(0, 0, width, tui_attr(ROLE_TITLE));
    tui_put(0, 0, width, tui_attr(ROLE_TITLE), title);
}

static void options_draw(struct tui_screen *base, struct tui_app *app,
                         int height, int width)
{
    struct options_screen *s = (struct options_screen *)base;
    struct table_model *m = &s->model;
    columns_update(s, app);
    draw_title(s, width);
    char sort[160];
    sort_text(s, s->model.browse.feasible_first, sort, sizeof sort);
    char shown[32];
    table_model_count_text(m, shown, sizeof shown);
    /* the scroll position first: "row 12 of 336" (the count, "2,000+"
     * while it is a lower bound) */
    char position[64];
    if (m->count > 0)
        table_model_position_text(m, position, sizeof position);
    else
        snprintf(position, sizeof position, "%s shown", shown);
    int room = width;
    const char *where = m->filter ? filter_text(m->filter) : "";
    /* "feasible first" goes where it would push the filter off the line
     * (the ok column's header still shows it as the leading key) */
    if ((int)(strlen(position) + strlen(sort) + strlen(where) + 24 +
              (m->browse.pareto_only ? 13 : 0)) > width)
        sort_text(s, 0, sort, sizeof sort);
    int x = tui_putf(1, 0, room, A_NORMAL, " %s  sort %s", position, sort);
    x += tui_putf(1, x, room - x, where[0] ? tui_attr(ROLE_PARETO)
                                           : A_NORMAL,
                  "  filter %s", where[0] ? where : "none");
    if (m->browse.pareto_only)
        x += tui_put(1, x, room - x, tui_attr(ROLE_PARETO),
                     "  Pareto only");
    if (m->nmarks)
        tui_putf(1, x, room - x, tui_attr(ROLE_MARKED), "  %d marked",
                 m->nmarks);

    int columns = tui_columns_width(&app->columns);
    if (columns < 80)
        columns = 80;
    int side = s->detail && width >= columns + 40;
    int table_width = side ? columns : width;
    int pane = s->detail && !side && height >= 14 ? 5 : 0;
    draw_header(s, app, 2, table_width);
    s->rows = height - 4 - pane;
    if (s->rows < 1)
        s->rows = 1;
    s->top = table_model_scroll(s->top, m->selected, s->rows, m->count);
    struct facet_error err;
    if (table_model_fetch(m, s->top, s->rows, &err) != FACET_OK)
        tui_error(app, "%s", err.message);
    for (int r = 0; r < s->rows; r++) {
        const struct option_row *o = table_model_row(m, s->top + r);
        if (o == NULL)
            break;
        draw_row(s, app, 4 + r, table_width, o, s->top + r == m->selected);
    }
    if (m->count == 0)
        tui_put(5, 2, table_width - 2, tui_attr(ROLE_DIM),
                m->filter || m->browse.pareto_only
                    ? "No option passes the filter (/ edits it, p toggles "
                      "Pareto only)."
                    : "No options yet.");
    const struct option_row *o = table_model_selection(m);
    if (o == NULL)
        return;
    if (side) {
        draw_detail_side(o, &s->model.run, 2, table_width + 1, height - 2,
                         width - table_width - 1);
    } else if (pane) {
        char lines[4][160];
        int n = detail_lines(o, &s->model.run, width - 1, lines);
        int y = height - pane;
        tui_fill(y, 0, width, tui_attr(ROLE_DIM));
        tui_put(y, 0, width, tui_attr(ROLE_HEADER), " Selected option ");
        for (int k = 0; k < n; k++)
            tui_putf(y + 1 + k, 0, width, A_NORMAL, " %s", lines[k]);
    }
    if (s->choosing)
        draw_chooser(s, app, height, width);
}

/* --- keys --- */

static void report(struct tui_app *app, int rc, const struct facet_error *e)
{
    if (rc == FACET_OK)
        return;
    /* an error of the filter line or the sort says which it is */
    if (e->setting == FACET_SETTING_FILTER)
        tui_error(app, "filter: %s", e->message);
    else if (e->setting == FACET_SETTING_SORT)
        tui_error(app, "sort: %s", e->message);
    else
        tui_error(app, "%s", e->message);
}

static void apply_sort(struct options_screen *s, struct tui_app *app)
{
    struct facet_error err;
    int rc = table_model_set_sort(&s->model, s->keys, s->nkeys, &err);
    report(app, rc, &err);
    if (rc != FACET_OK)
        return;
    /* A new order starts at its top: the selected option stays selected
     * only when it is among the rows the top page shows (keeping its
     * screen row hid the new first rows). */
    s->top = 0;
    if (s->model.selected >= s->rows || s->model.estimated)
        report(app, table_model_select_first(&s->model, &err), &err);
}

/* s: the cursor's column becomes the primary key, or is reversed. */
static void sort_primary(struct options_screen *s, struct tui_app *app)
{
    const char *column = tui_option_columns[s->column].column;
    if (s->nkeys > 0 && strcmp(s->keys[0].column, column) == 0) {
        s->keys[0].descending = !s->keys[0].descending;
    } else {
        if (s->nkeys == 2 && strcmp(s->keys[1].column, column) == 0)
            s->nkeys = 1;
        else if (s->nkeys > 0) {
            s->keys[1] = s->keys[0];   /* the old primary becomes second */
            s->nkeys = 2;
        } else {
            s->nkeys = 1;
        }
        s->keys[0].column = column;
        s->keys[0].descending = 0;
    }
    apply_sort(s, app);
}

/* S: the cursor's column as the secondary key: asc, desc, off. */
static void sort_secondary(struct options_screen *s, struct tui_app *app)
{
    const char *column = tui_option_columns[s->column].column;
    if (s->nkeys == 0 || strcmp(s->keys[0].column, column) == 0) {
        tui_error(app, "that is the primary key; move the cursor (h/l) "
                  "to another column");
        return;
    }
    if (s->nkeys == 2 && strcmp(s->keys[1].column, column) == 0) {
        if (s->keys[1].descending)
            s->nkeys = 1;
        else
            s->keys[1].descending = 1;
    } else {
        s->keys[1].column = column;
        s->keys[1].descending = 0;
        s->nkeys = 2;
    }
    apply_sort(s, app);
}

static void jump_knee(struct options_screen *s, struct tui_app *app)
{
    struct facet_error err;
    if (table_model_read_run(&s->model, &err) != FACET_OK) {
        tui_error(app, "%s", err.message);
        return;
    }
    if (s->model.run.knee <= 0) {
        tui_error(app, "run %lld has no knee option (not ranked yet)",
                  (long long)s->model.run.id);
        return;
    }
    int found;
    int rc = table_model_select_number(&s->model, s->model.run.knee, &found, &err);
    if (rc != FACET_OK)
        report(app, rc, &err);
    else if (!found)
        tui_error(app, "the knee option %lld is hidden by the filter",
                  (long long)s->model.run.knee);
    else
        tui_status(app, "knee option %lld", (long long)s->model.run.knee);
}

/* n / N: the next Pareto-optimal row in the table's order. */
static void next_pareto(struct options_screen *s, struct tui_app *app,
                        int dir)
{
    struct table_model *m = &s->model;
    struct facet_error err;
    for (int64_t p = m->selected + dir, steps = 0;
         p >= 0 && p < m->count && steps < 20000; p += dir, steps++) {
        const struct option_row *o = table_model_row(m, p);
        if (o == NULL) {
            int rc = table_model_fetch(m, dir > 0 ? p : p - TABLE_PAGE + 1,
                                       TABLE_PAGE, &err);
            if (rc != FACET_OK || (o = table_model_row(m, p)) == NULL) {
                report(app, rc, &err);
                return;
            }
        }
        if (o->rank == 1) {
            report(app, table_model_select(m, p, &err), &err);
            return;
        }
    }
    tui_error(app, "no Pareto-optimal option %s", dir > 0 ? "below"
                                                          : "above");
}

static void toggle_mark(struct options_screen *s, struct tui_app *app)
{
    const struct option_row *o = table_model_selection(&s->model);
    if (o == NULL)
        return;
    int64_t number = o->number;
    if (table_model_marked(&s->model, number)) {
        table_model_set_mark(&s->model, number, 0, NULL);
        /* said, so that Space on an option marked before (the knee
         * after K) is not a silent unmark */
        tui_status(app, "unmarked No. %lld (%d marked; Space marks it "
                   "again)", (long long)number, s->model.nmarks);
        return;
    }
    struct facet_error err;
    if (table_model_set_mark(&s->model, number, 1, &err) != FACET_OK) {
        tui_error(app, "%s", err.message);
        return;
    }
    tui_status(app, "marked No. %lld (%d marked%s)", (long long)number,
               s->model.nmarks, s->model.nmarks >= 2 ? "; c compares" : "");
    table_model_select(&s->model, s->model.selected + 1, &err);
}

/* E: the marked options (or the selected one) to a CSV file. */
static void export_marks_open(struct options_screen *s, struct tui_app *app)
{
    if (s->model.nmarks == 0) {
        tui_error(app, "export: mark options with Space first");
        return;
    }
    char name[128];
    snprintf(name, sizeof name, "facet-run%lld-marked.csv",
             (long long)s->model.run.id);
    tui_input_set(&s->export_to, name);
    s->exporting = 1;
    tui_prompt(app, "Export marked to (CSV):", &s->export_to);
}

static enum tui_result export_marks_key(struct options_screen *s,
                                        struct tui_app *app, int key)
{
    if (tui_prompt_key(app, &s->export_to, &s->exporting, key) !=
        INPUT_DONE)
        return RESULT_HANDLED;
    char path[TUI_INPUT_MAX];
    snprintf(path, sizeof path, "%s", s->export_to.text);
    size_t n = strlen(path);
    int force = n > 0 && path[n - 1] == '!';
    if (force)
        path[--n] = '\0';
    struct facet_error err;
    if (n == 0)
        tui_error(app, "export: give a file name");
    else if (study_export_options_csv(app->store, s->model.run.id, s->model.marks,
                                      (size_t)s->model.nmarks, path, force,
                                      &err) != FACET_OK)
        tui_error(app, "export: %s", err.message);
    else
        tui_status(app, "wrote %d marked options to %s", s->model.nmarks,
                   path);
    return RESULT_HANDLED;
}

static enum tui_result filter_key(struct options_screen *s,
                                  struct tui_app *app, int key)
{
    if (tui_filter_history_key(app, &s->filter, key))
        return RESULT_HANDLED;
    if (tui_prompt_key(app, &s->filter, &s->editing, key) != INPUT_DONE)
        return RESULT_HANDLED;
    struct facet_error err;
    int rc = table_model_set_filter(&s->model, s->filter.text, &err);
    tui_history_add(&app->filters, s->filter.text, rc != FACET_OK);
    report(app, rc, &err);
    if (rc == FACET_OK) {
        char shown[32];
        table_model_count_text(&s->model, shown, sizeof shown);
        tui_status(app, "%s options pass the filter", shown);
    }
    return RESULT_HANDLED;
}

/* The column chooser's keys; the set is the session's (app->columns). */
static enum tui_result chooser_key(struct options_screen *s,
                                   struct tui_app *app, int key)
{
    struct tui_column_set *set = &app->columns;
    switch (key) {
    case ' ': case 'x':
        if (tui_columns_toggle(set, s->choice) != 0)
            tui_error(app, "the table keeps at least one column");
        break;
    case 'J': case '+': case KEY_SF:
        s->choice = tui_columns_move(set, s->choice, 1);
        break;
    case 'K': case '-': case KEY_SR:
        s->choice = tui_columns_move(set, s->choice, -1);
        break;
    case 'r':
        tui_columns_default(set);
        break;
    case 'C': case KEY_F(2): case 'q': case 27: case '\r': case '\n':
    case KEY_ENTER:
        s->choosing = 0;
        break;
    default:
        switch (tui_key_action(key)) {
        case ACTION_UP: if (s->choice > 0) s->choice--; break;
        case ACTION_DOWN: if (s->choice + 1 < set->n) s->choice++; break;
        case ACTION_TOP: s->choice = 0; break;
        case ACTION_BOTTOM: s->choice = set->n - 1; break;
        case ACTION_HELP: case ACTION_QUIT: return RESULT_UNHANDLED;
        default: break;
        }
    }
    columns_update(s, app);
    return RESULT_HANDLED;
}

/* A click on a header sorts by its column (again: the other way); on a
 * row selects it, twice opens its panel map. The wheel is the frame's
 * (three rows, as the arrows). */
static enum tui_result options_mouse(struct options_screen *s,
                                     struct tui_app *app)
{
    const struct tui_mouse *ev = &app->mouse;
    struct facet_error err;
    if (ev->kind != MOUSE_CLICK)
        return RESULT_UNHANDLED;
    int widths[TUI_COLUMNS_MAX];
    for (int v = 0; v < s->nvis; v++)
        widths[v] = tui_option_columns[s->vis[v]].width;
    if (ev->y == 2 || ev->y == 3) {
        int v = tui_column_at(widths, s->nvis, ev->x);
        if (v < 0)
            return RESULT_HANDLED;
        s->column = s->vis[v];
        sort_primary(s, app);
        return RESULT_HANDLED;
    }
    int64_t position = s->top + (ev->y - 4);
    if (ev->y < 4 || ev->y >= 4 + s->rows || position >= s->model.count)
        return RESULT_HANDLED;
    report(app, table_model_select(&s->model, position, &err), &err);
    const struct option_row *o = table_model_selection(&s->model);
    if (ev->clicks == 2 && o != NULL)
        tui_push(app, screen_map_new(app, s->model.run.id, o->number));
    return RESULT_HANDLED;
}

static enum tui_result options_key(struct tui_screen *base,
                                   struct tui_app *app, int key)
{
    struct options_screen *s = (struct options_screen *)base;
    struct table_model *m = &s->model;
    struct facet_error err;
    const struct option_row *o = table_model_selection(m);
    columns_update(s, app);
    if (s->editing)
        return filter_key(s, app, key);
    if (s->exporting)
        return export_marks_key(s, app, key);
    if (s->choosing)
        return chooser_key(s, app, key);
    switch (key) {
    case KEY_MOUSE:
        return options_mouse(s, app);
    case 's': case KEY_F(6):
        sort_primary(s, app);
        return RESULT_HANDLED;
    case 'S':
        sort_secondary(s, app);
        return RESULT_HANDLED;
    case '<': case '>':
        s->column = s->vis[(cursor_place(s) + (key == '>' ? 1 : -1) +
                            s->nvis) % s->nvis];
        if (s->nkeys > 0 &&
            strcmp(s->keys[0].column, tui_option_columns[s->column].column)
                == 0)
            return RESULT_HANDLED;
        sort_primary(s, app);
        return RESULT_HANDLED;
    case 'I':
        if (s->nkeys == 0) {
            s->keys[0].column = "number";
            s->nkeys = 1;
        }
        s->keys[0].descending = !s->keys[0].descending;
        apply_sort(s, app);
        return RESULT_HANDLED;
    case 'p': case KEY_F(4):
        report(app, table_model_set_pareto(m, !m->browse.pareto_only, &err),
               &err);
        return RESULT_HANDLED;
    case 'F': {
        int on = !m->browse.feasible_first;
        int rc = table_model_set_feasible_first(m, on, &err);
        report(app, rc, &err);
        if (rc == FACET_OK)
            tui_status(app, on ? "sorted, the feasible options come first"
                               : "sorted by the keys alone, the infeasible "
                                 "options mixed in (F: feasible first)");
        return RESULT_HANDLED;
    }
    case 'K':
        jump_knee(s, app);
        return RESULT_HANDLED;
    case '|': case 'a':
        tui_push(app, screen_parallel_new(app, m));
        return RESULT_HANDLED;
    case 'C': case KEY_F(2):
        s->choosing = 1;
        s->choice = 0;
        return RESULT_HANDLED;
    case ' ':
        toggle_mark(s, app);
        return RESULT_HANDLED;
    case 'u':
        tui_status(app, "%d mark%s cleared", m->nmarks,
                   m->nmarks == 1 ? "" : "s");
        m->nmarks = 0;
        return RESULT_HANDLED;
    case 'c': case KEY_F(7):
        if (m->nmarks < 2) {
            tui_error(app, "mark 2 to 4 options with Space first");
            return RESULT_HANDLED;
        }
        tui_push(app, screen_compare_new(app, s->model.run.id, m->marks,
                                         m->nmarks > 4 ? 4 : m->nmarks));
        return RESULT_HANDLED;
    case 'm': case KEY_F(8): case '\r': case '\n': case KEY_ENTER:
        if (o != NULL)
            tui_push(app, screen_map_new(app, s->model.run.id, o->number));
        return RESULT_HANDLED;
    case 'x': case KEY_F(5):
        tui_push(app, screen_scatter_new(app, m));
        return RESULT_HANDLED;
    case 't': case 'T':
        tui_push(app, screen_stats_new(app, m, key == 'T' ? 5 : 0));
        return RESULT_HANDLED;
    case 'o':
        if (o != NULL && store_run_is_project(&s->model.run))
            tui_push(app, screen_surfaces_new(app, s->model.run.id, o->number));
        else if (o != NULL)
            tui_status(app, "o: run %lld is of a single surface: its "
                       "options have no surfaces to list (Enter: the map)",
                       (long long)s->model.run.id);
        return RESULT_HANDLED;
    case 'L':
        if (o != NULL)
            tui_push(app, screen_newrun_like(app, &s->model.run, o));
        return RESULT_HANDLED;
    case 'E':
        export_marks_open(s, app);
        return RESULT_HANDLED;
    case 'd':
        s->detail = !s->detail;
        return RESULT_HANDLED;
    case 'r':
        table_model_read_run(&s->model, &err);
        report(app, table_model_refresh(m, &err), &err);
        return RESULT_HANDLED;
    case KEY_F(3):
        key = '/';
        break;
    default:
        break;
    }
    int64_t page = s->rows > 1 ? s->rows - 1 : 1;
    int rc = FACET_OK;
    switch (tui_key_action(key)) {
    case ACTION_UP: rc = table_model_select(m, m->selected - 1, &err); break;
    case ACTION_DOWN: rc = table_model_select(m, m->selected + 1, &err);
        break;
    case ACTION_PAGE_UP:
        s->top -= page;
        rc = table_model_select(m, m->selected - page, &err);
        break;
    case ACTION_PAGE_DOWN:
        s->top += page;
        rc = table_model_select(m, m->selected + page, &err);
        break;
    case ACTION_TOP: rc = table_model_select(m, 0, &err); break;
    case ACTION_BOTTOM:
        rc = table_model_select_last(m, &err);
        break;
    case ACTION_LEFT:
        if (cursor_place(s) > 0)
            s->column = s->vis[cursor_place(s) - 1];
        break;
    case ACTION_RIGHT:
        if (cursor_place(s) + 1 < s->nvis)
            s->column = s->vis[cursor_place(s) + 1];
        break;
    case ACTION_SEARCH:
        s->editing = 1;
        tui_filter_open(app, &s->filter, m);
        break;
    case ACTION_NEXT: next_pareto(s, app, 1); break;
    case ACTION_PREVIOUS: next_pareto(s, app, -1); break;
    default:
        return RESULT_UNHANDLED;
    }
    report(app, rc, &err);
    return RESULT_HANDLED;
}

/* A running run: the run and the table are read again every second, so
 * the table fills in as options are committed; when the run ends (seen
 * here, or a run of this workbench finishing) once more, so that the
 * header, the count and the ranks are the finished run's. Between, a
 * count that is a lower bound goes on counting, and stops once exact. */
static int options_tick(struct tui_screen *base, struct tui_app *app)
{
    struct options_screen *s = (struct options_screen *)base;
    struct facet_error err;
    int live = s->model.run.status == RUN_RUNNING;
    int finished = s->runs_finished != app->runs_finished;
    /* this workbench's own run: at the gauge's sample; another
     * process's: every second */
    int own = app->job != NULL && app->job_run == s->model.run.id;
    /* A refresh that reads much (a run of many options stores them
     * without the indexes by metric: a sorted page reads the whole run,
     * 0.4 s a refresh at a million) comes no oftener than four times its
     * own time, so that keys keep most of the time. */
    double since = tui_seconds_since(&s->last_refresh);
    int due = own ? app->job_sampling && app->job_samples != s->job_samples
                  : since >= 1.0;
    due = due && since >= 4 * s->refresh_seconds;
    if (finished || (live && due)) {
        s->runs_finished = app->runs_finished;
        s->job_samples = app->job_samples;
        clock_gettime(CLOCK_MONOTONIC, &s->last_refresh);
        struct table_model *m = &s->model;
        if (table_model_read_run(&s->model, &err) != FACET_OK ||
            table_model_refresh(m, &err) != FACET_OK) {
            tui_error(app, "%s", err.message);
            return 1;
        }
        s->refresh_seconds = tui_seconds_since(&s->last_refresh);
        /* without a filter the count is the run's index, cheap even for a
         * million options: counted whole now, so that the title, the
         * count and the gauge are one moment's (a step between samples
         * ran ahead of the gauge) */
        int exact;
        if (m->filter == NULL && !m->browse.pareto_only &&
            table_model_count_step(m, 0, &exact, &err) != FACET_OK)
            tui_error(app, "%s", err.message);
        return 1;
    }
    if (!s->model.count_exact) {
        int exact;
        if (table_model_count_step(&s->model, TABLE_COUNT_STEP, &exact,
                                   &err) != FACET_OK)
            tui_error(app, "%s", err.message);
        return 1;
    }
    return 0;
}

static void options_destroy(struct tui_screen *base)
{
    struct options_screen *s = (struct options_screen *)base;
    table_model_close(&s->model);
    free(s);
}

static const struct tui_screen_class options_class = {
    "Options", options_help,
    {"Help", "Cols", "Filter", "Pareto", "Plot", "Sort", "Compare", "Map",
     NULL, "Quit"},
    options_draw, options_key, options_tick, options_destroy,
};

/* What a designer must see on opening a run: its first warning (a mesh
 * coarser than its panels, ...), else a front on a bound of its space. */
static void say_run_notes(struct tui_app *app, const struct run_info *run)
{
    if (run->warnings[0] != '\0') {
        const char *end = strchr(run->warnings, '\n');
        int n = end ? (int)(end - run->warnings) : (int)strlen(run->warnings);
        tui_error(app, "warning: %.*s", n, run->warnings);
        return;
    }
    struct front_bounds bounds;
    struct facet_error err;
    char note[1024];
    if (store_front_bounds(app->store, run->id, &bounds, &err) == FACET_OK &&
        study_front_edge_note(run, &bounds, note, sizeof note))
        tui_status(app, "note: %s", note);
}

struct tui_screen *screen_options_new(struct tui_app *app, int64_t run)
{
    struct options_screen *s = calloc(1, sizeof *s);
    struct facet_error err;
    if (s == NULL) {
        tui_error(app, "out of memory");
        return NULL;
    }
    s->base.cls = &options_class;
    s->runs_finished = app->runs_finished;
    s->detail = 1;
    s->column = 4;  /* cost */
    s->keys[0].column = "cost";  /* the paper's Table 2: cheapest first */
    s->nkeys = 1;
    clock_gettime(CLOCK_MONOTONIC, &s->last_refresh);
    if (table_model_open_sorted(&s->model, app->store, run, s->keys,
                                s->nkeys, &err) != FACET_OK) {
        tui_error(app, "%s", err.message);
        table_model_close(&s->model);
        free(s);
        return NULL;
    }
    say_run_notes(app, &s->model.run);
    return &s->base;
}
