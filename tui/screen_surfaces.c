/*
 * screen_surfaces.c: a project option's surfaces (issue 17), one row
 * each as the run stored it (option_surfaces): grid, panels, FP/SP/DP,
 * cost, moulds started and used, largest deviation, gap and kink
 * (surface_rows.h), scrolled with the selection; the building's totals
 * underneath. Enter opens the panel map at the selected surface. A
 * single surface's option has no such rows: the options table says so
 * instead of opening this screen.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "app.h"
#include "core/base/units.h"
#include "format.h"
#include "keys.h"
#include "surface_rows.h"

struct surfaces_screen {
    struct tui_screen base;
    struct run_info run;
    struct option_row option;
    struct surface_row *surfaces;      /* the run's, in order */
    struct option_surface_row *rows;   /* the option's, in the same order */
    size_t n;
    int selected, top;
    int shown;                         /* rows shown at the last draw */
};

static const struct tui_key_help surfaces_help[] = {
    {"j/k, Up/Down", "select a surface"},
    {"PgUp/PgDn, g/G", "a page up / down, first / last surface"},
    {"Enter, m, F8", "panel map of the option at the selected surface "
                     "(] and [ page on through the building)"},
    {"(columns)", "grid nu x nv; panels and FP/SP/DP; cost (USD); moulds "
                  "started here / used here; largest deviation (mm), gap "
                  "(mm) and kink (deg) on the surface"},
    {NULL, NULL},
};

static void surfaces_draw(struct tui_screen *base, struct tui_app *app,
                          int height, int width)
{
    struct surfaces_screen *s = (struct surfaces_screen *)base;
    (void)app;
    const struct option_totals *t = &s->option.totals;
    tui_fill(0, 0, width, tui_attr(ROLE_TITLE));
    tui_putf(0, 0, width, tui_attr(ROLE_TITLE),
             " Surfaces of option %lld of run %lld | module %.2f x %.2f m "
             "| t %.2f mm", (long long)s->option.number,
             (long long)s->run.id, s->option.module_w, s->option.module_h,
             s->option.threshold_mm);
    tui_putf(1, 0, width, A_NORMAL, " surface %d of %zu", s->selected + 1,
             s->n);
    char names[160], units[160], line[160];
    surface_rows_header(names, units, sizeof names);
    tui_fill(2, 0, width, tui_attr(ROLE_HEADER));
    tui_put(2, 0, width, tui_attr(ROLE_HEADER), names);
    tui_fill(3, 0, width, tui_attr(ROLE_HEADER));
    tui_put(3, 0, width, tui_attr(ROLE_HEADER), units);
    s->shown = height - 6;
    if (s->shown < 1)
        s->shown = 1;
    s->top = (int)table_model_scroll(s->top, s->selected, s->shown,
                                     (int64_t)s->n);
    for (int r = 0; r < s->shown && (size_t)(s->top + r) < s->n; r++) {
        size_t k = (size_t)(s->top + r);
        surface_rows_line(line, sizeof line, s->surfaces[k].name,
                          &s->rows[k]);
        attr_t attr = (int)k == s->selected ? tui_attr(ROLE_SELECTION)
                                            : A_NORMAL;
        if ((int)k == s->selected)
            tui_fill(4 + r, 0, width, attr);
        tui_put(4 + r, 0, width, attr, line);
    }
    /* the building: what the surfaces add up to (moulds are shared) */
    char cost[32];
    tui_fmt_number(cost, sizeof cost, t->cost, 0, 1);
    tui_fill(height - 2, 0, width, tui_attr(ROLE_DIM));
    tui_putf(height - 2, 0, width, tui_attr(ROLE_HEADER),
             " building: %zu panels (FP %zu, SP %zu, DP %zu), %s USD, %zu "
             "moulds", t->panels, t->count[TYPE_FP], t->count[TYPE_SP],
             t->count[TYPE_DP], cost, t->moulds);
    tui_putf(height - 1, 0, width, A_NORMAL,
             " max deviation %.2f mm, gap %.2f mm, kink %.2f deg; %s",
             t->max_deviation * 1000, units_mm(t->max_gap),
             units_deg(t->max_kink),
             t->feasible ? "feasible" : "infeasible");
}

static enum tui_result surfaces_key(struct tui_screen *base,
                                    struct tui_app *app, int key)
{
    struct surfaces_screen *s = (struct surfaces_screen *)base;
    int last = (int)s->n - 1, page = s->shown > 1 ? s->shown - 1 : 1;
    switch (key) {
    case 'm': case KEY_F(8): case '\r': case '\n': case KEY_ENTER:
        tui_push(app, screen_map_at(app, s->run.id, s->option.number,
                                    s->selected));
        return RESULT_HANDLED;
    default:
        break;
    }
    switch (tui_key_action(key)) {
    case ACTION_UP: s->selected--; break;
    case ACTION_DOWN: s->selected++; break;
    case ACTION_PAGE_UP: s->selected -= page; break;
    case ACTION_PAGE_DOWN: s->selected += page; break;
    case ACTION_TOP: s->selected = 0; break;
    case ACTION_BOTTOM: s->selected = last; break;
    default:
        return RESULT_UNHANDLED;
    }
    if (s->selected > last)
        s->selected = last;
    if (s->selected < 0)
        s->selected = 0;
    return RESULT_HANDLED;
}

static void surfaces_destroy(struct tui_screen *base)
{
    struct surfaces_screen *s = (struct surfaces_screen *)base;
    free(s->surfaces);
    free(s->rows);
    free(s);
}

static const struct tui_screen_class surfaces_class = {
    "Surfaces", surfaces_help,
    {"Help", NULL, NULL, NULL, NULL, NULL, NULL, "Map", NULL, "Quit"},
    surfaces_draw, surfaces_key, NULL, surfaces_destroy,
};

struct tui_screen *screen_surfaces_new(struct tui_app *app, int64_t run,
                                       int64_t option)
{
    struct surfaces_screen *s = calloc(1, sizeof *s);
    if (s == NULL) {
        tui_error(app, "out of memory");
        return NULL;
    }
    s->base.cls = &surfaces_class;
    struct facet_error err;
    size_t nsurfaces = 0;
    int rc = store_run_get(app->store, run, &s->run, &err);
    if (rc == FACET_OK)
        rc = store_option_get(app->store, run, option, &s->option, &err);
    if (rc == FACET_OK)
        rc = store_surfaces_get(app->store, run, &s->surfaces, &nsurfaces,
                                &err);
    if (rc == FACET_OK)
        rc = store_option_surfaces_get(app->store, run, option, &s->rows,
                                       &s->n, &err);
    if (rc == FACET_OK && s->n == 0)
        rc = facet_error_set(&err, FACET_EINPUT,
                             "option %lld of run %lld is a single "
                             "surface's: no surfaces to list",
                             (long long)option, (long long)run);
    if (rc == FACET_OK && s->n != nsurfaces)
        rc = facet_error_set(&err, FACET_EINPUT,
                             "option %lld has %zu surface rows, run %lld "
                             "%zu surfaces", (long long)option, s->n,
                             (long long)run, nsurfaces);
    if (rc != FACET_OK) {
        tui_error(app, "surfaces: %s", err.message);
        surfaces_destroy(&s->base);
        return NULL;
    }
    return &s->base;
}
