/*
 * screen_compare.c: Compare: two to four marked options side by side,
 * every metric, with the differences to the first (d shows the
 * differences alone when the values do not fit).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "app.h"
#include "format.h"
#include "keys.h"

struct compare_screen {
    struct tui_screen base;
    int64_t run;
    struct option_row options[4];
    int n;
    int differences;   /* show the differences only */
    int top;
};

static const struct tui_key_help compare_help[] = {
    {"j/k, Up/Down", "scroll the metrics"},
    {"d, F4", "values with differences, or the differences alone"},
    {"1-4", "panel map of the first, second, ... option"},
    {NULL, NULL},
};

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
    int rows = height - 2;
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
                snprintf(diff, sizeof diff, "%s%s", v > first ? "+" : "", d);
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
    case 'd': case KEY_F(4):
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
    free(base);
}

static const struct tui_screen_class compare_class = {
    "Compare", compare_help,
    {"Help", NULL, NULL, "Diff", NULL, NULL, NULL, NULL, NULL, "Quit"},
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
    return &s->base;
}
