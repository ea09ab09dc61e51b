/*
 * infile.c: regular files only, opened without waiting. See infile.h.
 */
#include "core/obj/infile.h"

#include <errno.h>
#include <fcntl.h>
#include <string.h>
#include <unistd.h>

int infile_open(const char *path, int *fd, struct stat *st,
                struct facet_error *err)
{
    *fd = open(path, O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (*fd < 0)
        return facet_error_set(err, FACET_EINPUT, "%s: cannot open: %s",
                               path, strerror(errno));
    int rc = FACET_OK;
    if (fstat(*fd, st) != 0)
        rc = facet_error_set(err, FACET_EWORK, "%s: cannot stat: %s", path,
                             strerror(errno));
    else if (S_ISDIR(st->st_mode))
        rc = facet_error_set(err, FACET_EINPUT,
                             "%s: is a directory, not an OBJ file", path);
    else if (!S_ISREG(st->st_mode))
        rc = facet_error_set(err, FACET_EINPUT,
            "%s: not a regular file (a %s): Facet reads surfaces from "
            "files; save it to one first", path,
            S_ISFIFO(st->st_mode) ? "FIFO or pipe"
            : S_ISCHR(st->st_mode) || S_ISBLK(st->st_mode) ? "device"
                                                          : "socket");
    if (rc == FACET_OK) {
        /* A regular file never blocks; reads go on as usual. */
        int flags = fcntl(*fd, F_GETFL);
        if (flags >= 0)
            fcntl(*fd, F_SETFL, flags & ~O_NONBLOCK);
    }
    if (rc != FACET_OK) {
        close(*fd);
        *fd = -1;
    }
    return rc;
}
