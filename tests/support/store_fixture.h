/*
 * store_fixture.h: the least a run needs to be stored, for tests that
 * store options of a run no study made, and a database file removed with
 * its side files.
 *
 * Test support, not part of Facet: tests/ links it, the binary does not.
 */
#ifndef FACET_STORE_FIXTURE_H
#define FACET_STORE_FIXTURE_H

#include "store/store.h"

/* Fills *run with a run of x.obj (m, exhaustive, extremes, objective
 * cost, a 1 x 1 grid, one job) that store_run_create accepts. */
void store_fixture_run(struct run_info *run);

/* Removes the database at path and its -wal and -shm files, where
 * there are any. */
void store_fixture_remove(const char *path);

#endif
