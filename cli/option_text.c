/*
 * option_text.c: totals tables and the panel map. See option_text.h.
 */
#include "option_text.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include "core/base/units.h"
#include "core/base/numformat.h"
#include "core/quantity/quantity.h"

/* What a value of an option not known shows (NULL in the store): its
 * run did not need it (a run measures what its objectives, limits and
 * prices read; facet show measures the rest), or an older Facet stored
 * the option before it measured joints and moulds. */
static const char not_stored[] =
    "- (not measured in this run, or stored by an older Facet)";

/* value grouped by thousands with decimals places, in text (a buffer of
 * its caller's): panels, areas and money read alike everywhere. */
static const char *grouped(char text[40], double value, int decimals)
{
    number_grouped(text, 40, value, decimals);
    return text;
}

/* The quantity named name of t as its row shows it, with its unit
 * ("1674.54 mm"). */
static const char *shown(char text[64], const struct option_totals *t,
                         const char *name)
{
    const struct quantity *q = quantity_named(name);
    char number[48];
    quantity_text(number, sizeof number, q, quantity_of_totals(q, t),
                  q->decimals);
    snprintf(text, 64, "%s %s", number, q->unit);
    return text;
}

/* A building's seams (part of the gaps and kinks above), when measured:
 * a single surface has none to show. */
static void seams_text(FILE *out, const struct option_totals *t)
{
    if (t->seams == TOTALS_UNKNOWN)
        return;
    char length[64], gap[64], kink[64], crease[64];
    fprintf(out, "%-16s %zu, %s long", "seams", t->seams,
            shown(length, t, "seam_length"));
    if (isnan(t->seam_max_gap)) {
        fprintf(out, " (no seam joint)\n");
        return;
    }
    fprintf(out, ": max gap %s, max kink added %s to a crease of up to %s "
            "(%zu gaps, %zu kinks over the limits)\n",
            shown(gap, t, "seam_max_gap"), shown(kink, t, "seam_max_kink"),
            shown(crease, t, "seam_max_crease"), t->seam_gaps_over,
            t->seam_kinks_over);
}

/* The SP misfits, gaps and kinks of t, against o's limits. */
static void joints_text(FILE *out, const struct option_totals *t,
                        const struct classify_options *o)
{
    if (t->sp_misfits == TOTALS_UNKNOWN || t->sp_fitted == TOTALS_UNKNOWN) {
        fprintf(out, "\n%-16s %s\n", "SP misfits", not_stored);
    } else {
        size_t classed_sp = t->sp_fitted + t->sp_misfits;
        fprintf(out, "\n%-16s %zu of %zu SP panels (by class) fit no "
                "cylinder or cone within %g mm: %s\n", "SP misfits",
                t->sp_misfits, classed_sp, o->threshold * 1000,
                o->sp_by_class ? "kept SP (SP by class alone)"
                               : "built and priced DP");
    }
    if (isnan(t->max_gap)) {
        fprintf(out, "%-16s %s\n", "gaps, kinks", not_stored);
        return;
    }
    char limit[64] = "no limit";
    if (o->max_gap > 0)
        snprintf(limit, sizeof limit, "%zu over the %g mm limit",
                 t->gaps_over, o->max_gap * 1000);
    fprintf(out, "%-16s max %.3f mm, mean %.3f mm (%s)\n", "gap",
            units_mm(t->max_gap), units_mm(t->mean_gap), limit);
    snprintf(limit, sizeof limit, "no limit");
    if (o->max_kink > 0)
        snprintf(limit, sizeof limit, "%zu over the %g degree limit",
                 t->kinks_over, o->max_kink * 180 / M_PI);
    fprintf(out, "%-16s max %.3f deg, mean %.3f deg (%s)\n", "kink",
            units_deg(t->max_kink), units_deg(t->mean_kink), limit);
    seams_text(out, t);
}

/* The smallest panel of t by area and by width, and its slivers against
 * o's width limit. */
static void slivers_text(FILE *out, const struct option_totals *t,
                         const struct classify_options *o)
{
    if (isnan(t->min_panel_area))
        fprintf(out, "%-16s %s\n", "min panel area", not_stored);
    else
        fprintf(out, "%-16s %.3f m^2\n", "min panel area",
                t->min_panel_area);
    if (t->slivers == TOTALS_UNKNOWN) {
        fprintf(out, "%-16s %s\n", "min panel width", not_stored);
        return;
    }
    char limit[96] = "no width limit";
    if (o->min_panel_width > 0)
        snprintf(limit, sizeof limit,
                 "%zu slivers narrower than the %g mm width limit: %s",
                 t->slivers, o->min_panel_width * 1000,
                 t->slivers == 0 ? "within" : "NOT within");
    fprintf(out, "%-16s %.1f mm (%s)\n", "min panel width",
            t->min_panel_width * 1000, limit);
}

void option_text_kind(FILE *out, const struct option_totals *t,
                      const struct panelization *p, double budget_mm)
{
    if (!t->planarized) {
        fprintf(out, "%-16s classified: the surface cut along the grid, "
                "never moved\n", "kind");
        return;
    }
    double moved = NAN;
    for (size_t k = 0; p->corner_moved != NULL && k < p->npanels; k++)
        if (!isnan(p->corner_moved[k]))
            moved = isnan(moved) ? p->corner_moved[k]
                                 : fmax(moved, p->corner_moved[k]);
    fprintf(out, "%-16s planarized: its corners moved off the surface until "
            "its quads are planar\n", "kind");
    fprintf(out, "%-16s reached %.3f mm at most, %.3f mm on average "
            "(budget %g mm)\n", "closeness", t->closeness_reached * 1000,
            t->closeness_mean * 1000, budget_mm);
    fprintf(out, "%-16s reached %.3g of the longer diagonal at most\n",
            "quad planarity", t->planarity_reached);
    if (!isnan(moved))
        fprintf(out, "%-16s %.3f mm at most\n", "corners moved",
                moved * 1000);
    if (t->planar_over == 0)
        fprintf(out, "%-16s every quad planar, every corner within the "
                "budget\n", "planarized");
    else
        fprintf(out, "%-16s INFEASIBLE: %zu quads not planar or beyond the "
                "budget; not a planar option\n", "planarized",
                t->planar_over);
}

void option_text_totals(FILE *out, const struct option_totals *t,
                        const struct classify_options *o)
{
    char a[40], b[40], c[40];
    fprintf(out, "\n%-6s %8s %14s %8s %16s\n", "type", "panels", "area m^2",
            "share", "cost USD");
    for (int k = 0; k < TYPE_COUNT; k++)
        fprintf(out, "%-6s %8s %14s %7.1f%% %16s\n",
                panel_type_name((enum panel_type)k),
                grouped(a, (double)t->count[k], 0),
                grouped(b, t->area_of[k], 3),
                t->area > 0 ? 100 * t->area_of[k] / t->area : 0,
                grouped(c, t->cost_of[k], 2));
    fprintf(out, "%-6s %8s %14s %7.1f%% %16s\n", "total",
            grouped(a, (double)t->panels, 0), grouped(b, t->area, 3), 100.0,
            grouped(c, t->area_cost, 2));
    if (isnan(t->area_cost)) {
        fprintf(out, "%-16s %s\n", "cost terms", not_stored);
    } else if (t->cost != t->area_cost) {
        fprintf(out, "%-16s %s panels x %g USD = %s USD\n", "panel cost",
                grouped(a, (double)t->panels, 0), o->panel_cost,
                grouped(b, t->panel_cost, 2));
        fprintf(out, "%-16s %s m x %g USD/m = %s USD\n", "joint cost",
                grouped(a, t->joint_length, 3), o->joint_cost,
                grouped(b, t->joint_cost, 2));
        fprintf(out, "%-16s SP %zu x %g + DP %zu x %g USD = %s USD\n",
                "mould cost", t->moulds_of[TYPE_SP], o->mould_cost[TYPE_SP],
                t->moulds_of[TYPE_DP], o->mould_cost[TYPE_DP],
                grouped(a, t->mould_cost, 2));
        fprintf(out, "%-16s %s USD (area, panels, joints and moulds)\n",
                "total cost", grouped(a, t->cost, 2));
    }
    if (isnan(t->joint_length))
        fprintf(out, "\n%-16s %s\n", "joint length", not_stored);
    else
        fprintf(out, "\n%-16s %s m (panel edges once each, and the "
                "outline)\n", "joint length", grouped(a, t->joint_length, 3));
    if (t->moulds == TOTALS_UNKNOWN ||
        t->moulds_of[TYPE_SP] == TOTALS_UNKNOWN ||
        t->moulds_of[TYPE_DP] == TOTALS_UNKNOWN ||
        t->largest_family == TOTALS_UNKNOWN ||
        t->singleton_families == TOTALS_UNKNOWN)
        fprintf(out, "%-16s %s\n", "moulds", not_stored);
    else
        fprintf(out, "%-16s %zu (SP %zu, DP %zu; largest family %zu panels, "
                "%zu of one panel; greedy: at most this many)\n", "moulds",
                t->moulds, t->moulds_of[TYPE_SP], t->moulds_of[TYPE_DP],
                t->largest_family, t->singleton_families);

    fprintf(out, "\n%-16s %.6f m (sum of FP and SP panel deviations)\n",
            "planarity", t->planarity);
    fprintf(out, "%-16s %.3f mm\n", "max deviation", t->max_deviation * 1000);
    int area_ok = classify_area_excess(t->max_panel_area,
                                       o->max_panel_area) == 0;
    fprintf(out, "%-16s %.3f m^2 (limit %g: %s)\n", "max panel area",
            t->max_panel_area, o->max_panel_area,
            area_ok ? "within" : "NOT within");

    slivers_text(out, t, o);

    joints_text(out, t, o);
    fprintf(out, "%-16s %s\n", "feasible", t->feasible ? "yes" : "NO");

    fprintf(out, "\n%-22s %8s %14s\n", "class", "panels", "area m^2");
    for (int k = 0; k < CLASS_COUNT; k++)
        fprintf(out, "%-22s %8s %14s\n",
                panel_class_name((enum panel_class)k),
                grouped(a, (double)t->class_count[k], 0),
                grouped(b, t->class_area[k], 3));
}

static int terminal_width(FILE *out)
{
    struct winsize size;
    if (ioctl(fileno(out), TIOCGWINSZ, &size) == 0 && size.ws_col > 0)
        return size.ws_col;
    const char *columns = getenv("COLUMNS");
    if (columns != NULL && atoi(columns) > 0)
        return atoi(columns);
    return 80;
}

static int use_colour(FILE *out)
{
    const char *term = getenv("TERM");
    return isatty(fileno(out)) && getenv("NO_COLOR") == NULL &&
           term != NULL && strcmp(term, "dumb") != 0;
}

void option_text_map(FILE *out, const struct panelization *p)
{
    static const char letter[TYPE_COUNT] = {'F', 'S', 'D'};
    static const char *const colour[TYPE_COUNT] = {
        "\033[30;42m", "\033[30;43m", "\033[37;41m"};
    int colours = use_colour(out);
    if (p->nu + 4 > terminal_width(out)) {
        fprintf(out, "\n(panel map not shown: %d columns do not fit the "
                "terminal)\n", p->nu);
        return;
    }
    fprintf(out, "\npanel map (u to the right, v upwards): F flat, S "
            "single-curved, D double-curved, . no panel\n");
    for (int j = p->nv - 1; j >= 0; j--) {
        fputs("  ", out);
        for (int i = 0; i < p->nu; i++) {
            int n = p->cell_panel[j * p->nu + i];
            if (n < 0) {
                fputc('.', out);
                continue;
            }
            enum panel_type type = p->panels[n].type;
            if (colours)
                fprintf(out, "%s%c\033[0m", colour[type], letter[type]);
            else
                fputc(letter[type], out);
        }
        fputc('\n', out);
    }
}
