/*
 * merge_side.c: finding and removing the side files of dead merges. See
 * merge_side.h.
 */
#include "merge_side.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

void merge_side_remove_sqlite(const char *path)
{
    static const char *const suffix[3] = {"-wal", "-shm", "-journal"};
    char side[4200];
    for (int k = 0; k < 3; k++)
        if (snprintf(side, sizeof side, "%s%s", path, suffix[k]) <
            (int)sizeof side)
            unlink(side);
}

/* The newest change time of path and its SQLite side files (a merge in
 * WAL mode writes its -wal for long stretches), or -1 when path is gone. */
static double newest_change(const char *path)
{
    static const char *const suffix[4] = {"", "-wal", "-shm", "-journal"};
    double newest = -1;
    char name[4200];
    for (int k = 0; k < 4; k++) {
        struct stat st;
        if (snprintf(name, sizeof name, "%s%s", path, suffix[k]) >=
                (int)sizeof name ||
            stat(name, &st) != 0)
            continue;
        double t = (double)st.st_mtim.tv_sec + 1e-9 * st.st_mtim.tv_nsec;
        if (t > newest)
            newest = t;
    }
    return newest;
}

/* When process pid started, in seconds since the epoch, from /proc: its
 * start in clock ticks after boot (field 22 of /proc/PID/stat) and the
 * boot time (btime of /proc/stat). -1 when /proc cannot say. */
static double process_start(long pid)
{
    char name[64], text[1024];
    snprintf(name, sizeof name, "/proc/%ld/stat", pid);
    FILE *f = fopen(name, "r");
    if (f == NULL)
        return -1;
    size_t n = fread(text, 1, sizeof text - 1, f);
    fclose(f);
    text[n] = '\0';
    /* The command name, field 2, is in parentheses and may hold spaces:
     * the fields are counted after its last ')'. */
    char *p = strrchr(text, ')');
    unsigned long long ticks = 0;
    int field = 2;
    for (; p != NULL && *p != '\0' && field < 22; p++)
        if (*p == ' ')
            field++;
    if (p == NULL || field != 22 || sscanf(p, "%llu", &ticks) != 1)
        return -1;
    f = fopen("/proc/stat", "r");
    if (f == NULL)
        return -1;
    long long boot = -1;
    char line[256];
    while (fgets(line, sizeof line, f) != NULL)
        if (sscanf(line, "btime %lld", &boot) == 1)
            break;
    fclose(f);
    long hz = sysconf(_SC_CLK_TCK);
    if (boot < 0 || hz <= 0)
        return -1;
    return (double)boot + (double)ticks / (double)hz;
}

/* Whether another process holds a lock on any byte of path (F_GETLK,
 * which takes none). A file that cannot be opened holds none. */
static int locked(const char *path)
{
    int fd = open(path, O_RDWR);
    if (fd < 0)
        return 0;
    struct flock lock;
    memset(&lock, 0, sizeof lock);
    lock.l_type = F_WRLCK;
    lock.l_whence = SEEK_SET;
    lock.l_start = 0;
    lock.l_len = 0;  /* to the end, however far */
    int held = fcntl(fd, F_GETLK, &lock) != 0 || lock.l_type != F_UNLCK;
    close(fd);
    return held;
}

int merge_side_stale(const char *path, long pid)
{
    if (pid <= 0 || pid == (long)getpid())
        return 0;
    if (kill((pid_t)pid, 0) == 0 || errno != ESRCH) {
        /* Alive (or not ours to signal): stale only when it started
         * after the file last changed, a reused id. The start's clock
         * ticks are coarse: a second's margin. */
        double started = process_start(pid);
        double changed = newest_change(path);
        if (started < 0 || changed < 0 || started <= changed + 1.0)
            return 0;
    }
    char shm[4200];
    if (snprintf(shm, sizeof shm, "%s-shm", path) >= (int)sizeof shm)
        return 0;
    return !locked(path) && !locked(shm);
}

/* The process id a name of out's side files carries: name is
 * "BASE.merge-DIGITS" exactly. 0 when it is not such a name. */
static long side_pid(const char *name, const char *base)
{
    static const char tag[] = ".merge-";
    size_t b = strlen(base), t = sizeof tag - 1;
    if (strncmp(name, base, b) != 0 || strncmp(name + b, tag, t) != 0)
        return 0;
    const char *digits = name + b + t;
    if (*digits < '0' || *digits > '9' || strlen(digits) > 9)
        return 0;
    long pid = 0;
    for (const char *p = digits; *p != '\0'; p++) {
        if (*p < '0' || *p > '9')
            return 0;
        pid = 10 * pid + (*p - '0');
    }
    return pid;
}

size_t merge_side_sweep(const char *out)
{
    char folder[4096];
    const char *slash = strrchr(out, '/');
    const char *base = slash != NULL ? slash + 1 : out;
    if (slash == NULL)
        snprintf(folder, sizeof folder, ".");
    else if (slash == out)
        snprintf(folder, sizeof folder, "/");
    else if ((size_t)(slash - out) < sizeof folder)
        snprintf(folder, sizeof folder, "%.*s", (int)(slash - out), out);
    else
        return 0;
    DIR *dir = opendir(folder);
    if (dir == NULL)
        return 0;
    size_t removed = 0;
    struct dirent *entry;
    char path[4200];
    while ((entry = readdir(dir)) != NULL) {
        long pid = side_pid(entry->d_name, base);
        if (pid == 0 ||
            snprintf(path, sizeof path, "%s/%s", folder, entry->d_name) >=
                (int)sizeof path ||
            !merge_side_stale(path, pid))
            continue;
        if (unlink(path) == 0)
            removed++;
        merge_side_remove_sqlite(path);
    }
    closedir(dir);
    return removed;
}
