/*
 * test_progress.c: a search's time left follows its work, not its option
 * count (issue 32 item 8). An exhaustive walk's grids grow finer as it
 * goes (u outermost), so its later options take longer: weighing options
 * by their panels makes the ETA right where the count made it about 2x
 * low. The truths are sums by hand over a small space.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <string.h>

#include "cli/progress.h"
#include "core/search/optimize.h"

/* The reports a search made. */
struct reports {
    struct optimize_progress at[16];
    int n;
};

/* Every option costs its grid's panels; nothing else is read. */
static int panel_cost(void *context, const struct option_params *base,
                      const struct design_point *points, size_t n, int jobs,
                      const struct facet_stop *stop,
                      struct option_totals *totals, struct facet_error *err)
{
    (void)context;
    (void)base;
    (void)jobs;
    (void)stop;
    (void)err;
    for (size_t k = 0; k < n; k++) {
        memset(&totals[k], 0, sizeof totals[k]);
        totals[k].cost = (double)points[k].nu * points[k].nv;
    }
    return FACET_OK;
}

static void record(void *context, const struct optimize_progress *p)
{
    struct reports *r = context;
    assert_true(r->n < 16);
    r->at[r->n++] = *p;
}

/* Runs settings' search to its end with panel_cost, its reports into *r. */
static void run_recorded(const struct optimize_settings *settings,
                         struct reports *r)
{
    struct option_evaluator evaluator = {NULL, NULL, panel_cost};
    memset(r, 0, sizeof *r);
    struct optimize_hooks hooks = {r, NULL, record, NULL};
    enum optimize_outcome outcome;
    struct facet_error err;
    assert_int_equal(optimize_run_with(&evaluator, settings, NULL, 0,
                                       &hooks, &outcome, &err), FACET_OK);
    assert_int_equal(outcome, OPTIMIZE_DONE);
}

/* The time left at the costs fitted: updates that took exactly 0.5 s an
 * option plus 0.002 s a panel give those costs back, and for 10 options
 * of 4,000 panels 5 + 8 = 13 s. Options of the same work each cannot tell
 * the two costs apart: the rate of the work (0.3 s an option of 100
 * panels: 0.003 s a panel, 500 panels left: 1.5 s). Nothing measured:
 * -1. */
static void test_eta(void **state)
{
    (void)state;
    struct progress_fit fit;
    memset(&fit, 0, sizeof fit);
    assert_true(progress_fit_left(&fit, 10, 4000) < 0);
    static const double n[3] = {16, 32, 48}, w[3] = {1000, 5000, 12000};
    for (int k = 0; k < 3; k++)
        progress_fit_add(&fit, n[k], w[k], 0.5 * n[k] + 0.002 * w[k]);
    assert_true(fabs(progress_fit_left(&fit, 10, 4000) - 13) < 1e-9);
    memset(&fit, 0, sizeof fit);
    for (int k = 1; k <= 3; k++)
        progress_fit_add(&fit, 10.0 * k, 1000.0 * k, 3.0 * k);
    assert_true(fabs(progress_fit_left(&fit, 5, 500) - 1.5) < 1e-9);
}

/* u 1:4 x v 1:8 at one threshold, 32 options in batches of 16: the first
 * batch is u 1 and 2 (the walk's order), sum over u in {1, 2} and v in
 * 1..8 of u v = 3 x 36 = 108 panels of the walk's (1 + 2 + 3 + 4) x 36 =
 * 360. Half the options are done but under a third of the work: the time
 * left is 252 / 108 = 2.33 times the time taken, not 1 time. */
static void test_exhaustive_work(void **state)
{
    (void)state;
    struct optimize_settings settings;
    memset(&settings, 0, sizeof settings);
    settings.method = METHOD_EXHAUSTIVE;
    settings.space = (struct design_space){1, 4, 1, 8, 3, 3, 0};
    settings.jobs = 1;
    struct reports r;
    run_recorded(&settings, &r);
    assert_int_equal(r.n, 2);
    assert_int_equal(r.at[0].done, 16);
    assert_int_equal(r.at[0].total, 32);
    assert_true(r.at[0].work_done == 108);
    assert_true(r.at[0].work_total == 360);
    assert_int_equal(r.at[1].done, 32);
    assert_true(r.at[1].work_done == 360);
    assert_true(r.at[1].work_total == 360);
    /* 1 s for the first batch, all of it put down to its panels (one
     * update cannot tell an option's fixed cost from its panels'): 2.33 s
     * left, where the count says 1 s. */
    struct progress_fit fit;
    memset(&fit, 0, sizeof fit);
    progress_fit_add(&fit, (double)r.at[0].done, r.at[0].work_done, 1);
    double left = progress_fit_left(&fit,
                                    (double)(r.at[0].total - r.at[0].done),
                                    r.at[0].work_total - r.at[0].work_done);
    assert_true(fabs(left - 252.0 / 108) < 1e-12);
}

/* NSGA-II draws its points as it goes: its total work is what it did and
 * the space's mean panels (u 1:4, v 1:8: 2.5 x 4.5) for each option to
 * come; at its end, what it did. */
static void test_nsga2_work(void **state)
{
    (void)state;
    struct optimize_settings settings;
    memset(&settings, 0, sizeof settings);
    settings.method = METHOD_NSGA2;
    settings.space = (struct design_space){1, 4, 1, 8, 3, 3, 0};
    settings.jobs = 1;
    settings.population = 8;
    settings.generations = 3;
    settings.seed = 5;
    settings.objectives[0] = objective_named("cost");
    settings.nobjectives = 1;
    struct reports r;
    run_recorded(&settings, &r);
    assert_int_equal(r.n, 3);
    assert_int_equal(r.at[0].done, 8);
    assert_int_equal(r.at[0].total, 24);
    assert_true(fabs(r.at[0].work_total -
                     (r.at[0].work_done + 16 * 2.5 * 4.5)) < 1e-9);
    assert_int_equal(r.at[2].done, 24);
    assert_true(r.at[2].work_total == r.at[2].work_done);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_eta),
        cmocka_unit_test(test_exhaustive_work),
        cmocka_unit_test(test_nsga2_work),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
