/*
 * screen_map.c: Option detail / panel map: the UV grid of one option with
 * each panel coloured by type (FP/SP/DP), class, mould family, worst gap
 * or worst kink (c cycles), a legend
 * with counts and areas, and a cursor over the panels that shows one
 * panel's class, type, k1, k2, K, H, area, deviation and cost. The view
 * opens fitted to the screen: the whole grid at the surface's true aspect,
 * a character standing for the panels it covers (map_model.h); z and Z
 * zoom to one and two columns per panel, where the view pans with the
 * cursor, and back. Deviations are in mm, as the threshold. Panels come
 * from study_option_panels, which evaluates and stores them when
 * missing.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "app.h"
#include "format.h"
#include "keys.h"
#include "input.h"
#include "map_model.h"
#include "study/study.h"
#include "study/study_export.h"

struct map_screen {
    struct tui_screen base;
    struct run_info run;
    struct option_row option;
    struct panelization panels;
    struct option_totals totals;
    enum map_colour colour;  /* c cycles type, class, mould family, gap,
                                kink */
    double bound[MAP_LEVELS];  /* by gap or kink: the levels' bounds */
    int zoom;            /* 0: fit the whole grid; 1, 2: columns per
                            panel, one row per panel */
    double width_m, height_m;  /* the surface's extent (map_model.h) */
    int ci, cj;          /* cursor cell */
    int left, top;       /* first column (i) and row (from v's top) shown */
    int exporting;       /* the export line is open */
    struct tui_input export_to;
};

static const struct tui_key_help map_help[] = {
    {"h/j/k/l, arrows", "move the cursor from panel to panel"},
    {"PgUp/PgDn", "a page up / down"},
    {"g / G", "first / last panel"},
    {"0 / $", "start / end of the row"},
    {"c, F2", "colour by type (FP/SP/DP), by class, by mould family, by "
              "worst gap or by worst kink"},
    {"z", "zoom in: fit the screen, 1, then 2 columns per panel"},
    {"Z", "zoom out, back to the whole grid fitted to the screen"},
    {"e, F9", "export: PREFIX.obj (+ .mtl), PREFIX.csv and PREFIX.svg; "
              "end the prefix with ! to overwrite"},
    {NULL, NULL},
};

/* One letter per class, as the legend lists them. */
static const char class_letter[CLASS_COUNT] = {
    'v', 'x', 'c', 'r', 'f', 'R', 'o', 'O'};

/* The classes' names, short enough for the legend. */
static const char *const class_label[CLASS_COUNT] = {
    "convex feature", "saddle", "concave feature", "ruled convex", "flat",
    "ruled concave", "convex round", "concave round"};

static const struct panel *panel_at(const struct map_screen *s, int i, int j)
{
    if (i < 0 || j < 0 || i >= s->panels.nu || j >= s->panels.nv)
        return NULL;
    int k = s->panels.cell_panel[(size_t)j * (size_t)s->panels.nu +
                                 (size_t)i];
    return k >= 0 ? &s->panels.panels[k] : NULL;
}

/* The letter and colour of mould family k: eight colours and 36 letters
 * in turn, so that neighbours differ though families outnumber them. */
static void family_look(int k, char *letter, attr_t *attr)
{
    static const char digits[] = "0123456789abcdefghijklmnopqrstuvwxyz";
    *letter = digits[k % 36];
    *attr = tui_attr(ROLE_CLASS0 + k % CLASS_COUNT);
}

/* 1 when the map colours by gap or kink. */
static int by_joint(const struct map_screen *s)
{
    return s->colour == MAP_BY_GAP || s->colour == MAP_BY_KINK;
}

/* The run's limit on what the map colours by (mm or degrees), NaN for
 * none. */
static double joint_limit(const struct map_screen *s)
{
    return s->colour == MAP_BY_KINK ? s->run.max_kink_deg
                                    : s->run.max_gap_mm;
}

/* Sets the levels' bounds for the colouring (map_level_bounds). */
static void set_bounds(struct map_screen *s)
{
    if (!by_joint(s))
        return;
    double limit = joint_limit(s);
    map_level_bounds(isnan(limit) ? 0 : limit,
                     s->colour == MAP_BY_KINK ? s->totals.max_kink_deg
                                              : s->totals.max_gap_mm,
                     s->bound);
}

/* The levels of the gap or kink colouring, their bounds and panels. */
static void draw_joint_legend(struct map_screen *s, int y, int x, int width)
{
    const struct option_totals *t = &s->totals;
    int kink = s->colour == MAP_BY_KINK;
    const char *unit = kink ? "deg" : "mm";
    size_t count[MAP_LEVELS] = {0}, unknown = 0;
    for (size_t k = 0; k < s->panels.npanels; k++) {
        int level = map_level(map_panel_measure(&s->panels.panels[k],
                                                s->colour), s->bound);
        if (level < 0)
            unknown++;
        else
            count[level]++;
    }
    for (int k = 0; k < MAP_LEVELS; k++) {
        char letter[2] = {(char)('0' + k), 0}, range[40];
        if (k == MAP_LEVELS - 1)
            snprintf(range, sizeof range, "> %.2f %s", s->bound[k - 1], unit);
        else
            snprintf(range, sizeof range, "<= %.2f %s", s->bound[k], unit);
        tui_put(y, x + 1, 1, tui_attr(ROLE_SCALE0 + k), letter);
        tui_putf(y++, x + 2, width - 2, A_NORMAL, " %-18s %6zu", range,
                 count[k]);
    }
    if (unknown > 0)
        tui_putf(y++, x, width, A_NORMAL, "   not measured     %6zu",
                 unknown);
    double limit = joint_limit(s);
    if (isnan(limit))
        tui_putf(y++, x, width, A_NORMAL, "   (quarters of the worst; no "
                 "limit)");
    else
        tui_putf(y++, x, width, A_NORMAL, "   limit %g %s: %zu joints over",
                 limit, unit, kink ? t->kinks_over : t->gaps_over);
    tui_putf(y++, x, width, A_NORMAL, " max %.2f %s, mean %.2f %s",
             kink ? t->max_kink_deg : t->max_gap_mm, unit,
             kink ? t->mean_kink_deg : t->mean_gap_mm, unit);
    tui_putf(y++, x, width, A_NORMAL, " SP misfits %zu (%s)", t->sp_misfits,
             s->run.sp_fit ? "built DP" : "kept SP: by class");
}

static void draw_legend(struct map_screen *s, int y, int x, int width)
{
    const struct option_totals *t = &s->totals;
    tui_put(y++, x, width, tui_attr(ROLE_HEADER),
            s->colour == MAP_BY_CLASS ? " class              count       m^2"
            : s->colour == MAP_BY_MOULD ? " moulds           families  panels"
            : s->colour == MAP_BY_GAP ? " worst gap              panels"
            : s->colour == MAP_BY_KINK ? " worst kink             panels"
                                        : " type               count       m^2");
    if (by_joint(s)) {
        draw_joint_legend(s, y, x, width);
        return;
    }
    if (s->colour == MAP_BY_MOULD) {
        /* "-" for counts an older Facet's run did not store */
        char sp[24], dp[24];
        tui_fmt_number(sp, sizeof sp, totals_count(t->moulds_of[TYPE_SP]),
                       0, 0);
        tui_fmt_number(dp, sizeof dp, totals_count(t->moulds_of[TYPE_DP]),
                       0, 0);
        tui_putf(y++, x, width, A_NORMAL, "   %-15s %6s %9zu", "SP", sp,
                 t->count[TYPE_SP]);
        tui_putf(y++, x, width, A_NORMAL, "   %-15s %6s %9zu", "DP", dp,
                 t->count[TYPE_DP]);
        tui_putf(y++, x, width, A_NORMAL, "   %-15s %6s %9zu", "FP (none)",
                 "-", t->count[TYPE_FP]);
        if (t->largest_family == TOTALS_UNKNOWN ||
            t->singleton_families == TOTALS_UNKNOWN)
            tui_putf(y++, x, width, A_NORMAL,
                     "   families not stored (older run)");
        else
            tui_putf(y++, x, width, A_NORMAL,
                     "   largest family %zu, %zu of one", t->largest_family,
                     t->singleton_families);
        tui_putf(y++, x, width, A_NORMAL, "   (greedy: at most this many)");
    } else if (s->colour == MAP_BY_CLASS) {
        for (int c = 0; c < CLASS_COUNT; c++) {
            char letter[2] = {class_letter[c], 0};
            tui_put(y, x + 1, 1, tui_attr(ROLE_CLASS0 + c), letter);
            tui_putf(y++, x + 2, width - 2, A_NORMAL, " %-15s %6zu %9.1f",
                     class_label[c], t->class_count[c], t->class_area[c]);
        }
    } else {
        for (int k = 0; k < TYPE_COUNT; k++) {
            const char *name = panel_type_name((enum panel_type)k);
            char letter[2] = {name[0], 0};
            tui_put(y, x + 1, 1, tui_attr(tui_type_role(k)), letter);
            tui_putf(y++, x + 2, width - 2, A_NORMAL, " %-15s %6zu %9.1f",
                     name, t->count[k], t->area_of[k]);
        }
    }
    char cost[32];
    tui_fmt_number(cost, sizeof cost, t->cost, 0, 1);
    tui_putf(y++, x, width, A_NORMAL, "   %-15s %6zu %9.1f", "all", t->panels,
             t->area);
    y++;
    tui_putf(y++, x, width, A_NORMAL, " cost      %s USD", cost);
    tui_putf(y++, x, width, A_NORMAL, " planarity %.4f m (sum)",
             t->planarity);
    tui_putf(y++, x, width, A_NORMAL, " max dev.  %.2f mm",
             t->max_deviation * 1000);
    tui_putf(y++, x, width, A_NORMAL, " largest   %.2f m^2 (%s)",
             t->max_panel_area, t->feasible ? "feasible" : "infeasible");
}

static void map_draw(struct tui_screen *base, struct tui_app *app,
                     int height, int width)
{
    struct map_screen *s = (struct map_screen *)base;
    int nu = s->panels.nu, nv = s->panels.nv;
    tui_fill(0, 0, width, tui_attr(ROLE_TITLE));
    tui_putf(0, 0, width, tui_attr(ROLE_TITLE),
             " Panel map: option %lld of run %lld | grid %d x %d | t %.2f mm "
             "| by %s", (long long)s->option.number, (long long)s->run.id,
             nu, nv, s->option.threshold_mm,
             s->colour == MAP_BY_CLASS ? "class"
             : s->colour == MAP_BY_MOULD ? "mould family"
             : s->colour == MAP_BY_GAP ? "worst gap"
             : s->colour == MAP_BY_KINK ? "worst kink" : "type");
    int legend = width >= 70 ? 36 : 0;
    int map_w = width - legend - 2, map_h = height - 5;
    if (map_h < 1)
        map_h = 1;
    if (map_w < 1)
        map_w = 1;
    /* the picture: cols x lines characters; in the fit view each stands
     * for its share of the grid, zoomed in each is a panel's column */
    int cols, lines, zoom = s->zoom;
    if (zoom == 0) {
        map_fit_box(s->width_m, s->height_m, map_w, map_h, MAP_CELL_ASPECT,
                    &cols, &lines);
        s->left = s->top = 0;
    } else {
        cols = map_w / zoom < nu ? map_w / zoom : nu;
        lines = map_h < nv ? map_h : nv;
        if (cols < 1)
            cols = 1;
        /* pan so the cursor shows: rows count down from v's top */
        s->left = (int)table_model_scroll(s->left, s->ci, cols, nu);
        s->top = (int)table_model_scroll(s->top, nv - 1 - s->cj, lines, nv);
    }
    int cursor_c = -1, cursor_r = -1;
    if (zoom == 0)
        map_cell_of(&s->panels, cols, lines, s->ci, s->cj, &cursor_c,
                    &cursor_r);
    for (int r = 0; r < lines; r++) {
        for (int c = 0; c < cols; c++) {
            int value, here;
            if (zoom == 0) {
                value = map_cell_value(&s->panels, cols, lines, c, r,
                                       s->colour, s->bound);
                here = c == cursor_c && r == cursor_r;
            } else {
                int i = s->left + c, j = nv - 1 - (s->top + r);
                const struct panel *p = panel_at(s, i, j);
                value = p == NULL ? -1
                        : by_joint(s)
                            ? map_level(map_panel_measure(p, s->colour),
                                        s->bound)
                        : s->colour == MAP_BY_CLASS ? (int)p->class
                        : s->colour == MAP_BY_TYPE ? (int)p->type
                        : p->mould >= 0 ? p->mould : MAP_NO_MOULD;
                here = i == s->ci && j == s->cj;
            }
            char text[8];
            attr_t attr;
            if (value == MAP_NO_MOULD) {
                snprintf(text, sizeof text, "-");
                attr = tui_attr(tui_type_role(TYPE_FP));
            } else if (value < 0) {
                snprintf(text, sizeof text, "%s", app->glyphs->empty);
                attr = tui_attr(ROLE_DIM);
            } else if (by_joint(s)) {
                snprintf(text, sizeof text, "%c", '0' + value);
                attr = tui_attr(ROLE_SCALE0 + value);
            } else if (s->colour == MAP_BY_MOULD) {
                text[1] = '\0';
                family_look(value, &text[0], &attr);
            } else if (s->colour == MAP_BY_CLASS) {
                snprintf(text, sizeof text, "%c", class_letter[value]);
                attr = tui_attr(ROLE_CLASS0 + value);
            } else {
                snprintf(text, sizeof text, "%c",
                         panel_type_name((enum panel_type)value)[0]);
                attr = tui_attr(tui_type_role(value));
            }
            if (here)
                attr = A_REVERSE | A_BOLD;
            int x = 1 + c * (zoom ? zoom : 1);
            tui_put(1 + r, x, 1, attr, text);
            if (zoom == 2)
                tui_put(1 + r, x + 1, 1, attr, value < 0 ? " " : text);
        }
    }
    /* what the view shows of the grid */
    int shown_u = zoom ? cols : nu, shown_v = zoom ? lines : nv;
    if (legend)
        draw_legend(s, 1, width - legend, legend);
    /* the cursor's panel */
    int y = height - 4;
    tui_fill(y, 0, width, tui_attr(ROLE_DIM));
    char scale[48];
    if (zoom == 0)
        snprintf(scale, sizeof scale, "fit, %.1fx%.1f panels/char",
                 (double)nu / cols, (double)nv / lines);
    else
        snprintf(scale, sizeof scale, "%d char%s/panel", zoom,
                 zoom > 1 ? "s" : "");
    tui_putf(y, 0, width, tui_attr(ROLE_HEADER),
             " Panel (%d, %d) | rows %d of %d, cols %d of %d shown | %s ",
             s->ci, s->cj, shown_v, nv, shown_u, nu, scale);
    const struct panel *p = panel_at(s, s->ci, s->cj);
    if (p == NULL) {
        tui_put(y + 1, 1, width - 1, A_NORMAL,
                "no panel: the surface does not reach this cell");
        return;
    }
    char cost[32];
    tui_fmt_number(cost, sizeof cost, p->cost, 0, 1);
    tui_putf(y + 1, 0, width, A_NORMAL,
             " class %s  type %s  area %.3f m^2%s  cost %s USD",
             panel_class_name(p->class), panel_type_name(p->type), p->area,
             p->trimmed ? " (trimmed)" : "", cost);
    /* By mould the family takes the curvatures' line: 80 columns hold
     * one or the other. */
    if (by_joint(s)) {
        char fit[64] = "";
        if (p->misfit)
            snprintf(fit, sizeof fit, " | SP misfit: built DP");
        else if (p->built == TYPE_SP)
            snprintf(fit, sizeof fit, " | SP fit %.2f mm",
                     p->sp_deviation * 1000);
        tui_putf(y + 2, 0, width, A_NORMAL,
                 " worst gap %.2f mm  worst kink %.2f deg | deviation "
                 "%.2f mm%s", p->worst_gap_mm, p->worst_kink_deg,
                 p->deviation * 1000, fit);
    } else if (s->colour == MAP_BY_MOULD && p->mould >= 0)
        tui_putf(y + 2, 0, width, A_NORMAL,
                 " mould family %d (%zu panels) | deviation %.2f mm",
                 p->mould, map_family_size(&s->panels, p->mould),
                 p->deviation * 1000);
    else if (s->colour == MAP_BY_MOULD && p->type != TYPE_FP)
        /* a curved panel of a run an older Facet stored (NULL) */
        tui_putf(y + 2, 0, width, A_NORMAL,
                 " mould family not stored (an older Facet's run) | "
                 "deviation %.2f mm", p->deviation * 1000);
    else if (s->colour == MAP_BY_MOULD)
        tui_putf(y + 2, 0, width, A_NORMAL,
                 " no mould: an FP panel | deviation %.2f mm",
                 p->deviation * 1000);
    else
        tui_putf(y + 2, 0, width, A_NORMAL,
                 " k1 %.4g  k2 %.4g 1/m  K %.4g 1/m^2  H %.4g 1/m  "
                 "deviation %.2f mm", p->k1, p->k2, p->K, p->H,
                 p->deviation * 1000);
}

/* Moves the cursor by (di, dj), clamped to the grid. */
static void move_cursor(struct map_screen *s, int di, int dj)
{
    s->ci += di;
    s->cj += dj;
    if (s->ci < 0)
        s->ci = 0;
    if (s->ci >= s->panels.nu)
        s->ci = s->panels.nu - 1;
    if (s->cj < 0)
        s->cj = 0;
    if (s->cj >= s->panels.nv)
        s->cj = s->panels.nv - 1;
}

/* Splits "PREFIX" or "PREFIX!" (overwrite) into the export's paths. */
static void export_option(struct map_screen *s, struct tui_app *app)
{
    char prefix[TUI_INPUT_MAX];
    snprintf(prefix, sizeof prefix, "%s", s->export_to.text);
    size_t n = strlen(prefix);
    int force = n > 0 && prefix[n - 1] == '!';
    if (force)
        prefix[--n] = '\0';
    if (n == 0) {
        tui_error(app, "export: give a file name prefix");
        return;
    }
    char obj[TUI_INPUT_MAX + 8], csv[TUI_INPUT_MAX + 8];
    char svg[TUI_INPUT_MAX + 8];
    snprintf(obj, sizeof obj, "%s.obj", prefix);
    snprintf(csv, sizeof csv, "%s.csv", prefix);
    snprintf(svg, sizeof svg, "%s.svg", prefix);
    struct export_request request;
    memset(&request, 0, sizeof request);
    request.obj = obj;
    request.csv = csv;
    request.svg = svg;
    request.force = force;
    svg_map_defaults(&request.map);
    /* The SVG map knows types and classes; by mould it is drawn by type
     * (the families are in the OBJ's groups and the CSV's column). */
    request.map.colour_by = s->colour == MAP_BY_CLASS ? SVG_MAP_BY_CLASS
                                                      : SVG_MAP_BY_TYPE;
    struct facet_error err;
    if (study_export(app->store, s->run.id, s->option.number, &request,
                     &err) != FACET_OK) {
        tui_error(app, "export: %s", err.message);
        return;
    }
    tui_status(app, "wrote %s (+ .mtl), %s, %s", obj, csv, svg);
}

static enum tui_result export_key(struct map_screen *s, struct tui_app *app,
                                  int key)
{
    enum tui_input_result r = tui_input_key(&s->export_to, key);
    if (r == INPUT_EDITING || r == INPUT_IGNORED)
        return RESULT_HANDLED;
    s->exporting = 0;
    tui_prompt(app, NULL, NULL);
    if (r == INPUT_DONE)
        export_option(s, app);
    return RESULT_HANDLED;
}

static enum tui_result map_key(struct tui_screen *base, struct tui_app *app,
                               int key)
{
    struct map_screen *s = (struct map_screen *)base;
    int page = LINES - 7 > 1 ? LINES - 7 : 1;
    if (s->exporting)
        return export_key(s, app, key);
    switch (key) {
    case 'e': case KEY_F(9): {
        char prefix[128];
        snprintf(prefix, sizeof prefix, "facet-run%lld-option%lld",
                 (long long)s->run.id, (long long)s->option.number);
        tui_input_set(&s->export_to, prefix);
        s->exporting = 1;
        tui_prompt(app, "Export to (prefix):", &s->export_to);
        return RESULT_HANDLED;
    }
    case 'c': case KEY_F(2):
        s->colour = (enum map_colour)((s->colour + 1) % MAP_COLOURS);
        set_bounds(s);
        return RESULT_HANDLED;
    case 'z':
        if (s->zoom == 2)
            tui_status(app, "zoom: 2 chars a panel is the closest; Z "
                       "zooms out");
        else
            s->zoom++;
        return RESULT_HANDLED;
    case 'Z':
        if (s->zoom == 0)
            tui_status(app, "zoom: the whole grid shows already (fit); z "
                       "zooms in");
        else
            s->zoom--;
        return RESULT_HANDLED;
    case '0':
        s->ci = 0;
        return RESULT_HANDLED;
    case '$':
        s->ci = s->panels.nu - 1;
        return RESULT_HANDLED;
    default:
        break;
    }
    (void)app;
    switch (tui_key_action(key)) {
    case ACTION_LEFT: move_cursor(s, -1, 0); break;
    case ACTION_RIGHT: move_cursor(s, 1, 0); break;
    case ACTION_UP: move_cursor(s, 0, 1); break;
    case ACTION_DOWN: move_cursor(s, 0, -1); break;
    case ACTION_PAGE_UP: move_cursor(s, 0, page); break;
    case ACTION_PAGE_DOWN: move_cursor(s, 0, -page); break;
    case ACTION_TOP:
        s->ci = 0;
        s->cj = s->panels.nv - 1;
        break;
    case ACTION_BOTTOM:
        s->ci = s->panels.nu - 1;
        s->cj = 0;
        break;
    default:
        return RESULT_UNHANDLED;
    }
    return RESULT_HANDLED;
}

static void map_destroy(struct tui_screen *base)
{
    struct map_screen *s = (struct map_screen *)base;
    panelization_free(&s->panels);
    free(s);
}

static const struct tui_screen_class map_class = {
    "Panel map", map_help,
    {"Help", "Colour", NULL, NULL, NULL, NULL, NULL, NULL, "Export",
     "Quit"},
    map_draw, map_key, NULL, map_destroy,
};

struct tui_screen *screen_map_new(struct tui_app *app, int64_t run,
                                  int64_t option)
{
    struct map_screen *s = calloc(1, sizeof *s);
    struct facet_error err;
    if (s == NULL) {
        tui_error(app, "out of memory");
        return NULL;
    }
    s->base.cls = &map_class;
    int rc = store_run_get(app->store, run, &s->run, &err);
    if (rc == FACET_OK)
        rc = store_option_get(app->store, run, option, &s->option, &err);
    if (rc == FACET_OK)
        rc = study_option_panels(app->store, &s->run, NULL, option,
                                 &s->panels, &s->totals, &err);
    if (rc == FACET_OK && (s->panels.nu < 1 || s->panels.nv < 1))
        rc = facet_error_set(&err, FACET_EWORK, "option %lld has no panels",
                             (long long)option);
    if (rc != FACET_OK) {
        tui_error(app, "panel map: %s", err.message);
        map_destroy(&s->base);
        return NULL;
    }
    s->cj = s->panels.nv - 1;  /* top left, as the map reads */
    map_surface_size(&s->panels, &s->width_m, &s->height_m);
    return &s->base;
}
