/*
 * test_export.c: the exports of an option (issue 6) against what they must
 * hold: panel geometry whose pieces add up to the panel areas and whose
 * outlines enclose exactly the panel's UV area (holes included) and are
 * the pieces' unmatched edges, counted by brute force (issue 27); an OBJ
 * that Facet's own loader reads back with one group per panel and, per
 * material, the area of the panelization; SVG maps with one mark per
 * panel; a scatter plot with one circle per option inside its axes; and
 * files that are never overwritten without force nor left half-written.
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
#include <sys/stat.h>
#include <unistd.h>

#include "core/surface/example.h"
#include "core/out/export_obj.h"
#include "core/evaluate/evaluate.h"
#include "core/panel/panel_geometry.h"
#include "core/search/pareto.h"
#include "core/base/numformat.h"
#include "core/out/svg.h"
#include "core/out/svg_map.h"
#include "core/out/svg_plot.h"
#include "tests/support/surface_fixture.h"

/* An evaluated option with its geometry. */
struct fixture {
    struct surface surface;
    struct panelization panels;
    struct option_totals totals;
    struct panel_geometry geometry;
};

/* Opens and prepares the OBJ file at path as a surface. */
static void open_surface(const char *path, struct surface *s)
{
    struct facet_error err;
    if (surface_fixture_open(path, s, &err) != FACET_OK)
        fail_msg("%s: %s", path, err.message);
}

/* Evaluates an nu x nv option with the paper's defaults and flatness
 * threshold (m) on the prepared surface in f and builds its geometry. */
static void evaluate(struct fixture *f, int nu, int nv, double threshold)
{
    struct option_params params;
    memset(&params, 0, sizeof params);
    params.nu = nu;
    params.nv = nv;
    params.mode = PANEL_EXTREMES;
    classify_defaults(&params.classify);
    params.classify.threshold = threshold;
    struct facet_error err;
    if (option_evaluate(&f->surface, &params, NULL, &f->panels, &f->totals,
                        &err) != FACET_OK)
        fail_msg("%s", err.message);
    if (panel_geometry_build(&f->surface.mesh, &f->surface.uv, &f->panels,
                             &f->geometry, &err) != FACET_OK)
        fail_msg("%s", err.message);
}

/* Example name at res quads, evaluated on an nu x nv grid. */
static void example_fixture(struct fixture *f, const char *name, int res,
                            int nu, int nv)
{
    struct facet_error err;
    if (surface_fixture_example(name, res, &f->surface, &err) != FACET_OK)
        fail_msg("%s: %s", name, err.message);
    evaluate(f, nu, nv, 0.003);
}

/* A ring (annulus 0.1 < r < 0.45 about (0.5, 0.5)) cut from a gently
 * curved n x n grid over the unit square, vt = (x, y): its panels are
 * trimmed by a jagged outer edge, and the cells around the centre by a
 * hole. */
static void ring_fixture(struct fixture *f, int n, int nu, int nv,
                         double threshold)
{
    char path[] = "/tmp/facet_test_export_ring_XXXXXX";
    int fd = mkstemp(path);
    assert_true(fd >= 0);
    FILE *out = fdopen(fd, "w");
    for (int j = 0; j <= n; j++)
        for (int i = 0; i <= n; i++) {
            double x = (double)i / n, y = (double)j / n;
            fprintf(out, "v %.17g %.17g %.17g\nvt %.17g %.17g\n", 20 * x,
                    20 * y, 0.5 * sin(3 * x) * cos(2 * y), x, y);
        }
    for (int j = 0; j < n; j++)
        for (int i = 0; i < n; i++) {
            double cx = (i + 0.5) / n - 0.5, cy = (j + 0.5) / n - 0.5;
            double r = sqrt(cx * cx + cy * cy);
            if (r < 0.1 || r > 0.45)
                continue;
            int a = j * (n + 1) + i + 1, b = a + 1, c = b + n + 1,
                d = a + n + 1;
            fprintf(out, "f %d/%d %d/%d %d/%d\nf %d/%d %d/%d %d/%d\n", a, a,
                    b, b, c, c, a, a, c, c, d, d);
        }
    fclose(out);
    open_surface(path, &f->surface);
    unlink(path);
    evaluate(f, nu, nv, threshold);
}

static void fixture_free(struct fixture *f)
{
    panel_geometry_free(&f->geometry);
    panelization_free(&f->panels);
    surface_close(&f->surface);
}

/* The signed UV area inside loop l (shoelace). */
static double loop_uv_area(const struct panel_geometry *g, size_t l)
{
    double sum = 0;
    size_t k0 = g->loop_start[l], k1 = g->loop_start[l + 1];
    for (size_t k = k0; k < k1; k++) {
        const double *a = &g->uv[2 * g->outline[k]];
        const double *b = &g->uv[2 * g->outline[k + 1 < k1 ? k + 1 : k0]];
        sum += a[0] * b[1] - a[1] * b[0];
    }
    return 0.5 * sum;
}

/* Checks what every panel geometry must hold; returns the number of
 * panels with more than one loop. */
static size_t check_geometry(const struct fixture *f)
{
    const struct panel_geometry *g = &f->geometry;
    const struct panelization *p = &f->panels;
    assert_int_equal(g->npanels, p->npanels);
    size_t several = 0;
    double du = (p->umax - p->umin) / p->nu, dv = (p->vmax - p->vmin) / p->nv;
    for (size_t n = 0; n < p->npanels; n++) {
        const struct panel *panel = &p->panels[n];
        /* Pieces: their areas add up to the panel's (merging points
         * within 1e-9 of a cell drops at most slivers that thin). */
        double area = 0;
        for (size_t q = g->panel_piece[n]; q < g->panel_piece[n + 1]; q++) {
            area += panel_geometry_piece_area(g, q);
            for (size_t c = g->piece_start[q]; c < g->piece_start[q + 1];
                 c++)
                assert_true(g->corner[c] >= g->panel_vertex[n] &&
                            g->corner[c] < g->panel_vertex[n + 1]);
        }
        if (fabs(area - panel->area) > 1e-8 * panel->area)
            fail_msg("panel %d,%d: pieces %.12g m^2, panel %.12g m^2",
                     panel->i, panel->j, area, panel->area);
        /* Outline: the loops enclose the panel's UV area, holes counted
         * negative; every point lies in the cell. */
        size_t nloops = g->panel_loop[n + 1] - g->panel_loop[n];
        assert_true(nloops >= 1);
        several += nloops > 1;
        double uv_area = 0;
        for (size_t l = g->panel_loop[n]; l < g->panel_loop[n + 1]; l++) {
            uv_area += loop_uv_area(g, l);
            for (size_t k = g->loop_start[l]; k < g->loop_start[l + 1];
                 k++) {
                const double *uv = &g->uv[2 * g->outline[k]];
                double u0 = p->umin + panel->i * du, v0 = p->vmin +
                                                          panel->j * dv;
                assert_true(uv[0] >= u0 - 1e-9 * du &&
                            uv[0] <= u0 + du * (1 + 1e-9));
                assert_true(uv[1] >= v0 - 1e-9 * dv &&
                            uv[1] <= v0 + dv * (1 + 1e-9));
            }
        }
        if (fabs(fabs(uv_area) - panel->uv_area) > 1e-8 * panel->uv_area)
            fail_msg("panel %d,%d: outline encloses %.12g, panel %.12g (UV)",
                     panel->i, panel->j, uv_area, panel->uv_area);
        /* An untrimmed panel is one loop through its four cell corners. */
        if (!panel->trimmed) {
            assert_int_equal(nloops, 1);
            int corners = 0;
            size_t l = g->panel_loop[n];
            for (size_t k = g->loop_start[l]; k < g->loop_start[l + 1];
                 k++) {
                const double *uv = &g->uv[2 * g->outline[k]];
                double fu = (uv[0] - p->umin) / du - panel->i;
                double fv = (uv[1] - p->vmin) / dv - panel->j;
                if ((fabs(fu) < 1e-9 || fabs(fu - 1) < 1e-9) &&
                    (fabs(fv) < 1e-9 || fabs(fv - 1) < 1e-9))
                    corners++;
            }
            assert_int_equal(corners, 4);
        }
        /* The projected outline lies on the panel's plane. */
        for (size_t k = g->loop_start[g->panel_loop[n]];
             k < g->loop_start[g->panel_loop[n + 1]]; k++) {
            double d = 0;
            for (int c = 0; c < 3; c++)
                d += (g->outline_plane[3 * k + c] - panel->centroid[c]) *
                     panel->normal[c];
            assert_true(fabs(d) < 1e-9);
        }
    }
    return several;
}

static void test_geometry_of_examples(void **state)
{
    (void)state;
    struct fixture f;
    /* The plane: panel edges fall on mesh lines (140 quads, 4 x 3 cells
     * of 35 x 46.7), the degenerate case of clipping. */
    example_fixture(&f, "plane", 0, 4, 3);
    assert_int_equal(check_geometry(&f), 0);
    for (size_t n = 0; n < f.panels.npanels; n++) {
        /* Flat: the projected outline has the panel's whole area. */
        double a = panel_geometry_loop_area(&f.geometry,
                                            f.geometry.panel_loop[n],
                                            f.panels.panels[n].normal);
        assert_true(fabs(a - f.panels.panels[n].area) <
                    1e-9 * f.panels.panels[n].area);
    }
    fixture_free(&f);

    example_fixture(&f, "roof", 60, 13, 17);
    assert_int_equal(check_geometry(&f), 0);
    fixture_free(&f);

    example_fixture(&f, "torus", 40, 7, 9);
    assert_int_equal(check_geometry(&f), 0);
    fixture_free(&f);
}

/* Brute force, against panel_geometry's sorted merge and outline: in
 * every panel of f, no two vertices equal in UV and position (the merge
 * joins them), and each directed piece edge (a, b) is on the outline as
 * often as (a, b) outnumbers (b, a) among the pieces, counted pair by
 * pair; the outline's edges are the consecutive points of its loops. Its
 * count of panels checked. */
static size_t check_outline_brute(const struct fixture *f)
{
    const struct panel_geometry *g = &f->geometry;
    for (size_t n = 0; n < g->npanels; n++) {
        for (size_t a = g->panel_vertex[n]; a < g->panel_vertex[n + 1]; a++)
            for (size_t b = a + 1; b < g->panel_vertex[n + 1]; b++) {
                const double *x = &g->position[3 * a], *y = &g->position[3 * b];
                const double *u = &g->uv[2 * a], *v = &g->uv[2 * b];
                assert_false(u[0] == v[0] && u[1] == v[1] && x[0] == y[0] &&
                             x[1] == y[1] && x[2] == y[2]);
            }
        /* Every directed edge of the panel's pieces, then of its loops. */
        size_t npiece_edges = g->piece_start[g->panel_piece[n + 1]] -
                              g->piece_start[g->panel_piece[n]];
        size_t l0 = g->panel_loop[n], l1 = g->panel_loop[n + 1];
        size_t nloop_edges = g->loop_start[l1] - g->loop_start[l0];
        size_t (*piece_edges)[2] = malloc((npiece_edges + 1) *
                                          sizeof *piece_edges);
        size_t (*loop_edges)[2] = malloc((nloop_edges + 1) *
                                         sizeof *loop_edges);
        assert_non_null(piece_edges);
        assert_non_null(loop_edges);
        size_t e = 0;
        for (size_t p = g->panel_piece[n]; p < g->panel_piece[n + 1]; p++)
            for (size_t c = g->piece_start[p]; c < g->piece_start[p + 1];
                 c++) {
                size_t next = c + 1 < g->piece_start[p + 1]
                                  ? c + 1 : g->piece_start[p];
                piece_edges[e][0] = g->corner[c];
                piece_edges[e++][1] = g->corner[next];
            }
        e = 0;
        for (size_t l = l0; l < l1; l++)
            for (size_t k = g->loop_start[l]; k < g->loop_start[l + 1];
                 k++) {
                size_t next = k + 1 < g->loop_start[l + 1]
                                  ? k + 1 : g->loop_start[l];
                loop_edges[e][0] = g->outline[k];
                loop_edges[e++][1] = g->outline[next];
            }
        for (size_t i = 0; i < npiece_edges; i++) {
            size_t a = piece_edges[i][0], b = piece_edges[i][1];
            long forward = 0, back = 0, outline = 0;
            for (size_t j = 0; j < npiece_edges; j++) {
                forward += piece_edges[j][0] == a && piece_edges[j][1] == b;
                back += piece_edges[j][0] == b && piece_edges[j][1] == a;
            }
            for (size_t j = 0; j < nloop_edges; j++)
                outline += loop_edges[j][0] == a && loop_edges[j][1] == b;
            assert_int_equal(outline, forward > back ? forward - back : 0);
        }
        /* And nothing on the outline that no piece has. */
        for (size_t j = 0; j < nloop_edges; j++) {
            long found = 0;
            for (size_t i = 0; i < npiece_edges; i++)
                found += piece_edges[i][0] == loop_edges[j][0] &&
                         piece_edges[i][1] == loop_edges[j][1];
            assert_true(found > 0);
        }
        free(piece_edges);
        free(loop_edges);
    }
    return g->npanels;
}

static void test_outline_by_brute_force(void **state)
{
    (void)state;
    struct fixture f;
    /* facet example roof's own resolution, 140, on a front's grid. */
    example_fixture(&f, "roof", 140, 23, 37);
    assert_int_equal(check_outline_brute(&f), 23 * 37);
    fixture_free(&f);
    /* Trimmed cells: two lobes or a hole in one. */
    ring_fixture(&f, 60, 5, 5, 0.003);
    assert_true(check_outline_brute(&f) > 10);
    fixture_free(&f);
    example_fixture(&f, "torus", 40, 7, 9);
    assert_int_equal(check_outline_brute(&f), 7 * 9);
    fixture_free(&f);
}

static void test_geometry_of_trimmed_panels(void **state)
{
    (void)state;
    struct fixture f;
    ring_fixture(&f, 60, 5, 5, 0.003);
    size_t trimmed = 0;
    for (size_t n = 0; n < f.panels.npanels; n++)
        trimmed += f.panels.panels[n].trimmed;
    assert_true(trimmed > 10);
    check_geometry(&f);
    fixture_free(&f);

    /* One cell: an outer loop and the hole, wound opposite ways. */
    ring_fixture(&f, 60, 1, 1, 0.003);
    assert_int_equal(f.panels.npanels, 1);
    assert_int_equal(check_geometry(&f), 1);
    assert_int_equal(f.geometry.nloops, 2);
    double a0 = loop_uv_area(&f.geometry, 0);
    double a1 = loop_uv_area(&f.geometry, 1);
    assert_true(a0 * a1 < 0);
    double outer = fmax(fabs(a0), fabs(a1)), hole = fmin(fabs(a0), fabs(a1));
    /* Jagged circles of radius 0.45 and 0.1 on a 1/60 grid. */
    assert_true(fabs(outer - M_PI * 0.45 * 0.45) < 0.03);
    assert_true(fabs(hole - M_PI * 0.1 * 0.1) < 0.01);
    fixture_free(&f);
}

/* A fresh temporary directory. */
static void temp_dir(char *path, size_t size)
{
    snprintf(path, size, "/tmp/facet_test_export_dir_XXXXXX");
    assert_non_null(mkdtemp(path));
}

static int file_exists(const char *path)
{
    return access(path, F_OK) == 0;
}

/* Reads a whole file into a new string. */
static char *read_text(const char *path)
{
    FILE *in = fopen(path, "rb");
    assert_non_null(in);
    fseek(in, 0, SEEK_END);
    long size = ftell(in);
    fseek(in, 0, SEEK_SET);
    char *text = malloc((size_t)size + 1);
    assert_non_null(text);
    assert_int_equal(fread(text, 1, (size_t)size, in), (size_t)size);
    text[size] = '\0';
    fclose(in);
    return text;
}

static size_t count_of(const char *text, const char *needle)
{
    size_t count = 0;
    for (const char *s = strstr(text, needle); s != NULL;
         s = strstr(s + 1, needle))
        count++;
    return count;
}

/* Runs xmllint on path when it is installed (make deps installs it). */
static void xml_well_formed(const char *path)
{
    if (system("command -v xmllint >/dev/null 2>&1") != 0)
        return;
    char command[600];
    snprintf(command, sizeof command, "xmllint --noout '%s'", path);
    if (system(command) != 0)
        fail_msg("%s is not well-formed XML", path);
}

/* The area of every triangle of obj, summed per material name. */
static void obj_area_by_material(const struct obj_file *obj,
                                 double area[TYPE_COUNT])
{
    for (int t = 0; t < TYPE_COUNT; t++)
        area[t] = 0;
    for (size_t t = 0; t < obj->ntriangles; t++) {
        const char *name = obj->materials[obj->triangle_material[t]].text;
        int type = -1;
        for (int k = 0; k < TYPE_COUNT; k++)
            if (strcmp(name, panel_type_name((enum panel_type)k)) == 0)
                type = k;
        assert_true(type >= 0);
        const double *p[3];
        for (int c = 0; c < 3; c++)
            p[c] = &obj->position[3 * obj->corner[3 * t + c].v];
        double ab[3], ac[3];
        for (int c = 0; c < 3; c++) {
            ab[c] = p[1][c] - p[0][c];
            ac[c] = p[2][c] - p[0][c];
        }
        double x = ab[1] * ac[2] - ab[2] * ac[1];
        double y = ab[2] * ac[0] - ab[0] * ac[2];
        double z = ab[0] * ac[1] - ab[1] * ac[0];
        area[type] += 0.5 * sqrt(x * x + y * y + z * z);
    }
}

/* The area of FP panels' patches projected onto their own planes: what
 * the FP polygons must enclose, from the pieces rather than the outline. */
static double fp_projected_area(const struct fixture *f)
{
    const struct panel_geometry *g = &f->geometry;
    double total = 0;
    for (size_t n = 0; n < f->panels.npanels; n++) {
        const struct panel *panel = &f->panels.panels[n];
        if (panel->type != TYPE_FP)
            continue;
        double sum = 0;
        if (!panel->trimmed && panel->ncorners == 4) {
            /* A full cell is the quad of its corners on its plane: the
             * area along the normal of that quad (corners taken as they
             * are; the plane's offset does not change it). */
            for (int c = 0; c < 4; c++) {
                const double *a = panel->corner[c];
                const double *b = panel->corner[(c + 1) % 4];
                double cross[3] = {a[1] * b[2] - a[2] * b[1],
                                   a[2] * b[0] - a[0] * b[2],
                                   a[0] * b[1] - a[1] * b[0]};
                for (int x = 0; x < 3; x++)
                    sum += 0.5 * cross[x] * panel->normal[x];
            }
            total += fabs(sum);
            continue;
        }
        for (size_t q = g->panel_piece[n]; q < g->panel_piece[n + 1]; q++) {
            const double *a = &g->position[3 * g->corner[g->piece_start[q]]];
            for (size_t c = g->piece_start[q] + 1;
                 c + 1 < g->piece_start[q + 1]; c++) {
                const double *b = &g->position[3 * g->corner[c]];
                const double *d = &g->position[3 * g->corner[c + 1]];
                double ab[3], ad[3];
                for (int x = 0; x < 3; x++) {
                    ab[x] = b[x] - a[x];
                    ad[x] = d[x] - a[x];
                }
                double cross[3] = {ab[1] * ad[2] - ab[2] * ad[1],
                                   ab[2] * ad[0] - ab[0] * ad[2],
                                   ab[0] * ad[1] - ab[1] * ad[0]};
                for (int x = 0; x < 3; x++)
                    sum += 0.5 * cross[x] * panel->normal[x];
            }
        }
        total += sum;
    }
    return total;
}

/* Writes f as OBJ in dir, reloads it with obj_load and checks groups,
 * materials, texture coordinates and areas. */
static void check_obj_roundtrip(const struct fixture *f, const char *dir,
                                const char *name)
{
    char path[512], mtl[512];
    snprintf(path, sizeof path, "%s/%s.obj", dir, name);
    snprintf(mtl, sizeof mtl, "%s/%s.mtl", dir, name);
    struct facet_error err;
    if (export_obj_save(path, 0, &f->geometry, &f->panels, &err) !=
        FACET_OK)
        fail_msg("%s", err.message);
    assert_true(file_exists(mtl));
    char partial[600];
    snprintf(partial, sizeof partial, "%s.partial", path);
    assert_false(file_exists(partial));

    struct obj_file obj;
    if (obj_load(path, &obj, &err) != FACET_OK)
        fail_msg("%s", err.message);
    /* One group per panel (entry 0 is the unnamed default), in objects
     * by type: the panels of each type together, in the grid's order. */
    assert_int_equal(obj.ngroups, f->panels.npanels + 1);
    size_t g = 1;
    for (int t = 0; t < TYPE_COUNT; t++)
        for (size_t n = 0; n < f->panels.npanels; n++) {
            if ((int)f->panels.panels[n].type != t)
                continue;
            /* An SP or DP panel is in its mould's group too. */
            char group[64];
            int mould = f->panels.panels[n].mould;
            int len = snprintf(group, sizeof group, "panel_%d_%d",
                               f->panels.panels[n].i, f->panels.panels[n].j);
            if (mould >= 0)
                snprintf(group + len, sizeof group - (size_t)len,
                         " mould_%d", mould);
            assert_string_equal(obj.groups[g++].text, group);
        }
    size_t types = 0;
    for (int t = 0; t < TYPE_COUNT; t++)
        types += f->totals.count[t] > 0;
    assert_int_equal(obj.nobjects, types + 1);
    /* The MTL it names is the one beside it; every corner has its vt. */
    assert_int_equal(obj.nmtllibs, 1);
    char expected[256];
    snprintf(expected, sizeof expected, "%s.mtl", name);
    assert_string_equal(obj.mtllibs[0].text, expected);
    for (size_t t = 0; t < 3 * obj.ntriangles; t++)
        assert_true(obj.corner[t].vt != OBJ_NONE);
    char *text = read_text(mtl);
    for (int t = 0; t < TYPE_COUNT; t++) {
        char line[32];
        snprintf(line, sizeof line, "newmtl %s\n",
                 panel_type_name((enum panel_type)t));
        assert_non_null(strstr(text, line));
    }
    assert_int_equal(count_of(text, "\nKd "), 3);
    free(text);

    /* Areas per type. SP and DP are the surface patches: their area is
     * the panels' to the 12 digits written. FP panels are polygons on
     * their best-fit planes: a full cell the quad of its corners, a
     * trimmed one the patch projected onto that plane (compared with the
     * corners' quad and the pieces' projection, to the digits written),
     * within 1e-3 of the surface area. */
    double area[TYPE_COUNT];
    obj_area_by_material(&obj, area);
    for (int t = TYPE_SP; t <= TYPE_DP; t++)
        if (fabs(area[t] - f->totals.area_of[t]) >
            1e-6 * f->totals.area_of[t])
            fail_msg("%s: %s area %.9g in the OBJ, %.9g in the option", name,
                     panel_type_name((enum panel_type)t), area[t],
                     f->totals.area_of[t]);
    double projected = fp_projected_area(f);
    if (fabs(area[TYPE_FP] - projected) > 1e-6 * projected)
        fail_msg("%s: FP polygons %.9g m^2, quads and projected patches "
                 "%.9g m^2", name, area[TYPE_FP], projected);
    if (fabs(area[TYPE_FP] - f->totals.area_of[TYPE_FP]) >
        1e-3 * f->totals.area_of[TYPE_FP])
        fail_msg("%s: FP polygons %.9g m^2, surface %.9g m^2", name,
                 area[TYPE_FP], f->totals.area_of[TYPE_FP]);
    obj_free(&obj);
}

static void test_obj_roundtrip(void **state)
{
    (void)state;
    char dir[64];
    temp_dir(dir, sizeof dir);
    struct fixture f;
    example_fixture(&f, "roof", 80, 20, 26);
    /* The roof has all three types at this grid. */
    for (int t = 0; t < TYPE_COUNT; t++)
        assert_true(f.totals.count[t] > 0);
    check_obj_roundtrip(&f, dir, "roof");
    fixture_free(&f);

    /* Every panel of the plane is FP and flat: polygons of full area. */
    example_fixture(&f, "plane", 0, 4, 3);
    assert_int_equal(f.totals.count[TYPE_FP], f.panels.npanels);
    check_obj_roundtrip(&f, dir, "plane");
    fixture_free(&f);

    /* Trimmed panels, non-convex FP polygons among them. */
    ring_fixture(&f, 48, 6, 6, 0.003);
    check_obj_roundtrip(&f, dir, "ring");
    fixture_free(&f);
    /* The centre cell of 3 x 3 holds the whole hole: made flat (a 1 m
     * threshold makes every panel FP), it is written as its pieces on
     * its plane, since an OBJ face has no holes. */
    ring_fixture(&f, 48, 3, 3, 1.0);
    assert_int_equal(f.totals.count[TYPE_FP], f.panels.npanels);
    size_t holed = 0;
    for (size_t n = 0; n < f.panels.npanels; n++)
        holed += f.geometry.panel_loop[n + 1] - f.geometry.panel_loop[n] > 1;
    assert_int_equal(holed, 1);
    check_obj_roundtrip(&f, dir, "ring_flat");
    fixture_free(&f);

    char command[200];
    snprintf(command, sizeof command, "rm -rf '%s'", dir);
    assert_int_equal(system(command), 0);
}

/* Writes an SVG map of f to memory. */
static char *map_text(const struct fixture *f,
                      const struct svg_map_options *options)
{
    char *text = NULL;
    size_t size = 0;
    FILE *out = open_memstream(&text, &size);
    assert_non_null(out);
    svg_map_write(out, &f->geometry, &f->panels, &f->totals, options);
    assert_int_equal(fclose(out), 0);
    return text;
}

static void test_svg_map(void **state)
{
    (void)state;
    struct fixture f;
    example_fixture(&f, "roof", 60, 13, 17);
    char dir[64];
    temp_dir(dir, sizeof dir);
    for (int view = SVG_MAP_UV; view <= SVG_MAP_SIDE; view++)
        for (int by = SVG_MAP_BY_TYPE; by <= SVG_MAP_BY_CLASS; by++)
            for (int triangles = 0; triangles <= 1; triangles++) {
                struct svg_map_options options;
                svg_map_defaults(&options);
                options.view = (enum svg_map_view)view;
                options.colour_by = (enum svg_map_colouring)by;
                options.triangles = triangles;
                options.title = "roof <&> \"test\"";
                char *text = map_text(&f, &options);
                /* Exactly one mark per panel. */
                assert_int_equal(count_of(text, "data-i=\""),
                                 f.panels.npanels);
                assert_int_equal(count_of(text, "<path class=\"panel "),
                                 f.panels.npanels);
                for (int t = 0; t < TYPE_COUNT; t++) {
                    char mark[32];
                    snprintf(mark, sizeof mark, "class=\"panel %s\"",
                             panel_type_name((enum panel_type)t));
                    assert_int_equal(count_of(text, mark),
                                     f.totals.count[t]);
                }
                assert_non_null(strstr(text, "grid 13 x 17"));
                assert_non_null(strstr(text, " USD"));
                assert_non_null(strstr(text, "DP area "));
                assert_non_null(strstr(text, "roof &lt;&amp;&gt; "
                                             "&quot;test&quot;"));
                /* The legend lists every type or every class (besides
                 * the page, the UV box of the UV view and the scale bar
                 * of the others). */
                int rows = by == SVG_MAP_BY_CLASS ? CLASS_COUNT : TYPE_COUNT;
                assert_int_equal(count_of(text, "<rect") - 2, (size_t)rows);
                /* A projected view has a scale bar of a round length in
                 * metres, drawn at the view's scale. */
                if (view != SVG_MAP_UV) {
                    const char *bar = strstr(text, "<g class=\"scale-bar\">");
                    assert_non_null(bar);
                    double x, y, w, metres;
                    assert_int_equal(sscanf(bar, "<g class=\"scale-bar\">\n"
                                            "<rect x=\"%lf\" y=\"%lf\" "
                                            "width=\"%lf\"", &x, &y, &w), 3);
                    const char *label = strstr(bar, "data-metres=\"1\">");
                    assert_non_null(label);
                    assert_int_equal(sscanf(label, "data-metres=\"1\">%lf m",
                                            &metres), 1);
                    double mantissa = metres / pow(10, floor(log10(metres)));
                    assert_true(fabs(mantissa - 1) < 1e-9 ||
                                fabs(mantissa - 2) < 1e-9 ||
                                fabs(mantissa - 5) < 1e-9);
                    assert_true(w > 20);
                } else {
                    assert_null(strstr(text, "scale-bar"));
                }
                free(text);
            }
    /* One written to a file is well-formed. */
    struct svg_map_options options;
    svg_map_defaults(&options);
    options.view = SVG_MAP_TOP;
    char path[128];
    snprintf(path, sizeof path, "%s/map.svg", dir);
    struct facet_error err;
    assert_int_equal(svg_map_save(path, 0, &f.geometry, &f.panels,
                                  &f.totals, &options, &err), FACET_OK);
    xml_well_formed(path);
    fixture_free(&f);

    /* Trimmed panels with holes: still one mark each. */
    ring_fixture(&f, 48, 3, 3, 0.003);
    svg_map_defaults(&options);
    char *text = map_text(&f, &options);
    assert_int_equal(count_of(text, "data-i=\""), f.panels.npanels);
    free(text);
    fixture_free(&f);

    enum svg_map_view view;
    assert_int_equal(svg_map_view_parse("front", &view, &err), FACET_OK);
    assert_int_equal(view, SVG_MAP_FRONT);
    assert_int_equal(svg_map_view_parse("back", &view, &err), FACET_EINPUT);
    assert_non_null(strstr(err.message, "back"));
    enum svg_map_colouring by;
    assert_int_equal(svg_map_colouring_parse("class", &by, &err), FACET_OK);
    assert_int_equal(by, SVG_MAP_BY_CLASS);

    char command[200];
    snprintf(command, sizeof command, "rm -rf '%s'", dir);
    assert_int_equal(system(command), 0);
}

/* A mantissa of 1, 2 or 5. */
static int nice_step(double step)
{
    double m = step / pow(10, floor(log10(step) + 1e-12));
    return fabs(m - 1) < 1e-9 || fabs(m - 2) < 1e-9 || fabs(m - 5) < 1e-9;
}

static void test_plot_axis(void **state)
{
    (void)state;
    struct svg_axis a;
    svg_plot_axis(0.013, 0.087, 0.05, 6, &a);
    assert_true(a.min < 0.013 && a.max > 0.087);
    assert_true(fabs(a.step - 0.01) < 1e-15 || fabs(a.step - 0.02) < 1e-15);
    assert_int_equal(a.decimals, 2);
    svg_plot_axis(812345, 1934567, 0.05, 6, &a);
    assert_true(a.min < 812345 && a.max > 1934567);
    assert_true(a.step == 200000);
    assert_int_equal(a.decimals, 0);
    /* One value: a range around it. */
    svg_plot_axis(3, 3, 0.05, 6, &a);
    assert_true(a.min < 3 && a.max > 3);
    /* Values none of which is negative: no negative axis (issue 32 item
     * 3: planarity drawn from -0.5 m). */
    svg_plot_axis(0, 0, 0.05, 6, &a);
    assert_true(a.min == 0 && a.max > 0);
    svg_plot_axis(0.02, 7.3, 0.05, 6, &a);
    assert_true(a.min == 0 && a.max > 7.3);
    svg_plot_axis(-0.02, 7.3, 0.05, 6, &a);
    assert_true(a.min < -0.02 && a.max > 7.3);
    /* Many ranges, from tiny to huge, near and far from zero. */
    unsigned long long seed = 12345;
    for (int k = 0; k < 20000; k++) {
        seed = seed * 6364136223846793005ULL + 1442695040888963407ULL;
        double r1 = (double)(seed >> 11) / 9007199254740992.0;
        seed = seed * 6364136223846793005ULL + 1442695040888963407ULL;
        double r2 = (double)(seed >> 11) / 9007199254740992.0;
        double scale = pow(10, (int)(r1 * 24) - 12);
        double lo = (r2 - 0.5) * scale * 100, hi = lo + r1 * scale;
        svg_plot_axis(lo, hi, 0.05, 6, &a);
        /* below lo, but never below 0 for values none of which is
         * negative */
        int low_ok = lo >= 0 ? a.min >= 0 && a.min <= lo : a.min < lo;
        if (!(low_ok && a.max > hi && nice_step(a.step)))
            fail_msg("[%.17g, %.17g] -> [%.17g, %.17g] step %.17g", lo, hi,
                     a.min, a.max, a.step);
        double ticks = (a.max - a.min) / a.step;
        assert_true(ticks >= 3 && ticks <= 16);
    }
}

/* Counts circles, checks every circle's centre against the frame and
 * returns the axes' ranges (data attributes). */
static void parse_plot(const char *text, double range[4], size_t *circles)
{
    const char *axes = strstr(text, "<g class=\"axes\"");
    assert_non_null(axes);
    assert_int_equal(sscanf(axes, "<g class=\"axes\" data-x-min=\"%lf\" "
                            "data-x-max=\"%lf\" data-y-min=\"%lf\" "
                            "data-y-max=\"%lf\"", &range[0], &range[1],
                            &range[2], &range[3]), 4);
    const char *frame = strstr(text, "class=\"frame\"");
    assert_non_null(frame);
    while (frame > text && strncmp(frame, "<rect", 5) != 0)
        frame--;
    double fx, fy, fw, fh;
    assert_int_equal(sscanf(frame, "<rect x=\"%lf\" y=\"%lf\" width=\"%lf\" "
                            "height=\"%lf\"", &fx, &fy, &fw, &fh), 4);
    *circles = 0;
    for (const char *c = strstr(text, "<circle"); c != NULL;
         c = strstr(c + 1, "<circle")) {
        const char *cx = strstr(c, " cx=\""), *cy = strstr(c, " cy=\"");
        assert_non_null(cx);
        assert_non_null(cy);
        double x = atof(cx + 5), y = atof(cy + 5);
        assert_true(x > fx && x < fx + fw);
        assert_true(y > fy && y < fy + fh);
        (*circles)++;
    }
}

static void test_svg_plot(void **state)
{
    (void)state;
    /* Two runs of options in Figure 13's terms. */
    enum { N1 = 40, N2 = 25 };
    double x1[N1], y1[N1], s1[N1], x2[N2], y2[N2];
    int r1[N1], r2[N2];
    for (int k = 0; k < N1; k++) {
        x1[k] = 0.5 + 3.0 * (k % 7) / 7 + 0.01 * k;
        y1[k] = 1.9e6 - 1.5e5 * x1[k] + 4e4 * ((k * 37) % 11);
        s1[k] = 40 + 7.5 * ((k * 13) % 17);
    }
    for (int k = 0; k < N2; k++) {
        x2[k] = 0.2 + 0.15 * k;
        y2[k] = 1.7e6 + 1e6 / (1 + k) + 3e4 * ((k * 5) % 3);
    }
    struct facet_error err;
    double obj1[2 * N1], obj2[2 * N2];
    for (int k = 0; k < N1; k++) {
        obj1[2 * k] = x1[k];
        obj1[2 * k + 1] = y1[k];
    }
    for (int k = 0; k < N2; k++) {
        obj2[2 * k] = x2[k];
        obj2[2 * k + 1] = y2[k];
    }
    assert_int_equal(pareto_rank(obj1, N1, 2, NULL, r1, NULL, &err),
                     FACET_OK);
    assert_int_equal(pareto_rank(obj2, N2, 2, NULL, r2, NULL, &err),
                     FACET_OK);
    size_t knee1, knee2;
    assert_int_equal(pareto_knee(obj1, N1, 2, r1, &knee1, &err), FACET_OK);
    assert_int_equal(pareto_knee(obj2, N2, 2, r2, &knee2, &err), FACET_OK);
    size_t front1 = 0, front2 = 0;
    for (int k = 0; k < N1; k++)
        front1 += r1[k] == 1;
    for (int k = 0; k < N2; k++)
        front2 += r2[k] == 1;

    struct svg_plot_series series[2] = {
        {"run 1 <exhaustive>", NULL, N1, x1, y1, s1, r1, knee1},
        {"run 2", "#123abc", N2, x2, y2, NULL, r2, knee2},
    };
    struct svg_plot plot;
    svg_plot_defaults(&plot);
    plot.title = "Roof: cost against planarity";
    for (size_t nseries = 1; nseries <= 2; nseries++) {
        plot.series = series;
        plot.nseries = nseries;
        char *text = NULL;
        size_t size = 0;
        FILE *out = open_memstream(&text, &size);
        assert_int_equal(svg_plot_write(out, &plot, &err), FACET_OK);
        fclose(out);
        double range[4];
        size_t circles;
        parse_plot(text, range, &circles);
        size_t n = nseries == 1 ? N1 : N1 + N2;
        assert_int_equal(circles, n);
        assert_int_equal(count_of(text, "<circle class=\"option"), n);
        assert_int_equal(count_of(text, "class=\"option pareto\""),
                         nseries == 1 ? front1 : front1 + front2);
        assert_int_equal(count_of(text, "<polyline class=\"front\""),
                         nseries);
        assert_int_equal(count_of(text, "<path class=\"knee\""), nseries);
        /* The first front's polyline has one point per rank 1 option. */
        const char *points = strstr(strstr(text, "class=\"front\""),
                                    "points=\"");
        size_t commas = 0;
        for (const char *c = points + 8; *c != '"'; c++)
            commas += *c == ',';
        assert_int_equal(commas, front1);
        /* Every point within the axes' ranges. */
        for (size_t s = 0; s < nseries; s++)
            for (size_t k = 0; k < series[s].n; k++) {
                assert_true(series[s].x[k] > range[0] &&
                            series[s].x[k] < range[1]);
                assert_true(series[s].y[k] > range[2] &&
                            series[s].y[k] < range[3]);
            }
        assert_non_null(strstr(text, "planarity (m)"));
        assert_non_null(strstr(text, "cost (USD)"));
        assert_non_null(strstr(text, "DP area (m^2)"));
        assert_non_null(strstr(text, "run 1 &lt;exhaustive&gt;"));
        free(text);
    }

    char dir[64];
    temp_dir(dir, sizeof dir);
    char path[128];
    snprintf(path, sizeof path, "%s/plot.svg", dir);
    assert_int_equal(svg_plot_save(path, 0, &plot, &err), FACET_OK);
    xml_well_formed(path);

    /* Bad values are refused before any file is made. */
    y2[3] = NAN;
    snprintf(path, sizeof path, "%s/bad.svg", dir);
    assert_int_equal(svg_plot_save(path, 0, &plot, &err), FACET_EINPUT);
    assert_non_null(strstr(err.message, "series 2 option 4"));
    assert_false(file_exists(path));
    y2[3] = 1e6;
    series[1].colour = "red\" onload=\"x";
    assert_int_equal(svg_plot_save(path, 0, &plot, &err), FACET_EINPUT);
    assert_false(file_exists(path));

    char command[200];
    snprintf(command, sizeof command, "rm -rf '%s'", dir);
    assert_int_equal(system(command), 0);
}

/* A plot of the one option in series. */
static void one_point_plot(struct svg_plot *plot,
                           const struct svg_plot_series *series)
{
    svg_plot_defaults(plot);
    plot->series = series;
    plot->nseries = 1;
}

static void write_file(const char *path, const char *text)
{
    FILE *out = fopen(path, "w");
    assert_non_null(out);
    fputs(text, out);
    fclose(out);
}

static void test_refuses_existing_paths(void **state)
{
    (void)state;
    struct fixture f;
    example_fixture(&f, "plane", 20, 2, 2);
    char dir[64], obj[128], mtl[128], svg[128];
    temp_dir(dir, sizeof dir);
    snprintf(obj, sizeof obj, "%s/out.OBJ", dir);
    snprintf(mtl, sizeof mtl, "%s/out.mtl", dir);
    snprintf(svg, sizeof svg, "%s/map.svg", dir);
    struct facet_error err;

    /* An existing OBJ: refused, untouched, no MTL made. */
    write_file(obj, "keep\n");
    assert_int_equal(export_obj_save(obj, 0, &f.geometry, &f.panels, &err),
                     FACET_EINPUT);
    assert_non_null(strstr(err.message, obj));
    assert_null(strchr(err.message, '\n'));
    char *text = read_text(obj);
    assert_string_equal(text, "keep\n");
    free(text);
    assert_false(file_exists(mtl));

    /* An existing MTL alone is refused too: it would be overwritten. */
    remove(obj);
    write_file(mtl, "keep\n");
    assert_int_equal(export_obj_save(obj, 0, &f.geometry, &f.panels, &err),
                     FACET_EINPUT);
    assert_non_null(strstr(err.message, mtl));
    assert_false(file_exists(obj));

    /* With force both are written. */
    assert_int_equal(export_obj_save(obj, 1, &f.geometry, &f.panels, &err),
                     FACET_OK);
    text = read_text(mtl);
    assert_non_null(strstr(text, "newmtl FP"));
    free(text);
    text = read_text(obj);
    assert_non_null(strstr(text, "mtllib out.mtl\n"));
    free(text);

    /* The pictures likewise. */
    struct svg_map_options options;
    svg_map_defaults(&options);
    write_file(svg, "keep\n");
    assert_int_equal(svg_map_save(svg, 0, &f.geometry, &f.panels, &f.totals,
                                  &options, &err), FACET_EINPUT);
    assert_non_null(strstr(err.message, svg));
    assert_int_equal(svg_map_save(svg, 1, &f.geometry, &f.panels, &f.totals,
                                  &options, &err), FACET_OK);
    static const double x = 1, y = 2;
    static const struct svg_plot_series one = {NULL, NULL, 1, &x, &y, NULL,
                                               NULL, SIZE_MAX};
    struct svg_plot plot;
    one_point_plot(&plot, &one);
    assert_int_equal(svg_plot_save(svg, 0, &plot, &err), FACET_EINPUT);
    assert_non_null(strstr(err.message, svg));
    assert_int_equal(svg_plot_save(svg, 1, &plot, &err), FACET_OK);
    text = read_text(svg);
    assert_int_equal(count_of(text, "<circle"), 1);
    free(text);

    fixture_free(&f);
    char command[200];
    snprintf(command, sizeof command, "rm -rf '%s'", dir);
    assert_int_equal(system(command), 0);
}

/* Every writer, at path: refused with a one-line message naming it, and
 * nothing left behind. */
static void check_unwritable(const struct fixture *f, const char *path)
{
    struct facet_error err;
    char partial[600];
    snprintf(partial, sizeof partial, "%s.partial", path);
    int rc = export_obj_save(path, 0, &f->geometry, &f->panels, &err);
    assert_true(rc == FACET_EINPUT || rc == FACET_EWORK);
    assert_non_null(strstr(err.message, path));
    assert_null(strchr(err.message, '\n'));
    assert_false(file_exists(path));
    assert_false(file_exists(partial));

    struct svg_map_options options;
    svg_map_defaults(&options);
    rc = svg_map_save(path, 0, &f->geometry, &f->panels, &f->totals,
                      &options, &err);
    assert_true(rc == FACET_EINPUT || rc == FACET_EWORK);
    assert_non_null(strstr(err.message, path));
    assert_false(file_exists(partial));

    static const double x = 1, y = 2;
    static const struct svg_plot_series one = {NULL, NULL, 1, &x, &y, NULL,
                                               NULL, SIZE_MAX};
    struct svg_plot plot;
    one_point_plot(&plot, &one);
    rc = svg_plot_save(path, 0, &plot, &err);
    assert_true(rc == FACET_EINPUT || rc == FACET_EWORK);
    assert_non_null(strstr(err.message, path));
    assert_false(file_exists(partial));
}

static void test_unwritable_directory(void **state)
{
    (void)state;
    struct fixture f;
    example_fixture(&f, "plane", 20, 2, 2);
    char dir[64], path[256];
    temp_dir(dir, sizeof dir);
    /* A directory that does not exist. */
    snprintf(path, sizeof path, "%s/missing/out.obj", dir);
    check_unwritable(&f, path);
    /* A "directory" that is a file. */
    char file[128];
    snprintf(file, sizeof file, "%s/file", dir);
    write_file(file, "x\n");
    snprintf(path, sizeof path, "%s/out.svg", file);
    check_unwritable(&f, path);
    /* A read-only directory (root writes anyway, so only as a user). */
    if (geteuid() != 0) {
        char locked[128];
        snprintf(locked, sizeof locked, "%s/locked", dir);
        assert_int_equal(mkdir(locked, 0500), 0);
        snprintf(path, sizeof path, "%s/out.obj", locked);
        check_unwritable(&f, path);
        chmod(locked, 0700);
    }
    fixture_free(&f);
    char command[200];
    snprintf(command, sizeof command, "rm -rf '%s'", dir);
    assert_int_equal(system(command), 0);
}

static void test_svg_helpers(void **state)
{
    (void)state;
    char text[64];
    svg_format_number(text, sizeof text, 1.5, 3);
    assert_string_equal(text, "1.5");
    svg_format_number(text, sizeof text, 2.0, 2);
    assert_string_equal(text, "2");
    svg_format_number(text, sizeof text, -0.0001, 2);
    assert_string_equal(text, "0");
    svg_format_number(text, sizeof text, -12.345678, 2);
    assert_string_equal(text, "-12.35");
    svg_format_number(text, sizeof text, NAN, 2);
    assert_string_equal(text, "0");
    number_grouped(text, sizeof text, 1234567.891, 1);
    assert_string_equal(text, "1,234,567.9");
    number_grouped(text, sizeof text, -1234, 0);
    assert_string_equal(text, "-1,234");
    number_grouped(text, sizeof text, 999, 0);
    assert_string_equal(text, "999");
    number_grouped(text, sizeof text, -0.001, 1);
    assert_string_equal(text, "0.0");
    number_grouped(text, sizeof text, 0.05, 2);
    assert_string_equal(text, "0.05");

    char *escaped = NULL;
    size_t size = 0;
    FILE *out = open_memstream(&escaped, &size);
    svg_escape(out, "a<b & \"c\" 'd' m\xc2\xb2 \xff\x01 \xe2\x82");
    fclose(out);
    assert_string_equal(escaped, "a&lt;b &amp; &quot;c&quot; &apos;d&apos; "
                                 "m\xc2\xb2 ?? ??");
    free(escaped);

    /* Every type and class has its own colour. */
    for (int a = 0; a < CLASS_COUNT; a++)
        for (int b = a + 1; b < CLASS_COUNT; b++)
            assert_string_not_equal(svg_class_colour((enum panel_class)a),
                                    svg_class_colour((enum panel_class)b));
    assert_string_not_equal(svg_type_colour(TYPE_FP),
                            svg_type_colour(TYPE_SP));
    assert_string_not_equal(svg_type_colour(TYPE_SP),
                            svg_type_colour(TYPE_DP));
}

/* ---- Colour vision ----------------------------------------------------- */

static double srgb_to_linear(double c)
{
    return c <= 0.04045 ? c / 12.92 : pow((c + 0.055) / 1.055, 2.4);
}

static double lab_f(double t)
{
    return t > 0.008856 ? cbrt(t) : 7.787 * t + 16.0 / 116;
}

/* CIE L*a*b* (D65) of "#rrggbb" as seen through the linear-RGB matrix m
 * (the identity for normal vision, Vienot, Brettel and Mollon 1999 for
 * protanopia and deuteranopia, and a tritanopia projection). */
static void lab_seen(const char *hex, const double m[3][3], double lab[3])
{
    unsigned r, g, b;
    assert_int_equal(sscanf(hex, "#%02x%02x%02x", &r, &g, &b), 3);
    double in[3] = {srgb_to_linear(r / 255.0), srgb_to_linear(g / 255.0),
                    srgb_to_linear(b / 255.0)};
    double l[3];
    for (int i = 0; i < 3; i++)
        l[i] = m[i][0] * in[0] + m[i][1] * in[1] + m[i][2] * in[2];
    double x = 0.4124 * l[0] + 0.3576 * l[1] + 0.1805 * l[2];
    double y = 0.2126 * l[0] + 0.7152 * l[1] + 0.0722 * l[2];
    double z = 0.0193 * l[0] + 0.1192 * l[1] + 0.9505 * l[2];
    double fx = lab_f(x / 0.95047), fy = lab_f(y), fz = lab_f(z / 1.08883);
    lab[0] = 116 * fy - 16;
    lab[1] = 500 * (fx - fy);
    lab[2] = 200 * (fy - fz);
}

/* The least colour difference (CIE76 delta E) between any two of the
 * colours, under the vision m. */
static double least_difference(const char *const *colour, int n,
                               const double m[3][3])
{
    double least = INFINITY;
    for (int a = 0; a < n; a++)
        for (int b = a + 1; b < n; b++) {
            double p[3], q[3];
            lab_seen(colour[a], m, p);
            lab_seen(colour[b], m, q);
            double d = sqrt((p[0] - q[0]) * (p[0] - q[0]) +
                            (p[1] - q[1]) * (p[1] - q[1]) +
                            (p[2] - q[2]) * (p[2] - q[2]));
            least = fmin(least, d);
        }
    return least;
}

/* The colours of panel types and classes stay apart for readers with
 * protanopia, deuteranopia and tritanopia, simulated: types by a delta E
 * of 30 or more (clearly different at a glance), classes by 7 or more
 * (distinguishable side by side). Red against green, as FP against DP
 * were before, is 0.7 under deuteranopia. */
static void test_palette_colour_blind(void **state)
{
    (void)state;
    static const double vision[4][3][3] = {
        {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}},
        {{0.11238, 0.88762, 0}, {0.11238, 0.88762, 0},
         {0.00401, -0.00401, 1}},
        {{0.29275, 0.70725, 0}, {0.29275, 0.70725, 0},
         {-0.02234, 0.02234, 1}},
        {{1, 0.1273989, -0.1273989}, {0, 0.8739093, 0.1260907},
         {0, 0.8739093, 0.1260907}},
    };
    static const char *const name[4] = {"normal", "protanopia",
                                        "deuteranopia", "tritanopia"};
    const char *types[TYPE_COUNT], *classes[CLASS_COUNT];
    for (int t = 0; t < TYPE_COUNT; t++)
        types[t] = svg_type_colour((enum panel_type)t);
    for (int c = 0; c < CLASS_COUNT; c++)
        classes[c] = svg_class_colour((enum panel_class)c);
    for (int v = 0; v < 4; v++) {
        double dt = least_difference(types, TYPE_COUNT, vision[v]);
        double dc = least_difference(classes, CLASS_COUNT, vision[v]);
        print_message("%-13s types %.1f, classes %.1f\n", name[v], dt, dc);
        assert_true(dt >= 30);
        assert_true(dc >= 7);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_geometry_of_examples),
        cmocka_unit_test(test_geometry_of_trimmed_panels),
        cmocka_unit_test(test_outline_by_brute_force),
        cmocka_unit_test(test_obj_roundtrip),
        cmocka_unit_test(test_svg_map),
        cmocka_unit_test(test_palette_colour_blind),
        cmocka_unit_test(test_plot_axis),
        cmocka_unit_test(test_svg_plot),
        cmocka_unit_test(test_refuses_existing_paths),
        cmocka_unit_test(test_unwritable_directory),
        cmocka_unit_test(test_svg_helpers),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
