/*
 * project_grids.c: an option's grid per surface. See project_grids.h.
 */
#include "core/project/project_grids.h"

#include "core/project/module.h"

void project_module_grids(const struct project *project, double w, double h,
                          struct surface_grid *grids)
{
    for (size_t i = 0; i < project->nsurfaces; i++) {
        const struct project_surface *s = &project->surfaces[i];
        module_grid(s->u_length, s->v_length, w, h, &grids[i].nu,
                    &grids[i].nv);
    }
}

/* FNV-1a over the nbytes low bytes of value, lowest first. */
static uint64_t hash_bytes(uint64_t hash, uint64_t value, int nbytes)
{
    for (int b = 0; b < nbytes; b++) {
        hash ^= (value >> (8 * b)) & 0xff;
        hash *= 0x100000001b3u;
    }
    return hash;
}

uint64_t surface_grids_hash(const struct surface_grid *grids, size_t n)
{
    uint64_t hash = hash_bytes(0xcbf29ce484222325u, (uint64_t)n, 8);
    for (size_t i = 0; i < n; i++) {
        hash = hash_bytes(hash, (uint32_t)grids[i].nu, 4);
        hash = hash_bytes(hash, (uint32_t)grids[i].nv, 4);
    }
    return hash;
}

int surface_grids_equal(const struct surface_grid *a,
                        const struct surface_grid *b, size_t n)
{
    for (size_t i = 0; i < n; i++)
        if (a[i].nu != b[i].nu || a[i].nv != b[i].nv)
            return 0;
    return 1;
}

size_t surface_grids_cells(const struct surface_grid *grids, size_t n)
{
    size_t cells = 0;
    for (size_t i = 0; i < n; i++)
        cells += (size_t)grids[i].nu * (size_t)grids[i].nv;
    return cells;
}
