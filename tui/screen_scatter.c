/*
 * screen_scatter.c: the Scatter plot: two metrics of the options against
 * each other (default total planarity vs cost, the paper's Figure 13), a
 * third as glyph size (default DP area), the two-metric Pareto front
 * drawn as a line and the run's Pareto options highlighted, and a cursor
 * moving from point to point. It shows the options table's filter and
 * Pareto-only setting (and changes them: they are the same model), and
 * moving the cursor moves the table's selection.
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
#include "store/study_export.h"

#define SCATTER_POINTS 8000

static const char *const axis_columns[] = {
    "planarity", "cost", "dp_area", "fp_area", "sp_area", "max_deviation",
    "max_panel_area", "p_dist", "nu", "nv", "threshold_mm", "panels",
    "dp_count", "rank", "crowding",
};
#define AXES ((int)(sizeof axis_columns / sizeof axis_columns[0]))

struct scatter_screen {
    struct tui_screen base;
    struct table_model *model;   /* the options table's, borrowed */
    struct option_row *rows;
    struct scatter_point *points;
    size_t *front;
    size_t n, nfront, capacity;
    int axis[3];                 /* x, y, size: indexes of axis_columns */
    size_t cursor;
    int show_front;
    int sampled;                 /* the points are a sample */
    int editing;
    struct tui_input filter;
    int exporting;               /* the plot's file line is open */
    struct tui_input plot_to;
};

static const struct tui_key_help scatter_help[] = {
    {"h/j/k/l, arrows", "move the cursor to the nearest point that way"},
    {"Enter, m", "panel map of the point's option"},
    {"x / X", "next / previous metric on the x axis"},
    {"y / Y", "next / previous metric on the y axis"},
    {"z / Z", "next / previous metric for the glyph size"},
    {"f", "show / hide the two-metric Pareto front line"},
    {"p, F4", "Pareto-optimal options only (shared with the table)"},
    {"/, F3", "filter (shared with the table)"},
    {"K", "the knee option"},
    {"e, F9", "write the run's scatter as SVG with these axes (every "
              "option); end the name with ! to overwrite"},
    {NULL, NULL},
};

static const char *axis_name(const struct scatter_screen *s, int a)
{
    return axis_columns[s->axis[a]];
}

/* Fills the points' x, y, z from the rows, and the front. */
static void compute(struct scatter_screen *s)
{
    for (size_t k = 0; k < s->n; k++) {
        s->points[k].number = s->rows[k].number;
        s->points[k].rank = s->rows[k].rank;
        s->points[k].x = store_option_value(&s->rows[k], axis_name(s, 0));
        s->points[k].y = store_option_value(&s->rows[k], axis_name(s, 1));
        s->points[k].z = store_option_value(&s->rows[k], axis_name(s, 2));
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
    const struct tui_column *c = tui_metric_column(column);
    if (c)
        tui_fmt_value(out, size, c, value);
    else
        snprintf(out, size, "%.4g", value);
}

static const char *unit_of(const char *column)
{
    const struct tui_column *c = tui_metric_column(column);
    return c && c->unit[0] ? c->unit : "";
}

static void scatter_draw(struct tui_screen *base, struct tui_app *app,
                         int height, int width)
{
    struct scatter_screen *s = (struct scatter_screen *)base;
    const struct tui_glyphs *g = app->glyphs;
    const char *where = s->model->filter ? filter_text(s->model->filter) : "";
    tui_fill(0, 0, width, tui_attr(ROLE_TITLE));
    tui_putf(0, 0, width, tui_attr(ROLE_TITLE),
             " Scatter: %s vs %s, size %s | %zu points%s%s%s%s",
             axis_name(s, 1), axis_name(s, 0), axis_name(s, 2), s->n,
             s->sampled ? " (sampled)" : "",
             s->model->browse.pareto_only ? " | Pareto only" : "",
             where[0] ? " | filter " : "", where);
    int x = tui_putf(1, 0, width, A_NORMAL, " x %s (%s)  y %s (%s)  ",
                     axis_name(s, 0), unit_of(axis_name(s, 0)),
                     axis_name(s, 1), unit_of(axis_name(s, 1)));
    x += tui_put(1, x, 1, tui_attr(ROLE_PARETO), g->pareto);
    x += tui_put(1, x, width - x, A_NORMAL, " Pareto  ");
    if (s->show_front)
        x += tui_putf(1, x, width - x, tui_attr(ROLE_PARETO), "%s%s",
                      g->front, g->front);
    x += tui_put(1, x, width - x, A_NORMAL, s->show_front ? " front  " : "");
    tui_putf(1, x, width - x, A_NORMAL, "%s%s%s small..large %s",
             g->point[0], g->point[1], g->point[2], axis_name(s, 2));

    int lw = 11, ph = height - 5, pw = width - lw - 2;
    if (ph < 3 || pw < 10)
        return;
    double xmin, xmax, ymin, ymax, zmin, zmax;
    scatter_range(s->points, s->n, 0, &xmin, &xmax);
    scatter_range(s->points, s->n, 1, &ymin, &ymax);
    scatter_range(s->points, s->n, 2, &zmin, &zmax);
    /* axes */
    attr_t dim = tui_attr(ROLE_DIM);
    for (int r = 0; r < ph; r++)
        tui_put(2 + r, lw, 1, dim, g->vline);
    tui_put(2 + ph, lw, 1, dim, g->corner);
    for (int c = 0; c < pw; c++)
        tui_put(2 + ph, lw + 1 + c, 1, dim, g->hline);
    char text[64];
    label(text, sizeof text, axis_name(s, 1), ymax);
    tui_putf(2, 0, lw, A_NORMAL, "%*s", lw - 1, text);
    label(text, sizeof text, axis_name(s, 1), (ymin + ymax) / 2);
    tui_putf(2 + ph / 2, 0, lw, A_NORMAL, "%*s", lw - 1, text);
    label(text, sizeof text, axis_name(s, 1), ymin);
    tui_putf(1 + ph, 0, lw, A_NORMAL, "%*s", lw - 1, text);
    label(text, sizeof text, axis_name(s, 0), xmin);
    tui_put(3 + ph, lw, pw, A_NORMAL, text);
    label(text, sizeof text, axis_name(s, 0), (xmin + xmax) / 2);
    tui_put(3 + ph, lw + pw / 2 - (int)strlen(text) / 2, pw, A_NORMAL, text);
    label(text, sizeof text, axis_name(s, 0), xmax);
    tui_put(3 + ph, lw + 1 + pw - (int)strlen(text), pw, A_NORMAL, text);
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
    /* the points: Pareto options over others, larger over smaller */
    for (int pass = 0; pass < 2; pass++)
        for (size_t k = 0; k < s->n; k++) {
            const struct scatter_point *p = &s->points[k];
            if ((p->rank == 1) != pass)
                continue;
            int c = scatter_cell(p->x, xmin, xmax, pw);
            int r = scatter_cell(p->y, ymin, ymax, ph);
            if (c < 0 || r < 0)
                continue;
            int level = scatter_level(p->z, zmin, zmax, 3);
            tui_put(2 + ph - 1 - r, lw + 1 + c, 1,
                    p->rank == 1 ? tui_attr(ROLE_PARETO) : A_NORMAL,
                    g->point[level]);
        }
    const struct scatter_point *p = &s->points[s->cursor];
    int c = scatter_cell(p->x, xmin, xmax, pw);
    int r = scatter_cell(p->y, ymin, ymax, ph);
    if (c >= 0 && r >= 0)
        tui_put(2 + ph - 1 - r, lw + 1 + c, 1, tui_attr(ROLE_SELECTION) |
                A_BOLD, g->point[scatter_level(p->z, zmin, zmax, 3)]);
    char xs[32], ys[32], zs[32];
    label(xs, sizeof xs, axis_name(s, 0), p->x);
    label(ys, sizeof ys, axis_name(s, 1), p->y);
    label(zs, sizeof zs, axis_name(s, 2), p->z);
    tui_putf(4 + ph, 0, width, tui_attr(ROLE_HEADER),
             " No. %lld  %s %s  %s %s  %s %s  rank %d%s ",
             (long long)p->number, axis_name(s, 0), xs, axis_name(s, 1), ys,
             axis_name(s, 2), zs, p->rank,
             s->rows[s->cursor].knee ? " knee" : "");
}

static void cycle(struct scatter_screen *s, int a, int dir)
{
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
                                   axis_name(s, 2), NULL, force};
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
        enum tui_input_result r = tui_input_key(&s->filter, key);
        if (r == INPUT_DONE || r == INPUT_CANCEL) {
            s->editing = 0;
            tui_prompt(app, NULL, NULL);
            if (r == INPUT_DONE) {
                if (table_model_set_filter(s->model, s->filter.text, &err) !=
                    FACET_OK)
                    tui_error(app, "filter: %s",
                              strncmp(err.message, "--where: ", 9) == 0
                                  ? err.message + 9 : err.message);
                else
                    load(s, app);
            }
        }
        return RESULT_HANDLED;
    }
    switch (key) {
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
        tui_input_set(&s->filter, s->model->filter
                                      ? filter_text(s->model->filter) : "");
        tui_prompt(app, "Filter:", &s->filter);
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
    s->show_front = 1;
    if (load(s, app) != FACET_OK) {
        scatter_destroy(&s->base);
        return NULL;
    }
    return &s->base;
}
