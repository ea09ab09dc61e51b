/*
 * quad_grid.h: the corners of a UV panel grid, as a planarization starts
 * from them.
 *
 * Node (i, j), i = 0..nu along u and j = 0..nv along v, is the corner
 * shared by the cells around it, where the panels placed it on the
 * surface (panel.h's corner: the UV grid point mapped by the mesh
 * triangle that holds it), so a planarization starts from the very
 * corners facet classify measures. A node off the surface (a trimmed
 * edge) is NaN. Quad (i, j) has the corners (i, j), (i + 1, j),
 * (i + 1, j + 1), (i, j + 1), in panel.h's order; it is one to planarize
 * when all four lie on the surface.
 */
#ifndef FACET_QUAD_GRID_H
#define FACET_QUAD_GRID_H

#include <stddef.h>

#include "core/base/error.h"
#include "core/panel/panel.h"

struct quad_grid {
    int nu, nv;
    double *node;          /* (nu + 1)(nv + 1) x 3 at [j (nu + 1) + i] (m),
                              NaN off the surface */
    unsigned char *quad;   /* nu nv at [j nu + i]: 1 when all four corners
                              are on the surface */
    size_t nquads;         /* quads with quad[] set */
};

/* The node of (i, j) in g. */
static inline double *quad_grid_node(const struct quad_grid *g, int i, int j)
{
    return &g->node[3 * ((size_t)j * (g->nu + 1) + i)];
}

/* The grid of panels' corners into *out (caller-owned, released with
 * quad_grid_free, also after a failure). Returns FACET_OK, FACET_EINPUT
 * when no quad has its four corners on the surface, FACET_EWORK when out
 * of memory. */
int quad_grid_from_panels(const struct panelization *panels,
                          struct quad_grid *out, struct facet_error *err);

/* The four corners of quad (i, j) of g into c. */
void quad_grid_corners(const struct quad_grid *g, int i, int j,
                       double c[4][3]);

void quad_grid_free(struct quad_grid *g);

#endif
