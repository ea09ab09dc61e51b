/*
 * project_grids.c: an option's grid per surface. See project_grids.h.
 */
#include "core/project/project_grids.h"

#include <stdio.h>
#include <string.h>

#include "core/base/numrange.h"
#include "core/panel/panel.h"
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

int surface_grid_overrides_parse(const char *text, const char *what,
                                 struct surface_grid_overrides *out,
                                 struct facet_error *err)
{
    out->n = 0;
    if (strlen(text) >= sizeof out->text)
        return facet_error_set(err, FACET_EINPUT, "%s: too long", what);
    snprintf(out->text, sizeof out->text, "%s", text);
    if (out->text[0] == '\0')
        return FACET_OK;
    for (char *item = out->text; item != NULL;) {
        char *next = strchr(item, ',');
        if (next != NULL)
            *next++ = '\0';
        char *equals = strrchr(item, '=');
        if (equals == NULL || equals == item ||
            out->n == SURFACE_GRID_OVERRIDES_MAX)
            return facet_error_set(err, FACET_EINPUT,
                "%s: '%s' is not NAME=NUxNV (e.g. roof_3=12x40)", what,
                item);
        *equals = '\0';
        char named[200];
        snprintf(named, sizeof named, "%.40s %.140s", what, item);
        int nu, nv, rc = numrange_grid(equals + 1, PANEL_MAX_GRID, named,
                                       &nu, &nv, err);
        if (rc != FACET_OK)
            return rc;
        out->name[out->n] = item;
        out->grid[out->n++] = (struct surface_grid){nu, nv};
        item = next;
    }
    return FACET_OK;
}

void surface_grid_overrides_copy(struct surface_grid_overrides *to,
                                 const struct surface_grid_overrides *from)
{
    memcpy(to->text, from->text, sizeof to->text);
    to->n = from->n;
    for (size_t k = 0; k < from->n; k++) {
        to->name[k] = to->text + (from->name[k] - from->text);
        to->grid[k] = from->grid[k];
    }
}
