/*
 * surface_fixture.h: a prepared surface for a test, from the real files of
 * ../shared/data or from an example Facet writes.
 *
 * Test support, not part of Facet: tests/ links it, the binary does not.
 * Nothing here fails a test itself: callers say how (cmocka's fail_msg,
 * skip), so that benches can link it too.
 */
#ifndef FACET_SURFACE_FIXTURE_H
#define FACET_SURFACE_FIXTURE_H

#include <stddef.h>

#include "core/surface/surface.h"

/* The path of the real surface name under FACET_DATA (default
 * ../shared/data) into path (size bytes). Returns 1 when it can be read;
 * else 0, after printing the line "skipped: PATH is absent ..." that
 * tests/run.sh lists and counts the test skipped by. */
int surface_fixture_data(const char *name, char *path, size_t size);

/* Opens the OBJ at path in metres and prepares it (every core, the UV the
 * first method that applies) into *s (caller-owned: surface_close).
 * Returns FACET_OK or the error, with err saying what. */
int surface_fixture_open(const char *path, struct surface *s,
                         struct facet_error *err);

/* surface_fixture_open of example name at res (example.h) written to a
 * temporary file, removed after. */
int surface_fixture_example(const char *name, int res, struct surface *s,
                            struct facet_error *err);

#endif
