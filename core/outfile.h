/*
 * outfile.h: writing an output file so that a failure never leaves half of
 * it under the name the user asked for.
 *
 * Output goes to PATH.partial, which is renamed to PATH only once it is
 * complete and closed without error; any failure removes PATH.partial. An
 * existing PATH is refused unless the caller says to overwrite it. Exports
 * (OBJ + MTL, SVG) write through this; the messages name PATH, never the
 * partial file the user did not ask for.
 */
#ifndef FACET_OUTFILE_H
#define FACET_OUTFILE_H

#include <stdio.h>

#include "error.h"

struct outfile {
    FILE *out;        /* write here between open and commit */
    char *path;       /* owned copy of the target */
    char *partial;    /* owned: path + ".partial" */
};

/* Fails with FACET_EINPUT, "PATH exists (pass --force to overwrite it)",
 * when something exists at path and force is 0; FACET_OK otherwise. For
 * writers of several files, to refuse before creating any. */
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
