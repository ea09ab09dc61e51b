/*
 * store_snapshot.c: a read transaction around several reads. See
 * snapshot.h.
 */
#include "snapshot.h"

#include "store_internal.h"

int store_snapshot_begin(struct store *store, int *began,
                         struct facet_error *err)
{
    *began = 0;
    if (!sqlite3_get_autocommit(store->db))
        return FACET_OK;
    int rc = store_exec(store, "BEGIN", "beginning a snapshot", err);
    /* BEGIN is deferred: the snapshot is taken by the first read, which
     * is the caller's next one */
    *began = rc == FACET_OK;
    return rc;
}

void store_snapshot_end(struct store *store, int began)
{
    if (began)
        sqlite3_exec(store->db, "COMMIT", NULL, NULL, NULL);
}
