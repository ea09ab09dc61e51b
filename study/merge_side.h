/*
 * merge_side.h: the side files of a merge (internal to study/).
 *
 * A merge writes the merged database into OUT.db.merge-PID beside OUT.db
 * (PID its process id) and renames it over OUT.db at the end. A merge
 * that stops or fails removes its own; one killed (kill -9, a node that
 * went down, a second Ctrl-C) cannot, and its file, tens or hundreds of
 * megabytes, stays. The next merge into the same OUT.db removes such
 * files, and only those whose merge surely is gone (merge_side_stale).
 */
#ifndef FACET_MERGE_SIDE_H
#define FACET_MERGE_SIDE_H

#include <stddef.h>

/* Removes path's SQLite side files (-wal, -shm, -journal). */
void merge_side_remove_sqlite(const char *path);

/* Whether the side file path, named for process pid, belongs to no merge
 * that is still running, as far as this host can tell:
 *   - pid is not this process's (whose own file the caller handles);
 *   - no process has that id here (kill(pid, 0) says ESRCH), or the one
 *     that has it started after the file last changed: a merge creates
 *     its file after it starts, so that process reuses a dead merge's
 *     id (its start read from /proc; where /proc cannot say, alive);
 *   - no process holds a lock on the file or its -shm (F_GETLK): an open
 *     SQLite connection holds one on the -shm for its whole life, also
 *     seen across hosts on a shared file system, where a merge running on
 *     another node has an id that means nothing here.
 * Any doubt keeps the file: a stale file left costs disk space, a live
 * one removed costs a merge. */
int merge_side_stale(const char *path, long pid);

/* Removes the stale side files of merges into out (out.merge-PID and
 * their SQLite side files, in out's folder); returns how many it
 * removed. Errors (an unreadable folder) remove nothing. */
size_t merge_side_sweep(const char *out);

#endif
