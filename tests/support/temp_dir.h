/*
 * temp_dir.h: a fresh directory under /tmp for a test's files, and its
 * removal with everything in it.
 *
 * Test support, not part of Facet: tests/ links it, the binary does not.
 */
#ifndef FACET_TEMP_DIR_H
#define FACET_TEMP_DIR_H

#include <stddef.h>

/* Makes the directory /tmp/facet_NAME_XXXXXX (the Xs made unique) and
 * puts its path into dir (size bytes). Returns 0, or -1 when it cannot. */
int temp_dir_make(char *dir, size_t size, const char *name);

/* Removes dir and everything below it. Returns 0, or -1 when it cannot. */
int temp_dir_remove(const char *dir);

#endif
