/*
 * obj_part.c: parsing one part of an OBJ file, and writing its faces into
 * the merged obj_file. See obj_part.h; obj.c cuts, schedules and merges.
 *
 * Parsing is statement by statement. A logical line is a physical line plus
 * any lines joined to it by a '\' just before the newline. Arrays grow by
 * doubling; nothing is allocated per line (only per new o/g/usemtl name).
 *
 * Face corners are stored as written: a positive index as its 0-based
 * value; a negative one counted back from the part's own count when it
 * stays inside the part (flagged in part->relative, as the merge must add
 * the part's base), else listed in part->before for the merge to resolve.
 * Triangulation waits for obj_part_emit, when every position is known.
 */
#include "core/obj/obj_part.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/base/numparse.h"

#define MAX_VERTEX_NUMBERS 7      /* x y z w r g b */
#define NOT_AN_INDEX (-1)         /* read_index found no digits */

/* ---- errors and small helpers ----------------------------------------- */

static int set_error(struct obj_part_error *error, int code, size_t line,
                     const char *fmt, ...) __attribute__((format(printf, 4, 5)));

static int set_error(struct obj_part_error *error, int code, size_t line,
                     const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(error->what, sizeof error->what, fmt, ap);
    va_end(ap);
    error->code = code;
    error->line = line;
    return code;
}

#define input_error(part, ...) \
    set_error(&(part)->error, FACET_EINPUT, (part)->line, __VA_ARGS__)

static int out_of_memory(struct obj_part *part)
{
    return set_error(&part->error, FACET_EWORK, part->line, "out of memory");
}

static int is_space(char c)
{
    return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' ||
           c == '\v';
}

/* Within a logical line, a '\' that ends a physical line (or the text)
 * joins lines and counts as a blank. */
static int is_continuation(const char *p, const char *end)
{
    return *p == '\\' && (p + 1 == end || p[1] == '\n' ||
                          (p[1] == '\r' && (p + 2 == end || p[2] == '\n')));
}

static const char *skip_blanks(const char *p, const char *end)
{
    while (p < end && (*p == ' ' || is_space(*p) || is_continuation(p, end)))
        p++;
    return p;
}

/* Whether a number or face corner may end at p. */
static int ends_token(const char *p, const char *end)
{
    return p == end || is_space(*p) || *p == '#' || is_continuation(p, end);
}

/* Length of the token at p, up to a blank, for quoting in messages. */
static int token_length(const char *p, const char *end)
{
    const char *q = p;
    while (q < end && !is_space(*q) && q - p < 40)
        q++;
    return (int)(q - p);
}

static int lower(char c)
{
    return c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c;
}

/* Whether the token at p starts like NaN or infinity (any case, signed). */
static int looks_non_finite(const char *p, const char *end)
{
    if (p < end && (*p == '-' || *p == '+'))
        p++;
    if (end - p < 3)
        return 0;
    char a = (char)lower(p[0]), b = (char)lower(p[1]), c = (char)lower(p[2]);
    return (a == 'n' && b == 'a' && c == 'n') ||
           (a == 'i' && b == 'n' && c == 'f');
}

/* ---- v, vt, vn -------------------------------------------------------- */

/* Reads the numbers of a v, vt or vn statement from p to end into
 * number[0..max), stopping at a comment. Stores how many in *count. */
static int read_numbers(struct obj_part *part, const char *p, const char *end,
                        double *number, size_t max, size_t *count,
                        const char *statement)
{
    size_t n = 0;
    for (;;) {
        p = skip_blanks(p, end);
        if (p == end || *p == '#')
            break;
        if (n == max)
            return input_error(part,
                "%s statement has more than %zu numbers", statement, max);
        const char *stop;
        int rc = numparse_double(p, end, &number[n], &stop);
        if (rc == NUMPARSE_RANGE || (rc == NUMPARSE_SYNTAX &&
                                     looks_non_finite(p, end)))
            return input_error(part, "NaN or infinite coordinate \"%.*s\"",
                               token_length(p, end), p);
        if (rc != NUMPARSE_OK || !ends_token(stop, end))
            return input_error(part, "number does not parse: \"%.*s\"",
                               token_length(p, end), p);
        n++;
        p = stop;
    }
    *count = n;
    return FACET_OK;
}

static int statement_vertex(struct obj_part *part, const char *p,
                            const char *end)
{
    double x[MAX_VERTEX_NUMBERS];
    size_t n;
    int rc = read_numbers(part, p, end, x, MAX_VERTEX_NUMBERS, &n, "v");
    if (rc != FACET_OK)
        return rc;
    if (n < 3)
        return input_error(part,
            "vertex has %zu coordinates (x y z needed)", n);
    if (n == 5)
        return input_error(part,
            "vertex has 5 numbers (expected x y z, x y z w, x y z r g b "
            "or x y z w r g b)");
    if (part->nvertices >= OBJ_MAX_INDEX)
        return input_error(part, "more than %llu vertices",
                           (unsigned long long)OBJ_MAX_INDEX);
    size_t v = part->nvertices;
    if (v == part->vertex_capacity) {
        size_t capacity = part->vertex_capacity;
        double *position = obj_grow(part->position, &capacity, v + 1,
                                    3 * sizeof *position);
        if (position == NULL)
            return out_of_memory(part);
        part->position = position;
        if (part->color != NULL) {
            size_t same = part->vertex_capacity;
            double *color = obj_grow(part->color, &same, capacity,
                                     3 * sizeof *color);
            if (color == NULL)
                return out_of_memory(part);
            part->color = color;
        }
        part->vertex_capacity = capacity;
    }
    double *to = part->position + 3 * v;
    to[0] = x[0];
    to[1] = x[1];
    to[2] = x[2];

    int has_color = n >= 6;
    if (has_color && part->color == NULL) {
        part->color = malloc(part->vertex_capacity * 3 * sizeof *part->color);
        if (part->color == NULL)
            return out_of_memory(part);
        for (size_t i = 0; i < 3 * v; i++)
            part->color[i] = 1.0;  /* white for vertices written without */
    }
    if (part->color != NULL) {
        const double *rgb = x + (n == 7 ? 4 : 3);
        for (int k = 0; k < 3; k++)
            part->color[3 * v + (size_t)k] = has_color ? rgb[k] : 1.0;
        part->ncolors += (size_t)has_color;
    }
    part->nvertices = v + 1;
    return FACET_OK;
}

static int statement_texcoord(struct obj_part *part, const char *p,
                              const char *end)
{
    double x[3] = {0, 0, 0};
    size_t n;
    int rc = read_numbers(part, p, end, x, 3, &n, "vt");
    if (rc != FACET_OK)
        return rc;
    if (n < 1)
        return input_error(part,
            "texture coordinate has no numbers (u needed)");
    if (part->ntexcoords >= OBJ_MAX_INDEX)
        return input_error(part, "more than %llu texture coordinates",
                           (unsigned long long)OBJ_MAX_INDEX);
    size_t t = part->ntexcoords;
    if (t == part->texcoord_capacity) {
        double *texcoord = obj_grow(part->texcoord, &part->texcoord_capacity,
                                    t + 1, 2 * sizeof *texcoord);
        if (texcoord == NULL)
            return out_of_memory(part);
        part->texcoord = texcoord;
    }
    part->texcoord[2 * t] = x[0];
    part->texcoord[2 * t + 1] = x[1];
    part->ntexcoords = t + 1;
    return FACET_OK;
}

static int statement_normal(struct obj_part *part, const char *p,
                            const char *end)
{
    double x[3];
    size_t n;
    int rc = read_numbers(part, p, end, x, 3, &n, "vn");
    if (rc != FACET_OK)
        return rc;
    if (n != 3)
        return input_error(part,
            "normal has %zu numbers (x y z needed)", n);
    if (part->nnormals >= OBJ_MAX_INDEX)
        return input_error(part, "more than %llu normals",
                           (unsigned long long)OBJ_MAX_INDEX);
    size_t k = part->nnormals;
    if (k == part->normal_capacity) {
        double *normal = obj_grow(part->normal, &part->normal_capacity, k + 1,
                                  3 * sizeof *normal);
        if (normal == NULL)
            return out_of_memory(part);
        part->normal = normal;
    }
    memcpy(part->normal + 3 * k, x, 3 * sizeof *x);
    part->nnormals = k + 1;
    return FACET_OK;
}

/* ---- f ---------------------------------------------------------------- */

/* Marks index which (0 v, 1 vt, 2 vn) of corner slot as part-relative,
 * creating part->relative (all clear so far) on first use. */
static int mark_relative(struct obj_part *part, size_t slot, int which)
{
    if (part->relative == NULL) {
        part->relative = calloc(part->corner_capacity, 1);
        if (part->relative == NULL)
            return out_of_memory(part);
    }
    part->relative[slot] |= (uint8_t)(1u << which);
    return FACET_OK;
}

/* Notes a negative index that reaches before the part's first element. */
static int add_before(struct obj_part *part, size_t slot, int which,
                      uint64_t value, size_t count)
{
    struct obj_part_before *before = obj_grow(part->before,
        &part->before_capacity, part->nbefore + 1, sizeof *before);
    if (before == NULL)
        return out_of_memory(part);
    part->before = before;
    before[part->nbefore].corner = slot;
    before[part->nbefore].line = part->line;
    before[part->nbefore].value = value;
    before[part->nbefore].count = count;
    before[part->nbefore].which = which;
    part->nbefore++;
    return FACET_OK;
}

/* The careful path of read_index: any sign, any length, with the errors. */
static int read_index_slow(struct obj_part *part, const char **p,
                           const char *end, size_t count, int which,
                           size_t slot, uint32_t *index)
{
    const char *q = *p;
    int negative = 0;
    if (q < end && (*q == '-' || *q == '+')) {
        negative = *q == '-';
        q++;
    }
    if (q == end || (unsigned)(*q - '0') > 9)
        return NOT_AN_INDEX;
    uint64_t value = 0;
    for (; q < end && (unsigned)(*q - '0') <= 9; q++)
        if (value <= OBJ_MAX_INDEX + 1)
            value = value * 10 + (uint64_t)(*q - '0');
    *p = q;
    if (value == 0)
        return input_error(part,
            "face index 0 is invalid (OBJ indices start at 1)");
    if (negative) {
        if (value <= count) {
            *index = (uint32_t)(count - value);
            return mark_relative(part, slot, which);
        }
        *index = 0;  /* until the merge resolves it */
        return add_before(part, slot, which, value, count);
    }
    static const char *const what[3] = {"vertex", "texture coordinate",
                                        "normal"};
    if (value > OBJ_MAX_INDEX + 1)
        return input_error(part, "%s index %llu is too large", what[which],
                           (unsigned long long)value);
    *index = (uint32_t)(value - 1);
    return FACET_OK;
}

/* Reads one index of a face corner at *p: a nonzero integer, negative ones
 * counting back from count (the part's elements of that kind so far).
 * Stores it in *index (see the file comment), advances *p and notes a
 * negative index for the merge against corner slot. Returns FACET_OK,
 * FACET_EINPUT / FACET_EWORK with the error set, or NOT_AN_INDEX (error not
 * set: the caller quotes the whole corner) when no digits are at *p.
 * Plain positive indices of up to 10 digits take the short way here. */
static int read_index(struct obj_part *part, const char **p, const char *end,
                      size_t count, int which, size_t slot, uint32_t *index)
{
    const char *q = *p, *stop = end - *p > 10 ? *p + 10 : end;
    uint64_t value = 0;
    while (q < stop && (unsigned)(*q - '0') <= 9)
        value = value * 10 + (uint64_t)(*q++ - '0');
    if (value - 1 <= OBJ_MAX_INDEX &&
        (q == end || (unsigned)(*q - '0') > 9)) {
        *index = (uint32_t)(value - 1);
        *p = q;
        return FACET_OK;
    }
    return read_index_slow(part, p, end, count, which, slot, index);
}

/* Makes room for one more corner (and its relative flags). */
static int reserve_corner(struct obj_part *part, size_t slot)
{
    if (slot < part->corner_capacity)
        return FACET_OK;
    size_t capacity = part->corner_capacity;
    struct obj_corner *corner = obj_grow(part->corner, &capacity, slot + 1,
                                         sizeof *corner);
    if (corner == NULL)
        return out_of_memory(part);
    part->corner = corner;
    if (part->relative != NULL) {
        uint8_t *relative = realloc(part->relative, capacity);
        if (relative == NULL)
            return out_of_memory(part);
        memset(relative + part->corner_capacity, 0,
               capacity - part->corner_capacity);
        part->relative = relative;
    }
    part->corner_capacity = capacity;
    return FACET_OK;
}

/* Reads the corners of an f statement to the end of part->corner and
 * stores how many in *ncorners (the part's ncorners is not advanced). */
static int read_face_corners(struct obj_part *part, const char *p,
                             const char *end, size_t *ncorners)
{
    size_t n = 0;
    for (;;) {
        p = skip_blanks(p, end);
        if (p == end || *p == '#')
            break;
        size_t slot = part->ncorners + n;
        int rc = reserve_corner(part, slot);
        if (rc != FACET_OK)
            return rc;
        if (part->relative != NULL)
            part->relative[slot] = 0;
        struct obj_corner *c = &part->corner[slot];
        const char *start = p;
        c->vt = c->vn = OBJ_NONE;
        rc = read_index(part, &p, end, part->nvertices, 0, slot, &c->v);
        if (rc == FACET_OK && p < end && *p == '/') {
            p++;
            if (p < end && *p == '/') {
                p++;
                rc = read_index(part, &p, end, part->nnormals, 2, slot,
                                &c->vn);
            } else {
                rc = read_index(part, &p, end, part->ntexcoords, 1, slot,
                                &c->vt);
                if (rc == FACET_OK && p < end && *p == '/') {
                    p++;
                    rc = read_index(part, &p, end, part->nnormals, 2, slot,
                                    &c->vn);
                }
            }
        }
        if (rc == FACET_OK && !ends_token(p, end))
            rc = NOT_AN_INDEX;
        if (rc == NOT_AN_INDEX)
            return input_error(part,
                "face corner \"%.*s\" does not parse (expected v, "
                "v/vt, v//vn or v/vt/vn)", token_length(start, end), start);
        if (rc != FACET_OK)
            return rc;
        n++;
    }
    *ncorners = n;
    return FACET_OK;
}

/* Starts a new state run at the next face if the names changed since the
 * last one. */
static int note_state(struct obj_part *part)
{
    if (part->nstates > 0) {
        const struct obj_part_state *s = &part->state[part->nstates - 1];
        if (s->object == part->object && s->group == part->group &&
            s->material == part->material)
            return FACET_OK;
    }
    struct obj_part_state *state = obj_grow(part->state,
        &part->state_capacity, part->nstates + 1, sizeof *state);
    if (state == NULL)
        return out_of_memory(part);
    part->state = state;
    state[part->nstates].first_face = part->nfaces;
    state[part->nstates].object = part->object;
    state[part->nstates].group = part->group;
    state[part->nstates].material = part->material;
    part->nstates++;
    return FACET_OK;
}

static int statement_face(struct obj_part *part, const char *p,
                          const char *end)
{
    size_t n = 0;
    int rc = read_face_corners(part, p, end, &n);
    if (rc != FACET_OK)
        return rc;
    if (n < 3)
        return input_error(part,
            "face has %zu %s (a face needs at least 3)", n,
            n == 1 ? "vertex" : "vertices");
    if (n >= UINT32_MAX || part->nfaces >= OBJ_MAX_INDEX)
        return input_error(part, "face too large or too many faces");
    rc = note_state(part);
    if (rc != FACET_OK)
        return rc;
    if (part->nfaces == part->face_capacity) {
        struct obj_part_face *face = obj_grow(part->face,
            &part->face_capacity, part->nfaces + 1, sizeof *face);
        if (face == NULL)
            return out_of_memory(part);
        part->face = face;
    }
    part->face[part->nfaces].ncorners = (uint32_t)n;
    part->face[part->nfaces].line = (uint32_t)part->line;
    part->nfaces++;
    part->ncorners += n;
    part->ntriangles += n - 2;
    return FACET_OK;
}

/* ---- o, g, usemtl, mtllib --------------------------------------------- */

/* Copies the rest of the statement into part->text, trimmed, with joined
 * lines turned into single spaces, and stores its length in *length. */
static int read_rest(struct obj_part *part, const char *p, const char *end,
                     size_t *length)
{
    p = skip_blanks(p, end);
    while (end > p && (is_space(end[-1]) || is_continuation(end - 1, end)))
        end--;
    size_t n = (size_t)(end - p);
    char *text = obj_grow(part->text, &part->text_capacity, n + 1, 1);
    if (text == NULL)
        return out_of_memory(part);
    part->text = text;
    size_t k = 0;
    while (p < end) {
        if (is_continuation(p, end) || *p == '\r' || *p == '\n') {
            if (k == 0 || text[k - 1] != ' ')
                text[k++] = ' ';  /* joined lines become one space */
            p++;
            continue;
        }
        text[k++] = *p++;
    }
    text[k] = '\0';
    *length = k;
    return FACET_OK;
}

static int statement_name(struct obj_part *part, const char *p,
                          const char *end, struct obj_names *table,
                          uint32_t *current)
{
    size_t length;
    int rc = read_rest(part, p, end, &length);
    if (rc != FACET_OK)
        return rc;
    struct facet_error err;
    rc = obj_names_find(table, part->text, length, current, &err);
    if (rc != FACET_OK)
        return set_error(&part->error, rc, part->line, "%s", err.message);
    return FACET_OK;
}

static int statement_mtllib(struct obj_part *part, const char *p,
                            const char *end)
{
    size_t length;
    int rc = read_rest(part, p, end, &length);
    if (rc != FACET_OK)
        return rc;
    struct obj_name *mtllibs = obj_grow(part->mtllibs, &part->mtllib_capacity,
                                        part->nmtllibs + 1, sizeof *mtllibs);
    if (mtllibs == NULL)
        return out_of_memory(part);
    part->mtllibs = mtllibs;
    char *copy = malloc(length + 1);
    if (copy == NULL)
        return out_of_memory(part);
    memcpy(copy, part->text, length + 1);
    mtllibs[part->nmtllibs++].text = copy;
    return FACET_OK;
}

static int keyword_is(const char *word, size_t length, const char *name)
{
    return strlen(name) == length && memcmp(word, name, length) == 0;
}

/* Parses one logical line [p, end) (without its final newline). */
static int parse_statement(struct obj_part *part, const char *p,
                           const char *end)
{
    /* OBJ is text: a NUL byte anywhere (past the first 4 KB the binary
     * check reads) is data, and would cut a name short of its length. */
    if (memchr(p, '\0', (size_t)(end - p)) != NULL)
        return input_error(part, "a NUL byte: binary data, not OBJ text");
    p = skip_blanks(p, end);
    if (p == end || *p == '#')
        return FACET_OK;
    const char *word = p;
    while (p < end && !is_space(*p) && !is_continuation(p, end))
        p++;
    size_t length = (size_t)(p - word);
    part->nstatements++;

    if (length == 1) {
        switch (word[0]) {
        case 'v': return statement_vertex(part, p, end);
        case 'f': return statement_face(part, p, end);
        case 'o': return statement_name(part, p, end, &part->objects,
                                        &part->object);
        case 'g': return statement_name(part, p, end, &part->groups,
                                        &part->group);
        default: break;
        }
    } else if (length == 2 && word[0] == 'v') {
        if (word[1] == 't')
            return statement_texcoord(part, p, end);
        if (word[1] == 'n')
            return statement_normal(part, p, end);
    } else if (keyword_is(word, length, "usemtl")) {
        return statement_name(part, p, end, &part->materials,
                              &part->material);
    } else if (keyword_is(word, length, "mtllib")) {
        return statement_mtllib(part, p, end);
    }
    part->nskipped++;
    return FACET_OK;
}

/* ---- the part --------------------------------------------------------- */

void obj_part_init(struct obj_part *part)
{
    memset(part, 0, sizeof *part);
    part->object = part->group = part->material = OBJ_INHERITED;
}

void obj_part_free(struct obj_part *part)
{
    free(part->position);
    free(part->color);
    free(part->texcoord);
    free(part->normal);
    free(part->face);
    free(part->corner);
    free(part->relative);
    free(part->before);
    free(part->state);
    obj_names_free(&part->objects);
    obj_names_free(&part->groups);
    obj_names_free(&part->materials);
    for (size_t i = 0; i < part->nmtllibs; i++)
        free(part->mtllibs[i].text);
    free(part->mtllibs);
    free(part->text);
    obj_part_init(part);
}

int obj_part_parse(struct obj_part *part, const char *text, const char *end)
{
    const char *p = text;
    while (p < end) {
        const char *search = p, *newline;
        size_t nnewlines = 0;
        for (;;) {
            newline = memchr(search, '\n', (size_t)(end - search));
            if (newline == NULL)
                break;
            nnewlines++;
            const char *before = newline;
            if (before > search && before[-1] == '\r')
                before--;
            if (before > search && before[-1] == '\\') {
                search = newline + 1;  /* joined to the next line */
                continue;
            }
            break;
        }
        if (newline == NULL) {
            part->unterminated = end > search;
            newline = end;
        }
        int rc = parse_statement(part, p, newline);
        if (rc != FACET_OK)
            return rc;
        part->line += nnewlines;
        p = newline < end ? newline + 1 : end;
    }
    return FACET_OK;
}

/* ---- emission --------------------------------------------------------- */

void obj_emitter_free(struct obj_emitter *emitter)
{
    free(emitter->point);
    free(emitter->local);
    triangulate_scratch_free(&emitter->scratch);
    memset(emitter, 0, sizeof *emitter);
}

/* Checks the resolved corner c of the face at line against the totals. */
static int check_corner(const struct obj_file *obj, const struct obj_corner *c,
                        size_t line, struct obj_part_error *error)
{
    if (c->v >= obj->nvertices)
        return set_error(error, FACET_EINPUT, line,
            "vertex index %llu out of range (file has %zu vertices)",
            (unsigned long long)c->v + 1, obj->nvertices);
    if (c->vt != OBJ_NONE && c->vt >= obj->ntexcoords)
        return set_error(error, FACET_EINPUT, line, "texture coordinate "
            "index %llu out of range (file has %zu texture coordinates)",
            (unsigned long long)c->vt + 1, obj->ntexcoords);
    if (c->vn != OBJ_NONE && c->vn >= obj->nnormals)
        return set_error(error, FACET_EINPUT, line,
            "normal index %llu out of range (file has %zu normals)",
            (unsigned long long)c->vn + 1, obj->nnormals);
    return FACET_OK;
}

/* Writes the n - 2 triangles of the resolved face to out. */
static int triangulate_face(const struct obj_file *obj,
                            const struct obj_corner *face, size_t n,
                            struct obj_corner *out, size_t line,
                            struct obj_emitter *em,
                            struct obj_part_error *error)
{
    if (n == 3) {
        out[0] = face[0];
        out[1] = face[1];
        out[2] = face[2];
        return FACET_OK;
    }
    const double *x = obj->position;
    if (n == 4) {
        uint32_t local[6];
        triangulate_quad(x + 3 * (size_t)face[0].v, x + 3 * (size_t)face[1].v,
                         x + 3 * (size_t)face[2].v, x + 3 * (size_t)face[3].v,
                         local);
        for (int k = 0; k < 6; k++)
            out[k] = face[local[k]];
        return FACET_OK;
    }
    double *point = obj_grow(em->point, &em->point_capacity, n,
                             3 * sizeof *point);
    if (point == NULL)
        return set_error(error, FACET_EWORK, line, "out of memory");
    em->point = point;
    uint32_t *local = obj_grow(em->local, &em->local_capacity, n - 2,
                               3 * sizeof *local);
    if (local == NULL)
        return set_error(error, FACET_EWORK, line, "out of memory");
    em->local = local;
    for (size_t i = 0; i < n; i++)
        memcpy(point + 3 * i, x + 3 * (size_t)face[i].v, 3 * sizeof *point);
    struct facet_error err;
    if (triangulate_polygon(point, n, local, &em->scratch, &err) != FACET_OK)
        return set_error(error, err.code, line, "%s", err.message);
    for (size_t k = 0; k < 3 * (n - 2); k++)
        out[k] = face[local[k]];
    return FACET_OK;
}

static uint32_t merged_id(uint32_t id, const uint32_t *map, uint32_t inherited)
{
    return id == OBJ_INHERITED ? inherited : map[id];
}

int obj_part_emit(struct obj_part *part, size_t first, size_t end,
                  struct obj_file *obj, struct obj_emitter *emitter,
                  struct obj_part_error *error)
{
    size_t k = 0, t = part->triangle_base, s = 0;
    for (size_t i = 0; i < first; i++) {
        k += part->face[i].ncorners;
        t += part->face[i].ncorners - 2;
    }
    /* Every face has a state run: the first starts at face 0. */
    while (s + 1 < part->nstates && part->state[s + 1].first_face <= first)
        s++;
    uint32_t object = 0, group = 0, material = 0;
    size_t next_state = first;  /* where state s takes over */
    size_t vbase = part->vertex_base, tbase = part->texcoord_base;
    size_t nbase = part->normal_base;
    for (size_t i = first; i < end; i++) {
        if (i == next_state) {
            const struct obj_part_state *st = &part->state[s];
            object = merged_id(st->object, part->object_map,
                               part->inherited_object);
            group = merged_id(st->group, part->group_map,
                              part->inherited_group);
            material = merged_id(st->material, part->material_map,
                                 part->inherited_material);
            s++;
            next_state = s < part->nstates ? part->state[s].first_face
                                           : SIZE_MAX;
        }
        size_t n = part->face[i].ncorners;
        size_t line = part->face[i].line;
        struct obj_corner *c = part->corner + k;
        if (part->relative != NULL) {
            const uint8_t *rel = part->relative + k;
            for (size_t j = 0; j < n; j++) {
                if (rel[j] & OBJ_RELATIVE_V)
                    c[j].v += (uint32_t)vbase;
                if (rel[j] & OBJ_RELATIVE_VT)
                    c[j].vt += (uint32_t)tbase;
                if (rel[j] & OBJ_RELATIVE_VN)
                    c[j].vn += (uint32_t)nbase;
            }
        }
        for (size_t j = 0; j < n; j++) {
            if (c[j].v >= obj->nvertices ||
                (c[j].vt >= obj->ntexcoords && c[j].vt != OBJ_NONE) ||
                (c[j].vn >= obj->nnormals && c[j].vn != OBJ_NONE))
                return check_corner(obj, &c[j], line, error);
        }
        int rc = triangulate_face(obj, c, n, obj->corner + 3 * t, line,
                                  emitter, error);
        if (rc != FACET_OK)
            return rc;
        uint32_t face = (uint32_t)(part->face_base + i);
        for (size_t j = t; j < t + n - 2; j++) {
            obj->triangle_face[j] = face;
            obj->triangle_object[j] = object;
            obj->triangle_group[j] = group;
            obj->triangle_material[j] = material;
        }
        k += n;
        t += n - 2;
    }
    return FACET_OK;
}
