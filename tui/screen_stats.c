/*
 * screen_stats.c: Statistics of the options the table shows (its filter
 * and Pareto-only), in sections chosen with Tab or h/l: every metric's
 * count, min, median, max and mean; frequency tables of the options per
 * U, per V, per threshold (in bins when it takes many values) and per
 * panel class; and, per generation, the options an NSGA-II run met with
 * the best cost, planarity and DP area found so far (the search's
 * progress). Every figure comes from SQL in store/ (store_browse_stats,
 * _median, _groups, _classes), so a filtered million-option run is summed
 * by SQLite, not read row by row here. A table is computed when its
 * section is first shown, and the medians one a tick while no key comes,
 * so the screen answers keys at once even where a median takes 0.7 s.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "app.h"
#include "format.h"
#include "keys.h"

enum section { SEC_COLUMNS, SEC_U, SEC_V, SEC_T, SEC_CLASS, SEC_GENERATION,
               SEC_COUNT };

static const char *const section_name[SEC_COUNT] = {
    "columns", "per U", "per V", "per t", "per class", "per generation"};
/* A project's grid is its module, in metres: nu and nv only index the
 * module range (tui_shown_column). */
static const char *const project_section_name[SEC_COUNT] = {
    "columns", "per module width", "per module height", "per t",
    "per class", "per generation"};
static const char *const group_column[SEC_COUNT] = {
    NULL, "nu", "nv", "threshold_mm", NULL, "generation"};

static const char *const stat_columns[] = {
    "cost", "planarity", "dp_area", "fp_area", "sp_area", "area", "nu", "nv",
    "threshold_mm", "panels", "dp_count", "max_deviation", "max_panel_area",
    "p_dist", "rank", "generation", "moulds", "joint_length", "max_gap",
    "max_kink", "sp_misfits", "sp_min_radius"};
#define STATS ((int)(sizeof stat_columns / sizeof stat_columns[0]))

struct stats_screen {
    struct tui_screen base;
    struct table_model *model;     /* the options table's, borrowed */
    int section;
    int top;
    struct column_stats stats[STATS];
    struct option_group *groups[SEC_COUNT];
    size_t ngroups[SEC_COUNT];
    double bin[SEC_COUNT];         /* the bin of a binned table, or 0 */
    struct class_frequency classes[CLASS_COUNT];
    int loaded[SEC_COUNT];         /* the section's table is computed */
    int medians;                   /* medians computed: column[0..) */
    /* stat_columns and group_column as this run's options show them: a
     * project's module (module_w, module_h) for nu and nv */
    const char *column[STATS];
    const char *group[SEC_COUNT];
    int project;
    int64_t options;               /* the options summed */
};

static const struct tui_key_help stats_help[] = {
    {"Tab, l / h", "next / previous section: columns, per U, per V, per "
                   "t, per class, per generation"},
    {"1-6", "a section by its place"},
    {"j/k, PgUp/PgDn", "scroll"},
    {"r", "compute again (a live run, a new filter)"},
    {"(figures)", "of the options the table shows: its filter and Pareto "
                  "only apply"},
    {NULL, NULL},
};

static void release(struct stats_screen *s)
{
    for (int k = 0; k < SEC_COUNT; k++) {
        free(s->groups[k]);
        s->groups[k] = NULL;
        s->ngroups[k] = 0;
    }
}

/* A round bin giving at most about 25 rows over [min, max]. */
static double round_bin(double min, double max)
{
    double raw = (max - min) / 25, e = pow(10, floor(log10(raw)));
    double m = raw / e;
    return (m <= 1 ? 1 : m <= 2 ? 2 : m <= 5 ? 5 : 10) * e;
}

/* Computes the table of section when it is not yet. */
static int load_section(struct stats_screen *s, struct tui_app *app,
                        int section)
{
    if (s->loaded[section])
        return FACET_OK;
    struct facet_error err;
    const struct option_browse *b = &s->model->browse;
    int rc = FACET_OK;
    if (section == SEC_CLASS) {
        rc = store_browse_classes(app->store, b, s->classes, &err);
    } else if (s->group[section] != NULL) {
        /* more values than rows to show: bins, known before the query
         * from the range and the column's step (1 for U, V and the
         * generation, the run's for t; a continuous t takes any value) */
        int c = section == SEC_T ? 8 : section == SEC_U ? 6
                : section == SEC_V ? 7 : 15;
        double min = s->stats[c].min, max = s->stats[c].max, step = 1;
        if (section == SEC_T)
            step = s->model->run.threshold_step_mm;
        else if (s->project && section == SEC_U)
            step = s->model->run.module_w_step;
        else if (s->project && section == SEC_V)
            step = s->model->run.module_h_step;
        if (!(step >= 0))
            step = 0;
        int many = max > min && (step > 0 ? (max - min) / step + 1 > 60 : 1);
        s->bin[section] = many ? round_bin(min, max) : 0;
        rc = store_browse_groups(app->store, b, s->group[section],
                                 s->bin[section], &s->groups[section],
                                 &s->ngroups[section], &err);
    }
    if (rc != FACET_OK)
        tui_error(app, "statistics: %s", err.message);
    else
        s->loaded[section] = 1;
    return rc;
}

/* Starts over: the counts, minima, maxima and means at once, the
 * section's table, and the medians from the next tick on, which comes as
 * soon as the screen is drawn. */
static int load(struct stats_screen *s, struct tui_app *app)
{
    struct facet_error err;
    release(s);
    memset(s->loaded, 0, sizeof s->loaded);
    s->medians = 0;
    int rc = store_browse_stats(app->store, &s->model->browse, s->column,
                                STATS, s->stats, &err);
    s->options = rc == FACET_OK ? s->stats[0].count : 0;
    if (rc != FACET_OK) {
        tui_error(app, "statistics: %s", err.message);
        return rc;
    }
    s->loaded[SEC_COLUMNS] = 1;
    app->tick_soon = 1;
    return load_section(s, app, s->section);
}

/* A tick's share of the medians: as many as MEDIAN_BUDGET allows, one
 * at the least, and the next tick at once while any is left
 * (app->tick_soon), a key answered between two. One a tick (a quarter of
 * a second apart while no key comes) took 5.5 s for the 22 medians of any
 * run; a budget's worth a quarter second apart, 1.5 s at 10,000 options. */
#define MEDIAN_BUDGET 0.05

static int stats_tick(struct tui_screen *base, struct tui_app *app)
{
    struct stats_screen *s = (struct stats_screen *)base;
    if (s->medians >= STATS)
        return 0;
    if (s->medians == 0 && s->options <= STORE_MEDIANS_AT_ONCE) {
        /* A run that fits in memory: every median from one read. */
        struct facet_error err;
        if (store_browse_medians(app->store, &s->model->browse, s->column,
                                 STATS, s->stats, &err) != FACET_OK)
            tui_error(app, "statistics: %s", err.message);
        s->medians = STATS;
        return 1;
    }
    struct timespec started;
    clock_gettime(CLOCK_MONOTONIC, &started);
    do {
        struct facet_error err;
        int k = s->medians++;
        if (store_browse_median(app->store, &s->model->browse, s->column[k],
                                s->stats[k].count, &s->stats[k].median,
                                &err) != FACET_OK) {
            tui_error(app, "statistics: %s", err.message);
            break;
        }
    } while (s->medians < STATS &&
             tui_seconds_since(&started) < MEDIAN_BUDGET);
    app->tick_soon = s->medians < STATS;
    return 1;
}

static void show(struct stats_screen *s, struct tui_app *app, int section)
{
    s->section = (section + SEC_COUNT) % SEC_COUNT;
    s->top = 0;
    load_section(s, app, s->section);
}

static void fmt(char *out, size_t size, const char *column, double value)
{
    const struct quantity *c = quantity_named(column);
    if (c)
        tui_fmt_value(out, size, c, value);
    else
        tui_fmt_number(out, size, value, 2, 0);
}

/* Rows of the section, for scrolling. */
static int section_rows(const struct stats_screen *s)
{
    switch (s->section) {
    case SEC_COLUMNS: return STATS;
    case SEC_CLASS: return CLASS_COUNT;
    default: return (int)s->ngroups[s->section];
    }
}

static void draw_bar(int y, int x, int width, const struct tui_app *app,
                     int64_t n, int64_t most)
{
    int full = most > 0 ? (int)((double)n / (double)most * width + 0.5) : 0;
    for (int k = 0; k < full && k < width; k++)
        tui_put(y, x + k, 1, tui_attr(ROLE_GAUGE), app->glyphs->gauge_full);
}

static void stats_draw(struct tui_screen *base, struct tui_app *app,
                       int height, int width)
{
    struct stats_screen *s = (struct stats_screen *)base;
    const struct table_model *m = s->model;
    const char *where = m->filter ? filter_text(m->filter) : "";
    char count[32];
    tui_fmt_number(count, sizeof count, (double)s->options, 0, 1);
    tui_fill(0, 0, width, tui_attr(ROLE_TITLE));
    static const char *const note[SEC_COUNT] = {
        "", " | least of each group", " | least of each group",
        " | least of each group", "", " | best found so far"};
    char bins[48] = "";
    if (s->bin[s->section] > 0)
        snprintf(bins, sizeof bins, ", in bins of %g", s->bin[s->section]);
    tui_putf(0, 0, width, tui_attr(ROLE_TITLE),
             " Statistics: run %lld | %s options%s%s%s%s%s",
             (long long)m->browse.run, count, note[s->section], bins,
             m->browse.pareto_only ? " | Pareto only" : "",
             where[0] ? " | filter " : "", where);
    int x = 0;
    for (int k = 0; k < SEC_COUNT; k++) {
        char tab[40];
        snprintf(tab, sizeof tab, " %d %s ", k + 1,
                 (s->project ? project_section_name : section_name)[k]);
        x += tui_put(1, x, width - x, k == s->section
                                          ? tui_attr(ROLE_SELECTION)
                                          : A_NORMAL, tab);
    }
    int rows = height - 3, total = section_rows(s);
    if (s->top > total - rows)
        s->top = total - rows > 0 ? total - rows : 0;
    if (s->top < 0)
        s->top = 0;
    tui_fill(2, 0, width, tui_attr(ROLE_HEADER));
    char a[32], b2[32], c[32], d[32], e[32];
    if (s->section == SEC_COLUMNS) {
        tui_put(2, 0, width, tui_attr(ROLE_HEADER),
                " metric          unit       n         min      median"
                "         max        mean");
        for (int r = 0; r < rows && s->top + r < STATS; r++) {
            int k = s->top + r;
            const struct quantity *col =
                quantity_named(s->column[k]);
            const struct column_stats *st = &s->stats[k];
            fmt(a, sizeof a, s->column[k], st->min);
            if (k < s->medians)
                fmt(b2, sizeof b2, s->column[k], st->median);
            else
                snprintf(b2, sizeof b2, "...");
            fmt(c, sizeof c, s->column[k], st->max);
            fmt(d, sizeof d, s->column[k], st->mean);
            tui_fmt_number(e, sizeof e, (double)st->count, 0, 1);
            tui_putf(3 + r, 0, width, A_NORMAL,
                     " %-15s %-4s %7s %11s %11s %11s %11s",
                     col ? col->label : s->column[k],
                     col ? col->unit : "", e, a, b2, c, d);
        }
        return;
    }
    if (s->section == SEC_CLASS) {
        int64_t most = 1;
        for (int k = 0; k < CLASS_COUNT; k++)
            if (s->classes[k].options > most)
                most = s->classes[k].options;
        tui_put(2, 0, width, tui_attr(ROLE_HEADER),
                " class                  options with it         panels"
                "   mean m^2/option");
        for (int r = 0; r < rows && s->top + r < CLASS_COUNT; r++) {
            int k = s->top + r;
            const struct class_frequency *f = &s->classes[k];
            tui_fmt_number(a, sizeof a, (double)f->options, 0, 1);
            tui_fmt_number(b2, sizeof b2, (double)f->panels, 0, 1);
            tui_fmt_number(c, sizeof c, s->options ? f->area /
                           (double)s->options : NAN, 2, 1);
            tui_putf(3 + r, 0, width, A_NORMAL, " %-22s %7s %-14s %8s %12s",
                     panel_class_name((enum panel_class)k), a, "", b2, c);
            draw_bar(3 + r, 32, 14, app, f->options, most);
        }
        return;
    }
    const struct option_group *g = s->groups[s->section];
    size_t ng = s->ngroups[s->section];
    const char *column = s->group[s->section];
    int64_t most = 1;
    for (size_t k = 0; k < ng; k++)
        if (g[k].options > most)
            most = g[k].options;
    char head[160];
    int gen = s->section == SEC_GENERATION;
    snprintf(head, sizeof head, " %-7s options              Pareto feasible"
             " %11s %10s %7s", gen ? "gen" : s->section == SEC_T ? "t mm"
                 : s->project ? (s->section == SEC_U ? "W m" : "H m")
                 : s->section == SEC_U ? "U" : "V",
             gen ? "best USD" : "least USD", "planar. m", "DP m^2");
    tui_put(2, 0, width, tui_attr(ROLE_HEADER), head);
    if (ng == 0)
        tui_put(4, 2, width - 2, tui_attr(ROLE_DIM), "no option to count");
    /* per generation: the best found up to each generation, which is what
     * a search's progress is */
    double best_cost = INFINITY, best_plan = INFINITY, best_dp = INFINITY;
    for (size_t k = 0; k < ng; k++) {
        best_cost = fmin(best_cost, g[k].min_cost);
        best_plan = fmin(best_plan, g[k].min_planarity);
        best_dp = fmin(best_dp, g[k].min_dp_area);
        int r = (int)k - s->top;
        if (r < 0 || r >= rows)
            continue;
        char value[32];
        if (gen)
            snprintf(value, sizeof value, "%.0f", g[k].value);
        else
            fmt(value, sizeof value, column, g[k].value);
        tui_fmt_number(a, sizeof a, (double)g[k].options, 0, 1);
        tui_fmt_number(b2, sizeof b2, gen ? best_cost : g[k].min_cost, 0, 1);
        tui_fmt_number(c, sizeof c, gen ? best_plan : g[k].min_planarity, 4,
                       0);
        tui_fmt_number(d, sizeof d, gen ? best_dp : g[k].min_dp_area, 1, 0);
        tui_putf(3 + r, 0, width, A_NORMAL,
                 " %-7s %7s %-12s %6lld %8lld %11s %10s %7s", value, a, "",
                 (long long)g[k].pareto, (long long)g[k].feasible, b2, c, d);
        draw_bar(3 + r, 17, 12, app, g[k].options, most);
    }
}

static enum tui_result stats_key(struct tui_screen *base, struct tui_app *app,
                                 int key)
{
    struct stats_screen *s = (struct stats_screen *)base;
    if (key >= '1' && key < '1' + SEC_COUNT) {
        show(s, app, key - '1');
        return RESULT_HANDLED;
    }
    int page = LINES - 6 > 1 ? LINES - 6 : 1;
    switch (key) {
    case '\t':
        show(s, app, s->section + 1);
        return RESULT_HANDLED;
    case KEY_BTAB:
        show(s, app, s->section - 1);
        return RESULT_HANDLED;
    case 'r':
        load(s, app);
        return RESULT_HANDLED;
    default:
        break;
    }
    switch (tui_key_action(key)) {
    case ACTION_RIGHT:
        show(s, app, s->section + 1);
        return RESULT_HANDLED;
    case ACTION_LEFT:
        show(s, app, s->section - 1);
        return RESULT_HANDLED;
    case ACTION_UP: s->top--; return RESULT_HANDLED;
    case ACTION_DOWN: s->top++; return RESULT_HANDLED;
    case ACTION_PAGE_UP: s->top -= page; return RESULT_HANDLED;
    case ACTION_PAGE_DOWN: s->top += page; return RESULT_HANDLED;
    case ACTION_TOP: s->top = 0; return RESULT_HANDLED;
    case ACTION_BOTTOM: s->top = 1 << 30; return RESULT_HANDLED;
    default:
        return RESULT_UNHANDLED;
    }
}

static void stats_destroy(struct tui_screen *base)
{
    struct stats_screen *s = (struct stats_screen *)base;
    release(s);
    free(s);
}

static const struct tui_screen_class stats_class = {
    "Statistics", stats_help,
    {"Help", NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL, "Quit"},
    stats_draw, stats_key, stats_tick, stats_destroy,
};

struct tui_screen *screen_stats_new(struct tui_app *app,
                                    struct table_model *model, int section)
{
    struct stats_screen *s = calloc(1, sizeof *s);
    if (s == NULL) {
        tui_error(app, "out of memory");
        return NULL;
    }
    s->base.cls = &stats_class;
    s->model = model;
    s->project = model->project;
    for (int k = 0; k < STATS; k++)
        s->column[k] = s->project
                           ? quantity_of_project(stat_columns[k])->name
                           : stat_columns[k];
    for (int k = 0; k < SEC_COUNT; k++)
        s->group[k] = s->project && group_column[k] != NULL
                          ? quantity_of_project(group_column[k])->name
                          : group_column[k];
    s->section = section >= 0 && section < SEC_COUNT ? section : 0;
    if (load(s, app) != FACET_OK) {
        stats_destroy(&s->base);
        return NULL;
    }
    return &s->base;
}
