/*
 * screen_parallel.c: Parallel coordinates: one vertical axis per design
 * variable and metric (U, V, threshold, planarity, DP area, cost, FP
 * area, SP area), one polyline per option in braille dots (ASCII slopes
 * without UTF-8): the options the filter shows on top of the others
 * (dimmed, c hides them), Pareto options on top of those, the selected
 * option on top of all. Brushing from the keyboard sets a [lo, hi] range
 * on an axis; the brushes are the filter of the options table's model,
 * written in the --where language, so the table, the scatter and this
 * view show one filtered set and one selection. A large run is drawn
 * from a sample (store_browse_sample) that keeps every Pareto option.
 * The arithmetic is in parallel_model.c.
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
#include "parallel_model.h"

/* Options drawn at most from each sample (plus the Pareto ones). */
#define PC_SAMPLE 1500

struct row_list {
    struct option_row *rows;
    size_t n, capacity;
    int failed;
};

struct parallel_screen {
    struct tui_screen base;
    struct table_model *model;    /* borrowed: the options table's, and
                                     model->run the run shown */
    struct pc_state st;
    int axis;                     /* the current axis */
    struct row_list context;      /* a sample of every option */
    struct row_list shown;        /* a sample of what the filter shows */
    int sampled;                  /* some options are not drawn */
    int hide_context;             /* c: the filtered-out options hidden */
    int editing;                  /* the range prompt is open */
    struct tui_input range;
    char prompt[64];
    struct timespec last_load;
};

static const struct tui_key_help parallel_help[] = {
    {"h/l, Left/Right", "move to the previous / next axis"},
    {"[ / {", "raise / lower the low edge of the axis's brush"},
    {"] / }", "lower / raise the high edge of the axis's brush"},
    {"e, =, F3", "type the axis's range: LO:HI (1.1M:1.2M, :900, 20:)"},
    {"x, Backspace", "clear the axis's brush"},
    {"X", "clear every brush (the rest of the filter stays)"},
    {"j/k, Up/Down", "select the next / previous option (table order)"},
    {"g/G", "select the first / last option"},
    {"p, F4", "Pareto-optimal options only (toggle)"},
    {"c, F2", "show / hide the options the filter hides (dimmed; "
              "dotted without colours)"},
    {"Enter, m, F8", "panel map of the selected option"},
    {"r", "reload from the database"},
    {"(brushes)", "are the table's filter: q shows the filtered table"},
    {NULL, NULL},
};

static int add_row(void *context, const struct option_row *option)
{
    struct row_list *l = context;
    if (l->n == l->capacity) {
        size_t capacity = l->capacity ? 2 * l->capacity : 256;
        struct option_row *rows = realloc(l->rows, capacity * sizeof *rows);
        if (rows == NULL) {
            l->failed = 1;
            return 1;
        }
        l->rows = rows;
        l->capacity = capacity;
    }
    l->rows[l->n++] = *option;
    return 0;
}

/* Fills l with a sample of b of about PC_SAMPLE options, every Pareto
 * option kept. *sampled is set when some are left out. */
static int sample(struct store *store, const struct option_browse *b,
                  struct row_list *l, int *sampled, struct facet_error *err)
{
    l->n = 0;
    l->failed = 0;
    int64_t count;
    int rc = store_browse_count(store, b, &count, err);
    if (rc != FACET_OK)
        return rc;
    int64_t stride = count > PC_SAMPLE ? (count + PC_SAMPLE - 1) / PC_SAMPLE
                                       : 1;
    if (stride > 1)
        *sampled = 1;
    rc = store_browse_sample(store, b, stride, 4 * PC_SAMPLE, add_row, l,
                             err);
    if (rc == FACET_OK && l->failed)
        rc = facet_error_set(err, FACET_EWORK, "out of memory");
    return rc;
}

/* The browse of every option of the run (no filter, no Pareto-only). */
static struct option_browse every_option(const struct parallel_screen *s)
{
    struct option_browse b;
    memset(&b, 0, sizeof b);
    b.run = s->model->browse.run;
    return b;
}

/* Axis ranges over every option of the run, and the brushes read back
 * from the model's filter. */
static int load_ranges(struct parallel_screen *s, struct tui_app *app,
                       struct facet_error *err)
{
    for (int a = 0; a < PC_AXES; a++) {
        int rc = store_run_column_range(app->store, s->model->browse.run,
                                        pc_axis_column(&s->st, a), &s->st.min[a],
                                        &s->st.max[a], err);
        if (rc != FACET_OK)
            return rc;
    }
    pc_from_filter(&s->st, s->model->filter ? filter_text(s->model->filter)
                                            : "");
    return FACET_OK;
}

static int load(struct parallel_screen *s, struct tui_app *app)
{
    struct facet_error err;
    clock_gettime(CLOCK_MONOTONIC, &s->last_load);
    s->sampled = 0;
    struct option_browse b = every_option(s);
    /* the model read the run when the table opened: read again only
     * while it runs, when its count and status move */
    int rc = s->model->run.status == RUN_RUNNING
                 ? table_model_read_run(s->model, &err) : FACET_OK;
    if (rc == FACET_OK)
        rc = load_ranges(s, app, &err);
    if (rc == FACET_OK)
        rc = sample(app->store, &b, &s->context, &s->sampled, &err);
    if (rc == FACET_OK)
        rc = sample(app->store, &s->model->browse, &s->shown, &s->sampled,
                    &err);
    if (rc != FACET_OK)
        tui_error(app, "%s", err.message);
    return rc;
}

/* The filtered sample again, after the filter changed. */
static void reload_shown(struct parallel_screen *s, struct tui_app *app)
{
    struct facet_error err;
    int sampled = 0;
    if (sample(app->store, &s->model->browse, &s->shown, &sampled, &err) !=
        FACET_OK)
        tui_error(app, "%s", err.message);
}

/* The brushes become the model's filter. */
static void apply(struct parallel_screen *s, struct tui_app *app)
{
    char text[2048];
    struct facet_error err;
    if (pc_filter_text(&s->st, text, sizeof text, &err) != FACET_OK) {
        tui_error(app, "%s", err.message);
        return;
    }
    if (table_model_set_filter(s->model, text, &err) != FACET_OK) {
        tui_error(app, "%s", err.message);
        return;
    }
    pc_from_filter(&s->st, s->model->filter ? filter_text(s->model->filter)
                                            : "");
    reload_shown(s, app);
    char shown[32];
    table_model_count_text(s->model, shown, sizeof shown);
    tui_status(app, "%s options pass: %s", shown,
               text[0] ? text : "no filter");
}

/* --- drawing --- */

/* value as the axis's metric shows, in at most width characters. */
static void axis_label(char *out, size_t size, const struct pc_state *st,
                       int axis, double value, int width)
{
    const struct quantity *c = quantity_named(pc_axis_column(st, axis));
    if (c)
        tui_fmt_value(out, size, c, value);
    else
        snprintf(out, size, "%.4g", value);
    if ((int)strlen(out) > width) {
        if (fabs(value) >= 1e6)
            snprintf(out, size, "%.4gM", value / 1e6);
        else if (fabs(value) >= 1e4)
            snprintf(out, size, "%.4gk", value / 1e3);
        else
            snprintf(out, size, "%.3g", value);
    }
}

/* text centred on column x, kept within [0, width). */
static void put_centred(int y, int x, int width, attr_t attr,
                        const char *text)
{
    int n = (int)strlen(text);
    int at = x - n / 2;
    if (at + n > width)
        at = width - n;
    if (at < 0)
        at = 0;
    tui_put(y, at, n, attr, text);
}

static void polyline(struct pc_canvas *c, const struct pc_state *st,
                     const int *ax, const struct option_row *o, int level)
{
    int px = -1, py = -1;
    for (int a = 0; a < PC_AXES; a++) {
        double v = option_quantity_value(o, pc_axis_column(st, a));
        int y = pc_axis_dot(v, st->min[a], st->max[a], 4 * c->height);
        int x = 2 * ax[a];
        if (y < 0) {
            px = -1;
            continue;
        }
        if (px >= 0)
            pc_canvas_line(c, px, py, x, y, level);
        px = x;
        py = y;
    }
}

enum { LEVEL_CONTEXT = 1, LEVEL_SHOWN, LEVEL_PARETO, LEVEL_SELECTED };

static void parallel_draw(struct tui_screen *base, struct tui_app *app,
                          int height, int width)
{
    struct parallel_screen *s = (struct parallel_screen *)base;
    struct table_model *m = s->model;
    const struct pc_state *st = &s->st;
    tui_fill(0, 0, width, tui_attr(ROLE_TITLE));
    char shown[32];
    table_model_count_text(m, shown, sizeof shown);
    tui_putf(0, 0, width, tui_attr(ROLE_TITLE),
             " Parallel coordinates: run %lld | %s of %lld options shown%s%s",
             (long long)s->model->run.id, shown,
             (long long)s->model->run.options, m->browse.pareto_only
                                            ? " | Pareto only" : "",
             s->sampled ? " | sampled" : "");
    const char *where = m->filter ? filter_text(m->filter) : "";
    tui_putf(1, 0, width, where[0] ? tui_attr(ROLE_PARETO) : A_NORMAL,
             " filter %s", where[0] ? where : "none");

    int plot_h = height - 7;
    if (plot_h < 2)
        plot_h = 2;
    int left = 4, right = 5;
    int ax[PC_AXES];
    int span = width - left - right - 1;
    for (int a = 0; a < PC_AXES; a++)
        ax[a] = left + a * span / (PC_AXES - 1);
    int room = span / (PC_AXES - 1) - 1;
    if (room > 12)
        room = 12;
    int top = 4, bottom = top + plot_h;  /* plot rows [top, bottom) */

    /* the polylines */
    struct pc_canvas c;
    struct facet_error canvas_err;  /* no canvas: the axes alone */
    if (pc_canvas_init(&c, width, plot_h, &canvas_err) == FACET_OK) {
        if (!s->hide_context)
            for (size_t k = 0; k < s->context.n; k++)
                if (!table_model_shows(m, &s->context.rows[k]))
                    polyline(&c, st, ax, &s->context.rows[k],
                             LEVEL_CONTEXT);
        for (int pass = 0; pass < 2; pass++)
            for (size_t k = 0; k < s->shown.n; k++)
                if ((s->shown.rows[k].rank == 1) == pass)
                    polyline(&c, st, ax, &s->shown.rows[k],
                             pass ? LEVEL_PARETO : LEVEL_SHOWN);
        const struct option_row *sel = table_model_selection(m);
        if (sel != NULL)
            polyline(&c, st, ax, sel, LEVEL_SELECTED);
        static const enum tui_role role[5] = {
            ROLE_NORMAL, ROLE_DIM, ROLE_NORMAL, ROLE_PARETO,
            ROLE_SELECTION};
        for (int y = 0; y < plot_h; y++)
            for (int x = 0; x < width; x++) {
                size_t k = (size_t)y * (size_t)width + (size_t)x;
                if (c.level[k] == 0)
                    continue;
                char glyph[4];
                if (c.level[k] == LEVEL_CONTEXT && !app->colour)
                    /* without colours dim may not show (vt100): the
                     * options the filter hides are dotted, so that a
                     * filter always changes the picture */
                    snprintf(glyph, sizeof glyph, "%s",
                             app->glyphs->point[0]);
                else if (app->utf8)
                    pc_braille(c.dots[k], glyph);
                else
                    snprintf(glyph, sizeof glyph, "%c", c.slope[k]);
                tui_put(top + y, x, 1, tui_attr(role[c.level[k]]), glyph);
            }
        pc_canvas_free(&c);
    }

    /* the axes, their brushes and labels */
    const struct option_row *sel = table_model_selection(m);
    for (int a = 0; a < PC_AXES; a++) {
        int current = a == s->axis;
        const struct pc_brush *b = &st->brush[a];
        int hi_row = -1, lo_row = -1;
        if (b->active) {
            hi_row = pc_axis_dot(b->hi, st->min[a], st->max[a], 4 * plot_h)
                     / 4;
            lo_row = pc_axis_dot(b->lo, st->min[a], st->max[a], 4 * plot_h)
                     / 4;
        }
        int sel_row = sel ? pc_axis_dot(option_quantity_value(sel,
                                            pc_axis_column(&s->st, a)),
                                        st->min[a], st->max[a], 4 * plot_h)
                            / 4
                          : -1;
        for (int y = 0; y < plot_h; y++) {
            int brushed = b->active && y >= hi_row && y <= lo_row;
            attr_t attr = brushed ? tui_attr(current ? ROLE_COLUMN
                                                     : ROLE_MARKED)
                          : current ? tui_attr(ROLE_HEADER)
                                    : tui_attr(ROLE_DIM);
            const char *glyph = brushed ? (app->utf8 ? "\u2503" : "#")
                                        : app->glyphs->vline;
            if (y == sel_row && sel != NULL) {
                glyph = app->utf8 ? "\u25cf" : "o";
                attr = tui_attr(ROLE_SELECTION);
            }
            tui_put(top + y, ax[a], 1, attr, glyph);
        }
        char title[32], hi[32], lo[32];
        snprintf(title, sizeof title, "%s%s%s%s", current ? "[" : "",
                 quantity_named(pc_axis_column(&s->st, a))->heading,
                 b->active ? "*" : "", current ? "]" : "");
        put_centred(2, ax[a], width, current ? tui_attr(ROLE_COLUMN)
                                             : tui_attr(ROLE_HEADER),
                    title);
        axis_label(hi, sizeof hi, st, a, st->max[a], room);
        axis_label(lo, sizeof lo, st, a, st->min[a], room);
        put_centred(3, ax[a], width, tui_attr(ROLE_DIM), hi);
        put_centred(bottom, ax[a], width, tui_attr(ROLE_DIM), lo);
    }

    /* the current axis's brush, and the selected option */
    const struct quantity *cur =
        quantity_named(pc_axis_column(&s->st, s->axis));
    const struct pc_brush *b = &st->brush[s->axis];
    char lo[32], hi[32];
    int y = bottom + 1;
    if (b->active) {
        axis_label(lo, sizeof lo, &s->st, s->axis, b->lo, 20);
        axis_label(hi, sizeof hi, &s->st, s->axis, b->hi, 20);
        tui_putf(y, 0, width, tui_attr(ROLE_MARKED),
                 " %s %s: brush %s%s .. %s%s %s  ([ ] { } move, e types, x "
                 "clears)", cur->heading, cur->unit,
                 b->lo_open ? "over " : "", lo, b->hi_open ? "under " : "",
                 hi, cur->unit);
    } else {
        tui_putf(y, 0, width, A_NORMAL,
                 " %s %s: no brush  ([ raises the low edge, ] lowers the "
                 "high one, e types)", cur->heading, cur->unit);
    }
    if (sel != NULL) {
        char cost[32], grid[64];
        tui_fmt_number(cost, sizeof cost, sel->totals.cost, 0, 1);
        tui_fmt_grid(grid, sizeof grid, sel);
        tui_putf(y + 1, 0, width, A_NORMAL,
                 " No. %lld%s: %s, t %.2f mm, planarity %.3f m, DP %.1f m^2, "
                 "cost %s USD, FP %.1f m^2, SP %.1f m^2",
                 (long long)sel->number, sel->rank == 1 ? " (Pareto)" : "",
                 grid, sel->threshold_mm, sel->totals.planarity,
                 sel->totals.area_of[TYPE_DP], cost,
                 sel->totals.area_of[TYPE_FP], sel->totals.area_of[TYPE_SP]);
    } else {
        tui_put(y + 1, 0, width, tui_attr(ROLE_DIM),
                " No option passes the filter (x or X clears brushes).");
    }
}

/* --- keys --- */

static void open_range(struct parallel_screen *s, struct tui_app *app)
{
    const struct pc_brush *b = &s->st.brush[s->axis];
    char text[80] = "";
    if (b->active)
        snprintf(text, sizeof text, "%.15g:%.15g", b->lo, b->hi);
    tui_input_set(&s->range, text);
    snprintf(s->prompt, sizeof s->prompt, "Range of %s (LO:HI):",
             pc_axis_column(&s->st, s->axis));
    s->editing = 1;
    tui_prompt(app, s->prompt, &s->range);
}

static enum tui_result range_key(struct parallel_screen *s,
                                 struct tui_app *app, int key)
{
    if (tui_prompt_key(app, &s->range, &s->editing, key) != INPUT_DONE)
        return RESULT_HANDLED;
    int a = s->axis;
    double lo, hi;
    struct facet_error err;
    const char *t = s->range.text;
    while (*t == ' ')
        t++;
    if (*t == '\0') {
        s->st.brush[a].active = 0;
    } else if (pc_parse_range(t, s->st.min[a], s->st.max[a], &lo, &hi,
                              &err) != FACET_OK) {
        tui_error(app, "%s", err.message);
        return RESULT_HANDLED;
    } else {
        pc_brush_set(&s->st, a, lo, hi);
    }
    apply(s, app);
    return RESULT_HANDLED;
}

static enum tui_result parallel_key(struct tui_screen *base,
                                    struct tui_app *app, int key)
{
    struct parallel_screen *s = (struct parallel_screen *)base;
    struct table_model *m = s->model;
    struct facet_error err;
    if (s->editing)
        return range_key(s, app, key);
    switch (key) {
    case '[': pc_brush_move(&s->st, s->axis, 0, 1); apply(s, app);
        return RESULT_HANDLED;
    case '{': pc_brush_move(&s->st, s->axis, 0, -1); apply(s, app);
        return RESULT_HANDLED;
    case ']': pc_brush_move(&s->st, s->axis, 1, -1); apply(s, app);
        return RESULT_HANDLED;
    case '}': pc_brush_move(&s->st, s->axis, 1, 1); apply(s, app);
        return RESULT_HANDLED;
    case 'e': case '=': case KEY_F(3):
        open_range(s, app);
        return RESULT_HANDLED;
    case 'x': case KEY_BACKSPACE: case 127: case KEY_DC:
        s->st.brush[s->axis].active = 0;
        apply(s, app);
        return RESULT_HANDLED;
    case 'X':
        memset(s->st.brush, 0, sizeof s->st.brush);
        apply(s, app);
        return RESULT_HANDLED;
    case 'p': case KEY_F(4):
        if (table_model_set_pareto(m, !m->browse.pareto_only, &err) !=
            FACET_OK)
            tui_error(app, "%s", err.message);
        reload_shown(s, app);
        return RESULT_HANDLED;
    case 'c': case KEY_F(2):
        s->hide_context = !s->hide_context;
        return RESULT_HANDLED;
    case 'm': case KEY_F(8): case '\r': case '\n': case KEY_ENTER: {
        const struct option_row *o = table_model_selection(m);
        if (o != NULL)
            tui_push(app, screen_map_new(app, m->browse.run, o->number));
        return RESULT_HANDLED;
    }
    case 'r':
        load(s, app);
        return RESULT_HANDLED;
    default:
        break;
    }
    int rc = FACET_OK;
    switch (tui_key_action(key)) {
    case ACTION_LEFT:
        s->axis = (s->axis + PC_AXES - 1) % PC_AXES;
        break;
    case ACTION_RIGHT:
        s->axis = (s->axis + 1) % PC_AXES;
        break;
    case ACTION_DOWN: rc = table_model_select(m, m->selected + 1, &err);
        break;
    case ACTION_UP: rc = table_model_select(m, m->selected - 1, &err);
        break;
    case ACTION_TOP: rc = table_model_select(m, 0, &err); break;
    case ACTION_BOTTOM:
        rc = table_model_select_last(m, &err);
        break;
    default:
        return RESULT_UNHANDLED;
    }
    if (rc != FACET_OK)
        tui_error(app, "%s", err.message);
    return RESULT_HANDLED;
}

/* Counts on while the count is a lower bound; a running run: everything
 * again every two seconds. */
static int parallel_tick(struct tui_screen *base, struct tui_app *app)
{
    struct parallel_screen *s = (struct parallel_screen *)base;
    struct facet_error err;
    if (!s->model->count_exact) {
        int exact;
        if (table_model_count_step(s->model, TABLE_COUNT_STEP, &exact,
                                   &err) != FACET_OK)
            tui_error(app, "%s", err.message);
        return 1;
    }
    if (s->model->run.status != RUN_RUNNING ||
        tui_seconds_since(&s->last_load) < 2.0)
        return 0;
    if (table_model_refresh(s->model, &err) != FACET_OK)
        tui_error(app, "%s", err.message);
    load(s, app);
    return 1;
}

static void parallel_destroy(struct tui_screen *base)
{
    struct parallel_screen *s = (struct parallel_screen *)base;
    free(s->context.rows);
    free(s->shown.rows);
    free(s);
}

static const struct tui_screen_class parallel_class = {
    "Parallel coordinates", parallel_help,
    {"Help", "Dim", "Range", "Pareto", NULL, NULL, NULL, "Map", NULL,
     "Quit"},
    parallel_draw, parallel_key, parallel_tick, parallel_destroy,
};

struct tui_screen *screen_parallel_new(struct tui_app *app,
                                       struct table_model *model)
{
    struct parallel_screen *s = calloc(1, sizeof *s);
    if (s == NULL) {
        tui_error(app, "out of memory");
        return NULL;
    }
    s->base.cls = &parallel_class;
    s->model = model;
    s->axis = 5;  /* cost */
    s->st.project = model->project;
    if (load(s, app) != FACET_OK) {
        parallel_destroy(&s->base);
        return NULL;
    }
    return &s->base;
}
