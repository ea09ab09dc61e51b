/*
 * quad_grid.c: a panel grid's corners as nodes (quad_grid.h).
 */
#include "quad_grid.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static const int corner_offset[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};

int quad_grid_from_panels(const struct panelization *panels,
                          struct quad_grid *out, struct facet_error *err)
{
    memset(out, 0, sizeof *out);
    out->nu = panels->nu;
    out->nv = panels->nv;
    size_t nodes = (size_t)(out->nu + 1) * (out->nv + 1);
    out->node = malloc(3 * nodes * sizeof *out->node);
    out->quad = calloc((size_t)out->nu * out->nv, 1);
    if (out->node == NULL || out->quad == NULL)
        return facet_error_set(err, FACET_EWORK, "out of memory");
    for (size_t k = 0; k < 3 * nodes; k++)
        out->node[k] = NAN;
    for (size_t p = 0; p < panels->npanels; p++) {
        const struct panel *panel = &panels->panels[p];
        for (int c = 0; c < 4; c++)
            if (!isnan(panel->corner[c][0]))
                memcpy(quad_grid_node(out, panel->i + corner_offset[c][0],
                                      panel->j + corner_offset[c][1]),
                       panel->corner[c], sizeof panel->corner[c]);
        if (panel->ncorners == 4) {
            out->quad[(size_t)panel->j * out->nu + panel->i] = 1;
            out->nquads++;
        }
    }
    if (out->nquads == 0)
        return facet_error_set(err, FACET_EINPUT,
            "no panel of the %d x %d grid has its four corners on the "
            "surface: there is no quad to planarize", out->nu, out->nv);
    return FACET_OK;
}

void quad_grid_corners(const struct quad_grid *g, int i, int j,
                       double c[4][3])
{
    for (int k = 0; k < 4; k++)
        memcpy(c[k], quad_grid_node(g, i + corner_offset[k][0],
                                    j + corner_offset[k][1]),
               sizeof c[k]);
}

void quad_grid_free(struct quad_grid *g)
{
    free(g->node);
    free(g->quad);
    g->node = NULL;
    g->quad = NULL;
}
