/*
 * surface_fixture.c: prepared surfaces for tests. See surface_fixture.h.
 */
#include "tests/support/surface_fixture.h"

#include <stdio.h>
#include <stdlib.h>
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
