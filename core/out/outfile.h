/*
 * outfile.h: writing an output file so that a failure never leaves half of
 * it under the name the user asked for.
 *
 * Output to a file goes to PATH.partial, which is renamed to PATH only
 * once it is complete and closed without error; any failure removes
 * PATH.partial. An existing regular file is refused unless the caller says
 * to overwrite it; a symbolic link, a directory or any other special file
 * is never replaced. A stream, "-" (stdout), a character device or a FIFO,
 * is written straight into (nothing is replaced, so no --force is needed)
 * and its write errors are reported as a file's are; a FIFO without a
 * reader is refused at once, never waited on. Exports write through this;
 * the messages name PATH, never the partial file the user did not ask
 * for.
 */
#ifndef FACET_OUTFILE_H
#define FACET_OUTFILE_H

#include <stdio.h>

#include "core/base/error.h"

struct outfile {
    FILE *out;        /* write here between open and commit */
    char *path;       /* owned copy of the target */
    char *partial;    /* owned: path + ".partial" */
    int direct;       /* a stream: written straight, no partial file */
};

/* 1 when path is a stream outfile_open writes straight into: "-"
 * (stdout), a character device or a FIFO. Files written beside an output
 * (an OBJ's MTL, a schedule's totals) have no place beside a stream. */
int outfile_is_stream(const char *path);

/* Fails with FACET_EINPUT when path is a symbolic link, naming the file
 * it points to; FACET_OK when it is anything else or nothing. Facet reads
 * through links but never writes through or over one: an output, or a
 * database written into, whose name is a link is refused, so a link
 * planted where an output goes cannot make Facet replace another file
 * (a system file, when run as root). Every writer asks this. */
int outfile_refuse_link(const char *path, struct facet_error *err);

/* Fails with FACET_EINPUT, "PATH exists" about FACET_SETTING_OVERWRITE
 * (error.h), when a regular file exists at path and force is 0, and whatever force
 * is when path is a symbolic link, a directory or a special file other
 * than a stream; FACET_OK otherwise. For writers of several files, to
 * refuse before creating any. */
int outfile_check(const char *path, int force, struct facet_error *err);

/* Checks path (outfile_check) and opens path.partial for writing into *f
 * (caller-owned). Returns FACET_OK, FACET_EINPUT when path exists without
 * force or the file cannot be created (missing or unwritable directory:
 * "cannot write PATH: reason"), FACET_EWORK when out of memory. After a
 * failure nothing is open or created and *f needs no release. */
int outfile_open(struct outfile *f, const char *path, int force,
                 struct facet_error *err);

/* Closes f->out and renames the partial file to the path. Returns FACET_OK,
 * or FACET_EWORK naming the path when a write, the close or the rename
 * failed (the partial file is then removed). Releases f either way. */
int outfile_commit(struct outfile *f, struct facet_error *err);

/* Abandons f: closes and removes the partial file, releases f. Does
 * nothing on a zeroed or already released f. */
void outfile_abort(struct outfile *f);

/* The path of a file written beside path: path less a final extension
 * (".obj", any case) plus suffix (".mtl", "-totals.csv"), into out (size
 * bytes). Returns FACET_OK or FACET_EINPUT when it does not fit. */
int outfile_sibling(const char *path, const char *extension,
                    const char *suffix, char *out, size_t size,
                    struct facet_error *err);

#endif
