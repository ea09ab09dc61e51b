/*
 * fuzz_surface.c: any bytes as a surface file, through everything a
 * `facet classify` does: load, UV (whichever applies), curvature, two
 * grids of panels, classification. Areas must add up and every number
 * stay finite.
 */
#define _GNU_SOURCE  /* memfd_create */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <sys/mman.h>
#include <unistd.h>

#include "core/evaluate/evaluate.h"
#include "core/surface/surface.h"
#include "fuzz.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    /* A regular file without touching the disk: Facet reads surfaces from
     * regular files only. */
    int fd = memfd_create("fuzz.obj", MFD_CLOEXEC);
    if (fd < 0)
        return 0;
    if (write(fd, data, size) != (ssize_t)size) {
        close(fd);
        return 0;
    }
    char path[64];
    snprintf(path, sizeof path, "/proc/self/fd/%d", fd);
    struct surface surface;
    struct facet_error err;
    struct mesh_options options = {UNITS_M, NULL, NULL};
    int rc = surface_open(path, &options, &surface, &err);
    if (rc == FACET_OK)
        rc = surface_prepare(&surface, 0, PARAM_AUTO, &err);
    static const int grid[2][2] = {{3, 3}, {7, 5}};
    for (int g = 0; rc == FACET_OK && g < 2; g++) {
        struct option_params params = {0};
        params.nu = grid[g][0];
        params.nv = grid[g][1];
        params.mode = g ? PANEL_MEAN : PANEL_EXTREMES;
        classify_defaults(&params.classify);
        struct panelization panels;
        struct option_totals totals;
        if (option_evaluate(&surface, &params, NULL, &panels, &totals, &err) ==
            FACET_OK) {
            if (!isfinite(totals.cost) || !isfinite(totals.planarity))
                abort();
            /* Panels cover the surface: their areas add up to its area,
             * to 1e-6 of it (trimming by UV drops nothing). */
            double area = surface.mesh.area;
            if (isfinite(area) && area > 0 && area < 1e12 &&
                fabs(totals.area - area) > 1e-6 * area + 1e-12 &&
                surface.param.report.degenerate == 0)
                abort();
        }
        panelization_free(&panels);
    }
    surface_close(&surface);
    close(fd);
    return 0;
}
