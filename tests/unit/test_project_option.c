/*
 * test_project_option.c: one design option over a whole project
 * (core/project/project_option.h) and the grids it takes
 * (core/project/project_grids.h).
 *
 * Truths:
 *   - a project of one surface: that surface's option_evaluate, to the
 *     bit, panel by panel and total by total;
 *   - a project of K rigid copies of a torus section written here (each
 *     copy turned and moved): the mould families are known by symmetry
 *     (at a tolerance of 0, the cells of a row are congruent, and so are
 *     the rows mirrored about the equator), so one copy has nv / 2 of them
 *     and K copies have the same nv / 2 shared, where the copies evaluated
 *     on their own need K times as many; panels and areas are K times
 *     one copy's;
 *   - the example skin: every surface evaluated on its own with
 *     option_evaluate (the same numbers, moulds aside) and the building's
 *     totals summed and maximised here by brute force; the module's grid of
 *     a flat face by hand (its sides are 12, 16 and 20 m exactly);
 *   - the same option on 1, 2 and 3 threads: the same bits;
 *   - the grids' hash against FNV-1a computed by Python's struct and int
 *     arithmetic, by hand, outside Facet.
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
#include "core/project/project.h"
#include "core/project/project_grids.h"
#include "core/project/project_option.h"
#include "core/quantity/quantity.h"
#include "core/surface/example.h"
#include "core/surface/example_skin.h"
#include "tests/support/temp_dir.h"

#define PI 3.14159265358979323846

static char dir[64];

static int make_dir(void **state)
{
    (void)state;
    return temp_dir_make(dir, sizeof dir, "project_option");
}

static int remove_dir(void **state)
{
    (void)state;
    return temp_dir_remove(dir);
}

static void same_bits(double a, double b, const char *what)
{
    if (memcmp(&a, &b, sizeof a) != 0)
        fail_msg("%s: %.17g and %.17g differ", what, a, b);
}

/* Every total but the moulds' own (counts and their cost), bit for bit. */
static void same_totals_but_moulds(const struct option_totals *a,
                                   const struct option_totals *b,
                                   const char *what)
{
    char name[160];
#define SAME_COUNT(f)                                                      \
    do {                                                                   \
        if (a->f != b->f)                                                  \
            fail_msg("%s: " #f " %zu and %zu differ", what, (size_t)a->f,  \
                     (size_t)b->f);                                        \
    } while (0)
#define SAME_DOUBLE(f)                                                     \
    do {                                                                   \
        snprintf(name, sizeof name, "%s: " #f, what);                      \
        same_bits(a->f, b->f, name);                                       \
    } while (0)
    SAME_COUNT(panels);
    for (int t = 0; t < TYPE_COUNT; t++) {
        SAME_COUNT(count[t]);
        SAME_DOUBLE(area_of[t]);
        SAME_DOUBLE(cost_of[t]);
    }
    for (int c = 0; c < CLASS_COUNT; c++) {
        SAME_COUNT(class_count[c]);
        SAME_DOUBLE(class_area[c]);
    }
    SAME_DOUBLE(area);
    SAME_DOUBLE(planarity);
    SAME_DOUBLE(max_deviation);
    SAME_DOUBLE(max_panel_area);
    SAME_DOUBLE(p_dist);
    SAME_COUNT(feasible);
    SAME_DOUBLE(joint_length);
    SAME_DOUBLE(area_cost);
    SAME_DOUBLE(panel_cost);
    SAME_DOUBLE(joint_cost);
    SAME_DOUBLE(max_gap);
    SAME_DOUBLE(mean_gap);
    SAME_DOUBLE(max_kink);
    SAME_DOUBLE(mean_kink);
    SAME_COUNT(gaps_over);
    SAME_COUNT(kinks_over);
    SAME_COUNT(sp_misfits);
    SAME_COUNT(sp_fitted);
}

static void same_totals(const struct option_totals *a,
                        const struct option_totals *b, const char *what)
{
    same_totals_but_moulds(a, b, what);
    char name[160];
    SAME_COUNT(moulds);
    for (int t = 0; t < TYPE_COUNT; t++)
        SAME_COUNT(moulds_of[t]);
    SAME_COUNT(largest_family);
    SAME_COUNT(singleton_families);
    SAME_DOUBLE(mould_cost);
    SAME_DOUBLE(cost);
#undef SAME_COUNT
#undef SAME_DOUBLE
}

/* Every panel field an evaluation sets, bit for bit; the moulds too when
 * moulds is set. */
static void same_panels(const struct panelization *a,
                        const struct panelization *b, int moulds,
                        const char *what)
{
    assert_int_equal(a->nu, b->nu);
    assert_int_equal(a->nv, b->nv);
    assert_int_equal(a->npanels, b->npanels);
    for (size_t k = 0; k < a->npanels; k++) {
        const struct panel *p = &a->panels[k], *q = &b->panels[k];
        char name[160];
        snprintf(name, sizeof name, "%s panel %zu", what, k);
        assert_int_equal(p->i, q->i);
        assert_int_equal(p->j, q->j);
        assert_int_equal(p->type, q->type);
        assert_int_equal(p->class, q->class);
        assert_int_equal(p->built, q->built);
        assert_int_equal(p->misfit, q->misfit);
        assert_int_equal(p->worst_gap_side, q->worst_gap_side);
        same_bits(p->area, q->area, name);
        same_bits(p->deviation, q->deviation, name);
        same_bits(p->cost, q->cost, name);
        same_bits(p->sp_deviation, q->sp_deviation, name);
        same_bits(p->worst_gap, q->worst_gap, name);
        same_bits(p->worst_kink, q->worst_kink, name);
        if (moulds && p->mould != q->mould)
            fail_msg("%s: mould %d and %d differ", name, p->mould, q->mould);
    }
}

/* Settings that exercise every term: costs per panel, joint and mould,
 * gap and kink limits. */
static struct option_params test_params(double threshold_mm)
{
    struct option_params base;
    option_params_defaults(&base);
    base.classify.panel_cost = 40;
    base.classify.joint_cost = 12.5;
    base.classify.mould_cost[TYPE_SP] = 1500;
    base.classify.mould_cost[TYPE_DP] = 9000;
    base.classify.max_gap = 0.004;
    base.classify.max_kink = 3 * PI / 180;
    return option_params_at(&base, 0, 0, threshold_mm);
}

static void open_project(const char *path, struct project *p)
{
    struct facet_error err;
    if (project_open(&path, 1, UNITS_M, p, &err) != FACET_OK ||
        project_prepare(p, 0, PARAM_AUTO, &err) != FACET_OK)
        fail_msg("%s: %s", path, err.message);
}

static const char *write_example(const char *name, int res)
{
    static char path[128];
    snprintf(path, sizeof path, "%s/%s%d.obj", dir, name, res);
    FILE *out = fopen(path, "w");
    assert_non_null(out);
    struct facet_error err;
    assert_int_equal(example_write(name, res, out, &err), FACET_OK);
    fclose(out);
    return path;
}

static void evaluate(const struct project *p, const struct surface_grid *g,
                     const struct option_params *params, int jobs,
                     struct project_option *out)
{
    struct facet_error err;
    if (project_option_evaluate(p, g, params, jobs, out, &err) != FACET_OK)
        fail_msg("project_option_evaluate: %s", err.message);
}

/* The example skin at res quads a face, prepared, into *p, and room for
 * its grids (free them). */
static struct surface_grid *open_skin(int res, struct project *p)
{
    open_project(write_example("skin", res), p);
    assert_int_equal(p->nsurfaces, SKIN_FACES);
    struct surface_grid *g = malloc(p->nsurfaces * sizeof *g);
    assert_non_null(g);
    return g;
}

/* A project of one surface is that surface's option_evaluate. */
static void test_one_surface(void **state)
{
    (void)state;
    struct project p;
    open_project(write_example("roof", 40), &p);
    assert_int_equal(p.nsurfaces, 1);
    const int grid[3][2] = {{9, 7}, {23, 17}, {4, 31}};
    const double threshold[2] = {3, 12};
    for (int g = 0; g < 3; g++)
        for (int t = 0; t < 2; t++) {
            struct option_params params = test_params(threshold[t]);
            struct surface_grid one = {grid[g][0], grid[g][1]};
            struct project_option option;
            evaluate(&p, &one, &params, 2, &option);
            params.nu = one.nu;
            params.nv = one.nv;
            struct panelization panels;
            struct option_totals totals;
            struct facet_error err;
            assert_int_equal(option_evaluate(&p.surfaces[0].surface, &params, NULL,
                                             &panels, &totals, &err),
                             FACET_OK);
            char what[64];
            snprintf(what, sizeof what, "roof %dx%d at %g mm", one.nu,
                     one.nv, threshold[t]);
            assert_true(totals.moulds > 0);
            same_totals(&option.totals, &totals, what);
            same_totals(&option.surfaces[0].totals, &totals, what);
            same_panels(&option.surfaces[0].panels, &panels, 1, what);
            assert_int_equal(option.surfaces[0].moulds_used, totals.moulds);
            assert_int_equal(option.joints, option.surfaces[0].joints);
            for (int k = 0; k < TYPE_COUNT; k++)
                assert_int_equal(option.surfaces[0].moulds_used_of[k],
                                 totals.moulds_of[k]);
            panelization_free(&panels);
            project_option_free(&option);
        }
    project_close(&p);
}

/* The torus section of R 20 m, r 6 m: s over 90 degrees around its axis,
 * t from -60 to 60 degrees around the tube, so symmetric about the
 * equator t = 1/2. */
static void torus_point(double s, double t, double p[3])
{
    double a = 0.5 * PI * s, q = (-60 + 120 * t) * PI / 180;
    p[0] = (20 + 6 * cos(q)) * cos(a);
    p[1] = (20 + 6 * cos(q)) * sin(a);
    p[2] = 6 * sin(q);
}

/* The rotation by angle about the unit axis (Rodrigues) into r. */
static void rotation(const double axis[3], double angle, double r[3][3])
{
    double c = cos(angle), s = sin(angle), x = axis[0], y = axis[1],
           z = axis[2];
    double m[3][3] = {
        {c + x * x * (1 - c), x * y * (1 - c) - z * s,
         x * z * (1 - c) + y * s},
        {y * x * (1 - c) + z * s, c + y * y * (1 - c),
         y * z * (1 - c) - x * s},
        {z * x * (1 - c) - y * s, z * y * (1 - c) + x * s,
         c + z * z * (1 - c)},
    };
    memcpy(r, m, sizeof m);
}

/* Writes copies rigid copies of the torus section, each its own object
 * with its own vt = (s, t), on quads x quads quads each split into four
 * triangles about its centre (a triangulation every symmetry of the cell
 * keeps). Copy k is turned by 0.7 k rad about a tilted axis and moved by
 * (70 k, -40 k, 25 k) m. */
static const char *write_torus_copies(int copies, int quads)
{
    static char path[128];
    snprintf(path, sizeof path, "%s/torus%d.obj", dir, copies);
    FILE *out = fopen(path, "w");
    assert_non_null(out);
    const double n = sqrt(1 + 4 + 9);
    const double axis[3] = {1 / n, 2 / n, 3 / n};
    int side = quads + 1;
    int per_copy = side * side + quads * quads;
    for (int k = 0; k < copies; k++) {
        double r[3][3];
        rotation(axis, 0.7 * k, r);
        const double move[3] = {70.0 * k, -40.0 * k, 25.0 * k};
        fprintf(out, "o copy%d\n", k);
        /* Corners, then centres: their points and their vt. */
        for (int pass = 0; pass < 2; pass++)
            for (int b = 0; b < (pass ? quads : side); b++)
                for (int a = 0; a < (pass ? quads : side); a++) {
                    double s = (a + 0.5 * pass) / quads;
                    double t = (b + 0.5 * pass) / quads;
                    double p[3], q[3];
                    torus_point(s, t, p);
                    for (int x = 0; x < 3; x++)
                        q[x] = r[x][0] * p[0] + r[x][1] * p[1] +
                               r[x][2] * p[2] + move[x];
                    fprintf(out, "v %.17g %.17g %.17g\nvt %.17g %.17g\n",
                            q[0], q[1], q[2], s, t);
                }
        int base = k * per_copy + 1;
        for (int b = 0; b < quads; b++)
            for (int a = 0; a < quads; a++) {
                int c[4] = {base + b * side + a, base + b * side + a + 1,
                            base + (b + 1) * side + a + 1,
                            base + (b + 1) * side + a};
                int m = base + side * side + b * quads + a;
                for (int e = 0; e < 4; e++)
                    fprintf(out, "f %d/%d %d/%d %d/%d\n", c[e], c[e],
                            c[(e + 1) % 4], c[(e + 1) % 4], m, m);
            }
    }
    fclose(out);
    return path;
}

/* Congruent surfaces share their moulds: K copies need one copy's. */
static void test_copies_share_moulds(void **state)
{
    (void)state;
    enum { QUADS = 24, NU = 6, NV = 8, K = 3 };
    struct option_params params = test_params(3);
    params.mould_tol_given = 1;
    params.mould_tol = 0;
    struct project one, many;
    open_project(write_torus_copies(1, QUADS), &one);
    open_project(write_torus_copies(K, QUADS), &many);
    assert_int_equal(many.nsurfaces, K);
    struct surface_grid grids[K];
    for (int k = 0; k < K; k++)
        grids[k] = (struct surface_grid){NU, NV};
    struct project_option a, b;
    evaluate(&one, grids, &params, 1, &a);
    evaluate(&many, grids, &params, 2, &b);

    /* The truth by symmetry: every panel double-curved, one family per
     * row up to the mirror about the equator. */
    const struct option_totals *t1 = &a.totals, *tk = &b.totals;
    assert_int_equal(t1->panels, NU * NV);
    assert_int_equal(t1->count[TYPE_DP], NU * NV);
    assert_int_equal(t1->moulds, NV / 2);
    assert_int_equal(t1->moulds_of[TYPE_DP], NV / 2);
    assert_int_equal(t1->largest_family, 2 * NU);

    /* K copies: K times the panels and areas, the same families. */
    assert_int_equal(tk->panels, K * t1->panels);
    assert_int_equal(tk->count[TYPE_DP], K * t1->count[TYPE_DP]);
    /* Joints: (nu - 1) nv + nu (nv - 1) a copy, none between copies. */
    assert_int_equal(a.joints, (NU - 1) * NV + NU * (NV - 1));
    assert_int_equal(b.joints, K * a.joints);
    assert_true(fabs(tk->area - K * t1->area) <= 1e-12 * tk->area);
    assert_true(fabs(tk->area_cost - K * t1->area_cost) <=
                1e-12 * tk->area_cost);
    assert_true(fabs(tk->joint_length - K * t1->joint_length) <=
                1e-12 * tk->joint_length);
    assert_true(fabs(tk->panel_cost - K * t1->panel_cost) <= 1e-9);
    assert_int_equal(tk->moulds, NV / 2);
    assert_int_equal(tk->moulds_of[TYPE_DP], NV / 2);
    assert_int_equal(tk->largest_family, K * 2 * NU);
    same_bits(tk->mould_cost, NV / 2 * 9000.0, "building mould cost");
    same_bits(tk->cost, tk->area_cost + tk->panel_cost + tk->joint_cost +
                            tk->mould_cost, "building cost");

    /* Each copy on its own needs them all: the sum would be K times. */
    size_t alone = 0;
    double alone_mould_cost = 0;
    for (int k = 0; k < K; k++) {
        struct option_params own = params;
        own.nu = NU;
        own.nv = NV;
        struct panelization panels;
        struct option_totals totals;
        struct facet_error err;
        assert_int_equal(option_evaluate(&many.surfaces[k].surface, &own, NULL,
                                         &panels, &totals, &err),
                         FACET_OK);
        alone += totals.moulds;
        alone_mould_cost += totals.mould_cost;
        panelization_free(&panels);
    }
    assert_int_equal(alone, K * (NV / 2));
    same_bits(alone_mould_cost, K * (NV / 2) * 9000.0, "alone");

    /* The first copy starts every family, the others use them. */
    size_t started = 0;
    for (int k = 0; k < K; k++) {
        const struct project_surface_option *s = &b.surfaces[k];
        assert_int_equal(s->totals.moulds, k == 0 ? NV / 2 : 0);
        same_bits(s->totals.mould_cost, k == 0 ? NV / 2 * 9000.0 : 0,
                  "a copy's mould cost");
        assert_int_equal(s->moulds_used, NV / 2);
        assert_int_equal(s->moulds_used_of[TYPE_DP], NV / 2);
        started += s->totals.moulds;
        /* Panel (i, j) of every copy is in the family of the first's. */
        for (size_t n = 0; n < s->panels.npanels; n++)
            assert_int_equal(s->panels.panels[n].mould,
                             b.surfaces[0].panels.panels[n].mould);
    }
    assert_int_equal(started, tk->moulds);
    project_option_free(&a);
    project_option_free(&b);
    project_close(&one);
    project_close(&many);
}

static double relative(double a, double b)
{
    double scale = fmax(fabs(a), fabs(b));
    return scale > 0 ? fabs(a - b) / scale : 0;
}

/* The building's totals are its surfaces' summed, and each surface's are
 * what it gives on its own, moulds aside. */
static void test_skin_brute_force(void **state)
{
    (void)state;
    struct project p;
    struct surface_grid *g = open_skin(6, &p);
    project_module_grids(&p, 3.2, 2.9, g);
    struct option_params params = test_params(3);
    /* A width limit some of the skin's panels are under (slivers). */
    params.classify.min_panel_width = 2.7;
    struct project_option option;
    evaluate(&p, g, &params, 2, &option);

    struct option_totals sum;
    memset(&sum, 0, sizeof sum);
    double mean_gap = 0, mean_kink = 0, min_radius = INFINITY;
    double min_area = INFINITY, min_width = INFINITY;
    size_t alone_moulds = 0, started = 0, all_joints = 0;
    for (size_t i = 0; i < p.nsurfaces; i++) {
        struct option_params own = params;
        own.nu = g[i].nu;
        own.nv = g[i].nv;
        struct panelization panels;
        struct option_totals t;
        struct facet_error err;
        assert_int_equal(option_evaluate(&p.surfaces[i].surface, &own, NULL,
                                         &panels, &t, &err),
                         FACET_OK);
        const struct project_surface_option *s = &option.surfaces[i];
        assert_int_equal(s->grid.nu, g[i].nu);
        assert_int_equal(s->grid.nv, g[i].nv);
        same_totals_but_moulds(&s->totals, &t, p.surfaces[i].name);
        same_panels(&s->panels, &panels, 0, p.surfaces[i].name);
        alone_moulds += t.moulds;
        started += s->totals.moulds;
        /* It uses at most what it needs on its own, at least what it
         * starts. */
        assert_true(s->moulds_used >= s->totals.moulds);
        panelization_free(&panels);

        sum.panels += t.panels;
        for (int k = 0; k < TYPE_COUNT; k++) {
            sum.count[k] += t.count[k];
            sum.area_of[k] += t.area_of[k];
        }
        sum.area += t.area;
        sum.planarity += t.planarity;
        sum.joint_length += t.joint_length;
        sum.max_deviation = fmax(sum.max_deviation, t.max_deviation);
        sum.max_panel_area = fmax(sum.max_panel_area, t.max_panel_area);
        sum.max_gap = fmax(sum.max_gap, t.max_gap);
        sum.max_kink = fmax(sum.max_kink, t.max_kink);
        sum.gaps_over += t.gaps_over;
        sum.kinks_over += t.kinks_over;
        sum.sp_misfits += t.sp_misfits;
        if (!isnan(t.sp_min_radius))
            min_radius = fmin(min_radius, t.sp_min_radius);
        min_area = fmin(min_area, t.min_panel_area);
        min_width = fmin(min_width, t.min_panel_width);
        sum.slivers += t.slivers;
        /* Every cell of a face is a panel: each side between two is a
         * joint. */
        size_t joints = (size_t)(g[i].nu - 1) * (size_t)g[i].nv +
                        (size_t)g[i].nu * (size_t)(g[i].nv - 1);
        assert_int_equal(s->joints, joints);
        all_joints += joints;
        mean_gap += t.mean_gap * (double)joints;
        mean_kink += t.mean_kink * (double)joints;
    }
    const struct option_totals *b = &option.totals;
    assert_int_equal(b->panels, sum.panels);
    assert_true(b->panels > 3000);
    for (int k = 0; k < TYPE_COUNT; k++) {
        assert_int_equal(b->count[k], sum.count[k]);
        assert_true(b->count[k] > 0);
        assert_true(relative(b->area_of[k], sum.area_of[k]) < 1e-13);
    }
    assert_true(relative(b->area, sum.area) < 1e-13);
    assert_true(relative(b->area, p.area) < 1e-9);
    assert_true(relative(b->planarity, sum.planarity) < 1e-13);
    assert_true(relative(b->joint_length, sum.joint_length) < 1e-13);
    same_bits(b->max_deviation, sum.max_deviation, "max deviation");
    same_bits(b->max_panel_area, sum.max_panel_area, "max panel area");
    same_bits(b->max_gap, sum.max_gap, "max gap");
    same_bits(b->max_kink, sum.max_kink, "max kink");
    assert_int_equal(b->gaps_over, sum.gaps_over);
    assert_int_equal(b->kinks_over, sum.kinks_over);
    assert_int_equal(b->sp_misfits, sum.sp_misfits);
    /* The least of the surfaces' that have SP panels built. */
    if (isinf(min_radius))
        assert_true(isnan(b->sp_min_radius));
    else
        same_bits(b->sp_min_radius, min_radius, "smallest SP radius");
    /* Slivers: the least area and width of the surfaces', their slivers
     * added. */
    same_bits(b->min_panel_area, min_area, "smallest panel area");
    same_bits(b->min_panel_width, min_width, "smallest panel width");
    assert_int_equal(b->slivers, sum.slivers);
    assert_true(sum.slivers > 0 && sum.slivers < b->panels);
    assert_int_equal(option.joints, all_joints);
    assert_true(relative(b->mean_gap, mean_gap / (double)all_joints) <
                1e-12);
    assert_true(relative(b->mean_kink, mean_kink / (double)all_joints) <
                1e-12);
    /* Feasible only if no surface is over a limit. */
    assert_int_equal(b->feasible, sum.gaps_over == 0 && sum.kinks_over == 0 &&
                                      sum.slivers == 0 &&
                                      sum.max_panel_area <=
                                          params.classify.max_panel_area);
    /* Moulds: counted once, each on the surface that starts it; fewer
     * than the surfaces need one by one (the skin repeats its faces). */
    assert_int_equal(started, b->moulds);
    assert_int_equal(b->moulds, option.families.nfamilies);
    assert_true(b->moulds < alone_moulds);
    assert_true(relative(b->mould_cost,
                         (double)b->moulds_of[TYPE_SP] * 1500 +
                             (double)b->moulds_of[TYPE_DP] * 9000) < 1e-15);
    assert_true(relative(b->cost, b->area_cost + b->panel_cost +
                                      b->joint_cost + b->mould_cost) < 1e-15);
    assert_true(relative(b->area_cost,
                         sum.area_of[TYPE_FP] * 701 +
                             sum.area_of[TYPE_SP] * 766 +
                             sum.area_of[TYPE_DP] * 1518) < 1e-12);
    project_option_free(&option);
    free(g);
    project_close(&p);
}

/* A count a run does not measure is not known for the building either:
 * TOTALS_UNKNOWN (stored NULL), never the surfaces' unknowns added (which
 * wrapped round to a count near 2^64 for two surfaces and more). */
static void test_unmeasured_counts_unknown(void **state)
{
    (void)state;
    struct project p;
    struct surface_grid *g = open_skin(4, &p);
    project_module_grids(&p, 3, 3, g);
    struct option_params params = test_params(3);
    params.classify.max_gap = params.classify.max_kink = 0;
    params.unmeasured = OPTION_MEASURE_JOINTS | OPTION_MEASURE_WIDTHS;
    struct project_option option;
    evaluate(&p, g, &params, 2, &option);
    assert_true(p.nsurfaces > 1);
    const struct option_totals *b = &option.totals;
    assert_true(b->gaps_over == TOTALS_UNKNOWN);
    assert_true(b->kinks_over == TOTALS_UNKNOWN);
    assert_true(b->slivers == TOTALS_UNKNOWN);
    assert_true(isnan(b->min_panel_width));
    assert_true(isnan(quantity_of_totals(quantity_named("gaps_over"), b)));
    assert_true(b->min_panel_area > 0);
    project_option_free(&option);
    free(g);
    project_close(&p);
}

/* The same option on 1, 2 and 3 threads: the same bits. */
static void test_threads(void **state)
{
    (void)state;
    struct project p;
    struct surface_grid *g = open_skin(5, &p);
    project_module_grids(&p, 2.5, 2.5, g);
    struct option_params params = test_params(3);
    struct project_option one;
    evaluate(&p, g, &params, 1, &one);
    for (int jobs = 2; jobs <= 3; jobs++) {
        struct project_option other;
        evaluate(&p, g, &params, jobs, &other);
        same_totals(&other.totals, &one.totals, "building");
        for (size_t i = 0; i < p.nsurfaces; i++) {
            same_totals(&other.surfaces[i].totals, &one.surfaces[i].totals,
                        p.surfaces[i].name);
            same_panels(&other.surfaces[i].panels, &one.surfaces[i].panels,
                        1, p.surfaces[i].name);
            assert_int_equal(other.surfaces[i].moulds_used,
                             one.surfaces[i].moulds_used);
            assert_int_equal(other.surfaces[i].joints, one.surfaces[i].joints);
        }
        assert_int_equal(other.families.nfamilies, one.families.nfamilies);
        for (size_t f = 0; f < one.families.nfamilies; f++)
            assert_int_equal(other.families.representative[f],
                             one.families.representative[f]);
        project_option_free(&other);
    }
    project_option_free(&one);
    free(g);
    project_close(&p);
}

/* The module's grid per surface, by hand on the podium's flat faces
 * (12 x 20 m on the short sides, 16 x 20 m on the long ones), and
 * round(L / w) on every face. */
static void test_module_grids(void **state)
{
    (void)state;
    struct project p;
    struct surface_grid *g = open_skin(4, &p);
    project_module_grids(&p, 1.5, 1.5, g);
    const struct project_surface *s = project_find(&p, "skin_r00_c00");
    assert_non_null(s);
    size_t short_face = (size_t)(s - p.surfaces);
    s = project_find(&p, "skin_r01_c05");
    assert_non_null(s);
    size_t long_face = (size_t)(s - p.surfaces);
    /* 12 / 1.5 = 8, 20 / 1.5 = 13.3; 16 / 1.5 = 10.7. */
    assert_int_equal(g[short_face].nu, 8);
    assert_int_equal(g[short_face].nv, 13);
    assert_int_equal(g[long_face].nu, 11);
    assert_int_equal(g[long_face].nv, 13);
    const double w[3] = {0.9, 2.2, 7.0}, h[3] = {1.3, 0.6, 30.0};
    for (int m = 0; m < 3; m++) {
        project_module_grids(&p, w[m], h[m], g);
        for (size_t i = 0; i < p.nsurfaces; i++) {
            double lu = p.surfaces[i].u_length, lv = p.surfaces[i].v_length;
            int nu = (int)floor(lu / w[m] + 0.5), nv = (int)floor(lv / h[m]
                                                                 + 0.5);
            assert_int_equal(g[i].nu, nu < 1 ? 1 : nu);
            assert_int_equal(g[i].nv, nv < 1 ? 1 : nv);
        }
    }
    free(g);
    project_close(&p);
}

/* Modules that give every surface the same grid are one option. */
static void test_grids_dedupe(void **state)
{
    (void)state;
    /* FNV-1a of the 8 bytes of 2, then 3, 4, 5, 6 as 4 bytes each,
     * little-endian, by Python's struct.pack('<Qiiii') and the
     * algorithm's definition. */
    struct surface_grid known[2] = {{3, 4}, {5, 6}};
    assert_true(surface_grids_hash(known, 2) == 0x6809cd9160d8c5c3u);
    assert_true(surface_grids_hash(known, 0) == 0xa8c7f832281a39c5u);
    assert_int_equal(surface_grids_cells(known, 2), 42);

    struct project p;
    struct surface_grid *a = open_skin(4, &p);
    size_t n = p.nsurfaces;
    struct surface_grid *b = malloc(n * sizeof *b);
    assert_non_null(b);
    /* Every face's u length is 12 to 17.9 m, away from 13.5 to 13.8 m
     * (none between 13.42 and 14.11), and its v length 20 to 22.2 m: a
     * module 9 x 10 m and one 9.2 x 10.3 m both give 1 panel along u
     * below 13.5 m and 2 above, 2 along v. */
    project_module_grids(&p, 9, 10, a);
    project_module_grids(&p, 9.2, 10.3, b);
    assert_true(surface_grids_equal(a, b, n));
    assert_true(surface_grids_hash(a, n) == surface_grids_hash(b, n));
    const struct project_surface *face = project_find(&p, "skin_r00_c00");
    assert_int_equal(a[face - p.surfaces].nu, 1);  /* 12 m */
    assert_int_equal(a[face - p.surfaces].nv, 2);
    face = project_find(&p, "skin_r00_c04");
    assert_int_equal(a[face - p.surfaces].nu, 2);  /* 16 m */
    assert_int_equal(a[face - p.surfaces].nv, 2);
    /* Modules of 30 x 50 m and 40 x 60 m: every face one panel. */
    project_module_grids(&p, 30, 50, a);
    project_module_grids(&p, 40, 60, b);
    assert_true(surface_grids_equal(a, b, n));
    assert_true(surface_grids_hash(a, n) == surface_grids_hash(b, n));
    assert_int_equal(surface_grids_cells(a, n), n);
    /* 9 m and 7 m: the 12 m faces get 1 panel, then 2. */
    project_module_grids(&p, 9, 10, a);
    project_module_grids(&p, 7, 10, b);
    assert_false(surface_grids_equal(a, b, n));
    assert_true(surface_grids_hash(a, n) != surface_grids_hash(b, n));
    /* One surface's grid changed changes the hash; so does the order. */
    memcpy(b, a, n * sizeof *a);
    b[n - 1].nv++;
    assert_true(surface_grids_hash(a, n) != surface_grids_hash(b, n));
    memcpy(b, a, n * sizeof *a);
    struct surface_grid swap = {a[0].nv, a[0].nu};
    b[0] = swap;
    assert_true(a[0].nu == a[0].nv ||
                surface_grids_hash(a, n) != surface_grids_hash(b, n));
    free(a);
    free(b);
    project_close(&p);
}

/* A bad grid names its surface. */
static void test_bad_grid(void **state)
{
    (void)state;
    struct project p;
    open_project(write_torus_copies(3, 4), &p);
    struct surface_grid g[3] = {{2, 2}, {0, 2}, {2, 2}};
    struct option_params params = test_params(3);
    struct project_option option;
    struct facet_error err;
    for (int jobs = 1; jobs <= 3; jobs++) {
        assert_int_equal(project_option_evaluate(&p, g, &params, jobs,
                                                 &option, &err),
                         FACET_EINPUT);
        assert_non_null(strstr(err.message, "surface copy1"));
        project_option_free(&option);
    }
    project_close(&p);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_one_surface),
        cmocka_unit_test(test_copies_share_moulds),
        cmocka_unit_test(test_skin_brute_force),
        cmocka_unit_test(test_unmeasured_counts_unknown),
        cmocka_unit_test(test_threads),
        cmocka_unit_test(test_module_grids),
        cmocka_unit_test(test_grids_dedupe),
        cmocka_unit_test(test_bad_grid),
    };
    return cmocka_run_group_tests(tests, make_dir, remove_dir);
}
