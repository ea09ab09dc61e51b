/*
 * project_search.h: searching a building's design space with the search
 * of a single surface (core/search/optimize.h).
 *
 * A project's design point is a module w x h and a flatness threshold.
 * The search walks integer points, so a point's nu and nv carry the
 * module's width and height indices, 1-based, in the run's module range
 * (module.h: width index i is width_min + (i - 1) x width_step); the
 * design space the search is given is u 1..widths, v 1..heights, and the
 * run's threshold range. Each module maps to one
 * grid per surface (project_module_grids), and the evaluator evaluates a
 * point with project_option_evaluate: the building's totals go to the
 * search, which ranks and stores them as a single surface's.
 *
 * One option per grid vector: nu of every surface depends on w alone and
 * nv on h alone (module_grid), so two modules give every surface the same
 * grid exactly when their widths give the same nu on every surface and
 * their heights the same nv. The evaluator's canonical point is therefore
 * the first width of its width's class and the first height of its
 * height's class (the classes told apart by surface_grids_hash, then
 * surface_grids_equal, on the grids of each width at the first height and
 * each height at the first width): the module of that grid vector with the
 * lowest index, which an exhaustive search meets first, whatever order
 * another method meets them in. Every option is evaluated and stored once,
 * as its first module, and project_search_modules says how many modules
 * of the range it stands for.
 *
 * Per-surface overrides (a surface given its own nu x nv, whatever the
 * module) replace that surface's entry in every vector; the classes are
 * then taken over the vectors with the override.
 *
 * Ownership: project_search_init fills a caller-owned struct that borrows
 * project (prepared; it must outlive the search); project_search_free
 * releases what it holds.
 */
#ifndef FACET_PROJECT_SEARCH_H
#define FACET_PROJECT_SEARCH_H

#include <stddef.h>

#include "core/base/error.h"
#include "core/project/module.h"
#include "core/project/project.h"
#include "core/project/project_grids.h"
#include "core/project/project_option.h"
#include "core/search/optimize.h"

/* One surface's part of an evaluated option, as the store keeps it. */
struct project_surface_row {
    struct surface_grid grid;
    struct option_totals totals;  /* as project_surface_option's */
    size_t moulds_used;
    size_t joints;
};

struct project_search {
    const struct project *project;
    struct module_range range;
    size_t widths, heights;
    struct surface_grid *overrides;  /* nsurfaces; nu 0: none */
    size_t *width_first;   /* widths: the first width index of its class */
    size_t *width_size;    /* widths: how many widths its class holds */
    size_t *height_first;  /* heights, likewise */
    size_t *height_size;
    /* The last evaluate call's options, nlast of them, each nsurfaces
     * rows in surface order: rows[k * nsurfaces + i]. */
    struct project_surface_row *rows;
    size_t nlast, capacity;
    struct option_evaluator evaluator;  /* what optimize_run_with takes */
};

/* Sets up *search over project (prepared) for the modules of range, with
 * overrides[i] (NULL: none; nu 0: none for surface i) replacing surface
 * i's grid. FACET_EINPUT when a range holds more than PANEL_MAX_GRID
 * values (the search walks them as grid sides), FACET_EWORK when out of
 * memory. Release with project_search_free, also after a failure. */
int project_search_init(struct project_search *search,
                        const struct project *project,
                        const struct module_range *range,
                        const struct surface_grid *overrides,
                        struct facet_error *err);
void project_search_free(struct project_search *search);

/* The module (m) of point (its nu, nv the width and height indices). */
void project_search_module(const struct project_search *search,
                           const struct design_point *point, double *w,
                           double *h);

/* The grid of every surface for point into grids[0 .. nsurfaces). */
void project_search_grids(const struct project_search *search,
                          const struct design_point *point,
                          struct surface_grid *grids);

/* How many modules of the range give point's grid vector (point
 * canonical or not). */
size_t project_search_modules(const struct project_search *search,
                              const struct design_point *point);

/* The rows of option k (0-based) of the last evaluate call: nsurfaces of
 * them, valid until the next call. */
const struct project_surface_row *
project_search_rows(const struct project_search *search, size_t k);

#endif
