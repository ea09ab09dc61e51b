/*
 * panel_lattice_build.c: dividing the surface along every line of a design
 * space. See panel_lattice.h, and panel_lattice_internal.h for what is kept.
 *
 * The triangles are clipped row by row and then cell by cell, as
 * panel_fast.c clips a triangle, into the fine cells' sums; the piece
 * vertices that are mesh points on a line or crossings of two lines are
 * noted on the way. The cuts of mesh edges by the lines are found edge by
 * edge, and the running sums made last. Each part runs on every core.
 */
#include "core/panel/panel_lattice_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/base/extremes.h"
#include "core/base/parallel.h"

/* The number of lines at or below x. */
static size_t line_rank_above(const double *line, size_t n, double x)
{
    size_t lo = 0, hi = n;
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        if (line[mid] <= x)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo;
}

static int compare_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

/* The interior lines of every grid side lo..hi over [min, max], as the
 * grids compute them, sorted and distinct, into *line (malloc'ed). */
static int make_lines(double min, double max, int lo, int hi, double **line,
                      size_t *nline)
{
    size_t n = 0;
    for (int side = lo; side <= hi; side++)
        n += (size_t)(side - 1);
    double *all = malloc((n ? n : 1) * sizeof *all);
    if (all == NULL)
        return FACET_EWORK;
    n = 0;
    for (int side = lo; side <= hi; side++) {
        double step = (max - min) / side;
        for (int i = 1; i < side; i++)
            all[n++] = min + i * step;
    }
    qsort(all, n, sizeof *all, compare_double);
    size_t distinct = 0;
    for (size_t k = 0; k < n; k++)
        if (distinct == 0 || all[k] != all[distinct - 1])
            all[distinct++] = all[k];
    *line = all;
    *nline = distinct;
    return FACET_OK;
}

static void sample_at(const struct panel_prep *prep, const uint32_t *point,
                      const double b[3], struct lattice_sample *out)
{
    const struct panel_prep_point *P[3] = {&prep->point[point[0]],
                                           &prep->point[point[1]],
                                           &prep->point[point[2]]};
    panel_point_at(P, b, out->position, &out->k1, &out->k2);
}

/* --- building --- */

static int compare_extra(const void *a, const void *b)
{
    const struct lattice_extra *x = a, *y = b;
    if (x->point != y->point)
        return x->point < y->point ? -1 : 1;
    if (x->column != y->column)
        return x->column < y->column ? -1 : 1;
    return x->row < y->row ? -1 : x->row > y->row;
}

/* One thread's share of dividing the triangles: the fine rows
 * row_lo..row_hi-1, from every triangle that reaches them. Rows are the
 * unit so that no two threads write one fine cell or one line crossing. */
struct divide_job {
    struct panel_lattice *lattice;
    uint32_t *fine_pieces;          /* nrows x ncolumns: pieces with area */
    size_t row_lo, row_hi;
    struct lattice_extra *extra;    /* this job's points on lines */
    size_t nextra, capacity;
    int rc;
    const struct facet_stop *stop;  /* asked every STOP_EVERY triangles */
};

/* Triangles divided between two questions to the stop: milliseconds. */
#define STOP_EVERY ((size_t)1 << 15)

static int note_extra(struct divide_job *job, uint32_t point, size_t column,
                      size_t row)
{
    struct lattice_extra e = {point, (uint32_t)column, (uint32_t)row};
    if (job->nextra > 0) {
        const struct lattice_extra *last = &job->extra[job->nextra - 1];
        if (last->point == point && last->column == e.column &&
            last->row == e.row)
            return FACET_OK;
    }
    if (job->nextra == job->capacity) {
        size_t grown = job->capacity ? 2 * job->capacity : 1024;
        struct lattice_extra *more = realloc(job->extra,
                                             grown * sizeof *more);
        if (more == NULL)
            return FACET_EWORK;
        job->extra = more;
        job->capacity = grown;
    }
    job->extra[job->nextra++] = e;
    return FACET_OK;
}

/* Files what pass 2 needs from piece vertices in fine cell (column, row)
 * of triangle t: its mesh points that lie on a line, and the line
 * crossings inside it. A crossing is taken from the row below it only: a
 * crossing inside a triangle is a vertex of its piece there, and one on a
 * mesh edge is also a cut of that edge, filed with the cuts. */
static int note_piece_vertices(struct divide_job *job, uint32_t t,
                               size_t column, size_t row,
                               const struct split_vertex *piece, int count)
{
    struct panel_lattice *L = job->lattice;
    const uint32_t *point = L->prep->corner + 3 * (size_t)t;
    for (int k = 0; k < count; k++) {
        const struct split_vertex *x = &piece[k];
        int corner = x->b[0] == 1 ? 0 : x->b[1] == 1 ? 1 : x->b[2] == 1 ? 2
                                                                      : -1;
        if (corner >= 0) {
            uint32_t p = point[corner];
            if ((L->on_line[2 * (size_t)p] != 0 ||
                 L->on_line[2 * (size_t)p + 1] != 0) &&
                note_extra(job, p, column, row) != FACET_OK)
                return FACET_EWORK;
            continue;
        }
        if (row >= L->nline[1] || x->v != L->line[1][row])
            continue;
        size_t a;
        if (column > 0 && x->u == L->line[0][column - 1])
            a = column - 1;
        else if (column < L->nline[0] && x->u == L->line[0][column])
            a = column;
        else
            continue;
        struct lattice_corner *q = &L->corner[row * L->nline[0] + a];
        if (q->state >= 0)
            continue;
        sample_at(L->prep, point, x->b, &q->at);
        q->state = x->b[0] <= 1e-12 || x->b[1] <= 1e-12 || x->b[2] <= 1e-12;
    }
    return FACET_OK;
}

/* One triangle being divided: what add_piece needs besides the piece. */
struct dividing {
    struct divide_job *job;
    uint32_t t;
    double corner[3][3];  /* relative to the triangle's centroid */
};

/* Adds a piece of the triangle to fine cell (column, row). */
static int add_piece(void *context, size_t column, size_t row,
                     const struct split_vertex *piece, int count)
{
    struct dividing *d = context;
    struct panel_lattice *L = d->job->lattice;
    const struct panel_prep_triangle *T = &L->prep->triangle[d->t];
    size_t cell = row * L->ncolumns + column;
    struct piece_moments m;
    panel_piece_moments(T, d->corner, piece, count, &m);
    cell_moments_add(&L->fine[cell], T->centroid, &m);
    if (m.area > 0)
        d->job->fine_pieces[cell]++;
    return note_piece_vertices(d->job, d->t, column, row, piece, count);
}

/* Clips triangle t along the fine lines into the fine sums of the job's
 * rows. */
static int divide_triangle(struct divide_job *job, uint32_t t)
{
    struct panel_lattice *L = job->lattice;
    const struct panel_prep *prep = L->prep;
    const struct panel_prep_triangle *T = &prep->triangle[t];
    const uint32_t *point = prep->corner + 3 * (size_t)t;
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (int k = 0; k < 3; k++)
        for (int a = 0; a < 2; a++) {
            double x = prep->point_uv[2 * point[k] + a];
            lo[a] = smaller(lo[a], x);
            hi[a] = larger(hi[a], x);
        }
    int on;
    size_t c0 = line_rank(L->line[0], L->nline[0], lo[0], &on);
    size_t c1 = line_rank_above(L->line[0], L->nline[0], hi[0]);
    size_t r0 = line_rank(L->line[1], L->nline[1], lo[1], &on);
    size_t r1 = line_rank_above(L->line[1], L->nline[1], hi[1]);
    if (r1 < job->row_lo || r0 >= job->row_hi)
        return FACET_OK;
    if (c0 == c1 && r0 == r1) {
        size_t cell = r0 * L->ncolumns + c0;
        cell_moments_add_triangle(&L->fine[cell], T);
        if (T->area > 0)
            job->fine_pieces[cell]++;
        return FACET_OK;
    }
    struct dividing d = {job, t, {{0}}};
    panel_triangle_corners(prep, t, d.corner);
    return panel_split_cells(prep, t, L->line[0], c0, c1, L->line[1], r0, r1,
                             job->row_lo, job->row_hi, add_piece, &d);
}

static void divide_run(void *argument)
{
    /* Worked on in a copy: jobs lie side by side in one array, and
     * writing to a neighbour's cache line on every triangle would cost
     * more than the second thread gains. */
    struct divide_job job = *(struct divide_job *)argument;
    struct panel_lattice *L = job.lattice;
    const struct panel_prep *prep = L->prep;
    /* The job's rows are zeroed here, by writing: memory read before it
     * is written maps the zero page, and replacing that with threads
     * running costs every CPU a TLB flush on each page. */
    size_t first = job.row_lo * L->ncolumns;
    size_t cells = (job.row_hi - job.row_lo) * L->ncolumns;
    memset(&L->fine[first], 0, cells * sizeof *L->fine);
    memset(&job.fine_pieces[first], 0, cells * sizeof *job.fine_pieces);
    for (size_t t = 0; t < prep->mesh->ntriangles && job.rc == FACET_OK;
         t++) {
        if (t % STOP_EVERY == STOP_EVERY - 1 &&
            facet_stop_requested(job.stop)) {
            job.rc = FACET_ESTOP;
            break;
        }
        job.rc = divide_triangle(&job, (uint32_t)t);
    }
    *(struct divide_job *)argument = job;
}

/* Which edges each triangle files cuts for, so that an edge two
 * triangles share is filed once: bit k of owned[t] for the edge from
 * corner k to corner k + 1, set unless the edge runs from the higher point
 * to the lower and its twin (the other way round) is another triangle's.
 * A hash set of the directed edges tells. Returns the malloc'ed mask or
 * NULL when out of memory. */
static unsigned char *owned_edges(const struct panel_prep *prep)
{
    size_t nt = prep->mesh->ntriangles, size = 1024;
    while (size < 6 * nt)
        size *= 2;
    uint64_t *key = malloc(size * sizeof *key);
    unsigned char *owned = malloc(nt ? nt : 1);
    if (key == NULL || owned == NULL) {
        free(key);
        free(owned);
        return NULL;
    }
    size_t mask = size - 1;
    for (size_t k = 0; k < size; k++)
        key[k] = UINT64_MAX;
    for (int pass = 0; pass < 2; pass++)
        for (size_t t = 0; t < nt; t++) {
            const uint32_t *point = prep->corner + 3 * t;
            if (pass == 1)
                owned[t] = 0;
            for (int k = 0; k < 3; k++) {
                uint32_t from = point[k], to = point[k == 2 ? 0 : k + 1];
                /* Inserted the way it runs; looked up the other way. */
                uint64_t wanted = pass == 0 ? (uint64_t)from << 32 | to
                                            : (uint64_t)to << 32 | from;
                size_t slot = (size_t)((wanted * 0x9E3779B97F4A7C15ull) >>
                                       20) & mask;
                while (key[slot] != UINT64_MAX && key[slot] != wanted)
                    slot = (slot + 1) & mask;
                if (pass == 0)
                    key[slot] = wanted;
                else if (from < to || key[slot] != wanted)
                    owned[t] |= (unsigned char)(1u << k);
            }
        }
    free(key);
    return owned;
}

/* For every cut of a fine line of axis by a mesh edge (a shared edge
 * once): with cut NULL, makes room for it in count[line] (two slots: a cut
 * on a crossing of lines is filed for the cells on each side); else writes
 * it at cut[count[line]++]. */
static void cut_edges(const struct panel_lattice *L,
                      const unsigned char *owned, int axis, size_t *count,
                      struct lattice_cut *cut)
{
    const struct panel_prep *prep = L->prep;
    const double *line = L->line[axis], *across = L->line[1 - axis];
    size_t nline = L->nline[axis], nacross = L->nline[1 - axis];
    for (size_t t = 0; t < prep->mesh->ntriangles; t++) {
        const uint32_t *point = prep->corner + 3 * t;
        for (int k = 0; k < 3; k++) {
            if (!(owned[t] >> k & 1))
                continue;
            uint32_t pa = point[k], pb = point[k == 2 ? 0 : k + 1];
            double xa = prep->point_uv[2 * pa + axis];
            double xb = prep->point_uv[2 * pb + axis];
            if (xa == xb)
                continue;
            /* The lines strictly between the ends: a line through an end
             * is that point's, not a cut. */
            int on;
            size_t first = line_rank_above(line, nline, fmin(xa, xb));
            size_t last = line_rank(line, nline, fmax(xa, xb), &on);
            if (cut == NULL) {
                for (size_t n = first; n < last; n++)
                    count[n] += 2;
                continue;
            }
            double ya = prep->point_uv[2 * pa + 1 - axis];
            double yb = prep->point_uv[2 * pb + 1 - axis];
            uint32_t ends[3] = {pa, pb, pb};
            for (size_t n = first; n < last; n++) {
                double s = (line[n] - xa) / (xb - xa);
                double b[3] = {1 - s, s, 0};
                struct lattice_cut c;
                sample_at(prep, ends, b, &c.at);
                size_t r = line_rank(across, nacross, ya + s * (yb - ya),
                                     &on);
                c.across = (uint32_t)r;
                cut[count[n]++] = c;
                if (on) {
                    c.across = (uint32_t)r + 1;
                    cut[count[n]++] = c;
                }
            }
        }
    }
}

/* Files the cuts of the lines of axis, line by line. */
static int file_cuts(struct panel_lattice *L, const unsigned char *owned,
                     int axis)
{
    size_t nline = L->nline[axis];
    size_t *room = calloc(nline ? nline : 1, sizeof *room);
    size_t *start = malloc((nline + 1) * sizeof *start);
    if (room == NULL || start == NULL) {
        free(room);
        free(start);
        return FACET_EWORK;
    }
    L->cut_start[axis] = start;
    cut_edges(L, owned, axis, room, NULL);
    size_t total = 0;
    for (size_t n = 0; n < nline; n++) {
        start[n] = total;
        total += room[n];
        room[n] = start[n];
    }
    start[nline] = total;
    struct lattice_cut *cut = malloc((total ? total : 1) * sizeof *cut);
    if (cut == NULL) {
        free(room);
        return FACET_EWORK;
    }
    L->cut[axis] = cut;
    cut_edges(L, owned, axis, room, cut);
    /* Close the room left for crossings that were not. */
    size_t kept = 0;
    for (size_t n = 0; n < nline; n++) {
        size_t begin = start[n], end = room[n];
        start[n] = kept;
        memmove(&cut[kept], &cut[begin], (end - begin) * sizeof *cut);
        kept += end - begin;
    }
    start[nline] = kept;
    free(room);
    struct lattice_cut *shrunk = realloc(cut, (kept ? kept : 1) * sizeof *cut);
    if (shrunk != NULL)
        L->cut[axis] = shrunk;
    return FACET_OK;
}

struct cut_job {
    struct panel_lattice *lattice;
    const unsigned char *owned;
    int axis;
    int rc;
};

static void cut_run(void *argument)
{
    struct cut_job *job = argument;
    job->rc = file_cuts(job->lattice, job->owned, job->axis);
}

/* A fine cell's moments about the lattice's origin. */
static void raw_moments(const struct cell_moments *m, const double origin[3],
                        struct lattice_sums *out)
{
    static const int at[6][2] = {{0, 0}, {0, 1}, {0, 2},
                                 {1, 1}, {1, 2}, {2, 2}};
    long double area = m->area, d[3], f[3];
    for (int x = 0; x < 3; x++) {
        d[x] = m->has_reference ? (long double)m->reference[x] - origin[x]
                                : 0;
        f[x] = m->first[x];
    }
    out->area = area;
    out->uv_area = m->uv_area;
    for (int x = 0; x < 3; x++) {
        out->first[x] = f[x] + area * d[x];
        out->normal_sum[x] = m->normal_sum[x];
    }
    for (int e = 0; e < 6; e++) {
        int r = at[e][0], q = at[e][1];
        out->second[e] = m->second[e] + f[r] * d[q] + d[r] * f[q] +
                         area * d[r] * d[q];
    }
}

/* The running sums: prefix[(r + 1) * W + c + 1] holds the fine cells of
 * rows 0..r, columns 0..c (W = ncolumns + 1), made in two phases a job
 * shares: along each of rows lo..hi-1, then down each of columns
 * lo..hi-1 (1..W-1). */
struct prefix_job {
    struct panel_lattice *lattice;
    const uint32_t *fine_pieces;
    int phase;
    size_t lo, hi;
};

static void prefix_run(void *argument)
{
    struct prefix_job *job = argument;
    struct panel_lattice *L = job->lattice;
    size_t W = L->ncolumns + 1;
    if (job->phase == 0) {
        for (size_t r = job->lo; r < job->hi; r++) {
            struct lattice_sums *to = &L->prefix[(r + 1) * W];
            uint32_t *pieces = &L->pieces[(r + 1) * W];
            memset(to, 0, sizeof *to);
            pieces[0] = 0;
            for (size_t c = 0; c < L->ncolumns; c++) {
                raw_moments(&L->fine[r * L->ncolumns + c], L->origin,
                            &to[c + 1]);
                sums_add(&to[c + 1], &to[c], 1);
                pieces[c + 1] = pieces[c] +
                                job->fine_pieces[r * L->ncolumns + c];
            }
        }
        return;
    }
    for (size_t r = 2; r <= L->nrows; r++)
        for (size_t c = job->lo; c < job->hi; c++) {
            sums_add(&L->prefix[r * W + c], &L->prefix[(r - 1) * W + c], 1);
            L->pieces[r * W + c] += L->pieces[(r - 1) * W + c];
        }
}

static void make_prefix(struct panel_lattice *L, const uint32_t *fine_pieces,
                        int jobs)
{
    size_t W = L->ncolumns + 1;
    memset(L->prefix, 0, W * sizeof *L->prefix);
    memset(L->pieces, 0, W * sizeof *L->pieces);
    struct prefix_job job[PARALLEL_MAX];
    for (int phase = 0; phase < 2; phase++) {
        size_t count = phase == 0 ? L->nrows : W - 1;
        for (int k = 0; k < jobs; k++)
            job[k] = (struct prefix_job){L, fine_pieces, phase,
                count * (size_t)k / (size_t)jobs + (phase == 1),
                count * (size_t)(k + 1) / (size_t)jobs + (phase == 1)};
        parallel_run(job, sizeof *job, jobs, prefix_run);
    }
}

void panel_lattice_free(struct panel_lattice *lattice)
{
    if (lattice == NULL)
        return;
    for (int a = 0; a < 2; a++) {
        free(lattice->line[a]);
        free(lattice->cut_start[a]);
        free(lattice->cut[a]);
    }
    free(lattice->fine);
    free(lattice->prefix);
    free(lattice->pieces);
    free(lattice->place);
    free(lattice->on_line);
    free(lattice->extra);
    free(lattice->corner);
    free(lattice);
}

static int out_of_memory(struct panel_lattice *lattice, uint32_t *scratch,
                         struct facet_error *err)
{
    free(scratch);
    panel_lattice_free(lattice);
    return facet_error_set(err, FACET_EWORK, "out of memory (panel lattice)");
}

int panel_lattice_build(const struct panel_prep *prep, int u_lo, int u_hi,
                        int v_lo, int v_hi, int jobs,
                        struct panel_lattice **out, struct facet_error *err)
{
    return panel_lattice_build_stoppable(prep, u_lo, u_hi, v_lo, v_hi, jobs,
                                         NULL, out, err);
}

int panel_lattice_build_stoppable(const struct panel_prep *prep, int u_lo,
                                  int u_hi, int v_lo, int v_hi, int jobs,
                                  const struct facet_stop *stop,
                                  struct panel_lattice **out,
                                  struct facet_error *err)
{
    *out = NULL;
    if (jobs < 1)
        jobs = 1;
    if (jobs > PARALLEL_MAX)
        jobs = PARALLEL_MAX;
    int lo[2] = {u_lo, v_lo}, hi[2] = {u_hi, v_hi};
    for (int a = 0; a < 2; a++)
        if (lo[a] < 1 || hi[a] < lo[a] || hi[a] > PANEL_MAX_GRID)
            return facet_error_set(err, FACET_EINPUT,
                "grid sides %d..%d are out of range (1 to %d)", lo[a], hi[a],
                PANEL_MAX_GRID);
    const struct uv_index *index = prep->index;
    if (!(index->umax > index->umin) || !(index->vmax > index->vmin))
        return facet_error_set(err, FACET_EINPUT,
            "the UV map has no extent (all texture coordinates equal in u "
            "or in v)");
    /* Too fine before anything is made: the largest grid's own lines are
     * distinct already. */
    if ((size_t)(u_hi + 1) * (size_t)(v_hi + 1) > PANEL_LATTICE_MAX_NODES)
        return FACET_OK;

    struct panel_lattice *L = calloc(1, sizeof *L);
    if (L == NULL)
        return facet_error_set(err, FACET_EWORK,
                               "out of memory (panel lattice)");
    L->prep = prep;
    double min[2] = {index->umin, index->vmin};
    double max[2] = {index->umax, index->vmax};
    for (int a = 0; a < 2; a++) {
        L->side_lo[a] = lo[a];
        L->side_hi[a] = hi[a];
        if (make_lines(min[a], max[a], lo[a], hi[a], &L->line[a],
                       &L->nline[a]) != FACET_OK)
            return out_of_memory(L, NULL, err);
    }
    if ((L->nline[0] + 2) * (L->nline[1] + 2) > PANEL_LATTICE_MAX_NODES) {
        panel_lattice_free(L);
        return FACET_OK;
    }
    L->ncolumns = L->nline[0] + 1;
    L->nrows = L->nline[1] + 1;
    size_t nfine = L->ncolumns * L->nrows;
    size_t nprefix = (L->ncolumns + 1) * (L->nrows + 1);
    size_t ncorners = L->nline[0] * L->nline[1];
    /* Zeroed by the jobs that fill them (divide_run). */
    uint32_t *fine_pieces = malloc(nfine * sizeof *fine_pieces);
    L->fine = malloc(nfine * sizeof *L->fine);
    L->prefix = malloc(nprefix * sizeof *L->prefix);
    L->pieces = malloc(nprefix * sizeof *L->pieces);
    L->place = malloc((prep->npoints ? prep->npoints : 1) * 2 *
                      sizeof *L->place);
    L->on_line = malloc((prep->npoints ? prep->npoints : 1) * 2 *
                        sizeof *L->on_line);
    L->corner = malloc((ncorners ? ncorners : 1) * sizeof *L->corner);
    if (fine_pieces == NULL || L->fine == NULL || L->prefix == NULL ||
        L->pieces == NULL || L->place == NULL || L->on_line == NULL ||
        L->corner == NULL)
        return out_of_memory(L, fine_pieces, err);
    for (size_t q = 0; q < ncorners; q++)
        L->corner[q].state = -1;

    /* The origin of the running sums: the middle of the surface, so that
     * they are as small as they can be. */
    double low[3] = {INFINITY, INFINITY, INFINITY};
    double high[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (size_t p = 0; p < prep->npoints; p++)
        for (int x = 0; x < 3; x++) {
            low[x] = smaller(low[x], prep->point[p].position[x]);
            high[x] = larger(high[x], prep->point[p].position[x]);
        }
    for (int x = 0; x < 3; x++)
        L->origin[x] = prep->npoints ? 0.5 * (low[x] + high[x]) : 0;

    /* Each point's fine cell, and the lines it lies on. */
    for (size_t p = 0; p < prep->npoints; p++) {
        int on_u, on_v;
        size_t c = line_rank(L->line[0], L->nline[0], prep->point_uv[2 * p],
                             &on_u);
        size_t r = line_rank(L->line[1], L->nline[1],
                             prep->point_uv[2 * p + 1], &on_v);
        L->place[2 * p] = (uint32_t)c;
        L->place[2 * p + 1] = (uint32_t)r;
        L->on_line[2 * p] = on_u ? (uint32_t)c + 1 : 0;
        L->on_line[2 * p + 1] = on_v ? (uint32_t)r + 1 : 0;
    }

    /* The triangles divided by bands of rows... */
    struct divide_job divide[PARALLEL_MAX];
    int bands = (size_t)jobs < L->nrows ? jobs : (int)L->nrows;
    for (int k = 0; k < bands; k++)
        divide[k] = (struct divide_job){L, fine_pieces,
            L->nrows * (size_t)k / (size_t)bands,
            L->nrows * (size_t)(k + 1) / (size_t)bands, NULL, 0, 0,
            FACET_OK, stop};
    parallel_run(divide, sizeof *divide, bands, divide_run);
    int rc = FACET_OK, stopped = 0;
    size_t nextra = 0;
    for (int k = 0; k < bands; k++) {
        if (divide[k].rc == FACET_ESTOP)
            stopped = 1;
        else if (divide[k].rc != FACET_OK)
            rc = divide[k].rc;
        nextra += divide[k].nextra;
    }
    if (stopped) {
        for (int k = 0; k < bands; k++)
            free(divide[k].extra);
        free(fine_pieces);
        panel_lattice_free(L);
        return facet_stop_error(err);
    }
    L->extra = malloc((nextra ? nextra : 1) * sizeof *L->extra);
    if (L->extra == NULL)
        rc = FACET_EWORK;
    for (int k = 0; k < bands; k++) {
        if (rc == FACET_OK && divide[k].nextra > 0) {
            memcpy(&L->extra[L->nextra], divide[k].extra,
                   divide[k].nextra * sizeof *L->extra);
            L->nextra += divide[k].nextra;
        }
        free(divide[k].extra);
    }
    if (rc != FACET_OK)
        return out_of_memory(L, fine_pieces, err);
    /* A point on a line is a piece vertex of each of its triangles on
     * each side: once per fine cell is enough. */
    qsort(L->extra, L->nextra, sizeof *L->extra, compare_extra);
    size_t distinct = 0;
    for (size_t e = 0; e < L->nextra; e++)
        if (distinct == 0 ||
            compare_extra(&L->extra[e], &L->extra[distinct - 1]) != 0)
            L->extra[distinct++] = L->extra[e];
    L->nextra = distinct;

    if (facet_stop_requested(stop)) {
        free(fine_pieces);
        panel_lattice_free(L);
        return facet_stop_error(err);
    }
    /* ...the cuts of each axis's lines, an axis a job... */
    unsigned char *owned = owned_edges(prep);
    if (owned == NULL)
        return out_of_memory(L, fine_pieces, err);
    struct cut_job cut[2] = {{L, owned, 0, FACET_OK},
                             {L, owned, 1, FACET_OK}};
    parallel_run(cut, sizeof *cut, jobs > 1 ? 2 : 1, cut_run);
    if (jobs == 1)
        cut_run(&cut[1]);
    free(owned);
    if (cut[0].rc != FACET_OK || cut[1].rc != FACET_OK)
        return out_of_memory(L, fine_pieces, err);

    /* ...and the running sums. */
    make_prefix(L, fine_pieces, jobs);
    free(fine_pieces);
    *out = L;
    return FACET_OK;
}

size_t panel_lattice_bytes(const struct panel_lattice *L)
{
    size_t nfine = L->ncolumns * L->nrows;
    size_t nprefix = (L->ncolumns + 1) * (L->nrows + 1);
    size_t npoints = L->prep->npoints;
    size_t ncuts = L->cut_start[0][L->nline[0]] + L->cut_start[1][L->nline[1]];
    return sizeof *L + (L->nline[0] + L->nline[1]) * sizeof(double) +
           nfine * sizeof *L->fine +
           nprefix * (sizeof *L->prefix + sizeof *L->pieces) +
           npoints * 2 * (sizeof *L->place + sizeof *L->on_line) +
           L->nextra * sizeof *L->extra +
           (L->nline[0] + L->nline[1] + 2) * sizeof(size_t) +
           ncuts * sizeof(struct lattice_cut) +
           L->nline[0] * L->nline[1] * sizeof *L->corner;
}

int panel_lattice_has(const struct panel_lattice *lattice, int nu, int nv)
{
    return nu >= lattice->side_lo[0] && nu <= lattice->side_hi[0] &&
           nv >= lattice->side_lo[1] && nv <= lattice->side_hi[1];
}
