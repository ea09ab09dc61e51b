/*
 * store_snapshot.c: a read transaction around several reads. See
 * snapshot.h.
 */
#include "snapshot.h"

#include "store_internal.h"

int store_snapshot_begin(struct store *store)
{
    if (!sqlite3_get_autocommit(store->db))
        return 0;
    if (sqlite3_exec(store->db, "BEGIN", NULL, NULL, NULL) != SQLITE_OK)
        return 0;
    /* BEGIN is deferred: the snapshot is taken by the first read, which
     * is the caller's next one */
    return 1;
}

void store_snapshot_end(struct store *store, int began)
{
    if (began)
        sqlite3_exec(store->db, "COMMIT", NULL, NULL, NULL);
}
