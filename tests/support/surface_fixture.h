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

/* A surface given by its formula: the point p (m) at parameters s, t in
 * [0, 1], for the shape's own dimensions (caller's data, passed through). */
typedef void (*surface_formula)(const void *shape, double s, double t,
                                double p[3]);

/* How surface_fixture_formula_write meshes the ns x nt parameter grid. */
enum formula_faces {
    FORMULA_QUADS,      /* one OBJ quad a cell */
    FORMULA_TRIANGLES   /* each cell split in two along (i,j)-(i+1,j+1) */
};

/* Writes formula f of shape on an ns x nt grid, vertices at (i / ns,
 * j / nt) with vt = those parameters, faces winding s then t (the normal
 * along ds x dt), to a new temporary file. Returns its path (malloc'ed:
 * the caller unlinks and frees it), or NULL when the file cannot be
 * made. The one writer of analytic meshes for the unit tests. */
char *surface_fixture_formula_write(surface_formula f, const void *shape,
                                    int ns, int nt, enum formula_faces faces);

/* surface_fixture_open of that file, removed after. */
int surface_fixture_formula(surface_formula f, const void *shape, int ns,
                            int nt, enum formula_faces faces,
                            struct surface *s, struct facet_error *err);

#endif
