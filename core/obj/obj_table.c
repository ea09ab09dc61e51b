/*
 * obj_table.c: growable arrays and name tables of the OBJ reader. See
 * obj_table.h. Names are hashed with FNV-1a into an open-addressing table
 * that is rebuilt at twice the size when it would become half full.
 */
#include "core/obj/obj_table.h"

#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>

#define HUGE_PAGE ((uintptr_t)2 << 20)

void *obj_grow(void *array, size_t *capacity, size_t needed, size_t size)
{
    if (needed <= *capacity && array != NULL)
        return array;
    size_t grown = *capacity ? *capacity : 64;
    while (grown < needed) {
        if (grown > SIZE_MAX / 2)
            return NULL;
        grown *= 2;
    }
    if (grown > SIZE_MAX / size)
        return NULL;
    void *p = realloc(array, grown * size);
    if (p != NULL)
        *capacity = grown;
    return p;
}

void obj_advise_huge(void *p, size_t bytes)
{
#ifdef MADV_HUGEPAGE
    if (p == NULL || bytes < 2 * HUGE_PAGE)
        return;
    uintptr_t from = ((uintptr_t)p + HUGE_PAGE - 1) & ~(HUGE_PAGE - 1);
    uintptr_t to = ((uintptr_t)p + bytes) & ~(HUGE_PAGE - 1);
    if (to > from)
        (void)madvise((void *)from, to - from, MADV_HUGEPAGE);
#else
    (void)p;
    (void)bytes;
#endif
}

static uint64_t name_hash(const char *text, size_t length)
{
    uint64_t h = 14695981039346656037u;
    for (size_t i = 0; i < length; i++) {
        h ^= (unsigned char)text[i];
        h *= 1099511628211u;
    }
    return h;
}

static int rehash(struct obj_names *table, size_t nslots)
{
    uint32_t *slot = calloc(nslots, sizeof *slot);
    if (slot == NULL)
        return -1;
    for (size_t i = 0; i < table->count; i++) {
        const char *t = table->names[i].text;
        size_t s = name_hash(t, strlen(t)) & (nslots - 1);
        while (slot[s] != 0)
            s = (s + 1) & (nslots - 1);
        slot[s] = (uint32_t)(i + 1);
    }
    free(table->slot);
    table->slot = slot;
    table->nslots = nslots;
    return 0;
}

int obj_names_find(struct obj_names *table, const char *text, size_t length,
                   uint32_t *index, struct facet_error *err)
{
    if (table->nslots < 2 * (table->count + 1)) {
        size_t nslots = table->nslots ? 2 * table->nslots : 16;
        if (rehash(table, nslots) != 0)
            return facet_error_set(err, FACET_EWORK, "out of memory");
    }
    size_t mask = table->nslots - 1;
    size_t s = name_hash(text, length) & mask;
    for (; table->slot[s] != 0; s = (s + 1) & mask) {
        const char *t = table->names[table->slot[s] - 1].text;
        /* By length first: a stored name shorter than text is never read
         * past its end. */
        if (strlen(t) == length && memcmp(t, text, length) == 0) {
            *index = table->slot[s] - 1;
            return FACET_OK;
        }
    }
    if (table->count >= OBJ_MAX_INDEX)
        return facet_error_set(err, FACET_EINPUT, "more than %llu names",
                               (unsigned long long)OBJ_MAX_INDEX);
    struct obj_name *names = obj_grow(table->names, &table->capacity,
                                      table->count + 1, sizeof *names);
    if (names == NULL)
        return facet_error_set(err, FACET_EWORK, "out of memory");
    table->names = names;
    char *copy = malloc(length + 1);
    if (copy == NULL)
        return facet_error_set(err, FACET_EWORK, "out of memory");
    memcpy(copy, text, length);
    copy[length] = '\0';
    names[table->count].text = copy;
    table->slot[s] = (uint32_t)(table->count + 1);
    *index = (uint32_t)table->count++;
    return FACET_OK;
}

void obj_names_release(struct obj_names *table, struct obj_name **names,
                       size_t *count)
{
    *names = table->names;
    *count = table->count;
    free(table->slot);
    memset(table, 0, sizeof *table);
}

void obj_names_free(struct obj_names *table)
{
    for (size_t i = 0; i < table->count; i++)
        free(table->names[i].text);
    free(table->names);
    free(table->slot);
    memset(table, 0, sizeof *table);
}
