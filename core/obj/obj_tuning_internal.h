/*
 * obj_tuning_internal.h: the OBJ reader's knobs for how it splits and
 * streams a file, so that tests can force many small parts and windows.
 *
 * Internal (tests and obj.c only); callers use obj.h. Every field 0 means
 * the default obj_load and obj_parse use.
 */
#ifndef FACET_OBJ_TUNING_INTERNAL_H
#define FACET_OBJ_TUNING_INTERNAL_H

#include <stddef.h>

#include "core/obj/obj.h"

struct obj_tuning {
    unsigned nthreads;     /* threads at most; default online CPUs, <= 8 */
    size_t part_bytes;     /* text per part at least; default 1 MiB */
    size_t max_parts;      /* parts per window at most; default nthreads */
    size_t window_bytes;   /* streaming read size; default 64 MiB */
    size_t whole_bytes;    /* files up to this are read whole; 1 GiB */
};

/* obj_parse and obj_load with the given knobs (tuning may be NULL). */
int obj_parse_tuned(const char *text, size_t length, const char *name,
                    struct obj_file *out, struct facet_error *err,
                    const struct obj_tuning *tuning);
int obj_load_tuned(const char *path, struct obj_file *out,
                   struct facet_error *err, const struct obj_tuning *tuning);

#endif
