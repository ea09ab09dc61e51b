/*
 * test_search_stop.c: a stop heard inside a batch (issue 32 item 7). A
 * generation of NSGA-II is one batch; of fine grids it takes minutes, so
 * the search evaluates and stores it in chunks and hears the stop between
 * them and inside them. What was stored before the stop is kept, nothing
 * of the chunk it interrupted is, and a resume from what was stored ends
 * with exactly the options of a run never stopped (the truth: that run).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <stdlib.h>
#include <string.h>

#include "core/search/optimize.h"

/* What a run stored, and when it is to ask for a stop. */
struct run {
    struct evaluated_option stored[4096];
    size_t nstored;
    int stores;          /* store calls so far */
    int stop_after;      /* ask to stop once this many stores: 0 never */
    int evaluating;      /* inside evaluate: stop asked from there */
};

/* A cost and a planarity that trade off, so the front is not one point. */
static int fake_evaluate(void *context, const struct option_params *base,
                         const struct design_point *points, size_t n,
                         int jobs, const struct facet_stop *stop,
                         struct option_totals *totals,
                         struct facet_error *err)
{
    (void)context;
    (void)base;
    (void)jobs;
    for (size_t k = 0; k < n; k++) {
        /* The stop is asked inside the evaluation, too. */
        if (facet_stop_requested(stop))
            return facet_stop_error(err);
        memset(&totals[k], 0, sizeof totals[k]);
        totals[k].cost = points[k].nu * 10.0 + points[k].nv;
        totals[k].planarity = 1000.0 / (points[k].nu * points[k].nv);
    }
    return FACET_OK;
}

static int fake_store(void *context, const struct evaluated_option *options,
                      size_t n, struct facet_error *err)
{
    (void)err;
    struct run *r = context;
    assert_true(r->nstored + n <= 4096);
    memcpy(r->stored + r->nstored, options, n * sizeof *options);
    r->nstored += n;
    r->stores++;
    return FACET_OK;
}

static int fake_should_stop(void *context)
{
    const struct run *r = context;
    return r->stop_after > 0 && r->stores >= r->stop_after;
}

static int by_number(const void *a, const void *b)
{
    const struct evaluated_option *p = a, *q = b;
    return (p->number > q->number) - (p->number < q->number);
}

static void settings_of(struct optimize_settings *s)
{
    memset(s, 0, sizeof *s);
    s->method = METHOD_NSGA2;
    s->space = (struct design_space){1, 60, 1, 60, 3, 3, 0};
    s->jobs = 1;                /* chunks of 16 */
    s->population = 40;         /* a generation: chunks of 16, 16, 8 */
    s->generations = 4;
    s->seed = 11;
    s->objectives[0] = objective_named("cost");
    s->objectives[1] = objective_named("planarity");
    s->nobjectives = 2;
}

static void search(struct run *r, const struct evaluated_option *stored,
                   size_t nstored, enum optimize_outcome *outcome)
{
    struct optimize_settings settings;
    settings_of(&settings);
    struct option_evaluator evaluator = {NULL, NULL, fake_evaluate};
    struct optimize_hooks hooks = {r, fake_store, NULL, fake_should_stop};
    struct facet_error err;
    assert_int_equal(optimize_run_with(&evaluator, &settings, stored,
                                       nstored, &hooks, outcome, &err),
                     FACET_OK);
}

static void test_stop_inside_a_generation(void **state)
{
    (void)state;
    static struct run whole, stopped, resumed;
    enum optimize_outcome outcome;
    memset(&whole, 0, sizeof whole);
    search(&whole, NULL, 0, &outcome);
    assert_int_equal(outcome, OPTIMIZE_DONE);

    /* Stop asked once the first chunk of the first generation is
     * stored: the run ends there, with those 16 options, not the
     * generation's 40. */
    memset(&stopped, 0, sizeof stopped);
    stopped.stop_after = 1;
    search(&stopped, NULL, 0, &outcome);
    assert_int_equal(outcome, OPTIMIZE_INTERRUPTED);
    assert_int_equal(stopped.nstored, 16);
    for (size_t k = 0; k < stopped.nstored; k++)
        assert_true(stopped.stored[k].totals.cost > 0);

    /* Resumed from them: the options of the run never stopped, the same
     * numbers, points and totals; the 16 not evaluated again. */
    memset(&resumed, 0, sizeof resumed);
    search(&resumed, stopped.stored, stopped.nstored, &outcome);
    assert_int_equal(outcome, OPTIMIZE_DONE);
    assert_int_equal(stopped.nstored + resumed.nstored, whole.nstored);
    static struct evaluated_option both[4096];
    memcpy(both, stopped.stored, stopped.nstored * sizeof *both);
    memcpy(both + stopped.nstored, resumed.stored,
           resumed.nstored * sizeof *both);
    qsort(both, whole.nstored, sizeof *both, by_number);
    qsort(whole.stored, whole.nstored, sizeof *whole.stored, by_number);
    for (size_t k = 0; k < whole.nstored; k++) {
        assert_int_equal(both[k].number, whole.stored[k].number);
        assert_int_equal(both[k].point.nu, whole.stored[k].point.nu);
        assert_int_equal(both[k].point.nv, whole.stored[k].point.nv);
        assert_int_equal(both[k].generation, whole.stored[k].generation);
        assert_true(both[k].totals.cost == whole.stored[k].totals.cost);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_stop_inside_a_generation),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
