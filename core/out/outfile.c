/*
 * outfile.c: output through PATH.partial and rename. See outfile.h.
 */
#include "core/out/outfile.h"

#include <errno.h>
#include <fcntl.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include <unistd.h>

int outfile_is_stream(const char *path)
{
    if (strcmp(path, "-") == 0)
        return 1;
    /* stat, not lstat: /dev/stdout is a link to the stream itself. */
    struct stat st;
    return stat(path, &st) == 0 &&
           (S_ISCHR(st.st_mode) || S_ISFIFO(st.st_mode));
}

int outfile_refuse_link(const char *path, struct facet_error *err)
{
    struct stat st;
    if (lstat(path, &st) != 0 || !S_ISLNK(st.st_mode))
        return FACET_OK;
    char target[1024];
    ssize_t n = readlink(path, target, sizeof target - 1);
    if (n < 0)
        n = 0;
    target[n] = '\0';
    return facet_error_set(err, FACET_EINPUT,
        "%s is a symbolic link (to %s): Facet does not write through or "
        "over one; name the file itself", path, n > 0 ? target : "?");
}

int outfile_check(const char *path, int force, struct facet_error *err)
{
    if (strcmp(path, "-") == 0)
        return FACET_OK;
    struct stat st;
    if (lstat(path, &st) != 0)
        return FACET_OK;  /* nothing there: it will be made */
    /* A stream is written into, not replaced: --force is not needed and
     * the device or FIFO (or a link to one, as /dev/stdout) stays what it
     * is. */
    if (outfile_is_stream(path))
        return FACET_OK;
    if (S_ISLNK(st.st_mode))
        return outfile_refuse_link(path, err);
    if (S_ISDIR(st.st_mode))
        return facet_error_set(err, FACET_EINPUT,
                               "%s is a directory, not a file to write",
                               path);
    if (!S_ISREG(st.st_mode))
        return facet_error_set(err, FACET_EINPUT,
                               "%s is not a regular file: not replaced",
                               path);
    if (!force)
        return facet_error_about(err, FACET_SETTING_OVERWRITE, FACET_EINPUT,
                                 "%s exists", path);
    return FACET_OK;
}

static void outfile_release(struct outfile *f)
{
    free(f->path);
    free(f->partial);
    memset(f, 0, sizeof *f);
}

/* Opens the stream path (a character device or FIFO) straight: a FIFO
 * without a reader is refused at once rather than waited on. */
static FILE *open_stream(const char *path)
{
    int fd = open(path, O_WRONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0)
        return NULL;
    int flags = fcntl(fd, F_GETFL);
    if (flags < 0 || fcntl(fd, F_SETFL, flags & ~O_NONBLOCK) != 0) {
        close(fd);
        return NULL;
    }
    FILE *out = fdopen(fd, "w");
    if (out == NULL)
        close(fd);
    return out;
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
    if (strcmp(path, "-") == 0) {
        f->out = stdout;
        f->direct = 1;
        return FACET_OK;
    }
    f->direct = outfile_is_stream(path);
    errno = 0;
    f->out = f->direct ? open_stream(path) : fopen(f->partial, "w");
    if (f->out == NULL) {
        rc = facet_error_set(err, FACET_EINPUT, "cannot write %s: %s", path,
                             errno == ENXIO ? "a FIFO with no reader"
                                            : strerror(errno));
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
    int failed = fflush(f->out) != 0 || ferror(f->out);
    int reason = errno;
    if (f->out != stdout && fclose(f->out) != 0) {
        failed = 1;
        if (reason == 0)
            reason = errno;
    }
    f->out = NULL;
    int rc = FACET_OK;
    if (failed)
        rc = facet_error_set(err, FACET_EWORK, "writing %s failed%s%s",
                             f->path, reason ? ": " : "",
                             reason ? strerror(reason) : "");
    else if (!f->direct && rename(f->partial, f->path) != 0)
        rc = facet_error_set(err, FACET_EWORK, "cannot write %s: %s",
                             f->path, strerror(errno));
    if (rc != FACET_OK && !f->direct)
        remove(f->partial);
    outfile_release(f);
    return rc;
}

void outfile_abort(struct outfile *f)
{
    if (f->out != NULL && f->out != stdout)
        fclose(f->out);
    if (f->out != NULL && !f->direct)
        remove(f->partial);
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
