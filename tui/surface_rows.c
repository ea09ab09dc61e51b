/*
 * surface_rows.c: a project option's surfaces as text. See
 * surface_rows.h.
 */
#include "surface_rows.h"

#include <stdio.h>
#include <string.h>

#include "core/base/units.h"
#include "format.h"

/* The name column's width: what is left of SURFACE_ROW_WIDTH. */
#define NAME_WIDTH 12
#define LINE " %-*s %7s %6s %4s %4s %4s %9s %7s %5s %5s %5s"

void surface_rows_header(char *names, char *units, size_t size)
{
    snprintf(names, size, LINE, NAME_WIDTH, "surface", "grid", "panels",
             "FP", "SP", "DP", "cost", "moulds", "dev", "gap", "kink");
    snprintf(units, size, LINE, NAME_WIDTH, "", "", "", "", "", "", "USD",
             "st/used", "mm", "mm", "deg");
}

void surface_rows_line(char *out, size_t size, const char *name,
                       const struct option_surface_row *r)
{
    const struct option_totals *t = &r->totals;
    char shown[NAME_WIDTH + 1];
    size_t n = strlen(name);
    if (n > NAME_WIDTH)
        snprintf(shown, sizeof shown, "%.*s~", NAME_WIDTH - 1, name);
    else
        snprintf(shown, sizeof shown, "%s", name);
    char grid[24], cost[32], moulds[48], dev[24], gap[24], kink[24];
    snprintf(grid, sizeof grid, "%dx%d", r->nu, r->nv);
    tui_fmt_number(cost, sizeof cost, t->cost, 0, 1);
    snprintf(moulds, sizeof moulds, "%zu/%lld", t->moulds,
             (long long)r->moulds_used);
    tui_fmt_number(dev, sizeof dev, t->max_deviation * 1000, 2, 0);
    tui_fmt_number(gap, sizeof gap, units_mm(t->max_gap), 2, 0);
    tui_fmt_number(kink, sizeof kink, units_deg(t->max_kink), 2, 0);
    char panels[24], fp[24], sp[24], dp[24];
    snprintf(panels, sizeof panels, "%zu", t->panels);
    snprintf(fp, sizeof fp, "%zu", t->count[TYPE_FP]);
    snprintf(sp, sizeof sp, "%zu", t->count[TYPE_SP]);
    snprintf(dp, sizeof dp, "%zu", t->count[TYPE_DP]);
    snprintf(out, size, LINE, NAME_WIDTH, shown, grid, panels, fp, sp, dp,
             cost, moulds, dev, gap, kink);
}
