/*
 * parallel_model.c: axes, brushes and the dot canvas of the parallel
 * coordinates view. See parallel_model.h.
 */
#include "parallel_model.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/quantity/quantity.h"

const struct pc_axis pc_axes[PC_AXES] = {
    {"nu"}, {"nv"}, {"threshold_mm"}, {"planarity"}, {"dp_area"}, {"cost"},
    {"fp_area"}, {"sp_area"},
};

const char *pc_axis_column(const struct pc_state *st, int axis)
{
    return st->project ? quantity_of_project(pc_axes[axis].column)->name
                       : pc_axes[axis].column;
}

/* Whether axis takes whole numbers only. */
static int whole_numbers(const struct pc_state *st, int axis)
{
    return quantity_named(pc_axis_column(st, axis))->field != FIELD_DOUBLE;
}

int pc_axis_dot(double value, double min, double max, int dots)
{
    if (!isfinite(value) || dots < 1)
        return -1;
    if (!(max > min))
        return dots / 2;
    double f = (value - min) / (max - min);
    if (f < 0)
        f = 0;
    if (f > 1)
        f = 1;
    int d = (int)lround((1.0 - f) * (dots - 1));
    return d < 0 ? 0 : d >= dots ? dots - 1 : d;
}

static int has_range(const struct pc_state *st, int axis)
{
    return isfinite(st->min[axis]) && isfinite(st->max[axis]);
}

double pc_step(const struct pc_state *st, int axis)
{
    if (!has_range(st, axis) || !(st->max[axis] > st->min[axis]))
        return 1;
    double step = (st->max[axis] - st->min[axis]) / PC_STEPS;
    if (whole_numbers(st, axis))
        step = step < 1 ? 1 : round(step);
    return step;
}

/* value rounded down (up non-zero: up) to a short decimal: a power of ten
 * about a hundredth of the axis's range, or a whole number. */
static double round_edge(const struct pc_state *st, int axis, double value,
                         int up)
{
    if (whole_numbers(st, axis))
        return up ? ceil(value - 1e-9) : floor(value + 1e-9);
    double range = st->max[axis] - st->min[axis];
    if (!(range > 0))
        return value;
    double q = pow(10, floor(log10(range)) - 2);
    double n = value / q;
    /* a value already on the grid stays (n is off by an ulp or so) */
    double near = round(n);
    if (fabs(n - near) < 1e-6)
        return near * q;
    return (up ? ceil(n) : floor(n)) * q;
}

/* Clamps and deactivates a brush that covers everything. */
static void settle(struct pc_state *st, int axis)
{
    struct pc_brush *b = &st->brush[axis];
    if (b->lo < st->min[axis]) {
        b->lo = st->min[axis];
        b->lo_open = 0;
    }
    if (b->hi > st->max[axis]) {
        b->hi = st->max[axis];
        b->hi_open = 0;
    }
    if (b->lo > b->hi)
        b->lo = b->hi;
    if (b->lo <= st->min[axis] && !b->lo_open && b->hi >= st->max[axis] &&
        !b->hi_open)
        b->active = 0;
}

void pc_brush_move(struct pc_state *st, int axis, int edge, int steps)
{
    if (axis < 0 || axis >= PC_AXES || !has_range(st, axis))
        return;
    struct pc_brush *b = &st->brush[axis];
    if (!b->active) {
        b->active = 1;
        b->lo = st->min[axis];
        b->hi = st->max[axis];
    }
    double step = pc_step(st, axis) * steps;
    if (edge == 0)
        b->lo_open = 0;
    else
        b->hi_open = 0;
    if (edge == 0) {
        b->lo = round_edge(st, axis, b->lo + step, 0);
        if (b->lo > b->hi)
            b->lo = round_edge(st, axis, b->hi, 0);
    } else {
        b->hi = round_edge(st, axis, b->hi + step, 1);
        if (b->hi < b->lo)
            b->hi = round_edge(st, axis, b->lo, 1);
    }
    settle(st, axis);
}

void pc_brush_set(struct pc_state *st, int axis, double lo, double hi)
{
    if (axis < 0 || axis >= PC_AXES || !has_range(st, axis))
        return;
    struct pc_brush *b = &st->brush[axis];
    b->active = 1;
    b->lo = lo < hi ? lo : hi;
    b->hi = lo < hi ? hi : lo;
    b->lo_open = b->hi_open = 0;
    settle(st, axis);
}

/* A number with an optional k or M suffix, the whole of [text, end). */
static int parse_number(const char *text, const char *end, double *out)
{
    while (text < end && *text == ' ')
        text++;
    while (end > text && end[-1] == ' ')
        end--;
    if (text == end)
        return 1;  /* empty */
    char buffer[64];
    size_t n = (size_t)(end - text);
    if (n >= sizeof buffer)
        return -1;
    memcpy(buffer, text, n);
    buffer[n] = '\0';
    double scale = 1;
    if (buffer[n - 1] == 'k' || buffer[n - 1] == 'K')
        scale = 1e3;
    else if (buffer[n - 1] == 'M')
        scale = 1e6;
    if (scale != 1)
        buffer[--n] = '\0';
    char *stop;
    double v = strtod(buffer, &stop);
    if (stop == buffer || *stop != '\0' || !isfinite(v))
        return -1;
    *out = v * scale;
    return 0;
}

static int not_a_range(const char *text, struct facet_error *err)
{
    return facet_error_set(err, FACET_EINPUT, "range: '%s' is not LO:HI "
                           "(e.g. 1.1M:1.2M, :900, 20:)", text);
}

int pc_parse_range(const char *text, double min, double max, double *lo,
                   double *hi, struct facet_error *err)
{
    const char *sep = strstr(text, "..");
    size_t width = 2;
    if (sep == NULL) {
        sep = strchr(text, ':');
        width = 1;
    }
    if (sep == NULL) {
        /* "LO HI": the first blank between two words */
        const char *p = text;
        while (*p == ' ')
            p++;
        sep = strchr(p, ' ');
        width = 1;
        if (sep == NULL)
            return not_a_range(text, err);
    }
    int a = parse_number(text, sep, lo);
    int b = parse_number(sep + width, sep + strlen(sep), hi);
    if (a < 0 || b < 0 || (a == 1 && b == 1))
        return not_a_range(text, err);
    if (a == 1)
        *lo = min;
    if (b == 1)
        *hi = max;
    return FACET_OK;
}

/* Whether the parenthesis at text[0] closes at text's last character. */
static int enclosed(const char *text, size_t n)
{
    if (n < 2 || text[0] != '(' || text[n - 1] != ')')
        return 0;
    int depth = 0;
    for (size_t k = 0; k < n; k++) {
        if (text[k] == '(')
            depth++;
        else if (text[k] == ')' && --depth == 0 && k + 1 < n)
            return 0;
    }
    return 1;
}

/* Appends text to out (at *used), " and " first when it is not the
 * first. Returns -1 when it does not fit. */
static int append(char *out, size_t size, size_t *used, const char *text)
{
    int n = snprintf(out + *used, size - *used, "%s%s",
                     *used ? " and " : "", text);
    if (n < 0 || (size_t)n >= size - *used)
        return -1;
    *used += (size_t)n;
    return 0;
}

static int too_long(struct facet_error *err)
{
    return facet_error_set(err, FACET_EINPUT, "the filter is too long");
}

int pc_filter_text(const struct pc_state *st, char *out, size_t size,
                   struct facet_error *err)
{
    if (size == 0)
        return too_long(err);
    out[0] = '\0';
    size_t used = 0;
    char term[1100];
    if (st->base[0]) {
        size_t n = strlen(st->base);
        if (strchr(st->base, ' ') && !enclosed(st->base, n))
            snprintf(term, sizeof term, "(%s)", st->base);
        else
            snprintf(term, sizeof term, "%s", st->base);
        if (append(out, size, &used, term))
            return too_long(err);
    }
    for (int a = 0; a < PC_AXES; a++) {
        const struct pc_brush *b = &st->brush[a];
        if (!b->active)
            continue;
        if (b->lo > st->min[a] || b->lo_open) {
            snprintf(term, sizeof term, "%s %s %.15g", pc_axis_column(st, a),
                     b->lo_open ? ">" : ">=", b->lo);
            if (append(out, size, &used, term))
                return too_long(err);
        }
        if (b->hi < st->max[a] || b->hi_open) {
            snprintf(term, sizeof term, "%s %s %.15g", pc_axis_column(st, a),
                     b->hi_open ? "<" : "<=", b->hi);
            if (append(out, size, &used, term))
                return too_long(err);
        }
    }
    return FACET_OK;
}

/* The axis of column, or -1. */
static int axis_of(const struct pc_state *st, const char *column)
{
    for (int a = 0; a < PC_AXES; a++)
        if (strcmp(pc_axis_column(st, a), column) == 0)
            return a;
    return -1;
}

/* Reads one conjunct [text, text + n) as a brush edge; 0 when it is one. */
static int read_edge(struct pc_state *st, const char *text, size_t n)
{
    if (enclosed(text, n)) {
        text++;
        n -= 2;
    }
    char part[128], column[32], op[3], number[64], extra;
    if (n >= sizeof part)
        return -1;
    memcpy(part, text, n);
    part[n] = '\0';
    if (sscanf(part, "%31s %2s %63s %c", column, op, number, &extra) != 3)
        return -1;
    int a = axis_of(st, column);
    double v;
    if (a < 0 || !has_range(st, a) ||
        parse_number(number, number + strlen(number), &v) != 0)
        return -1;
    /* an edge each: "<" and ">" exclude it, "=" is both, closed */
    int equal = strcmp(op, "=") == 0;
    int lower = equal || strcmp(op, ">=") == 0 || strcmp(op, ">") == 0;
    int upper = equal || strcmp(op, "<=") == 0 || strcmp(op, "<") == 0;
    int open = strcmp(op, "<") == 0 || strcmp(op, ">") == 0;
    if (!lower && !upper)
        return -1;
    struct pc_brush *b = &st->brush[a];
    if (!b->active) {
        b->active = 1;
        b->lo = st->min[a];
        b->hi = st->max[a];
        b->lo_open = b->hi_open = 0;
    }
    if (lower && (v > b->lo || (v == b->lo && open))) {
        b->lo = v;
        b->lo_open = open;
    }
    if (upper && (v < b->hi || (v == b->hi && open))) {
        b->hi = v;
        b->hi_open = open;
    }
    return 0;
}

void pc_from_filter(struct pc_state *st, const char *filter)
{
    memset(st->brush, 0, sizeof st->brush);
    st->base[0] = '\0';
    size_t used = 0;
    const char *part = filter;
    int depth = 0;
    for (const char *p = filter;; p++) {
        int end = *p == '\0';
        if (!end && *p == '(')
            depth++;
        else if (!end && *p == ')')
            depth--;
        if (!end && !(depth == 0 && strncmp(p, " and ", 5) == 0))
            continue;
        size_t n = (size_t)(p - part);
        while (n > 0 && *part == ' ') {
            part++;
            n--;
        }
        if (n > 0 && read_edge(st, part, n) != 0) {
            char text[1024];
            snprintf(text, sizeof text, "%.*s", (int)n, part);
            if (append(st->base, sizeof st->base, &used, text) != 0) {
                /* too long to split: all of it is the base */
                memset(st->brush, 0, sizeof st->brush);
                snprintf(st->base, sizeof st->base, "%s", filter);
                return;
            }
        }
        if (end)
            break;
        part = p + 5;
        p += 4;
    }
    /* a whole "or" at the top is one base term, not split */
    depth = 0;
    for (const char *p = filter; *p; p++) {
        if (*p == '(')
            depth++;
        else if (*p == ')')
            depth--;
        else if (depth == 0 && strncmp(p, " or ", 4) == 0) {
            memset(st->brush, 0, sizeof st->brush);
            snprintf(st->base, sizeof st->base, "%s", filter);
            return;
        }
    }
}

int pc_canvas_init(struct pc_canvas *c, int width, int height,
                   struct facet_error *err)
{
    memset(c, 0, sizeof *c);
    if (width < 1 || height < 1)
        return facet_error_set(err, FACET_EINPUT,
                               "no room for a %d x %d canvas", width, height);
    size_t n = (size_t)width * (size_t)height;
    c->dots = calloc(n, 1);
    c->level = calloc(n, 1);
    c->slope = calloc(n, 1);
    if (!c->dots || !c->level || !c->slope) {
        pc_canvas_free(c);
        return facet_error_set(err, FACET_EWORK,
                               "out of memory (a %d x %d canvas)", width,
                               height);
    }
    c->width = width;
    c->height = height;
    return FACET_OK;
}

void pc_canvas_free(struct pc_canvas *c)
{
    free(c->dots);
    free(c->level);
    free(c->slope);
    memset(c, 0, sizeof *c);
}

static void plot(struct pc_canvas *c, int x, int y, int level, char slope)
{
    if (x < 0 || y < 0 || x >= 2 * c->width || y >= 4 * c->height)
        return;
    static const unsigned char bit[4][2] = {
        {0x01, 0x08}, {0x02, 0x10}, {0x04, 0x20}, {0x40, 0x80}};
    size_t k = (size_t)(y / 4) * (size_t)c->width + (size_t)(x / 2);
    unsigned char b = bit[y % 4][x % 2];
    if (level > c->level[k]) {
        c->level[k] = (unsigned char)level;
        c->dots[k] = b;
        c->slope[k] = (unsigned char)slope;
    } else if (level == c->level[k]) {
        c->dots[k] |= b;
        c->slope[k] = (unsigned char)slope;
    }
}

void pc_canvas_line(struct pc_canvas *c, int x0, int y0, int x1, int y1,
                    int level)
{
    if (level < 1)
        level = 1;
    if (level > 255)
        level = 255;
    /* slope in cells: a cell is 2 dots wide and 4 tall */
    double cx = (x1 - x0) / 2.0, cy = (y1 - y0) / 4.0;
    char slope = fabs(cy) < 0.5 * fabs(cx) ? '-'
                 : fabs(cx) < 0.5 * fabs(cy) ? '|'
                 : (cx > 0) == (cy < 0) ? '/' : '\\';
    int dx = abs(x1 - x0), dy = -abs(y1 - y0);
    int sx = x0 < x1 ? 1 : -1, sy = y0 < y1 ? 1 : -1;
    int e = dx + dy;
    for (;;) {
        plot(c, x0, y0, level, slope);
        if (x0 == x1 && y0 == y1)
            break;
        int e2 = 2 * e;
        if (e2 >= dy) {
            e += dy;
            x0 += sx;
        }
        if (e2 <= dx) {
            e += dx;
            y0 += sy;
        }
    }
}

void pc_braille(unsigned bits, char out[4])
{
    unsigned cp = 0x2800 + (bits & 0xff);
    out[0] = (char)(0xe0 | (cp >> 12));
    out[1] = (char)(0x80 | ((cp >> 6) & 0x3f));
    out[2] = (char)(0x80 | (cp & 0x3f));
    out[3] = '\0';
}
