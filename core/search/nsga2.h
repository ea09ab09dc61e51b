/*
 * nsga2.h: the NSGA-II multi-objective genetic algorithm (Deb, Pratap,
 * Agarwal and Meyarivan 2002), over real and integer variables with
 * bounds, under constraint-domination.
 *
 * One generation: binary tournaments (lower rank wins, then larger
 * crowding distance) pick parents from the population; pairs are crossed
 * by simulated binary crossover (SBX, bounded form) with probability
 * crossover_probability and every child variable is mutated by polynomial
 * mutation (bounded form) with probability mutation_probability; the
 * children are evaluated in one batch; the best population-size of
 * parents and children survive (pareto_select: rank, then crowding, the
 * last front pruned one point at a time).
 *
 * Integer variables: the operators work on the real relaxation within
 * [lower, upper], then the result is rounded to the nearest integer
 * (halves away from zero) and clamped to the bounds. Initial values of an
 * integer variable are uniform over its integers.
 *
 * Generations are numbered from 0, the random initial population; a run
 * of settings.generations generations ends with generation
 * generations - 1 and evaluates population x generations design points
 * (DEAP's convention). Generation g >= 1 draws its random numbers from
 * rng_seed_stream(seed, g) and depends only on population g - 1, so a run
 * resumed from a stored generation (struct nsga2_start) finishes with the
 * population an uninterrupted run would have, bit for bit, given the same
 * settings and a deterministic evaluator. (The random numbers are the
 * same on every platform; the operators use pow(), so runs agree bit for
 * bit across machines only where the maths libraries agree.) The rank and crowding used by
 * the tournaments are recomputed from the population itself, so nothing
 * but variables, objectives and violations needs storing.
 *
 * Nothing here does I/O. The evaluator and the per-generation callback are
 * the caller's: they may run threads, write to SQLite, or stop the run by
 * returning an error. Duplicate design points are evaluated again (the
 * caller caches if it wants to); they never break the algorithm.
 */
#ifndef FACET_NSGA2_H
#define FACET_NSGA2_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "core/base/error.h"

/* Evaluates count design points: vars is count x nvars (row-major), and
 * the evaluator fills objectives (count x nobjectives, all minimised,
 * finite) and violation (count, >= 0, 0 = feasible). Returns 0, or a
 * FACET_E* code with err filled, which ends the run with that error. */
typedef int (*nsga2_evaluate_fn)(void *context, size_t count,
                                 const double *vars, double *objectives,
                                 double *violation, struct facet_error *err);

struct nsga2_problem {
    size_t nvars;
    const double *lower;      /* nvars lower bounds (integral if integer) */
    const double *upper;      /* nvars upper bounds, >= lower */
    const bool *is_integer;   /* nvars flags, or NULL: all real */
    size_t nobjectives;
    nsga2_evaluate_fn evaluate;
    void *context;            /* passed to evaluate */
};

struct nsga2_settings {
    size_t population;              /* >= 2; odd sizes are fine */
    size_t generations;             /* >= 1, counting the initial one */
    uint64_t seed;
    double crossover_probability;   /* per pair, in [0, 1] */
    double eta_c;                   /* SBX distribution index, >= 0 */
    double mutation_probability;    /* per variable, in [0, 1] */
    double eta_m;                   /* mutation distribution index, >= 0 */
};

/* One generation: population x nvars variables and their evaluation, with
 * the rank and crowding distance of each member within the population. */
struct nsga2_population {
    size_t generation;
    size_t size;
    size_t nvars;
    size_t nobjectives;
    double *vars;         /* size x nvars */
    double *objectives;   /* size x nobjectives */
    double *violation;    /* size */
    int *rank;            /* size, 1 = non-dominated in the population */
    double *crowding;     /* size */
};

/* A stored generation to resume from: settings.population members, all
 * borrowed for the duration of nsga2_run. */
struct nsga2_start {
    size_t generation;           /* the index it was stored under */
    const double *vars;          /* population x nvars */
    const double *objectives;    /* population x nobjectives */
    const double *violation;     /* population */
};

/* Called after each generation is complete (its population evaluated and,
 * after generation 0, selected). population is borrowed for the call.
 * Returns 0 to go on, or a FACET_E* code (with err filled) to stop the run
 * with that error. */
typedef int (*nsga2_generation_fn)(void *context,
                                   const struct nsga2_population *population,
                                   struct facet_error *err);

/* The defaults of Deb et al. 2002: crossover 0.9 with eta_c 20, mutation
 * 1 / nvars with eta_m 20; population 100, 250 generations, seed 1. */
void nsga2_settings_default(struct nsga2_settings *settings, size_t nvars);

/* Runs NSGA-II. With start NULL, from a random generation 0 (reported to
 * on_generation); otherwise from the stored generation start->generation
 * (not reported again, not re-evaluated). on_generation may be NULL.
 * On success *result (caller-owned, release with nsga2_free) holds the
 * last generation, settings.generations - 1, or the start itself when it
 * is already that late. Errors: FACET_EINPUT for bad settings, bounds,
 * start population (outside the bounds, non-integral integer variable) or
 * evaluator output (non-finite objective, negative or NaN violation);
 * FACET_EWORK when out of memory; or whatever the callbacks return.
 * *result is zeroed on failure (nsga2_free on it is harmless). */
int nsga2_run(const struct nsga2_problem *problem,
              const struct nsga2_settings *settings,
              const struct nsga2_start *start,
              nsga2_generation_fn on_generation, void *callback_context,
              struct nsga2_population *result, struct facet_error *err);

/* Frees the arrays of a population from nsga2_run and zeroes it. */
void nsga2_free(struct nsga2_population *population);

#endif
