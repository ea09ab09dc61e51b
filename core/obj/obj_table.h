/*
 * obj_table.h: growable arrays and name tables for the OBJ reader.
 *
 * Internal to obj.c and obj_part.c (not part of the library's API). A name
 * table keeps distinct names in order of first use, with a hash from name to
 * position so that a file with many groups stays linear. Each part of a file
 * parsed on its own thread has its own tables; the merge in obj.c folds them
 * into one table per kind, in file order.
 */
#ifndef FACET_OBJ_TABLE_H
#define FACET_OBJ_TABLE_H

#include <stddef.h>
#include <stdint.h>

#include "core/base/error.h"
#include "core/obj/obj.h"

#define OBJ_MAX_INDEX ((uint64_t)UINT32_MAX - 1)  /* largest 0-based index */

struct obj_names {
    struct obj_name *names;  /* count names, each text owned */
    size_t count;
    size_t capacity;
    uint32_t *slot;          /* nslots: 1 + name index, or 0 if empty */
    size_t nslots;           /* a power of two, at least 2 x count */
};

/* Returns array grown (by doubling, from 64) to hold at least needed
 * elements of size bytes, updating *capacity, or NULL when out of memory or
 * the size overflows (array is then still valid and owned by the caller). */
void *obj_grow(void *array, size_t *capacity, size_t needed, size_t size);

/* Asks the kernel to back the whole pages of [p, p + bytes) with huge
 * pages when they are first touched (fewer, cheaper page faults for the
 * big arrays the reader fills once). Only a hint: does nothing for small
 * ranges or where unsupported. p must stay allocated as it is (memory that
 * is later realloc'd may lose the hint or be copied). */
void obj_advise_huge(void *p, size_t bytes);

/* Finds text (length bytes, no NUL needed) in the table, adding a copy of
 * it if it is new, and stores its index in *index. Returns FACET_OK,
 * FACET_EINPUT when the table is full (more than OBJ_MAX_INDEX names) or
 * FACET_EWORK when out of memory, with err saying which (the caller adds
 * the file and line). A zeroed table is an empty one. */
int obj_names_find(struct obj_names *table, const char *text, size_t length,
                   uint32_t *index, struct facet_error *err);

/* Hands the names over to the caller (*names, *count) and empties table. */
void obj_names_release(struct obj_names *table, struct obj_name **names,
                       size_t *count);

/* Frees the table and every name still in it, and zeroes it. */
void obj_names_free(struct obj_names *table);

#endif
