/*
 * test_optimize.c: the search driver without a store: exhaustive numbering,
 * random distinctness, NSGA-II reproducibility, and that a run stopped and
 * resumed from what it stored ends with exactly the options of a run that
 * was never stopped, for every method; and the ranks of runs on symmetric
 * surfaces against a brute force that treats ties as ties.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "core/evaluate/evaluate.h"
#include "core/surface/example.h"
#include "core/search/front.h"
#include "core/search/optimize.h"
#include "core/panel/panel_lattice.h"
#include "tie_oracle.h"

static struct surface roof;

/* The example roof at res x res quads, prepared, into *out. */
static int open_roof(int res, struct surface *out)
{
    char path[] = "/tmp/facet_test_optimize_XXXXXX";
    int fd = mkstemp(path);
    FILE *file = fdopen(fd, "w");
    struct facet_error err;
    if (example_write("roof", res, file, &err) != FACET_OK)
        return -1;
    fclose(file);
    struct mesh_options options = {UNITS_M, NULL, NULL};
    int rc = surface_open(path, &options, out, &err);
    if (rc == FACET_OK)
        rc = surface_prepare(out, 0, PARAM_AUTO, &err);
    unlink(path);
    return rc;
}

static int setup(void **state)
{
    (void)state;
    return open_roof(24, &roof);
}

static int teardown(void **state)
{
    (void)state;
    surface_close(&roof);
    return 0;
}

/* What a store would hold: every option committed, in order. */
struct log {
    struct evaluated_option *options;
    size_t n, capacity;
    int batches;
    int stop_after;   /* stop once this many batches are stored (0: never) */
};

static int keep(void *context, const struct evaluated_option *options,
                size_t n, struct facet_error *err)
{
    (void)err;
    struct log *log = context;
    if (log->n + n > log->capacity) {
        log->capacity = 2 * (log->n + n);
        log->options = realloc(log->options,
                               log->capacity * sizeof *log->options);
    }
    memcpy(log->options + log->n, options, n * sizeof *options);
    log->n += n;
    log->batches++;
    return 0;
}

static int stop_now(void *context)
{
    struct log *log = context;
    return log->stop_after > 0 && log->batches >= log->stop_after;
}

static void settings_for(enum optimize_method method,
                         struct optimize_settings *s)
{
    memset(s, 0, sizeof *s);
    s->method = method;
    s->space = (struct design_space){4, 9, 5, 8, 1, 5, 2};
    s->base.mode = PANEL_EXTREMES;
    classify_defaults(&s->base.classify);
    /* The search is tested on the paper's typing: as built, every SP
     * panel of this coarse roof is a misfit (DP), planarity is rounding
     * noise and the front one point. */
    s->base.classify.sp_by_class = 1;
    struct facet_error err;
    objectives_parse("cost,planarity,dp_area", "objectives", s->objectives,
                     &s->nobjectives, &err);
    s->seed = 11;
    s->evaluations = 40;
    s->population = 10;
    s->generations = 6;
    s->jobs = 2;
}

static void run(const struct optimize_settings *s, struct log *log,
                const struct evaluated_option *stored, size_t nstored,
                enum optimize_outcome *outcome)
{
    struct optimize_hooks hooks = {log, keep, NULL, stop_now};
    struct facet_error err;
    int rc = optimize_run(&roof, NULL, s, stored, nstored, &hooks, outcome,
                          &err);
    if (rc != FACET_OK)
        fail_msg("%s", err.message);
}

static int by_number(const void *a, const void *b)
{
    const struct evaluated_option *x = a, *y = b;
    return x->number < y->number ? -1 : x->number > y->number;
}

static void assert_same_options(struct evaluated_option *a, size_t na,
                                struct evaluated_option *b, size_t nb)
{
    assert_int_equal(na, nb);
    qsort(a, na, sizeof *a, by_number);
    qsort(b, nb, sizeof *b, by_number);
    for (size_t k = 0; k < na; k++) {
        assert_int_equal(a[k].number, b[k].number);
        assert_int_equal(a[k].point.nu, b[k].point.nu);
        assert_int_equal(a[k].point.nv, b[k].point.nv);
        assert_true(a[k].point.threshold_mm == b[k].point.threshold_mm);
        assert_true(a[k].totals.cost == b[k].totals.cost);
        assert_true(a[k].totals.planarity == b[k].totals.planarity);
        assert_int_equal(a[k].generation, b[k].generation);
    }
}

static void test_exhaustive_numbering(void **state)
{
    (void)state;
    struct optimize_settings s;
    settings_for(METHOD_EXHAUSTIVE, &s);
    assert_int_equal(design_space_size(&s.space), 6 * 4 * 3);
    struct log log = {0};
    enum optimize_outcome outcome;
    run(&s, &log, NULL, 0, &outcome);
    assert_int_equal(outcome, OPTIMIZE_DONE);
    assert_int_equal(log.n, 72);
    /* u outermost, then v, then threshold. */
    for (size_t k = 0; k < log.n; k++) {
        const struct evaluated_option *o = &log.options[k];
        assert_int_equal(o->number, (int64_t)k + 1);
        assert_int_equal(o->point.nu, 4 + (int)(k / 12));
        assert_int_equal(o->point.nv, 5 + (int)(k / 3 % 4));
        assert_true(o->point.threshold_mm == 1 + 2.0 * (double)(k % 3));
    }
    free(log.options);
}

static void test_random_is_distinct(void **state)
{
    (void)state;
    struct optimize_settings s;
    settings_for(METHOD_RANDOM, &s);
    struct log log = {0};
    enum optimize_outcome outcome;
    run(&s, &log, NULL, 0, &outcome);
    assert_int_equal(log.n, 40);
    for (size_t a = 0; a < log.n; a++)
        for (size_t b = a + 1; b < log.n; b++)
            assert_false(log.options[a].point.nu == log.options[b].point.nu &&
                         log.options[a].point.nv == log.options[b].point.nv &&
                         log.options[a].point.threshold_mm ==
                             log.options[b].point.threshold_mm);
    free(log.options);
}

static void test_nsga2_same_seed_same_options(void **state)
{
    (void)state;
    struct optimize_settings s;
    settings_for(METHOD_NSGA2, &s);
    s.space.t_step_mm = 0;
    struct log a = {0}, b = {0};
    enum optimize_outcome outcome;
    run(&s, &a, NULL, 0, &outcome);
    s.jobs = 1;
    run(&s, &b, NULL, 0, &outcome);
    assert_true(a.n > 10);
    assert_same_options(a.options, a.n, b.options, b.n);
    free(a.options);
    free(b.options);
}

/* Stops after two batches, resumes from what was stored, and compares
 * with a run that was never stopped. */
static void check_resume(enum optimize_method method)
{
    struct optimize_settings s;
    settings_for(method, &s);
    if (method == METHOD_NSGA2) {
        /* Room for every generation to find new points. */
        s.space = (struct design_space){4, 40, 5, 40, 1, 9, 0};
        s.generations = 8;
    }
    struct log whole = {0}, first = {0};
    enum optimize_outcome outcome;
    run(&s, &whole, NULL, 0, &outcome);
    assert_int_equal(outcome, OPTIMIZE_DONE);
    first.stop_after = 2;
    run(&s, &first, NULL, 0, &outcome);
    assert_int_equal(outcome, OPTIMIZE_INTERRUPTED);
    assert_true(first.n < whole.n);
    struct log rest = {0};
    run(&s, &rest, first.options, first.n, &outcome);
    assert_int_equal(outcome, OPTIMIZE_DONE);
    /* Nothing stored was evaluated or stored again. */
    assert_int_equal(first.n + rest.n, whole.n);
    struct evaluated_option *all = malloc(whole.n * sizeof *all);
    memcpy(all, first.options, first.n * sizeof *all);
    memcpy(all + first.n, rest.options, rest.n * sizeof *all);
    assert_same_options(all, whole.n, whole.options, whole.n);
    free(all);
    free(whole.options);
    free(first.options);
    free(rest.options);
}

static void test_resume_exhaustive(void **state)
{
    (void)state;
    check_resume(METHOD_EXHAUSTIVE);
}

static void test_resume_random(void **state)
{
    (void)state;
    check_resume(METHOD_RANDOM);
}

static void test_resume_nsga2(void **state)
{
    (void)state;
    check_resume(METHOD_NSGA2);
}

static void test_front(void **state)
{
    (void)state;
    struct optimize_settings s;
    settings_for(METHOD_EXHAUSTIVE, &s);
    struct log log = {0};
    enum optimize_outcome outcome;
    run(&s, &log, NULL, 0, &outcome);
    for (size_t k = 0; k < log.n; k++)
        assert_true(log.options[k].totals.max_panel_area < 100);
    struct front front;
    struct facet_error err;
    assert_int_equal(front_analyse(log.options, log.n, s.objectives,
                                   s.nobjectives, 100, &front, &err),
                     FACET_OK);
    assert_true(front.pareto > 0);
    assert_true(front.knee < log.n && front.rank[front.knee] == 1);
    assert_true(front.hypervolume > 0 && front.hypervolume <= 1.331);
    /* Brute force, with ties as ties (tie_oracle.h): every rank. */
    size_t m = (size_t)s.nobjectives;
    double *f = malloc(log.n * m * sizeof *f);
    int *expected = malloc(log.n * sizeof *expected);
    for (size_t a = 0; a < log.n; a++)
        for (size_t j = 0; j < m; j++)
            f[a * m + j] = objective_value(&log.options[a].totals,
                                           &s.objectives[j]);
    brute_rank_within(f, NULL, log.n, m, expected);
    for (size_t a = 0; a < log.n; a++)
        assert_int_equal(front.rank[a], expected[a]);
    free(f);
    free(expected);
    front_free(&front);
    free(log.options);
}

/* Surfaces with exact symmetries (a torus section, a barrel vault, a
 * plane) give many options whose totals are equal in exact arithmetic and
 * differ by rounding: a grid and its mirror image, or on the plane every
 * grid's cost. The run's ranks (front_analyse, from a lattice as
 * `facet optimize` takes them) must be those of a brute force with the
 * same tolerance (tie_oracle.h). With exact comparisons, the torus's
 * paper space has 61 options of rank 1 where 36 are Pareto-optimal. */
static void test_front_ties_on_symmetric_surfaces(void **state)
{
    (void)state;
    const char *const names[] = {"torus", "cylinder", "plane"};
    for (int e = 0; e < 3; e++) {
        char path[] = "/tmp/facet_test_ties_XXXXXX";
        int fd = mkstemp(path);
        FILE *out = fdopen(fd, "w");
        struct facet_error err;
        assert_int_equal(example_write(names[e], 60, out, &err), FACET_OK);
        fclose(out);
        struct surface surface;
        struct mesh_options options = {UNITS_M, NULL, NULL};
        assert_int_equal(surface_open(path, &options, &surface, &err),
                         FACET_OK);
        unlink(path);
        assert_int_equal(surface_prepare(&surface, 0, PARAM_AUTO, &err), FACET_OK);

        struct optimize_settings s;
        settings_for(METHOD_EXHAUSTIVE, &s);
        s.space = (struct design_space){20, 40, 35, 50, 3, 3, 0};
        struct panel_lattice *lattice;
        assert_int_equal(optimize_lattice(&surface, &s, &lattice, &err),
                         FACET_OK);
        struct log log = {0};
        enum optimize_outcome outcome;
        struct optimize_hooks hooks = {&log, keep, NULL, stop_now};
        assert_int_equal(optimize_run(&surface, lattice, &s, NULL, 0, &hooks,
                                      &outcome, &err), FACET_OK);
        size_t n = log.n, m = (size_t)s.nobjectives;
        assert_int_equal(n, 21 * 16);

        double limit = s.base.classify.max_panel_area;
        struct front front;
        assert_int_equal(front_analyse(log.options, n, s.objectives,
                                       s.nobjectives, limit, &front, &err),
                         FACET_OK);
        double *f = malloc(n * m * sizeof *f);
        double *violation = malloc(n * sizeof *violation);
        int *expected = malloc(n * sizeof *expected);
        for (size_t i = 0; i < n; i++) {
            const struct option_totals *t = &log.options[i].totals;
            for (size_t j = 0; j < m; j++)
                f[i * m + j] = objective_value(t, &s.objectives[j]);
            violation[i] = t->max_panel_area > limit
                               ? t->max_panel_area - limit : 0;
        }
        brute_rank_within(f, violation, n, m, expected);
        size_t pareto = 0;
        for (size_t i = 0; i < n; i++) {
            assert_int_equal(front.rank[i], expected[i]);
            pareto += expected[i] == 1;
        }
        assert_int_equal(front.pareto, pareto);
        print_message("%s: %zu options, %zu Pareto-optimal\n", names[e], n,
                      pareto);
        free(f);
        free(violation);
        free(expected);
        front_free(&front);
        free(log.options);
        panel_lattice_free(lattice);
        surface_close(&surface);
    }
}

/* A run over enough grids takes them from a lattice (optimize_lattice
 * says so from the settings alone, for every method); its options are the
 * run without one, to 1e-9, in the same order. */
static void test_lattice_run(void **state)
{
    (void)state;
    for (int m = 0; m < 3; m++) {
        struct optimize_settings s;
        settings_for((enum optimize_method)m, &s);
        s.space = (struct design_space){4, 10, 5, 10, 1, 5, 2};
        s.evaluations = 60;
        struct panel_lattice *lattice;
        struct facet_error err;
        assert_int_equal(optimize_lattice(&roof, &s, &lattice, &err),
                         FACET_OK);
        assert_non_null(lattice);
        struct log with = {0}, without = {0};
        enum optimize_outcome outcome;
        struct optimize_hooks hooks = {&with, keep, NULL, stop_now};
        assert_int_equal(optimize_run(&roof, lattice, &s, NULL, 0, &hooks,
                                      &outcome, &err), FACET_OK);
        panel_lattice_free(lattice);
        run(&s, &without, NULL, 0, &outcome);
        assert_int_equal(with.n, without.n);
        for (size_t k = 0; k < with.n; k++) {
            const struct evaluated_option *a = &with.options[k];
            const struct evaluated_option *b = &without.options[k];
            assert_int_equal(a->number, b->number);
            assert_int_equal(a->point.nu, b->point.nu);
            assert_int_equal(a->point.nv, b->point.nv);
            for (int t = 0; t < TYPE_COUNT; t++)
                assert_int_equal(a->totals.count[t], b->totals.count[t]);
            assert_true(fabs(a->totals.cost - b->totals.cost) <=
                        1e-9 * b->totals.cost);
            /* Flat panels deviate by nothing, to rounding. */
            assert_true(fabs(a->totals.planarity - b->totals.planarity) <=
                        1e-9 * b->totals.planarity + 1e-12);
        }
        free(with.options);
        free(without.options);
    }
    /* Too few grids to pay for one: none. */
    struct optimize_settings few;
    settings_for(METHOD_EXHAUSTIVE, &few);
    struct panel_lattice *none;
    struct facet_error err;
    assert_int_equal(optimize_lattice(&roof, &few, &none, &err), FACET_OK);
    assert_null(none);
}

/* A grid's thresholds evaluated together keep its SP fits and sides
 * (option_evaluate with the grid's fits kept): every option's totals are, to the bit, those of
 * the option evaluated alone, as a shard holding only some of the grid's
 * thresholds evaluates them. */
static void test_grid_thresholds_equal_alone(void **state)
{
    (void)state;
    /* Finer than the search tests' roof, so that SP panels fit. */
    struct surface fine;
    assert_int_equal(open_roof(96, &fine), FACET_OK);
    struct optimize_settings s;
    settings_for(METHOD_EXHAUSTIVE, &s);
    s.base.classify.sp_by_class = 0;
    struct design_point points[3 * 3 * 3];
    size_t n = 0;
    for (int nu = 8; nu <= 16; nu += 4)
        for (int nv = 10; nv <= 12; nv++)
            for (int t = 2; t <= 18; t *= 3)
                points[n++] = (struct design_point){nu, nv, (double)t};
    struct option_totals together[3 * 3 * 3];
    struct facet_error err;
    if (optimize_evaluate(&fine, NULL, &s.base, points, n, 2, together,
                          &err) != FACET_OK)
        fail_msg("%s", err.message);
    size_t sp = 0, fitted = 0;
    for (size_t k = 0; k < n; k++) {
        struct option_params params = option_params_at(
            &s.base, points[k].nu, points[k].nv, points[k].threshold_mm);
        struct panelization panels;
        struct option_totals alone;
        if (option_evaluate(&fine, &params, NULL, &panels, &alone, &err) !=
            FACET_OK)
            fail_msg("%s", err.message);
        panelization_free(&panels);
        if (memcmp(&alone, &together[k], sizeof alone) != 0)
            fail_msg("%d x %d at %g mm: totals differ from the option "
                     "alone (cost %.17g against %.17g, max gap %.17g "
                     "against %.17g)", points[k].nu, points[k].nv,
                     points[k].threshold_mm, together[k].cost, alone.cost,
                     together[k].max_gap, alone.max_gap);
        sp += alone.sp_fitted + alone.sp_misfits;
        fitted += alone.sp_fitted;
    }
    surface_close(&fine);
    /* The comparison saw SP panels fitted, not only misfits. */
    assert_true(sp > fitted && fitted > 0);
}

static void test_bad_space(void **state)
{
    (void)state;
    struct optimize_settings s;
    settings_for(METHOD_EXHAUSTIVE, &s);
    s.space.u_min = 0;
    struct log log = {0};
    struct optimize_hooks hooks = {&log, keep, NULL, NULL};
    enum optimize_outcome outcome;
    struct facet_error err;
    assert_int_equal(optimize_run(&roof, NULL, &s, NULL, 0, &hooks, &outcome,
                                  &err),
                     FACET_EINPUT);
    /* below the CLI the field is named in words, not as a flag */
    assert_non_null(strstr(err.message, "u 0:9 is not a range within 1.."));
    assert_null(strstr(err.message, "--"));
    free(log.options);
}

/* The design space as a designer types it, in the CLI and the TUI alike. */
static void test_parse_space(void **state)
{
    (void)state;
    struct facet_error err;
    struct design_space s = {1, 1, 1, 1, 0, 0, 0};  /* one grid */
    int lo, hi;
    assert_int_equal(design_space_parse_sides("20:40", "--u", &lo, &hi,
                                              &err), FACET_OK);
    assert_int_equal(lo, 20);
    assert_int_equal(hi, 40);
    assert_int_equal(design_space_parse_sides("30", "--u", &lo, &hi, &err),
                     FACET_OK);
    assert_int_equal(lo * 100 + hi, 3030);
    assert_int_equal(design_space_parse_sides("20:", "--u", &lo, &hi, &err),
                     FACET_EINPUT);
    assert_non_null(strstr(err.message, "--u"));
    assert_int_equal(design_space_parse_sides("2x3", "--v", &lo, &hi, &err),
                     FACET_EINPUT);
    assert_int_equal(design_space_parse_threshold("3", "t", &s, &err), FACET_OK);
    assert_true(s.t_min_mm == 3 && s.t_max_mm == 3 && s.t_step_mm == 0);
    assert_int_equal(design_space_parse_threshold("1:5", "t", &s, &err),
                     FACET_OK);
    assert_true(s.t_min_mm == 1 && s.t_max_mm == 5 && s.t_step_mm == 0);
    assert_int_equal(design_space_parse_threshold("1:5:0.5", "t", &s, &err),
                     FACET_OK);
    assert_true(s.t_step_mm == 0.5);
    assert_int_equal(design_space_size(&s), 9);
    /* -0 is the 0 it means: no "-0 mm" in a run's settings */
    assert_int_equal(design_space_parse_threshold("-0:-0", "t", &s, &err),
                     FACET_OK);
    assert_false(signbit(s.t_min_mm) || signbit(s.t_max_mm));
    const char *bad[] = {"", "x", "5:1", "1:5:0", "1:2:3:4", "-1", "1e9",
                         "2:", "nan", "1::2"};
    for (size_t k = 0; k < sizeof bad / sizeof *bad; k++) {
        assert_int_equal(design_space_parse_threshold(bad[k], "t", &s, &err),
                         FACET_EINPUT);
        assert_null(strchr(err.message, '\n'));
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_exhaustive_numbering),
        cmocka_unit_test(test_random_is_distinct),
        cmocka_unit_test(test_nsga2_same_seed_same_options),
        cmocka_unit_test(test_resume_exhaustive),
        cmocka_unit_test(test_resume_random),
        cmocka_unit_test(test_resume_nsga2),
        cmocka_unit_test(test_front),
        cmocka_unit_test(test_front_ties_on_symmetric_surfaces),
        cmocka_unit_test(test_lattice_run),
        cmocka_unit_test(test_grid_thresholds_equal_alone),
        cmocka_unit_test(test_bad_space),
        cmocka_unit_test(test_parse_space),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
