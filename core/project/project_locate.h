/*
 * project_locate.h: the line of a statement in an OBJ file, read again.
 *
 * The OBJ reader keeps which f statement each triangle came from, not its
 * line. A project's errors name the line, and they are rare, so the file
 * is read once more, line by line, only when one is reported. Lines are
 * physical lines, 1-based, as the reader counts them; a statement
 * continued with '\' is found at its first line.
 */
#ifndef FACET_PROJECT_LOCATE_H
#define FACET_PROJECT_LOCATE_H

#include <stddef.h>

/* The line of the f statement number face (0-based, in file order) of
 * path, or 0 when the file cannot be read or has fewer faces. */
size_t locate_face(const char *path, size_t face);

/* The line of the first statement keyword ("o" or "g") whose name is
 * name, or 0. */
size_t locate_name(const char *path, const char *keyword, const char *name);

#endif
