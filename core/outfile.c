/*
 * outfile.c: output through PATH.partial and rename. See outfile.h.
 */
#include "outfile.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <unistd.h>

int outfile_check(const char *path, int force, struct facet_error *err)
{
    if (!force && access(path, F_OK) == 0)
        return facet_error_set(err, FACET_EINPUT,
                               "%s exists (pass --force to overwrite it)",
                               path);
    return FACET_OK;
}

static void outfile_release(struct outfile *f)
{
    free(f->path);
    free(f->partial);
    memset(f, 0, sizeof *f);
}

int outfile_open(struct outfile *f, const char *path, int force,
                 struct facet_error *err)
{
    memset(f, 0, sizeof *f);
    int rc = outfile_check(path, force, err);
    if (rc != FACET_OK)
        return rc;
    size_t length = strlen(path);
    f->path = malloc(length + 1);
    f->partial = malloc(length + sizeof ".partial");
    if (f->path == NULL || f->partial == NULL) {
        outfile_release(f);
        return facet_error_set(err, FACET_EWORK, "out of memory (%s)", path);
    }
    memcpy(f->path, path, length + 1);
    memcpy(f->partial, path, length);
    memcpy(f->partial + length, ".partial", sizeof ".partial");
    f->out = fopen(f->partial, "w");
    if (f->out == NULL) {
        rc = facet_error_set(err, FACET_EINPUT, "cannot write %s: %s", path,
                             strerror(errno));
        outfile_release(f);
        return rc;
    }
    return FACET_OK;
}

int outfile_commit(struct outfile *f, struct facet_error *err)
{
    if (f->out == NULL)
        return facet_error_set(err, FACET_EWORK, "%s: not open",
                               f->path ? f->path : "output");
    /* errno is only the reason when the last call failed; a stream error
     * from earlier has none to give. */
    errno = 0;
    int failed = ferror(f->out);
    if (fclose(f->out) != 0)
        failed = 1;
    int reason = errno;
    f->out = NULL;
    int rc = FACET_OK;
    if (failed)
        rc = facet_error_set(err, FACET_EWORK, "writing %s failed%s%s",
                             f->path, reason ? ": " : "",
                             reason ? strerror(reason) : "");
    else if (rename(f->partial, f->path) != 0)
        rc = facet_error_set(err, FACET_EWORK, "cannot write %s: %s",
                             f->path, strerror(errno));
    if (rc != FACET_OK)
        remove(f->partial);
    outfile_release(f);
    return rc;
}

void outfile_abort(struct outfile *f)
{
    if (f->out != NULL) {
        fclose(f->out);
        remove(f->partial);
    }
    outfile_release(f);
}

int outfile_sibling(const char *path, const char *extension,
                    const char *suffix, char *out, size_t size,
                    struct facet_error *err)
{
    size_t length = strlen(path), ext = strlen(extension);
    if (length >= ext && strcasecmp(path + length - ext, extension) == 0)
        length -= ext;
    size_t tail = strlen(suffix);
    if (length + tail + 1 > size)
        return facet_error_set(err, FACET_EINPUT, "path too long: %s", path);
    memcpy(out, path, length);
    memcpy(out + length, suffix, tail + 1);
    return FACET_OK;
}
