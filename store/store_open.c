/*
 * store_open.c: opening a Facet database: recognising the file, checking
 * its schema (schema_check.c) and migrating it (schema.c), the connection
 * settings a writer and a reader share, and noticing runs whose writer is
 * gone; and what a store says of itself (its path, its check, its close).
 */
#include "store_internal.h"

#include "core/out/outfile.h"

#include <assert.h>
#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

/* Whether the process that wrote a run is gone: on this host, no process
 * with that pid. (A pid reused by another process since reads as alive;
 * --resume then says who holds the run.) */
static int writer_gone(int64_t pid, const char *host)
{
    char here[64] = "";
    gethostname(here, sizeof here - 1);
    if (strcmp(here, host) != 0)
        return 0;  /* another machine's writer: cannot tell */
    return pid <= 0 || (kill((pid_t)pid, 0) != 0 && errno == ESRCH);
}

/* Lists into orphan (64 at most) the "running" runs whose writer is gone. */
static int find_orphans(struct store *store, int64_t orphan[64],
                        int *norphans, struct facet_error *err)
{
    sqlite3_stmt *stmt;
    *norphans = 0;
    int rc = store_prepare(store,
        "SELECT id, writer_pid, coalesce(writer_host, '') FROM runs"
        " WHERE status = 'running'", &stmt, "reading runs", err);
    if (rc != FACET_OK)
        return rc;
    int step;
    while ((step = sqlite3_step(stmt)) == SQLITE_ROW && *norphans < 64)
        if (writer_gone(sqlite3_column_int64(stmt, 1),
                        (const char *)sqlite3_column_text(stmt, 2)))
            orphan[(*norphans)++] = sqlite3_column_int64(stmt, 0);
    sqlite3_finalize(stmt);
    if (step != SQLITE_ROW && step != SQLITE_DONE)
        return store_fail(store, "reading runs", err);
    return FACET_OK;
}

/* Marks "running" runs whose writer is gone as "interrupted". Found again
 * and marked in one write transaction: a --resume that claimed the run
 * between a first look and the mark would otherwise lose its claim to the
 * mark, and a second --resume take the run too. */
static int reap_orphans(struct store *store, struct facet_error *err)
{
    int64_t orphan[64];
    int norphans;
    int rc = find_orphans(store, orphan, &norphans, err);
    if (rc != FACET_OK || norphans == 0)
        return rc;
    if ((rc = store_exec(store, "BEGIN IMMEDIATE", "reading runs", err)))
        return rc;
    rc = find_orphans(store, orphan, &norphans, err);
    for (int k = 0; k < norphans && rc == FACET_OK; k++) {
        struct run_info run;
        rc = store_run_get(store, orphan[k], &run, err);
        if (rc == FACET_OK)
            rc = store_run_set_status(store, orphan[k], RUN_INTERRUPTED,
                                      run.elapsed, err);
    }
    if (rc == FACET_OK)
        rc = store_exec(store, "COMMIT", "marking orphaned runs", err);
    if (rc != FACET_OK)
        sqlite3_exec(store->db, "ROLLBACK", NULL, NULL, NULL);
    return rc;
}

/* Puts the file in WAL mode (once per file: it stays so). Switching
 * needs the file to itself and SQLite does not wait for it, so a second
 * process opening a new file at the same moment retries for up to 10 s. */
static int use_wal(struct store *store, struct facet_error *err)
{
    for (int attempt = 0;; attempt++) {
        sqlite3_stmt *stmt;
        int rc = store_prepare(store, "PRAGMA journal_mode = WAL", &stmt,
                               "opening", err);
        if (rc != FACET_OK)
            return rc;
        int step = sqlite3_step(stmt);
        const char *mode = step == SQLITE_ROW
            ? (const char *)sqlite3_column_text(stmt, 0) : NULL;
        int wal = mode != NULL && strcmp(mode, "wal") == 0;
        sqlite3_finalize(stmt);
        if (wal)
            return FACET_OK;
        int code = sqlite3_errcode(store->db);
        if ((step == SQLITE_ROW || code == SQLITE_BUSY ||
             code == SQLITE_LOCKED) && attempt < 200) {
            struct timespec pause = {0, 50000000};  /* 50 ms */
            nanosleep(&pause, NULL);
            continue;
        }
        return step == SQLITE_ROW
            ? facet_error_set(err, FACET_EINPUT,
                  "%s: cannot switch to WAL mode (journal mode %s)",
                  store->path, mode ? mode : "?")
            : store_fail(store, "opening", err);
    }
}

/* "file:" + path as an SQLite URI (RFC 3986: everything but unreserved
 * characters and '/' percent-encoded) + query, into uri. Returns 0 when
 * it does not fit. */
static int file_uri(const char *path, const char *query, char *uri,
                    size_t size)
{
    static const char hex[] = "0123456789ABCDEF";
    size_t n = (size_t)snprintf(uri, size, "file:");
    for (const unsigned char *c = (const unsigned char *)path; *c; c++) {
        int plain = (*c >= 'A' && *c <= 'Z') || (*c >= 'a' && *c <= 'z') ||
                    (*c >= '0' && *c <= '9') || strchr("-._~/", *c) != NULL;
        if (n + 4 >= size)
            return 0;
        if (plain) {
            uri[n++] = (char)*c;
        } else {
            uri[n++] = '%';
            uri[n++] = hex[*c >> 4];
            uri[n++] = hex[*c & 15];
        }
    }
    int tail = snprintf(uri + n, size - n, "%s", query);
    return tail >= 0 && (size_t)tail < size - n;
}

/* Sets the connection up for a file anyone may have written (SQLite's
 * "Defense against the dark arts"): no SQL of the file's own runs on it.
 * Facet makes no trigger, and reads none of the views it makes for the
 * user (pareto, run_summary): both are switched off, so that a trigger
 * does not fire and a view is not read even if one were missed by
 * store_schema_check. Functions the schema calls (a CHECK, an index on
 * an expression) may only be innocuous ones; and SQL cannot corrupt the
 * file on purpose (DEFENSIVE). */
static int defend(struct store *store, struct facet_error *err)
{
    static const int settings[][2] = {
        {SQLITE_DBCONFIG_DEFENSIVE, 1},
        {SQLITE_DBCONFIG_TRUSTED_SCHEMA, 0},
        {SQLITE_DBCONFIG_ENABLE_TRIGGER, 0},
        {SQLITE_DBCONFIG_ENABLE_VIEW, 0},
    };
    for (size_t k = 0; k < sizeof settings / sizeof settings[0]; k++) {
        int now = -1;
        if (sqlite3_db_config(store->db, settings[k][0], settings[k][1],
                              &now) != SQLITE_OK || now != settings[k][1])
            return facet_error_set(err, FACET_EWORK,
                "%s: this SQLite (%s) cannot open a file defensively: "
                "Facet needs SQLite 3.31 or later", store->path,
                sqlite3_libversion());
    }
    return FACET_OK;
}

/* Opens path into *store (allocated here) with SQLite flags, reading the
 * header: *application and *version. The file name is given as a URI when
 * query is not NULL. */
static int open_connection(const char *path, const char *query, int flags,
                           struct store **out, int *application,
                           int *version, struct facet_error *err)
{
    *out = NULL;
    struct store *store = calloc(1, sizeof *store);
    if (store == NULL || (store->path = strdup(path)) == NULL) {
        free(store);
        return facet_error_set(err, FACET_EWORK, "out of memory");
    }
    store->read_only = (flags & SQLITE_OPEN_READONLY) != 0;
    char uri[4200];
    const char *name = path;
    if (query != NULL) {
        if (!file_uri(path, query, uri, sizeof uri)) {
            store_close(store);
            return facet_error_set(err, FACET_EINPUT, "%.200s...: path too "
                                   "long", path);
        }
        name = uri;
        flags |= SQLITE_OPEN_URI;
    }
    int rc;
    if (sqlite3_open_v2(name, &store->db, flags | SQLITE_OPEN_NOMUTEX,
                        NULL) != SQLITE_OK) {
        rc = store->db ? store_fail(store, "opening", err)
                       : facet_error_set(err, FACET_EWORK,
                                         "%s: cannot open", path);
        store_close(store);
        return rc;
    }
    rc = defend(store, err);
    if (rc != FACET_OK) {
        store_close(store);
        return rc;
    }
    /* A reader and a writer wait for each other's short transactions
     * rather than fail. */
    sqlite3_busy_timeout(store->db, 10000);
    /* Pages read in place from a mapping of the file, not copied into the
     * page cache by a read() each: half of a walk of a million options
     * was the kernel copying pages. SQLite's largest map (2 GB); the WAL
     * is read as before. */
    sqlite3_exec(store->db, "PRAGMA mmap_size = 2147418112", NULL, NULL,
                 NULL);
    /* The header is read through SQLite, never with a second file
     * descriptor: closing one would drop every lock this process holds
     * on the file (POSIX), under another connection of this process. */
    rc = store_pragma_int(store, "PRAGMA application_id", application, err);
    if (rc != FACET_OK && sqlite3_errcode(store->db) == SQLITE_NOTADB)
        rc = facet_error_set(err, FACET_EINPUT,
            "%s: not an SQLite database (is it the right file?)", path);
    if (rc == FACET_OK)
        rc = store_pragma_int(store, "PRAGMA user_version", version, err);
    if (rc == FACET_OK && *application != STORE_APPLICATION_ID) {
        int tables = 0;
        rc = store_pragma_int(store, "SELECT count(*) FROM sqlite_schema", &tables,
                        err);
        if (rc == FACET_OK && (*application != 0 || tables != 0))
            rc = facet_error_set(err, FACET_EINPUT,
                "%s: an SQLite database of another application, not "
                "Facet's (use a new file)", path);
    }
    /* Checked before anything is written: a negative version names no
     * migration, and the file is left exactly as it is. */
    if (rc == FACET_OK && *version < 0)
        rc = facet_error_set(err, FACET_EINPUT,
            "%s: schema version %d is none Facet writes (the file is "
            "damaged or not Facet's); nothing was changed", path, *version);
    if (rc == FACET_OK && *version > STORE_SCHEMA_VERSION)
        rc = facet_error_set(err, FACET_EINPUT,
            "%s: written by a newer Facet (schema %d; this Facet %s reads "
            "up to %d): upgrade Facet", path, *version, FACET_VERSION,
            STORE_SCHEMA_VERSION);
    /* Before anything else is read or written: what the file holds
     * besides data is Facet's own schema of its version, or it is not
     * opened. */
    if (rc == FACET_OK && *application == STORE_APPLICATION_ID)
        rc = store_schema_check(store, *version, err);
    if (rc != FACET_OK) {
        store_close(store);
        return rc;
    }
    *out = store;
    return FACET_OK;
}

/* Refuses a file that is not at this Facet's schema, for an open that
 * does not migrate (only reads, or writes only what it computes): an empty
 * file holds no database, an older one says how to migrate it. Before
 * anything is written, so the file is left as it was. */
static int refuse_older(const char *path, int application, int version,
                        struct facet_error *err)
{
    if (version >= STORE_SCHEMA_VERSION)
        return FACET_OK;
    if (application != STORE_APPLICATION_ID)
        return facet_error_about(err, FACET_SETTING_STORE, FACET_EINPUT,
                                 "%s: an empty file, no Facet database",
                                 path);
    return facet_error_about(err, FACET_SETTING_MIGRATE, FACET_EINPUT,
        "%s: written by an older Facet (schema %d; this one reads %d), "
        "and left as it is: migrating writes into it, and no older Facet "
        "opens it after", path, version, STORE_SCHEMA_VERSION);
}

/* Gives a new (empty) file the current schema in one transaction: the
 * entries its migrations leave (store_schemas), stamped as Facet's at
 * STORE_SCHEMA_VERSION. Replaying the migrations on a new file was most
 * of a small run's time: each ALTER TABLE has SQLite parse the whole
 * schema again. A file another process began to create meanwhile is
 * migrated from where it stands instead. */
static int create_schema(struct store *store, struct facet_error *err)
{
    int rc = store_exec(store, "BEGIN IMMEDIATE", "creating the schema",
                        err);
    if (rc != FACET_OK)
        return rc;
    int now = 0;
    rc = store_pragma_int(store, "PRAGMA user_version", &now, err);
    if (rc == FACET_OK && now > 0) {
        rc = store_exec(store, "COMMIT", "creating the schema", err);
        if (rc == FACET_OK && now < STORE_SCHEMA_VERSION)
            rc = store_schema_migrate(store, now, STORE_SCHEMA_VERSION, err);
        return rc;
    }
    char stamp[96];
    snprintf(stamp, sizeof stamp, "PRAGMA application_id = %d;"
             " PRAGMA user_version = %d", STORE_APPLICATION_ID,
             STORE_SCHEMA_VERSION);
    for (const struct store_schema_entry *e =
             store_schemas[STORE_SCHEMA_VERSION];
         rc == FACET_OK && e->type != NULL; e++)
        rc = store_exec(store, e->sql, "creating the schema", err);
    if (rc == FACET_OK)
        rc = store_exec(store, stamp, "creating the schema", err);
    if (rc == FACET_OK)
        rc = store_exec(store, "COMMIT", "creating the schema", err);
    if (rc != FACET_OK)
        sqlite3_exec(store->db, "ROLLBACK", NULL, NULL, NULL);
    return rc;
}

/* How open_writer treats a file of an older schema. */
enum older { OLDER_MIGRATE, OLDER_REFUSE };

/* Opens path for writing (creating it when create is set): WAL, foreign
 * keys, the schema migrated forward (or refused: older), orphaned runs
 * marked. *found (NULL: not wanted) gets the file's schema version as it
 * was opened. */
static int open_writer(const char *path, int create, enum older older,
                       int *found, struct store **out,
                       struct facet_error *err)
{
    int application = 0, version = 0;
    struct store *store;
    int flags = SQLITE_OPEN_READWRITE | (create ? SQLITE_OPEN_CREATE : 0);
    int rc = open_connection(path, NULL, flags, &store, &application,
                             &version, err);
    if (rc != FACET_OK)
        return rc;
    if (found != NULL)
        *found = version;
    /* A new or empty file is given the schema whatever older says: it
     * holds nothing to keep as it is. */
    if (older == OLDER_REFUSE && application == STORE_APPLICATION_ID)
        rc = refuse_older(path, application, version, err);
    if (rc == FACET_OK)
        rc = use_wal(store, err);
    if (rc == FACET_OK)
        rc = store_exec(store, "PRAGMA synchronous = NORMAL;"
                        "PRAGMA foreign_keys = ON;"
                        /* After each checkpoint that resets it, the WAL
                         * shrinks back to 64 MB: a slow reader cannot
                         * leave it at its largest for good. */
                        "PRAGMA journal_size_limit = 67108864;",
                        "opening", err);
    if (rc == FACET_OK && version == 0)
        rc = create_schema(store, err);
    else if (rc == FACET_OK && version < STORE_SCHEMA_VERSION)
        rc = store_schema_migrate(store, version, STORE_SCHEMA_VERSION, err);
    if (rc == FACET_OK)
        rc = reap_orphans(store, err);
    /* A writer killed while its run stored options without the indexes
     * by metric left them dropped: built now that it is gone. */
    int built = 0;
    if (rc == FACET_OK)
        rc = store_indexes_build(store, 0, &built, err);
    if (rc == FACET_OK && built)
        rc = store_analyze(store, err);
    if (rc != FACET_OK) {
        store_close(store);
        return rc;
    }
    *out = store;
    return FACET_OK;
}

/* Refuses a path where there is no database file to read. */
static int require_file(const char *path, struct facet_error *err)
{
    struct stat st;
    if (stat(path, &st) != 0)
        return facet_error_about(err, errno == ENOENT ? FACET_SETTING_STORE
                                                      : FACET_SETTING_NONE,
                                 FACET_EINPUT, "%s: %s%s", path,
                                 strerror(errno),
                                 errno == ENOENT ? " (no such database)"
                                                 : "");
    if (!S_ISREG(st.st_mode))
        return facet_error_set(err, FACET_EINPUT,
                               "%s: not a regular file, not a database",
                               path);
    return FACET_OK;
}

/* Refuses a path a writer may not open: anything but a regular file or
 * a new one, for SQLite would write its journal beside it
 * (/dev/null-journal, as root), and a link, for Facet writes through
 * none (outfile.h). */
static int writable_place(const char *path, struct facet_error *err)
{
    int rc = outfile_refuse_link(path, err);
    if (rc != FACET_OK)
        return rc;
    struct stat st;
    if (stat(path, &st) == 0 && !S_ISREG(st.st_mode))
        return facet_error_set(err, FACET_EINPUT,
                               "%s: not a regular file, not a database "
                               "(name a Facet database or a new file)",
                               path);
    return FACET_OK;
}

int store_open(const char *path, struct store **out,
               struct facet_error *err)
{
    int rc = writable_place(path, err);
    if (rc != FACET_OK)
        return rc;
    return open_writer(path, 1, OLDER_MIGRATE, NULL, out, err);
}

int store_open_current(const char *path, struct store **out,
                       struct facet_error *err)
{
    int rc = writable_place(path, err);
    if (rc != FACET_OK)
        return rc;
    return open_writer(path, 1, OLDER_REFUSE, NULL, out, err);
}

int store_migrate(const char *path, int *from, struct facet_error *err)
{
    int rc = require_file(path, err);
    if (rc == FACET_OK)
        rc = writable_place(path, err);
    if (rc == FACET_OK && access(path, W_OK) != 0)
        return facet_error_set(err, FACET_EINPUT,
            "%s: read-only here (%s): copy it where it can be written and "
            "migrate the copy", path, strerror(errno));
    struct store *store;
    if (rc == FACET_OK)
        rc = open_writer(path, 0, OLDER_MIGRATE, from, &store, err);
    if (rc == FACET_OK)
        store_close(store);
    return rc;
}

int store_open_existing(const char *path, struct store **out,
                        struct facet_error *err)
{
    *out = NULL;
    int rc = require_file(path, err);
    if (rc != FACET_OK)
        return rc;
    if (access(path, W_OK) == 0)
        return open_writer(path, 0, OLDER_REFUSE, NULL, out, err);
    return store_open_read(path, out, err);
}

int store_open_read(const char *path, struct store **out,
                    struct facet_error *err)
{
    *out = NULL;
    int rc = require_file(path, err);
    if (rc != FACET_OK)
        return rc;
    int application = 0, version = 0;
    struct store *store;
    rc = open_connection(path, "?mode=ro", SQLITE_OPEN_READONLY, &store,
                         &application, &version, err);
    /* A WAL file whose folder is read-only cannot get its shared memory
     * file: read it as immutable media (no writer can change it there). */
    if (rc != FACET_OK && (strstr(err->message, "unable to open") != NULL ||
                           strstr(err->message, "readonly") != NULL)) {
        struct facet_error first = *err;
        rc = open_connection(path, "?mode=ro&immutable=1",
                             SQLITE_OPEN_READONLY, &store, &application,
                             &version, err);
        if (rc != FACET_OK)
            *err = first;
    }
    if (rc != FACET_OK)
        return rc;
    /* A reader cannot read an older file's missing columns, and does not
     * migrate it: that would write into a file it was asked to read, and
     * shut every older Facet out of it. */
    rc = refuse_older(path, application, version, err);
    if (rc != FACET_OK) {
        store_close(store);
        return rc;
    }
    *out = store;
    return FACET_OK;
}

int store_schema_version(void)
{
    return STORE_SCHEMA_VERSION;
}

int store_read_only(const struct store *store)
{
    return store->read_only;
}

const char *store_path(const struct store *store)
{
    return store->path;
}

int store_run_writer_gone(int64_t pid, const char *host)
{
    return writer_gone(pid, host);
}

int store_analyze(struct store *store, struct facet_error *err)
{
    /* SQLite reads the first entries of each index only: 1,000 of them
     * all had one run and one nu, and left a file of one large run and a
     * small one scanning the large run for `nu = 7 and nv = 13` (210 ms
     * instead of 1 ms); 50,000 see enough, in 0.07 s on a million. */
    return store_exec(store, "PRAGMA analysis_limit = 50000; ANALYZE;",
                      "gathering statistics", err);
}

int store_check(struct store *store, struct facet_error *err)
{
    sqlite3_stmt *stmt;
    /* quick_check reads every page and checks its structure, its records
     * and the constraints, and leaves out integrity_check's lookup of
     * every index entry in its table: 0.9 s instead of 17 s on a file of
     * a million options, before every run. */
    int rc = store_prepare(store, "PRAGMA quick_check(1)", &stmt,
                           "checking the file", err);
    if (rc != FACET_OK)
        return rc;
    int step = sqlite3_step(stmt);
    if (step == SQLITE_ROW) {
        const char *text = (const char *)sqlite3_column_text(stmt, 0);
        char verdict[200];
        snprintf(verdict, sizeof verdict, "%s", text ? text : "no verdict");
        /* SQLite's verdict spans lines; the error is one. */
        for (char *c = verdict; *c != '\0'; c++)
            if (*c == '\n')
                *c = ' ';
        if (strcmp(verdict, "ok") != 0)
            rc = facet_error_set(err, FACET_EINPUT,
                "%s: the database is damaged (%s); restore it from a copy "
                "or use a new file", store->path, verdict);
    } else {
        rc = store_fail(store, "checking the file", err);
    }
    sqlite3_finalize(stmt);
    return rc;
}

int store_seal(struct store *store, struct facet_error *err)
{
    assert(!store->read_only);
    int frames = -1, moved = -1;
    int step = sqlite3_wal_checkpoint_v2(store->db, NULL,
                                         SQLITE_CHECKPOINT_TRUNCATE, &frames,
                                         &moved);
    if (step != SQLITE_OK)
        return store_fail(store, "writing the file whole (checkpoint)", err);
    if (frames != moved)
        return facet_error_set(err, FACET_EWORK,
            "%s: the checkpoint moved %d of %d pages into the file: it is "
            "not whole", store->path, moved, frames);
    return store_check(store, err);
}

void store_close(struct store *store)
{
    if (store == NULL)
        return;
    sqlite3_finalize(store->option_insert);
    sqlite3_finalize(store->held_insert);
    sqlite3_finalize(store->option_get);
    /* Closing the last connection would checkpoint and delete the WAL
     * under an exclusive lock, failing a reader without a busy timeout
     * (sqlite3 on the command line) that opens the file at that moment.
     * A passive checkpoint moves everything into the main file without
     * blocking anyone, and the WAL file stays. */
    if (store->db != NULL && !store->read_only) {
        /* A writer leaving empties the WAL (truncated to 0 bytes, the file
         * kept) when no reader holds it within a moment; with a reader
         * there, a passive checkpoint moves what it can. Either way no
         * -wal of hundreds of MB is left behind. */
        sqlite3_busy_timeout(store->db, 200);
        if (sqlite3_wal_checkpoint_v2(store->db, NULL,
                                      SQLITE_CHECKPOINT_TRUNCATE, NULL,
                                      NULL) != SQLITE_OK)
            sqlite3_wal_checkpoint_v2(store->db, NULL,
                                      SQLITE_CHECKPOINT_PASSIVE, NULL, NULL);
        sqlite3_db_config(store->db, SQLITE_DBCONFIG_NO_CKPT_ON_CLOSE, 1,
                          NULL);
    }
    sqlite3_close(store->db);
    free(store->path);
    free(store);
}
