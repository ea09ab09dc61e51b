/*
 * surface_fixture.c: prepared surfaces for tests. See surface_fixture.h.
 */
#include "tests/support/surface_fixture.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "core/surface/example.h"

int surface_fixture_data(const char *name, char *path, size_t size)
{
    const char *data = getenv("FACET_DATA");
    snprintf(path, size, "%s/%s", data != NULL ? data : "../shared/data",
             name);
    if (access(path, R_OK) == 0)
        return 1;
    printf("skipped: %s is absent (the real surfaces of ../shared/data; "
           "set FACET_DATA)\n", path);
    return 0;
}

int surface_fixture_open(const char *path, struct surface *s,
                         struct facet_error *err)
{
    struct mesh_options options = {UNITS_M, NULL, NULL};
    int rc = surface_open(path, &options, s, err);
    if (rc == FACET_OK)
        rc = surface_prepare(s, 0, PARAM_AUTO, err);
    return rc;
}

int surface_fixture_example(const char *name, int res, struct surface *s,
                            struct facet_error *err)
{
    char path[] = "/tmp/facet_test_surface_XXXXXX";
    int fd = mkstemp(path);
    if (fd < 0)
        return facet_error_set(err, FACET_EWORK, "no temporary file");
    FILE *out = fdopen(fd, "w");
    if (out == NULL) {
        close(fd);
        unlink(path);
        return facet_error_set(err, FACET_EWORK, "no temporary file");
    }
    int rc = example_write(name, res, out, err);
    if (fclose(out) != 0 && rc == FACET_OK)
        rc = facet_error_set(err, FACET_EWORK, "writing %s", path);
    if (rc == FACET_OK)
        rc = surface_fixture_open(path, s, err);
    unlink(path);
    return rc;
}

char *surface_fixture_formula_write(surface_formula f, const void *shape,
                                    int ns, int nt, enum formula_faces faces)
{
    char *path = strdup("/tmp/facet_test_formula_XXXXXX");
    if (path == NULL)
        return NULL;
    int fd = mkstemp(path);
    FILE *out = fd >= 0 ? fdopen(fd, "w") : NULL;
    if (out == NULL) {
        if (fd >= 0) {
            close(fd);
            unlink(path);
        }
        free(path);
        return NULL;
    }
    for (int j = 0; j <= nt; j++)
        for (int i = 0; i <= ns; i++) {
            double p[3];
            f(shape, (double)i / ns, (double)j / nt, p);
            fprintf(out, "v %.17g %.17g %.17g\nvt %.17g %.17g\n", p[0], p[1],
                    p[2], (double)i / ns, (double)j / nt);
        }
    for (int j = 0; j < nt; j++)
        for (int i = 0; i < ns; i++) {
            int a = j * (ns + 1) + i + 1, b = a + 1, c = b + ns + 1,
                d = a + ns + 1;
            if (faces == FORMULA_QUADS)
                fprintf(out, "f %d/%d %d/%d %d/%d %d/%d\n", a, a, b, b, c, c,
                        d, d);
            else
                fprintf(out, "f %d/%d %d/%d %d/%d\nf %d/%d %d/%d %d/%d\n",
                        a, a, b, b, c, c, a, a, c, c, d, d);
        }
    if (fclose(out) != 0) {
        unlink(path);
        free(path);
        return NULL;
    }
    return path;
}

int surface_fixture_formula(surface_formula f, const void *shape, int ns,
                            int nt, enum formula_faces faces,
                            struct surface *s, struct facet_error *err)
{
    char *path = surface_fixture_formula_write(f, shape, ns, nt, faces);
    if (path == NULL)
        return facet_error_set(err, FACET_EWORK, "no temporary file");
    int rc = surface_fixture_open(path, s, err);
    unlink(path);
    free(path);
    return rc;
}
