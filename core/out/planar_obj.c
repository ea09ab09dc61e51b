/*
 * planar_obj.c: a planarized grid as OBJ quads (planar_obj.h).
 */
#include "planar_obj.h"

#include <math.h>
#include <stdlib.h>

#include "core/base/units.h"

int planar_obj_write(FILE *out, const char *source,
                     const struct planarize_options *o,
                     const struct planarize_result *r,
                     struct facet_error *err)
{
    const struct quad_grid *g = &r->grid;
    size_t nodes = (size_t)(g->nu + 1) * (g->nv + 1);
    /* OBJ numbers the corners written, from 1. */
    size_t *number = calloc(nodes, sizeof *number);
    if (number == NULL)
        return facet_error_set(err, FACET_EWORK, "out of memory");
    fprintf(out, "# facet planarize: %s quads of %s, %d x %d grid\n",
            r->feasible ? "planar" : "INFEASIBLE, not planar within the "
            "budget:", source, g->nu, g->nv);
    fprintf(out, "# closeness budget %.6g mm, reached %.6g mm (mean %.6g mm)\n",
            units_mm(o->closeness), units_mm(r->max_distance),
            units_mm(r->mean_distance));
    fprintf(out, "# planarity tolerance %.6g of the diagonal, reached %.6g; "
            "%zu of %zu quads over it\n", o->planarity, r->max_relative,
            r->over, r->nquads);
    size_t written = 0;
    for (size_t k = 0; k < nodes; k++) {
        const double *p = &g->node[3 * k];
        if (isnan(p[0]))
            continue;
        number[k] = ++written;
        fprintf(out, "v %.17g %.17g %.17g\n", p[0], p[1], p[2]);
    }
    for (int j = 0; j < g->nv; j++)
        for (int i = 0; i < g->nu; i++) {
            if (!g->quad[(size_t)j * g->nu + i])
                continue;
            size_t a = (size_t)j * (g->nu + 1) + i;
            size_t b = a + 1, c = b + g->nu + 1, d = a + g->nu + 1;
            fprintf(out, "g quad_%d_%d\nf %zu %zu %zu %zu\n", i, j, number[a],
                    number[b], number[c], number[d]);
        }
    free(number);
    return FACET_OK;
}
