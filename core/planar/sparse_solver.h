/*
 * sparse_solver.h: SuiteSparse's CHOLMOD, loaded by the run that solves.
 *
 * CHOLMOD brings OpenBLAS, LAPACK, gfortran, OpenMP and METIS with it, and
 * a process that links them pays for loading them and for OpenBLAS's
 * threads whether it solves or not: 25 ms of every sanitizer-built facet
 * call's 119 ms, of which only `facet planarize` needs any. So facet is
 * not linked with CHOLMOD; planarize.c opens it here, at its first solve,
 * with dlopen(3), and calls it through the table below.
 *
 * This is core's one exception to "no I/O but the files it is asked to
 * read": it maps a system library, the same bytes the dynamic linker would
 * have mapped at start, and reads nothing of the user's. The library is
 * libcholmod.so.N, N the CHOLMOD_MAIN_VERSION of the header Facet was
 * built with (the soname's major is that version), found on the dynamic
 * linker's usual path.
 *
 * Loading it twice in a process is cheap (dlopen counts); it is never
 * unloaded (RTLD_NODELETE), for OpenBLAS's threads outlive a dlclose.
 *
 * Threads: the solve runs on the calling thread alone. CHOLMOD 3's
 * supernodal factorization opens OpenMP regions of a fixed 4 threads
 * (its CHOLMOD_OMP_NUM_THREADS, whatever OMP_NUM_THREADS says) around
 * loops of a few hundred entries, and OpenBLAS starts one thread per
 * core; on 2 shared cores those threads spin and yield more than they
 * compute: one planarization of the roof's 100 x 100 grid took 15 to 19
 * s of user and 11 to 24 s of system time, against 7 and 1 s on the
 * calling thread alone (bench_planarize). sparse_solver_open turns both
 * off through the libraries' own calls: omp_set_max_active_levels(0),
 * every OpenMP region on the thread that opens it, and
 * openblas_set_num_threads(1). Both settings are the process's; Facet
 * uses neither library elsewhere. A BLAS or an OpenMP without those
 * calls is left as it is.
 */
#ifndef FACET_SPARSE_SOLVER_H
#define FACET_SPARSE_SOLVER_H

#include <suitesparse/cholmod.h>

#include "core/base/error.h"

/* CHOLMOD's functions that planarize.c calls, each of the header's own
 * type, so that a mismatch is a compile error. */
struct sparse_solver {
    void *library;   /* dlopen's handle; NULL when closed */
    __typeof__(cholmod_start) *start;
    __typeof__(cholmod_finish) *finish;
    __typeof__(cholmod_allocate_sparse) *allocate_sparse;
    __typeof__(cholmod_zeros) *zeros;
    __typeof__(cholmod_analyze) *analyze;
    __typeof__(cholmod_factorize) *factorize;
    __typeof__(cholmod_solve) *solve;
    __typeof__(cholmod_free_dense) *free_dense;
    __typeof__(cholmod_free_factor) *free_factor;
    __typeof__(cholmod_free_sparse) *free_sparse;
};

/* Loads CHOLMOD into *s (caller-owned; sparse_solver_close releases it,
 * also after a failure) and keeps its BLAS and OpenMP on the calling
 * thread (above). FACET_EWORK, naming the library and why, when it
 * cannot be loaded or lacks a function. */
int sparse_solver_open(struct sparse_solver *s, struct facet_error *err);

void sparse_solver_close(struct sparse_solver *s);

#endif
