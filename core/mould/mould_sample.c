/*
 * mould_sample.c: a panel's lattice of surface points. See mould_sample.h.
 */
#include "core/mould/mould_sample.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "core/base/error.h"

/* The corner of the cell that lattice point (a, b) is, 0..3 as
 * panel->corner, or -1. */
static int corner_at(int a, int b)
{
    const int last = MOULD_SIDE - 1;
    if ((a != 0 && a != last) || (b != 0 && b != last))
        return -1;
    return b == 0 ? (a == 0 ? 0 : 1) : (a == 0 ? 3 : 2);
}

/* The surface point at (u, v) into x, as panels_build finds a corner;
 * returns 0 when the surface does not reach it. */
static int surface_point(const struct mesh *mesh,
                         const struct uv_index *index, double u, double v,
                         double x[3])
{
    double w[3];
    /* The corners' widening (panel.c), for points on the UV box's edge
     * that rounding puts a hair outside it. */
    uint32_t t = uv_index_locate(index, u, v, 1e-9, w);
    if (t == UINT32_MAX)
        return 0;
    struct panel_piece_vertex p = {u, v, {w[0], w[1], w[2]}};
    panel_piece_point(mesh, t, &p, x);
    return 1;
}

/* Whether panel n is sampled at all: not trimmed, with its four corners. */
static int samplable(const struct panel *panel)
{
    return !panel->trimmed && panel->ncorners >= 4;
}

int mould_sample_panel(const struct mesh *mesh, const struct uv_index *index,
                       const struct panelization *panels, size_t n,
                       double out[MOULD_SAMPLES][3])
{
    const struct panel *panel = &panels->panels[n];
    if (!samplable(panel))
        return 0;
    const int last = MOULD_SIDE - 1;
    double du = (panels->umax - panels->umin) / panels->nu;
    double dv = (panels->vmax - panels->vmin) / panels->nv;
    for (int b = 0; b <= last; b++)
        for (int a = 0; a <= last; a++) {
            double *x = out[mould_sample_index(a, b)];
            /* The corners as panels_build located them. */
            int c = corner_at(a, b);
            if (c >= 0) {
                memcpy(x, panel->corner[c], sizeof panel->corner[c]);
                continue;
            }
            double u = panels->umin + (panel->i + (double)a / last) * du;
            double v = panels->vmin + (panel->j + (double)b / last) * dv;
            if (!surface_point(mesh, index, u, v, x))
                return 0;
        }
    return 1;
}

/* One band of lattice rows (a row of cells), MOULD_SIDE rows of width
 * points each. */
enum { UNKNOWN, ON, OFF };  /* a point: not located yet, on the surface,
                               off it */

struct band {
    double (*point[MOULD_SIDE])[3];
    unsigned char *state[MOULD_SIDE];
    unsigned char *need[MOULD_SIDE];
};

int mould_sample_grid(const struct mesh *mesh, const struct uv_index *index,
                      const struct panelization *panels,
                      const unsigned char *want,
                      double (*out)[MOULD_SAMPLES][3],
                      unsigned char *sampled,
                      const struct facet_stop *stop)
{
    const int last = MOULD_SIDE - 1;
    const int nu = panels->nu, nv = panels->nv;
    const size_t width = (size_t)last * (size_t)nu + 1;
    struct band band;
    int rc = FACET_OK;
    for (int b = 0; b < MOULD_SIDE; b++) {
        band.point[b] = malloc(width * sizeof *band.point[b]);
        band.state[b] = calloc(width, 1);
        band.need[b] = malloc(width);
        if (band.point[b] == NULL || band.state[b] == NULL ||
            band.need[b] == NULL)
            rc = FACET_EWORK;
    }
    double du = (panels->umax - panels->umin) / nu;
    double dv = (panels->vmax - panels->vmin) / nv;
    for (int j = 0; j < nv && rc == FACET_OK; j++) {
        if (facet_stop_requested(stop)) {
            rc = FACET_ESTOP;
            break;
        }
        if (j > 0) {
            /* The row of points between this band and the last is the
             * last's top row: keep it, and start the others afresh. */
            double (*keep)[3] = band.point[0];
            unsigned char *keep_state = band.state[0];
            band.point[0] = band.point[last];
            band.state[0] = band.state[last];
            band.point[last] = keep;
            band.state[last] = keep_state;
            for (int b = 1; b <= last; b++)
                memset(band.state[b], UNKNOWN, width);
        }
        for (int b = 0; b <= last; b++)
            memset(band.need[b], 0, width);
        for (int i = 0; i < nu; i++) {
            int n = panels->cell_panel[(size_t)j * nu + i];
            if (n < 0 || !want[n] || !samplable(&panels->panels[n]))
                continue;
            for (int b = 0; b <= last; b++)
                for (int a = 0; a <= last; a++)
                    if (corner_at(a, b) < 0)
                        band.need[b][(size_t)last * i + a] = 1;
        }
        /* Row by row along u: neighbouring points, neighbouring
         * triangles. A point is at the UV mould_sample_panel gives it
         * from either cell it borders: i + a / last is the same double
         * as (i + 1) + 0 / last when a = last. */
        for (int b = 0; b <= last; b++) {
            double v = panels->vmin + (j + (double)b / last) * dv;
            for (size_t c = 0; c < width; c++) {
                if (!band.need[b][c] || band.state[b][c] != UNKNOWN)
                    continue;
                double u = panels->umin +
                           ((int)(c / last) + (double)(c % last) / last) * du;
                band.state[b][c] = surface_point(mesh, index, u, v,
                                                 band.point[b][c])
                                   ? ON : OFF;
            }
        }
        for (int i = 0; i < nu; i++) {
            int n = panels->cell_panel[(size_t)j * nu + i];
            if (n < 0)
                continue;
            const struct panel *panel = &panels->panels[n];
            int on = want[n] && samplable(panel);
            for (int b = 0; b <= last && on; b++)
                for (int a = 0; a <= last && on; a++) {
                    double *x = out[n][mould_sample_index(a, b)];
                    int corner = corner_at(a, b);
                    size_t c = (size_t)last * i + a;
                    if (corner >= 0)
                        memcpy(x, panel->corner[corner],
                               sizeof panel->corner[corner]);
                    else if (band.state[b][c] == ON)
                        memcpy(x, band.point[b][c], sizeof band.point[b][c]);
                    else
                        on = 0;
                }
            sampled[n] = (unsigned char)on;
        }
    }
    for (int b = 0; b < MOULD_SIDE; b++) {
        free(band.point[b]);
        free(band.state[b]);
        free(band.need[b]);
    }
    return rc;
}
