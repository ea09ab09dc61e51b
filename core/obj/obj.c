/*
 * obj.c: the Wavefront OBJ reader. See obj.h for what it accepts.
 *
 * This file reads the file, cuts its text into parts, runs the parts on
 * threads and merges them; obj_part.c parses one part and writes its
 * triangles; obj_table.c holds the growable arrays and name tables.
 *
 * Reading: obj_load does not mmap the file (a file that shrinks while it
 * is mapped turns into SIGBUS, which a library cannot report). A regular
 * file of up to 1 GiB is read whole into one buffer, a slice per thread
 * with pread() (reading is mostly page faults and copying); a larger
 * file, a pipe or a file that grows while read is streamed in windows of
 * 64 MiB, each ending at the last line boundary in it, the unfinished rest
 * moved to the front before the next read. A file that vanishes or
 * shrinks mid-read is an I/O error. obj_parse uses the caller's text as
 * one window, without copying it.
 *
 * Cutting: a window of text is cut into parts of at least 1 MiB, at most
 * one per thread (threads: online CPUs, at most 8), each cut moved forward
 * to the end of a logical line: just after a newline that no '\' joins to
 * the next line. A small file is one part, parsed on the calling thread.
 *
 * Parsing (phase 1, one thread per run of parts): each part fills arrays
 * of its own and keeps its faces as written. It cannot know what came
 * before it, so names start as "inherited", line numbers and negative
 * indices are part-local (see obj_part.h), and triangulation waits.
 *
 * Merging (on the calling thread, after each window): parts get their
 * bases (lines, vertices, texture coordinates, normals before them);
 * negative indices that reach before their part are resolved now, and the
 * first error in file order wins: a part's own error or such an index,
 * whichever comes first. So errors name the same line as a serial parse
 * would. At the end, name tables are folded together in file order.
 *
 * Writing (phase 2, threads again): the first part with vertices hands its
 * array over (realloc to the total, no copy), the other parts' elements
 * are copied in slices; then the faces, split evenly between threads, are
 * checked against the totals (a positive index may point forward, so this
 * waits until the end, and such errors are only reported when the file
 * has no other error, earliest face first, as before) and triangulated
 * straight into the final arrays, so no output byte is written twice.
 *
 * Big buffers and output arrays are hinted to be backed by huge pages
 * (obj_advise_huge): zeroing fresh memory was a fifth of the load time.
 *
 * Stopping (obj_load_stoppable): a part is parsed, its faces written and a
 * whole file read in slices of a few megabytes (STOP_SLICE_*), the caller's
 * stop asked between them, so that a stop is heard within milliseconds
 * whatever the file's size; parts stay as large as before, so the result
 * and the speed do not change.
 *
 * Nothing is allocated per line (only per part, per array growth and per
 * new o/g/usemtl name). Not here: units, welding, objects (mesh.c), .mtl.
 */
#include "core/obj/obj.h"

#include <assert.h>
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/obj/infile.h"
#include "core/obj/obj_part.h"
#include "core/obj/obj_table.h"
#include "core/obj/obj_tuning_internal.h"
#include "core/base/parallel.h"

#define BINARY_SAMPLE 4096               /* bytes that tell text from data */
#define DEFAULT_PART_BYTES ((size_t)1 << 20)
#define DEFAULT_WINDOW_BYTES ((size_t)64 << 20)
#define DEFAULT_WHOLE_BYTES ((size_t)1 << 30)
#define MAX_PART_BYTES ((size_t)1 << 30) /* keeps part lines in 32 bits */
#define MAX_THREADS 8u
/* Work between two questions to the stop: a few milliseconds each. */
#define STOP_SLICE_BYTES ((size_t)4 << 20)   /* text parsed, bytes read */
#define STOP_SLICE_FACES ((size_t)1 << 18)   /* faces written */

/* Everything one load or parse works with. */
struct loader {
    const char *name;            /* for messages */
    struct facet_error *err;
    const struct facet_stop *stop;  /* the caller's, or NULL */
    unsigned nthreads;
    size_t part_bytes;
    size_t max_parts;

    struct obj_part *part;       /* nparts, in file order */
    size_t nparts;
    size_t part_capacity;
    size_t nmerged;              /* parts whose bases are set */
    size_t nlines, nvertices, ntexcoords, nnormals;  /* in merged parts */
    uint32_t *map;               /* 3 maps per part, see merge_names */
};

/* ---- small helpers ---------------------------------------------------- */

static int is_space(char c)
{
    return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' ||
           c == '\v';
}

/* Whether the first BINARY_SAMPLE bytes look like binary data rather than
 * text: any NUL byte, or more than one in ten bytes being control
 * characters or bytes that are not valid UTF-8. */
static int looks_binary(const char *text, size_t length)
{
    size_t n = length < BINARY_SAMPLE ? length : BINARY_SAMPLE;
    const unsigned char *s = (const unsigned char *)text;
    size_t odd = 0;
    for (size_t i = 0; i < n; i++) {
        unsigned char c = s[i];
        if (c == 0)
            return 1;
        if (c < 0x80) {
            if ((c < 0x20 && !is_space((char)c)) || c == 0x7f)
                odd++;
            continue;
        }
        size_t follow = (c & 0xe0) == 0xc0 ? 1 : (c & 0xf0) == 0xe0 ? 2
                      : (c & 0xf8) == 0xf0 ? 3 : 0;
        size_t k = 1;
        while (k <= follow && i + k < n && (s[i + k] & 0xc0) == 0x80)
            k++;
        if (follow == 0 || (k <= follow && i + k < n)) {
            odd++;
            continue;
        }
        i += k - 1;
    }
    return odd * 10 > n;
}

static int out_of_memory(struct loader *ld)
{
    return facet_error_set(ld->err, FACET_EWORK, "%s: out of memory",
                           ld->name);
}

/* Sets the loader's error from a part's, naming the file line. */
static int part_error(struct loader *ld, const struct obj_part *part,
                      const struct obj_part_error *error)
{
    return facet_error_set(ld->err, error->code, "%s:%zu: %s", ld->name,
                           part->line_base + error->line, error->what);
}

/* Whether the newline at text[i] ends a logical line (no '\' before it
 * joins the next line). text[0] starts a line. */
static int ends_logical_line(const char *text, size_t i)
{
    if (i > 0 && text[i - 1] == '\r')
        i--;
    return !(i > 0 && text[i - 1] == '\\');
}

/* Where the first logical line ending at or after from ends: just after
 * its newline, or length if none does. */
static size_t line_end_after(const char *text, size_t length, size_t from)
{
    while (from < length) {
        const char *nl = memchr(text + from, '\n', length - from);
        if (nl == NULL)
            return length;
        size_t i = (size_t)(nl - text);
        if (ends_logical_line(text, i))
            return i + 1;
        from = i + 1;
    }
    return length;
}

/* Where the last logical line that ends in text[0..length) ends, or 0. */
static size_t last_line_end(const char *text, size_t length)
{
    while (length > 0) {
        size_t i = length - 1;
        while (i > 0 && text[i] != '\n')
            i--;
        if (text[i] != '\n')
            return 0;
        if (ends_logical_line(text, i))
            return i + 1;
        length = i;
    }
    return 0;
}

/* ---- threads ---------------------------------------------------------- */

struct job {
    struct loader *ld;
    unsigned index;              /* this job, 0..njobs */
    unsigned njobs;
    const char *text;            /* phase 1: the window */
    const size_t *cut;           /* phase 1: part p is [cut[p], cut[p+1]) */
    size_t first_part;           /* phase 1: the window's first part */
    size_t window_parts;
    int fd;                      /* phase 0: reading a whole file */
    char *buffer;
    size_t size;
    size_t got;
    int read_errno;
    struct obj_file *obj;        /* phase 2 */
    int rc;                      /* phase 2b: first error of the job */
    size_t error_part;
    struct obj_part_error error;
    int stopped;                 /* the job heard the stop and gave up */
};

/* Whether any of jobs[0..n) heard the stop. */
static int jobs_stopped(const struct job *jobs, unsigned n)
{
    for (unsigned t = 0; t < n; t++)
        if (jobs[t].stopped)
            return 1;
    return 0;
}

/* Makes jobs[0..njobs) copies of like, numbered 0..njobs: the job
 * functions split their work by index and njobs, the rest is shared. */
static void jobs_like(struct job *jobs, unsigned njobs, const struct job *like)
{
    assert(njobs <= MAX_THREADS);
    for (unsigned t = 0; t < njobs; t++) {
        jobs[t] = *like;
        jobs[t].index = t;
        jobs[t].njobs = njobs;
    }
}

/* Runs jobs[0..n) with run (parallel.h). */
static void run_jobs(struct job *jobs, unsigned n, void (*run)(void *job))
{
    parallel_run(jobs, sizeof *jobs, (int)n, run);
}

/* Slice t of n of the range [0, count). */
static size_t slice_start(size_t count, size_t t, size_t n)
{
    return count / n * t + count % n * t / n;  /* floor(count t / n) */
}

/* ---- phase 1: parsing a window ---------------------------------------- */

/* Parses part p of the window in slices that end at line ends (the part
 * reads them as it would the whole: obj_part_parse goes on where it
 * stopped), asking the stop between them. Returns FACET_OK, the part's
 * error code, or FACET_ESTOP (job->stopped set). */
static int parse_part(struct job *job, size_t p)
{
    struct obj_part *part = &job->ld->part[job->first_part + p];
    size_t at = job->cut[p], end = job->cut[p + 1];
    while (at < end) {
        if (facet_stop_requested(job->ld->stop)) {
            job->stopped = 1;
            return FACET_ESTOP;
        }
        size_t next = end - at <= STOP_SLICE_BYTES
                    ? end
                    : line_end_after(job->text, end, at + STOP_SLICE_BYTES);
        int rc = obj_part_parse(part, job->text + at, job->text + next);
        if (rc != FACET_OK)
            return rc;
        at = next;
    }
    return FACET_OK;
}

static void parse_job(void *argument)
{
    struct job *job = argument;
    size_t from = slice_start(job->window_parts, job->index, job->njobs);
    size_t to = slice_start(job->window_parts, job->index + 1, job->njobs);
    for (size_t p = from; p < to; p++)
        if (parse_part(job, p) != FACET_OK)
            break;  /* later parts cannot hold an earlier error */
}

/* Gives the parts parsed so far their bases, resolves negative indices
 * that reach before their part and finds the first error in file order.
 * Returns FACET_OK or that error, set in ld->err. */
static int merge_bases(struct loader *ld)
{
    static const char *const what[3] = {"vertex", "texture coordinate",
                                        "normal"};
    static const char *const plural[3] = {"vertices", "texture coordinates",
                                          "normals"};
    for (; ld->nmerged < ld->nparts; ld->nmerged++) {
        struct obj_part *part = &ld->part[ld->nmerged];
        part->line_base = ld->nlines + 1;
        part->vertex_base = ld->nvertices;
        part->texcoord_base = ld->ntexcoords;
        part->normal_base = ld->nnormals;
        size_t base[3] = {ld->nvertices, ld->ntexcoords, ld->nnormals};
        for (size_t i = 0; i < part->nbefore; i++) {
            const struct obj_part_before *b = &part->before[i];
            uint64_t so_far = (uint64_t)base[b->which] + b->count;
            if (b->value > so_far)
                return facet_error_set(ld->err, FACET_EINPUT,
                    "%s:%zu: relative %s index -%llu points before the "
                    "first %s (file has %llu %s so far)", ld->name,
                    part->line_base + b->line, what[b->which],
                    (unsigned long long)b->value, what[b->which],
                    (unsigned long long)so_far, plural[b->which]);
            uint32_t index = (uint32_t)(so_far - b->value);
            struct obj_corner *c = &part->corner[b->corner];
            if (b->which == 0)
                c->v = index;
            else if (b->which == 1)
                c->vt = index;
            else
                c->vn = index;
        }
        if (part->error.code != FACET_OK)
            return part_error(ld, part, &part->error);
        ld->nlines += part->line;
        ld->nvertices += part->nvertices;
        ld->ntexcoords += part->ntexcoords;
        ld->nnormals += part->nnormals;
        if (ld->nvertices > OBJ_MAX_INDEX || ld->ntexcoords > OBJ_MAX_INDEX ||
            ld->nnormals > OBJ_MAX_INDEX)
            return facet_error_set(ld->err, FACET_EINPUT,
                "%s:%zu: more than %llu vertices, texture coordinates or "
                "normals", ld->name, part->line_base,
                (unsigned long long)OBJ_MAX_INDEX);
    }
    return FACET_OK;
}

/* Parses the window text[0..length), which starts at the start of a line
 * and ends at the end of one or of the file, into new parts. */
static int parse_window(struct loader *ld, const char *text, size_t length)
{
    size_t nparts = length / ld->part_bytes;
    if (nparts > ld->max_parts)
        nparts = ld->max_parts;
    if (nparts < length / MAX_PART_BYTES + 1)
        nparts = length / MAX_PART_BYTES + 1;
    size_t *cut = malloc((nparts + 1) * sizeof *cut);
    if (cut == NULL)
        return out_of_memory(ld);
    size_t n = 0;
    cut[0] = 0;
    for (size_t p = 1; p < nparts; p++) {
        size_t at = line_end_after(text, length,
                                   slice_start(length, p, nparts));
        if (at > cut[n] && at < length)
            cut[++n] = at;
    }
    cut[++n] = length;  /* n parts now */

    struct obj_part *part = obj_grow(ld->part, &ld->part_capacity,
                                     ld->nparts + n, sizeof *part);
    if (part == NULL) {
        free(cut);
        return out_of_memory(ld);
    }
    ld->part = part;
    for (size_t p = 0; p < n; p++)
        obj_part_init(&part[ld->nparts + p]);
    size_t first = ld->nparts;
    ld->nparts += n;

    unsigned njobs = n < ld->nthreads ? (unsigned)n : ld->nthreads;
    struct job jobs[MAX_THREADS];
    jobs_like(jobs, njobs, &(struct job){.ld = ld, .text = text, .cut = cut,
                                         .first_part = first,
                                         .window_parts = n});
    run_jobs(jobs, njobs, parse_job);
    free(cut);
    if (jobs_stopped(jobs, njobs))
        return facet_stop_error(ld->err);
    return merge_bases(ld);
}

/* ---- phase 2: merging and writing ------------------------------------- */

/* obj_names_find into a merged table, its error naming the file. */
static int merged_name(struct loader *ld, struct obj_names *table,
                       const char *text, uint32_t *index)
{
    struct facet_error err;
    int rc = obj_names_find(table, text, strlen(text), index, &err);
    if (rc != FACET_OK)
        facet_error_set(ld->err, rc, "%s: %s", ld->name, err.message);
    return rc;
}

/* Folds the parts' name tables into obj's, in file order, and points each
 * part at its maps from part-local to merged ids. */
static int merge_names(struct loader *ld, struct obj_file *obj)
{
    struct obj_names table[3];
    memset(table, 0, sizeof table);
    uint32_t current[3] = {0, 0, 0}, unnamed;
    size_t nmaps = 0, nmtllibs = 0;
    int rc = FACET_OK;
    for (size_t p = 0; p < ld->nparts; p++) {
        nmaps += ld->part[p].objects.count + ld->part[p].groups.count +
                 ld->part[p].materials.count;
        nmtllibs += ld->part[p].nmtllibs;
    }
    ld->map = malloc((nmaps ? nmaps : 1) * sizeof *ld->map);
    obj->mtllibs = nmtllibs ? malloc(nmtllibs * sizeof *obj->mtllibs) : NULL;
    if (ld->map == NULL || (nmtllibs && obj->mtllibs == NULL))
        rc = out_of_memory(ld);
    for (int k = 0; k < 3 && rc == FACET_OK; k++)
        rc = merged_name(ld, &table[k], "", &unnamed);
    uint32_t *map = ld->map;
    for (size_t p = 0; p < ld->nparts && rc == FACET_OK; p++) {
        struct obj_part *part = &ld->part[p];
        struct obj_names *local[3] = {&part->objects, &part->groups,
                                      &part->materials};
        const uint32_t *ids[3];
        uint32_t inherited[3], now[3] = {part->object, part->group,
                                         part->material};
        for (int k = 0; k < 3 && rc == FACET_OK; k++) {
            for (size_t i = 0; i < local[k]->count && rc == FACET_OK; i++) {
                const char *text = local[k]->names[i].text;
                rc = merged_name(ld, &table[k], text, &map[i]);
            }
            ids[k] = map;
            map += local[k]->count;
            inherited[k] = current[k];
            if (now[k] != OBJ_INHERITED)
                current[k] = ids[k][now[k]];
        }
        part->object_map = ids[0];
        part->group_map = ids[1];
        part->material_map = ids[2];
        part->inherited_object = inherited[0];
        part->inherited_group = inherited[1];
        part->inherited_material = inherited[2];
        for (size_t i = 0; i < part->nmtllibs; i++) {
            obj->mtllibs[obj->nmtllibs++] = part->mtllibs[i];
            part->mtllibs[i].text = NULL;
        }
        part->nmtllibs = 0;
    }
    if (rc != FACET_OK) {
        for (int k = 0; k < 3; k++)
            obj_names_free(&table[k]);
        return rc;
    }
    obj_names_release(&table[0], &obj->objects, &obj->nobjects);
    obj_names_release(&table[1], &obj->groups, &obj->ngroups);
    obj_names_release(&table[2], &obj->materials, &obj->nmaterials);
    return FACET_OK;
}

/* One element array of the merge: where each part keeps it. */
struct column {
    size_t width;                /* doubles per element */
    size_t offset;               /* of the array pointer in obj_part */
    size_t count_offset;         /* of its element count in obj_part */
    size_t base_offset;          /* of its base in obj_part */
};

static const struct column columns[4] = {
    {3, offsetof(struct obj_part, position),
     offsetof(struct obj_part, nvertices),
     offsetof(struct obj_part, vertex_base)},
    {3, offsetof(struct obj_part, color), offsetof(struct obj_part, nvertices),
     offsetof(struct obj_part, vertex_base)},
    {2, offsetof(struct obj_part, texcoord),
     offsetof(struct obj_part, ntexcoords),
     offsetof(struct obj_part, texcoord_base)},
    {3, offsetof(struct obj_part, normal), offsetof(struct obj_part, nnormals),
     offsetof(struct obj_part, normal_base)},
};

static double **column_array(struct obj_part *part, int k)
{
    return (double **)((char *)part + columns[k].offset);
}

static size_t column_size(const struct obj_part *part, size_t which)
{
    return *(const size_t *)((const char *)part + which);
}

/* Copies slice job->index of every part's elements into obj (those of the
 * part that handed its array over are there already); vertices of parts
 * without colour get white when the file has colours. */
static void copy_job(void *argument)
{
    struct job *job = argument;
    struct obj_file *obj = job->obj;
    double *merged[4] = {obj->position, obj->color, obj->texcoord,
                         obj->normal};
    for (size_t p = 0; p < job->ld->nparts; p++) {
        struct obj_part *part = &job->ld->part[p];
        for (int k = 0; k < 4; k++) {
            size_t w = columns[k].width;
            size_t count = w * column_size(part, columns[k].count_offset);
            size_t base = w * column_size(part, columns[k].base_offset);
            const double *from = *column_array(part, k);
            if (merged[k] == NULL || count == 0 || from == merged[k] + base)
                continue;
            size_t a = slice_start(count, job->index, job->njobs);
            size_t b = slice_start(count, job->index + 1, job->njobs);
            if (from != NULL) {
                memcpy(merged[k] + base + a, from + a, (b - a) * sizeof *from);
            } else {
                for (size_t i = a; i < b; i++)
                    merged[k][base + i] = 1.0;
            }
        }
    }
}

/* Writes the triangles of faces slice job->index of the whole file. */
static void emit_job(void *argument)
{
    struct job *job = argument;
    struct loader *ld = job->ld;
    size_t a = slice_start(job->obj->nfaces, job->index, job->njobs);
    size_t b = slice_start(job->obj->nfaces, job->index + 1, job->njobs);
    struct obj_emitter emitter;
    memset(&emitter, 0, sizeof emitter);
    job->rc = FACET_OK;
    for (size_t p = 0; p < ld->nparts && job->rc == FACET_OK; p++) {
        struct obj_part *part = &ld->part[p];
        size_t from = part->face_base, to = from + part->nfaces;
        if (to <= a || from >= b)
            continue;
        size_t first = (a > from ? a : from) - from;
        size_t last = (b < to ? b : to) - from;
        while (first < last && job->rc == FACET_OK) {
            if (facet_stop_requested(ld->stop)) {
                job->stopped = 1;
                break;
            }
            size_t next = last - first <= STOP_SLICE_FACES
                        ? last : first + STOP_SLICE_FACES;
            job->rc = obj_part_emit(part, first, next, job->obj, &emitter,
                                    &job->error);
            first = next;
        }
        job->error_part = p;
        if (job->stopped)
            break;
    }
    obj_emitter_free(&emitter);
}

/* Allocates obj's element arrays at the merged counts: the first part that
 * has elements of a kind hands its array over (its base is 0). */
static int merge_columns(struct loader *ld, struct obj_file *obj)
{
    double **merged[4] = {&obj->position, &obj->color, &obj->texcoord,
                          &obj->normal};
    size_t total[4] = {obj->nvertices, obj->ncolors ? obj->nvertices : 0,
                       obj->ntexcoords, obj->nnormals};
    for (int k = 0; k < 4; k++) {
        if (total[k] == 0)
            continue;
        size_t bytes = columns[k].width * total[k] * sizeof(double);
        for (size_t p = 0; p < ld->nparts; p++) {
            struct obj_part *part = &ld->part[p];
            if (column_size(part, columns[k].count_offset) == 0)
                continue;
            double **array = column_array(part, k);
            if (*array != NULL) {  /* hand it over */
                double *grown = realloc(*array, bytes);
                if (grown == NULL)
                    return out_of_memory(ld);
                *merged[k] = grown;
                *array = grown;  /* marks it in place for copy_job */
            }
            break;
        }
        if (*merged[k] == NULL && (*merged[k] = malloc(bytes)) == NULL)
            return out_of_memory(ld);
        obj_advise_huge(*merged[k], bytes);
    }
    return FACET_OK;
}

/* After the last window: merges the parts into obj and writes its
 * triangles. Returns FACET_OK or the error, set in ld->err. */
static int finish(struct loader *ld, struct obj_file *obj)
{
    size_t nstatements = 0;
    int unterminated = ld->nparts ? ld->part[ld->nparts - 1].unterminated : 0;
    for (size_t p = 0; p < ld->nparts; p++) {
        struct obj_part *part = &ld->part[p];
        part->face_base = obj->nfaces;
        part->triangle_base = obj->ntriangles;
        obj->nfaces += part->nfaces;
        obj->ntriangles += part->ntriangles;
        obj->ncolors += part->ncolors;
        obj->nskipped += part->nskipped;
        nstatements += part->nstatements;
    }
    obj->nlines = ld->nlines + (size_t)unterminated;
    obj->nvertices = ld->nvertices;
    obj->ntexcoords = ld->ntexcoords;
    obj->nnormals = ld->nnormals;
    if (nstatements == 0)
        return facet_error_set(ld->err, FACET_EINPUT,
            "%s: empty file (no OBJ statements)", ld->name);
    if (obj->nfaces > OBJ_MAX_INDEX)
        return facet_error_set(ld->err, FACET_EINPUT,
            "%s: too many faces (more than %llu)", ld->name,
            (unsigned long long)OBJ_MAX_INDEX);
    int rc = merge_names(ld, obj);
    if (rc == FACET_OK)
        rc = merge_columns(ld, obj);
    if (rc == FACET_OK && obj->ntriangles > 0) {
        size_t n = obj->ntriangles;
        if (n > SIZE_MAX / (3 * sizeof *obj->corner))
            return out_of_memory(ld);
        obj->corner = malloc(3 * n * sizeof *obj->corner);
        obj->triangle_face = malloc(n * sizeof(uint32_t));
        obj->triangle_object = malloc(n * sizeof(uint32_t));
        obj->triangle_group = malloc(n * sizeof(uint32_t));
        obj->triangle_material = malloc(n * sizeof(uint32_t));
        if (obj->corner == NULL || obj->triangle_face == NULL ||
            obj->triangle_object == NULL || obj->triangle_group == NULL ||
            obj->triangle_material == NULL)
            return out_of_memory(ld);
        obj_advise_huge(obj->corner, 3 * n * sizeof *obj->corner);
        obj_advise_huge(obj->triangle_face, n * sizeof(uint32_t));
        obj_advise_huge(obj->triangle_object, n * sizeof(uint32_t));
        obj_advise_huge(obj->triangle_group, n * sizeof(uint32_t));
        obj_advise_huge(obj->triangle_material, n * sizeof(uint32_t));
    }
    if (rc != FACET_OK)
        return rc;

    unsigned njobs = ld->nthreads;
    if (ld->nparts < njobs)
        njobs = (unsigned)ld->nparts;
    struct job jobs[MAX_THREADS];
    jobs_like(jobs, njobs, &(struct job){.ld = ld, .obj = obj});
    run_jobs(jobs, njobs, copy_job);
    if (facet_stop_requested(ld->stop))
        return facet_stop_error(ld->err);
    run_jobs(jobs, njobs, emit_job);
    if (jobs_stopped(jobs, njobs))
        return facet_stop_error(ld->err);
    for (unsigned t = 0; t < njobs; t++)
        if (jobs[t].rc != FACET_OK)
            return part_error(ld, &ld->part[jobs[t].error_part],
                              &jobs[t].error);
    return FACET_OK;
}

/* ---- start and end ---------------------------------------------------- */

static void loader_start(struct loader *ld, const char *name,
                         struct obj_file *obj, struct facet_error *err,
                         const struct obj_tuning *tuning)
{
    memset(ld, 0, sizeof *ld);
    memset(obj, 0, sizeof *obj);
    facet_error_clear(err);
    ld->name = name;
    ld->err = err;
    ld->nthreads = (unsigned)parallel_cpus(MAX_THREADS);
    ld->part_bytes = DEFAULT_PART_BYTES;
    if (tuning != NULL && tuning->nthreads > 0)
        ld->nthreads = tuning->nthreads < MAX_THREADS ? tuning->nthreads
                                                      : MAX_THREADS;
    if (tuning != NULL && tuning->part_bytes > 0)
        ld->part_bytes = tuning->part_bytes;
    ld->max_parts = tuning != NULL && tuning->max_parts > 0
                  ? tuning->max_parts : ld->nthreads;
}

/* Frees the parts and maps, but never obj's arrays (a part's array that
 * was handed over to obj is obj's now). */
static void loader_free(struct loader *ld, const struct obj_file *obj)
{
    const double *merged[4] = {obj->position, obj->color, obj->texcoord,
                               obj->normal};
    for (size_t p = 0; p < ld->nparts; p++) {
        for (int k = 0; k < 4; k++) {
            double **array = column_array(&ld->part[p], k);
            if (*array != NULL && *array == merged[k])
                *array = NULL;
        }
        obj_part_free(&ld->part[p]);
    }
    free(ld->part);
    free(ld->map);
    memset(ld, 0, sizeof *ld);
}

/* ---- public ----------------------------------------------------------- */

int obj_parse_tuned(const char *text, size_t length, const char *name,
                    struct obj_file *out, struct facet_error *err,
                    const struct obj_tuning *tuning)
{
    struct loader ld;
    loader_start(&ld, name, out, err, tuning);
    int rc = FACET_OK;
    if (looks_binary(text, length))
        rc = facet_error_set(err, FACET_EINPUT,
                             "%s: binary file, not OBJ text", name);
    if (rc == FACET_OK)
        rc = parse_window(&ld, text, length);
    if (rc == FACET_OK)
        rc = finish(&ld, out);
    loader_free(&ld, out);
    return rc;
}

int obj_parse(const char *text, size_t length, const char *name,
              struct obj_file *out, struct facet_error *err)
{
    return obj_parse_tuned(text, length, name, out, err, NULL);
}

/* Reads into buffer[*filled..capacity) until it is full or the file ends
 * (*at_end set). Returns FACET_OK or FACET_EWORK on a read error. */
static int fill_buffer(int fd, char *buffer, size_t capacity, size_t *filled,
                       int *at_end, const char *name, struct facet_error *err)
{
    while (*filled < capacity) {
        ssize_t got = read(fd, buffer + *filled, capacity - *filled);
        if (got < 0) {
            if (errno == EINTR)
                continue;
            return facet_error_set(err, FACET_EWORK, "%s: read error: %s",
                                   name, strerror(errno));
        }
        if (got == 0) {
            *at_end = 1;
            break;
        }
        *filled += (size_t)got;
    }
    return FACET_OK;
}

/* Phase 0 for a whole file: reads slice job->index of its job->size bytes
 * with pread, counting them in job->got (fewer if the file shrank). */
static void read_job(void *argument)
{
    struct job *job = argument;
    size_t a = slice_start(job->size, job->index, job->njobs);
    size_t b = slice_start(job->size, job->index + 1, job->njobs);
    while (a < b) {
        if (facet_stop_requested(job->ld->stop)) {
            job->stopped = 1;
            break;
        }
        size_t want = b - a < STOP_SLICE_BYTES ? b - a : STOP_SLICE_BYTES;
        ssize_t got = pread(job->fd, job->buffer + a, want, (off_t)a);
        if (got < 0 && errno == EINTR)
            continue;
        if (got < 0)
            job->read_errno = errno;
        if (got <= 0)
            break;
        a += (size_t)got;
        job->got += (size_t)got;
    }
}

/* Reads the first size bytes of fd into buffer, a slice per thread, and
 * leaves the file offset after them. Returns FACET_OK or FACET_EWORK. */
static int read_whole(struct loader *ld, int fd, char *buffer, size_t size)
{
    size_t n = size / ld->part_bytes;
    unsigned njobs = n < ld->nthreads ? (n ? (unsigned)n : 1) : ld->nthreads;
    struct job jobs[MAX_THREADS];
    jobs_like(jobs, njobs, &(struct job){.ld = ld, .fd = fd,
                                         .buffer = buffer, .size = size});
    run_jobs(jobs, njobs, read_job);
    if (jobs_stopped(jobs, njobs))
        return facet_stop_error(ld->err);
    size_t total = 0;
    for (unsigned t = 0; t < njobs; t++) {
        if (jobs[t].read_errno != 0)
            return facet_error_set(ld->err, FACET_EWORK,
                "%s: read error: %s", ld->name,
                strerror(jobs[t].read_errno));
        total += jobs[t].got;
    }
    if (total < size)
        return facet_error_set(ld->err, FACET_EWORK,
            "%s: file shrank while being read (%zu of %zu bytes read)",
            ld->name, total, size);
    if (lseek(fd, (off_t)size, SEEK_SET) < 0)
        return facet_error_set(ld->err, FACET_EWORK, "%s: cannot seek: %s",
                               ld->name, strerror(errno));
    return FACET_OK;
}

/* Reads the open file fd window by window and parses each window (see the
 * file comment). */
static int load_windows(struct loader *ld, int fd, const struct stat *st,
                        const struct obj_tuning *tuning)
{
    size_t window = DEFAULT_WINDOW_BYTES, whole = DEFAULT_WHOLE_BYTES;
    if (tuning != NULL && tuning->window_bytes > 0)
        window = tuning->window_bytes;
    if (tuning != NULL && tuning->whole_bytes > 0)
        whole = tuning->whole_bytes;
    size_t capacity = window, filled = 0;
    int is_whole = S_ISREG(st->st_mode) && (uint64_t)st->st_size <= whole;
    if (is_whole)
        capacity = (size_t)st->st_size + 1;  /* + 1 to see the end */
    if (capacity < BINARY_SAMPLE)
        capacity = BINARY_SAMPLE;
    char *buffer = malloc(capacity);
    if (buffer == NULL)
        return out_of_memory(ld);
    obj_advise_huge(buffer, capacity);
    int at_end = 0, first = 1, rc = FACET_OK;
    if (is_whole) {
        rc = read_whole(ld, fd, buffer, (size_t)st->st_size);
        filled = (size_t)st->st_size;
    }
    uint64_t total = filled;
    while (rc == FACET_OK) {
        if ((rc = facet_stop_check(ld->stop, ld->err)) != FACET_OK)
            break;
        size_t before = filled;
        rc = fill_buffer(fd, buffer, capacity, &filled, &at_end, ld->name,
                         ld->err);
        if (rc != FACET_OK)
            break;
        total += filled - before;
        if (first && looks_binary(buffer, filled)) {
            rc = facet_error_set(ld->err, FACET_EINPUT,
                                 "%s: binary file, not OBJ text", ld->name);
            break;
        }
        first = 0;
        size_t cut = at_end ? filled : last_line_end(buffer, filled);
        if (cut == 0 && !at_end) {
            /* One line fills the buffer: make room for more of it. */
            size_t grown_capacity = capacity;
            char *grown = obj_grow(buffer, &grown_capacity, capacity + 1, 1);
            if (grown == NULL) {
                rc = facet_error_set(ld->err, FACET_EWORK,
                    "%s:%zu: out of memory for a line of %zu bytes",
                    ld->name, ld->nlines + 1, capacity);
                break;
            }
            buffer = grown;
            capacity = grown_capacity;
            continue;
        }
        rc = parse_window(ld, buffer, cut);
        if (rc != FACET_OK || at_end)
            break;
        memmove(buffer, buffer + cut, filled - cut);
        filled -= cut;
    }
    free(buffer);
    if (rc == FACET_OK && S_ISREG(st->st_mode) &&
        total < (uint64_t)st->st_size)
        rc = facet_error_set(ld->err, FACET_EWORK,
            "%s: file shrank while being read (%llu of %llu bytes read)",
            ld->name, (unsigned long long)total,
            (unsigned long long)st->st_size);
    return rc;
}

/* obj_load_tuned, asking stop. */
static int load(const char *path, const struct facet_stop *stop,
                struct obj_file *out, struct facet_error *err,
                const struct obj_tuning *tuning)
{
    struct loader ld;
    loader_start(&ld, path, out, err, tuning);
    ld.stop = stop;
    int fd;
    struct stat st;
    int rc = infile_open(path, &fd, &st, err);
    if (rc != FACET_OK)
        return rc;
    rc = load_windows(&ld, fd, &st, tuning);
    close(fd);
    if (rc == FACET_OK)
        rc = finish(&ld, out);
    loader_free(&ld, out);
    return rc;
}

int obj_load_tuned(const char *path, struct obj_file *out,
                   struct facet_error *err, const struct obj_tuning *tuning)
{
    return load(path, NULL, out, err, tuning);
}

int obj_load(const char *path, struct obj_file *out, struct facet_error *err)
{
    return load(path, NULL, out, err, NULL);
}

int obj_load_stoppable(const char *path, const struct facet_stop *stop,
                       struct obj_file *out, struct facet_error *err)
{
    return load(path, stop, out, err, NULL);
}

static void free_names(struct obj_name *names, size_t count)
{
    for (size_t i = 0; i < count; i++)
        free(names[i].text);
    free(names);
}

void obj_free(struct obj_file *obj)
{
    free(obj->position);
    free(obj->color);
    free(obj->texcoord);
    free(obj->normal);
    free(obj->corner);
    free(obj->triangle_face);
    free(obj->triangle_object);
    free(obj->triangle_group);
    free(obj->triangle_material);
    free_names(obj->objects, obj->nobjects);
    free_names(obj->groups, obj->ngroups);
    free_names(obj->materials, obj->nmaterials);
    free_names(obj->mtllibs, obj->nmtllibs);
    memset(obj, 0, sizeof *obj);
}

void obj_names_list(const struct obj_name *names, size_t count, char *text,
                    size_t size)
{
    size_t used = 0;
    text[0] = '\0';
    for (size_t i = 1; i < count && used + 1 < size; i++) {
        int n = snprintf(text + used, size - used, "%s%s", used ? ", " : "",
                         names[i].text);
        if (n < 0)
            break;
        used += (size_t)n;
    }
    if (used >= size && size > 4)
        strcpy(text + size - 4, "...");
}
