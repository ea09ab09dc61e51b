/*
 * study_merge.c: the shards of a run joined into one run. See
 * study_merge.h.
 */
#include "study/study_merge.h"

#include <assert.h>
#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/base/numformat.h"
#include "core/out/outfile.h"
#include "merge_side.h"
#include "study_internal.h"

/* One shard file as read. */
struct shard_file {
    const char *path;
    struct run_info run;
    struct option_row *rows;
    size_t n;
    /* A project run's surfaces (the surfaces table), nsurfaces of them;
     * NULL, 0 for a single surface's. */
    struct surface_row *surfaces;
    size_t nsurfaces;
};

/* The settings that make two runs shards of one run, as text (doubles to
 * the bit), in a fixed order with their names: what a merge compares. */
enum { RUN_KEYS = 28, KEY_TEXT = 200 };
static const char *const key_name[RUN_KEYS] = {
    "surface (SHA-256)", "units", "object", "group", "method", "seed",
    "module range (m)", "u", "v", "threshold", "prices (FP, SP, DP)",
    "sp_as_fp",
    "max_panel_area", "curvature_tol", "per_panel", "flip_normals", "uv",
    "uv_method", "objectives", "population and generations", "evaluations",
    "cost model (panel, joint, SP and DP moulds)",
    "mould tolerance and mirror",
    "panels as built (SP fit, gap limit mm, kink limit deg)",
    "panel width limit (m)", "welding tolerance of the seams (mm)",
    "store_panels",
    "number of shards"};

static void run_keys(const struct run_info *r, char text[RUN_KEYS][KEY_TEXT])
{
    int k = 0;
    snprintf(text[k++], KEY_TEXT, "%s", r->surface_sha256);
    snprintf(text[k++], KEY_TEXT, "%s",
             store_run_setting_text(r, RUN_SETTING_UNITS));
    snprintf(text[k++], KEY_TEXT, "%s", r->object);
    snprintf(text[k++], KEY_TEXT, "%s", r->group);
    snprintf(text[k++], KEY_TEXT, "%s",
             store_run_setting_text(r, RUN_SETTING_METHOD));
    snprintf(text[k++], KEY_TEXT, "%llu", (unsigned long long)r->seed);
    /* Before u and v, which of a project are indices into it. */
    if (store_run_is_project(r)) {
        const double module[6] = {r->module_w_min, r->module_w_max,
                                  r->module_w_step, r->module_h_min,
                                  r->module_h_max, r->module_h_step};
        char m[6][NUMBER_EXACT_SIZE];
        for (int j = 0; j < 6; j++)
            number_exact(m[j], module[j]);
        snprintf(text[k++], KEY_TEXT, "%s:%s:%s x %s:%s:%s", m[0], m[1], m[2],
                 m[3], m[4], m[5]);
    } else
        snprintf(text[k++], KEY_TEXT, "none (a single surface)");
    snprintf(text[k++], KEY_TEXT, "%d:%d", r->u_min, r->u_max);
    snprintf(text[k++], KEY_TEXT, "%d:%d", r->v_min, r->v_max);
    snprintf(text[k++], KEY_TEXT, "%.17g:%.17g:%.17g", r->threshold_min_mm,
             r->threshold_max_mm, r->threshold_step_mm);
    snprintf(text[k++], KEY_TEXT, "%.17g, %.17g, %.17g", r->price[TYPE_FP],
             r->price[TYPE_SP], r->price[TYPE_DP]);
    snprintf(text[k++], KEY_TEXT, "%d", r->sp_as_fp);
    snprintf(text[k++], KEY_TEXT, "%.17g", r->max_panel_area);
    snprintf(text[k++], KEY_TEXT, "%.17g", r->curvature_tol);
    snprintf(text[k++], KEY_TEXT, "%s",
             store_run_setting_text(r, RUN_SETTING_PER_PANEL));
    snprintf(text[k++], KEY_TEXT, "%d", r->flip_normals);
    snprintf(text[k++], KEY_TEXT, "%s",
             store_run_setting_text(r, RUN_SETTING_UV));
    snprintf(text[k++], KEY_TEXT, "%s",
             store_run_setting_text(r, RUN_SETTING_UV_METHOD));
    snprintf(text[k++], KEY_TEXT, "%s", r->objectives);
    snprintf(text[k++], KEY_TEXT, "%d x %d", r->population, r->generations);
    snprintf(text[k++], KEY_TEXT, "%lld", (long long)r->evaluations);
    snprintf(text[k++], KEY_TEXT, "%.17g, %.17g, %.17g, %.17g", r->panel_cost,
             r->joint_cost, r->mould_cost[TYPE_SP], r->mould_cost[TYPE_DP]);
    snprintf(text[k++], KEY_TEXT, "%.17g, %d", r->mould_tol_mm,
             r->mould_mirror);
    snprintf(text[k++], KEY_TEXT, "%d, %.17g, %.17g", r->sp_fit, r->max_gap_mm,
             r->max_kink_deg);
    snprintf(text[k++], KEY_TEXT, "%.17g", r->min_panel_width);
    snprintf(text[k++], KEY_TEXT, "%.17g", r->weld_mm);
    snprintf(text[k++], KEY_TEXT, "%s",
             store_run_setting_text(r, RUN_SETTING_STORE_PANELS));
    snprintf(text[k++], KEY_TEXT, "%d", r->shard_count);
    assert(k == RUN_KEYS);
}

/* The first setting in which b differs from a, or -1; its texts into
 * ta, tb. */
static int first_difference(const struct run_info *a,
                            const struct run_info *b, char ta[KEY_TEXT],
                            char tb[KEY_TEXT])
{
    char x[RUN_KEYS][KEY_TEXT], y[RUN_KEYS][KEY_TEXT];
    run_keys(a, x);
    run_keys(b, y);
    for (int k = 0; k < RUN_KEYS; k++)
        if (strcmp(x[k], y[k]) != 0) {
            memcpy(ta, x[k], KEY_TEXT);
            memcpy(tb, y[k], KEY_TEXT);
            return k;
        }
    return -1;
}

/* Where the surfaces b differ from a's, as a project's shards must not:
 * the first surface that differs in its name, file (by SHA-256), UV or
 * grid of its own, or a count that differs, described into text (size
 * bytes). Returns 1 when they differ, 0 when they are the same (a single
 * surface's runs have none, and so never differ here). The files' paths
 * are not compared: each shard may have read its copy from its own
 * node's folder. */
static int surfaces_differ(const struct surface_row *a, size_t na,
                           const struct surface_row *b, size_t nb,
                           char *text, size_t size)
{
    if (na != nb) {
        snprintf(text, size, "%zu surfaces, not %zu", nb, na);
        return 1;
    }
    for (size_t i = 0; i < na; i++) {
        const struct surface_row *x = &a[i], *y = &b[i];
        if (strcmp(x->name, y->name) != 0)
            snprintf(text, size, "surface %zu: '%.100s', not '%.100s'",
                     i + 1, y->name, x->name);
        else if (strcmp(x->file_sha256, y->file_sha256) != 0)
            snprintf(text, size, "surface %zu ('%.100s'): a file of "
                     "SHA-256 %.12s..., not %.12s...", i + 1, y->name,
                     y->file_sha256, x->file_sha256);
        else if (x->uv_method != y->uv_method)
            snprintf(text, size, "surface %zu ('%.100s'): UV %s, not %s",
                     i + 1, y->name, param_method_name(y->uv_method),
                     param_method_name(x->uv_method));
        else if (x->grid_nu != y->grid_nu || x->grid_nv != y->grid_nv)
            snprintf(text, size, "surface %zu ('%.100s'): its own grid "
                     "%d x %d, not %d x %d (0 x 0: none)", i + 1, y->name,
                     y->grid_nu, y->grid_nv, x->grid_nu, x->grid_nv);
        else
            continue;
        return 1;
    }
    return 0;
}

/* Reads the one finished shard run of path into *f. */
static int read_shard(const char *path, struct shard_file *f,
                      struct facet_error *err)
{
    memset(f, 0, sizeof *f);
    f->path = path;
    struct store *store;
    int rc = store_open_read(path, &store, err);
    if (rc != FACET_OK)
        return rc;
    /* A shard has come over a network: every page is read, so that a
     * damaged copy is refused, not merged from the pages that read. */
    struct run_info *runs = NULL;
    size_t nruns = 0, found = 0;
    rc = store_check(store, err);
    if (rc == FACET_OK)
        rc = store_run_list(store, &runs, &nruns, err);
    for (size_t k = 0; rc == FACET_OK && k < nruns; k++)
        if (runs[k].shard_index > 0) {
            if (found++ == 0)
                f->run = runs[k];
        }
    if (rc == FACET_OK && found == 0)
        rc = facet_error_set(err, FACET_EINPUT,
            "%s: holds no shard (a run made with a shard I/N)", path);
    else if (rc == FACET_OK && found > 1)
        rc = facet_error_set(err, FACET_EINPUT,
            "%s: holds %zu shards; give each shard in a file of its own",
            path, found);
    else if (rc == FACET_OK && f->run.status != RUN_DONE)
        rc = facet_error_set(err, FACET_EINPUT,
            "%s: shard %d/%d (run %lld) is %s, not done: resume it first",
            path, f->run.shard_index, f->run.shard_count,
            (long long)f->run.id, run_status_name(f->run.status));
    if (rc == FACET_OK)
        rc = store_shard_check(store, &f->run, err);
    if (rc == FACET_OK)
        rc = store_options_get(store, f->run.id, &f->rows, &f->n, err);
    if (rc == FACET_OK && store_run_is_project(&f->run)) {
        rc = store_surfaces_get(store, f->run.id, &f->surfaces,
                                &f->nsurfaces, err);
        if (rc == FACET_OK && f->nsurfaces == 0)
            rc = facet_error_set(err, FACET_EINPUT,
                "%s: shard %d/%d is a project's without its surfaces "
                "recorded", path, f->run.shard_index, f->run.shard_count);
    }
    free(runs);
    store_close(store);
    return rc;
}

/* Refuses shards that are not of one run: the first setting that
 * differs from the first shard's, or an index given twice. */
static int check_shards(const struct shard_file *f, int n,
                        struct facet_error *err)
{
    for (int k = 1; k < n; k++) {
        char a[KEY_TEXT], b[KEY_TEXT];
        int d = first_difference(&f[0].run, &f[k].run, a, b);
        if (d == 0)
            return facet_error_set(err, FACET_EINPUT,
                "%s (shard %d/%d) was made from another surface than %s "
                "(SHA-256 %.12s..., not %.12s...): merge only shards of "
                "one run", f[k].path, f[k].run.shard_index,
                f[k].run.shard_count, f[0].path, b, a);
        if (d > 0)
            return facet_error_set(err, FACET_EINPUT,
                "%s (shard %d/%d) differs from %s in its %s: %s, not %s: "
                "merge only shards of one run", f[k].path,
                f[k].run.shard_index, f[k].run.shard_count, f[0].path,
                key_name[d], b, a);
        char why[400];
        if (surfaces_differ(f[0].surfaces, f[0].nsurfaces, f[k].surfaces,
                            f[k].nsurfaces, why, sizeof why))
            return facet_error_set(err, FACET_EINPUT,
                "%s (shard %d/%d) is of another project than %s: %s: "
                "merge only shards of one run", f[k].path,
                f[k].run.shard_index, f[k].run.shard_count, f[0].path, why);
        for (int j = 0; j < k; j++)
            if (f[j].run.shard_index == f[k].run.shard_index)
                return facet_error_set(err, FACET_EINPUT,
                    "%s and %s are both shard %d/%d: give each shard once",
                    f[j].path, f[k].path, f[k].run.shard_index,
                    f[k].run.shard_count);
    }
    return FACET_OK;
}

/* Where a merged option came from: the shard file (its index among the
 * files given) and its number there, which a project's surface rows
 * (option_surfaces) are read by. */
struct row_origin {
    int file;
    int64_t number;
};

/* A row of the union and the shard it came from. */
struct merged_row {
    struct option_row row;
    int shard;
    struct row_origin origin;
};

static int by_number(const void *a, const void *b)
{
    const struct merged_row *p = a, *q = b;
    if (p->row.number != q->row.number)
        return p->row.number < q->row.number ? -1 : 1;
    return (p->shard > q->shard) - (p->shard < q->shard);
}

/* By design point (to a thousandth of a millimetre, as the search tells
 * points apart), then shard and number: the first of equal points is
 * the one met first in shard order. */
static struct design_point point_of(const struct option_row *row)
{
    return (struct design_point){row->nu, row->nv, row->threshold_mm};
}

static int by_point(const void *a, const void *b)
{
    const struct merged_row *p = a, *q = b;
    struct design_point pp = point_of(&p->row), qp = point_of(&q->row);
    int order = design_point_compare(&pp, &qp);
    if (order != 0)
        return order;
    if (p->shard != q->shard)
        return p->shard < q->shard ? -1 : 1;
    return (p->row.number > q->row.number) - (p->row.number < q->row.number);
}

static int same_point(const struct option_row *a, const struct option_row *b)
{
    struct design_point pa = point_of(a), pb = point_of(b);
    return design_point_compare(&pa, &pb) == 0;
}

static int by_shard(const void *a, const void *b)
{
    const struct merged_row *p = a, *q = b;
    if (p->shard != q->shard)
        return p->shard < q->shard ? -1 : 1;
    return (p->row.number > q->row.number) - (p->row.number < q->row.number);
}

/* The union of the shards' options, numbered as the merged run numbers
 * them, into *out (malloc'ed), *nout of them, with where each came from
 * in (*origin)[k] (malloc'ed). */
static int union_rows(const struct shard_file *f, int n,
                      struct option_row **out, struct row_origin **origin,
                      size_t *nout, struct facet_error *err)
{
    size_t total = 0;
    for (int k = 0; k < n; k++)
        total += f[k].n;
    struct merged_row *all = malloc((total ? total : 1) * sizeof *all);
    *out = malloc((total ? total : 1) * sizeof **out);
    *origin = malloc((total ? total : 1) * sizeof **origin);
    if (all == NULL || *out == NULL || *origin == NULL) {
        free(all);
        free(*out);
        free(*origin);
        *out = NULL;
        *origin = NULL;
        return facet_error_set(err, FACET_EWORK, "out of memory");
    }
    size_t m = 0;
    for (int k = 0; k < n; k++)
        for (size_t j = 0; j < f[k].n; j++) {
            all[m].row = f[k].rows[j];
            all[m].row.rank = 0;
            all[m].row.crowding = 0;
            all[m].row.knee = 0;
            all[m].origin = (struct row_origin){k, f[k].rows[j].number};
            all[m++].shard = f[k].run.shard_index;
        }
    int rc = FACET_OK;
    size_t kept = 0;
    if (f[0].run.method != METHOD_NSGA2) {
        /* Numbered as in the unsharded run already: a partition. */
        qsort(all, m, sizeof *all, by_number);
        for (size_t j = 0; j < m; j++) {
            if (j > 0 && all[j].row.number == all[j - 1].row.number) {
                rc = facet_error_set(err, FACET_EINPUT,
                    "shards %d and %d both hold option %lld: not shards of "
                    "one run", all[j - 1].shard, all[j].shard,
                    (long long)all[j].row.number);
                break;
            }
            (*origin)[kept] = all[j].origin;
            (*out)[kept++] = all[j].row;
        }
    } else {
        /* Islands: each point once, the first island's, numbered in
         * shard order. */
        qsort(all, m, sizeof *all, by_point);
        size_t distinct = 0;
        for (size_t j = 0; j < m; j++)
            if (j == 0 || !same_point(&all[j].row, &all[j - 1].row))
                all[distinct++] = all[j];
        qsort(all, distinct, sizeof *all, by_shard);
        for (size_t j = 0; j < distinct; j++) {
            (*origin)[kept] = all[j].origin;
            (*out)[kept] = all[j].row;
            (*out)[kept].number = (int64_t)kept + 1;
            kept++;
        }
    }
    free(all);
    if (rc != FACET_OK) {
        free(*out);
        free(*origin);
        *out = NULL;
        *origin = NULL;
        return rc;
    }
    *nout = kept;
    return FACET_OK;
}

/* Whether paths a and b are the same file (both exist). */
static int same_file(const char *a, const char *b)
{
    struct stat x, y;
    return stat(a, &x) == 0 && stat(b, &y) == 0 && x.st_dev == y.st_dev &&
           x.st_ino == y.st_ino;
}

/* Refuses to replace out (open in store) while another Facet writes a run
 * into it: the writer would go on into the file replaced, and its options
 * be lost, as --resume refuses a run that is being written. */
static int refuse_live_writer(struct store *store, const char *out,
                              struct facet_error *err)
{
    struct run_info run;
    int live;
    int rc = store_run_live_writer(store, 0, &run, &live, err);
    if (rc == FACET_OK && live)
        rc = facet_error_set(err, FACET_EINPUT,
            "%s: run %lld in it is being written by process %lld on %s: "
            "merge when it ends, or into another file", out,
            (long long)run.id, (long long)run.writer_pid, run.writer_host);
    return rc;
}

/* Flushes path's contents to the disk, so that the rename that puts it in
 * place never shows a file the disk does not hold. */
static int sync_file(const char *path, struct facet_error *err)
{
    int fd = open(path, O_RDONLY);
    if (fd < 0 || fsync(fd) != 0) {
        int code = errno;
        if (fd >= 0)
            close(fd);
        return facet_error_set(err, FACET_EWORK, "%s: cannot write it to "
                               "the disk (%s)", path, strerror(code));
    }
    if (close(fd) != 0)
        return facet_error_set(err, FACET_EWORK, "%s: cannot write it to "
                               "the disk (%s)", path, strerror(errno));
    return FACET_OK;
}

/* FACET_ESTOP when the hooks' stop fires: asked between the merge's
 * steps, each a few seconds at most on shards of a million options, so
 * that a stopped merge leaves the output as it was and its side file
 * removed. */
static int merge_stop(const struct study_hooks *hooks,
                      struct facet_error *err)
{
    struct facet_stop stop = study_stop(hooks);
    return facet_stop_check(&stop, err);
}

/* The indices of 1..count not in f[0..n) into text, "" when none. */
static void missing_text(const struct shard_file *f, int n, int count,
                         char *text, size_t size)
{
    size_t used = 0;
    text[0] = '\0';
    for (int index = 1; index <= count; index++) {
        int given = 0;
        for (int k = 0; k < n && !given; k++)
            given = f[k].run.shard_index == index;
        if (given)
            continue;
        int wrote = snprintf(text + used, size - used, "%s%d",
                             used ? ", " : "", index);
        if (wrote < 0 || (size_t)wrote >= size - used) {
            snprintf(text + (size > 5 ? size - 5 : 0), size > 5 ? 5 : size,
                     "...");
            return;
        }
        used += (size_t)wrote;
    }
}

static void tell_warning(const struct study_hooks *hooks, const char *text)
{
    if (hooks != NULL && hooks->warning != NULL)
        hooks->warning(hooks->context, text);
}

/* The merged run of f's settings (and, of a project, its surfaces) in
 * store, or 0. */
static int find_merged(struct store *store, const struct shard_file *f,
                       const struct run_info *like, int64_t *id,
                       struct facet_error *err)
{
    *id = 0;
    struct run_info *runs;
    size_t n;
    int rc = store_run_list(store, &runs, &n, err);
    for (size_t k = 0; rc == FACET_OK && k < n; k++) {
        char a[KEY_TEXT], b[KEY_TEXT];
        if (runs[k].shard_index != 0 || runs[k].shard_count == 0 ||
            first_difference(like, &runs[k], a, b) >= 0)
            continue;
        struct surface_row *surfaces;
        size_t nsurfaces;
        rc = store_surfaces_get(store, runs[k].id, &surfaces, &nsurfaces,
                                err);
        char why[400];
        if (rc == FACET_OK &&
            !surfaces_differ(f->surfaces, f->nsurfaces, surfaces, nsurfaces,
                             why, sizeof why))
            *id = runs[k].id;
        free(surfaces);
    }
    if (rc == FACET_OK)
        free(runs);
    return rc;
}

/* Options per transaction when a project's options are written with
 * their surface rows. */
#define PROJECT_CHUNK 256

/* Writes a project's merged options rows[0..nrows) into run with their
 * surface rows, read from the shard each came from (origin): shard by
 * shard, so each file is opened once and only a chunk of rows is held. */
static int put_project_options(struct store *store, int64_t run,
                               const struct shard_file *f, int nfiles,
                               const struct option_row *rows,
                               const struct row_origin *origin,
                               size_t nrows, struct facet_error *err)
{
    size_t ns = f[0].nsurfaces;
    struct option_row *chunk = malloc(PROJECT_CHUNK * sizeof *chunk);
    struct option_surface_row *surfaces =
        malloc(PROJECT_CHUNK * ns * sizeof *surfaces);
    /* The rows of each file together, in merged order (a counting sort
     * by file): file k's are order[first[k] .. first[k + 1]). */
    size_t *order = malloc((nrows ? nrows : 1) * sizeof *order);
    size_t *first = calloc((size_t)nfiles + 1, sizeof *first);
    size_t *next = malloc((size_t)nfiles * sizeof *next);
    int rc = FACET_OK;
    if (chunk == NULL || surfaces == NULL || order == NULL ||
        first == NULL || next == NULL)
        rc = facet_error_set(err, FACET_EWORK, "out of memory");
    for (size_t j = 0; rc == FACET_OK && j < nrows; j++)
        first[origin[j].file + 1]++;
    for (int k = 0; rc == FACET_OK && k < nfiles; k++) {
        first[k + 1] += first[k];
        next[k] = first[k];
    }
    for (size_t j = 0; rc == FACET_OK && j < nrows; j++)
        order[next[origin[j].file]++] = j;
    for (int k = 0; rc == FACET_OK && k < nfiles; k++) {
        struct store *shard;
        if ((rc = store_open_read(f[k].path, &shard, err)) != FACET_OK)
            break;
        size_t n = 0;
        for (size_t at = first[k]; rc == FACET_OK && at < first[k + 1];
             at++) {
            size_t j = order[at];
            struct option_surface_row *got;
            size_t ngot;
            rc = store_option_surfaces_get(shard, f[k].run.id,
                                           origin[j].number, &got, &ngot,
                                           err);
            if (rc == FACET_OK && ngot != ns)
                rc = facet_error_set(err, FACET_EINPUT,
                    "%s: option %lld of shard %d/%d has %zu surface rows, "
                    "not %zu", f[k].path, (long long)origin[j].number,
                    f[k].run.shard_index, f[k].run.shard_count, ngot, ns);
            if (rc == FACET_OK) {
                chunk[n] = rows[j];
                memcpy(surfaces + n * ns, got, ns * sizeof *got);
                n++;
            }
            free(got);
            if (rc == FACET_OK &&
                (n == PROJECT_CHUNK || at + 1 == first[k + 1])) {
                rc = store_project_options_put(store, run, chunk, n,
                                               surfaces, ns, err);
                n = 0;
            }
        }
        store_close(shard);
    }
    free(chunk);
    free(surfaces);
    free(order);
    free(first);
    free(next);
    return rc;
}

/* Writes the merged run into the (temporary) database at path. */
static int write_merged(const char *path, const struct shard_file *f, int n,
                        int allow_fewer, const struct option_row *rows,
                        const struct row_origin *origin, size_t nrows,
                        const struct study_hooks *hooks,
                        struct merge_report *report, struct facet_error *err)
{
    struct store *store;
    int rc = store_open(path, &store, err);
    if (rc != FACET_OK)
        return rc;
    struct run_info run = f[0].run;
    run.shard_index = 0;
    run.shards_merged = n;
    double elapsed = 0;
    for (int k = 0; k < n; k++)
        elapsed += f[k].run.elapsed;
    int project = store_run_is_project(&run);
    rc = find_merged(store, &f[0], &run, &run.id, err);
    report->replaced = run.id != 0;
    if (rc == FACET_OK && run.id != 0 && !allow_fewer) {
        struct run_info held;
        rc = store_run_get(store, run.id, &held, err);
        if (rc == FACET_OK && held.shards_merged > n)
            rc = facet_error_about(err, FACET_SETTING_FEWER, FACET_EINPUT,
                "run %lld there holds %d of %d shards merged; these %d would "
                "replace it with fewer (the other shards' options lost): "
                "give every shard it holds", (long long)run.id,
                held.shards_merged, held.shard_count, n);
    }
    if (rc == FACET_OK && run.id != 0) {
        rc = store_run_clear_options(store, run.id, err);
        if (rc == FACET_OK)
            rc = store_run_set_status(store, run.id, RUN_RUNNING, elapsed,
                                      err);
    } else if (rc == FACET_OK) {
        rc = store_run_create(store, &run, err);
        /* The first shard's surfaces: every shard's are the same but
         * for where its node read the files. */
        if (rc == FACET_OK && project)
            rc = store_surfaces_put(store, run.id, f[0].surfaces,
                                    f[0].nsurfaces, err);
    }
    /* The shards' warnings (of one surface and space: the first's), and
     * the shards missing. */
    if (report->missing[0] != '\0') {
        size_t used = strlen(run.warnings);
        snprintf(run.warnings + used, sizeof run.warnings - used,
                 "%sincomplete: %d of %d shards merged; missing: %s",
                 used ? "\n" : "", n, run.shard_count, report->missing);
    }
    if (rc == FACET_OK)
        rc = store_run_set_shard(store, &run, err);
    /* Many options go in without the indexes by metric, built once
     * after (store_indexes_defer). */
    int deferred = 0;
    if (rc == FACET_OK)
        rc = store_indexes_defer(store, (int64_t)nrows, &deferred, err);
    const size_t chunk = 10000;
    if (rc == FACET_OK && project)
        rc = put_project_options(store, run.id, f, n, rows, origin, nrows,
                                 err);
    for (size_t first = 0; rc == FACET_OK && !project && first < nrows;
         first += chunk)
        if ((rc = merge_stop(hooks, err)) == FACET_OK)
            rc = store_options_put(store, run.id, rows + first,
                                   nrows - first < chunk ? nrows - first
                                                         : chunk, err);
    if (rc == FACET_OK && deferred)
        rc = merge_stop(hooks, err);
    if (rc == FACET_OK && deferred)
        rc = store_indexes_build(store, run.id, NULL, err);
    /* The end of every run: ranks, and the front's panels on the surface
     * when it can be found (else computed when shown). */
    struct optimize_settings settings;
    struct mesh_options mesh;
    int flip;
    struct surface surface;
    memset(&surface, 0, sizeof surface);
    int have_surface = 0;
    struct panel_lattice *lattice = NULL;
    if (rc == FACET_OK)
        rc = study_settings(&run, &settings, &mesh, &flip, err);
    /* A project's options keep their surfaces' totals, not panels
     * (study_project_view.h evaluates them again when looked at). */
    if (rc == FACET_OK)
        rc = merge_stop(hooks, err);
    if (rc == FACET_OK && run.store_panels != KEEP_NONE && !project) {
        struct facet_error why;
        int opened = study_open_surface_stoppable(store, &run, hooks,
                                                  &surface, &why);
        if (opened == FACET_OK)
            opened = merge_stop(hooks, &why);
        if (opened == FACET_OK)
            opened = optimize_lattice(&surface, &settings, &lattice, &why);
        if (opened == FACET_ESTOP) {
            rc = facet_stop_error(err);
        } else if (opened == FACET_OK) {
            have_surface = 1;
        } else {
            char text[sizeof why.message + 128];
            snprintf(text, sizeof text, "the Pareto options' panels are "
                     "not stored (facet show and export compute them when "
                     "asked): %s", why.message);
            tell_warning(hooks, text);
        }
    }
    enum optimize_outcome outcome = OPTIMIZE_DONE;
    if (rc == FACET_OK)
        rc = study_finish(store, &run, have_surface ? &surface : NULL,
                          lattice, &settings, hooks, &outcome, err);
    /* A merge has no half: stopped while it ranked or stored panels, it
     * is dropped whole like any other stop. */
    if (rc == FACET_OK && outcome == OPTIMIZE_INTERRUPTED)
        rc = facet_stop_error(err);
    panel_lattice_free(lattice);
    surface_close(&surface);
    if (rc == FACET_OK)
        rc = store_run_set_status(store, run.id, RUN_DONE, elapsed, err);
    if (rc == FACET_OK)
        rc = store_run_get(store, run.id, &run, err);
    if (rc == FACET_OK) {
        report->run = run.id;
        report->options = run.options;
        report->pareto_options = run.pareto_options;
    }
    /* The copy takes the output's place with its side files deleted: it
     * must hold every page itself, and read whole, first. */
    if (rc == FACET_OK)
        rc = store_seal(store, err);
    store_close(store);
    return rc;
}

int study_merge(const char *out, const char *const *paths, int nshards,
                int allow_fewer, const struct study_hooks *hooks,
                struct merge_report *report, struct facet_error *err)
{
    memset(report, 0, sizeof *report);
    if (nshards < 1)
        return facet_error_set(err, FACET_EINPUT, "no shard to merge");
    /* The merge replaces out by a rename, which would put a file where
     * the link was; reading through it first would be a second rule. */
    int rc = outfile_refuse_link(out, err);
    if (rc != FACET_OK)
        return rc;
    for (int k = 0; k < nshards; k++)
        if (same_file(out, paths[k]) || strcmp(out, paths[k]) == 0)
            return facet_error_set(err, FACET_EINPUT,
                "%s is one of the shards: name a new file for the merged "
                "run", out);
    struct shard_file *f = calloc((size_t)nshards, sizeof *f);
    if (f == NULL)
        return facet_error_set(err, FACET_EWORK, "out of memory");
    /* Side files of merges into out that were killed: no one else
     * removes them. */
    merge_side_sweep(out);
    for (int k = 0; rc == FACET_OK && k < nshards; k++)
        if ((rc = merge_stop(hooks, err)) == FACET_OK)
            rc = read_shard(paths[k], &f[k], err);
    if (rc == FACET_OK)
        rc = check_shards(f, nshards, err);
    struct option_row *rows = NULL;
    struct row_origin *origin = NULL;
    size_t nrows = 0;
    if (rc == FACET_OK)
        rc = union_rows(f, nshards, &rows, &origin, &nrows, err);
    if (rc == FACET_OK) {
        report->shard_count = f[0].run.shard_count;
        report->shards_merged = nshards;
        missing_text(f, nshards, report->shard_count, report->missing,
                     sizeof report->missing);
    }

    /* The copy beside the output, put in its place at the end: created
     * with the mode a new file gets (the umask's), or the output's own. */
    char temp[4200] = "";
    if (rc == FACET_OK &&
        snprintf(temp, sizeof temp, "%s.merge-%ld", out, (long)getpid()) >=
            (int)sizeof temp) {
        temp[0] = '\0';
        rc = facet_error_set(err, FACET_EINPUT, "%.200s...: path too long",
                             out);
    }
    int fd = -1;
    if (rc == FACET_OK)
        rc = merge_stop(hooks, err);
    if (rc == FACET_OK) {
        unlink(temp);  /* a merge of this pid killed long ago */
        merge_side_remove_sqlite(temp);
        fd = open(temp, O_WRONLY | O_CREAT | O_EXCL, 0666);
        if (fd < 0) {
            rc = facet_error_set(err, FACET_EINPUT,
                "%s: cannot write beside it (%s): the merged run needs a "
                "folder it may write in", out, strerror(errno));
            temp[0] = '\0';
        }
    }
    struct stat st;
    if (fd >= 0 && stat(out, &st) == 0)
        fchmod(fd, st.st_mode & 0777);
    if (fd >= 0)
        close(fd);
    if (rc == FACET_OK && access(out, F_OK) == 0) {
        struct store *old;
        rc = store_open_read(out, &old, err);
        if (rc == FACET_OK)
            rc = refuse_live_writer(old, out, err);
        if (rc == FACET_OK)
            rc = store_copy(old, temp, err);
        store_close(old);
    }
    if (rc == FACET_OK && (rc = merge_stop(hooks, err)) == FACET_OK)
        rc = write_merged(temp, f, nshards, allow_fewer, rows, origin,
                          nrows, hooks, report, err);
    /* Sealed (store_seal), the copy's WAL is empty; unsealed, the copy is
     * dropped whole with its side files below. */
    if (temp[0] != '\0')
        merge_side_remove_sqlite(temp);
    if (rc == FACET_OK)
        rc = sync_file(temp, err);
    /* The last moment a stop is heard: after the rename the merge is
     * done, and said so. */
    if (rc == FACET_OK)
        rc = merge_stop(hooks, err);
    /* Asked again at the last moment: a writer that opened the output
     * while the merge worked would lose its work to the rename too. */
    if (rc == FACET_OK && access(out, F_OK) == 0) {
        struct store *old;
        rc = store_open_read(out, &old, err);
        if (rc == FACET_OK)
            rc = refuse_live_writer(old, out, err);
        store_close(old);
    }
    if (rc == FACET_OK && rename(temp, out) != 0)
        rc = facet_error_set(err, FACET_EINPUT, "%s: cannot replace it "
                             "(%s)", out, strerror(errno));
    if (rc == FACET_OK) {
        /* The old file's side files would be taken for the new one's. */
        merge_side_remove_sqlite(out);
    } else if (temp[0] != '\0') {
        unlink(temp);
        merge_side_remove_sqlite(temp);
    }
    for (int k = 0; k < nshards; k++) {
        free(f[k].rows);
        free(f[k].surfaces);
    }
    free(f);
    free(rows);
    free(origin);
    return rc;
}
