/*
 * project_search.c: a building's design space for the search, and the
 * evaluator of its options. See project_search.h.
 */
#include "core/project/project_search.h"

#include <assert.h>
#include <stdlib.h>
#include <string.h>

#include "core/panel/panel.h"

/* The value index (0-based) of a range of count values, whose grids
 * grids_of gives, into first[] and size[]: classes of equal grid
 * vectors, told apart by hash then by the vectors. */
static int classes_of(const struct project_search *search, size_t count,
                      int along_width, size_t *first, size_t *size,
                      struct facet_error *err)
{
    size_t n = search->project->nsurfaces;
    struct surface_grid *grids = malloc((count ? count : 1) * (n ? n : 1) *
                                        sizeof *grids);
    uint64_t *hash = malloc((count ? count : 1) * sizeof *hash);
    if (grids == NULL || hash == NULL) {
        free(grids);
        free(hash);
        return facet_error_set(err, FACET_EWORK, "out of memory");
    }
    for (size_t k = 0; k < count; k++) {
        struct design_point p = {along_width ? (int)k + 1 : 1,
                                 along_width ? 1 : (int)k + 1, 0};
        project_search_grids(search, &p, grids + k * n);
        hash[k] = surface_grids_hash(grids + k * n, n);
        first[k] = k;
        size[k] = 0;
        /* Ranges are short (at most PANEL_MAX_GRID values): the earlier
         * values are looked through. */
        for (size_t j = 0; j < k; j++)
            if (first[j] == j && hash[j] == hash[k] &&
                surface_grids_equal(grids + j * n, grids + k * n, n)) {
                first[k] = j;
                break;
            }
        size[first[k]]++;
    }
    for (size_t k = 0; k < count; k++)
        size[k] = size[first[k]];
    free(grids);
    free(hash);
    return FACET_OK;
}

static void canonical(void *context, struct design_point *point)
{
    const struct project_search *search = context;
    assert(point->nu >= 1 && (size_t)point->nu <= search->widths);
    assert(point->nv >= 1 && (size_t)point->nv <= search->heights);
    point->nu = (int)search->width_first[point->nu - 1] + 1;
    point->nv = (int)search->height_first[point->nv - 1] + 1;
}

static int evaluate(void *context, const struct option_params *base,
                    const struct design_point *points, size_t n, int jobs,
                    const struct facet_stop *stop,
                    struct option_totals *totals, struct facet_error *err)
{
    struct project_search *search = context;
    size_t ns = search->project->nsurfaces;
    if (n * ns > search->capacity) {
        struct project_surface_row *grown =
            realloc(search->rows, n * ns * sizeof *grown);
        if (grown == NULL)
            return facet_error_set(err, FACET_EWORK, "out of memory");
        search->rows = grown;
        search->capacity = n * ns;
    }
    search->nlast = 0;
    struct surface_grid *grids = malloc((ns ? ns : 1) * sizeof *grids);
    if (grids == NULL)
        return facet_error_set(err, FACET_EWORK, "out of memory");
    int rc = FACET_OK;
    /* One option at a time, its surfaces on the threads
     * (project_option.h): the numbers do not depend on jobs. */
    for (size_t k = 0; rc == FACET_OK && k < n; k++) {
        if ((rc = facet_stop_check(stop, err)) != FACET_OK)
            break;
        project_search_grids(search, &points[k], grids);
        struct option_params params = option_params_at(
            base, grids[0].nu, grids[0].nv, points[k].threshold_mm);
        struct project_option option;
        rc = project_option_evaluate_stoppable(search->project, grids,
                                               &params, jobs, stop, &option,
                                               err);
        if (rc == FACET_OK) {
            totals[k] = option.totals;
            for (size_t i = 0; i < ns; i++) {
                const struct project_surface_option *s = &option.surfaces[i];
                search->rows[k * ns + i] = (struct project_surface_row){
                    s->grid, s->totals, s->moulds_used, s->joints};
            }
        }
        project_option_free(&option);
    }
    free(grids);
    if (rc == FACET_OK)
        search->nlast = n;
    return rc;
}

int project_search_init(struct project_search *search,
                        const struct project *project,
                        const struct module_range *range,
                        const struct surface_grid *overrides,
                        struct facet_error *err)
{
    memset(search, 0, sizeof *search);
    search->project = project;
    search->range = *range;
    search->widths = module_widths(range);
    search->heights = module_heights(range);
    if (search->widths > PANEL_MAX_GRID || search->heights > PANEL_MAX_GRID)
        return facet_error_set(err, FACET_EINPUT,
            "the module range holds %zu widths and %zu heights: at most %d "
            "each (take a larger step)", search->widths, search->heights,
            PANEL_MAX_GRID);
    size_t n = project->nsurfaces;
    search->overrides = calloc(n ? n : 1, sizeof *search->overrides);
    search->width_first = malloc(search->widths * sizeof(size_t));
    search->width_size = malloc(search->widths * sizeof(size_t));
    search->height_first = malloc(search->heights * sizeof(size_t));
    search->height_size = malloc(search->heights * sizeof(size_t));
    if (search->overrides == NULL || search->width_first == NULL ||
        search->width_size == NULL || search->height_first == NULL ||
        search->height_size == NULL)
        return facet_error_set(err, FACET_EWORK, "out of memory");
    if (overrides != NULL)
        memcpy(search->overrides, overrides, n * sizeof *overrides);
    int rc = classes_of(search, search->widths, 1, search->width_first,
                        search->width_size, err);
    if (rc == FACET_OK)
        rc = classes_of(search, search->heights, 0, search->height_first,
                        search->height_size, err);
    search->evaluator =
        (struct option_evaluator){search, canonical, evaluate};
    return rc;
}

void project_search_free(struct project_search *search)
{
    free(search->overrides);
    free(search->width_first);
    free(search->width_size);
    free(search->height_first);
    free(search->height_size);
    free(search->rows);
    memset(search, 0, sizeof *search);
}

void project_search_module(const struct project_search *search,
                           const struct design_point *point, double *w,
                           double *h)
{
    assert(point->nu >= 1 && (size_t)point->nu <= search->widths);
    assert(point->nv >= 1 && (size_t)point->nv <= search->heights);
    module_at(&search->range,
              (size_t)(point->nu - 1) * search->heights +
                  (size_t)(point->nv - 1), w, h);
}

void project_search_grids(const struct project_search *search,
                          const struct design_point *point,
                          struct surface_grid *grids)
{
    double w, h;
    project_search_module(search, point, &w, &h);
    project_module_grids(search->project, w, h, grids);
    for (size_t i = 0; i < search->project->nsurfaces; i++)
        if (search->overrides[i].nu > 0)
            grids[i] = search->overrides[i];
}

size_t project_search_modules(const struct project_search *search,
                              const struct design_point *point)
{
    return search->width_size[point->nu - 1] *
           search->height_size[point->nv - 1];
}

const struct project_surface_row *
project_search_rows(const struct project_search *search, size_t k)
{
    assert(k < search->nlast);
    return search->rows + k * search->project->nsurfaces;
}
