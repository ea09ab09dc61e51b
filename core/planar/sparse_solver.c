/*
 * sparse_solver.c: dlopen of CHOLMOD at the first solve (sparse_solver.h).
 */
#include "sparse_solver.h"

#include <dlfcn.h>
#include <stdio.h>
#include <string.h>

/* Finds name in s->library, or says which function is missing. */
static void *function_find(const struct sparse_solver *s, const char *library,
                           const char *name, struct facet_error *err)
{
    void *f = dlsym(s->library, name);
    if (f == NULL)
        facet_error_set(err, FACET_EWORK,
                        "the sparse solver %s has no %s: %s", library, name,
                        dlerror());
    return f;
}

int sparse_solver_open(struct sparse_solver *s, struct facet_error *err)
{
    memset(s, 0, sizeof *s);
    char library[64];
    snprintf(library, sizeof library, "libcholmod.so.%d",
             CHOLMOD_MAIN_VERSION);
    s->library = dlopen(library, RTLD_NOW | RTLD_LOCAL | RTLD_NODELETE);
    if (s->library == NULL)
        return facet_error_set(err, FACET_EWORK,
            "the sparse solver CHOLMOD cannot be loaded (install "
            "SuiteSparse's libcholmod): %s", dlerror());
    /* A function pointer from dlsym's void *: POSIX's own idiom. */
    if (!(*(void **)&s->start = function_find(s, library, "cholmod_start", err)) ||
        !(*(void **)&s->finish = function_find(s, library, "cholmod_finish", err)) ||
        !(*(void **)&s->allocate_sparse =
              function_find(s, library, "cholmod_allocate_sparse", err)) ||
        !(*(void **)&s->zeros = function_find(s, library, "cholmod_zeros", err)) ||
        !(*(void **)&s->analyze = function_find(s, library, "cholmod_analyze", err)) ||
        !(*(void **)&s->factorize =
              function_find(s, library, "cholmod_factorize", err)) ||
        !(*(void **)&s->solve = function_find(s, library, "cholmod_solve", err)) ||
        !(*(void **)&s->free_dense =
              function_find(s, library, "cholmod_free_dense", err)) ||
        !(*(void **)&s->free_factor =
              function_find(s, library, "cholmod_free_factor", err)) ||
        !(*(void **)&s->free_sparse =
              function_find(s, library, "cholmod_free_sparse", err)))
        return FACET_EWORK;
    return FACET_OK;
}

void sparse_solver_close(struct sparse_solver *s)
{
    if (s->library != NULL)
        dlclose(s->library);
    memset(s, 0, sizeof *s);
}
