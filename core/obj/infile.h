/*
 * infile.h: opening an input file that is really a file.
 *
 * A surface is read whole, twice at once (its SHA-256 and the OBJ
 * loader), so an input that never ends (/dev/zero, /dev/urandom) or that
 * waits for a writer (a FIFO) would hang the command beyond any signal's
 * reach. Facet reads regular files only, and opens without blocking, so a
 * FIFO with no writer is refused at once.
 */
#ifndef FACET_INFILE_H
#define FACET_INFILE_H

#include <sys/stat.h>

#include "core/base/error.h"

/* Opens path for reading into *fd (the caller closes it) with its status
 * in *st. FACET_EINPUT, naming path, when it cannot be opened, is a
 * directory, or is not a regular file (a FIFO, a device, a socket);
 * FACET_EWORK when its status cannot be read. */
int infile_open(const char *path, int *fd, struct stat *st,
                struct facet_error *err);

#endif
