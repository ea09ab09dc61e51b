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
#include "store/study.h"

struct compare_screen {
    struct tui_screen base;
    int64_t run;
    struct option_row options[4];
    int n;
    int differences;   /* show the differences only */
    int top;
    int maps;          /* the panel maps show (m toggles) */
    struct panelization panels[4];
    int has_map[4];
    char map_error[4][600];
};

static const struct tui_key_help compare_help[] = {
    {"j/k, Up/Down", "scroll the metrics"},
    {"d, F2", "values with differences, or the differences alone"},
    {"m, F8", "show / hide the small panel maps under the metrics"},
    {"(maps)", "one character per panel (or block): F FP, S SP, D DP"},
    {"1-4", "panel map of the first, second, ... option"},
    {NULL, NULL},
};

/* The type a character shows for the block of panels [i0, i0 + f) x
 * [j0, j0 + f): the most common, ties going to the dearer type; -1 when
 * the block has no panel. */
static int block_type(const struct panelization *p, int i0, int j0, int f)
{
    int count[TYPE_COUNT] = {0};
    for (int j = j0; j < j0 + f && j < p->nv; j++)
        for (int i = i0; i < i0 + f && i < p->nu; i++) {
            int k = p->cell_panel[(size_t)j * (size_t)p->nu + (size_t)i];
            if (k >= 0)
                count[p->panels[k].type]++;
        }
    int best = -1;
    for (int t = 0; t < TYPE_COUNT; t++)
        if (count[t] > 0 && (best < 0 || count[t] >= count[best]))
            best = t;
    return best;
}

/* Rows the maps take: a caption and the tallest map, leaving the metrics
 * at least 6 rows. */
static int map_height(const struct compare_screen *s, int height)
{
    int tallest = 1;
    for (int k = 0; k < s->n; k++)
        if (s->has_map[k] && s->panels[k].nv > tallest)
            tallest = s->panels[k].nv;
    int room = height - 2 - 6;
    int rows = tallest + 2;
    return rows < room ? rows : room < 3 ? 0 : room;
}

static void draw_maps(struct compare_screen *s, struct tui_app *app, int y0,
                      int rows, int x0, int cw)
{
    tui_fill(y0, 0, x0 + s->n * cw, tui_attr(ROLE_HEADER));
    tui_put(y0, 0, x0, tui_attr(ROLE_HEADER), " panel maps");
    for (int t = 0; t < TYPE_COUNT; t++) {
        const char *name = panel_type_name((enum panel_type)t);
        char letter[2] = {name[0], 0};
        if (y0 + 1 + t < y0 + rows) {
            tui_put(y0 + 1 + t, 1, 1, tui_attr(tui_type_role(t)), letter);
            tui_putf(y0 + 1 + t, 2, x0 - 3, A_NORMAL, " %s", name);
        }
    }
    int map_h = rows - 1, map_w = cw - 2;
    if (map_w < 1 || map_h < 1)
        return;
    for (int k = 0; k < s->n; k++) {
        int x = x0 + k * cw + 1;
        if (!s->has_map[k]) {
            tui_put(y0 + 1, x, cw - 1, tui_attr(ROLE_ERROR),
                    s->map_error[k]);
            continue;
        }
        const struct panelization *p = &s->panels[k];
        int f = 1;
        while ((p->nu + f - 1) / f > map_w || (p->nv + f - 1) / f > map_h)
            f++;
        char caption[48];
        if (f > 1)
            snprintf(caption, sizeof caption, "%d x %d, 1:%d", p->nu, p->nv,
                     f);
        else
            snprintf(caption, sizeof caption, "%d x %d", p->nu, p->nv);
        tui_putf(y0, x - 1, cw, tui_attr(ROLE_HEADER), "%*s", cw - 1,
                 caption);
        int cols = (p->nu + f - 1) / f, lines = (p->nv + f - 1) / f;
        x = x0 + (k + 1) * cw - 1 - cols;  /* right-aligned, as the values */
        /* v's top row first, as the panel map reads */
        for (int r = 0; r < lines; r++) {
            int j0 = (lines - 1 - r) * f;
            for (int c = 0; c < cols; c++) {
                int t = block_type(p, c * f, j0, f);
                char text[8];
                if (t < 0)
                    tui_put(y0 + 1 + r, x + c, 1, tui_attr(ROLE_DIM),
                            app->glyphs->empty);
                else {
                    snprintf(text, sizeof text, "%c",
                             panel_type_name((enum panel_type)t)[0]);
                    tui_put(y0 + 1 + r, x + c, 1, tui_attr(tui_type_role(t)),
                            text);
                }
            }
        }
    }
}

static void compare_draw(struct tui_screen *base, struct tui_app *app,
                         int height, int width)
{
    struct compare_screen *s = (struct compare_screen *)base;
    (void)app;
    tui_fill(0, 0, width, tui_attr(ROLE_TITLE));
    tui_putf(0, 0, width, tui_attr(ROLE_TITLE),
             " Compare %d options of run %lld | %s", s->n, (long long)s->run,
             s->differences ? "differences to the first" : "values (and "
                                                          "difference)");
    int lw = 16, cw = (width - lw - 6) / s->n;
    if (cw > 26)
        cw = 26;
    tui_fill(1, 0, width, tui_attr(ROLE_HEADER));
    tui_put(1, 0, lw, tui_attr(ROLE_HEADER), " metric");
    for (int k = 0; k < s->n; k++) {
        char title[32];
        snprintf(title, sizeof title, "No. %lld",
                 (long long)s->options[k].number);
        tui_putf(1, lw + 6 + k * cw, cw, tui_attr(ROLE_HEADER), "%*s",
                 cw - 1, title);
    }
    int map_rows = s->maps ? map_height(s, height) : 0;
    int rows = height - 2 - map_rows;
    if (map_rows > 0)
        draw_maps(s, app, 2 + rows, map_rows, lw + 6, cw);
    if (s->top > tui_metric_column_count - rows)
        s->top = tui_metric_column_count - rows > 0
                     ? tui_metric_column_count - rows : 0;
    for (int r = 0; r < rows && s->top + r < tui_metric_column_count; r++) {
        const struct tui_column *c = &tui_metric_columns[s->top + r];
        int y = 2 + r;
        tui_putf(y, 0, lw + 6, A_NORMAL, " %-15s %-5s", c->title, c->unit);
        double first = store_option_value(&s->options[0], c->column);
        for (int k = 0; k < s->n; k++) {
            double v = store_option_value(&s->options[k], c->column);
            char value[48], diff[48], cell[100];
            tui_fmt_value(value, sizeof value, c, v);
            diff[0] = '\0';
            if (k > 0 && c->kind == COLUMN_NUMBER && v != first &&
                isfinite(v) && isfinite(first)) {
                char d[40];
                tui_fmt_number(d, sizeof d, v - first, c->decimals,
                               c->thousands);
                /* a difference that rounds to nothing is no difference */
                if (strspn(d, "-0.,") != strlen(d))
                    snprintf(diff, sizeof diff, "%s%s", v > first ? "+" : "",
                             d);
            }
            if (s->differences && k > 0)
                snprintf(cell, sizeof cell, "%s", diff[0] ? diff : "=");
            else if (diff[0] && (int)(strlen(value) + strlen(diff) + 3) < cw)
                snprintf(cell, sizeof cell, "%s (%s)", value, diff);
            else
                snprintf(cell, sizeof cell, "%s", value);
            attr_t attr = A_NORMAL;
            if (diff[0])
                attr = tui_attr(ROLE_PARETO);
            tui_putf(y, lw + 6 + k * cw, cw, attr, "%*s", cw - 1, cell);
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
            snprintf(s->map_error[k], sizeof s->map_error[k], "%s",
                     err.message);
        return;
    }
    struct surface surface;
    int opened = 0, open_failed = 0;
    memset(&surface, 0, sizeof surface);
    for (int k = 0; k < s->n; k++) {
        int64_t number = s->options[k].number;
        int stored = store_panels_exist(app->store, s->run, number, &err);
        int rc = stored < 0 ? FACET_EWORK : FACET_OK;
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
            snprintf(s->map_error[k], sizeof s->map_error[k], "no map: %s",
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
    s->maps = 1;
    load_maps(s, app);
    return &s->base;
}
