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
 * missing. A project run's option (a building of many surfaces) shows
 * one surface at a time, ] and [ paging through them: its panels are not
 * stored, so the option is evaluated again over the run's project
 * (study_project_view.h), which app->project prepares in a thread once
 * for every map of the run while the map shows the stage. By gap or kink
 * a building's map marks its seam joints too (issue 31): the panels of
 * the surface at a seam with another, '=' coloured by the level of the
 * seam joint's gap or kink added to the crease, '!' at the highest
 * (over the limit), from the option's seam joints (project_option_seam_
 * joints, as the export's seams schedule).
 */
#include <assert.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "app.h"
#include "core/base/units.h"
#include "format.h"
#include "keys.h"
#include "input.h"
#include "map_model.h"
#include "study/study.h"
#include "study/study_export.h"
#include "project_load.h"

struct map_screen {
    struct tui_screen base;
    struct run_info run;
    struct option_row option;
    /* What the map shows: a single surface's own panels and the option's
     * totals, or one surface of a project option's building. */
    const struct panelization *panels;
    const struct option_totals *totals;
    struct panelization own;       /* a single surface's panels */
    struct option_totals own_totals;
    /* A project run's option (issue 17): its building evaluated over the
     * project app->project holds, surface by surface ([ and ]). */
    int project;
    int loading;                   /* app->project is being prepared */
    char failed[sizeof ((struct facet_error *)0)->message];  /* why no map */
    struct project_option building;
    struct surface_row *surfaces;  /* the run's, as stored (names) */
    size_t nsurfaces;
    int surface;                   /* shown, 0-based */
    int seams_found;               /* the run found its seams (a weld) */
    struct building_seam_joint *seam_joints;  /* the option's, owned */
    size_t nseam_joints;
    struct map_seams seams;        /* the shown surface's (map_model.h) */
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
              "worst gap or by worst kink; by gap or kink a building's "
              "seam joints show as = (! over the limit)"},
    {"z", "zoom in: fit the screen, 1, then 2 columns per panel"},
    {"Z", "zoom out, back to the whole grid fitted to the screen"},
    {"e, F9", "export: PREFIX.csv, .xlsx, .dxf, .ifc, and of a single "
              "surface .obj (+ .mtl) and .svg; a building's every "
              "surface's panels; end the prefix with ! to overwrite"},
    {"] / [", "a project's option: the next / previous surface of the "
              "building"},
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
    if (i < 0 || j < 0 || i >= s->panels->nu || j >= s->panels->nv)
        return NULL;
    int k = s->panels->cell_panel[(size_t)j * (size_t)s->panels->nu +
                                 (size_t)i];
    return k >= 0 ? &s->panels->panels[k] : NULL;
}

/* The letters the mould map draws families with, in turn. */
static const char family_letters[] = "0123456789abcdefghijklmnopqrstuvwxyz";
enum { FAMILY_LETTERS = sizeof family_letters - 1 };

/* The letter and colour of mould family k: eight colours and 36 letters
 * in turn, so that neighbours differ though families outnumber them. */
static void family_look(int k, char *letter, attr_t *attr)
{
    *letter = family_letters[k % FAMILY_LETTERS];
    *attr = tui_attr(ROLE_CLASS0 + k % CLASS_COUNT);
}

/* The panels of mould family k: of the whole building for a project's
 * option (its families are the building's), else of the surface. */
static size_t family_size(const struct map_screen *s, int k)
{
    if (s->project && k >= 0 && (size_t)k < s->building.families.nfamilies)
        return s->building.families.size[k];
    return map_family_size(s->panels, k);
}

/* 1 when the map colours by gap, kink or corner move, in levels. */
static int by_joint(const struct map_screen *s)
{
    return map_by_level(s->colour);
}

/* The run's limit on what the map colours by (mm or degrees), NaN for
 * none. */
static double joint_limit(const struct map_screen *s)
{
    /* A corner's move has no limit: its distance to the surface has
     * (the budget), which the legend states. */
    return s->colour == MAP_BY_MOVE ? NAN
           : s->colour == MAP_BY_KINK ? s->run.max_kink_deg
                                      : s->run.max_gap_mm;
}

/* The farthest a corner of the option moved (mm), NaN when none did. */
static double largest_move(const struct map_screen *s)
{
    double most = NAN;
    for (size_t k = 0; s->panels->corner_moved != NULL &&
                       k < s->panels->npanels; k++)
        if (!isnan(s->panels->corner_moved[k]))
            most = isnan(most) ? s->panels->corner_moved[k]
                               : fmax(most, s->panels->corner_moved[k]);
    return 1000 * most;
}

/* The shown surface's seam joints, NULL when the run found no seams. */
static const struct map_seams *seam_map(const struct map_screen *s)
{
    return s->project && s->seams_found ? &s->seams : NULL;
}

/* Sets the levels' bounds for the colouring (map_level_bounds). */
static void set_bounds(struct map_screen *s)
{
    if (!by_joint(s))
        return;
    double limit = joint_limit(s);
    double largest = s->colour == MAP_BY_MOVE ? largest_move(s)
                     : s->colour == MAP_BY_KINK
                         ? units_deg(s->totals->max_kink)
                         : units_mm(s->totals->max_gap);
    /* without a limit the quarters are of the worst joint shown, a seam
     * joint's too */
    double seam = map_seams_largest(seam_map(s), s->colour);
    if (!isnan(seam) && !(seam <= largest))
        largest = seam;
    map_level_bounds(isnan(limit) ? 0 : limit, largest, s->bound);
}

/* A project option's seams, the building's (the legend's other lines are
 * the surface's): how many, and the largest gap, or kink added to the
 * crease, at them, in the quantity's own unit. Nothing for a single
 * surface, or a run that found none (an older Facet's). Then what the
 * seam marks on the map mean. */
static void draw_seams_line(const struct map_screen *s, int y, int x,
                            int width, int kink)
{
    const struct option_totals *b = &s->building.totals;
    if (!s->project || b->seams == TOTALS_UNKNOWN)
        return;
    if (seam_map(s) != NULL) {
        double limit = joint_limit(s);
        char mark[2] = {map_seam_glyph(0), 0};
        tui_put(y + 1, x + 1, 1, tui_attr(ROLE_SCALE0) | A_BOLD, mark);
        tui_putf(y + 1, x + 2, width - 2, A_NORMAL,
                 " seam joint: %s, %zu here",
                 kink ? "kink added" : "its gap", s->seams.joints);
        mark[0] = map_seam_glyph(MAP_LEVELS - 1);
        tui_put(y + 2, x + 1, 1, tui_attr(ROLE_SCALE0 + MAP_LEVELS - 1) |
                A_BOLD, mark);
        tui_putf(y + 2, x + 2, width - 2, A_NORMAL, " %s",
                 isnan(limit) ? "one in the top quarter"
                              : "a seam joint over the limit");
    }
    const struct quantity *q =
        quantity_named(kink ? "seam_max_kink" : "seam_max_gap");
    double value = quantity_of_totals(q, b);
    if (isnan(value)) {
        tui_putf(y, x, width, A_NORMAL, " building: %zu seams, no joint",
                 b->seams);
        return;
    }
    char text[48];
    tui_fmt_value(text, sizeof text, q, value);
    tui_putf(y, x, width, A_NORMAL, " building: %zu seams, %s%s %s",
             b->seams, kink ? "+" : "", text, q->unit);
}

static void draw_joint_legend(struct map_screen *s, int y, int x, int width)
{
    const struct option_totals *t = s->totals;
    int kink = s->colour == MAP_BY_KINK;
    const char *unit = kink ? "deg" : "mm";
    size_t count[MAP_LEVELS] = {0}, unknown = 0;
    for (size_t k = 0; k < s->panels->npanels; k++) {
        int level = map_level(map_panel_measure(s->panels,
                                                &s->panels->panels[k],
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
        tui_putf(y++, x, width, A_NORMAL, "   %-16s %6zu",
                 s->colour == MAP_BY_MOVE ? "not moved" : "not measured",
                 unknown);
    if (s->colour == MAP_BY_MOVE) {
        tui_putf(y++, x, width, A_NORMAL, "   (quarters of the farthest)");
        tui_putf(y++, x, width, A_NORMAL, " moved at most %.2f mm",
                 largest_move(s));
        tui_putf(y++, x, width, A_NORMAL, " off the surface %.2f mm",
                 t->closeness_reached * 1000);
        tui_putf(y++, x, width, A_NORMAL, " budget %g mm: %s",
                 s->run.planarize_closeness_mm,
                 t->planar_over == 0 ? "planar within it"
                                     : "INFEASIBLE, not planar");
        return;
    }
    double limit = joint_limit(s);
    if (isnan(limit))
        tui_putf(y++, x, width, A_NORMAL, "   (quarters of the worst; no "
                 "limit)");
    else
        tui_putf(y++, x, width, A_NORMAL, "   limit %g %s: %zu joints over",
                 limit, unit, kink ? t->kinks_over : t->gaps_over);
    tui_putf(y++, x, width, A_NORMAL, " max %.2f %s, mean %.2f %s",
             kink ? units_deg(t->max_kink) : units_mm(t->max_gap), unit,
             kink ? units_deg(t->mean_kink) : units_mm(t->mean_gap), unit);
    tui_putf(y++, x, width, A_NORMAL, " SP misfits %zu (%s)", t->sp_misfits,
             s->run.sp_fit ? "built DP" : "kept SP: by class");
    draw_seams_line(s, y, x, width, kink);
}

static void draw_legend(struct map_screen *s, int y, int x, int width)
{
    const struct option_totals *t = s->totals;
    tui_put(y++, x, width, tui_attr(ROLE_HEADER),
            s->colour == MAP_BY_CLASS ? " class              count       m^2"
            : s->colour == MAP_BY_MOULD ? " moulds           families  panels"
            : s->colour == MAP_BY_GAP ? " worst gap              panels"
            : s->colour == MAP_BY_KINK ? " worst kink             panels"
            : s->colour == MAP_BY_MOVE ? " corner move            panels"
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
        if (s->project)
            tui_putf(y++, x, width, A_NORMAL,
                     "   started here; %zu used here",
                     s->building.surfaces[s->surface].moulds_used);
        tui_putf(y++, x, width, A_NORMAL, "   (greedy: at most this many)");
        /* More families than letters: one letter stands for several, and
         * only the cursor tells them apart. */
        size_t families = s->project
            ? s->building.families.nfamilies
            : (t->moulds_of[TYPE_SP] == TOTALS_UNKNOWN ? 0
                                                       : t->moulds_of[TYPE_SP]) +
              (t->moulds_of[TYPE_DP] == TOTALS_UNKNOWN ? 0
                                                       : t->moulds_of[TYPE_DP]);
        if (families > FAMILY_LETTERS) {
            tui_putf(y++, x, width, A_NORMAL,
                     "   %d letters for %zu families:", FAMILY_LETTERS,
                     families);
            tui_putf(y++, x, width, A_NORMAL,
                     "   each repeats; the cursor names");
            tui_putf(y++, x, width, A_NORMAL, "   a panel's family");
        }
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

static const char *colour_name(enum map_colour colour)
{
    return colour == MAP_BY_CLASS ? "class"
           : colour == MAP_BY_MOULD ? "mould family"
           : colour == MAP_BY_GAP ? "worst gap"
           : colour == MAP_BY_KINK ? "worst kink"
           : colour == MAP_BY_MOVE ? "corner move" : "type";
}

/* A project option's map before its building shows: the stage of the
 * preparing and its seconds, or why it failed. */
static void draw_waiting(struct map_screen *s, struct tui_app *app,
                         int width)
{
    tui_fill(0, 0, width, tui_attr(ROLE_TITLE));
    tui_putf(0, 0, width, tui_attr(ROLE_TITLE),
             " Panel map: option %lld of run %lld | a project of several "
             "surfaces", (long long)s->option.number, (long long)s->run.id);
    if (!s->loading) {
        tui_put(2, 1, width - 1, tui_attr(ROLE_ERROR), "no map:");
        tui_put(3, 1, width - 1, A_NORMAL, s->failed);
        return;
    }
    struct tui_project_load_state st;
    if (app->project == NULL)
        return;  /* the next tick starts it again */
    tui_project_load_state(app->project, &st);
    char seconds[32];
    tui_fmt_elapsed(seconds, sizeof seconds, st.seconds);
    tui_putf(2, 1, width - 1, A_NORMAL, "Preparing run %lld's project once "
             "for the maps of its options:", (long long)s->run.id);
    tui_putf(3, 1, width - 1, tui_attr(ROLE_STATUS), "%s ... %s",
             st.stage, seconds);
    tui_put(5, 1, width - 1, tui_attr(ROLE_DIM),
            "q goes back; the project is kept while this run is browsed");
}

static void map_draw(struct tui_screen *base, struct tui_app *app,
                     int height, int width)
{
    struct map_screen *s = (struct map_screen *)base;
    if (s->project && s->building.nsurfaces == 0) {
        draw_waiting(s, app, width);
        return;
    }
    int nu = s->panels->nu, nv = s->panels->nv;
    tui_fill(0, 0, width, tui_attr(ROLE_TITLE));
    /* whole fields dropped from the end where the line is short: a cut
     * would take "mm" off the threshold and leave it reading metres */
    char head[128], title[512], t[64], by[64], line[1024];
    snprintf(t, sizeof t, "t %.2f mm", s->option.threshold_mm);
    snprintf(by, sizeof by, "by %s", colour_name(s->colour));
    if (s->project) {
        map_surface_title(title, sizeof title, s->surface,
                          (int)s->building.nsurfaces,
                          s->surfaces[s->surface].name, nu, nv);
        /* "Map" alone: at 80 columns the surface's name needs the room */
        snprintf(head, sizeof head, " Map: option %lld of run %lld",
                 (long long)s->option.number, (long long)s->run.id);
    } else {
        snprintf(title, sizeof title, "grid %d x %d", nu, nv);
        snprintf(head, sizeof head, " Panel map: option %lld of run %lld",
                 (long long)s->option.number, (long long)s->run.id);
    }
    const char *fields[4] = {head, title, t, by};
    tui_fmt_fields(line, sizeof line, width, fields, 4);
    tui_put(0, 0, width, tui_attr(ROLE_TITLE), line);
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
        map_cell_of(s->panels, cols, lines, s->ci, s->cj, &cursor_c,
                    &cursor_r);
    for (int r = 0; r < lines; r++) {
        for (int c = 0; c < cols; c++) {
            int value, here, seam;
            if (zoom == 0) {
                value = map_cell_value(s->panels, cols, lines, c, r,
                                       s->colour, s->bound);
                seam = map_seam_cell_level(s->panels, seam_map(s), cols,
                                           lines, c, r, s->colour,
                                           s->bound);
                here = c == cursor_c && r == cursor_r;
            } else {
                int i = s->left + c, j = nv - 1 - (s->top + r);
                const struct panel *p = panel_at(s, i, j);
                value = p == NULL ? -1
                        : by_joint(s)
                            ? map_level(map_panel_measure(s->panels, p,
                                                          s->colour),
                                        s->bound)
                        : s->colour == MAP_BY_CLASS ? (int)p->class
                        : s->colour == MAP_BY_TYPE ? (int)p->type
                        : p->mould >= 0 ? p->mould : MAP_NO_MOULD;
                seam = p == NULL ? -1
                       : map_level(map_seam_measure(
                                       seam_map(s),
                                       (size_t)(p - s->panels->panels),
                                       s->colour),
                                   s->bound);
                here = i == s->ci && j == s->cj;
            }
            char text[8];
            attr_t attr;
            if (seam >= 0) {
                /* a seam joint: its own level, over the panel's */
                snprintf(text, sizeof text, "%c", map_seam_glyph(seam));
                attr = tui_attr(ROLE_SCALE0 + seam) | A_BOLD;
            } else if (value == MAP_NO_MOULD) {
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
                tui_put(1 + r, x + 1, 1, attr,
                        value < 0 && seam < 0 ? " " : text);
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
        size_t k = (size_t)(p - s->panels->panels);
        double seam_gap = map_seam_measure(seam_map(s), k, MAP_BY_GAP);
        if (!isnan(seam_gap))
            /* a seam panel: its seam joints' worst in the deviation's
             * place, which the classes' line keeps */
            tui_putf(y + 2, 0, width, A_NORMAL,
                     " worst gap %.2f mm  worst kink %.2f deg | seam gap "
                     "%.2f mm, kink +%.2f deg", units_mm(p->worst_gap),
                     units_deg(p->worst_kink), seam_gap,
                     map_seam_measure(seam_map(s), k, MAP_BY_KINK));
        else
            tui_putf(y + 2, 0, width, A_NORMAL,
                     " worst gap %.2f mm  worst kink %.2f deg | deviation "
                     "%.2f mm%s", units_mm(p->worst_gap),
                     units_deg(p->worst_kink), p->deviation * 1000, fit);
    } else if (s->colour == MAP_BY_MOULD && p->mould >= 0)
        tui_putf(y + 2, 0, width, A_NORMAL,
                 " mould family %d (%zu panels%s) | deviation %.2f mm",
                 p->mould, family_size(s, p->mould),
                 s->project ? " in the building" : "", p->deviation * 1000);
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

/* Shows surface k of the building, its cursor at the top left. */
static void show_surface(struct map_screen *s, int k)
{
    const struct project_surface_option *so = &s->building.surfaces[k];
    s->surface = k;
    s->panels = &so->panels;
    s->totals = &so->totals;
    s->ci = 0;
    s->cj = s->panels->nv > 0 ? s->panels->nv - 1 : 0;
    s->left = s->top = 0;
    map_surface_size(s->panels, &s->width_m, &s->height_m);
    map_seams_free(&s->seams);
    if (s->seams_found &&
        map_seams_of_surface(s->seam_joints, s->nseam_joints, (size_t)k,
                             s->panels->npanels, &s->seams) != 0)
        s->seams_found = 0;  /* out of memory: the map without them */
    set_bounds(s);
}

/* Moves the cursor by (di, dj), clamped to the grid. */
static void move_cursor(struct map_screen *s, int di, int dj)
{
    s->ci += di;
    s->cj += dj;
    if (s->ci < 0)
        s->ci = 0;
    if (s->ci >= s->panels->nu)
        s->ci = s->panels->nu - 1;
    if (s->cj < 0)
        s->cj = 0;
    if (s->cj >= s->panels->nv)
        s->cj = s->panels->nv - 1;
}

/* Splits "PREFIX" or "PREFIX!" (overwrite) into the export's paths: the
 * fabrication package, PREFIX.csv (+ -totals.csv), .xlsx, .dxf (on the
 * default sheets) and .ifc, and of a single surface PREFIX.obj (+ .mtl)
 * and .svg too; a building's from the building the map shows (no second
 * evaluation). */
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
    char svg[TUI_INPUT_MAX + 8], xlsx[TUI_INPUT_MAX + 8];
    char dxf[TUI_INPUT_MAX + 8], ifc[TUI_INPUT_MAX + 8];
    snprintf(obj, sizeof obj, "%s.obj", prefix);
    snprintf(csv, sizeof csv, "%s.csv", prefix);
    snprintf(svg, sizeof svg, "%s.svg", prefix);
    snprintf(xlsx, sizeof xlsx, "%s.xlsx", prefix);
    snprintf(dxf, sizeof dxf, "%s.dxf", prefix);
    snprintf(ifc, sizeof ifc, "%s.ifc", prefix);
    struct export_request request;
    memset(&request, 0, sizeof request);
    request.csv = csv;
    request.xlsx = xlsx;
    request.dxf = dxf;
    request.ifc = ifc;
    /* No sheet is asked for here: the default, grown to hold the
     * largest panel rather than refuse it. */
    request.sheet_grows = 1;
    request.force = force;
    if (s->project) {
        request.view = tui_project_load_view(app->project);
        request.building = &s->building;
        assert(request.view != NULL);
    } else {
        request.obj = obj;
        request.svg = svg;
    }
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
    if (s->project)
        tui_status(app, "wrote %s.csv (+ -totals.csv%s), .xlsx, .dxf, "
                   ".ifc: the building's %zu panels", prefix,
                   request.written[EXPORT_SEAMS][0] ? ", -seams.csv" : "",
                   s->building.totals.panels);
    else
        tui_status(app, "wrote %s.obj (+ .mtl), .csv, .svg, .xlsx, .dxf, "
                   ".ifc", prefix);
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
    if (s->project && s->building.nsurfaces == 0)
        return RESULT_UNHANDLED;  /* preparing, or failed: q goes back */
    switch (key) {
    case ']': case '[': {
        if (!s->project) {
            tui_status(app, "%c: a single surface's option has no other "
                       "surface to go to", key);
            return RESULT_HANDLED;
        }
        int n = (int)s->building.nsurfaces;
        int k = map_surface_step(s->surface, n, key == ']' ? 1 : -1);
        if (k == s->surface)
            tui_status(app, "surface %d of %d is the %s", k + 1, n,
                       key == ']' ? "last" : "first");
        else
            show_surface(s, k);
        return RESULT_HANDLED;
    }
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
        /* Only a planarized option's corners moved. */
        if (s->colour == MAP_BY_MOVE && s->panels->corner_moved == NULL) {
            tui_status(app, "corner move: not a planarized option");
            s->colour = (enum map_colour)((s->colour + 1) % MAP_COLOURS);
        }
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
        s->ci = s->panels->nu - 1;
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
        s->cj = s->panels->nv - 1;
        break;
    case ACTION_BOTTOM:
        s->ci = s->panels->nu - 1;
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
    panelization_free(&s->own);
    project_option_free(&s->building);
    map_seams_free(&s->seams);
    free(s->seam_joints);
    free(s->surfaces);
    free(s);
}

/* Gives the map the building once app->project is prepared: evaluates
 * the option over it (study_project_view_option). Returns 1 when the
 * screen changed. */
static int project_start(struct map_screen *s, struct tui_app *app,
                         struct facet_error *err);

static int project_poll(struct map_screen *s, struct tui_app *app)
{
    if (!s->loading)
        return 0;
    if (app->project == NULL || app->project_run != s->run.id) {
        /* another run's map took the room: prepare this run's again */
        struct facet_error err;
        if (project_start(s, app, &err) != FACET_OK) {
            s->loading = 0;
            snprintf(s->failed, sizeof s->failed, "%s", err.message);
        }
        return 1;
    }
    struct tui_project_load_state st;
    tui_project_load_state(app->project, &st);
    if (!st.finished)
        return 1;  /* the seconds move */
    s->loading = 0;
    struct facet_error err = st.err;
    const struct study_project_view *view =
        tui_project_load_view(app->project);
    int rc = st.rc;
    if (rc == FACET_OK)
        rc = study_project_view_option(app->store, view, s->option.number,
                                       &s->building, &err);
    if (rc == FACET_OK && (s->building.nsurfaces == 0 ||
                           s->building.nsurfaces != s->nsurfaces))
        rc = facet_error_set(&err, FACET_EWORK, "the project has %zu "
                             "surfaces, the run %zu",
                             s->building.nsurfaces, s->nsurfaces);
    if (rc == FACET_OK) {
        free(s->seam_joints);
        s->seam_joints = NULL;
        s->nseam_joints = 0;
        /* none to draw where the option's joints were not measured: its
         * panels were not built to place them on */
        s->seams_found = view->project.seams != NULL &&
                         s->building.totals.seams != TOTALS_UNKNOWN;
        struct facet_error seam_err;
        /* out of memory: the map without its seam joints, said */
        if (s->seams_found &&
            project_option_seam_joints(&view->project, &s->building,
                                       &s->seam_joints, &s->nseam_joints,
                                       &seam_err) != FACET_OK) {
            s->seams_found = 0;
            tui_error(app, "panel map: seam joints: %s", seam_err.message);
        }
    }
    if (rc != FACET_OK) {
        snprintf(s->failed, sizeof s->failed, "%s", err.message);
        tui_error(app, "panel map: %s", err.message);
        if (st.rc != FACET_OK) {
            /* not kept: the next map tries again (a file put back) */
            tui_project_load_free(app->project);
            app->project = NULL;
            app->project_run = 0;
        }
        return 1;
    }
    int k = s->surface;
    show_surface(s, k >= 0 && (size_t)k < s->building.nsurfaces ? k : 0);
    return 1;
}

/* Starts preparing the run's project unless app->project holds it
 * already (prepared or being prepared). */
static int project_start(struct map_screen *s, struct tui_app *app,
                         struct facet_error *err)
{
    if (app->project != NULL && app->project_run != s->run.id) {
        tui_project_load_free(app->project);
        app->project = NULL;
        app->project_run = 0;
    }
    if (app->project == NULL) {
        int rc = tui_project_load_start(app->db_path, s->run.id,
                                        &app->project, err);
        if (rc != FACET_OK)
            return rc;
        app->project_run = s->run.id;
    }
    s->loading = 1;
    project_poll(s, app);
    return FACET_OK;
}

static int map_tick(struct tui_screen *base, struct tui_app *app)
{
    return project_poll((struct map_screen *)base, app);
}

static const struct tui_screen_class map_class = {
    "Panel map", map_help,
    {"Help", "Colour", NULL, NULL, NULL, NULL, NULL, NULL, "Export",
     "Quit"},
    map_draw, map_key, map_tick, map_destroy,
};

struct tui_screen *screen_map_new(struct tui_app *app, int64_t run,
                                  int64_t option)
{
    return screen_map_at(app, run, option, 0);
}

struct tui_screen *screen_map_at(struct tui_app *app, int64_t run,
                                 int64_t option, int surface)
{
    struct map_screen *s = calloc(1, sizeof *s);
    struct facet_error err;
    if (s == NULL) {
        tui_error(app, "out of memory");
        return NULL;
    }
    s->base.cls = &map_class;
    s->panels = &s->own;
    s->totals = &s->own_totals;
    int rc = store_run_get(app->store, run, &s->run, &err);
    if (rc == FACET_OK)
        rc = store_option_get(app->store, run, option, &s->option, &err);
    if (rc == FACET_OK && store_run_is_project(&s->run)) {
        s->project = 1;
        s->surface = surface;
        rc = store_surfaces_get(app->store, run, &s->surfaces,
                                &s->nsurfaces, &err);
        if (rc == FACET_OK)
            rc = project_start(s, app, &err);
    } else if (rc == FACET_OK) {
        rc = study_option_panels(app->store, &s->run, NULL, option, &s->own,
                                 &s->own_totals, &err);
        if (rc == FACET_OK && (s->own.nu < 1 || s->own.nv < 1))
            rc = facet_error_set(&err, FACET_EWORK,
                                 "option %lld has no panels",
                                 (long long)option);
        s->cj = s->own.nv - 1;  /* top left, as the map reads */
        map_surface_size(s->panels, &s->width_m, &s->height_m);
    }
    if (rc != FACET_OK) {
        tui_error(app, "panel map: %s", err.message);
        map_destroy(&s->base);
        return NULL;
    }
    return &s->base;
}
