/*
 * snapshot.h: one moment of the database for several reads. Between
 * store_snapshot_begin and store_snapshot_end every read of the
 * connection sees the same committed state (SQLite's read transaction in
 * WAL mode: a writer goes on committing meanwhile, and is never waited
 * for), so that numbers read by separate queries agree: the workbench's
 * title, table count and gauge of a live run. Reads that open their own
 * transaction inside one (store_browse's pages) join it.
 */
#ifndef FACET_STORE_SNAPSHOT_H
#define FACET_STORE_SNAPSHOT_H

#include "store.h"

/* Begins the snapshot: *began becomes 1 when it began one (to end), 0
 * when the connection was already in a transaction (nothing to end).
 * Returns FACET_OK, or the FACET_E* of SQLite refusing BEGIN with err
 * filled and *began 0: a caller may then go on reading, each read its own
 * moment. */
int store_snapshot_begin(struct store *store, int *began,
                         struct facet_error *err);

/* Ends a snapshot that store_snapshot_begin returned 1 for. */
void store_snapshot_end(struct store *store, int began);

#endif
