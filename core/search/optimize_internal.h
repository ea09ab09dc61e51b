/*
 * optimize_internal.h: the state every search method shares (internal to
 * optimize*.c): the options the run knows, a hash of their design points,
 * and the batch step that evaluates what is new and hands it to the store.
 */
#ifndef FACET_OPTIMIZE_INTERNAL_H
#define FACET_OPTIMIZE_INTERNAL_H

#include "core/search/optimize.h"

struct search {
    const struct option_evaluator *evaluator;
    const struct optimize_settings *settings;
    const struct optimize_hooks *hooks;
    struct evaluated_option *known;  /* stored at start, then new ones */
    unsigned char *met;              /* known[k] met in this pass */
    size_t nknown, known_capacity;
    size_t *slot;                    /* open-addressing hash into known */
    size_t capacity;                 /* slots, a power of two */
    int64_t distinct_met;            /* distinct points met so far */
    int64_t done, total;             /* for progress */
    double work_done;                /* panels of the points met */
    double work_exact;               /* > 0: the walk's whole work */
    double work_each;                /* else: the mean of a point's */
};

/* Sets up *s with the run's stored options. Release with search_free. */
int search_init(struct search *s, const struct option_evaluator *evaluator,
                const struct optimize_settings *settings,
                const struct evaluated_option *stored, size_t nstored,
                const struct optimize_hooks *hooks, int64_t total,
                struct facet_error *err);
void search_free(struct search *s);

/* The point that stands for p in s (the evaluator's canonical one, or p
 * itself). */
void search_canonical(const struct search *s, struct design_point *p);

/* Meets points[0..n) in order, each as search_canonical gives it: a point met for the first time gets the
 * next option number, or numbers[k] when numbers is not NULL (a shard's
 * points keep their numbers in the unsharded run); those the run does not have yet are evaluated (in
 * parallel) and stored through the hook, in chunks. index[k] receives the
 * position in s->known of points[k], whose totals are then valid.
 * FACET_ESTOP when the stop hook fired during the batch: the chunks stored
 * before it are kept, the rest of the batch is not evaluated. */
int search_batch(struct search *s, const struct design_point *points,
                 size_t n, int generation, size_t *index,
                 const int64_t *numbers, struct facet_error *err);

/* A search_batch that returned FACET_ESTOP: the run ends interrupted
 * (*outcome), what was stored kept; clears err and returns FACET_OK. */
int search_stopped(enum optimize_outcome *outcome, struct facet_error *err);

/* NSGA-II over the design space (optimize_nsga2.c). */
int run_nsga2(struct search *s, enum optimize_outcome *outcome,
              struct facet_error *err);

#endif
