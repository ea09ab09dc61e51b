/*
 * export_obj.c: OBJ + MTL of an evaluated option. See export_obj.h.
 */
#include "core/out/export_obj.h"

#include <ctype.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "core/classify/classify.h"
#include "core/out/outfile.h"
#include "core/out/svg.h"
#include "core/base/vec3.h"

/* Twelve significant digits: a micrometre at a kilometre from the origin,
 * and areas exact to far below what the tests ask (1e-6). */
#define OBJ_NUMBER "%.12g"

static void write_vertex(FILE *out, const double x[3], const double uv[2])
{
    fprintf(out, "v " OBJ_NUMBER " " OBJ_NUMBER " " OBJ_NUMBER "\n",
            x[0], x[1], x[2]);
    fprintf(out, "vt " OBJ_NUMBER " " OBJ_NUMBER "\n", uv[0], uv[1]);
}

/* Writes panel n's vertices (projected onto its plane when flat is set)
 * and its pieces as faces; *next is the OBJ number of the next vertex. */
static void write_pieces(FILE *out, const struct panel_geometry *g,
                         const struct panel *panel, size_t n, int flat,
                         size_t *next)
{
    size_t v0 = g->panel_vertex[n], v1 = g->panel_vertex[n + 1];
    for (size_t v = v0; v < v1; v++) {
        double x[3];
        if (flat)
            panel_geometry_project(panel, &g->position[3 * v], x);
        else
            memcpy(x, &g->position[3 * v], sizeof x);
        write_vertex(out, x, &g->uv[2 * v]);
    }
    for (size_t p = g->panel_piece[n]; p < g->panel_piece[n + 1]; p++) {
        fputc('f', out);
        for (size_t c = g->piece_start[p]; c < g->piece_start[p + 1]; c++) {
            size_t k = *next + (g->corner[c] - v0);
            fprintf(out, " %zu/%zu", k, k);
        }
        fputc('\n', out);
    }
    *next += v1 - v0;
}

/* Whether outline point b lies on the line from a to c to rounding (its
 * distance from it under 1e-9 of the panel's diameter): a point of a
 * straight edge, which would make a fan of the polygon hold zero-area
 * triangles. */
static int on_line(const double *a, const double *b, const double *c,
                   double diameter)
{
    double ab[3], ac[3], cross[3];
    vec3_sub(b, a, ab);
    vec3_sub(c, a, ac);
    vec3_cross(ab, ac, cross);
    double base = sqrt(vec3_dot(ac, ac));
    double tol = 1e-9 * diameter;
    return base > 0 ? sqrt(vec3_dot(cross, cross)) / base <= tol
                    : sqrt(vec3_dot(ab, ab)) <= tol;
}

/* Writes trimmed FP panel n as the polygon of its one outline loop,
 * projected onto its plane, without the points that lie on a straight
 * edge between their neighbours. */
static void write_outline(FILE *out, const struct panel_geometry *g,
                          const struct panel *panel, size_t n, size_t *next)
{
    size_t l = g->panel_loop[n];
    size_t k0 = g->loop_start[l], k1 = g->loop_start[l + 1];
    size_t count = k1 - k0, written = 0;
    const double *plane = g->outline_plane;
    for (size_t k = k0; k < k1; k++) {
        size_t before = k > k0 ? k - 1 : k1 - 1;
        size_t after = k + 1 < k1 ? k + 1 : k0;
        /* Points of one straight run are dropped all but its ends; a
         * polygon keeps three points at least. */
        if (count - (k - k0) + written > 3 &&
            on_line(&plane[3 * before], &plane[3 * k], &plane[3 * after],
                    panel->diameter))
            continue;
        write_vertex(out, &plane[3 * k], &g->uv[2 * g->outline[k]]);
        written++;
    }
    fputc('f', out);
    for (size_t k = 0; k < written; k++)
        fprintf(out, " %zu/%zu", *next + k, *next + k);
    fputc('\n', out);
    *next += written;
}

/* Writes full-cell FP panel n as the planar quad of its four cell corners
 * projected onto its plane, wound as the surface faces. */
static void write_quad(FILE *out, const struct panelization *panels,
                       const struct panel *panel, size_t *next)
{
    double du = (panels->umax - panels->umin) / panels->nu;
    double dv = (panels->vmax - panels->vmin) / panels->nv;
    static const int step[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    double x[4][3], uv[4][2];
    for (int c = 0; c < 4; c++) {
        panel_geometry_project(panel, panel->corner[c], x[c]);
        uv[c][0] = panels->umin + (panel->i + step[c][0]) * du;
        uv[c][1] = panels->vmin + (panel->j + step[c][1]) * dv;
    }
    /* Newell's normal of the quad against the panel's (the surface's
     * side). */
    double normal[3] = {0, 0, 0};
    for (int c = 0; c < 4; c++) {
        const double *a = x[c], *b = x[(c + 1) % 4];
        normal[0] += (a[1] - b[1]) * (a[2] + b[2]);
        normal[1] += (a[2] - b[2]) * (a[0] + b[0]);
        normal[2] += (a[0] - b[0]) * (a[1] + b[1]);
    }
    int reverse = vec3_dot(normal, panel->normal) < 0;
    for (int c = 0; c < 4; c++) {
        int k = reverse ? 3 - c : c;
        write_vertex(out, x[k], uv[k]);
    }
    fprintf(out, "f %zu/%zu %zu/%zu %zu/%zu %zu/%zu\n", *next, *next,
            *next + 1, *next + 1, *next + 2, *next + 2, *next + 3, *next + 3);
    *next += 4;
}

void export_obj_write(FILE *out, const char *mtl_name,
                      const struct panel_geometry *g,
                      const struct panelization *panels)
{
    size_t count[TYPE_COUNT] = {0, 0, 0};
    for (size_t n = 0; n < panels->npanels; n++)
        if ((unsigned)panels->panels[n].type < TYPE_COUNT)
            count[panels->panels[n].type]++;
    fprintf(out, "# Facet panels: grid %dx%d, %zu panels (FP %zu, SP %zu, "
            "DP %zu); lengths in metres\n", panels->nu, panels->nv,
            panels->npanels, count[TYPE_FP], count[TYPE_SP], count[TYPE_DP]);
    fputs("# o FP, SP, DP: the panels of each type; g panel_I_J: one panel; "
          "g mould_K: the SP or DP panels of mould family K\n"
          "# FP: a full cell is the planar quad of its corners on its "
          "best-fit plane, a trimmed one its outline there; SP, DP: the "
          "surface patch; vt: the surface's UV\n", out);
    fprintf(out, "mtllib %s\n", mtl_name);
    size_t next = 1;
    /* One object per type, so that CAD layers and Blender collections
     * come out by type; within it a group per panel. */
    for (int type = 0; type < TYPE_COUNT; type++) {
        if (count[type] == 0)
            continue;
        fprintf(out, "o %s\n", panel_type_name((enum panel_type)type));
        for (size_t n = 0; n < panels->npanels && n < g->npanels; n++) {
            const struct panel *panel = &panels->panels[n];
            if ((int)panel->type != type)
                continue;
            /* A curved panel is in its mould's group too: selecting
             * mould_K in CAD selects every panel cast in it. */
            fprintf(out, "g panel_%d_%d", panel->i, panel->j);
            if (panel->mould >= 0)
                fprintf(out, " mould_%d", panel->mould);
            fprintf(out, "\nusemtl %s\n", panel_type_name(panel->type));
            if (panel->type != TYPE_FP)
                write_pieces(out, g, panel, n, 0, &next);
            else if (!panel->trimmed && panel->ncorners == 4)
                write_quad(out, panels, panel, &next);
            else if (g->panel_loop[n + 1] - g->panel_loop[n] == 1)
                write_outline(out, g, panel, n, &next);
            else
                write_pieces(out, g, panel, n, 1, &next);
        }
    }
}

void export_obj_write_mtl(FILE *out)
{
    static const char *const meaning[TYPE_COUNT] = {
        "flat panel", "single-curved panel", "double-curved panel",
    };
    fputs("# Facet panel materials\n", out);
    for (int t = 0; t < TYPE_COUNT; t++) {
        const char *hex = svg_type_colour((enum panel_type)t);
        unsigned long rgb = strtoul(hex + 1, NULL, 16);
        fprintf(out, "\n# %s\nnewmtl %s\nKa 0 0 0\nKd %.4f %.4f %.4f\n"
                "Ks 0 0 0\nd 1\nillum 1\n", meaning[t],
                panel_type_name((enum panel_type)t),
                (double)((rgb >> 16) & 0xff) / 255,
                (double)((rgb >> 8) & 0xff) / 255,
                (double)(rgb & 0xff) / 255);
    }
}

int export_obj_mtl_path(const char *path, char *mtl, size_t size,
                        struct facet_error *err)
{
    return outfile_sibling(path, ".obj", ".mtl", mtl, size, err);
}

int export_obj_save(const char *path, int force,
                    const struct panel_geometry *g,
                    const struct panelization *panels,
                    struct facet_error *err)
{
    char mtl[4096];
    int rc = export_obj_mtl_path(path, mtl, sizeof mtl, err);
    if (rc == FACET_OK)
        rc = outfile_check(path, force, err);
    if (rc == FACET_OK)
        rc = outfile_check(mtl, force, err);
    if (rc != FACET_OK)
        return rc;
    /* mtllib is relative to the OBJ: the MTL's own name. */
    const char *slash = strrchr(mtl, '/');
    const char *mtl_name = slash ? slash + 1 : mtl;

    int mtl_existed = access(mtl, F_OK) == 0;
    struct outfile obj_file, mtl_file;
    rc = outfile_open(&obj_file, path, force, err);
    if (rc != FACET_OK)
        return rc;
    rc = outfile_open(&mtl_file, mtl, force, err);
    if (rc != FACET_OK) {
        outfile_abort(&obj_file);
        return rc;
    }
    export_obj_write(obj_file.out, mtl_name, g, panels);
    export_obj_write_mtl(mtl_file.out);
    /* The MTL first: an OBJ is never left naming a missing MTL. */
    rc = outfile_commit(&mtl_file, err);
    if (rc != FACET_OK) {
        outfile_abort(&obj_file);
        return rc;
    }
    rc = outfile_commit(&obj_file, err);
    if (rc != FACET_OK && !mtl_existed)
        remove(mtl);  /* leave nothing of a failed export behind */
    return rc;
}
