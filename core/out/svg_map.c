/*
 * svg_map.c: the panel map as SVG. See svg_map.h.
 */
#include "core/out/svg_map.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/out/outfile.h"
#include "core/base/numformat.h"
#include "core/out/svg.h"
#include "core/base/units.h"

#define MARGIN 16.0
#define TITLE_HEIGHT 66.0
#define LEGEND_GAP 24.0
#define LEGEND_WIDTH 330.0
#define SCALE_BAR_HEIGHT 30  /* room for the scale bar under a view */
#define LEGEND_ROW 18.0

static const char *const view_names[] = {"uv", "top", "front", "side"};

static const char *const view_captions[] = {
    "UV (u to the right, v up)",
    "top: XY seen from above",
    "front: XZ seen from -y",
    "side: YZ seen from +x",
};

void svg_map_defaults(struct svg_map_options *options)
{
    memset(options, 0, sizeof *options);
    options->view = SVG_MAP_UV;
    options->colour_by = SVG_MAP_BY_TYPE;
    options->size = 720;
    options->worst_joints = 10;
}

int svg_map_view_parse(const char *text, enum svg_map_view *out,
                       struct facet_error *err)
{
    for (int v = 0; v < 4; v++)
        if (strcmp(text, view_names[v]) == 0) {
            *out = (enum svg_map_view)v;
            return FACET_OK;
        }
    return facet_error_set(err, FACET_EINPUT,
                           "unknown view '%s' (use uv, top, front or side)",
                           text);
}

int svg_map_colouring_parse(const char *text, enum svg_map_colouring *out,
                            struct facet_error *err)
{
    if (strcmp(text, "type") == 0) {
        *out = SVG_MAP_BY_TYPE;
        return FACET_OK;
    }
    if (strcmp(text, "class") == 0) {
        *out = SVG_MAP_BY_CLASS;
        return FACET_OK;
    }
    return facet_error_set(err, FACET_EINPUT,
                           "unknown colouring '%s' (use type or class)", text);
}

/* Where the data goes on the page. */
struct frame {
    enum svg_map_view view;
    double xmin, ymax;      /* data coordinates of the drawing's top left */
    double scale;           /* px per data unit */
    double left, top;       /* px of the drawing's top left */
};

/* The view's 2D data coordinates of vertex v of g: UV, or a projection of
 * its position. */
static void view_point(const struct frame *f, const struct panel_geometry *g,
                       size_t v, double out[2])
{
    const double *x = &g->position[3 * v];
    switch (f->view) {
    case SVG_MAP_TOP:
        out[0] = x[0];
        out[1] = x[1];
        return;
    case SVG_MAP_FRONT:
        out[0] = x[0];
        out[1] = x[2];
        return;
    case SVG_MAP_SIDE:
        out[0] = x[1];
        out[1] = x[2];
        return;
    case SVG_MAP_UV:
        break;
    }
    out[0] = g->uv[2 * v];
    out[1] = g->uv[2 * v + 1];
}

/* How near the viewer a point is (larger is nearer). */
static double view_depth(enum svg_map_view view, const double x[3])
{
    switch (view) {
    case SVG_MAP_TOP:
        return x[2];
    case SVG_MAP_FRONT:
        return -x[1];
    case SVG_MAP_SIDE:
        return x[0];
    case SVG_MAP_UV:
        break;
    }
    return 0;
}

static void screen_point(struct svg *svg, const struct frame *f,
                         const struct panel_geometry *g, size_t v)
{
    double p[2];
    view_point(f, g, v, p);
    svg_point(svg, f->left + (p[0] - f->xmin) * f->scale,
              f->top + (f->ymax - p[1]) * f->scale);
}

struct order {
    double depth;
    size_t n;
};

static int compare_order(const void *a, const void *b)
{
    const struct order *x = a, *y = b;
    if (x->depth != y->depth)
        return x->depth < y->depth ? -1 : 1;
    return x->n < y->n ? -1 : x->n > y->n;
}

static const char *colour_of(const struct panel *panel,
                             enum svg_map_colouring by)
{
    return by == SVG_MAP_BY_CLASS ? svg_class_colour(panel->class)
                                  : svg_type_colour(panel->type);
}

/* The class name as a reader writes it: "convex feature curve". */
static void class_words(enum panel_class class, char *text, size_t size)
{
    snprintf(text, size, "%s", panel_class_name(class));
    for (char *c = text; *c; c++)
        if (*c == '_')
            *c = ' ';
}

static void write_panel(struct svg *svg, const struct frame *f,
                        const struct panel_geometry *g,
                        const struct panel *panel, size_t n,
                        const struct svg_map_options *options)
{
    FILE *out = svg->out;
    fprintf(out, "<path class=\"panel %s\" data-i=\"%d\" data-j=\"%d\" "
            "data-type=\"%s\" data-class=\"%s\" fill=\"%s\"",
            panel_type_name(panel->type), panel->i, panel->j,
            panel_type_name(panel->type), panel_class_name(panel->class),
            colour_of(panel, options->colour_by));
    if (options->triangles)
        fprintf(out, " stroke=\"%s\"", colour_of(panel, options->colour_by));
    fputs(" d=\"", out);
    int first = 1;
    if (options->triangles) {
        for (size_t p = g->panel_piece[n]; p < g->panel_piece[n + 1]; p++) {
            for (size_t c = g->piece_start[p]; c < g->piece_start[p + 1];
                 c++) {
                fputs(c == g->piece_start[p] ? (first ? "M" : " M") : " ",
                      out);
                screen_point(svg, f, g, g->corner[c]);
            }
            fputc('Z', out);
            first = 0;
        }
    } else {
        for (size_t l = g->panel_loop[n]; l < g->panel_loop[n + 1]; l++) {
            for (size_t k = g->loop_start[l]; k < g->loop_start[l + 1]; k++) {
                fputs(k == g->loop_start[l] ? (first ? "M" : " M") : " ",
                      out);
                screen_point(svg, f, g, g->outline[k]);
            }
            fputc('Z', out);
            first = 0;
        }
    }
    char words[64], area[32];
    class_words(panel->class, words, sizeof words);
    number_grouped(area, sizeof area, panel->area, 3);
    fprintf(out, "\"><title>panel %d,%d: %s, %s, %s m^2, deviation %.1f mm"
            "</title></path>\n", panel->i, panel->j,
            panel_type_name(panel->type), words, area,
            units_mm(panel->deviation));
}

/* A panel's worst joint: the panel, its gap (mm) and a key that names
 * the joint whichever of its two panels names it. */
struct worst_joint {
    size_t panel;
    double gap;
    long long key;
};

static int compare_worst(const void *a, const void *b)
{
    const struct worst_joint *x = a, *y = b;
    if (x->gap != y->gap)
        return x->gap > y->gap ? -1 : 1;
    return x->key < y->key ? -1 : x->key > y->key;
}

/* The joint on side side of panel (i, j): which line (u or v), its index
 * and the cell along it, as one number. */
static long long joint_key(int i, int j, int side)
{
    int along_v = side == 0 || side == 2;
    int line = side == 1 ? i + 1 : side == 2 ? j + 1 : side == 3 ? i : j;
    int cell = along_v ? i : j;
    return ((long long)along_v * (PANEL_MAX_GRID + 1) + line) *
               (PANEL_MAX_GRID + 1) + cell;
}

/* Fills joints with the panels' worst joints to draw (see svg_map.h),
 * largest gap first; returns how many. */
static size_t worst_joints(const struct panelization *p,
                           const struct svg_map_options *options,
                           struct worst_joint *joints)
{
    size_t n = 0;
    for (size_t k = 0; k < p->npanels; k++) {
        const struct panel *x = &p->panels[k];
        if (x->worst_gap_side < 0 || !(x->worst_gap > 0))
            continue;
        joints[n++] = (struct worst_joint){
            k, units_mm(x->worst_gap), joint_key(x->i, x->j, x->worst_gap_side)};
    }
    qsort(joints, n, sizeof *joints, compare_worst);
    size_t kept = 0;
    for (size_t k = 0; k < n; k++) {
        int seen = 0;
        for (size_t m = 0; m < kept && !seen; m++)
            seen = joints[m].key == joints[k].key;
        int over = options->max_gap_mm > 0 &&
                   joints[k].gap > options->max_gap_mm;
        if (!seen && (kept < (size_t)options->worst_joints || over))
            joints[kept++] = joints[k];
    }
    return kept;
}

/* The page point of corner c of panel (UV: the cell's corner; else its
 * corner on the surface, projected), or 0 when it has none. */
static int corner_point(const struct frame *f, const struct panelization *p,
                        const struct panel *x, int c, double out[2])
{
    double d[2];
    if (f->view == SVG_MAP_UV) {
        double du = (p->umax - p->umin) / p->nu;
        double dv = (p->vmax - p->vmin) / p->nv;
        d[0] = p->umin + (x->i + (c == 1 || c == 2)) * du;
        d[1] = p->vmin + (x->j + (c == 2 || c == 3)) * dv;
    } else {
        const double *q = x->corner[c];
        if (!isfinite(q[0]))
            return 0;
        d[0] = f->view == SVG_MAP_SIDE ? q[1] : q[0];
        d[1] = f->view == SVG_MAP_TOP ? q[1] : q[2];
    }
    out[0] = f->left + (d[0] - f->xmin) * f->scale;
    out[1] = f->top + (f->ymax - d[1]) * f->scale;
    return 1;
}

static void write_worst_joints(struct svg *svg, const struct frame *f,
                               const struct panelization *p,
                               const struct worst_joint *joints, size_t n)
{
    fputs("<g class=\"worst-joints\" stroke=\"#d6249f\" stroke-width=\"3\" "
          "stroke-linecap=\"round\">\n", svg->out);
    for (size_t k = 0; k < n; k++) {
        const struct panel *x = &p->panels[joints[k].panel];
        int side = x->worst_gap_side;
        double a[2], b[2];
        if (!corner_point(f, p, x, side, a) ||
            !corner_point(f, p, x, (side + 1) % 4, b))
            continue;
        fprintf(svg->out, "<line class=\"worst-joint\" data-joint-i=\"%d\" "
                "data-joint-j=\"%d\" data-side=\"%d\" data-gap-mm=\"%.4f\" "
                "x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\"><title>"
                "joint of panel %d,%d: gap %.2f mm</title></line>\n",
                x->i, x->j, side, joints[k].gap, a[0], a[1], b[0], b[1],
                x->i, x->j, joints[k].gap);
    }
    fputs("</g>\n", svg->out);
}

static void write_legend(struct svg *svg, double left, double top,
                         const struct option_totals *totals,
                         enum svg_map_colouring by)
{
    int rows = by == SVG_MAP_BY_CLASS ? CLASS_COUNT : TYPE_COUNT;
    fputs("<g class=\"legend\">\n", svg->out);
    svg_text(svg, left, top + 12, "font-weight=\"bold\"", "%s",
             by == SVG_MAP_BY_CLASS ? "class" : "type");
    svg_text(svg, left + 230, top + 12,
             "font-weight=\"bold\" text-anchor=\"end\"", "panels");
    svg_text(svg, left + LEGEND_WIDTH, top + 12,
             "font-weight=\"bold\" text-anchor=\"end\"", "area (m^2)");
    char count[32], area[32], name[64];
    for (int r = 0; r < rows; r++) {
        double y = top + (r + 1) * LEGEND_ROW;
        const char *colour;
        size_t n;
        double a;
        if (by == SVG_MAP_BY_CLASS) {
            colour = svg_class_colour((enum panel_class)r);
            class_words((enum panel_class)r, name, sizeof name);
            n = totals->class_count[r];
            a = totals->class_area[r];
        } else {
            colour = svg_type_colour((enum panel_type)r);
            snprintf(name, sizeof name, "%s",
                     panel_type_name((enum panel_type)r));
            n = totals->count[r];
            a = totals->area_of[r];
        }
        char fill[48];
        snprintf(fill, sizeof fill, "fill=\"%s\" stroke=\"#333333\"", colour);
        svg_rect(svg, left, y + 2, 12, 12, fill);
        svg_text(svg, left + 18, y + 12, NULL, "%s", name);
        number_grouped(count, sizeof count, (double)n, 0);
        number_grouped(area, sizeof area, a, 2);
        svg_text(svg, left + 230, y + 12, "text-anchor=\"end\"", "%s", count);
        svg_text(svg, left + LEGEND_WIDTH, y + 12, "text-anchor=\"end\"",
                 "%s", area);
    }
    double y = top + (rows + 1) * LEGEND_ROW;
    svg_line(svg, left, y + 3, left + LEGEND_WIDTH, y + 3,
             "stroke=\"#333333\"");
    number_grouped(count, sizeof count, (double)totals->panels, 0);
    number_grouped(area, sizeof area, totals->area, 2);
    svg_text(svg, left + 18, y + 16, NULL, "total");
    svg_text(svg, left + 230, y + 16, "text-anchor=\"end\"", "%s", count);
    svg_text(svg, left + LEGEND_WIDTH, y + 16, "text-anchor=\"end\"", "%s",
             area);
    fputs("</g>\n", svg->out);
}

/* The worst joints' line of the legend, at y. */
static void write_joint_legend(struct svg *svg, double left, double y,
                               const struct svg_map_options *options,
                               const struct worst_joint *joints, size_t n)
{
    fputs("<g class=\"legend-joints\">\n", svg->out);
    svg_line(svg, left, y + 8, left + 12, y + 8,
             "stroke=\"#d6249f\" stroke-width=\"3\"");
    char limit[48] = "";
    if (options->max_gap_mm > 0)
        snprintf(limit, sizeof limit, " and all over %g mm",
                 options->max_gap_mm);
    if (n == 0)
        svg_text(svg, left + 18, y + 12, NULL, "no joint with a gap");
    else
        svg_text(svg, left + 18, y + 12, NULL,
                 "worst gaps (%d largest%s): %.2f to %.2f mm",
                 options->worst_joints, limit, joints[n - 1].gap,
                 joints[0].gap);
    fputs("</g>\n", svg->out);
}

/* A bar of a round length (1, 2 or 5 times a power of ten metres) near a
 * fifth of the drawing's width (m), at (x, y), scale px per metre. */
static void write_scale_bar(struct svg *svg, double x, double y,
                            double width, double scale)
{
    double want = width > 0 ? width / 5 : 1;
    double step = pow(10, floor(log10(want)));
    double length = step;
    if (5 * step <= want)
        length = 5 * step;
    else if (2 * step <= want)
        length = 2 * step;
    double px = length * scale;
    fputs("<g class=\"scale-bar\">\n", svg->out);
    svg_rect(svg, x, y, px, 5, "fill=\"#333333\"");
    svg_line(svg, x, y - 3, x, y + 8, "stroke=\"#333333\"");
    svg_line(svg, x + px, y - 3, x + px, y + 8, "stroke=\"#333333\"");
    svg_text(svg, x + px + 8, y + 7, "data-metres=\"1\"", "%g m", length);
    fputs("</g>\n", svg->out);
}

void svg_map_write(FILE *out, const struct panel_geometry *g,
                   const struct panelization *panels,
                   const struct option_totals *totals,
                   const struct svg_map_options *options)
{
    struct frame f;
    memset(&f, 0, sizeof f);
    f.view = options->view;
    double xmin, xmax, ymin, ymax;
    if (f.view == SVG_MAP_UV) {
        xmin = panels->umin;
        xmax = panels->umax;
        ymin = panels->vmin;
        ymax = panels->vmax;
    } else {
        xmin = ymin = INFINITY;
        xmax = ymax = -INFINITY;
        for (size_t v = 0; v < g->nvertices; v++) {
            double p[2];
            view_point(&f, g, v, p);
            xmin = fmin(xmin, p[0]);
            xmax = fmax(xmax, p[0]);
            ymin = fmin(ymin, p[1]);
            ymax = fmax(ymax, p[1]);
        }
        if (g->nvertices == 0)
            xmin = ymin = 0, xmax = ymax = 1;
    }
    double width = xmax - xmin, height = ymax - ymin;
    double longer = fmax(width, height);
    double size = options->size > 0 ? options->size : 720;
    if (!(longer > 0))
        longer = 1;
    f.scale = size / longer;
    f.xmin = xmin;
    f.ymax = ymax;
    f.left = MARGIN;
    f.top = MARGIN + TITLE_HEIGHT;
    double draw_width = fmax(width * f.scale, 1);
    double draw_height = fmax(height * f.scale, 1);
    int rows = options->colour_by == SVG_MAP_BY_CLASS ? CLASS_COUNT
                                                       : TYPE_COUNT;
    double legend_height = (rows + 3) * LEGEND_ROW + 8;
    double page_width = MARGIN + draw_width + LEGEND_GAP + LEGEND_WIDTH +
                        MARGIN;
    /* A projected view is in metres at one scale for both axes (its true
     * aspect), with a scale bar under it. */
    int scale_bar = f.view != SVG_MAP_UV;
    double page_height = f.top + fmax(draw_height, legend_height) + MARGIN +
                         (scale_bar ? SCALE_BAR_HEIGHT : 0);

    struct svg svg;
    svg_begin(&svg, out, page_width, page_height, 2);
    svg_rect(&svg, 0, 0, page_width, page_height, "fill=\"white\"");

    /* Title block. */
    char cost[48], dp[48];
    number_grouped(cost, sizeof cost, totals->cost, 0);
    number_grouped(dp, sizeof dp, totals->area_of[TYPE_DP], 2);
    fputs("<g class=\"title\">\n", out);
    svg_text(&svg, MARGIN, MARGIN + 14,
             "font-size=\"16\" font-weight=\"bold\"", "%s",
             options->title ? options->title : "Facet panel map");
    svg_text(&svg, MARGIN, MARGIN + 34, NULL,
             "grid %d x %d, %zu panels, cost %s USD, DP area %s m^2",
             panels->nu, panels->nv, panels->npanels, cost, dp);
    svg_text(&svg, MARGIN, MARGIN + 52, "fill=\"#555555\"",
             "%s, coloured by %s%s", view_captions[f.view],
             options->colour_by == SVG_MAP_BY_CLASS ? "class" : "type",
             options->triangles ? ", triangles" : "");
    fputs("</g>\n", out);

    if (f.view == SVG_MAP_UV)
        svg_rect(&svg, f.left, f.top, draw_width, draw_height,
                 "class=\"uv-box\" fill=\"none\" stroke=\"#bbbbbb\"");

    /* Far to near, so that what is in front is painted last. */
    struct order *order = malloc((panels->npanels + 1) * sizeof *order);
    size_t count = panels->npanels < g->npanels ? panels->npanels
                                                : g->npanels;
    for (size_t n = 0; order != NULL && n < count; n++) {
        order[n].depth = view_depth(f.view, panels->panels[n].centroid);
        order[n].n = n;
    }
    if (order != NULL && f.view != SVG_MAP_UV)
        qsort(order, count, sizeof *order, compare_order);
    if (options->triangles)
        fputs("<g class=\"panels\" stroke-width=\"0.3\" "
              "stroke-linejoin=\"round\">\n", out);
    else
        fputs("<g class=\"panels\" fill-rule=\"evenodd\" stroke=\"#333333\" "
              "stroke-width=\"0.6\" stroke-linejoin=\"round\">\n", out);
    for (size_t k = 0; k < count; k++) {
        /* Without memory for the order, file order is still one mark per
         * panel, only painted less well. */
        size_t n = order ? order[k].n : k;
        write_panel(&svg, &f, g, &panels->panels[n], n, options);
    }
    fputs("</g>\n", out);
    free(order);
    struct worst_joint *joints = NULL;
    size_t njoints = 0;
    if (options->worst_joints > 0 || options->max_gap_mm > 0) {
        joints = malloc((panels->npanels + 1) * sizeof *joints);
        if (joints != NULL) {
            njoints = worst_joints(panels, options, joints);
            write_worst_joints(&svg, &f, panels, joints, njoints);
        }
    }

    if (scale_bar)
        write_scale_bar(&svg, f.left, f.top + fmax(draw_height, 1) + 14,
                        width, f.scale);
    write_legend(&svg, MARGIN + draw_width + LEGEND_GAP, f.top, totals,
                 options->colour_by);
    if (joints != NULL)
        write_joint_legend(&svg, MARGIN + draw_width + LEGEND_GAP,
                           f.top + (rows + 2) * LEGEND_ROW, options, joints,
                           njoints);
    free(joints);
    svg_end(&svg);
}

int svg_map_save(const char *path, int force, const struct panel_geometry *g,
                 const struct panelization *panels,
                 const struct option_totals *totals,
                 const struct svg_map_options *options,
                 struct facet_error *err)
{
    struct outfile file;
    int rc = outfile_open(&file, path, force, err);
    if (rc != FACET_OK)
        return rc;
    svg_map_write(file.out, g, panels, totals, options);
    return outfile_commit(&file, err);
}
