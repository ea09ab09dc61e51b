/*
 * test_project_search.c: a building's modules as the search's integer
 * points (core/project/project_search.h). The truth is brute force: every
 * module of the range mapped to its grid vector here, with the module
 * rule written out (nu = max(1, floor(L / w + 1/2))), and the vectors
 * compared pairwise.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/project/project_search.h"

enum { SURFACES = 3 };

/* A project of three surfaces of which only the lengths are read. */
static void project_of(struct project *p, struct project_surface *s)
{
    memset(p, 0, sizeof *p);
    memset(s, 0, SURFACES * sizeof *s);
    static const double lu[SURFACES] = {12.0, 7.3, 20.05};
    static const double lv[SURFACES] = {3.6, 9.9, 4.45};
    for (int i = 0; i < SURFACES; i++) {
        s[i].u_length = lu[i];
        s[i].v_length = lv[i];
    }
    p->nsurfaces = SURFACES;
    p->surfaces = s;
}

static int count_along(double length, double module)
{
    int n = (int)floor(length / module + 0.5);
    return n < 1 ? 1 : n;
}

/* Module k of the range, widths outermost, the values as module.h says. */
static void module_of(const struct module_range *r, size_t widths,
                      size_t heights, size_t k, double *w, double *h)
{
    (void)widths;
    *w = round((r->width_min + (double)(k / heights) * r->width_step) * 1e9)
         / 1e9;
    *h = round((r->height_min + (double)(k % heights) * r->height_step) *
               1e9) / 1e9;
}

static void vector_of(const struct project *p, double w, double h,
                      const struct surface_grid *overrides, int *out)
{
    for (size_t i = 0; i < p->nsurfaces; i++) {
        out[2 * i] = count_along(p->surfaces[i].u_length, w);
        out[2 * i + 1] = count_along(p->surfaces[i].v_length, h);
        if (overrides != NULL && overrides[i].nu > 0) {
            out[2 * i] = overrides[i].nu;
            out[2 * i + 1] = overrides[i].nv;
        }
    }
}

/* Every module's canonical point is the first module (by index) of its
 * grid vector; two modules share a canonical point exactly when their
 * vectors are equal; modules counts each vector's modules; the grids
 * are the vector's. */
static void check_range(const struct module_range *range,
                        const struct surface_grid *overrides)
{
    struct project p;
    struct project_surface s[SURFACES];
    project_of(&p, s);
    struct project_search search;
    struct facet_error err;
    assert_int_equal(project_search_init(&search, &p, range, overrides,
                                         &err), FACET_OK);
    size_t widths = search.widths, heights = search.heights;
    assert_int_equal(widths, module_widths(range));
    size_t n = widths * heights;
    int(*vector)[2 * SURFACES] = calloc(n, sizeof *vector);
    assert_non_null(vector);
    for (size_t k = 0; k < n; k++) {
        double w, h;
        module_of(range, widths, heights, k, &w, &h);
        vector_of(&p, w, h, overrides, vector[k]);
    }
    size_t distinct = 0;
    for (size_t k = 0; k < n; k++) {
        struct design_point point = {(int)(k / heights) + 1,
                                     (int)(k % heights) + 1, 3};
        struct surface_grid grids[SURFACES];
        project_search_grids(&search, &point, grids);
        for (int i = 0; i < SURFACES; i++) {
            assert_int_equal(grids[i].nu, vector[k][2 * i]);
            assert_int_equal(grids[i].nv, vector[k][2 * i + 1]);
        }
        size_t first = k, members = 0;
        for (size_t j = n; j-- > 0;)
            if (memcmp(vector[j], vector[k], sizeof vector[k]) == 0) {
                first = j;
                members++;
            }
        distinct += first == k;
        struct design_point canonical = point;
        search.evaluator.canonical(search.evaluator.context, &canonical);
        assert_int_equal((size_t)(canonical.nu - 1) * heights +
                             (size_t)(canonical.nv - 1), first);
        assert_true(canonical.threshold_mm == 3);
        assert_int_equal(project_search_modules(&search, &point), members);
        double w, h, cw, ch;
        project_search_module(&search, &point, &w, &h);
        module_of(range, widths, heights, k, &cw, &ch);
        assert_true(w == cw && h == ch);
    }
    assert_true(distinct < n);  /* the range has modules of one vector */
    free(vector);
    project_search_free(&search);
}

static void test_canonical_modules(void **state)
{
    (void)state;
    struct module_range range = {1.0, 4.0, 0.1, 0.8, 3.0, 0.2};
    check_range(&range, NULL);
}

static void test_canonical_with_override(void **state)
{
    (void)state;
    struct module_range range = {1.0, 2.5, 0.05, 1.0, 2.0, 0.25};
    struct surface_grid overrides[SURFACES] = {{0, 0}, {6, 2}, {0, 0}};
    check_range(&range, overrides);
}

/* A range of more values than a grid side may take is refused. */
static void test_too_many_values(void **state)
{
    (void)state;
    struct project p;
    struct project_surface s[SURFACES];
    project_of(&p, s);
    struct module_range range = {0.001, 3.0, 0.001, 1.0, 1.0, 0.1};
    struct project_search search;
    struct facet_error err;
    assert_int_equal(project_search_init(&search, &p, &range, NULL, &err),
                     FACET_EINPUT);
    assert_non_null(strstr(err.message, "3000 widths"));
    project_search_free(&search);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_canonical_modules),
        cmocka_unit_test(test_canonical_with_override),
        cmocka_unit_test(test_too_many_values),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
