/*
 * xlsx_schedule.c: the panel schedule as XLSX. See xlsx_schedule.h.
 */
#include "core/out/xlsx_schedule.h"

#include <assert.h>
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <xlsxwriter.h>

#include "core/quantity/quantity.h"
#include "core/base/units.h"

/* The number formats, one per kind of value. */
struct formats {
    lxw_format *header, *text, *count, *area, *metre, *unit_vector, *mm,
        *degree, *usd;
};

struct sheet {
    lxw_worksheet *ws;
    lxw_row_t row;
    lxw_error error;   /* the first cell libxlsxwriter refused, if any */
};

/* Keeps the first error of a cell written to s. */
static void keep(struct sheet *s, lxw_error e)
{
    if (e != LXW_NO_ERROR && s->error == LXW_NO_ERROR)
        s->error = e;
}

static void make_formats(lxw_workbook *wb, struct formats *f)
{
    f->header = workbook_add_format(wb);
    format_set_bold(f->header);
    format_set_text_wrap(f->header);
    format_set_bottom(f->header, LXW_BORDER_THIN);
    f->text = NULL;
    f->count = workbook_add_format(wb);
    format_set_num_format(f->count, "0");
    f->area = workbook_add_format(wb);
    format_set_num_format(f->area, "0.000");
    f->metre = workbook_add_format(wb);
    format_set_num_format(f->metre, "0.000");
    f->unit_vector = workbook_add_format(wb);
    format_set_num_format(f->unit_vector, "0.00000");
    f->mm = workbook_add_format(wb);
    format_set_num_format(f->mm, "0.00");
    f->degree = workbook_add_format(wb);
    format_set_num_format(f->degree, "0.00");
    f->usd = workbook_add_format(wb);
    format_set_num_format(f->usd, "#,##0.00");
}

/* A column of a sheet: its header (with its unit), width and format. */
struct column {
    const char *header;
    double width;
    int kind;  /* index into the formats, below */
};

enum { K_TEXT, K_COUNT, K_AREA, K_METRE, K_UNIT, K_MM, K_DEGREE, K_USD };

static lxw_format *format_of(const struct formats *f, int kind)
{
    switch (kind) {
    case K_COUNT:  return f->count;
    case K_AREA:   return f->area;
    case K_METRE:  return f->metre;
    case K_UNIT:   return f->unit_vector;
    case K_MM:     return f->mm;
    case K_DEGREE: return f->degree;
    case K_USD:    return f->usd;
    default:       return f->text;
    }
}

/* The header row (frozen) and the columns' widths and formats. */
static void write_header(struct sheet *s, const struct formats *f,
                         const struct column *c, int n)
{
    for (int k = 0; k < n; k++) {
        worksheet_set_column(s->ws, (lxw_col_t)k, (lxw_col_t)k, c[k].width,
                             format_of(f, c[k].kind));
        keep(s, worksheet_write_string(s->ws, 0, (lxw_col_t)k, c[k].header,
                                       f->header));
    }
    worksheet_set_row(s->ws, 0, 30, NULL);
    worksheet_freeze_panes(s->ws, 1, 0);
    s->row = 1;
}

/* A number cell, or an empty one for a value not known. */
static void number(struct sheet *s, lxw_col_t col, double value,
                   lxw_format *format)
{
    if (isfinite(value))
        keep(s, worksheet_write_number(s->ws, s->row, col, value, format));
    else
        keep(s, worksheet_write_blank(s->ws, s->row, col, format));
}

static void text(struct sheet *s, lxw_col_t col, const char *value)
{
    keep(s, worksheet_write_string(s->ws, s->row, col, value, NULL));
}

/* The extent of panel p's corners along two directions in its best-fit
 * plane: along its first side (corner 0 to 1, the panel's i direction)
 * and across it. NaN for a trimmed panel or one whose corners are not
 * all on the surface: its outline is not its corners. */
static void corner_size(const struct panel *p, double size[2])
{
    size[0] = size[1] = NAN;
    if (p->trimmed || p->ncorners != 4)
        return;
    const double *n = p->normal;
    double d[3], e1[3], e2[3];
    for (int k = 0; k < 3; k++)
        d[k] = p->corner[1][k] - p->corner[0][k];
    double along = d[0] * n[0] + d[1] * n[1] + d[2] * n[2];
    for (int k = 0; k < 3; k++)
        e1[k] = d[k] - along * n[k];
    double length = sqrt(e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2]);
    if (!(length > 0))
        return;
    for (int k = 0; k < 3; k++)
        e1[k] /= length;
    e2[0] = n[1] * e1[2] - n[2] * e1[1];
    e2[1] = n[2] * e1[0] - n[0] * e1[2];
    e2[2] = n[0] * e1[1] - n[1] * e1[0];
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (int c = 0; c < 4; c++) {
        const double *q = p->corner[c];
        double a = q[0] * e1[0] + q[1] * e1[1] + q[2] * e1[2];
        double b = q[0] * e2[0] + q[1] * e2[1] + q[2] * e2[2];
        lo[0] = fmin(lo[0], a);
        hi[0] = fmax(hi[0], a);
        lo[1] = fmin(lo[1], b);
        hi[1] = fmax(hi[1], b);
    }
    size[0] = hi[0] - lo[0];
    size[1] = hi[1] - lo[1];
}

/* The bending radius and the fitted surface of panel p (b: its fit, or
 * NULL for none: empty cells), from column c; returns the next column. */
static lxw_col_t write_fit(struct sheet *s, const struct formats *f,
                           lxw_col_t c, const struct panel *p,
                           const struct built_panel *b)
{
    double foot[3] = {NAN, NAN, NAN}, axis[3] = {NAN, NAN, NAN};
    double apex[3] = {NAN, NAN, NAN}, alpha = NAN;
    int cone = 0;
    if (b != NULL) {
        alpha = developable_describe(&b->fit, p->centroid, foot, axis, apex);
        cone = isfinite(apex[0]);
    }
    number(s, c++, b ? b->bending_radius : NAN, f->metre);
    if (b != NULL)
        text(s, c, cone ? "cone" : "cylinder");
    c++;
    for (int d = 0; d < 3; d++)
        number(s, c++, foot[d], f->metre);
    for (int d = 0; d < 3; d++)
        number(s, c++, axis[d], f->unit_vector);
    number(s, c++, b && !cone ? b->fit.radius : NAN, f->metre);
    for (int d = 0; d < 3; d++)
        number(s, c++, apex[d], f->metre);
    number(s, c++, cone ? units_deg(alpha) : NAN, f->degree);
    number(s, c++, b ? units_mm(b->sp_deviation) : NAN, f->mm);
    return c;
}

static const struct column panel_columns[] = {
    {"id", 7, K_COUNT},
    {"surface", 16, K_TEXT},
    {"column i", 8, K_COUNT},
    {"row j", 8, K_COUNT},
    {"type as classed", 9, K_TEXT},
    {"type as built", 9, K_TEXT},
    {"class", 22, K_TEXT},
    {"area (m^2)", 10, K_AREA},
    {"size along i (m)", 10, K_METRE},
    {"size across i (m)", 10, K_METRE},
    {"centroid x (m)", 11, K_METRE},
    {"centroid y (m)", 11, K_METRE},
    {"centroid z (m)", 11, K_METRE},
    {"normal x", 9, K_UNIT},
    {"normal y", 9, K_UNIT},
    {"normal z", 9, K_UNIT},
    {"corner 0 x (m)", 11, K_METRE},
    {"corner 0 y (m)", 11, K_METRE},
    {"corner 0 z (m)", 11, K_METRE},
    {"corner 1 x (m)", 11, K_METRE},
    {"corner 1 y (m)", 11, K_METRE},
    {"corner 1 z (m)", 11, K_METRE},
    {"corner 2 x (m)", 11, K_METRE},
    {"corner 2 y (m)", 11, K_METRE},
    {"corner 2 z (m)", 11, K_METRE},
    {"corner 3 x (m)", 11, K_METRE},
    {"corner 3 y (m)", 11, K_METRE},
    {"corner 3 z (m)", 11, K_METRE},
    {"deviation (mm)", 10, K_MM},
    {"corner distance (mm)", 10, K_MM},
    {"corner moved (mm)", 10, K_MM},
    {"SP bending radius (m)", 11, K_METRE},
    {"SP fitted surface", 10, K_TEXT},
    {"SP axis point x (m)", 11, K_METRE},
    {"SP axis point y (m)", 11, K_METRE},
    {"SP axis point z (m)", 11, K_METRE},
    {"SP axis direction x", 10, K_UNIT},
    {"SP axis direction y", 10, K_UNIT},
    {"SP axis direction z", 10, K_UNIT},
    {"SP cylinder radius (m)", 11, K_METRE},
    {"SP cone apex x (m)", 11, K_METRE},
    {"SP cone apex y (m)", 11, K_METRE},
    {"SP cone apex z (m)", 11, K_METRE},
    {"SP cone half-angle (deg)", 11, K_DEGREE},
    {"SP deviation (mm)", 10, K_MM},
    {"worst gap (mm)", 10, K_MM},
    {"worst kink (deg)", 10, K_DEGREE},
    {"mould family", 9, K_COUNT},
    {"price (USD/m^2)", 11, K_USD},
    {"cost (USD)", 13, K_USD},
};
#define PANEL_COLUMNS (int)(sizeof panel_columns / sizeof panel_columns[0])

static void write_panels(struct sheet *s, const struct formats *f,
                         const struct xlsx_schedule *x,
                         const size_t *first_id)
{
    write_header(s, f, panel_columns, PANEL_COLUMNS);
    for (size_t k = 0; k < x->nsurfaces; k++) {
        const struct xlsx_surface *surface = &x->surfaces[k];
        for (size_t n = 0; n < surface->panels->npanels; n++) {
            const struct panel *p = &surface->panels->panels[n];
            lxw_col_t c = 0;
            number(s, c++, (double)(first_id[k] + n), f->count);
            text(s, c++, surface->name);
            number(s, c++, p->i, f->count);
            number(s, c++, p->j, f->count);
            text(s, c++, panel_type_name(p->type));
            text(s, c++, panel_type_name(p->built));
            text(s, c++, panel_class_name(p->class));
            number(s, c++, p->area, f->area);
            double size[2];
            corner_size(p, size);
            number(s, c++, size[0], f->metre);
            number(s, c++, size[1], f->metre);
            for (int d = 0; d < 3; d++)
                number(s, c++, p->centroid[d], f->metre);
            for (int d = 0; d < 3; d++)
                number(s, c++, p->normal[d], f->unit_vector);
            for (int q = 0; q < 4; q++)
                for (int d = 0; d < 3; d++)
                    number(s, c++, p->corner[q][d], f->metre);
            number(s, c++, units_mm(p->deviation), f->mm);
            number(s, c++,
                   units_mm(panel_corner_distance(surface->panels, n)),
                   f->mm);
            number(s, c++, units_mm(panel_corner_moved(surface->panels, n)),
                   f->mm);
            c = write_fit(s, f, c, p,
                          surface->sp_fit && surface->sp_fit[n].fitted
                              ? &surface->sp_fit[n] : NULL);
            number(s, c++, units_mm(p->worst_gap), f->mm);
            number(s, c++, units_deg(p->worst_kink), f->degree);
            number(s, c++, p->mould >= 0 ? p->mould : NAN, f->count);
            number(s, c++, p->price, f->usd);
            number(s, c++, p->cost, f->usd);
            assert(c == PANEL_COLUMNS);
            s->row++;
        }
    }
}

static const struct column mould_columns[] = {
    {"mould family", 9, K_COUNT},
    {"type", 22, K_TEXT},
    {"members", 9, K_COUNT},
    {"representative panel id", 14, K_COUNT},
    {"cost (USD)", 13, K_USD},
};

/* The families, from the panels' own: a family's members are the panels
 * that name it, its representative the first of them in the building's
 * order (mould.h), its type theirs as built. */
static int write_moulds(struct sheet *s, const struct formats *f,
                        const struct xlsx_schedule *x, const size_t *first_id,
                        struct facet_error *err)
{
    write_header(s, f, mould_columns, 5);
    size_t families = 0;
    for (size_t k = 0; k < x->nsurfaces; k++)
        for (size_t n = 0; n < x->surfaces[k].panels->npanels; n++) {
            int m = x->surfaces[k].panels->panels[n].mould;
            if (m >= 0 && (size_t)m + 1 > families)
                families = (size_t)m + 1;
        }
    size_t *members = calloc(families ? families : 1, sizeof *members);
    size_t *first = calloc(families ? families : 1, sizeof *first);
    int *type = calloc(families ? families : 1, sizeof *type);
    if (!members || !first || !type) {
        free(members);
        free(first);
        free(type);
        return facet_error_set(err, FACET_EWORK, "out of memory");
    }
    for (size_t k = 0; k < x->nsurfaces; k++)
        for (size_t n = 0; n < x->surfaces[k].panels->npanels; n++) {
            const struct panel *p = &x->surfaces[k].panels->panels[n];
            if (p->mould < 0)
                continue;
            if (members[p->mould]++ == 0) {
                first[p->mould] = first_id[k] + n;
                type[p->mould] = (int)p->built;
            }
        }
    for (size_t m = 0; m < families; m++) {
        if (members[m] == 0)
            continue;  /* a number no panel names: none */
        enum panel_type t = (enum panel_type)type[m];
        number(s, 0, (double)m, f->count);
        text(s, 1, t == TYPE_SP ? "SP (bending jig)"
                   : t == TYPE_DP ? "DP (mould)" : panel_type_name(t));
        number(s, 2, (double)members[m], f->count);
        number(s, 3, (double)first[m], f->count);
        number(s, 4, x->classify->mould_cost[t], f->usd);
        s->row++;
    }
    free(members);
    free(first);
    free(type);
    return FACET_OK;
}

/* The heading of quantity q with its unit: "max deviation (mm)". */
static void quantity_heading(const struct quantity *q, char *out,
                             size_t size)
{
    if (q->unit[0])
        snprintf(out, size, "%s (%s)", q->label, q->unit);
    else
        snprintf(out, size, "%s", q->label);
}

/* The format of a quantity as shown: its decimals, its separators. */
static lxw_format *quantity_format(lxw_workbook *wb, const struct quantity *q)
{
    char pattern[64];
    if (q->yes_no)
        snprintf(pattern, sizeof pattern, "\"yes\";\"yes\";\"no\"");
    else
        snprintf(pattern, sizeof pattern, "%s%s%.*s",
                 q->thousands ? "#,##0" : "0", q->decimals > 0 ? "." : "",
                 q->decimals, "0000000000");
    lxw_format *format = workbook_add_format(wb);
    format_set_num_format(format, pattern);
    return format;
}

/* The surfaces sheet's quantities, by name (quantity.h). */
static const char *const surface_quantities[] = {
    "panels", "fp_count", "sp_count", "dp_count", "area", "fp_area",
    "sp_area", "dp_area", "cost", "moulds", "max_deviation", "max_gap",
    "max_kink", "sp_misfits",
};
#define SURFACE_QUANTITIES \
    (int)(sizeof surface_quantities / sizeof surface_quantities[0])

static void write_surfaces(lxw_workbook *wb, struct sheet *s,
                           const struct formats *f,
                           const struct xlsx_schedule *x)
{
    struct column c[3 + SURFACE_QUANTITIES + 1];
    char heading[SURFACE_QUANTITIES][96];
    const struct quantity *q[SURFACE_QUANTITIES];
    c[0] = (struct column){"surface", 16, K_TEXT};
    c[1] = (struct column){"U panels", 8, K_COUNT};
    c[2] = (struct column){"V panels", 8, K_COUNT};
    for (int k = 0; k < SURFACE_QUANTITIES; k++) {
        q[k] = quantity_named(surface_quantities[k]);
        assert(q[k] != NULL && quantity_in_totals(q[k]));
        quantity_heading(q[k], heading[k], sizeof heading[k]);
        c[3 + k] = (struct column){heading[k], 12, K_TEXT};
    }
    c[3 + SURFACE_QUANTITIES] = (struct column){"moulds used", 9, K_COUNT};
    write_header(s, f, c, 3 + SURFACE_QUANTITIES + 1);
    lxw_format *format[SURFACE_QUANTITIES];
    for (int k = 0; k < SURFACE_QUANTITIES; k++)
        format[k] = quantity_format(wb, q[k]);
    for (size_t k = 0; k < x->nsurfaces; k++) {
        const struct xlsx_surface *surface = &x->surfaces[k];
        text(s, 0, surface->name);
        number(s, 1, surface->panels->nu, f->count);
        number(s, 2, surface->panels->nv, f->count);
        for (int m = 0; m < SURFACE_QUANTITIES; m++)
            number(s, (lxw_col_t)(3 + m),
                   quantity_of_totals(q[m], surface->totals) * q[m]->scale,
                   format[m]);
        number(s, 3 + SURFACE_QUANTITIES, (double)surface->moulds_used,
               f->count);
        s->row++;
    }
}

static const struct column total_columns[] = {
    {"quantity", 26, K_TEXT},
    {"label", 30, K_TEXT},
    {"value", 16, K_TEXT},
    {"unit", 7, K_TEXT},
};

/* Every quantity of the totals, in the registry's order, as shown. */
static void write_totals(lxw_workbook *wb, struct sheet *s,
                         const struct formats *f,
                         const struct xlsx_schedule *x)
{
    write_header(s, f, total_columns, 4);
    for (int k = 0; k < OPTION_QUANTITIES; k++) {
        const struct quantity *q = &option_quantities[k];
        if (!quantity_in_totals(q))
            continue;
        text(s, 0, q->name);
        text(s, 1, q->label);
        number(s, 2, quantity_of_totals(q, x->totals) * q->scale,
               quantity_format(wb, q));
        text(s, 3, q->unit);
        s->row++;
    }
}

static const struct column seam_columns[] = {
    {"seam", 7, K_COUNT},
    {"surface a", 16, K_TEXT},
    {"panel a", 8, K_COUNT},
    {"surface b", 16, K_TEXT},
    {"panel b", 8, K_COUNT},
    {"gap (mm)", 10, K_MM},
    {"kink (deg)", 10, K_DEGREE},
    {"crease (deg)", 10, K_DEGREE},
    {"added kink (deg)", 10, K_DEGREE},
};
#define SEAM_COLUMNS (int)(sizeof seam_columns / sizeof seam_columns[0])

/* Every seam joint, its panels by the panels sheet's ids. */
static void write_seams(struct sheet *s, const struct formats *f,
                        const struct xlsx_schedule *x, const size_t *first_id)
{
    write_header(s, f, seam_columns, SEAM_COLUMNS);
    for (size_t k = 0; k < x->nseam_joints; k++) {
        const struct building_seam_joint *j = &x->seam_joints[k];
        assert(j->a < x->nsurfaces && j->b < x->nsurfaces);
        lxw_col_t c = 0;
        number(s, c++, (double)(j->seam + 1), f->count);
        text(s, c++, x->surfaces[j->a].name);
        number(s, c++, (double)(first_id[j->a] + (size_t)j->joint.panel_a),
               f->count);
        text(s, c++, x->surfaces[j->b].name);
        number(s, c++, (double)(first_id[j->b] + (size_t)j->joint.panel_b),
               f->count);
        number(s, c++, units_mm(j->joint.gap), f->mm);
        number(s, c++, units_deg(j->joint.kink), f->degree);
        number(s, c++, units_deg(j->joint.crease), f->degree);
        number(s, c++, units_deg(j->joint.added), f->degree);
        assert(c == SEAM_COLUMNS);
        s->row++;
    }
}

/* Copies the file at path into out. */
static int copy_into(const char *path, FILE *out, struct facet_error *err)
{
    FILE *in = fopen(path, "rb");
    if (in == NULL)
        return facet_error_set(err, FACET_EWORK, "reading the workbook "
                               "back from %s: %s", path, strerror(errno));
    char buffer[65536];
    size_t n;
    int rc = FACET_OK;
    while ((n = fread(buffer, 1, sizeof buffer, in)) > 0)
        if (fwrite(buffer, 1, n, out) != n) {
            rc = facet_error_set(err, FACET_EWORK, "writing the workbook "
                                 "failed: %s", strerror(errno));
            break;
        }
    if (rc == FACET_OK && ferror(in))
        rc = facet_error_set(err, FACET_EWORK, "reading the workbook back "
                             "from %s failed", path);
    fclose(in);
    return rc;
}

int xlsx_schedule_write(FILE *out, const struct xlsx_schedule *x,
                        struct facet_error *err)
{
    /* A sheet holds LXW_ROW_MAX rows, the header one of them: more panels
     * would be cut off without a word. */
    size_t npanels = 0;
    for (size_t k = 0; k < x->nsurfaces; k++)
        npanels += x->surfaces[k].panels->npanels;
    if (npanels > (size_t)LXW_ROW_MAX - 1)
        return facet_error_set(err, FACET_EINPUT, "%zu panels: more than "
                               "an XLSX sheet holds (%lu rows); the CSV "
                               "schedule holds them all", npanels,
                               (unsigned long)LXW_ROW_MAX - 1);
    if (x->nseam_joints > (size_t)LXW_ROW_MAX - 1)
        return facet_error_set(err, FACET_EINPUT, "%zu seam joints: more "
                               "than an XLSX sheet holds (%lu rows); the "
                               "seams CSV holds them all", x->nseam_joints,
                               (unsigned long)LXW_ROW_MAX - 1);
    const char *folder = getenv("TMPDIR");
    if (folder == NULL || folder[0] == '\0')
        folder = "/tmp";
    char path[4096];
    if (snprintf(path, sizeof path, "%s/facet-xlsx-XXXXXX", folder) >=
        (int)sizeof path)
        return facet_error_set(err, FACET_EWORK, "TMPDIR is too long");
    int fd = mkstemp(path);
    if (fd < 0)
        return facet_error_set(err, FACET_EWORK, "cannot make a temporary "
                               "file in %s: %s", folder, strerror(errno));
    close(fd);
    /* Rows go out in order: constant memory keeps 45,000 panels small. */
    lxw_workbook_options options = {.constant_memory = LXW_TRUE,
                                    .tmpdir = (char *)folder};
    lxw_workbook *wb = workbook_new_opt(path, &options);
    if (wb == NULL) {
        remove(path);
        return facet_error_set(err, FACET_EWORK, "cannot start a workbook "
                               "in %s", path);
    }
    lxw_doc_properties properties = {0};
    properties.title = (char *)x->title;
    properties.author = (char *)"Facet";
    properties.created = x->created;
    workbook_set_properties(wb, &properties);
    struct formats f;
    make_formats(wb, &f);
    struct sheet panels = {workbook_add_worksheet(wb, "panels"), 0, 0};
    struct sheet moulds = {workbook_add_worksheet(wb, "moulds"), 0, 0};
    struct sheet surfaces = {x->building ? workbook_add_worksheet(
                                               wb, "surfaces") : NULL, 0, 0};
    struct sheet seams = {x->seam_joints != NULL ? workbook_add_worksheet(
                                                       wb, "seams") : NULL,
                          0, 0};
    struct sheet totals = {workbook_add_worksheet(wb, "totals"), 0, 0};
    /* The panels' ids, 1.. over the surfaces in order (the CSV's):
     * first_id[k] is surface k's first, for every sheet that names one. */
    size_t *first_id = malloc((x->nsurfaces ? x->nsurfaces : 1) *
                              sizeof *first_id);
    int rc = FACET_OK;
    if (!panels.ws || !moulds.ws || !totals.ws || first_id == NULL ||
        (x->building && !surfaces.ws) || (x->seam_joints && !seams.ws))
        rc = facet_error_set(err, FACET_EWORK, "out of memory (workbook)");
    for (size_t k = 0, id = 1; rc == FACET_OK && k < x->nsurfaces; k++) {
        first_id[k] = id;
        id += x->surfaces[k].panels->npanels;
    }
    if (rc == FACET_OK) {
        write_panels(&panels, &f, x, first_id);
        rc = write_moulds(&moulds, &f, x, first_id, err);
    }
    if (rc == FACET_OK && x->building)
        write_surfaces(wb, &surfaces, &f, x);
    if (rc == FACET_OK && x->seam_joints != NULL)
        write_seams(&seams, &f, x, first_id);
    if (rc == FACET_OK)
        write_totals(wb, &totals, &f, x);
    free(first_id);
    /* A cell refused is a schedule with a hole in it: not written. */
    const struct sheet *sheets[5] = {&panels, &moulds, &surfaces, &seams,
                                     &totals};
    for (int k = 0; rc == FACET_OK && k < 5; k++)
        if (sheets[k]->error != LXW_NO_ERROR)
            rc = facet_error_set(err, FACET_EWORK, "writing the workbook "
                                 "failed: %s",
                                 lxw_strerror(sheets[k]->error));
    lxw_error closed = workbook_close(wb);
    if (rc == FACET_OK && closed != LXW_NO_ERROR)
        rc = facet_error_set(err, FACET_EWORK, "writing the workbook "
                             "failed: %s", lxw_strerror(closed));
    if (rc == FACET_OK)
        rc = copy_into(path, out, err);
    remove(path);
    return rc;
}
