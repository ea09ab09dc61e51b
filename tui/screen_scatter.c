/*
 * screen_scatter.c: the Scatter plot: two metrics of the options against
 * each other (default total planarity vs cost, the paper's Figure 13), a
 * third as glyph size (default DP area), the two-metric Pareto front
 * drawn as a line and the run's Pareto options highlighted, and a cursor
 * moving from point to point. It shows the options table's filter and
 * Pareto-only setting (and changes them: they are the same model), and
 * moving the cursor moves the table's selection. Pareto options are drawn
 * with the Pareto glyph and the knee with its own, so they read without
 * colour; a fourth metric can colour the points (four levels), the axes
 * have round ticks, M picks any metric for any role, Space marks options
 * as the table does (one set of marks), and e writes what the screen
 * shows (the filter and Pareto-only apply) as SVG.
 *
 * A run of many options is sampled (every option of rank 1, and evenly
 * by number for the rest) to at most SCATTER_POINTS points.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "app.h"
#include "format.h"
#include "input.h"
#include "keys.h"
#include "scatter_model.h"
#include "study/study_export.h"

#define SCATTER_POINTS 8000

static const char *const axis_columns[] = {
    "planarity", "cost", "dp_area", "fp_area", "sp_area", "max_deviation",
    "max_panel_area", "p_dist", "nu", "nv", "threshold_mm", "panels",
    "dp_count", "rank", "crowding", "moulds", "sp_moulds", "dp_moulds",
    "joint_length", "max_gap", "max_kink", "sp_misfits", "sp_min_radius",
};
#define AXES ((int)(sizeof axis_columns / sizeof axis_columns[0]))

struct scatter_screen {
    struct tui_screen base;
    struct table_model *model;   /* the options table's, borrowed */
    struct option_row *rows;
    struct scatter_point *points;
    size_t *front;
    size_t n, nfront, capacity;
    int axis[4];                 /* x, y, size, colour: indexes of
                                    axis_columns; colour -1 for none */
    size_t cursor;
    int show_front;
    int sampled;                 /* the points are a sample */
    int editing;
    struct tui_input filter;
    int exporting;               /* the plot's file line is open */
    struct tui_input plot_to;
    int picking;                 /* the metric picker is open */
    int pick;                    /* its cursor: an axis_columns index */
    int project;                 /* a project run's: its module (m) where
                                    U and V stand */
};

/* The column of axis_columns[k] as this run's options show it: a
 * project's module for nu and nv, which only index its module range. */
static const char *axis_column(const struct scatter_screen *s, int k)
{
    return s->project ? quantity_of_project(axis_columns[k])->name
                      : axis_columns[k];
}

static const struct tui_key_help scatter_help[] = {
    {"h/j/k/l, arrows", "move the cursor to the nearest point that way"},
    {"Enter, m", "panel map of the point's option"},
    {"x / X", "next / previous metric on the x axis"},
    {"y / Y", "next / previous metric on the y axis"},
    {"z / Z", "next / previous metric for the glyph size"},
    {"c / C", "next / previous metric for the colour (or none)"},
    {"M", "metric picker: j/k choose, x y z c give it that role"},
    {"Space", "mark / unmark the option (the table's marks, for Compare)"},
    {"f", "show / hide the two-metric Pareto front line"},
    {"p, F4", "Pareto-optimal options only (shared with the table)"},
    {"/, F3", "filter (shared with the table; Up/Down: the filters "
              "entered before)"},
    {"K", "the knee option"},
    {"e, F9", "write the scatter as SVG: these axes, the options shown "
              "(filter, Pareto only); end the name with ! to overwrite"},
    {NULL, NULL},
};

static const char *axis_name(const struct scatter_screen *s, int a)
{
    return s->axis[a] < 0 ? "none" : axis_column(s, s->axis[a]);
}

/* The colour metric's value of point k (NaN without one). */
static double colour_value(const struct scatter_screen *s, size_t k)
{
    return s->axis[3] < 0 ? NAN
                          : option_quantity_value(&s->rows[k], axis_name(s, 3));
}

/* Fills the points' x, y, z from the rows, and the front. */
static void compute(struct scatter_screen *s)
{
    for (size_t k = 0; k < s->n; k++) {
        s->points[k].number = s->rows[k].number;
        s->points[k].rank = s->rows[k].rank;
        s->points[k].x = option_quantity_value(&s->rows[k], axis_name(s, 0));
        s->points[k].y = option_quantity_value(&s->rows[k], axis_name(s, 1));
        s->points[k].z = option_quantity_value(&s->rows[k], axis_name(s, 2));
    }
    s->nfront = scatter_front(s->points, s->n, s->front);
}

static int add_row(void *context, const struct option_row *option)
{
    struct scatter_screen *s = context;
    if (s->n == s->capacity) {
        size_t capacity = s->capacity ? 2 * s->capacity : 1024;
        struct option_row *rows = realloc(s->rows, capacity * sizeof *rows);
        if (rows == NULL)
            return 1;
        s->rows = rows;
        struct scatter_point *points = realloc(s->points,
                                               capacity * sizeof *points);
        if (points == NULL)
            return 1;
        s->points = points;
        size_t *front = realloc(s->front, capacity * sizeof *front);
        if (front == NULL)
            return 1;
        s->front = front;
        s->capacity = capacity;
    }
    s->rows[s->n++] = *option;
    return 0;
}

/* Moves the cursor to option number when it is a point. */
static int cursor_to(struct scatter_screen *s, int64_t number)
{
    for (size_t k = 0; k < s->n; k++)
        if (s->points[k].number == number) {
            s->cursor = k;
            return 1;
        }
    return 0;
}

/* Reads the points the model shows, keeping the cursor on the table's
 * selection. */
static int load(struct scatter_screen *s, struct tui_app *app)
{
    struct table_model *m = s->model;
    s->n = 0;
    int64_t stride = m->count > SCATTER_POINTS / 2
                         ? m->count / (SCATTER_POINTS / 2) : 1;
    s->sampled = stride > 1;
    struct facet_error err;
    int rc = store_browse_sample(m->store, &m->browse, stride,
                                 SCATTER_POINTS, add_row, s, &err);
    if (rc != FACET_OK) {
        tui_error(app, "%s", err.message);
        return rc;
    }
    compute(s);
    s->cursor = 0;
    const struct option_row *o = table_model_selection(m);
    if (o != NULL)
        cursor_to(s, o->number);
    return FACET_OK;
}

/* The table follows the cursor. */
static void follow(struct scatter_screen *s, struct tui_app *app)
{
    if (s->cursor >= s->n)
        return;
    int found;
    struct facet_error err;
    if (table_model_select_number(s->model, s->points[s->cursor].number,
                                  &found, &err) != FACET_OK)
        tui_error(app, "%s", err.message);
}

static void label(char *out, size_t size, const char *column, double value)
{
    const struct quantity *c = quantity_named(column);
    if (c)
        tui_fmt_value(out, size, c, value);
    else
        snprintf(out, size, "%.4g", value);
}

/* A tick's label: as many decimals as the step needs, in the column's
 * unit. */
static void tick_label(char *out, size_t size, const char *column,
                       double value, double step)
{
    const struct quantity *c = quantity_named(column);
    double scale = c ? c->scale : 1;
    int decimals = step * scale > 0 ? (int)ceil(-log10(step * scale) - 1e-9)
                                    : 0;
    if (decimals < 0)
        decimals = 0;
    tui_fmt_number(out, size, value * scale, decimals, c ? c->thousands : 0);
}

/* value in three digits with k or M, in the column's unit, for the
 * colour scale's ends. */
static void compact(char *out, size_t size, const char *column,
                    double value)
{
    const struct quantity *c = quantity_named(column);
    double v = value * (c ? c->scale : 1);
    if (fabs(v) >= 1e6)
        snprintf(out, size, "%.3gM", v / 1e6);
    else if (fabs(v) >= 1e4)
        snprintf(out, size, "%.3gk", v / 1e3);
    else
        snprintf(out, size, "%.3g", v);
}

static const char *unit_of(const char *column)
{
    const struct quantity *c = quantity_named(column);
    return c && c->unit[0] ? c->unit : "";
}

/* The metric picker over the plot: every metric with the roles it has. */
static void draw_picker(struct scatter_screen *s, int height, int width)
{
    int w = width < 46 ? width : 46, x0 = (width - w) / 2, y0 = 2;
    int rows = AXES < height - 5 ? AXES : height - 5;
    if (rows < 1)
        return;
    int top = s->pick >= rows ? s->pick - rows + 1 : 0;
    for (int y = 0; y < rows + 2; y++)
        tui_fill(y0 + y, x0, w, tui_attr(ROLE_NORMAL));
    tui_fill(y0, x0, w, tui_attr(ROLE_TITLE));
    tui_put(y0, x0, w, tui_attr(ROLE_TITLE),
            " Metrics: j/k choose, x y z c assign, q close");
    static const char role_letter[4] = {'x', 'y', 'z', 'c'};
    for (int r = 0; r < rows; r++) {
        int k = top + r;
        char roles[8] = "    ";
        for (int a = 0; a < 4; a++)
            if (s->axis[a] == k)
                roles[a] = role_letter[a];
        attr_t attr = k == s->pick ? tui_attr(ROLE_SELECTION) : A_NORMAL;
        tui_fill(y0 + 1 + r, x0, w, attr);
        tui_putf(y0 + 1 + r, x0, w, attr, " %s  %-16s %s", roles,
                 axis_column(s, k), unit_of(axis_column(s, k)));
    }
}

static void scatter_draw(struct tui_screen *base, struct tui_app *app,
                         int height, int width)
{
    struct scatter_screen *s = (struct scatter_screen *)base;
    const struct tui_glyphs *g = app->glyphs;
    const struct table_model *m = s->model;
    const char *where = m->filter ? filter_text(m->filter) : "";
    tui_fill(0, 0, width, tui_attr(ROLE_TITLE));
    char marked[32] = "";
    if (m->nmarks)
        snprintf(marked, sizeof marked, " | %d marked", m->nmarks);
    tui_putf(0, 0, width, tui_attr(ROLE_TITLE),
             " Scatter: %s vs %s, size %s | %zu points%s%s%s%s%s",
             axis_name(s, 1), axis_name(s, 0), axis_name(s, 2), s->n,
             s->sampled ? " (sampled)" : "",
             m->browse.pareto_only ? " | Pareto only" : "", marked,
             where[0] ? " | filter " : "", where);
    /* the legend: the glyphs as drawn */
    int x = tui_put(1, 0, width, A_NORMAL, " ");
    x += tui_put(1, x, 1, tui_attr(ROLE_PARETO), g->pareto);
    x += tui_put(1, x, width - x, A_NORMAL, " Pareto ");
    x += tui_put(1, x, 1, tui_attr(ROLE_KNEE), g->knee);
    x += tui_put(1, x, width - x, A_NORMAL, " knee ");
    x += tui_put(1, x, 1, tui_attr(ROLE_MARKED), g->mark);
    x += tui_put(1, x, width - x, A_NORMAL, " marked ");
    if (s->show_front) {
        x += tui_put(1, x, 1, tui_attr(ROLE_PARETO), g->front);
        x += tui_put(1, x, width - x, A_NORMAL, " front ");
    }
    x += tui_putf(1, x, width - x, A_NORMAL, "%s%s%s %s", g->point[0],
                  g->point[1], g->point[2], axis_name(s, 2));
    double cmin = NAN, cmax = NAN;
    if (s->axis[3] >= 0) {
        for (size_t k = 0; k < s->n; k++) {
            double v = colour_value(s, k);
            if (isfinite(v) && (isnan(cmin) || v < cmin))
                cmin = v;
            if (isfinite(v) && (isnan(cmax) || v > cmax))
                cmax = v;
        }
        x += tui_putf(1, x, width - x, A_NORMAL, " colour %s",
                      axis_name(s, 3));
        if (!app->colour)
            x += tui_put(1, x, width - x, tui_attr(ROLE_DIM),
                         " (no colours here)");
        else {
            char lo[32], hi[32];
            compact(lo, sizeof lo, axis_name(s, 3), cmin);
            compact(hi, sizeof hi, axis_name(s, 3), cmax);
            x += tui_putf(1, x, width - x, A_NORMAL, " %s ", lo);
            for (int l = 0; l < 4; l++)
                x += tui_put(1, x, 1, tui_attr(ROLE_SCALE0 + l) | A_REVERSE,
                             " ");
            x += tui_putf(1, x, width - x, A_NORMAL, " %s", hi);
        }
    }

    int lw = 11, ph = height - 5, pw = width - lw - 2;
    if (ph < 3 || pw < 10)
        return;
    double xmin, xmax, ymin, ymax, zmin, zmax;
    scatter_range(s->points, s->n, 0, &xmin, &xmax);
    scatter_range(s->points, s->n, 1, &ymin, &ymax);
    scatter_range(s->points, s->n, 2, &zmin, &zmax);
    /* axes with round ticks */
    attr_t dim = tui_attr(ROLE_DIM);
    for (int r = 0; r < ph; r++)
        tui_put(2 + r, lw, 1, dim, g->vline);
    tui_put(2 + ph, lw, 1, dim, g->corner);
    for (int c = 0; c < pw; c++)
        tui_put(2 + ph, lw + 1 + c, 1, dim, g->hline);
    double ticks[16], step;
    char text[64];
    int nt = scatter_ticks(ymin, ymax, ph / 3 + 1 < 16 ? ph / 3 + 1 : 16,
                           ticks, &step);
    int tick_row[16], ntick_rows = nt;
    for (int t = 0; t < nt; t++) {
        int r = scatter_cell(ticks[t], ymin, ymax, ph);
        tick_label(text, sizeof text, axis_name(s, 1), ticks[t], step);
        tick_row[t] = 2 + ph - 1 - r;
        tui_putf(tick_row[t], 0, lw, A_NORMAL, "%*s", lw - 1, text);
        tui_put(tick_row[t], lw, 1, dim, "+");
    }
    tick_label(text, sizeof text, axis_name(s, 0), xmax, 0);
    int max_x = pw / ((int)strlen(text) + 4);
    nt = scatter_ticks(xmin, xmax, max_x < 16 ? (max_x > 1 ? max_x : 1) : 16,
                       ticks, &step);
    for (int t = 0; t < nt; t++) {
        int c = scatter_cell(ticks[t], xmin, xmax, pw);
        tick_label(text, sizeof text, axis_name(s, 0), ticks[t], step);
        int at = lw + 1 + c - (int)strlen(text) / 2;
        if (at + (int)strlen(text) > width)
            at = width - (int)strlen(text);
        tui_put(2 + ph, lw + 1 + c, 1, dim, "+");
        tui_put(3 + ph, at < lw ? lw : at, pw, A_NORMAL, text);
    }
    tui_putf(3 + ph, 0, lw, A_NORMAL, "%s", unit_of(axis_name(s, 0)));
    /* The y unit at the middle row that holds no tick's label: written
     * over one it hid a number ("USD" over 1,200,000). */
    int unit_row = 2 + ph / 2;
    for (int d = 0; d < ph; d++) {
        int row = unit_row + (d % 2 ? -(d + 1) / 2 : d / 2);
        int taken = row < 2 || row >= 2 + ph;
        for (int t = 0; t < ntick_rows && !taken; t++)
            taken = tick_row[t] == row;
        if (!taken) {
            unit_row = row;
            break;
        }
    }
    tui_putf(unit_row, 0, lw, A_NORMAL, "%*s", lw - 1,
             unit_of(axis_name(s, 1)));
    if (s->n == 0) {
        tui_put(2 + ph / 2, lw + 4, pw - 4, tui_attr(ROLE_DIM),
                "no option to plot (the filter hides every one)");
        return;
    }
    /* the front line, under the points */
    if (s->show_front)
        for (size_t f = 0; f + 1 < s->nfront; f++) {
            const struct scatter_point *a = &s->points[s->front[f]];
            const struct scatter_point *b = &s->points[s->front[f + 1]];
            int c0 = scatter_cell(a->x, xmin, xmax, pw);
            int c1 = scatter_cell(b->x, xmin, xmax, pw);
            int r0 = scatter_cell(a->y, ymin, ymax, ph);
            int r1 = scatter_cell(b->y, ymin, ymax, ph);
            for (int c = c0 + 1; c < c1; c++) {
                int r = r0 + (r1 - r0) * (c - c0) / (c1 - c0);
                tui_put(2 + ph - 1 - r, lw + 1 + c, 1,
                        tui_attr(ROLE_PARETO) | A_DIM, g->front);
            }
        }
    /* the points: others, then Pareto options, then the knee and the
     * marked ones on top; each kind has its own glyph */
    for (int pass = 0; pass < 3; pass++)
        for (size_t k = 0; k < s->n; k++) {
            const struct scatter_point *p = &s->points[k];
            int knee = s->rows[k].knee, mark = table_model_marked(m,
                                                                  p->number);
            int kind = mark || knee ? 2 : p->rank == 1 ? 1 : 0;
            if (kind != pass)
                continue;
            int c = scatter_cell(p->x, xmin, xmax, pw);
            int r = scatter_cell(p->y, ymin, ymax, ph);
            if (c < 0 || r < 0)
                continue;
            const char *glyph = mark ? g->mark : knee ? g->knee
                                : p->rank == 1 ? g->pareto
                                : g->point[scatter_level(p->z, zmin, zmax,
                                                         3)];
            attr_t attr = mark ? tui_attr(ROLE_MARKED)
                          : knee ? tui_attr(ROLE_KNEE)
                          : p->rank == 1 ? tui_attr(ROLE_PARETO) : A_NORMAL;
            double cv = colour_value(s, k);
            if (s->axis[3] >= 0 && app->colour && isfinite(cv) && !mark)
                attr = tui_attr(ROLE_SCALE0 +
                                scatter_level(cv, cmin, cmax, 4)) |
                       (p->rank == 1 ? A_BOLD : 0);
            tui_put(2 + ph - 1 - r, lw + 1 + c, 1, attr, glyph);
        }
    const struct scatter_point *p = &s->points[s->cursor];
    int c = scatter_cell(p->x, xmin, xmax, pw);
    int r = scatter_cell(p->y, ymin, ymax, ph);
    int knee = s->rows[s->cursor].knee;
    if (c >= 0 && r >= 0)
        tui_put(2 + ph - 1 - r, lw + 1 + c, 1, tui_attr(ROLE_SELECTION) |
                A_BOLD, table_model_marked(m, p->number) ? g->mark
                        : knee ? g->knee : p->rank == 1 ? g->pareto
                        : g->point[scatter_level(p->z, zmin, zmax, 3)]);
    char xs[32], ys[32], zs[32];
    label(xs, sizeof xs, axis_name(s, 0), p->x);
    label(ys, sizeof ys, axis_name(s, 1), p->y);
    label(zs, sizeof zs, axis_name(s, 2), p->z);
    tui_putf(4 + ph, 0, width, tui_attr(ROLE_HEADER),
             " No. %lld  %s %s  %s %s  %s %s  rank %d%s%s ",
             (long long)p->number, axis_name(s, 0), xs, axis_name(s, 1), ys,
             axis_name(s, 2), zs, p->rank, knee ? " knee" : "",
             table_model_marked(m, p->number) ? " marked" : "");
    if (s->picking)
        draw_picker(s, height, width);
}

static void cycle(struct scatter_screen *s, int a, int dir)
{
    if (a == 3) {  /* the colour: none, then every metric */
        s->axis[3] = (s->axis[3] + 1 + dir + AXES + 1) % (AXES + 1) - 1;
        return;
    }
    s->axis[a] = (s->axis[a] + dir + AXES) % AXES;
    if (a < 2 && s->axis[a] == s->axis[1 - a])  /* not the other axis */
        s->axis[a] = (s->axis[a] + dir + AXES) % AXES;
    int64_t number = s->n ? s->points[s->cursor].number : 0;
    compute(s);
    cursor_to(s, number);
}

/* Writes the run's scatter (every option, the screen's axes) to the path
 * typed; a trailing ! overwrites. */
static void write_plot(struct scatter_screen *s, struct tui_app *app)
{
    char path[TUI_INPUT_MAX];
    snprintf(path, sizeof path, "%s", s->plot_to.text);
    size_t n = strlen(path);
    int force = n > 0 && path[n - 1] == '!';
    if (force)
        path[--n] = '\0';
    if (n == 0) {
        tui_error(app, "plot: give a file name");
        return;
    }
    int64_t run = s->model->browse.run;
    struct plot_request request = {&run, 1, axis_name(s, 0), axis_name(s, 1),
                                   axis_name(s, 2), NULL, force,
                                   s->model->filter,
                                   s->model->browse.pareto_only, NULL};
    struct facet_error err;
    if (study_plot(app->store, &request, path, &err) != FACET_OK)
        tui_error(app, "plot: %s", err.message);
    else
        tui_status(app, "wrote %s", path);
}

static enum tui_result scatter_key(struct tui_screen *base,
                                   struct tui_app *app, int key)
{
    struct scatter_screen *s = (struct scatter_screen *)base;
    struct facet_error err;
    if (s->exporting) {
        enum tui_input_result r = tui_input_key(&s->plot_to, key);
        if (r == INPUT_DONE || r == INPUT_CANCEL) {
            s->exporting = 0;
            tui_prompt(app, NULL, NULL);
            if (r == INPUT_DONE)
                write_plot(s, app);
        }
        return RESULT_HANDLED;
    }
    if (key == 'e' || key == KEY_F(9)) {
        char name[128];
        snprintf(name, sizeof name, "facet-run%lld-plot.svg",
                 (long long)s->model->browse.run);
        tui_input_set(&s->plot_to, name);
        s->exporting = 1;
        tui_prompt(app, "Plot to:", &s->plot_to);
        return RESULT_HANDLED;
    }
    if (s->editing) {
        if (tui_filter_history_key(app, &s->filter, key))
            return RESULT_HANDLED;
        enum tui_input_result r = tui_input_key(&s->filter, key);
        if (r == INPUT_DONE || r == INPUT_CANCEL) {
            s->editing = 0;
            tui_prompt(app, NULL, NULL);
            if (r == INPUT_DONE) {
                int rc = table_model_set_filter(s->model, s->filter.text,
                                                &err);
                tui_history_add(&app->filters, s->filter.text,
                                rc != FACET_OK);
                if (rc != FACET_OK)
                    tui_error(app, "filter: %s", err.message);
                else
                    load(s, app);
            }
        }
        return RESULT_HANDLED;
    }
    if (s->picking) {
        static const char role_key[4] = {'x', 'y', 'z', 'c'};
        for (int a = 0; a < 4; a++)
            if (key == role_key[a]) {
                if (a < 2 && s->axis[1 - a] == s->pick) {
                    tui_error(app, "%s is on the other axis already",
                              axis_column(s, s->pick));
                    return RESULT_HANDLED;
                }
                int64_t number = s->n ? s->points[s->cursor].number : 0;
                s->axis[a] = s->pick;
                compute(s);
                cursor_to(s, number);
                return RESULT_HANDLED;
            }
        switch (tui_key_action(key)) {
        case ACTION_UP: if (s->pick > 0) s->pick--; break;
        case ACTION_DOWN: if (s->pick + 1 < AXES) s->pick++; break;
        case ACTION_HELP: case ACTION_QUIT: return RESULT_UNHANDLED;
        default:
            if (key == 'M' || key == 'q' || key == 27 || key == '\r' ||
                key == '\n' || key == KEY_ENTER)
                s->picking = 0;
        }
        return RESULT_HANDLED;
    }
    switch (key) {
    case 'M':
        s->picking = 1;
        s->pick = s->axis[0];
        return RESULT_HANDLED;
    case 'c': cycle(s, 3, 1); return RESULT_HANDLED;
    case 'C': cycle(s, 3, -1); return RESULT_HANDLED;
    case ' ':
        if (s->n > 0) {
            int64_t number = s->points[s->cursor].number;
            int on = !table_model_marked(s->model, number);
            if (table_model_set_mark(s->model, number, on, &err) != FACET_OK)
                tui_error(app, "%s", err.message);
            else
                tui_status(app, "option %lld %s (%d marked)",
                           (long long)number, on ? "marked" : "unmarked",
                           s->model->nmarks);
        }
        return RESULT_HANDLED;
    case 'x': cycle(s, 0, 1); return RESULT_HANDLED;
    case 'X': cycle(s, 0, -1); return RESULT_HANDLED;
    case 'y': cycle(s, 1, 1); return RESULT_HANDLED;
    case 'Y': cycle(s, 1, -1); return RESULT_HANDLED;
    case 'z': cycle(s, 2, 1); return RESULT_HANDLED;
    case 'Z': cycle(s, 2, -1); return RESULT_HANDLED;
    case 'f': s->show_front = !s->show_front; return RESULT_HANDLED;
    case 'p': case KEY_F(4):
        if (table_model_set_pareto(s->model, !s->model->browse.pareto_only,
                                   &err) != FACET_OK)
            tui_error(app, "%s", err.message);
        load(s, app);
        return RESULT_HANDLED;
    case 'K':
        for (size_t k = 0; k < s->n; k++)
            if (s->rows[k].knee) {
                s->cursor = k;
                follow(s, app);
                return RESULT_HANDLED;
            }
        tui_error(app, "the knee option is not among the points");
        return RESULT_HANDLED;
    case 'm': case '\r': case '\n': case KEY_ENTER:
        if (s->n > 0)
            tui_push(app, screen_map_new(app, s->model->browse.run,
                                         s->points[s->cursor].number));
        return RESULT_HANDLED;
    case KEY_F(3):
        key = '/';
        break;
    default:
        break;
    }
    int dx = 0, dy = 0;
    switch (tui_key_action(key)) {
    case ACTION_LEFT: dx = -1; break;
    case ACTION_RIGHT: dx = 1; break;
    case ACTION_UP: dy = 1; break;
    case ACTION_DOWN: dy = -1; break;
    case ACTION_SEARCH:
        s->editing = 1;
        tui_filter_open(app, &s->filter, s->model);
        return RESULT_HANDLED;
    default:
        return RESULT_UNHANDLED;
    }
    s->cursor = scatter_step(s->points, s->n, s->cursor, dx, dy);
    follow(s, app);
    return RESULT_HANDLED;
}

static void scatter_destroy(struct tui_screen *base)
{
    struct scatter_screen *s = (struct scatter_screen *)base;
    free(s->rows);
    free(s->points);
    free(s->front);
    free(s);
}

static const struct tui_screen_class scatter_class = {
    "Scatter", scatter_help,
    {"Help", NULL, "Filter", "Pareto", NULL, NULL, NULL, NULL, "Export",
     "Quit"},
    scatter_draw, scatter_key, NULL, scatter_destroy,
};

struct tui_screen *screen_scatter_new(struct tui_app *app,
                                      struct table_model *model)
{
    struct scatter_screen *s = calloc(1, sizeof *s);
    if (s == NULL) {
        tui_error(app, "out of memory");
        return NULL;
    }
    s->base.cls = &scatter_class;
    s->model = model;
    s->axis[0] = 0;  /* planarity */
    s->axis[1] = 1;  /* cost */
    s->axis[2] = 2;  /* DP area */
    s->axis[3] = -1; /* no colour until c */
    s->show_front = 1;
    s->project = model->project;
    if (load(s, app) != FACET_OK) {
        scatter_destroy(&s->base);
        return NULL;
    }
    return &s->base;
}
