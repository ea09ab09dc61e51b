/*
 * project_grids.h: the grids of an option over a project, one per surface.
 *
 * An option over a project gives each surface its own grid nu x nv, in
 * surface order: from the building's module w x h (module_grid on each
 * surface's u and v lengths, module.h), or given one by one (a single
 * surface's nu x nv as the paper's; per-surface overrides replace a
 * surface's entry). The evaluation depends on the module only through
 * this vector, so two modules that give every surface the same grid are
 * one option: a search dedupes on the vector (its hash, then the vectors
 * themselves) and evaluates and stores each building once.
 *
 * The hash is FNV-1a (64 bits: offset basis 0xcbf29ce484222325, prime
 * 0x100000001b3) over the count of surfaces as 8 bytes, then each nu and
 * nv in turn as 4 bytes, all little-endian two's complement: the same
 * number on every machine and in every run, so that it may be stored.
 */
#ifndef FACET_PROJECT_GRIDS_H
#define FACET_PROJECT_GRIDS_H

#include <stddef.h>
#include <stdint.h>

#include "core/base/error.h"
#include "core/project/project.h"

struct surface_grid {
    int nu, nv;  /* panels along u and along v */
};

/* Surfaces of a project given a grid of their own whatever the module,
 * by name, as a user writes them: "roof_3=12x40,canopy=8x8" (a name may
 * hold '=', the last one parts it from the grid). The names point into
 * text, the struct's own copy of what was parsed: copy the struct with
 * surface_grid_overrides_copy, never by assignment. */
#define SURFACE_GRID_OVERRIDES_MAX 256
struct surface_grid_overrides {
    char text[4096];
    char *name[SURFACE_GRID_OVERRIDES_MAX];
    struct surface_grid grid[SURFACE_GRID_OVERRIDES_MAX];
    size_t n;
};

/* Parses text (above) into *out; "" gives none. Each grid is
 * numrange_grid's NUxNV, at most PANEL_MAX_GRID a side. FACET_EINPUT
 * names what (the caller's word for the setting) and the item. */
int surface_grid_overrides_parse(const char *text, const char *what,
                                 struct surface_grid_overrides *out,
                                 struct facet_error *err);

/* *to as a copy of *from, its names pointing into to's text. */
void surface_grid_overrides_copy(struct surface_grid_overrides *to,
                                 const struct surface_grid_overrides *from);

/* The grid of every surface of project (prepared: its u and v lengths)
 * for the module w x h (m, positive) into grids[0 .. nsurfaces). */
void project_module_grids(const struct project *project, double w, double h,
                          struct surface_grid *grids);

/* The hash of grids[0 .. n), as above. */
uint64_t surface_grids_hash(const struct surface_grid *grids, size_t n);

/* 1 when a and b (n each) give every surface the same grid. */
int surface_grids_equal(const struct surface_grid *a,
                        const struct surface_grid *b, size_t n);

/* The panels the grids cut at most: the sum of nu x nv (a cell the
 * surface does not reach is no panel, so the panels are at most this). */
size_t surface_grids_cells(const struct surface_grid *grids, size_t n);

#endif
