/*
 * planar_option.c: a planarized option evaluated as any option. See
 * planar_option.h.
 */
#include "core/planar/planar_option.h"

#include <assert.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/base/quad.h"
#include "core/base/vec3.h"
#include "core/evaluate/evaluate.h"
#include "core/planar/quad_grid.h"

/* The point at (s, t) in [0, 1]^2 of quad c, bilinear: on a planar quad
 * it lies in its plane. */
static void quad_point(const double c[4][3], double s, double t,
                       double out[3])
{
    for (int d = 0; d < 3; d++)
        out[d] = (1 - s) * (1 - t) * c[0][d] + s * (1 - t) * c[1][d] +
                 s * t * c[2][d] + (1 - s) * t * c[3][d];
}

/* The triangle (a, b, c)'s area and its area times its centroid, added. */
static void add_triangle(const double a[3], const double b[3],
                         const double c[3], double *area, double moment[3])
{
    double ab[3], ac[3], n[3];
    vec3_sub(b, a, ab);
    vec3_sub(c, a, ac);
    vec3_cross(ab, ac, n);
    double t = 0.5 * vec3_length(n);
    *area += t;
    for (int d = 0; d < 3; d++)
        moment[d] += t * (a[d] + b[d] + c[d]) / 3;
}

/* Makes panel its moved quad c (planar_option.h's list), typed by the
 * planarity tolerance. */
static void make_quad(struct panel *panel, const double c[4][3],
                      double relative, double tolerance,
                      const struct nearest_index *index)
{
    double d1[3], d2[3], n[3];
    vec3_sub(c[2], c[0], d1);
    vec3_sub(c[3], c[1], d2);
    vec3_cross(d1, d2, n);
    double vector_area = 0.5 * vec3_length(n);
    if (vec3_normalize(n) && vec3_dot(n, panel->normal) < 0)
        for (int d = 0; d < 3; d++)
            n[d] = -n[d];
    double area = 0, moment[3] = {0, 0, 0};
    add_triangle(c[0], c[1], c[2], &area, moment);
    add_triangle(c[0], c[2], c[3], &area, moment);
    for (int d = 0; d < 3; d++)
        panel->centroid[d] = area > 0 ? moment[d] / area
                                      : (c[0][d] + c[2][d]) / 2;
    if (vec3_length(n) > 0)
        memcpy(panel->normal, n, sizeof n);
    memcpy(panel->corner, c, sizeof panel->corner);
    panel->area = vector_area;
    panel->diameter = quad_diagonal(c);
    panel->corner_planarity = quad_planarity(c);
    double most = 0, squares = 0;
    const int m = PLANAR_OPTION_LATTICE;
    for (int a = 0; a < m; a++)
        for (int b = 0; b < m; b++) {
            double x[3];
            quad_point(c, (double)a / (m - 1), (double)b / (m - 1), x);
            struct nearest_hit hit;
            nearest_point(index, x, &hit);
            most = fmax(most, hit.distance);
            squares += hit.distance * hit.distance;
        }
    panel->deviation = most;
    panel->p_dist = panel->area * squares / (m * m);
    panel->type = relative <= tolerance ? TYPE_FP : TYPE_DP;
}

/* The quads of r that missed o: over the planarity tolerance, or with a
 * corner beyond the closeness budget. None exactly when r is feasible. */
static size_t quads_missed(const struct planarize_result *r,
                           const struct planarize_options *o)
{
    static const int offset[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    size_t over = 0;
    for (int j = 0; j < r->grid.nv; j++)
        for (int i = 0; i < r->grid.nu; i++) {
            size_t q = (size_t)j * (size_t)r->grid.nu + (size_t)i;
            if (!r->grid.quad[q])
                continue;
            int missed = r->relative[q] > o->planarity;
            for (int c = 0; c < 4; c++)
                missed |= r->distance[(size_t)(j + offset[c][1]) *
                                          (size_t)(r->grid.nu + 1) +
                                      (size_t)(i + offset[c][0])] >
                          o->closeness;
            over += missed;
        }
    return over;
}

/* Moves every full panel of panels onto its quad of r. */
static int move_panels(const struct planarize_result *r,
                       const struct planarize_options *o,
                       const struct nearest_index *index,
                       struct panelization *panels, struct facet_error *err)
{
    size_t m = panels->npanels ? panels->npanels : 1;
    panels->corner_distance = malloc(m * sizeof *panels->corner_distance);
    panels->corner_moved = malloc(m * sizeof *panels->corner_moved);
    if (panels->corner_distance == NULL || panels->corner_moved == NULL)
        return facet_error_set(err, FACET_EWORK,
                               "out of memory for %zu panels", m);
    static const int offset[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    for (size_t k = 0; k < panels->npanels; k++) {
        struct panel *panel = &panels->panels[k];
        panels->corner_distance[k] = panels->corner_moved[k] = NAN;
        size_t q = (size_t)panel->j * (size_t)r->grid.nu + (size_t)panel->i;
        if (panel->trimmed || panel->ncorners != 4 || !r->grid.quad[q])
            continue;
        double c[4][3], distance = 0, moved = 0;
        quad_grid_corners(&r->grid, panel->i, panel->j, c);
        for (int corner = 0; corner < 4; corner++) {
            size_t node = (size_t)(panel->j + offset[corner][1]) *
                              (size_t)(r->grid.nu + 1) +
                          (size_t)(panel->i + offset[corner][0]);
            distance = fmax(distance, r->distance[node]);
            moved = fmax(moved, r->moved[node]);
        }
        panels->corner_distance[k] = distance;
        panels->corner_moved[k] = moved;
        make_quad(panel, c, r->relative[q], o->planarity, index);
    }
    return FACET_OK;
}

int planar_option_evaluate(const struct surface *surface,
                           const struct nearest_index *index,
                           const struct option_params *params,
                           const struct planarize_options *o,
                           struct panelization *panels,
                           struct option_totals *totals,
                           struct planarize_result *result,
                           struct facet_error *err)
{
    memset(result, 0, sizeof *result);
    struct quad_grid grid;
    memset(&grid, 0, sizeof grid);
    struct evaluation_shared shared;
    memset(&shared, 0, sizeof shared);
    shared.stop = o->stop;
    int rc = option_evaluate(surface, params, &shared, panels, totals, err);
    double joint_length = rc == FACET_OK ? totals->joint_length : NAN;
    if (rc == FACET_OK)
        rc = quad_grid_from_panels(panels, &grid, err);
    if (rc == FACET_OK)
        rc = planarize(&surface->mesh, index, &grid, o, result, err);
    quad_grid_free(&grid);
    if (rc == FACET_OK)
        rc = move_panels(result, o, index, panels, err);
    if (rc == FACET_OK)
        rc = option_evaluate_typed(surface, params, joint_length, panels,
                                   totals, err);
    if (rc != FACET_OK)
        return rc;
    totals->planarized = 1;
    totals->closeness_reached = result->max_distance;
    totals->closeness_mean = result->mean_distance;
    totals->planarity_reached = result->max_relative;
    totals->planar_over = quads_missed(result, o);
    assert((totals->planar_over == 0) == (result->feasible != 0));
    totals->feasible =
        classify_violation(totals, params->classify.max_panel_area) == 0;
    return FACET_OK;
}
