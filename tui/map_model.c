/*
 * map_model.c: scaling panel maps. See map_model.h.
 */
#include "map_model.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "core/base/units.h"
#include "core/classify/classify.h"

static const struct panel *panel_at(const struct panelization *p, int i,
                                    int j)
{
    if (i < 0 || j < 0 || i >= p->nu || j >= p->nv)
        return NULL;
    int k = p->cell_panel[(size_t)j * (size_t)p->nu + (size_t)i];
    return k >= 0 ? &p->panels[k] : NULL;
}

static double edge(const double a[3], const double b[3])
{
    double dx = b[0] - a[0], dy = b[1] - a[1], dz = b[2] - a[2];
    return sqrt(dx * dx + dy * dy + dz * dz);
}

/* The mean, over the grid lines that have any, of the summed edge
 * lengths along u (along_u) or v. */
static double extent(const struct panelization *p, int along_u)
{
    int lines = along_u ? p->nv : p->nu, cells = along_u ? p->nu : p->nv;
    double sum = 0;
    int counted = 0;
    for (int l = 0; l < lines; l++) {
        double length = 0;
        int edges = 0;
        for (int k = 0; k < cells; k++) {
            const struct panel *q = along_u ? panel_at(p, k, l)
                                            : panel_at(p, l, k);
            if (q == NULL)
                continue;
            /* corners (i,j), (i+1,j), (i+1,j+1), (i,j+1) */
            const double *a = q->corner[0];
            const double *b = along_u ? q->corner[1] : q->corner[3];
            double e = edge(a, b);
            if (isfinite(e)) {
                length += e;
                edges++;
            }
        }
        if (edges > 0) {
            /* a line with cells off the surface is as long as its
             * panels reach */
            sum += length;
            counted++;
        }
    }
    return counted > 0 ? sum / counted : NAN;
}

void map_surface_size(const struct panelization *p, double *width,
                      double *height)
{
    *width = extent(p, 1);
    *height = extent(p, 0);
    if (!(*width > 0) || !(*height > 0)) {
        *width = p->umax - p->umin;
        *height = p->vmax - p->vmin;
    }
    if (!(*width > 0) || !(*height > 0))
        *width = *height = 1;
}

void map_fit_box(double width, double height, int max_cols, int max_rows,
                 double cell_aspect, int *cols, int *rows)
{
    if (max_cols < 1)
        max_cols = 1;
    if (max_rows < 1)
        max_rows = 1;
    /* characters across per character down at the true aspect */
    double per_row = width / height * cell_aspect;
    if (!(per_row > 0) || !isfinite(per_row))
        per_row = cell_aspect;
    int r = max_rows, c = (int)floor(r * per_row + 0.5);
    if (c > max_cols) {
        c = max_cols;
        r = (int)floor(c / per_row + 0.5);
    }
    *cols = c < 1 ? 1 : c > max_cols ? max_cols : c;
    *rows = r < 1 ? 1 : r > max_rows ? max_rows : r;
}

/* The slot of value in values[0..*n) (added when new, while room is
 * left), or -1. */
static int slot_of(int *values, int *n, int value)
{
    for (int k = 0; k < *n; k++)
        if (values[k] == value)
            return k;
    if (*n >= MAP_MOULDS_PER_CHAR)
        return -1;
    values[*n] = value;
    return (*n)++;
}

int map_by_level(enum map_colour colour)
{
    return colour == MAP_BY_GAP || colour == MAP_BY_KINK ||
           colour == MAP_BY_MOVE;
}

double map_panel_measure(const struct panelization *p, const struct panel *q,
                         enum map_colour colour)
{
    if (colour == MAP_BY_MOVE)
        return units_mm(panel_corner_moved(p, (size_t)(q - p->panels)));
    return colour == MAP_BY_KINK ? units_deg(q->worst_kink)
                                 : units_mm(q->worst_gap);
}

void map_level_bounds(double limit, double largest,
                      double bound[MAP_LEVELS])
{
    static const double share[2][MAP_LEVELS - 1] = {
        {0.5, 0.75, 1}, {0.25, 0.5, 0.75}};
    int relative = !(limit > 0);
    double reference = relative ? largest : limit;
    if (!(reference > 0) || !isfinite(reference))
        reference = 0;
    for (int k = 0; k < MAP_LEVELS - 1; k++)
        bound[k] = reference * share[relative][k];
    bound[MAP_LEVELS - 1] = INFINITY;
}

int map_level(double value, const double bound[MAP_LEVELS])
{
    if (isnan(value))
        return -1;
    for (int k = 0; k < MAP_LEVELS; k++)
        if (value <= bound[k])
            return k;
    return MAP_LEVELS - 1;
}

/* The highest level of a panel in character (c, r)'s share (as
 * map_cell_value): of its own worst joints, or with seams of its seam
 * joints (map_seam_measure). */
static int cell_level(const struct panelization *p,
                      const struct map_seams *seams, int cols, int rows,
                      int c, int r, enum map_colour colour,
                      const double *bound)
{
    double u0 = (double)c * p->nu / cols, u1 = (double)(c + 1) * p->nu / cols;
    int rb = rows - 1 - r;
    double v0 = (double)rb * p->nv / rows;
    double v1 = (double)(rb + 1) * p->nv / rows;
    int level = -1;
    for (int j = (int)floor(v0); j < p->nv && j < v1; j++) {
        if (fmin(v1, j + 1) - fmax(v0, j) <= 0)
            continue;
        for (int i = (int)floor(u0); i < p->nu && i < u1; i++) {
            const struct panel *q = panel_at(p, i, j);
            if (q == NULL || fmin(u1, i + 1) - fmax(u0, i) <= 0)
                continue;
            double x = seams != NULL
                ? map_seam_measure(seams, (size_t)(q - p->panels), colour)
                : map_panel_measure(p, q, colour);
            int k = map_level(x, bound);
            if (k > level)
                level = k;
        }
    }
    return level;
}

int map_cell_value(const struct panelization *p, int cols, int rows, int c,
                   int r, enum map_colour colour, const double *bound)
{
    if (map_by_level(colour))
        return cell_level(p, NULL, cols, rows, c, r, colour, bound);
    double weight[MAP_MOULDS_PER_CHAR] = {0};
    int value_of[MAP_MOULDS_PER_CHAR];
    int values = colour == MAP_BY_CLASS ? CLASS_COUNT : TYPE_COUNT;
    if (colour == MAP_BY_MOULD)
        values = 0;
    else
        for (int k = 0; k < values; k++)
            value_of[k] = k;
    double empty = 0;
    /* the character's share of the grid, in cells: u along i, and v
     * along j counted up from the bottom row */
    double u0 = (double)c * p->nu / cols, u1 = (double)(c + 1) * p->nu / cols;
    int rb = rows - 1 - r;
    double v0 = (double)rb * p->nv / rows;
    double v1 = (double)(rb + 1) * p->nv / rows;
    for (int j = (int)floor(v0); j < p->nv && j < v1; j++) {
        double wj = fmin(v1, j + 1) - fmax(v0, j);
        if (wj <= 0)
            continue;
        for (int i = (int)floor(u0); i < p->nu && i < u1; i++) {
            double w = (fmin(u1, i + 1) - fmax(u0, i)) * wj;
            if (w <= 0)
                continue;
            const struct panel *q = panel_at(p, i, j);
            int k = q == NULL ? -1
                    : colour == MAP_BY_CLASS ? (int)q->class
                    : colour == MAP_BY_TYPE ? (int)q->type
                    : slot_of(value_of, &values,
                              q->mould >= 0 ? q->mould : MAP_NO_MOULD);
            if (q == NULL)
                empty += w;
            else if (k >= 0)
                weight[k] += w;
        }
    }
    int best = -1;
    for (int k = 0; k < values; k++)
        if (weight[k] > 0 && (best < 0 || weight[k] >= weight[best]))
            best = k;
    return best >= 0 && weight[best] >= empty ? value_of[best] : -1;
}

size_t map_family_size(const struct panelization *p, int family)
{
    size_t n = 0;
    for (size_t k = 0; k < p->npanels; k++)
        n += p->panels[k].mould == family && family >= 0;
    return n;
}

void map_cell_of(const struct panelization *p, int cols, int rows, int i,
                 int j, int *c, int *r)
{
    *c = (int)floor((i + 0.5) * cols / p->nu);
    int rb = (int)floor((j + 0.5) * rows / p->nv);
    *r = rows - 1 - rb;
}

int map_surface_step(int current, int n, int step)
{
    int k = current + step;
    if (k < 0)
        k = 0;
    if (k > n - 1)
        k = n - 1;
    return k < 0 ? 0 : k;
}

void map_surface_title(char *out, size_t size, int k, int n,
                       const char *name, int nu, int nv)
{
    snprintf(out, size, "surface %d of %d: %s (%d x %d)", k + 1, n, name,
             nu, nv);
}

int map_seams_of_surface(const struct building_seam_joint *joints, size_t n,
                         size_t surface, size_t npanels,
                         struct map_seams *out)
{
    out->npanels = npanels;
    out->joints = 0;
    out->gap = malloc((npanels ? npanels : 1) * sizeof *out->gap);
    out->added = malloc((npanels ? npanels : 1) * sizeof *out->added);
    if (out->gap == NULL || out->added == NULL) {
        map_seams_free(out);
        return -1;
    }
    for (size_t k = 0; k < npanels; k++)
        out->gap[k] = out->added[k] = NAN;
    for (size_t k = 0; k < n; k++) {
        const struct building_seam_joint *b = &joints[k];
        /* a surface may meet itself along a seam only from two sides */
        for (int side = 0; side < 2; side++) {
            size_t of = side ? b->b : b->a;
            int32_t panel = side ? b->joint.panel_b : b->joint.panel_a;
            if (of != surface || panel < 0 || (size_t)panel >= npanels)
                continue;
            double *gap = &out->gap[panel], *added = &out->added[panel];
            *gap = isnan(*gap) ? b->joint.gap : fmax(*gap, b->joint.gap);
            *added = isnan(*added) ? b->joint.added
                                   : fmax(*added, b->joint.added);
            out->joints++;
        }
    }
    return 0;
}

void map_seams_free(struct map_seams *seams)
{
    free(seams->gap);
    free(seams->added);
    seams->gap = seams->added = NULL;
    seams->npanels = seams->joints = 0;
}

double map_seam_measure(const struct map_seams *seams, size_t k,
                        enum map_colour colour)
{
    if (seams == NULL || k >= seams->npanels)
        return NAN;
    if (colour == MAP_BY_GAP)
        return units_mm(seams->gap[k]);
    if (colour == MAP_BY_KINK)
        return units_deg(seams->added[k]);
    return NAN;
}

double map_seams_largest(const struct map_seams *seams,
                         enum map_colour colour)
{
    double most = NAN;
    for (size_t k = 0; seams != NULL && k < seams->npanels; k++) {
        double x = map_seam_measure(seams, k, colour);
        if (!isnan(x))
            most = isnan(most) ? x : fmax(most, x);
    }
    return most;
}

int map_seam_cell_level(const struct panelization *p,
                        const struct map_seams *seams, int cols, int rows,
                        int c, int r, enum map_colour colour,
                        const double *bound)
{
    if (seams == NULL || (colour != MAP_BY_GAP && colour != MAP_BY_KINK))
        return -1;
    return cell_level(p, seams, cols, rows, c, r, colour, bound);
}

char map_seam_glyph(int level)
{
    return level >= MAP_LEVELS - 1 ? '!' : '=';
}
