/*
 * mould_sample.c: a panel's lattice of surface points. See mould_sample.h.
 */
#include "core/mould/mould_sample.h"

#include <stdint.h>
#include <string.h>

int mould_sample_panel(const struct mesh *mesh, const struct uv_index *index,
                       const struct panelization *panels, size_t n,
                       double out[MOULD_SAMPLES][3])
{
    const struct panel *panel = &panels->panels[n];
    if (panel->trimmed || panel->ncorners < 4)
        return 0;
    const int last = MOULD_SIDE - 1;
    double du = (panels->umax - panels->umin) / panels->nu;
    double dv = (panels->vmax - panels->vmin) / panels->nv;
    for (int b = 0; b <= last; b++)
        for (int a = 0; a <= last; a++) {
            double *x = out[mould_sample_index(a, b)];
            /* The corners as panels_build located them: (0,0), (1,0),
             * (1,1), (0,1) of the cell. */
            if ((a == 0 || a == last) && (b == 0 || b == last)) {
                int c = b == 0 ? (a == 0 ? 0 : 1) : (a == 0 ? 3 : 2);
                memcpy(x, panel->corner[c], sizeof panel->corner[c]);
                continue;
            }
            double u = panels->umin + (panel->i + (double)a / last) * du;
            double v = panels->vmin + (panel->j + (double)b / last) * dv;
            double w[3];
            /* The corners' widening (panel.c), for points on the UV box's
             * edge that rounding puts a hair outside it. */
            uint32_t t = uv_index_locate(index, u, v, 1e-9, w);
            if (t == UINT32_MAX)
                return 0;
            struct panel_piece_vertex p = {u, v, {w[0], w[1], w[2]}};
            panel_piece_point(mesh, t, &p, x);
        }
    return 1;
}
