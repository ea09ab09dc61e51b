/*
 * optimize.h: searching the design space of a prepared surface.
 *
 * A design point is a grid (nu x nv) and a flatness threshold; the design
 * space is their ranges. Three methods, named after Refinery's study types:
 *   exhaustive  the cross product, u outermost, then v, then threshold:
 *               the exact Pareto front when the space is small;
 *   random      --evals distinct points drawn with the seed;
 *   nsga2       Deb et al. 2002 (nsga2.h) with --pop and --gens.
 * Options are numbered in the order the method first meets them, which the
 * seed fixes, so a run and its resumption number them alike.
 *
 * Evaluation runs on `jobs` threads in batches, each evaluated and stored
 * in chunks: after each chunk the caller's store hook receives its options
 * (to commit them). The stop hook is asked between chunks, between options
 * and inside an option (evaluate.h), so that a stop is heard within about
 * a second whatever the grid: the chunk it interrupts is dropped whole (no
 * option is stored half-evaluated), what was stored before it is kept. A
 * design point met twice is evaluated once. Resuming: pass
 * the options already stored; the method runs again from its start with
 * them as a cache (nothing stored is evaluated or stored again), so the
 * finished run has exactly the options of an uninterrupted one.
 */
#ifndef FACET_OPTIMIZE_H
#define FACET_OPTIMIZE_H

#include <stddef.h>
#include <stdint.h>

#include "core/base/stop.h"
#include "core/search/metric.h"
#include "core/search/shard.h"
#include "core/evaluate/evaluate.h"

struct design_space {
    int u_min, u_max;         /* grid sides, inclusive */
    int v_min, v_max;
    double t_min_mm, t_max_mm;/* flatness threshold (mm), inclusive */
    double t_step_mm;         /* exhaustive step; 0 = the single value
                                 t_min (exhaustive) or a continuous range
                                 (random, nsga2) */
};

struct design_point {
    int nu, nv;
    double threshold_mm;
};

/* Whether two design points are the same, the one rule every search,
 * resume and merge tells points apart by: the same grid and the same
 * threshold to a thousandth of a millimetre (the finest step a design
 * space takes). design_point_compare orders points by grid, then that
 * threshold, and is 0 exactly when they are the same; design_point_hash
 * is equal for the same points. */
int design_point_compare(const struct design_point *a,
                         const struct design_point *b);
uint64_t design_point_hash(const struct design_point *p);

/* threshold_mm on the grid design points lie on: rounded to the nearest
 * micrometre. */
double design_point_threshold_on_grid(double threshold_mm);

enum optimize_method { METHOD_EXHAUSTIVE, METHOD_RANDOM, METHOD_NSGA2 };

struct optimize_settings {
    enum optimize_method method;
    struct design_space space;
    struct option_params base;          /* everything but grid and t */
    struct objective objectives[OBJECTIVES_MAX];
    int nobjectives;
    uint64_t seed;
    int64_t evaluations;                /* random */
    int population, generations;        /* nsga2 */
    int jobs;                           /* threads, >= 1 */
    struct shard shard;                 /* this machine's share (shard.h);
                                           count 0: the whole space */
};

/* What every option of a run under s needs measured (option.h's
 * option_measure bits): option_measures_needed for its classification,
 * limits and prices and what its objectives read (metric_measures). */
unsigned optimize_measures_needed(const struct optimize_settings *s);

struct evaluated_option {
    int64_t number;                     /* 1-based, in order met */
    int generation;                     /* nsga2 generation, else 0 */
    struct design_point point;
    struct option_totals totals;
};

/* How far a run is: the options met of the most it meets, and the work
 * they take, in panels (a grid's nu x nv, the same for each of its
 * thresholds; a project's option counts 1). An option of 2000 x 2000 takes
 * a thousand times one of 60 x 60, and an exhaustive walk's grids grow
 * finer as it goes: time left follows the work left, not the options left
 * (progress_eta). work_total is exact for an exhaustive walk; for random
 * and NSGA-II, whose points are drawn as they go, it is the work done and
 * the space's mean work for each option still to come. */
struct optimize_progress {
    int64_t done, total;          /* options met (stored or reused) */
    double work_done, work_total; /* panels */
};

struct optimize_hooks {
    void *context;
    /* Commits n new options; a non-zero return ends the run with that
     * error. */
    int (*store)(void *context, const struct evaluated_option *options,
                 size_t n, struct facet_error *err);
    /* Reports progress (struct optimize_progress). */
    void (*progress)(void *context, const struct optimize_progress *p);
    /* Non-zero when the user asked to stop: asked between batches and,
     * from the evaluating threads at once, while a batch is evaluated
     * (core/base/stop.h): it must be cheap and thread-safe. */
    int (*should_stop)(void *context);
};

enum optimize_outcome { OPTIMIZE_DONE, OPTIMIZE_INTERRUPTED };

/* How the caller's user names the fields of a design space, for the
 * messages of the parsers and checks below: the CLI's flags ("--u"), the
 * New-run form's labels ("U (panels)"). NULL: "u", "v", "threshold". */
struct design_space_names {
    const char *u, *v, *threshold;
};

/* Names: "exhaustive", "random", "nsga2". */
const char *optimize_method_name(enum optimize_method method);
/* The method named text into *out; FACET_EINPUT naming the field what
 * (the caller's name for it) and the choices. */
int optimize_method_parse(const char *text, const char *what,
                          enum optimize_method *out,
                          struct facet_error *err);

/* Number of points of the exhaustive cross product (threshold steps from
 * t_min to t_max inclusive, to within a thousandth of a step). */
uint64_t design_space_size(const struct design_space *space);

/* The mean panels of a grid of space, nu x nv over its grids:
 * (u_min + u_max) / 2 x (v_min + v_max) / 2, what an option of it takes on
 * average (struct optimize_progress); of the whole cross product exactly,
 * of points drawn from it in expectation. */
double design_space_mean_panels(const struct design_space *space);

/* Parses a grid range as a designer writes it, "20:40" or "30" (a
 * numrange.h range of whole numbers, 1 to PANEL_MAX_GRID, no step), into
 * *lo, *hi. FACET_EINPUT with numrange.h's message naming the field what
 * ("--u", "U (panels)"). */
int design_space_parse_sides(const char *text, const char *what, int *lo,
                             int *hi, struct facet_error *err);

/* Parses a threshold as a designer writes it (mm): "3" (one value), "1:5"
 * (a continuous range) or "1:5:0.5" (stepped), a numrange.h range of
 * decimals 0 to CLASSIFY_THRESHOLD_MAX_MM of at most
 * DESIGN_THRESHOLD_STEPS_MAX steps, into space's t_min_mm, t_max_mm and
 * t_step_mm (0 for none). FACET_EINPUT with numrange.h's message naming
 * the field what. */
int design_space_parse_threshold(const char *text, const char *what,
                                 struct design_space *space,
                                 struct facet_error *err);

/* The most threshold steps an exhaustive space may have. */
#define DESIGN_THRESHOLD_STEPS_MAX 1000000

/* Checks ranges (1 <= min <= max <= PANEL_MAX_GRID, finite thresholds
 * >= 0, step >= 0, at most DESIGN_THRESHOLD_STEPS_MAX threshold steps).
 * FACET_EINPUT names the bad range as names (NULL: plain words) do. */
int design_space_check(const struct design_space *space,
                       const struct design_space_names *names,
                       struct facet_error *err);

/* Checks that method can search space: the exhaustive method needs a
 * stepped (or single) threshold. FACET_EINPUT naming the threshold as
 * names do. */
int optimize_method_check(enum optimize_method method,
                          const struct design_space *space,
                          const struct design_space_names *names,
                          struct facet_error *err);

/* The options a run of settings evaluates at most (a point met twice is
 * evaluated once): the space for exhaustive, the evaluations for random,
 * population x generations for NSGA-II (nsga2.h: the first generation
 * counts); of a shard, its share of
 * them (an NSGA-II island evaluates as many as a whole run). */
int64_t optimize_total(const struct optimize_settings *settings);

/* optimize_total for a search with evaluator (NULL: a single surface's),
 * into *total: an exhaustive walk of an evaluator with a canonical hook
 * evaluates each distinct canonical grid's thresholds once, so its total
 * (and a shard's deal, shard.h's shard_grid_unit) is over those grids,
 * in the order the walk first meets them. FACET_EWORK when out of
 * memory. */
struct option_evaluator;
int optimize_total_with(const struct option_evaluator *evaluator,
                        const struct optimize_settings *settings,
                        int64_t *total, struct facet_error *err);

/* What evaluates a run's options: a single surface's evaluation (what
 * optimize_run gives the search) or a project's (core/project/
 * project_search.h). The search itself (methods, the point cache,
 * batches, numbering, the hooks) is the same for both. */
struct option_evaluator {
    void *context;
    /* Replaces *point by the point that stands for every point whose
     * option is the same (a project's modules that give every surface
     * the same grid), the same whatever the order points are met in;
     * NULL: every point is its own. The search dedupes, numbers and
     * stores the points it gives. */
    void (*canonical)(void *context, struct design_point *point);
    /* Evaluates points[0..n) (canonical) with base on up to jobs threads
     * into totals[0..n). The store hook's next call receives exactly
     * these options, in this order, so an evaluator may keep what it
     * computed beside the totals (a project's per-surface rows) for the
     * store to take. It asks stop (NULL: never) at least between options
     * and returns FACET_ESTOP when it fires: totals are then not valid. */
    int (*evaluate)(void *context, const struct option_params *base,
                    const struct design_point *points, size_t n, int jobs,
                    const struct facet_stop *stop,
                    struct option_totals *totals, struct facet_error *err);
};

/* Runs the search of settings with evaluator, as optimize_run (below)
 * does for a surface. */
int optimize_run_with(const struct option_evaluator *evaluator,
                      const struct optimize_settings *settings,
                      const struct evaluated_option *stored, size_t nstored,
                      const struct optimize_hooks *hooks,
                      enum optimize_outcome *outcome,
                      struct facet_error *err);

/* Runs the search on the prepared surface, the panels of the grids
 * lattice holds (or NULL; see optimize_lattice) taken from it. stored[0..
 * nstored) are the options of the run already committed (resume), else
 * NULL/0. *outcome is OPTIMIZE_DONE or OPTIMIZE_INTERRUPTED (the stop hook
 * fired; everything evaluated was stored). Returns FACET_OK, or the first
 * error of an evaluation or of the store hook. */
int optimize_run(const struct surface *surface,
                 const struct panel_lattice *lattice,
                 const struct optimize_settings *settings,
                 const struct evaluated_option *stored, size_t nstored,
                 const struct optimize_hooks *hooks,
                 enum optimize_outcome *outcome, struct facet_error *err);

/* Evaluates points[0..n) on up to jobs threads into totals[0..n), the
 * panels of the grids lattice holds from it (NULL: none; see
 * option_evaluate's evaluation_shared). */
int optimize_evaluate(const struct surface *surface,
                      const struct panel_lattice *lattice,
                      const struct option_params *base,
                      const struct design_point *points, size_t n, int jobs,
                      struct option_totals *totals, struct facet_error *err);

/* Like optimize_evaluate, keeping every point's panels: panels[0..n)
 * (caller-owned, each released with panelization_free; all released
 * already when it fails), asking stop (NULL: never) as a search does:
 * FACET_ESTOP when it fires. */
int optimize_evaluate_panels(const struct surface *surface,
                             const struct panel_lattice *lattice,
                             const struct option_params *base,
                             const struct design_point *points, size_t n,
                             int jobs, const struct facet_stop *stop,
                             struct panelization *panels,
                             struct option_totals *totals,
                             struct facet_error *err);

/* The lattice a run with settings takes its panels from
 * (panel_lattice_build, on settings->jobs threads), when it evaluates
 * enough grids that share enough lines to pay for one; else NULL, with
 * FACET_OK. The choice depends on the settings alone, so that a resumed
 * run takes its panels the same way as the run it resumes and its options
 * come out the same to the bit. */
int optimize_lattice(const struct surface *surface,
                     const struct optimize_settings *settings,
                     struct panel_lattice **out, struct facet_error *err);

/* optimize_lattice, asking stop (core/base/stop.h) while the surface is
 * divided: FACET_ESTOP when it fires, *out NULL. */
int optimize_lattice_stoppable(const struct surface *surface,
                               const struct optimize_settings *settings,
                               const struct facet_stop *stop,
                               struct panel_lattice **out,
                               struct facet_error *err);

/* The joint lines (joint_length.h) of every grid of space, measured once
 * on jobs threads into *out (caller-owned, released with joint_lines_free,
 * also after a failure): what a run with a lattice takes every option's
 * joint length from. */
int optimize_joint_lines(const struct surface *surface,
                         const struct design_space *space, int jobs,
                         struct joint_lines *out, struct facet_error *err);

#endif
