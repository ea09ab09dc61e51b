/*
 * dxf_patterns.c: flat patterns as DXF. See dxf_patterns.h.
 */
#include "core/out/dxf_patterns.h"

#include <assert.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/base/numformat.h"
#include "core/base/numparse.h"
#include "core/base/units.h"

/* The space between two sheets side by side (m). */
#define SHEET_GAP 0.200

/* One panel's pattern and where it goes. */
struct part {
    size_t surface, panel, id;
    double lo[2];        /* its bounding box's lower corner, as turned */
    double size[2];      /* its bounding box (m), as turned */
    double turn;         /* turned by this (rad, counter-clockwise): its
                            least box, landscape (unroll.h), and a
                            quarter more when only so it fits */
    double c, s;         /* cos and sin of turn */
    size_t sheet;
    double at[2];        /* where lo goes on its sheet (m) */
};

/* A pattern point of p (m), turned as p is. */
static void turn(const struct part *p, const double in[2], double out[2])
{
    out[0] = p->c * in[0] - p->s * in[1];
    out[1] = p->s * in[0] + p->c * in[1];
}

/* Where pattern point in (m) of p lies in the drawing (m). */
static void placed(const struct part *p, double sheet_step,
                   const double in[2], double out[2])
{
    double t[2];
    turn(p, in, t);
    out[0] = t[0] - p->lo[0] + p->at[0] + (double)p->sheet * sheet_step;
    out[1] = t[1] - p->lo[1] + p->at[1];
}

static void bounding_box(struct part *p, const struct dxf_surface *s)
{
    const struct panel_geometry *g = s->geometry;
    size_t first = g->loop_start[g->panel_loop[p->panel]];
    size_t end = g->loop_start[g->panel_loop[p->panel + 1]];
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (size_t k = first; k < end; k++) {
        double t[2];
        turn(p, s->patterns->flat + 2 * k, t);
        for (int c = 0; c < 2; c++) {
            lo[c] = fmin(lo[c], t[c]);
            hi[c] = fmax(hi[c], t[c]);
        }
    }
    for (int c = 0; c < 2; c++) {
        p->lo[c] = lo[c];
        p->size[c] = hi[c] - lo[c];
    }
}

/* Tallest first, then by id: the order the shelves are filled in. */
static int taller_first(const void *a, const void *b)
{
    const struct part *p = a, *q = b;
    if (p->size[1] != q->size[1])
        return p->size[1] > q->size[1] ? -1 : 1;
    return p->id < q->id ? -1 : p->id > q->id;
}

static int by_id(const void *a, const void *b)
{
    const struct part *p = a, *q = b;
    return p->id < q->id ? -1 : p->id > q->id;
}

/* A sheet side that holds a pattern side of size (m) within its
 * margins, in whole steps of DXF_SHEET_STEP. */
static double side_to_hold(double size)
{
    return ceil((size + 2 * DXF_MARGIN) / DXF_SHEET_STEP) * DXF_SHEET_STEP;
}

/* Sizes, turns and places every part on sheets of sheet[0] x sheet[1]
 * (m), grown first to hold the largest pattern when x->sheet_grows;
 * FACET_EINPUT for one that fits no sheet. */
static int layout(const struct dxf_patterns *x, double sheet[2],
                  struct part *parts, size_t n, double *hull, size_t *order,
                  size_t *nsheets, struct facet_error *err)
{
    for (size_t k = 0; k < n; k++) {
        struct part *p = &parts[k];
        const struct dxf_surface *s = &x->surfaces[p->surface];
        const struct panel_geometry *g = s->geometry;
        size_t first = g->loop_start[g->panel_loop[p->panel]];
        size_t count = g->loop_start[g->panel_loop[p->panel + 1]] - first;
        p->turn = unroll_least_box_turn(s->patterns->flat + 2 * first, count,
                                        hull, order);
        p->c = cos(p->turn);
        p->s = sin(p->turn);
        bounding_box(p, s);
        /* The least box is landscape, as the sheets are. */
        if (x->sheet_grows) {
            sheet[0] = fmax(sheet[0], side_to_hold(p->size[0]));
            sheet[1] = fmax(sheet[1], side_to_hold(p->size[1]));
        }
    }
    double room[2] = {sheet[0] - 2 * DXF_MARGIN, sheet[1] - 2 * DXF_MARGIN};
    for (size_t k = 0; k < n; k++) {
        struct part *p = &parts[k];
        const struct dxf_surface *s = &x->surfaces[p->surface];
        if (p->size[0] <= room[0] && p->size[1] <= room[1])
            continue;
        double size[2] = {p->size[0], p->size[1]};
        /* A quarter turn more: exactly, (c, s) to (-s, c). */
        double c = p->c;
        p->c = -p->s;
        p->s = c;
        bounding_box(p, s);
        if (p->size[0] <= room[0] && p->size[1] <= room[1])
            continue;
        const struct panel *panel = &s->panels->panels[p->panel];
        return facet_error_set(err, FACET_EINPUT,
            "panel %zu (%s, cell %d, %d) lies flat in %.0f x %.0f mm: it "
            "does not fit a %.0f x %.0f mm sheet within its %.0f mm "
            "margins, either way round: give a larger sheet",
            p->id, s->name, panel->i, panel->j, units_mm(size[0]),
            units_mm(size[1]), units_mm(sheet[0]), units_mm(sheet[1]),
            units_mm(DXF_MARGIN));
    }
    qsort(parts, n, sizeof *parts, taller_first);
    size_t current = 0;
    double shelf_y = DXF_MARGIN, shelf_height = 0, cursor = DXF_MARGIN;
    for (size_t k = 0; k < n; k++) {
        struct part *p = &parts[k];
        if (cursor + p->size[0] > sheet[0] - DXF_MARGIN) {
            /* The next shelf. */
            shelf_y += shelf_height + DXF_MARGIN;
            shelf_height = 0;
            cursor = DXF_MARGIN;
        }
        if (shelf_y + p->size[1] > sheet[1] - DXF_MARGIN) {
            current++;
            shelf_y = DXF_MARGIN;
            shelf_height = 0;
            cursor = DXF_MARGIN;
        }
        p->sheet = current;
        p->at[0] = cursor;
        p->at[1] = shelf_y;
        cursor += p->size[0] + DXF_MARGIN;
        shelf_height = fmax(shelf_height, p->size[1]);
    }
    *nsheets = n ? current + 1 : 0;
    return FACET_OK;
}

/* ---- Writing: group code and value pairs. */

static void group(FILE *out, int code, const char *value)
{
    fprintf(out, "%3d\n%s\n", code, value);
}

static void integer(FILE *out, int code, long value)
{
    fprintf(out, "%3d\n%ld\n", code, value);
}

/* A length in the drawing, metres written as mm. */
static void mm(FILE *out, int code, double metres)
{
    double v = units_mm(metres);
    if (v == 0)
        v = 0;  /* never "-0.000000" */
    fprintf(out, "%3d\n%.6f\n", code, v);
}

static void point(FILE *out, int code, double x, double y, double z)
{
    mm(out, code, x);
    mm(out, code + 10, y);
    mm(out, code + 20, z);
}

static const char *const layer_of[TYPE_COUNT] = {"FP", "SP", "DP"};
static const char *const outline_layer_of[TYPE_COUNT] = {
    "OUTLINE_3D_FP", "OUTLINE_3D_SP", "OUTLINE_3D_DP"};

/* The header; lo and hi bound everything drawn (m). */
static void header(FILE *out, const double lo[3], const double hi[3])
{
    group(out, 0, "SECTION");
    group(out, 2, "HEADER");
    group(out, 9, "$ACADVER");
    group(out, 1, "AC1009");
    group(out, 9, "$INSUNITS");
    integer(out, 70, 4);
    group(out, 9, "$MEASUREMENT");
    integer(out, 70, 1);
    group(out, 9, "$EXTMIN");
    point(out, 10, lo[0], lo[1], lo[2]);
    group(out, 9, "$EXTMAX");
    point(out, 10, hi[0], hi[1], hi[2]);
    group(out, 0, "ENDSEC");

    group(out, 0, "SECTION");
    group(out, 2, "TABLES");
    group(out, 0, "TABLE");
    group(out, 2, "LTYPE");
    integer(out, 70, 1);
    group(out, 0, "LTYPE");
    group(out, 2, "CONTINUOUS");
    integer(out, 70, 0);
    group(out, 3, "Solid line");
    integer(out, 72, 65);
    integer(out, 73, 0);
    group(out, 40, "0.0");
    group(out, 0, "ENDTAB");
    static const struct {
        const char *name;
        int colour;
    } layers[] = {{"0", 7}, {"FP", 5}, {"SP", 3}, {"DP", 1},
                  {"SHEETS", 8}, {"OUTLINE_3D_FP", 5}, {"OUTLINE_3D_SP", 3},
                  {"OUTLINE_3D_DP", 1}};
    int nlayers = (int)(sizeof layers / sizeof layers[0]);
    group(out, 0, "TABLE");
    group(out, 2, "LAYER");
    integer(out, 70, nlayers);
    for (int k = 0; k < nlayers; k++) {
        group(out, 0, "LAYER");
        group(out, 2, layers[k].name);
        integer(out, 70, 0);
        integer(out, 62, layers[k].colour);
        group(out, 6, "CONTINUOUS");
    }
    group(out, 0, "ENDTAB");
    group(out, 0, "TABLE");
    group(out, 2, "STYLE");
    integer(out, 70, 1);
    group(out, 0, "STYLE");
    group(out, 2, "STANDARD");
    integer(out, 70, 0);
    group(out, 40, "0.0");
    group(out, 41, "1.0");
    group(out, 50, "0.0");
    integer(out, 71, 0);
    group(out, 42, "2.5");
    group(out, 3, "txt");
    group(out, 4, "");
    group(out, 0, "ENDTAB");
    /* Every application whose XDATA the file holds is registered. */
    static const char *const applications[] = {"ACAD", DXF_APPLICATION};
    group(out, 0, "TABLE");
    group(out, 2, "APPID");
    integer(out, 70, 2);
    for (int k = 0; k < 2; k++) {
        group(out, 0, "APPID");
        group(out, 2, applications[k]);
        integer(out, 70, 0);
    }
    group(out, 0, "ENDTAB");
    group(out, 0, "ENDSEC");
}


/* What a panel's polylines carry as extended data (dxf_patterns.h). */
struct panel_data {
    size_t id;
    double corner_distance, corner_moved;  /* m; NaN: not measured */
};

/* Panel k of surface s's extended data, numbered id. */
static struct panel_data data_of(const struct dxf_surface *s, size_t k,
                                 size_t id)
{
    return (struct panel_data){id, panel_corner_distance(s->panels, k),
                               panel_corner_moved(s->panels, k)};
}

/* A number of XDATA (1040, a real), in mm, as the shortest text that
 * reads back as the same double. */
static void xdata_mm(FILE *out, const char *name, double metres)
{
    char text[NUMBER_EXACT_SIZE];
    number_exact(text, units_mm(metres));
    group(out, 1000, name);
    group(out, 1040, text);
}

/* The panel's XDATA of the application FACET. */
static void xdata(FILE *out, const struct panel_data *d)
{
    char id[32];
    snprintf(id, sizeof id, "%zu", d->id);
    group(out, 1001, DXF_APPLICATION);
    group(out, 1000, "PanelId");
    group(out, 1000, id);
    if (isfinite(d->corner_distance))
        xdata_mm(out, "CornerDistance_mm", d->corner_distance);
    if (isfinite(d->corner_moved))
        xdata_mm(out, "CornerMoved_mm", d->corner_moved);
}

/* A closed polyline through n points: (x, y) pairs in the plane when xyz
 * is NULL, else 3D points; a panel's (data not NULL) carries its XDATA. */
static void polyline(FILE *out, const char *layer, size_t n,
                     const double *xy, const double *xyz,
                     const struct panel_data *data)
{
    group(out, 0, "POLYLINE");
    group(out, 8, layer);
    integer(out, 66, 1);
    point(out, 10, 0, 0, 0);
    integer(out, 70, xyz ? 1 | 8 : 1);  /* closed; 8: a 3D polyline */
    if (data != NULL)
        xdata(out, data);
    for (size_t k = 0; k < n; k++) {
        group(out, 0, "VERTEX");
        group(out, 8, layer);
        if (xyz)
            point(out, 10, xyz[3 * k], xyz[3 * k + 1], xyz[3 * k + 2]);
        else
            point(out, 10, xy[2 * k], xy[2 * k + 1], 0);
        if (xyz)
            integer(out, 70, 32);
    }
    group(out, 0, "SEQEND");
    group(out, 8, layer);
}

/* A TEXT centred on (x, y), height m. */
static void text(FILE *out, const char *layer, double x, double y,
                 double height, const char *value)
{
    group(out, 0, "TEXT");
    group(out, 8, layer);
    point(out, 10, x, y, 0);
    mm(out, 40, height);
    group(out, 1, value);
    integer(out, 72, 1);   /* centred */
    point(out, 11, x, y, 0);
    integer(out, 73, 2);   /* on its middle */
}

/* The area centroid of a part's pattern as placed (its loops' signed
 * areas weighing them, about one reference point), into c; its bounding
 * box's middle when it has no area. */
static void pattern_centre(const struct part *p, const struct dxf_surface *s,
                           double step, double c[2])
{
    const struct panel_geometry *g = s->geometry;
    double area = 0, sx = 0, sy = 0, ref[2] = {0, 0};
    size_t first_point = g->loop_start[g->panel_loop[p->panel]];
    placed(p, step, s->patterns->flat + 2 * first_point, ref);
    for (size_t l = g->panel_loop[p->panel]; l < g->panel_loop[p->panel + 1];
         l++) {
        size_t first = g->loop_start[l], n = g->loop_start[l + 1] - first;
        for (size_t k = 0; k < n; k++) {
            double a[2], b[2];
            placed(p, step, s->patterns->flat + 2 * (first + k), a);
            placed(p, step, s->patterns->flat + 2 * (first + (k + 1) % n),
                   b);
            double ax = a[0] - ref[0], ay = a[1] - ref[1];
            double bx = b[0] - ref[0], by = b[1] - ref[1];
            double cross = ax * by - ay * bx;
            area += cross / 2;
            sx += (ax + bx) * cross / 6;
            sy += (ay + by) * cross / 6;
        }
    }
    if (fabs(area) > 1e-12 * p->size[0] * p->size[1] && area != 0) {
        c[0] = ref[0] + sx / area;
        c[1] = ref[1] + sy / area;
    } else {
        c[0] = p->at[0] + (double)p->sheet * step + p->size[0] / 2;
        c[1] = p->at[1] + p->size[1] / 2;
    }
}

static void write_part(FILE *out, const struct part *p,
                       const struct dxf_surface *s, double step,
                       double *buffer)
{
    const struct panel_geometry *g = s->geometry;
    enum panel_type type = s->patterns->developed[p->panel];
    struct panel_data data = data_of(s, p->panel, p->id);
    for (size_t l = g->panel_loop[p->panel]; l < g->panel_loop[p->panel + 1];
         l++) {
        size_t first = g->loop_start[l], n = g->loop_start[l + 1] - first;
        for (size_t k = 0; k < n; k++)
            placed(p, step, s->patterns->flat + 2 * (first + k),
                   buffer + 2 * k);
        polyline(out, layer_of[type], n, buffer, NULL, &data);
    }
    double c[2];
    pattern_centre(p, s, step, c);
    double height = fmin(0.050, fmax(0.003, 0.12 * fmin(p->size[0],
                                                         p->size[1])));
    char id[32];
    snprintf(id, sizeof id, "%zu", p->id);
    text(out, layer_of[type], c[0], c[1], height, id);
    if (type == TYPE_DP)
        text(out, layer_of[type], c[0], c[1] - 1.5 * height, 0.5 * height,
             "DP: not developable");
}

int dxf_sheet_parse(const char *text, const char *what, double *width,
                    double *height, struct facet_error *err)
{
    const char *x = strpbrk(text, "xX");
    char first[64];
    size_t n = x ? (size_t)(x - text) : 0;
    if (x == NULL || n == 0 || n >= sizeof first || x[1] == '\0')
        return facet_error_set(err, FACET_EINPUT, "%s: '%s' is not a sheet "
                               "size: give width x height in mm, e.g. "
                               "3000x1500", what, text);
    memcpy(first, text, n);
    first[n] = '\0';
    double w, h;
    int rc;
    char name[96];
    snprintf(name, sizeof name, "%s width (mm)", what);
    if ((rc = numparse_number(first, units_mm(DXF_SHEET_MIN),
                              units_mm(DXF_SHEET_MAX), name, &w, err)))
        return rc;
    snprintf(name, sizeof name, "%s height (mm)", what);
    if ((rc = numparse_number(x + 1, units_mm(DXF_SHEET_MIN),
                              units_mm(DXF_SHEET_MAX), name, &h, err)))
        return rc;
    *width = units_m_of_mm(w);
    *height = units_m_of_mm(h);
    return FACET_OK;
}

int dxf_patterns_write(FILE *out, const struct dxf_patterns *x,
                       struct facet_error *err)
{
    assert(isfinite(x->sheet_width) && isfinite(x->sheet_height) &&
           x->sheet_width > 2 * DXF_MARGIN &&
           x->sheet_height > 2 * DXF_MARGIN);
    size_t n = 0, most = 0;
    for (size_t s = 0; s < x->nsurfaces; s++) {
        const struct panel_geometry *g = x->surfaces[s].geometry;
        n += g->npanels;
        for (size_t l = 0; l < g->nloops; l++)
            if (g->loop_start[l + 1] - g->loop_start[l] > most)
                most = g->loop_start[l + 1] - g->loop_start[l];
    }
    /* A panel's points, all its loops: the layout's hull and order. */
    size_t most_panel = 0;
    for (size_t s = 0; s < x->nsurfaces; s++) {
        const struct panel_geometry *g = x->surfaces[s].geometry;
        for (size_t k = 0; k < g->npanels; k++) {
            size_t count = g->loop_start[g->panel_loop[k + 1]] -
                           g->loop_start[g->panel_loop[k]];
            if (count > most_panel)
                most_panel = count;
        }
    }
    if (most_panel > most)
        most = most_panel;
    struct part *parts = malloc((n ? n : 1) * sizeof *parts);
    double *buffer = malloc((most ? most : 1) * 3 * sizeof *buffer);
    size_t *order = malloc((most ? most : 1) * sizeof *order);
    double *hull = malloc((4 * most + 2) * sizeof *hull);
    if (parts == NULL || buffer == NULL || order == NULL || hull == NULL) {
        free(parts);
        free(buffer);
        free(order);
        free(hull);
        return facet_error_set(err, FACET_EWORK, "out of memory");
    }
    size_t m = 0;
    for (size_t s = 0; s < x->nsurfaces; s++) {
        const struct dxf_surface *surface = &x->surfaces[s];
        const struct panel_geometry *g = surface->geometry;
        assert(g->npanels == surface->panels->npanels &&
               surface->patterns->npanels == g->npanels);
        for (size_t k = 0; k < g->npanels; k++)
            if (g->panel_loop[k + 1] > g->panel_loop[k])
                parts[m++] = (struct part){s, k, surface->first_id + k,
                                           {0, 0}, {0, 0}, 0, 1, 0, 0,
                                           {0, 0}};
    }
    size_t nsheets = 0;
    double sheet[2] = {x->sheet_width, x->sheet_height};
    int rc = layout(x, sheet, parts, m, hull, order, &nsheets, err);
    if (rc == FACET_OK) {
        double step = sheet[0] + SHEET_GAP;
        /* The extents: the sheets (and their labels under them) and
         * the 3D outlines. */
        double lo[3] = {0, -0.100, 0}, hi[3] = {0, sheet[1], 0};
        hi[0] = nsheets ? (double)nsheets * step - SHEET_GAP : 0;
        for (size_t s = 0; s < x->nsurfaces; s++) {
            const struct panel_geometry *g = x->surfaces[s].geometry;
            for (size_t k = 0; k < g->loop_start[g->nloops]; k++)
                for (int c = 0; c < 3; c++) {
                    double v = g->position[3 * g->outline[k] + c];
                    lo[c] = fmin(lo[c], v);
                    hi[c] = fmax(hi[c], v);
                }
        }
        header(out, lo, hi);
        group(out, 0, "SECTION");
        group(out, 2, "ENTITIES");
        for (size_t k = 0; k < nsheets; k++) {
            double x0 = (double)k * step;
            double frame[8] = {x0, 0, x0 + sheet[0], 0,
                               x0 + sheet[0], sheet[1], x0,
                               sheet[1]};
            polyline(out, "SHEETS", 4, frame, NULL, NULL);
            char name[40];
            snprintf(name, sizeof name, "sheet %zu", k + 1);
            text(out, "SHEETS", x0 + sheet[0] / 2, -0.060, 0.040,
                 name);
        }
        /* The patterns in id order, whatever their places. */
        qsort(parts, m, sizeof *parts, by_id);
        for (size_t k = 0; k < m; k++)
            write_part(out, &parts[k], &x->surfaces[parts[k].surface], step,
                       buffer);
        for (size_t s = 0; s < x->nsurfaces; s++) {
            const struct dxf_surface *surface = &x->surfaces[s];
            const struct panel_geometry *g = surface->geometry;
            for (size_t k = 0; k < g->npanels; k++) {
                enum panel_type type = surface->patterns->developed[k];
                struct panel_data data =
                    data_of(surface, k, surface->first_id + k);
                for (size_t l = g->panel_loop[k]; l < g->panel_loop[k + 1];
                     l++) {
                    size_t first = g->loop_start[l];
                    size_t count = g->loop_start[l + 1] - first;
                    for (size_t q = 0; q < count; q++)
                        memcpy(buffer + 3 * q,
                               g->position + 3 * g->outline[first + q],
                               3 * sizeof *buffer);
                    polyline(out, outline_layer_of[type], count, NULL,
                             buffer, &data);
                }
            }
        }
        group(out, 0, "ENDSEC");
        group(out, 0, "EOF");
    }
    free(parts);
    free(buffer);
    free(order);
    free(hull);
    return rc;
}
