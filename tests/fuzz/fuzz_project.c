/*
 * fuzz_project.c: any bytes as a project, the way `facet optimize a.obj
 * --module SPEC` and `facet info` take one: the first line is the module
 * text, the rest the OBJ file of the building. The file is split into
 * its surfaces (objects, else groups, else the whole file), each
 * prepared, then gridded by every module of the range and the modules
 * put in classes of equal grids, as a search over the range does. One
 * small option is evaluated over the building.
 *
 * Must hold, besides no crash, hang or leak:
 *   - every error is one line, never empty;
 *   - surfaces have unique names and add up to the building;
 *   - modules are finite, positive, inside their range, and two modules
 *     of one class give every surface the same grid (project_search.h);
 *   - a project of one surface evaluates as that surface alone, to the
 *     bit (project_option.h).
 */
#define _GNU_SOURCE  /* memfd_create */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <unistd.h>

#include "core/evaluate/evaluate.h"
#include "core/panel/panel.h"
#include "core/project/module.h"
#include "core/project/project.h"
#include "core/project/project_grids.h"
#include "core/project/project_option.h"
#include "core/project/project_search.h"
#include "fuzz.h"

/* Bounds that keep one input well under a second: an option is
 * evaluated only on a small building cut into few panels, and the
 * classes are checked on a sample of the modules, not all of them. */
enum {
    EVALUATE_TRIANGLES = 4096,
    EVALUATE_CELLS = 256,
    SAMPLE_SIDE = 8
};

static void check_message(const struct facet_error *err)
{
    if (err->message[0] == '\0' || strchr(err->message, '\n') != NULL) {
        fprintf(stderr, "fuzz_project: not one line: '%s'\n", err->message);
        abort();
    }
}

static int same_bits(double a, double b)
{
    return memcmp(&a, &b, sizeof a) == 0;
}

/* The index along a range of count values of the s-th of SAMPLE_SIDE
 * samples: both ends and points between. */
static size_t sample(size_t s, size_t count)
{
    return count <= SAMPLE_SIDE ? s : s * (count - 1) / (SAMPLE_SIDE - 1);
}

/* Modules of one class give every surface the same grid: point (k, j)
 * against its class's first module. */
static void check_classes(const struct project_search *search)
{
    size_t n = search->project->nsurfaces;
    struct surface_grid *a = malloc(n * sizeof *a);
    struct surface_grid *b = malloc(n * sizeof *b);
    if (a == NULL || b == NULL)
        abort();
    size_t sw = search->widths < SAMPLE_SIDE ? search->widths : SAMPLE_SIDE;
    size_t sh = search->heights < SAMPLE_SIDE ? search->heights
                                              : SAMPLE_SIDE;
    const struct module_range *r = &search->range;
    for (size_t x = 0; x < sw; x++)
        for (size_t y = 0; y < sh; y++) {
            size_t k = sample(x, search->widths);
            size_t j = sample(y, search->heights);
            struct design_point p = {(int)k + 1, (int)j + 1, 0};
            struct design_point q = p;
            search->evaluator.canonical(search->evaluator.context, &q);
            double w, h;
            project_search_module(search, &p, &w, &h);
            /* Rounded to the nanometre: within 1e-9 of the range. */
            if (!isfinite(w) || !isfinite(h) || !(w > 0) || !(h > 0) ||
                w < r->width_min - 1e-9 || w > r->width_max + 1e-9 ||
                h < r->height_min - 1e-9 || h > r->height_max + 1e-9) {
                fprintf(stderr, "fuzz_project: module %.17g x %.17g outside "
                        "%.17g:%.17g x %.17g:%.17g\n", w, h, r->width_min,
                        r->width_max, r->height_min, r->height_max);
                abort();
            }
            project_search_grids(search, &p, a);
            project_search_grids(search, &q, b);
            if (!surface_grids_equal(a, b, n) ||
                surface_grids_hash(a, n) != surface_grids_hash(b, n) ||
                project_search_modules(search, &p) !=
                    project_search_modules(search, &q) ||
                project_search_modules(search, &p) < 1)
                abort();
            for (size_t i = 0; i < n; i++)
                if (a[i].nu < 1 || a[i].nv < 1 ||
                    a[i].nu > MODULE_MAX_COUNT || a[i].nv > MODULE_MAX_COUNT)
                    abort();
        }
    free(a);
    free(b);
}

/* The first module's option over the building, when it is small; a
 * building of one surface against that surface alone. */
static void evaluate(const struct project *project,
                     const struct project_search *search)
{
    size_t n = project->nsurfaces;
    struct surface_grid *grids = malloc(n * sizeof *grids);
    if (grids == NULL)
        abort();
    struct design_point first = {1, 1, 0};
    project_search_grids(search, &first, grids);
    if (project->ntriangles > EVALUATE_TRIANGLES ||
        surface_grids_cells(grids, n) > EVALUATE_CELLS) {
        free(grids);
        return;
    }
    struct option_params base, params;
    option_params_defaults(&base);
    params = option_params_at(&base, grids[0].nu, grids[0].nv, 3.0);
    struct project_option option;
    struct facet_error err;
    int rc = project_option_evaluate(project, grids, &params, 1, &option,
                                     &err);
    if (rc != FACET_OK) {
        check_message(&err);
    } else {
        size_t panels = 0, moulds = 0;
        for (size_t i = 0; i < n; i++) {
            panels += option.surfaces[i].totals.panels;
            moulds += option.surfaces[i].totals.moulds;
        }
        if (panels != option.totals.panels ||
            moulds != option.totals.moulds ||
            option.totals.panels > surface_grids_cells(grids, n) ||
            !isfinite(option.totals.cost) ||
            !isfinite(option.totals.planarity))
            abort();
    }
    if (rc == FACET_OK && n == 1) {
        struct panelization panels;
        struct option_totals alone;
        if (option_evaluate(&project->surfaces[0].surface, &params, NULL, &panels,
                            &alone, &err) != FACET_OK)
            abort();
        const struct option_totals *t = &option.totals;
        if (alone.panels != t->panels || alone.moulds != t->moulds ||
            !same_bits(alone.cost, t->cost) ||
            !same_bits(alone.area, t->area) ||
            !same_bits(alone.planarity, t->planarity) ||
            !same_bits(alone.joint_length, t->joint_length) ||
            !same_bits(alone.max_gap, t->max_gap)) {
            fprintf(stderr, "fuzz_project: one surface: cost %.17g alone, "
                    "%.17g as a project\n", alone.cost, t->cost);
            abort();
        }
        panelization_free(&panels);
    }
    project_option_free(&option);
    free(grids);
}

/* The surfaces of a project read: unique names, their sums the
 * building's, their lengths finite. */
static void check_project(const struct project *project)
{
    if (project->nsurfaces == 0)
        abort();
    size_t triangles = 0;
    for (size_t i = 0; i < project->nsurfaces; i++) {
        const struct project_surface *s = &project->surfaces[i];
        triangles += s->surface.mesh.ntriangles;
        if (s->name == NULL || project_find(project, s->name) != s)
            abort();
        if (!isfinite(s->u_length) || !isfinite(s->v_length) ||
            s->u_length < 0 || s->v_length < 0)
            abort();
    }
    if (triangles != project->ntriangles)
        abort();
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const uint8_t *newline = memchr(data, '\n', size);
    size_t spec_length = newline ? (size_t)(newline - data) : size;
    size_t rest = newline ? spec_length + 1 : size;
    char *spec = malloc(spec_length + 1);
    if (spec == NULL)
        return 0;
    memcpy(spec, data, spec_length);
    spec[spec_length] = '\0';

    /* A module text the CLI refuses still lets the file be read, with a
     * module of its own: the OBJ is the larger part of the input. */
    struct module_range range = {1.0, 2.0, 0.5, 1.0, 2.0, 0.5};
    struct facet_error err;
    if (module_parse(spec, "--module", &range, &err) != FACET_OK)
        check_message(&err);
    free(spec);

    /* A regular file without touching the disk, as fuzz_surface.c; its
     * path is read again to name the line of an error. */
    int fd = memfd_create("project.obj", MFD_CLOEXEC);
    if (fd < 0)
        return 0;
    if (write(fd, data + rest, size - rest) != (ssize_t)(size - rest)) {
        close(fd);
        return 0;
    }
    char path[64];
    snprintf(path, sizeof path, "/proc/self/fd/%d", fd);
    const char *paths[1] = {path};
    struct project project;
    int rc = project_open(paths, 1, UNITS_M, &project, &err);
    if (rc == FACET_OK)
        rc = project_prepare(&project, 0, PARAM_AUTO, &err);
    if (rc == FACET_OK)
        check_project(&project);
    struct project_search search;
    if (rc == FACET_OK) {
        rc = project_search_init(&search, &project, &range, NULL, &err);
        if (rc == FACET_OK) {
            check_classes(&search);
            evaluate(&project, &search);
        }
        project_search_free(&search);
    }
    if (rc != FACET_OK)
        check_message(&err);
    project_close(&project);
    close(fd);
    return 0;
}
