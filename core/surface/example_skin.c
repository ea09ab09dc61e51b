/*
 * example_skin.c: the example building skin. See example_skin.h.
 *
 * The plan is walked counter-clockwise as 8 segments, straight and arc in
 * turn; a point of the skin is (segment, fraction along it, height), then
 * bulged and twisted by height. The OBJ text is formatted by hand into a
 * buffer (fixed decimals from a rounded integer), which writes 2M
 * triangles in about a second where printf's %g takes several.
 */
#include "core/surface/example_skin.h"

#include <assert.h>
#include <math.h>
#include <stdlib.h>
#include <stdint.h>
#include <string.h>

#define PI 3.14159265358979323846

#define HALF_X 50.0       /* half the plan's length (m) */
#define HALF_Y 30.0       /* half its width */
#define CORNER 18.0       /* corner radius */
#define HEIGHT 180.0
#define ROW_HEIGHT (HEIGHT / SKIN_ROWS)
#define PODIUM_ROWS 2     /* extruded, no bulge */
#define TWIST_ROW 6       /* first twisted row */
#define BULGE 0.12
#define TWIST 0.35        /* rad at the top */

struct segment {
    int arc;              /* 0: straight from a to b; 1: quarter arc */
    double a[2], b[2];    /* straight: ends; arc: a = centre, b[0] = start
                             angle */
    int columns;
};

static const struct segment segments[8] = {
    {0, {HALF_X, -(HALF_Y - CORNER)}, {HALF_X, HALF_Y - CORNER}, 2},
    {1, {HALF_X - CORNER, HALF_Y - CORNER}, {0, 0}, 2},
    {0, {HALF_X - CORNER, HALF_Y}, {-(HALF_X - CORNER), HALF_Y}, 4},
    {1, {-(HALF_X - CORNER), HALF_Y - CORNER}, {0.5 * PI, 0}, 2},
    {0, {-HALF_X, HALF_Y - CORNER}, {-HALF_X, -(HALF_Y - CORNER)}, 2},
    {1, {-(HALF_X - CORNER), -(HALF_Y - CORNER)}, {PI, 0}, 2},
    {0, {-(HALF_X - CORNER), -HALF_Y}, {HALF_X - CORNER, -HALF_Y}, 4},
    {1, {HALF_X - CORNER, -(HALF_Y - CORNER)}, {1.5 * PI, 0}, 2},
};

/* The segment of column c and the column's index within it. */
static const struct segment *column_segment(int c, int *within)
{
    for (int g = 0; g < 8; g++) {
        if (c < segments[g].columns) {
            *within = c;
            return &segments[g];
        }
        c -= segments[g].columns;
    }
    assert(0 && "column out of range");
    *within = 0;
    return &segments[0];
}

static double smoothstep01(double x)
{
    if (x <= 0)
        return 0;
    if (x >= 1)
        return 1;
    return x * x * (3 - 2 * x);
}

/* The point of column c at fraction f of it (0 <= f < 1 for canonical
 * seams; f = 1 only from skin_point) and height z. */
static void point_at(int c, double f, double z, double p[3])
{
    int within;
    const struct segment *g = column_segment(c, &within);
    double along = (within + f) / g->columns;
    double x, y;
    if (g->arc) {
        double angle = g->b[0] + along * 0.5 * PI;
        x = g->a[0] + CORNER * cos(angle);
        y = g->a[1] + CORNER * sin(angle);
    } else {
        x = g->a[0] + along * (g->b[0] - g->a[0]);
        y = g->a[1] + along * (g->b[1] - g->a[1]);
    }
    double scale = 1, turn = 0;
    if (z > PODIUM_ROWS * ROW_HEIGHT) {
        double w = sin(PI * (z - PODIUM_ROWS * ROW_HEIGHT) /
                       (HEIGHT - PODIUM_ROWS * ROW_HEIGHT));
        scale = 1 + BULGE * w * w;
    }
    if (z > TWIST_ROW * ROW_HEIGHT)
        turn = TWIST * smoothstep01((z - TWIST_ROW * ROW_HEIGHT) /
                                    (HEIGHT - TWIST_ROW * ROW_HEIGHT));
    double cs = cos(turn), sn = sin(turn);
    p[0] = scale * (x * cs - y * sn);
    p[1] = scale * (x * sn + y * cs);
    p[2] = z;
}

/* The point at global grid indices: i counts res steps per column around
 * the tower (taken modulo the loop), j res steps per row from the bottom.
 * Each seam vertex has one (i, j), so both faces get the same bits. */
static void grid_point(long i, long j, int res, double p[3])
{
    long around = (long)SKIN_COLUMNS * res;
    i = ((i % around) + around) % around;
    int c = (int)(i / res);
    double f = (double)(i % res) / res;
    point_at(c, f, HEIGHT * (double)j / ((double)SKIN_ROWS * res), p);
}

void skin_point(int face, double s, double t, double p[3])
{
    int row = face / SKIN_COLUMNS, c = face % SKIN_COLUMNS;
    point_at(c, s, ROW_HEIGHT * (row + t), p);
}

enum skin_kind skin_face_kind(int face)
{
    int row = face / SKIN_COLUMNS, within;
    const struct segment *g = column_segment(face % SKIN_COLUMNS, &within);
    if (row >= TWIST_ROW)
        return SKIN_DOUBLE;
    if (row < PODIUM_ROWS)
        return g->arc ? SKIN_SINGLE : SKIN_FLAT;
    return g->arc ? SKIN_DOUBLE : SKIN_SINGLE;
}

int skin_face_vt_metres(int face)
{
    return skin_face_kind(face) == SKIN_FLAT;
}

void skin_face_name(int face, char *name, size_t size)
{
    snprintf(name, size, "skin_r%02d_c%02d", face / SKIN_COLUMNS,
             face % SKIN_COLUMNS);
}

/* ---- writing ---------------------------------------------------------- */

struct writer {
    FILE *out;
    char buffer[1 << 16];
    size_t used;
    int failed;
};

static void flush(struct writer *w)
{
    if (w->used > 0 && fwrite(w->buffer, 1, w->used, w->out) != w->used)
        w->failed = 1;
    w->used = 0;
}

/* Room for one line (the longest is an f line: 6 numbers of 10 digits). */
static char *line_start(struct writer *w)
{
    if (w->used > sizeof w->buffer - 256)
        flush(w);
    return w->buffer + w->used;
}

static void line_end(struct writer *w, char *end)
{
    *end++ = '\n';
    w->used = (size_t)(end - w->buffer);
}

static char *put_text(char *p, const char *text)
{
    size_t n = strlen(text);
    memcpy(p, text, n);
    return p + n;
}

static char *put_unsigned(char *p, uint64_t n)
{
    char digits[24];
    int k = 0;
    do {
        digits[k++] = (char)('0' + n % 10);
        n /= 10;
    } while (n > 0);
    while (k > 0)
        *p++ = digits[--k];
    return p;
}

/* x with exactly decimals places (6 or 9), rounded half away from zero. */
static char *put_fixed(char *p, double x, int decimals)
{
    uint64_t unit = decimals == 9 ? 1000000000u : 1000000u;
    double scaled = round(fabs(x) * (double)unit);
    uint64_t n = (uint64_t)scaled;
    if (x < 0 && n > 0)
        *p++ = '-';
    p = put_unsigned(p, n / unit);
    *p++ = '.';
    uint64_t fraction = n % unit;
    for (int k = decimals - 1; k >= 0; k--) {
        p[k] = (char)('0' + fraction % 10);
        fraction /= 10;
    }
    return p + decimals;
}

static char *put_corner(char *p, uint64_t v, uint64_t vt)
{
    *p++ = ' ';
    p = put_unsigned(p, v);
    *p++ = '/';
    return put_unsigned(p, vt);
}

static void write_face(struct writer *w, int face, int res, uint64_t base)
{
    int row = face / SKIN_COLUMNS, c = face % SKIN_COLUMNS;
    char name[32];
    skin_face_name(face, name, sizeof name);
    char *p = line_start(w);
    p = put_text(p, "o ");
    p = put_text(p, name);
    line_end(w, p);
    for (int l = 0; l <= res; l++)
        for (int k = 0; k <= res; k++) {
            double q[3];
            grid_point((long)c * res + k, (long)row * res + l, res, q);
            p = line_start(w);
            p = put_text(p, "v");
            for (int x = 0; x < 3; x++) {
                *p++ = ' ';
                p = put_fixed(p, q[x], 6);
            }
            line_end(w, p);
        }
    /* vt in metres: the face's width (its chord on the plan) and height. */
    double width = 0;
    int metres = skin_face_vt_metres(face);
    if (metres) {
        double a[3], b[3];
        skin_point(face, 0, 0, a);
        skin_point(face, 1, 0, b);
        width = hypot(b[0] - a[0], b[1] - a[1]);
    }
    for (int l = 0; l <= res; l++)
        for (int k = 0; k <= res; k++) {
            double s = (double)k / res, t = (double)l / res;
            p = line_start(w);
            p = put_text(p, "vt ");
            if (metres) {
                p = put_fixed(p, s * width, 6);
                *p++ = ' ';
                p = put_fixed(p, t * ROW_HEIGHT, 6);
            } else {
                p = put_fixed(p, s, 9);
                *p++ = ' ';
                p = put_fixed(p, t, 9);
            }
            line_end(w, p);
        }
    /* Alternating diagonals, as the single examples (example.c). */
    for (int l = 0; l < res; l++)
        for (int k = 0; k < res; k++) {
            uint64_t a = base + (uint64_t)l * (res + 1) + k + 1, b = a + 1;
            uint64_t cc = b + res + 1, d = a + res + 1;
            uint64_t tri[2][3];
            if ((k + l) % 2 == 0) {
                uint64_t t0[2][3] = {{a, b, cc}, {a, cc, d}};
                memcpy(tri, t0, sizeof tri);
            } else {
                uint64_t t1[2][3] = {{a, b, d}, {b, cc, d}};
                memcpy(tri, t1, sizeof tri);
            }
            for (int h = 0; h < 2; h++) {
                p = line_start(w);
                *p++ = 'f';
                for (int x = 0; x < 3; x++)
                    p = put_corner(p, tri[h][x], tri[h][x]);
                line_end(w, p);
            }
        }
}

int skin_write(int res, FILE *out, struct facet_error *err)
{
    if (res == 0)
        res = SKIN_DEFAULT_RES;
    if (res < 1 || res > SKIN_MAX_RES)
        return facet_error_set(err, FACET_EINPUT,
            "resolution %d is out of range for the skin (1 to %d quads a "
            "side per face)", res, SKIN_MAX_RES);
    struct writer *w = calloc(1, sizeof *w);  /* 64 KiB: not the stack */
    if (w == NULL)
        return facet_error_set(err, FACET_EWORK, "out of memory (skin)");
    w->out = out;
    fprintf(out, "# Facet example 'skin': a 180 m tower of %d faces, "
                 "flat, single- and double-curved\n", SKIN_FACES);
    fprintf(out, "# units: metres; one o per face, each with its own v "
                 "and vt; %d x %d quads per face\n", res, res);
    uint64_t per_face = (uint64_t)(res + 1) * (res + 1);
    for (int face = 0; face < SKIN_FACES && !w->failed; face++)
        write_face(w, face, res, per_face * (uint64_t)face);
    flush(w);
    int failed = w->failed;
    free(w);
    if (failed || fflush(out) != 0 || ferror(out))
        return facet_error_set(err, FACET_EWORK,
                               "writing the example 'skin' failed");
    return FACET_OK;
}
