/*
 * screen_compare.c: Compare: two to four marked options side by side,
 * every metric, with the differences to the first (d shows the
 * differences alone when the values do not fit), and under the metrics
 * their panel maps, small (one character per panel, or per block of
 * panels when the grid is larger than the room), coloured by type. The
 * panels come from the store, or are evaluated once and stored
 * (study_option_panels) for an option that has none yet.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "app.h"
#include "format.h"
#include "keys.h"
#include "map_model.h"
#include "core/search/metric.h"
#include "study/study.h"

struct compare_screen {
    struct tui_screen base;
    int64_t run;
    struct objective objectives[OBJECTIVES_MAX];
    int nobjectives;
    struct option_row options[4];
    int n;
    int differences;   /* show the differences only */
    int top;
    int maps;          /* the panel maps show (m toggles) */
    struct panelization panels[4];
    int has_map[4];
    char map_error[4][600];
    double width_m, height_m;  /* the surface's extent, for the aspect */
};

static const struct tui_key_help compare_help[] = {
    {"j/k, Up/Down", "scroll the metrics"},
    {"d, F2", "values with differences, or the differences alone"},
    {"m, F8", "show / hide the small panel maps under the metrics"},
    {"(maps)", "one scale, the surface's aspect: F FP, S SP, D DP (a "
               "character shows the type covering most of it)"},
    {"(colours)", "a difference in an objective: better (v) or worse (x)"},
    {"1-4", "panel map of the first, second, ... option"},
    {NULL, NULL},
};

/* The column widths: the labels, then one column per option, as wide as
 * the terminal allows (up to 64). */
static int column_width(const struct compare_screen *s, int width, int lw)
{
    int cw = (width - lw - 6) / s->n;
    return cw > 64 ? 64 : cw;
}

/* The box every map is drawn in: the largest at the surface's aspect
 * within a column and the rows left to the maps. */
static void map_box(const struct compare_screen *s, int cw, int max_rows,
                    int *cols, int *rows)
{
    map_fit_box(s->width_m, s->height_m, cw - 2, max_rows, MAP_CELL_ASPECT,
                cols, rows);
}

static void draw_maps(struct compare_screen *s, struct tui_app *app, int y0,
                      int rows, int x0, int cw)
{
    tui_fill(y0, 0, x0 + s->n * cw, tui_attr(ROLE_HEADER));
    tui_put(y0, 0, x0, tui_attr(ROLE_HEADER), " panel maps, one scale");
    for (int t = 0; t < TYPE_COUNT; t++) {
        const char *name = panel_type_name((enum panel_type)t);
        char letter[2] = {name[0], 0};
        if (y0 + 1 + t < y0 + rows) {
            tui_put(y0 + 1 + t, 1, 1, tui_attr(tui_type_role(t)), letter);
            tui_putf(y0 + 1 + t, 2, x0 - 3, A_NORMAL, " %s", name);
        }
    }
    /* one reason for every option (a project's) is said once, across */
    int same = s->n > 0;
    for (int k = 0; k < s->n; k++)
        if (s->has_map[k] || strcmp(s->map_error[k], s->map_error[0]) != 0)
            same = 0;
    if (same) {
        tui_put_wrapped(y0 + 1, x0 + 1, s->n * cw - 2, rows - 1,
                    tui_attr(ROLE_ERROR), s->map_error[0]);
        return;
    }
    int box_w, box_h;
    map_box(s, cw, rows - 1, &box_w, &box_h);
    for (int k = 0; k < s->n; k++) {
        int x = x0 + k * cw + 1;
        if (!s->has_map[k]) {
            tui_put_wrapped(y0 + 1, x, cw - 2, rows - 1, tui_attr(ROLE_ERROR),
                        s->map_error[k]);
            continue;
        }
        const struct panelization *p = &s->panels[k];
        tui_putf(y0, x - 1, cw, tui_attr(ROLE_HEADER), "%*s", cw - 1, "");
        tui_putf(y0, x - 1, cw, tui_attr(ROLE_HEADER), "%*d x %d", cw - 6 -
                 (p->nv >= 10) - (p->nv >= 100), p->nu, p->nv);
        x = x0 + (k + 1) * cw - 1 - box_w;  /* right-aligned, as values */
        for (int r = 0; r < box_h; r++)
            for (int c = 0; c < box_w; c++) {
                int t = map_cell_value(p, box_w, box_h, c, r, MAP_BY_TYPE,
                                       NULL);
                char text[8];
                if (t < 0) {
                    tui_put(y0 + 1 + r, x + c, 1, tui_attr(ROLE_DIM),
                            app->glyphs->empty);
                    continue;
                }
                snprintf(text, sizeof text, "%c",
                         panel_type_name((enum panel_type)t)[0]);
                tui_put(y0 + 1 + r, x + c, 1, tui_attr(tui_type_role(t)),
                        text);
            }
    }
}

/* Whether column's difference means anything: not for the numbering and
 * the search's bookkeeping. */
static int has_difference(const char *column)
{
    static const char *const none[] = {"number", "generation", "crowding",
                                       "knee", "feasible"};
    for (size_t k = 0; k < sizeof none / sizeof none[0]; k++)
        if (strcmp(column, none[k]) == 0)
            return 0;
    return 1;
}

/* +1 when a larger value of column is better, -1 when a smaller one is,
 * 0 when column is not one of the run's objectives. */
static int direction(const struct compare_screen *s, const char *column)
{
    for (int k = 0; k < s->nobjectives; k++)
        if (strcmp(s->objectives[k].quantity->name, column) == 0)
            return s->objectives[k].maximise ? 1 : -1;
    return 0;
}

static void compare_draw(struct tui_screen *base, struct tui_app *app,
                         int height, int width)
{
    struct compare_screen *s = (struct compare_screen *)base;
    const struct tui_glyphs *g = app->glyphs;
    tui_fill(0, 0, width, tui_attr(ROLE_TITLE));
    tui_putf(0, 0, width, tui_attr(ROLE_TITLE),
             " Compare %d options of run %lld | %s", s->n, (long long)s->run,
             s->differences ? "differences to the first" : "values (and "
                                                          "difference)");
    int lw = 18, cw = column_width(s, width, lw);
    tui_fill(1, 0, width, tui_attr(ROLE_HEADER));
    tui_put(1, 0, lw + 6, tui_attr(ROLE_HEADER), " metric         unit obj");
    for (int k = 0; k < s->n; k++) {
        const struct option_row *o = &s->options[k];
        char title[64];
        snprintf(title, sizeof title, "No. %lld %s", (long long)o->number,
                 o->knee ? "knee" : o->rank == 1 ? "Pareto" : "");
        int x = lw + 6 + k * cw, n = (int)strlen(title);
        tui_putf(1, x, cw, tui_attr(ROLE_HEADER), "%*s", cw - 1, title);
        /* the knee's and the Pareto options' glyph before the title */
        if (o->rank == 1 && cw - 3 - n >= 0)
            tui_put(1, x + cw - 3 - n, 1, tui_attr(o->knee ? ROLE_KNEE
                                                           : ROLE_PARETO),
                    o->knee ? g->knee : g->pareto);
    }
    int map_rows = 0;
    if (s->maps) {
        int box_w, box_h, room = height - 2 - 7;
        map_box(s, cw, room - 1, &box_w, &box_h);
        map_rows = room >= 3 ? box_h + 1 : 0;
    }
    int rows = height - 2 - map_rows;
    if (rows > tui_metric_column_count)
        rows = tui_metric_column_count;
    if (map_rows > 0)
        draw_maps(s, app, 2 + rows, map_rows, lw + 6, cw);
    /* Fewer rows than metrics: the last row says how many more there are
     * and how to reach them (8 of 29 showed at 80x24, with no sign). */
    int hint = rows < tui_metric_column_count && rows >= 2;
    if (hint)
        rows--;
    if (s->top > tui_metric_column_count - rows)
        s->top = tui_metric_column_count - rows > 0
                     ? tui_metric_column_count - rows : 0;
    if (hint) {
        int below = tui_metric_column_count - s->top - rows;
        tui_putf(2 + rows, 0, width, tui_attr(ROLE_DIM),
                 " metrics %d-%d of %d: %d more below, %d above (j/k "
                 "scroll)", s->top + 1, s->top + rows,
                 tui_metric_column_count, below, s->top);
    }
    for (int r = 0; r < rows && s->top + r < tui_metric_column_count; r++) {
        /* a project's module in metres where U and V stand */
        const struct quantity *c = tui_shown_column(
            quantity_named(tui_metric_columns[s->top + r]), &s->options[0]);
        int y = 2 + r, dir = direction(s, c->name);
        tui_putf(y, 0, lw + 6, A_NORMAL, " %-14s %-4s %s", c->label,
                 c->unit, dir < 0 ? "min" : dir > 0 ? "max" : "");
        double first = quantity_value(c, &s->options[0]);
        for (int k = 0; k < s->n; k++) {
            double v = quantity_value(c, &s->options[k]);
            char value[48], diff[48], cell[100];
            tui_fmt_value(value, sizeof value, c, v);
            diff[0] = '\0';
            if (k > 0 && !c->yes_no && v != first &&
                has_difference(c->name) && isfinite(v) &&
                isfinite(first)) {
                char d[40];
                tui_fmt_value(d, sizeof d, c, v - first);
                /* a difference that rounds to nothing is no difference */
                if (strspn(d, "-0.,") != strlen(d))
                    snprintf(diff, sizeof diff, "%s%s", v > first ? "+" : "",
                             d);
            }
            /* better or worse, by the objective's direction */
            int verdict = diff[0] && dir != 0
                              ? ((v > first) == (dir > 0) ? 1 : -1) : 0;
            const char *mark = verdict > 0 ? g->better : verdict < 0
                                                             ? g->worse : "";
            if (s->differences && k > 0)
                snprintf(cell, sizeof cell, "%s%s%s", diff[0] ? diff : "=",
                         mark[0] ? " " : "", mark);
            else if (diff[0] && (int)(strlen(value) + strlen(diff) + 3 +
                                      (mark[0] ? 2 : 0)) <= cw - 1)
                snprintf(cell, sizeof cell, "%s (%s)%s%s", value, diff,
                         mark[0] ? " " : "", mark);
            else
                snprintf(cell, sizeof cell, "%s%s%s", value,
                         mark[0] ? " " : "", mark);
            attr_t attr = verdict > 0 ? tui_attr(ROLE_BETTER)
                          : verdict < 0 ? tui_attr(ROLE_WORSE) : A_NORMAL;
            /* a UTF-8 mark is one column of several bytes */
            int pad = cw - 1 + (int)(strlen(mark) > 1 ? strlen(mark) - 1 : 0);
            tui_putf(y, lw + 6 + k * cw, cw, attr, "%*s", pad, cell);
        }
    }
}

static enum tui_result compare_key(struct tui_screen *base,
                                   struct tui_app *app, int key)
{
    struct compare_screen *s = (struct compare_screen *)base;
    if (key >= '1' && key < '1' + s->n) {
        tui_push(app, screen_map_new(app, s->run,
                                     s->options[key - '1'].number));
        return RESULT_HANDLED;
    }
    switch (key) {
    case 'm': case KEY_F(8):
        s->maps = !s->maps;
        return RESULT_HANDLED;
    case 'd': case KEY_F(2):
        s->differences = !s->differences;
        return RESULT_HANDLED;
    default:
        break;
    }
    switch (tui_key_action(key)) {
    case ACTION_UP: if (s->top > 0) s->top--; return RESULT_HANDLED;
    case ACTION_DOWN: s->top++; return RESULT_HANDLED;
    case ACTION_TOP: s->top = 0; return RESULT_HANDLED;
    case ACTION_BOTTOM: s->top = tui_metric_column_count;
        return RESULT_HANDLED;
    default:
        return RESULT_UNHANDLED;
    }
}

static void compare_destroy(struct tui_screen *base)
{
    struct compare_screen *s = (struct compare_screen *)base;
    for (int k = 0; k < 4; k++)
        panelization_free(&s->panels[k]);
    free(s);
}

/* Reads (or evaluates and stores) the panels of every option; an option
 * whose panels cannot be had shows why instead of its map. The surface
 * is opened once, and only when an option has no stored panels. */
static void load_maps(struct compare_screen *s, struct tui_app *app)
{
    struct run_info run;
    struct facet_error err;
    if (store_run_get(app->store, s->run, &run, &err) != FACET_OK) {
        for (int k = 0; k < s->n; k++)
            snprintf(s->map_error[k], sizeof s->map_error[k], "%.*s",
                     (int)sizeof s->map_error[k] - 1, err.message);
        return;
    }
    if (store_run_is_project(&run)) {
        /* the panels of a building are the panel map's, surface by
         * surface */
        for (int k = 0; k < s->n; k++)
            snprintf(s->map_error[k], sizeof s->map_error[k],
                     "no map here for a building's options: Enter on the "
                     "options table opens an option's map, surface by "
                     "surface");
        return;
    }
    struct surface surface;
    int opened = 0, open_failed = 0;
    memset(&surface, 0, sizeof surface);
    for (int k = 0; k < s->n; k++) {
        int64_t number = s->options[k].number;
        int stored;
        int rc = store_panels_exist(app->store, s->run, number, &stored,
                                    &err);
        if (rc == FACET_OK && stored == 0 && !opened && !open_failed) {
            rc = study_open_surface(app->store, &run, &surface, &err);
            if (rc == FACET_OK)
                opened = 1;
            else
                open_failed = 1;
        }
        if (rc == FACET_OK && stored == 0 && !opened)
            rc = FACET_EINPUT;
        struct option_totals totals;
        if (rc == FACET_OK)
            rc = study_option_panels(app->store, &run,
                                     opened ? &surface : NULL, number,
                                     &s->panels[k], &totals, &err);
        if (rc == FACET_OK && s->panels[k].nu > 0 && s->panels[k].nv > 0)
            s->has_map[k] = 1;
        else
            snprintf(s->map_error[k], sizeof s->map_error[k], "no map: %.*s",
                     (int)sizeof s->map_error[k] - 9,
                     rc == FACET_OK ? "no panels" : err.message);
    }
    surface_close(&surface);
}

static const struct tui_screen_class compare_class = {
    "Compare", compare_help,
    {"Help", "Diffs", NULL, NULL, NULL, NULL, NULL, "Maps", NULL, "Quit"},
    compare_draw, compare_key, NULL, compare_destroy,
};

struct tui_screen *screen_compare_new(struct tui_app *app, int64_t run,
                                      const int64_t *options, int n)
{
    if (n < 2 || n > 4) {
        tui_error(app, "compare takes 2 to 4 options");
        return NULL;
    }
    struct compare_screen *s = calloc(1, sizeof *s);
    if (s == NULL) {
        tui_error(app, "out of memory");
        return NULL;
    }
    s->base.cls = &compare_class;
    s->run = run;
    s->n = n;
    for (int k = 0; k < n; k++) {
        struct facet_error err;
        if (store_option_get(app->store, run, options[k], &s->options[k],
                             &err) != FACET_OK) {
            tui_error(app, "%s", err.message);
            free(s);
            return NULL;
        }
    }
    struct run_info info;
    struct facet_error err;
    if (store_run_get(app->store, run, &info, &err) != FACET_OK ||
        objectives_parse(info.objectives, "the run's objectives",
                         s->objectives, &s->nobjectives, &err) != FACET_OK)
        s->nobjectives = 0;  /* no verdicts, the values still show */
    s->maps = 1;
    load_maps(s, app);
    s->width_m = s->height_m = 1;
    for (int k = n - 1; k >= 0; k--)
        if (s->has_map[k])
            map_surface_size(&s->panels[k], &s->width_m, &s->height_m);
    return &s->base;
}
