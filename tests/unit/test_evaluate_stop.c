/*
 * test_evaluate_stop: a stop is heard inside each stage of an option's
 * evaluation, not only between stages (issue 32 item 7).
 *
 * The truth is the stage hook itself (evaluate.h's shared->stage): the
 * stop below answers "stop" only once the evaluation has entered the
 * stage under test and has asked it again there. A stage that asks
 * between stages only is asked once, after its work, and never a second
 * time before the next stage starts: the evaluation then runs to the end
 * (FACET_OK), or is stopped in a later stage, and the test fails. It also
 * counts the questions within the stage: a fine grid's stage takes
 * seconds, so it must ask about once per grid line or row, not once.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "core/base/stop.h"
#include "core/evaluate/evaluate.h"
#include "core/evaluate/option.h"
#include "core/project/project_option.h"
#include "core/surface/surface.h"
#include "tests/support/surface_fixture.h"

#define GRID 96

struct stop_in_stage {
    const char *wanted;     /* the stage to stop in */
    const char *current;    /* the stage the hook last told */
    int asked_in_stage;     /* questions since the wanted stage began */
    int fire_at;            /* stop at this question within the stage */
    int fired;
    const char *fired_in;   /* the stage it fired in */
};

static void told(void *context, const char *what)
{
    struct stop_in_stage *s = context;
    s->current = what;
}

static int requested(void *context)
{
    struct stop_in_stage *s = context;
    if (s->current == NULL || strcmp(s->current, s->wanted) != 0)
        return 0;
    if (++s->asked_in_stage < s->fire_at)
        return 0;
    if (!s->fired) {
        s->fired = 1;
        s->fired_in = s->current;
    }
    return 1;
}

static struct surface roof;

static int setup(void **state)
{
    (void)state;
    struct facet_error err;
    if (surface_fixture_example("roof", 40, &roof, &err) != FACET_OK) {
        print_error("roof: %s\n", err.message);
        return -1;
    }
    return 0;
}

static int teardown(void **state)
{
    (void)state;
    surface_close(&roof);
    return 0;
}

/* Evaluates the roof at GRID x GRID, t = 0.1 mm (SP and DP panels in
 * plenty, so that every stage has work), every measure taken, stopping
 * at question fire_at within stage wanted. Returns what option_evaluate
 * returned; *s tells where it fired. */
static int evaluate_stopping(const char *wanted, int fire_at,
                             struct stop_in_stage *s)
{
    memset(s, 0, sizeof *s);
    s->wanted = wanted;
    s->fire_at = fire_at;
    struct facet_stop stop = {requested, s};
    struct option_params base;
    option_params_defaults(&base);
    struct option_params params = option_params_at(&base, GRID, GRID, 0.1);
    params.unmeasured = 0;
    const struct evaluation_shared shared = {
        .stop = &stop, .stage = told, .stage_context = s};
    struct panelization panels;
    struct option_totals totals;
    struct facet_error err;
    memset(&panels, 0, sizeof panels);
    int rc = option_evaluate(&roof, &params, &shared, &panels, &totals, &err);
    panelization_free(&panels);
    return rc;
}

static void stops_inside(const char *stage)
{
    struct stop_in_stage s;
    /* Asked a second time within the stage: inside its work. */
    assert_int_equal(evaluate_stopping(stage, 2, &s), FACET_ESTOP);
    assert_true(s.fired);
    assert_string_equal(s.fired_in, stage);
    /* And often: at least once per grid line or row of the grid. */
    evaluate_stopping(stage, 1 << 30, &s);
    print_message("%s: asked %d times within the stage\n", stage,
                  s.asked_in_stage);
    assert_true(s.asked_in_stage >= GRID);
}

static void test_stop_in_joint_lines(void **state)
{
    (void)state;
    stops_inside("measuring the joint lines");
}

static void test_stop_in_fits_and_joints(void **state)
{
    (void)state;
    stops_inside("fitting panels, measuring joints");
}

static void test_stop_in_moulds(void **state)
{
    (void)state;
    /* The moulds ask every few hundred panels and at every band of
     * samples: fewer questions than grid lines is not the point here, a
     * question inside the work is. */
    struct stop_in_stage s;
    assert_int_equal(evaluate_stopping("finding the mould families", 2, &s),
                     FACET_ESTOP);
    assert_string_equal(s.fired_in, "finding the mould families");
    evaluate_stopping("finding the mould families", 1 << 30, &s);
    print_message("moulds: asked %d times within the stage\n",
                  s.asked_in_stage);
    assert_true(s.asked_in_stage >= GRID);
}

/* A building: a stop while its surfaces are evaluated, and while its
 * mould families are found over all of them, is heard (before: the
 * project evaluated without any stop). */
static int stop_after_questions(void *context)
{
    int *left = context;
    return --*left < 0;
}

static void test_stop_in_a_building(void **state)
{
    (void)state;
    struct project project;
    memset(&project, 0, sizeof project);
    project.nsurfaces = 1;
    struct project_surface one;
    memset(&one, 0, sizeof one);
    char name[] = "roof";
    one.name = name;
    one.surface = roof;
    project.surfaces = &one;
    struct option_params base;
    option_params_defaults(&base);
    struct option_params params = option_params_at(&base, GRID, GRID, 0.1);
    params.unmeasured = 0;
    struct surface_grid grid = {GRID, GRID};
    struct facet_error err;
    struct project_option option;
    /* Never asked to stop: the evaluation runs whole, and counts the
     * questions. */
    int left = 1 << 30;
    struct facet_stop stop = {stop_after_questions, &left};
    assert_int_equal(project_option_evaluate_stoppable(&project, &grid,
                                                       &params, 1, &stop,
                                                       &option, &err),
                     FACET_OK);
    project_option_free(&option);
    int asked = (1 << 30) - left;
    print_message("a building of one surface: asked %d times\n", asked);
    assert_true(asked >= 4 * GRID);
    /* Stopped at the last question: inside the mould families, the last
     * stage; and at every question from halfway: each is heard. */
    for (int at = asked - 1; at >= asked / 2; at -= asked / 7) {
        left = at;
        assert_int_equal(project_option_evaluate_stoppable(
                             &project, &grid, &params, 1, &stop, &option,
                             &err),
                         FACET_ESTOP);
        project_option_free(&option);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_stop_in_joint_lines),
        cmocka_unit_test(test_stop_in_fits_and_joints),
        cmocka_unit_test(test_stop_in_moulds),
        cmocka_unit_test(test_stop_in_a_building),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
