/*
 * report.c: JSON and CSV of an evaluated option. See report.h.
 */
#include "core/out/report.h"

#include <assert.h>
#include <math.h>
#include <string.h>

#include "core/out/json.h"
#include "core/base/numformat.h"
#include "core/base/units.h"
#include "core/project/project_seams.h"
#include "core/quantity/quantity.h"

/* A count, null when it is not known (TOTALS_UNKNOWN). */
static void json_count(struct json_writer *w, size_t count)
{
    if (count == TOTALS_UNKNOWN)
        json_null(w);
    else
        json_integer(w, (long long)count);
}

static void json_totals(struct json_writer *w,
                        const struct option_totals *t,
                        size_t fp_over_threshold)
{
    json_begin_object(w);
    json_key(w, "panels");         json_integer(w, (long long)t->panels);
    json_key(w, "fp_count");       json_integer(w, (long long)t->count[TYPE_FP]);
    json_key(w, "sp_count");       json_integer(w, (long long)t->count[TYPE_SP]);
    json_key(w, "dp_count");       json_integer(w, (long long)t->count[TYPE_DP]);
    json_key(w, "fp_area");        json_number(w, t->area_of[TYPE_FP]);
    json_key(w, "sp_area");        json_number(w, t->area_of[TYPE_SP]);
    json_key(w, "dp_area");        json_number(w, t->area_of[TYPE_DP]);
    json_key(w, "area");           json_number(w, t->area);
    json_key(w, "cost");           json_number(w, t->cost);
    json_key(w, "planarity");      json_number(w, t->planarity);
    json_key(w, "max_deviation");  json_number(w, t->max_deviation);
    json_key(w, "max_panel_area"); json_number(w, t->max_panel_area);
    json_key(w, "p_dist");         json_number(w, t->p_dist);
    json_key(w, "feasible");       json_bool(w, t->feasible);
    json_key(w, "joint_length");   json_number(w, t->joint_length);
    json_key(w, "moulds");         json_count(w, t->moulds);
    json_key(w, "sp_moulds");      json_count(w, t->moulds_of[TYPE_SP]);
    json_key(w, "dp_moulds");      json_count(w, t->moulds_of[TYPE_DP]);
    json_key(w, "largest_family"); json_count(w, t->largest_family);
    json_key(w, "single_moulds");  json_count(w, t->singleton_families);
    json_key(w, "area_cost");      json_number(w, t->area_cost);
    json_key(w, "panel_cost");     json_number(w, t->panel_cost);
    json_key(w, "joint_cost");     json_number(w, t->joint_cost);
    json_key(w, "mould_cost");     json_number(w, t->mould_cost);
    json_key(w, "max_gap");        json_number(w, units_mm(t->max_gap));
    json_key(w, "mean_gap");       json_number(w, units_mm(t->mean_gap));
    json_key(w, "max_kink");       json_number(w, units_deg(t->max_kink));
    json_key(w, "mean_kink");      json_number(w, units_deg(t->mean_kink));
    json_key(w, "gaps_over");      json_integer(w, (long long)t->gaps_over);
    json_key(w, "kinks_over");     json_integer(w, (long long)t->kinks_over);
    json_key(w, "sp_misfits");     json_integer(w, (long long)t->sp_misfits);
    json_key(w, "sp_fitted");      json_integer(w, (long long)t->sp_fitted);
    json_key(w, "min_panel_area"); json_number(w, t->min_panel_area);
    json_key(w, "min_panel_width"); json_number(w, t->min_panel_width);
    json_key(w, "slivers");        json_count(w, t->slivers);
    /* The option's kind, and what a planarized one reached (null for a
     * classified one: planar_option.h). */
    json_key(w, "planarized");     json_bool(w, t->planarized);
    json_key(w, "closeness_reached"); json_number(w, t->closeness_reached);
    json_key(w, "closeness_mean"); json_number(w, t->closeness_mean);
    json_key(w, "planarity_reached"); json_number(w, t->planarity_reached);
    json_key(w, "planar_over");    json_count(w, t->planar_over);
    json_key(w, "fp_over_threshold");
    json_integer(w, (long long)fp_over_threshold);
    json_key(w, "classes");
    json_begin_object(w);
    for (int c = 0; c < CLASS_COUNT; c++) {
        json_key(w, panel_class_name((enum panel_class)c));
        json_begin_object(w);
        json_key(w, "count");
        json_integer(w, (long long)t->class_count[c]);
        json_key(w, "area");
        json_number(w, t->class_area[c]);
        json_end_object(w);
    }
    json_end_object(w);
    json_end_object(w);
}

void report_json(FILE *out, const struct report_source *source,
                 const struct classify_options *options,
                 const struct panelization *panels,
                 const struct option_totals *totals)
{
    struct json_writer w;
    json_init(&w, out);
    json_begin_object(&w);
    json_key(&w, "surface");
    json_begin_object(&w);
    json_key(&w, "file");      json_string(&w, source->file);
    json_key(&w, "units");     json_string(&w, source->units);
    json_key(&w, "area");      json_number(&w, source->area);
    json_key(&w, "triangles"); json_integer(&w, (long long)source->triangles);
    json_key(&w, "uv");        json_string(&w, source->uv_method);
    json_end_object(&w);
    json_key(&w, "grid");
    json_begin_object(&w);
    json_key(&w, "nu");        json_integer(&w, panels->nu);
    json_key(&w, "nv");        json_integer(&w, panels->nv);
    json_end_object(&w);
    json_key(&w, "threshold_mm");
    json_number(&w, units_mm(options->threshold));
    /* null: the tolerance is 8 t / d^2 per panel (each panel's "eps"). */
    json_key(&w, "curvature_tol");
    if (options->curvature_tol > 0)
        json_number(&w, options->curvature_tol);
    else
        json_null(&w);
    json_key(&w, "per_panel");  json_string(&w, source->per_panel);
    json_key(&w, "prices");
    json_begin_object(&w);
    json_key(&w, "FP");         json_number(&w, options->price[TYPE_FP]);
    json_key(&w, "SP");         json_number(&w, options->price[TYPE_SP]);
    json_key(&w, "DP");         json_number(&w, options->price[TYPE_DP]);
    json_key(&w, "sp_as_fp");   json_bool(&w, options->sp_as_fp);
    json_end_object(&w);
    json_key(&w, "max_panel_area_limit");
    json_number(&w, options->max_panel_area);
    /* true: a panel classed SP that no cylinder or cone fits is DP. */
    json_key(&w, "sp_fit");     json_bool(&w, !options->sp_by_class);
    /* null without a limit (json_number writes NaN as null) */
    json_key(&w, "max_gap_mm");
    json_number(&w, options->max_gap > 0 ? units_mm(options->max_gap) : NAN);
    json_key(&w, "max_kink_deg");
    json_number(&w, options->max_kink > 0 ? units_deg(options->max_kink)
                                          : NAN);
    json_key(&w, "min_panel_width_limit");
    json_number(&w, options->min_panel_width > 0 ? options->min_panel_width
                                                 : NAN);

    json_key(&w, "panels");
    json_begin_array(&w);
    for (size_t n = 0; n < panels->npanels; n++) {
        const struct panel *p = &panels->panels[n];
        json_begin_object(&w);
        json_key(&w, "i");         json_integer(&w, p->i);
        json_key(&w, "j");         json_integer(&w, p->j);
        json_key(&w, "class");     json_string(&w, panel_class_name(p->class));
        json_key(&w, "type");      json_string(&w, panel_type_name(p->type));
        json_key(&w, "area");      json_number(&w, p->area);
        json_key(&w, "deviation"); json_number(&w, p->deviation);
        json_key(&w, "k1");        json_number(&w, p->k1);
        json_key(&w, "k2");        json_number(&w, p->k2);
        json_key(&w, "K");         json_number(&w, p->K);
        json_key(&w, "H");         json_number(&w, p->H);
        json_key(&w, "eps");       json_number(&w, p->curvature_tol);
        json_key(&w, "p_dist");    json_number(&w, p->p_dist);
        json_key(&w, "diameter");  json_number(&w, p->diameter);
        json_key(&w, "trimmed");   json_bool(&w, p->trimmed);
        json_key(&w, "corner_planarity");
        json_number(&w, p->corner_planarity);
        json_key(&w, "cost");      json_number(&w, p->cost);
        json_key(&w, "mould");
        if (p->mould >= 0)
            json_integer(&w, p->mould);
        else
            json_null(&w);
        json_key(&w, "built_type");
        json_string(&w, panel_type_name(p->built));
        json_key(&w, "sp_deviation");   json_number(&w, p->sp_deviation);
        json_key(&w, "worst_gap");      json_number(&w, units_mm(p->worst_gap));
        json_key(&w, "worst_kink");     json_number(&w, units_deg(p->worst_kink));
        json_key(&w, "misfit_reason");
        char reason[200];
        classify_misfit_reason(panels, n, reason, sizeof reason);
        if (reason[0] != '\0')
            json_string(&w, reason);
        else
            json_null(&w);
        json_key(&w, "corner_distance");
        json_number(&w, panel_corner_distance(panels, n));
        json_key(&w, "corner_moved");
        json_number(&w, panel_corner_moved(panels, n));
        json_end_object(&w);
    }
    json_end_array(&w);
    json_key(&w, "totals");
    json_totals(&w, totals,
                classify_fp_over_threshold(panels, options, NULL));
    json_end_object(&w);
    json_finish(&w);
}

/* A CSV number, written so that it reads back exactly (numformat.h):
 * empty for NaN (a corner off the surface). */
static void csv_number(FILE *out, double x)
{
    fputc(',', out);
    if (isfinite(x)) {
        char text[NUMBER_EXACT_SIZE];
        number_exact(text, x);
        fputs(text, out);
    }
}

/* A CSV text field: as it is, or quoted (RFC 4180, quotes doubled) when
 * it holds a comma, a quote or a line break. */
static void csv_text(FILE *out, const char *text)
{
    if (strpbrk(text, ",\"\r\n") == NULL) {
        fputs(text, out);
        return;
    }
    fputc('"', out);
    for (const char *c = text; *c; c++) {
        if (*c == '"')
            fputc('"', out);
        fputc(*c, out);
    }
    fputc('"', out);
}

void report_seams_csv(FILE *out, const struct building_seam_joint *joints,
                      size_t n, const char *const *names,
                      const size_t *first_id)
{
    fputs("seam,surface_a,panel_a,surface_b,panel_b,gap_mm,kink_deg,"
          "crease_deg,added_kink_deg\n", out);
    for (size_t k = 0; k < n; k++) {
        const struct building_seam_joint *s = &joints[k];
        fprintf(out, "%zu,", s->seam + 1);
        csv_text(out, names[s->a]);
        fprintf(out, ",%zu,", first_id[s->a] + (size_t)s->joint.panel_a);
        csv_text(out, names[s->b]);
        fprintf(out, ",%zu", first_id[s->b] + (size_t)s->joint.panel_b);
        csv_number(out, units_mm(s->joint.gap));
        csv_number(out, units_deg(s->joint.kink));
        csv_number(out, units_deg(s->joint.crease));
        csv_number(out, units_deg(s->joint.added));
        fputc('\n', out);
    }
}

void report_csv_header(FILE *out, int with_surface)
{
    fputs(with_surface ? "id,surface,i,j" : "id,i,j", out);
    fputs(",class,type,area_m2,deviation_m,k1,k2,K,H,eps,p_dist_m4,"
          "diameter_m,trimmed,corner_planarity_m,price_usd_m2,cost_usd", out);
    for (int c = 0; c < 4; c++)
        fprintf(out, ",c%d_x_m,c%d_y_m,c%d_z_m", c, c, c);
    fputs(",mould_family,built_type,sp_deviation_m,worst_gap_mm,"
          "worst_kink_deg,misfit_reason,corner_distance_m,corner_moved_m\n",
          out);
}

void report_csv_rows(FILE *out, const struct panelization *panels,
                     const char *surface, size_t first_id)
{
    for (size_t n = 0; n < panels->npanels; n++) {
        const struct panel *p = &panels->panels[n];
        fprintf(out, "%zu,", first_id + n);
        if (surface != NULL) {
            csv_text(out, surface);
            fputc(',', out);
        }
        fprintf(out, "%d,%d,%s,%s", p->i, p->j,
                panel_class_name(p->class), panel_type_name(p->type));
        csv_number(out, p->area);
        csv_number(out, p->deviation);
        csv_number(out, p->k1);
        csv_number(out, p->k2);
        csv_number(out, p->K);
        csv_number(out, p->H);
        csv_number(out, p->curvature_tol);
        csv_number(out, p->p_dist);
        csv_number(out, p->diameter);
        fprintf(out, ",%d", p->trimmed);
        csv_number(out, p->corner_planarity);
        csv_number(out, p->price);
        csv_number(out, p->cost);
        for (int c = 0; c < 4; c++)
            for (int d = 0; d < 3; d++)
                csv_number(out, p->corner[c][d]);
        fputc(',', out);
        if (p->mould >= 0)
            fprintf(out, "%d", p->mould);
        fprintf(out, ",%s", panel_type_name(p->built));
        csv_number(out, p->sp_deviation);
        csv_number(out, units_mm(p->worst_gap));
        csv_number(out, units_deg(p->worst_kink));
        /* The reason holds commas: quoted (RFC 4180), never a quote in
         * it (sp_fit.h's wording). */
        char reason[200];
        classify_misfit_reason(panels, n, reason, sizeof reason);
        if (reason[0] != '\0')
            fprintf(out, ",\"%s\"", reason);
        else
            fputc(',', out);
        csv_number(out, panel_corner_distance(panels, n));
        csv_number(out, panel_corner_moved(panels, n));
        fputc('\n', out);
    }
}

void report_csv(FILE *out, const struct panelization *panels)
{
    report_csv_header(out, 0);
    report_csv_rows(out, panels, NULL, 1);
}

/* The totals CSV's first columns, in the order they had before the
 * quantity table held every quantity: kept first, so that a spreadsheet
 * that reads them by position still finds them. Every other quantity of
 * the totals follows in the table's order (totals_column), so that one
 * added to the table (a building's seams, issue 31) is a column here
 * without a line of its own. */
static const char *const first_columns[] = {
    "panels", "fp_count", "sp_count", "dp_count", "area", "fp_area",
    "sp_area", "dp_area", "fp_cost", "sp_cost", "dp_cost", "cost",
    "planarity", "max_deviation", "max_panel_area", "p_dist", "feasible",
    "joint_length", "moulds", "sp_moulds", "dp_moulds", "largest_family",
    "single_moulds", "area_cost", "panel_cost", "joint_cost", "mould_cost",
    "max_gap", "mean_gap", "max_kink", "mean_kink", "gaps_over",
    "kinks_over", "sp_misfits", "sp_fitted",
};
enum { FIRST_COLUMNS = sizeof first_columns / sizeof *first_columns };

static int is_first_column(const struct quantity *q)
{
    for (size_t k = 0; k < FIRST_COLUMNS; k++)
        if (strcmp(first_columns[k], q->name) == 0)
            return 1;
    return 0;
}

/* The quantity of the totals CSV's column k (from 0), NULL past the
 * last: first_columns, then every other quantity of the totals
 * (quantity_in_totals) in option_quantities' order. */
static const struct quantity *totals_column(size_t k)
{
    if (k < FIRST_COLUMNS) {
        const struct quantity *q = quantity_named(first_columns[k]);
        assert(q != NULL && quantity_in_totals(q));
        return q;
    }
    k -= FIRST_COLUMNS;
    for (size_t c = 0; c < OPTION_QUANTITIES; c++) {
        const struct quantity *q = &option_quantities[c];
        if (!quantity_in_totals(q) || is_first_column(q))
            continue;
        if (k-- == 0)
            return q;
    }
    return NULL;
}

void report_totals_csv(FILE *out, const struct option_totals *t)
{
    const struct quantity *q;
    for (size_t k = 0; (q = totals_column(k)) != NULL; k++) {
        char name[64];
        quantity_csv_name(q, name, sizeof name);
        fprintf(out, "%s%s", k ? "," : "", name);
    }
    fputc('\n', out);
    for (size_t k = 0; (q = totals_column(k)) != NULL; k++) {
        double value = quantity_of_totals(q, t);
        if (q->yes_no && !isnan(value))
            value = value != 0;
        /* csv_number writes its comma first */
        if (k == 0) {
            char text[NUMBER_EXACT_SIZE] = "";
            if (isfinite(value))
                number_exact(text, value);
            fputs(text, out);
        } else {
            csv_number(out, value);
        }
    }
    fputc('\n', out);
}
