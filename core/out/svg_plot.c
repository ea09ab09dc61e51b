/*
 * svg_plot.c: the design-option scatter plot as SVG. See svg_plot.h.
 */
#include "core/out/svg_plot.h"

#include <assert.h>
#include <ctype.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/out/outfile.h"
#include "core/base/numformat.h"
#include "core/base/text.h"
#include "core/out/svg.h"

/* Plot area inside the page (px). */
#define PLOT_LEFT 96.0
#define PLOT_TOP 56.0
#define PLOT_RIGHT_GAP 190.0
#define PLOT_BOTTOM_GAP 64.0
#define DOT_RADIUS 4.5
#define BUBBLE_MIN 3.0     /* radius of the smallest bubble (px) */
#define BUBBLE_MAX 13.0    /* radius of the largest */
#define DENSE_OPTIONS 600  /* beyond this, dominated options are dots */
#define DENSE_RADIUS 1.6   /* a dominated option's dot then (px) */

/* Okabe and Ito's palette, in their order: runs overlaid in one plot stay
 * apart for colour-blind readers. */
static const char *const series_colour[] = {
    "#0072b2", "#e69f00", "#009e73", "#cc79a7", "#56b4e9",
    "#d55e00", "#f0e442", "#000000",
};
#define NCOLOURS (sizeof series_colour / sizeof series_colour[0])

void svg_plot_defaults(struct svg_plot *plot)
{
    memset(plot, 0, sizeof *plot);
    plot->x_name = "planarity";
    plot->x_unit = "m";
    plot->y_name = "cost";
    plot->y_unit = "USD";
    plot->size_name = "DP area";
    plot->size_unit = "m^2";
    plot->width = 800;
    plot->height = 560;
}

void svg_plot_axis(double lo, double hi, double pad, int ticks,
                   struct svg_axis *axis)
{
    assert(isfinite(lo) && isfinite(hi));
    if (hi < lo) {
        double t = lo;
        lo = hi;
        hi = t;
    }
    /* A span lost in the values' own rounding (1e16 to 1e16 + 2) would
     * give ticks that cannot be told apart: widen it first. */
    double span = hi - lo;
    if (!(span > 0))
        span = lo != 0 ? fabs(lo) : 1;  /* one value: a range around it */
    span = fmax(span, 1e-9 * fmax(fabs(lo), fabs(hi)));
    /* Every quantity Facet plots is a length, area, price or count: values
     * that are none of them negative get no negative axis, which would
     * read as a planarity of -5 m. */
    int nonnegative = lo >= 0;
    lo -= pad * span;
    hi += pad * span;
    if (nonnegative && lo < 0)
        lo = 0;
    if (ticks < 1)
        ticks = 1;
    /* Of 1, 2, 5 and 10 x 10^k around the raw step, the one whose
     * rounded-out range has the number of intervals nearest ticks (the
     * larger step on a tie: fewer labels read better). */
    double raw = (hi - lo) / ticks;
    double magnitude = pow(10, floor(log10(raw)));
    static const double mantissa[] = {10, 5, 2, 1};
    double step = 10 * magnitude, best = INFINITY;
    for (int k = 0; k < 4; k++) {
        double s = mantissa[k] * magnitude;
        double intervals = ceil(hi / s) - floor(lo / s);
        if (fabs(intervals - ticks) < best) {
            best = fabs(intervals - ticks);
            step = s;
        }
    }
    axis->step = step;
    axis->min = floor(lo / step) * step;
    axis->max = ceil(hi / step) * step;
    /* Rounding of lo / step may land a hair inside; step out again. */
    for (int k = 0; k < 4 && axis->min > lo; k++)
        axis->min -= step;
    for (int k = 0; k < 4 && axis->max < hi; k++)
        axis->max += step;
    if (nonnegative && axis->min < 0)
        axis->min = 0;
    axis->decimals = step >= 1 ? 0 : (int)ceil(-log10(step) - 1e-9);
}

static int valid_colour(const char *c)
{
    if (c[0] != '#' || strlen(c) != 7)
        return 0;
    for (int k = 1; k < 7; k++)
        if (!isxdigit((unsigned char)c[k]))
            return 0;
    return 1;
}

static int check(const struct svg_plot *plot, struct facet_error *err)
{
    for (size_t s = 0; s < plot->nseries; s++) {
        const struct svg_plot_series *se = &plot->series[s];
        if (se->n > 0 && (se->x == NULL || se->y == NULL))
            return facet_error_set(err, FACET_EINPUT,
                                   "plot: series %zu has no x or y values",
                                   s + 1);
        if (se->colour != NULL && !valid_colour(se->colour))
            return facet_error_set(err, FACET_EINPUT,
                "plot: series %zu colour '%s' is not #rrggbb", s + 1,
                se->colour);
        if (se->knee != SIZE_MAX && se->knee >= se->n)
            return facet_error_set(err, FACET_EINPUT,
                "plot: series %zu knee %zu is past its %zu options", s + 1,
                se->knee, se->n);
        for (size_t k = 0; k < se->n; k++) {
            if (!isfinite(se->x[k]) || !isfinite(se->y[k]))
                return facet_error_set(err, FACET_EINPUT,
                    "plot: series %zu option %zu has a non-finite value",
                    s + 1, k + 1);
            if (se->size != NULL && !(se->size[k] >= 0 &&
                                      isfinite(se->size[k])))
                return facet_error_set(err, FACET_EINPUT,
                    "plot: series %zu option %zu has size %g (must be a "
                    "number >= 0)", s + 1, k + 1, se->size[k]);
        }
    }
    return FACET_OK;
}

/* Maps data to the page. */
struct plot_frame {
    struct svg_axis x, y;
    double left, top, width, height;   /* plot area (px) */
    int sized;                         /* some series has sizes */
    int dense;                         /* so many options that dominated
                                          ones are drawn as faint dots */
    double size_min, size_max;         /* their range */
};

static double px_x(const struct plot_frame *f, double x)
{
    return f->left + (x - f->x.min) / (f->x.max - f->x.min) * f->width;
}

static double px_y(const struct plot_frame *f, double y)
{
    return f->top + (f->y.max - y) / (f->y.max - f->y.min) * f->height;
}

/* A bubble's radius for value s: its area grows linearly from the
 * smallest value to the largest, so that differences among options show
 * even when every value is far from zero (DP areas of 250 to 470 m^2). */
static double bubble_radius(const struct plot_frame *f, double s)
{
    double range = f->size_max - f->size_min;
    double t = range > 0 ? (s - f->size_min) / range : 0.5;
    return sqrt(BUBBLE_MIN * BUBBLE_MIN +
                (BUBBLE_MAX * BUBBLE_MAX - BUBBLE_MIN * BUBBLE_MIN) * t);
}

static double radius(const struct plot_frame *f,
                     const struct svg_plot_series *se, size_t k)
{
    if (se->size == NULL)
        return DOT_RADIUS;
    return bubble_radius(f, se->size[k]);
}

/* "planarity (m)", or the name alone without a unit. */
static void axis_label(char *text, size_t size, const char *name,
                       const char *unit)
{
    if (unit != NULL && unit[0] != '\0')
        snprintf(text, size, "%s (%s)", name ? name : "", unit);
    else
        snprintf(text, size, "%s", name ? name : "");
}

/* The grid lines, tick marks and labels of axis, across the bottom when
 * horizontal is set, else up the left side. */
static void write_ticks(struct svg *svg, const struct plot_frame *f,
                        const struct svg_axis *axis, int horizontal)
{
    /* A range too wide for doubles has no ticks to speak of. */
    long n = lround((axis->max - axis->min) / axis->step);
    if (!(n >= 0 && n <= 1000))
        n = 0;
    double bottom = f->top + f->height, right = f->left + f->width;
    char label[64];
    for (long k = 0; k <= n; k++) {
        double v = axis->min + k * axis->step;
        number_grouped(label, sizeof label, v, axis->decimals);
        if (horizontal) {
            double x = px_x(f, v);
            svg_line(svg, x, f->top, x, bottom,
                     "class=\"grid\" stroke=\"#e6e6e6\"");
            svg_line(svg, x, bottom, x, bottom + 5, "stroke=\"#333333\"");
            svg_text(svg, x, bottom + 18,
                     "class=\"tick\" text-anchor=\"middle\"", "%s", label);
        } else {
            double y = px_y(f, v);
            svg_line(svg, f->left, y, right, y,
                     "class=\"grid\" stroke=\"#e6e6e6\"");
            svg_line(svg, f->left - 5, y, f->left, y, "stroke=\"#333333\"");
            svg_text(svg, f->left - 8, y + 4,
                     "class=\"tick\" text-anchor=\"end\"", "%s", label);
        }
    }
}

static void write_axes(struct svg *svg, const struct plot_frame *f,
                       const struct svg_plot *plot)
{
    FILE *out = svg->out;
    fprintf(out, "<g class=\"axes\" data-x-min=\"%.17g\" data-x-max=\"%.17g\""
            " data-y-min=\"%.17g\" data-y-max=\"%.17g\">\n", f->x.min,
            f->x.max, f->y.min, f->y.max);
    write_ticks(svg, f, &f->x, 1);
    write_ticks(svg, f, &f->y, 0);
    char label[160];
    svg_rect(svg, f->left, f->top, f->width, f->height,
             "class=\"frame\" fill=\"none\" stroke=\"#333333\"");
    axis_label(label, sizeof label, plot->x_name, plot->x_unit);
    svg_text(svg, f->left + f->width / 2, f->top + f->height + 44,
             "class=\"label\" text-anchor=\"middle\" font-size=\"13\"", "%s",
             label);
    axis_label(label, sizeof label, plot->y_name, plot->y_unit);
    double lx = 22, ly = f->top + f->height / 2;
    fputs("<text class=\"label\" text-anchor=\"middle\" font-size=\"13\"",
          out);
    svg_attribute(svg, "x", lx);
    svg_attribute(svg, "y", ly);
    fputs(" transform=\"rotate(-90 ", out);
    svg_point(svg, lx, ly);
    fputs(")\">", out);
    svg_escape(out, label);
    fputs("</text>\n</g>\n", out);
}

static void write_circle(struct svg *svg, const struct plot_frame *f,
                         const struct svg_plot *plot, size_t s,
                         const struct svg_plot_series *se, const char *colour,
                         size_t k)
{
    FILE *out = svg->out;
    int pareto = se->rank != NULL && se->rank[k] == 1;
    fprintf(out, "<circle class=\"option%s\" data-series=\"%zu\" "
            "data-index=\"%zu\"", pareto ? " pareto" : "", s, k);
    if (se->rank != NULL)
        fprintf(out, " data-rank=\"%d\"", se->rank[k]);
    svg_attribute(svg, "cx", px_x(f, se->x[k]));
    svg_attribute(svg, "cy", px_y(f, se->y[k]));
    svg_attribute(svg, "r", !pareto && f->dense ? DENSE_RADIUS
                                                : radius(f, se, k));
    if (!pareto && f->dense)
        fprintf(out, " fill=\"%s\" fill-opacity=\"0.25\" stroke=\"none\"",
                colour);
    else if (pareto)
        fprintf(out, " fill=\"%s\" fill-opacity=\"0.85\" stroke=\"#222222\" "
                "stroke-width=\"1.2\"", colour);
    else
        fprintf(out, " fill=\"%s\" fill-opacity=\"0.3\" stroke=\"%s\" "
                "stroke-width=\"0.8\"", colour, colour);
    fputs("><title>", out);
    char text[400];
    int n = snprintf(text, sizeof text, "%s%s%s %.6g %s, %s %.6g %s",
                     se->label ? se->label : "", se->label ? ": " : "",
                     plot->x_name ? plot->x_name : "x", se->x[k],
                     plot->x_unit ? plot->x_unit : "",
                     plot->y_name ? plot->y_name : "y", se->y[k],
                     plot->y_unit ? plot->y_unit : "");
    if (se->size != NULL && n > 0 && (size_t)n < sizeof text)
        n += snprintf(text + n, sizeof text - (size_t)n, ", %s %.6g %s",
                      plot->size_name ? plot->size_name : "size",
                      se->size[k], plot->size_unit ? plot->size_unit : "");
    if (se->rank != NULL && n > 0 && (size_t)n < sizeof text)
        snprintf(text + n, sizeof text - (size_t)n, ", rank %d%s",
                 se->rank[k], k == se->knee ? " (knee)" : "");
    svg_escape(out, text);
    fputs("</title></circle>\n", out);
}

struct front_point {
    double x, y;
};

static int compare_front(const void *a, const void *b)
{
    const struct front_point *p = a, *q = b;
    if (p->x != q->x)
        return p->x < q->x ? -1 : 1;
    return p->y < q->y ? -1 : p->y > q->y;
}

/* The rank 1 options of se joined in order of x. */
static void write_front(struct svg *svg, const struct plot_frame *f,
                        const struct svg_plot_series *se, const char *colour,
                        size_t s)
{
    size_t count = 0;
    for (size_t k = 0; k < se->n; k++)
        count += se->rank[k] == 1;
    if (count == 0)
        return;
    struct front_point *points = malloc(count * sizeof *points);
    if (points == NULL)
        return;  /* the front line is lost, the options are not */
    count = 0;
    for (size_t k = 0; k < se->n; k++)
        if (se->rank[k] == 1) {
            points[count].x = se->x[k];
            points[count++].y = se->y[k];
        }
    qsort(points, count, sizeof *points, compare_front);
    fprintf(svg->out, "<polyline class=\"front\" data-series=\"%zu\" "
            "fill=\"none\" stroke=\"%s\" stroke-width=\"1.5\" points=\"",
            s, colour);
    for (size_t k = 0; k < count; k++) {
        if (k > 0)
            fputc(' ', svg->out);
        svg_point(svg, px_x(f, points[k].x), px_y(f, points[k].y));
    }
    fputs("\"/>\n", svg->out);
    free(points);
}

static void write_knee(struct svg *svg, const struct plot_frame *f,
                       const struct svg_plot_series *se, size_t s)
{
    double x = px_x(f, se->x[se->knee]), y = px_y(f, se->y[se->knee]);
    double r = radius(f, se, se->knee) + 5;
    fprintf(svg->out, "<path class=\"knee\" data-series=\"%zu\" "
            "fill=\"none\" stroke=\"#000000\" stroke-width=\"1.5\" d=\"M", s);
    svg_point(svg, x, y - r);
    fputs(" L", svg->out);
    svg_point(svg, x + r, y);
    fputs(" L", svg->out);
    svg_point(svg, x, y + r);
    fputs(" L", svg->out);
    svg_point(svg, x - r, y);
    fputs("Z\"/>\n", svg->out);
    svg_text(svg, x + r + 3, y - r, "class=\"knee-label\" font-size=\"11\"",
             "knee");
}

static const char *colour_of(const struct svg_plot_series *se, size_t s)
{
    return se->colour ? se->colour : series_colour[s % NCOLOURS];
}

/* The legend's text column: PLOT_RIGHT_GAP less the mark, at 12 px
 * type of at most 6.7 px a character (DejaVu Sans, the widest of the
 * fonts a viewer falls back on, averages under it). */
#define LEGEND_CHARS 22
#define LEGEND_LINES 3

/* Series, marks and bubble sizes, to the right of the plot. Round marks
 * are rects with rounded corners, so that <circle> stays one per
 * option. */
static void write_legend(struct svg *svg, const struct plot_frame *f,
                         const struct svg_plot *plot)
{
    double x = f->left + f->width + 20, y = f->top + 4;
    fputs("<g class=\"legend\">\n", svg->out);
    char style[96];
    for (size_t s = 0; s < plot->nseries; s++) {
        const struct svg_plot_series *se = &plot->series[s];
        if (se->label == NULL && plot->nseries == 1)
            break;
        snprintf(style, sizeof style, "fill=\"%s\"", colour_of(se, s));
        svg_rect(svg, x, y, 12, 12, style);
        size_t pareto = 0;
        for (size_t k = 0; se->rank != NULL && k < se->n; k++)
            pareto += se->rank[k] == 1;
        char name[64];
        snprintf(name, sizeof name, "run %zu", s + 1);
        /* The label over as many lines as it needs of the column's
         * width, its counts on a line of their own: one line ran past the
         * page's edge ("run 1 paper space (336, 1"). */
        const char *label = se->label != NULL ? se->label : name;
        for (int line = 0; *label != '\0' && line < LEGEND_LINES; line++) {
            size_t n = text_break(label, LEGEND_CHARS);
            svg_text(svg, x + 18, y + 10, NULL, "%.*s", (int)n, label);
            label += n;
            while (*label == ' ')
                label++;
            y += 14;
        }
        svg_text(svg, x + 18, y + 10, "fill=\"#555555\"",
                 "%zu options, %zu Pareto", se->n, pareto);
        y += 20;
    }
    y += 6;
    if (f->dense)
        svg_rect(svg, x + 6 - DENSE_RADIUS, y + 5 - DENSE_RADIUS,
                 2 * DENSE_RADIUS, 2 * DENSE_RADIUS,
                 "rx=\"1.6\" fill=\"#888888\" fill-opacity=\"0.5\"");
    else
        svg_rect(svg, x + 1, y, 10, 10,
                 "rx=\"5\" fill=\"#888888\" fill-opacity=\"0.3\" "
                 "stroke=\"#888888\"");
    svg_text(svg, x + 18, y + 9, NULL, "%s",
             f->dense ? "dominated option" : "option");
    y += 18;
    svg_rect(svg, x + 1, y, 10, 10,
             "rx=\"5\" fill=\"#888888\" stroke=\"#222222\"");
    svg_text(svg, x + 18, y + 9, NULL, "Pareto-optimal");
    y += 18;
    svg_line(svg, x, y + 5, x + 12, y + 5,
             "stroke=\"#888888\" stroke-width=\"1.5\"");
    svg_text(svg, x + 18, y + 9, NULL, "Pareto front");
    y += 18;
    fputs("<path fill=\"none\" stroke=\"#000000\" d=\"M", svg->out);
    svg_point(svg, x + 6, y);
    fputs(" L", svg->out);
    svg_point(svg, x + 12, y + 5);
    fputs(" L", svg->out);
    svg_point(svg, x + 6, y + 10);
    fputs(" L", svg->out);
    svg_point(svg, x, y + 5);
    fputs("Z\"/>\n", svg->out);
    svg_text(svg, x + 18, y + 9, NULL, "knee");
    y += 28;
    if (f->sized) {
        char label[160], value[48];
        axis_label(label, sizeof label, plot->size_name, plot->size_unit);
        svg_text(svg, x, y, NULL, "size: %s", label);
        y += 10;
        double values[3] = {f->size_min, (f->size_min + f->size_max) / 2,
                            f->size_max};
        int nvalues = f->size_max > f->size_min ? 3 : 1;
        for (int k = 0; k < nvalues; k++) {
            double r = bubble_radius(f, values[k]);
            char rounded[64];
            snprintf(rounded, sizeof rounded, "rx=\"%.2f\" fill=\"none\" "
                     "stroke=\"#555555\"", r);
            svg_rect(svg, x + BUBBLE_MAX - r, y, 2 * r,
                     2 * r, rounded);
            number_grouped(value, sizeof value, values[k],
                               values[k] >= 100 ? 0 : 2);
            svg_text(svg, x + 2 * BUBBLE_MAX + 8,
                     y + r + 4, NULL, "%s", value);
            y += 2 * r + 6;
        }
    }
    fputs("</g>\n", svg->out);
}

int svg_plot_write(FILE *out, const struct svg_plot *plot,
                   struct facet_error *err)
{
    int rc = check(plot, err);
    if (rc != FACET_OK)
        return rc;
    double width = plot->width > 0 ? plot->width : 800;
    double height = plot->height > 0 ? plot->height : 560;
    struct plot_frame f;
    memset(&f, 0, sizeof f);
    f.left = PLOT_LEFT;
    f.top = PLOT_TOP;
    f.width = fmax(width - PLOT_LEFT - PLOT_RIGHT_GAP, 50);
    f.height = fmax(height - PLOT_TOP - PLOT_BOTTOM_GAP, 50);

    double xlo = INFINITY, xhi = -INFINITY, ylo = INFINITY, yhi = -INFINITY;
    size_t total = 0, pareto = 0;
    f.size_min = INFINITY;
    f.size_max = -INFINITY;
    for (size_t s = 0; s < plot->nseries; s++) {
        const struct svg_plot_series *se = &plot->series[s];
        for (size_t k = 0; k < se->n; k++) {
            xlo = fmin(xlo, se->x[k]);
            xhi = fmax(xhi, se->x[k]);
            ylo = fmin(ylo, se->y[k]);
            yhi = fmax(yhi, se->y[k]);
            if (se->size != NULL) {
                f.size_min = fmin(f.size_min, se->size[k]);
                f.size_max = fmax(f.size_max, se->size[k]);
                f.sized = 1;
            }
            pareto += se->rank != NULL && se->rank[k] == 1;
        }
        total += se->n;
    }
    if (total == 0)
        xlo = ylo = 0, xhi = yhi = 1;
    /* Pad by the largest bubble at least, so that bubbles at the extremes
     * stay inside the frame. */
    double rmax = f.sized ? BUBBLE_MAX : DOT_RADIUS;
    svg_plot_axis(xlo, xhi, fmax(0.05, (rmax + 2) / f.width), 6, &f.x);
    svg_plot_axis(ylo, yhi, fmax(0.05, (rmax + 2) / f.height), 6, &f.y);

    struct svg svg;
    svg_begin(&svg, out, width, height, 2);
    svg_rect(&svg, 0, 0, width, height, "fill=\"white\"");
    svg_text(&svg, PLOT_LEFT, 24, "class=\"title\" font-size=\"16\" "
             "font-weight=\"bold\"", "%s",
             plot->title ? plot->title : "Design options");
    svg_text(&svg, PLOT_LEFT, 42, "class=\"subtitle\" fill=\"#555555\"",
             "%zu options, %zu Pareto-optimal", total, pareto);
    write_axes(&svg, &f, plot);
    fputs("<g class=\"options\">\n", out);
    /* Every run's dominated options first, then every run's front, so
     * that a second run's cloud never hides the first run's front. Past
     * DENSE_OPTIONS they are small faint dots, so thousands of options
     * read as a density and the front stands out. */
    f.dense = total > DENSE_OPTIONS;
    for (size_t s = 0; s < plot->nseries; s++) {
        const struct svg_plot_series *se = &plot->series[s];
        for (size_t k = 0; k < se->n; k++)
            if (se->rank == NULL || se->rank[k] != 1)
                write_circle(&svg, &f, plot, s, se, colour_of(se, s), k);
    }
    for (size_t s = 0; s < plot->nseries; s++) {
        const struct svg_plot_series *se = &plot->series[s];
        const char *colour = colour_of(se, s);
        if (se->rank != NULL) {
            write_front(&svg, &f, se, colour, s);
            for (size_t k = 0; k < se->n; k++)
                if (se->rank[k] == 1)
                    write_circle(&svg, &f, plot, s, se, colour, k);
        }
        if (se->knee != SIZE_MAX)
            write_knee(&svg, &f, se, s);
    }
    fputs("</g>\n", out);
    write_legend(&svg, &f, plot);
    svg_end(&svg);
    return FACET_OK;
}

int svg_plot_save(const char *path, int force, const struct svg_plot *plot,
                  struct facet_error *err)
{
    /* Check first, so that bad data creates no file at all. */
    int rc = check(plot, err);
    if (rc != FACET_OK)
        return rc;
    struct outfile file;
    rc = outfile_open(&file, path, force, err);
    if (rc != FACET_OK)
        return rc;
    rc = svg_plot_write(file.out, plot, err);
    if (rc != FACET_OK) {
        outfile_abort(&file);
        return rc;
    }
    return outfile_commit(&file, err);
}
