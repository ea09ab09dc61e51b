/*
 * nsga2.c: the NSGA-II generation loop and its variation operators. See
 * nsga2.h for the algorithm as a whole; ranking, crowding and survivor
 * selection are pareto.c's.
 *
 * Random numbers are drawn in a fixed order (per child pair: two
 * tournaments of two draws each, the crossover draw, the per-variable
 * crossover draws, then the per-variable mutation draws of each child), so
 * a seed fixes the run.
 */
#include "core/search/nsga2.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/search/pareto.h"
#include "core/base/rng.h"
#include "core/search/ties.h"

void nsga2_settings_default(struct nsga2_settings *settings, size_t nvars)
{
    settings->population = 100;
    settings->generations = 250;
    settings->seed = 1;
    settings->crossover_probability = 0.9;
    settings->eta_c = 20;
    settings->mutation_probability = nvars > 0 ? 1.0 / (double)nvars : 1.0;
    settings->eta_m = 20;
}

void nsga2_free(struct nsga2_population *population)
{
    free(population->vars);
    free(population->objectives);
    free(population->violation);
    free(population->rank);
    free(population->crowding);
    memset(population, 0, sizeof *population);
}

/* Allocates the arrays of a population of size members. */
static int population_alloc(struct nsga2_population *population, size_t size,
                            size_t nvars, size_t nobjectives,
                            struct facet_error *err)
{
    memset(population, 0, sizeof *population);
    population->size = size;
    population->nvars = nvars;
    population->nobjectives = nobjectives;
    population->vars = malloc(size * nvars * sizeof(double));
    population->objectives = malloc(size * nobjectives * sizeof(double));
    population->violation = malloc(size * sizeof(double));
    population->rank = malloc(size * sizeof(int));
    population->crowding = malloc(size * sizeof(double));
    if (population->vars == NULL || population->objectives == NULL ||
        population->violation == NULL || population->rank == NULL ||
        population->crowding == NULL) {
        nsga2_free(population);
        return facet_error_set(err, FACET_EWORK,
                               "nsga2: out of memory (population of %zu)",
                               size);
    }
    return FACET_OK;
}

static bool is_integer_var(const struct nsga2_problem *problem, size_t v)
{
    return problem->is_integer != NULL && problem->is_integer[v];
}

static int check_setup(const struct nsga2_problem *problem,
                       const struct nsga2_settings *settings,
                       struct facet_error *err)
{
    if (problem->nvars == 0 || problem->nobjectives == 0 ||
        problem->evaluate == NULL || problem->lower == NULL ||
        problem->upper == NULL)
        return facet_error_set(err, FACET_EINPUT,
                               "nsga2: the problem needs variables, bounds, "
                               "objectives and an evaluator");
    for (size_t v = 0; v < problem->nvars; v++) {
        double lo = problem->lower[v], hi = problem->upper[v];
        if (!isfinite(lo) || !isfinite(hi) || lo > hi)
            return facet_error_set(err, FACET_EINPUT,
                                   "nsga2: variable %zu has bounds [%g, %g]",
                                   v, lo, hi);
        if (is_integer_var(problem, v) && (lo != floor(lo) || hi != floor(hi)))
            return facet_error_set(err, FACET_EINPUT,
                                   "nsga2: integer variable %zu has "
                                   "non-integral bounds [%g, %g]", v, lo, hi);
    }
    size_t widest = problem->nvars > problem->nobjectives
                        ? problem->nvars : problem->nobjectives;
    if (settings->population < 2 ||
        settings->population > SIZE_MAX / 16 / widest)
        return facet_error_set(err, FACET_EINPUT,
                               "nsga2: population %zu is out of range",
                               settings->population);
    if (settings->generations < 1)
        return facet_error_set(err, FACET_EINPUT,
                               "nsga2: generations must be at least 1");
    if (!(settings->crossover_probability >= 0 &&
          settings->crossover_probability <= 1) ||
        !(settings->mutation_probability >= 0 &&
          settings->mutation_probability <= 1))
        return facet_error_set(err, FACET_EINPUT,
                               "nsga2: crossover probability %g and mutation "
                               "probability %g must be in [0, 1]",
                               settings->crossover_probability,
                               settings->mutation_probability);
    if (!(settings->eta_c >= 0 && isfinite(settings->eta_c)) ||
        !(settings->eta_m >= 0 && isfinite(settings->eta_m)))
        return facet_error_set(err, FACET_EINPUT,
                               "nsga2: distribution indices eta_c %g and "
                               "eta_m %g must be finite and >= 0",
                               settings->eta_c, settings->eta_m);
    return FACET_OK;
}

/* Checks count evaluations; first names the design point of row 0 in the
 * message (its generation-wide index). */
static int check_evaluations(const double *objectives,
                             const double *violation, size_t count,
                             size_t nobjectives, const char *what,
                             struct facet_error *err)
{
    for (size_t i = 0; i < count; i++) {
        for (size_t j = 0; j < nobjectives; j++)
            if (!isfinite(objectives[i * nobjectives + j]))
                return facet_error_set(err, FACET_EINPUT,
                                       "nsga2: %s %zu has objective %zu = %g",
                                       what, i, j,
                                       objectives[i * nobjectives + j]);
        if (!(violation[i] >= 0))
            return facet_error_set(err, FACET_EINPUT,
                                   "nsga2: %s %zu has violation %g", what, i,
                                   violation[i]);
    }
    return FACET_OK;
}

/* Evaluates count design points through the problem's evaluator, and
 * checks what comes back (objectives left unset are caught as NaN). */
static int evaluate(const struct nsga2_problem *problem, size_t count,
                    const double *vars, double *objectives, double *violation,
                    struct facet_error *err)
{
    for (size_t k = 0; k < count * problem->nobjectives; k++)
        objectives[k] = NAN;
    for (size_t k = 0; k < count; k++)
        violation[k] = NAN;
    facet_error_clear(err);
    int rc = problem->evaluate(problem->context, count, vars, objectives,
                               violation, err);
    if (rc != FACET_OK) {
        if (err != NULL && err->code == FACET_OK)
            facet_error_set(err, rc, "nsga2: the evaluator failed (%d)", rc);
        return rc;
    }
    return check_evaluations(objectives, violation, count,
                             problem->nobjectives, "evaluated design point",
                             err);
}

/* Rank and crowding of every member, within the population. */
static int rank_population(struct nsga2_population *population,
                           struct facet_error *err)
{
    int rc = pareto_rank(population->objectives, population->size,
                         population->nobjectives, population->violation,
                         population->rank, NULL, err);
    if (rc == FACET_OK)
        rc = pareto_crowding(population->objectives, population->size,
                             population->nobjectives, population->rank,
                             population->crowding, err);
    return rc;
}

static double clamp(double x, double lo, double hi)
{
    return x < lo ? lo : x > hi ? hi : x;
}

/* Puts an integer variable back on the integers of its bounds. */
static void settle(const struct nsga2_problem *problem, double *vars)
{
    for (size_t v = 0; v < problem->nvars; v++)
        if (is_integer_var(problem, v))
            vars[v] = clamp(round(vars[v]), problem->lower[v],
                            problem->upper[v]);
}

/* The SBX spread factor beta_q for a uniform draw u, where alpha = 2 -
 * beta^-(eta + 1) accounts for the bound on that side. */
static double sbx_spread(double u, double alpha, double eta)
{
    double exponent = 1.0 / (eta + 1.0);
    if (u <= 1.0 / alpha)
        return pow(u * alpha, exponent);
    return pow(1.0 / (2.0 - u * alpha), exponent);
}

/* Bounded simulated binary crossover of two children in place: each
 * variable, with probability 1/2 and when the parents differ, is replaced
 * by two values spread around the parents' mean, whose distribution is
 * truncated to [lower, upper]; the two results go to either child at
 * random. */
static void crossover(const struct nsga2_problem *problem, double eta,
                      struct rng *rng, double *a, double *b)
{
    for (size_t v = 0; v < problem->nvars; v++) {
        if (rng_uniform(rng) > 0.5)
            continue;
        double low = fmin(a[v], b[v]), high = fmax(a[v], b[v]);
        if (high - low <= 1e-14)
            continue;
        double lo = problem->lower[v], hi = problem->upper[v];
        double u = rng_uniform(rng);
        double beta = 1.0 + 2.0 * (low - lo) / (high - low);
        double alpha = 2.0 - pow(beta, -(eta + 1.0));
        double c1 = 0.5 * ((low + high) -
                           sbx_spread(u, alpha, eta) * (high - low));
        beta = 1.0 + 2.0 * (hi - high) / (high - low);
        alpha = 2.0 - pow(beta, -(eta + 1.0));
        double c2 = 0.5 * ((low + high) +
                           sbx_spread(u, alpha, eta) * (high - low));
        c1 = clamp(c1, lo, hi);
        c2 = clamp(c2, lo, hi);
        if (rng_uniform(rng) <= 0.5) {
            a[v] = c2;
            b[v] = c1;
        } else {
            a[v] = c1;
            b[v] = c2;
        }
    }
}

/* Bounded polynomial mutation in place: each variable, with probability
 * probability, moves by a perturbation whose distribution (index eta) is
 * scaled so that the result stays within [lower, upper]. */
static void mutate(const struct nsga2_problem *problem, double probability,
                   double eta, struct rng *rng, double *x)
{
    for (size_t v = 0; v < problem->nvars; v++) {
        if (rng_uniform(rng) >= probability)
            continue;
        double lo = problem->lower[v], hi = problem->upper[v];
        double u = rng_uniform(rng);
        if (hi <= lo)
            continue;
        double width = hi - lo;
        double exponent = 1.0 / (eta + 1.0), delta;
        if (u < 0.5) {
            double rest = 1.0 - (x[v] - lo) / width;
            double value = 2.0 * u + (1.0 - 2.0 * u) * pow(rest, eta + 1.0);
            delta = pow(value, exponent) - 1.0;
        } else {
            double rest = 1.0 - (hi - x[v]) / width;
            double value = 2.0 * (1.0 - u) +
                           2.0 * (u - 0.5) * pow(rest, eta + 1.0);
            delta = 1.0 - pow(value, exponent);
        }
        x[v] = clamp(x[v] + delta * width, lo, hi);
    }
}

/* Binary tournament: the lower rank wins, then the larger crowding
 * distance (beyond the tolerance of ties.h: mirror-image points crowd
 * alike but for rounding), then the first drawn. */
static size_t tournament(const struct nsga2_population *population,
                         struct rng *rng)
{
    size_t a = (size_t)rng_below(rng, population->size);
    size_t b = (size_t)rng_below(rng, population->size);
    if (population->rank[b] < population->rank[a])
        return b;
    if (population->rank[b] == population->rank[a] &&
        ties_compare_normalised(population->crowding[b],
                                population->crowding[a]) > 0)
        return b;
    return a;
}

/* Fills children (population->size x nvars) from the parents. spare holds
 * nvars doubles, for the unused second child of an odd population. */
static void make_children(const struct nsga2_problem *problem,
                          const struct nsga2_settings *settings,
                          const struct nsga2_population *parents,
                          struct rng *rng, double *children, double *spare)
{
    size_t nvars = problem->nvars, size = parents->size;
    for (size_t k = 0; k < size; k += 2) {
        const double *pa = parents->vars + tournament(parents, rng) * nvars;
        const double *pb = parents->vars + tournament(parents, rng) * nvars;
        double *a = children + k * nvars;
        double *b = k + 1 < size ? children + (k + 1) * nvars : spare;
        memcpy(a, pa, nvars * sizeof *a);
        memcpy(b, pb, nvars * sizeof *b);
        if (rng_uniform(rng) < settings->crossover_probability)
            crossover(problem, settings->eta_c, rng, a, b);
        mutate(problem, settings->mutation_probability, settings->eta_m, rng,
               a);
        mutate(problem, settings->mutation_probability, settings->eta_m, rng,
               b);
        settle(problem, a);
        settle(problem, b);
    }
}

/* Generation 0: uniform in the bounds (uniform over the integers for
 * integer variables), evaluated. */
static int first_generation(const struct nsga2_problem *problem,
                            const struct nsga2_settings *settings,
                            struct nsga2_population *population,
                            struct facet_error *err)
{
    struct rng rng;
    rng_seed_stream(&rng, settings->seed, 0);
    for (size_t i = 0; i < population->size; i++)
        for (size_t v = 0; v < problem->nvars; v++) {
            double lo = problem->lower[v], hi = problem->upper[v];
            double *x = population->vars + i * problem->nvars + v;
            if (is_integer_var(problem, v))
                *x = lo + (double)rng_below(&rng, (uint64_t)(hi - lo) + 1);
            else
                *x = clamp(lo + rng_uniform(&rng) * (hi - lo), lo, hi);
        }
    population->generation = 0;
    return evaluate(problem, population->size, population->vars,
                    population->objectives, population->violation, err);
}

/* Copies a stored generation in, after checking it. */
static int resume_generation(const struct nsga2_problem *problem,
                             const struct nsga2_start *start,
                             struct nsga2_population *population,
                             struct facet_error *err)
{
    size_t size = population->size, nvars = problem->nvars;
    if (start->vars == NULL || start->objectives == NULL ||
        start->violation == NULL)
        return facet_error_set(err, FACET_EINPUT,
                               "nsga2: the start population is incomplete");
    for (size_t i = 0; i < size; i++)
        for (size_t v = 0; v < nvars; v++) {
            double x = start->vars[i * nvars + v];
            if (!(x >= problem->lower[v] && x <= problem->upper[v]) ||
                (is_integer_var(problem, v) && x != floor(x)))
                return facet_error_set(err, FACET_EINPUT,
                                       "nsga2: stored member %zu of "
                                       "generation %zu has variable %zu = %g, "
                                       "outside its bounds or not integral",
                                       i, start->generation, v, x);
        }
    int rc = check_evaluations(start->objectives, start->violation, size,
                               problem->nobjectives, "stored member", err);
    if (rc != FACET_OK)
        return rc;
    memcpy(population->vars, start->vars, size * nvars * sizeof(double));
    memcpy(population->objectives, start->objectives,
           size * problem->nobjectives * sizeof(double));
    memcpy(population->violation, start->violation, size * sizeof(double));
    population->generation = start->generation;
    return FACET_OK;
}

/* Working memory of the generations after the first: the children, and
 * parents followed by children for the survivor selection. */
struct offspring {
    double *vars;          /* size x nvars, children */
    double *spare;         /* nvars */
    double *all_vars;      /* 2 size x nvars */
    double *all_objectives;/* 2 size x nobjectives */
    double *all_violation; /* 2 size */
    size_t *survivors;     /* size */
};

static void offspring_free(struct offspring *o)
{
    free(o->vars);
    free(o->spare);
    free(o->all_vars);
    free(o->all_objectives);
    free(o->all_violation);
    free(o->survivors);
}

/* One generation: children of population, evaluated, then the survivors
 * of parents and children replace population. */
static int next_generation(const struct nsga2_problem *problem,
                           const struct nsga2_settings *settings,
                           struct offspring *o,
                           struct nsga2_population *population,
                           struct facet_error *err)
{
    size_t size = population->size, nvars = problem->nvars;
    size_t nobj = problem->nobjectives;
    size_t generation = population->generation + 1;
    struct rng rng;
    rng_seed_stream(&rng, settings->seed, generation);
    make_children(problem, settings, population, &rng, o->vars, o->spare);

    memcpy(o->all_vars, population->vars, size * nvars * sizeof(double));
    memcpy(o->all_vars + size * nvars, o->vars, size * nvars * sizeof(double));
    memcpy(o->all_objectives, population->objectives,
           size * nobj * sizeof(double));
    memcpy(o->all_violation, population->violation, size * sizeof(double));
    int rc = evaluate(problem, size, o->vars, o->all_objectives + size * nobj,
                      o->all_violation + size, err);
    if (rc != FACET_OK)
        return rc;

    rc = pareto_select(o->all_objectives, 2 * size, nobj, o->all_violation,
                       size, o->survivors, err);
    if (rc != FACET_OK)
        return rc;
    for (size_t k = 0; k < size; k++) {
        size_t from = o->survivors[k];
        memcpy(population->vars + k * nvars, o->all_vars + from * nvars,
               nvars * sizeof(double));
        memcpy(population->objectives + k * nobj,
               o->all_objectives + from * nobj, nobj * sizeof(double));
        population->violation[k] = o->all_violation[from];
    }
    population->generation = generation;
    return FACET_OK;
}

int nsga2_run(const struct nsga2_problem *problem,
              const struct nsga2_settings *settings,
              const struct nsga2_start *start,
              nsga2_generation_fn on_generation, void *callback_context,
              struct nsga2_population *result, struct facet_error *err)
{
    memset(result, 0, sizeof *result);
    int rc = check_setup(problem, settings, err);
    if (rc != FACET_OK)
        return rc;
    size_t size = settings->population, nvars = problem->nvars;
    size_t nobj = problem->nobjectives;

    struct nsga2_population population;
    struct offspring o = {0};
    rc = population_alloc(&population, size, nvars, nobj, err);
    if (rc != FACET_OK)
        return rc;
    o.vars = malloc(size * nvars * sizeof(double));
    o.spare = malloc(nvars * sizeof(double));
    o.all_vars = malloc(2 * size * nvars * sizeof(double));
    o.all_objectives = malloc(2 * size * nobj * sizeof(double));
    o.all_violation = malloc(2 * size * sizeof(double));
    o.survivors = malloc(size * sizeof(size_t));
    if (o.vars == NULL || o.spare == NULL || o.all_vars == NULL ||
        o.all_objectives == NULL || o.all_violation == NULL ||
        o.survivors == NULL) {
        rc = facet_error_set(err, FACET_EWORK, "nsga2: out of memory");
        goto fail;
    }

    if (start == NULL) {
        rc = first_generation(problem, settings, &population, err);
        if (rc == FACET_OK)
            rc = rank_population(&population, err);
        if (rc == FACET_OK && on_generation != NULL)
            rc = on_generation(callback_context, &population, err);
    } else {
        rc = resume_generation(problem, start, &population, err);
        if (rc == FACET_OK)
            rc = rank_population(&population, err);
    }
    while (rc == FACET_OK && population.generation + 1 < settings->generations) {
        rc = next_generation(problem, settings, &o, &population, err);
        if (rc == FACET_OK)
            rc = rank_population(&population, err);
        if (rc == FACET_OK && on_generation != NULL)
            rc = on_generation(callback_context, &population, err);
    }
    if (rc != FACET_OK)
        goto fail;
    offspring_free(&o);
    *result = population;
    return FACET_OK;
fail:
    offspring_free(&o);
    nsga2_free(&population);
    return rc;
}
