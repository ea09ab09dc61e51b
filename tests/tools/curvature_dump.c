/*
 * curvature_dump.c: every field curvature_at_vertices gives, to the bit,
 * for comparing two builds of the estimator (tests/e2e/curvature_bits.sh:
 * a change meant to be faster only must leave every bit as it was).
 *
 *   curvature_dump FILE [--flip-normals] [--jobs N]
 *
 * Output: "vertices N", then one line a vertex: k1 k2, dir1, dir2, normal,
 * surface_normal and k1_error k2_error, each double as C's %a (exact, and the same text for
 * the same bits). facet curvature --csv leaves out the directions, the
 * surface normal and the errors. Exits 0, or 2 with the error message on stderr.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/surface/curvature.h"
#include "core/surface/surface.h"

static void print3(const double *v)
{
    printf(" %a %a %a", v[0], v[1], v[2]);
}

int main(int argc, char **argv)
{
    const char *path = NULL;
    int flip = 0, jobs = 0;
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--flip-normals") == 0)
            flip = 1;
        else if (strcmp(argv[i], "--jobs") == 0 && i + 1 < argc)
            jobs = atoi(argv[++i]);
        else if (!path && argv[i][0] != '-')
            path = argv[i];
        else
            path = NULL, i = argc;
    }
    if (!path) {
        fprintf(stderr,
                "usage: curvature_dump FILE [--flip-normals] [--jobs N]\n");
        return 2;
    }
    struct mesh_options options = {UNITS_M, NULL, NULL};
    struct surface surface;
    struct curvature c;
    struct facet_error err;
    memset(&c, 0, sizeof c);
    int rc = surface_open(path, &options, &surface, &err);
    if (rc != FACET_OK) {
        fprintf(stderr, "curvature_dump: %s\n", err.message);
        return 2;
    }
    rc = jobs > 0 ? curvature_at_vertices_jobs(&surface.mesh, flip, jobs, &c,
                                               &err)
                  : curvature_at_vertices(&surface.mesh, flip, &c, &err);
    if (rc != FACET_OK) {
        fprintf(stderr, "curvature_dump: %s\n", err.message);
        curvature_free(&c);
        surface_close(&surface);
        return 2;
    }
    printf("vertices %zu\n", c.nvertices);
    for (size_t v = 0; v < c.nvertices; v++) {
        printf("%a %a", c.k1[v], c.k2[v]);
        print3(c.dir1 + 3 * v);
        print3(c.dir2 + 3 * v);
        print3(c.normal + 3 * v);
        print3(c.surface_normal + 3 * v);
        printf(" %a %a\n", c.k1_error[v], c.k2_error[v]);
    }
    curvature_free(&c);
    surface_close(&surface);
    return 0;
}
