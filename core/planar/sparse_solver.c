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

/* OpenMP's regions and OpenBLAS's calls on the calling thread alone
 * (sparse_solver.h: spinning threads on shared cores). Each library is
 * found among CHOLMOD's own dependencies, where it is loaded; one that is
 * not there (another BLAS) has no threads of this kind to stop. */
static void threads_keep_to_one(void *library)
{
    void (*openmp_levels)(int);
    void (*blas_threads)(int);
    *(void **)&openmp_levels = dlsym(library, "omp_set_max_active_levels");
    *(void **)&blas_threads = dlsym(library, "openblas_set_num_threads");
    if (openmp_levels != NULL)
        openmp_levels(0);
    if (blas_threads != NULL)
        blas_threads(1);
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
    threads_keep_to_one(s->library);
    return FACET_OK;
}

void sparse_solver_close(struct sparse_solver *s)
{
    if (s->library != NULL)
        dlclose(s->library);
    memset(s, 0, sizeof *s);
}
