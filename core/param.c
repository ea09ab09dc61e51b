/*
 * param.c: vt, plane projection or mean-value parameterization. See param.h.
 */
#include "param.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "sym3.h"
#include "vec3.h"

#define PI 3.14159265358979323846

const char *param_method_name(enum param_method method)
{
    switch (method) {
    case PARAM_VT:
        return "vt";
    case PARAM_PLANE:
        return "plane";
    default:
        return "harmonic";
    }
}

void param_free(struct parameterization *param)
{
    free(param->uv);
    memset(param, 0, sizeof *param);
}

static int folds(const struct uv_report *report)
{
    return report->flipped > 0 || report->overlapping > 0;
}

/* Per-corner UV from per-vertex (u, v). */
static double *corners_from_vertices(const struct mesh *mesh,
                                     const double *vertex_uv)
{
    double *uv = malloc(sizeof(double) * 6 * (mesh->ntriangles ? mesh->ntriangles : 1));
    if (uv == NULL)
        return NULL;
    for (size_t t = 0; t < mesh->ntriangles; t++)
        for (int k = 0; k < 3; k++) {
            uint32_t v = mesh->triangle[3 * t + k];
            uv[6 * t + 2 * k] = vertex_uv[2 * v];
            uv[6 * t + 2 * k + 1] = vertex_uv[2 * v + 1];
        }
    return uv;
}

/* Projects every vertex onto the least-squares plane of the vertices, u
 * along the direction of largest spread, v across it. */
static double *plane_projection(const struct mesh *mesh)
{
    size_t n = mesh->nvertices;
    double mean[3] = {0, 0, 0}, covariance[9] = {0};
    for (size_t v = 0; v < n; v++)
        for (int x = 0; x < 3; x++)
            mean[x] += mesh->position[3 * v + x] / (double)n;
    for (size_t v = 0; v < n; v++)
        for (int r = 0; r < 3; r++)
            for (int q = 0; q < 3; q++)
                covariance[3 * r + q] +=
                    (mesh->position[3 * v + r] - mean[r]) *
                    (mesh->position[3 * v + q] - mean[q]);
    double value[3], axis[3][3];
    sym3_eigen(covariance, value, axis);

    /* Keep the winding: v = normal x u with the normal on the side of the
     * faces' normals, so a surface seen from its front maps unmirrored. */
    double normal_sum[3] = {0, 0, 0};
    for (size_t t = 0; t < mesh->ntriangles; t++)
        for (int x = 0; x < 3; x++)
            normal_sum[x] += mesh->face_area[t] * mesh->face_normal[3 * t + x];
    double *normal = axis[0], *u_axis = axis[2], v_axis[3];
    if (normal[0] * normal_sum[0] + normal[1] * normal_sum[1] +
        normal[2] * normal_sum[2] < 0)
        for (int x = 0; x < 3; x++)
            normal[x] = -normal[x];
    v_axis[0] = normal[1] * u_axis[2] - normal[2] * u_axis[1];
    v_axis[1] = normal[2] * u_axis[0] - normal[0] * u_axis[2];
    v_axis[2] = normal[0] * u_axis[1] - normal[1] * u_axis[0];

    double *vertex_uv = malloc(sizeof(double) * 2 * (n ? n : 1));
    if (vertex_uv == NULL)
        return NULL;
    for (size_t v = 0; v < n; v++) {
        double d[3];
        for (int x = 0; x < 3; x++)
            d[x] = mesh->position[3 * v + x] - mean[x];
        vertex_uv[2 * v] = d[0] * u_axis[0] + d[1] * u_axis[1] +
                           d[2] * u_axis[2];
        vertex_uv[2 * v + 1] = d[0] * v_axis[0] + d[1] * v_axis[1] +
                               d[2] * v_axis[2];
    }
    return vertex_uv;
}

static double edge_length(const struct mesh *mesh, uint32_t a, uint32_t b)
{
    return vec3_distance(mesh->position + 3 * (size_t)a,
                         mesh->position + 3 * (size_t)b);
}

/* The angle of triangle t at its corner k (radians). */
static double corner_angle(const struct mesh *mesh, size_t t, int k)
{
    const uint32_t *tri = mesh->triangle + 3 * t;
    const double *a = mesh->position + 3 * (size_t)tri[k];
    const double *b = mesh->position + 3 * (size_t)tri[(k + 1) % 3];
    const double *c = mesh->position + 3 * (size_t)tri[(k + 2) % 3];
    double ab[3], ac[3], n[3];
    vec3_sub(b, a, ab);
    vec3_sub(c, a, ac);
    vec3_cross(ab, ac, n);
    return atan2(vec3_length(n), vec3_dot(ab, ac));
}

/* Places the boundary loop on a rectangle when it has four clear corners
 * (vertices where the surface's angle is under 135 degrees), keeping the
 * sides' lengths, and on a circle by arc length otherwise. */
static void place_boundary(const struct mesh *mesh, const double *angle_sum,
                           double *vertex_uv)
{
    const uint32_t *loop = mesh->loop_vertices + mesh->loop_start[0];
    size_t count = mesh->loop_start[1] - mesh->loop_start[0];
    double perimeter = 0;
    for (size_t k = 0; k < count; k++)
        perimeter += edge_length(mesh, loop[k], loop[(k + 1) % count]);

    /* The four sharpest boundary vertices, in loop order. */
    size_t corner[4];
    int ncorners = 0;
    for (int c = 0; c < 4; c++) {
        size_t best = count;
        for (size_t k = 0; k < count; k++) {
            int taken = 0;
            for (int x = 0; x < ncorners; x++)
                taken |= corner[x] == k;
            if (!taken && (best == count ||
                           angle_sum[loop[k]] < angle_sum[loop[best]]))
                best = k;
        }
        if (best == count || angle_sum[loop[best]] > 0.75 * PI)
            break;
        corner[ncorners++] = best;
    }

    if (ncorners == 4 && count >= 4) {
        for (int x = 0; x < 4; x++)
            for (int y = x + 1; y < 4; y++)
                if (corner[y] < corner[x]) {
                    size_t swap = corner[x];
                    corner[x] = corner[y];
                    corner[y] = swap;
                }
        double side[4] = {0, 0, 0, 0};
        for (int s = 0; s < 4; s++)
            for (size_t k = corner[s]; k != corner[(s + 1) % 4];
                 k = (k + 1) % count)
                side[s] += edge_length(mesh, loop[k], loop[(k + 1) % count]);
        double width = (side[0] + side[2]) / 2;
        double height = (side[1] + side[3]) / 2;
        static const double start[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
        for (int s = 0; s < 4; s++) {
            double along = 0;
            const double *from = start[s], *to = start[(s + 1) % 4];
            for (size_t k = corner[s]; k != corner[(s + 1) % 4];
                 k = (k + 1) % count) {
                double f = side[s] > 0 ? along / side[s] : 0;
                vertex_uv[2 * loop[k]] = width * (from[0] + f * (to[0] - from[0]));
                vertex_uv[2 * loop[k] + 1] =
                    height * (from[1] + f * (to[1] - from[1]));
                along += edge_length(mesh, loop[k], loop[(k + 1) % count]);
            }
        }
        return;
    }
    double along = 0, radius = perimeter / (2 * PI);
    for (size_t k = 0; k < count; k++) {
        double a = perimeter > 0 ? 2 * PI * along / perimeter : 0;
        vertex_uv[2 * loop[k]] = radius * cos(a);
        vertex_uv[2 * loop[k] + 1] = radius * sin(a);
        along += edge_length(mesh, loop[k], loop[(k + 1) % count]);
    }
}

/* The mean-value system over the interior vertices, in compressed rows:
 * row i holds w_ij for every neighbour j (interior or boundary). */
struct mean_value_system {
    size_t n;
    uint32_t *row_start;   /* n + 1 */
    uint32_t *column;      /* neighbour vertex */
    double *weight;        /* w_ij > 0 */
    double *diagonal;      /* sum of the row's weights */
};

static void system_free(struct mean_value_system *s)
{
    free(s->row_start);
    free(s->column);
    free(s->weight);
    free(s->diagonal);
}

/* Floater's weights w_ij = (tan(a/2) + tan(b/2)) / |x_i - x_j|, a and b the
 * angles at i of the two triangles beside edge ij. */
static int build_system(const struct mesh *mesh,
                        struct mean_value_system *s)
{
    size_t n = mesh->nvertices;
    memset(s, 0, sizeof *s);
    s->n = n;
    s->row_start = calloc(n + 1, sizeof *s->row_start);
    s->diagonal = calloc(n ? n : 1, sizeof *s->diagonal);
    size_t capacity = 6 * mesh->ntriangles + 1;
    s->column = malloc(capacity * sizeof *s->column);
    s->weight = calloc(capacity, sizeof *s->weight);
    if (!s->row_start || !s->diagonal || !s->column || !s->weight)
        return FACET_EWORK;
    size_t used = 0;
    for (size_t v = 0; v < n; v++) {
        s->row_start[v] = (uint32_t)used;
        for (uint32_t k = mesh->vertex_start[v]; k < mesh->vertex_start[v + 1];
             k++) {
            uint32_t t = mesh->vertex_triangles[k];
            const uint32_t *tri = mesh->triangle + 3 * (size_t)t;
            int corner = tri[0] == v ? 0 : tri[1] == v ? 1 : 2;
            double half = tan(corner_angle(mesh, t, corner) / 2);
            for (int side = 1; side <= 2; side++) {
                uint32_t j = tri[(corner + side) % 3];
                double length = edge_length(mesh, (uint32_t)v, j);
                double w = length > 0 ? half / length : 0;
                size_t e = s->row_start[v];
                while (e < used && s->column[e] != j)
                    e++;
                if (e == used) {
                    s->column[used] = j;
                    s->weight[used++] = 0;
                }
                s->weight[e] += w;
                s->diagonal[v] += w;
            }
        }
    }
    s->row_start[n] = (uint32_t)used;
    return FACET_OK;
}

/* y = A x over interior vertices: (A x)_i = d_i x_i - sum over interior
 * neighbours w_ij x_j; boundary rows are the identity. */
static void apply(const struct mean_value_system *s,
                  const unsigned char *fixed, const double *x, double *y)
{
    for (size_t i = 0; i < s->n; i++) {
        if (fixed[i]) {
            y[i] = x[i];
            continue;
        }
        double sum = s->diagonal[i] * x[i];
        for (uint32_t e = s->row_start[i]; e < s->row_start[i + 1]; e++)
            if (!fixed[s->column[e]])
                sum -= s->weight[e] * x[s->column[e]];
        y[i] = sum;
    }
}

static double dot_n(const double *a, const double *b, size_t n)
{
    double sum = 0;
    for (size_t i = 0; i < n; i++)
        sum += a[i] * b[i];
    return sum;
}

/* Solves A x = b by BiCGSTAB with a Jacobi preconditioner (the mean-value
 * matrix is not symmetric). x holds the initial guess. Returns 0 when it
 * converged to a relative residual under 1e-10. */
static int solve(const struct mean_value_system *s, const unsigned char *fixed,
                 const double *b, double *x)
{
    size_t n = s->n;
    double *work = malloc(sizeof(double) * 8 * (n ? n : 1));
    if (work == NULL)
        return -1;
    double *r = work, *r0 = r + n, *p = r0 + n, *v = p + n, *sv = v + n;
    double *ph = sv + n, *shat = ph + n, *t = shat + n;
    apply(s, fixed, x, r);
    for (size_t i = 0; i < n; i++)
        r[i] = b[i] - r[i];
    memcpy(r0, r, sizeof(double) * n);
    memset(p, 0, sizeof(double) * n);
    memset(v, 0, sizeof(double) * n);
    double rho = 1, alpha = 1, omega = 1;
    double norm_b = sqrt(dot_n(b, b, n));
    if (norm_b == 0)
        norm_b = 1;
    int status = -1;
    for (int iteration = 0; iteration < 20000; iteration++) {
        if (sqrt(dot_n(r, r, n)) <= 1e-10 * norm_b) {
            status = 0;
            break;
        }
        double rho_next = dot_n(r0, r, n);
        if (rho_next == 0)
            break;
        double beta = (rho_next / rho) * (alpha / omega);
        rho = rho_next;
        for (size_t i = 0; i < n; i++)
            p[i] = r[i] + beta * (p[i] - omega * v[i]);
        for (size_t i = 0; i < n; i++)
            ph[i] = fixed[i] || s->diagonal[i] == 0 ? p[i]
                                                    : p[i] / s->diagonal[i];
        apply(s, fixed, ph, v);
        double r0v = dot_n(r0, v, n);
        if (r0v == 0)
            break;
        alpha = rho / r0v;
        for (size_t i = 0; i < n; i++)
            sv[i] = r[i] - alpha * v[i];
        for (size_t i = 0; i < n; i++)
            shat[i] = fixed[i] || s->diagonal[i] == 0 ? sv[i]
                                                      : sv[i] / s->diagonal[i];
        apply(s, fixed, shat, t);
        double tt = dot_n(t, t, n);
        omega = tt > 0 ? dot_n(t, sv, n) / tt : 0;
        for (size_t i = 0; i < n; i++) {
            x[i] += alpha * ph[i] + omega * shat[i];
            r[i] = sv[i] - omega * t[i];
        }
        if (omega == 0) {
            status = sqrt(dot_n(r, r, n)) <= 1e-10 * norm_b ? 0 : -1;
            break;
        }
    }
    free(work);
    return status;
}

/* The mean-value parameterization of a disk-like mesh, per vertex. */
static int harmonic(const struct mesh *mesh, double **vertex_uv_out)
{
    size_t n = mesh->nvertices;
    double *vertex_uv = calloc(2 * (n ? n : 1), sizeof(double));
    double *angle_sum = calloc(n ? n : 1, sizeof(double));
    double *b = malloc(sizeof(double) * (n ? n : 1));
    double *x = malloc(sizeof(double) * (n ? n : 1));
    unsigned char *fixed = calloc(n ? n : 1, 1);
    struct mean_value_system system;
    int rc = FACET_EWORK;
    memset(&system, 0, sizeof system);
    if (!vertex_uv || !angle_sum || !b || !x || !fixed)
        goto done;
    for (size_t t = 0; t < mesh->ntriangles; t++)
        for (int k = 0; k < 3; k++)
            angle_sum[mesh->triangle[3 * t + k]] += corner_angle(mesh, t, k);
    place_boundary(mesh, angle_sum, vertex_uv);
    for (uint32_t k = mesh->loop_start[0]; k < mesh->loop_start[1]; k++)
        fixed[mesh->loop_vertices[k]] = 1;
    if (build_system(mesh, &system) != FACET_OK)
        goto done;

    for (int axis = 0; axis < 2; axis++) {
        for (size_t i = 0; i < n; i++) {
            if (fixed[i]) {
                b[i] = x[i] = vertex_uv[2 * i + axis];
                continue;
            }
            double sum = 0;
            for (uint32_t e = system.row_start[i]; e < system.row_start[i + 1];
                 e++)
                if (fixed[system.column[e]])
                    sum += system.weight[e] *
                           vertex_uv[2 * system.column[e] + axis];
            b[i] = sum;
            x[i] = 0;
        }
        if (solve(&system, fixed, b, x) != 0) {
            rc = FACET_EINPUT;
            goto done;
        }
        for (size_t i = 0; i < n; i++)
            vertex_uv[2 * i + axis] = x[i];
    }
    *vertex_uv_out = vertex_uv;
    vertex_uv = NULL;
    rc = FACET_OK;
done:
    system_free(&system);
    free(vertex_uv);
    free(angle_sum);
    free(b);
    free(x);
    free(fixed);
    return rc;
}

int param_choose(const struct mesh *mesh, const char *name,
                 struct parameterization *out, struct facet_error *err)
{
    memset(out, 0, sizeof *out);
    int rc;
    if (mesh->has_uv) {
        out->method = PARAM_VT;
        out->uv = malloc(sizeof(double) * 6 * (mesh->ntriangles ? mesh->ntriangles : 1));
        if (out->uv == NULL)
            return facet_error_set(err, FACET_EWORK, "out of memory (UV)");
        memcpy(out->uv, mesh->uv, sizeof(double) * 6 * mesh->ntriangles);
        rc = uv_check(out->uv, mesh->ntriangles, &out->report, err);
        if (rc != FACET_OK)
            return rc;
        if (folds(&out->report))
            return facet_error_set(err, FACET_EINPUT,
                "%s: the texture coordinates fold (%zu flipped, %zu "
                "overlapping UV triangles); re-export the surface with its "
                "surface parameters as UV, or select one surface with "
                "--object", name, out->report.flipped,
                out->report.overlapping);
        return FACET_OK;
    }

    double *vertex_uv = plane_projection(mesh);
    if (vertex_uv == NULL)
        return facet_error_set(err, FACET_EWORK, "out of memory (UV)");
    out->method = PARAM_PLANE;
    out->uv = corners_from_vertices(mesh, vertex_uv);
    free(vertex_uv);
    if (out->uv == NULL)
        return facet_error_set(err, FACET_EWORK, "out of memory (UV)");
    rc = uv_check(out->uv, mesh->ntriangles, &out->report, err);
    if (rc != FACET_OK)
        return rc;
    if (!folds(&out->report) && out->report.degenerate == 0)
        return FACET_OK;

    free(out->uv);
    out->uv = NULL;
    if (mesh->ncomponents != 1 || mesh->nloops != 1 ||
        mesh->nonmanifold_edges > 0)
        return facet_error_set(err, FACET_EINPUT,
            "%s has no texture coordinates, folds when projected onto a "
            "plane, and is not a disk (%zu pieces, %zu boundary loops): "
            "export it with texture coordinates (its surface parameters as "
            "vt, e.g. Rhino's mesh export with texture coordinates)",
            name, mesh->ncomponents, mesh->nloops);
    out->method = PARAM_HARMONIC;
    rc = harmonic(mesh, &vertex_uv);
    if (rc == FACET_EINPUT)
        return facet_error_set(err, FACET_EINPUT,
            "%s: the harmonic parameterization did not converge; export "
            "the surface with texture coordinates", name);
    if (rc != FACET_OK)
        return facet_error_set(err, FACET_EWORK, "out of memory (UV)");
    out->uv = corners_from_vertices(mesh, vertex_uv);
    free(vertex_uv);
    if (out->uv == NULL)
        return facet_error_set(err, FACET_EWORK, "out of memory (UV)");
    rc = uv_check(out->uv, mesh->ntriangles, &out->report, err);
    if (rc != FACET_OK)
        return rc;
    if (folds(&out->report))
        return facet_error_set(err, FACET_EINPUT,
            "%s: the harmonic parameterization folds (%zu flipped, %zu "
            "overlapping triangles); export the surface with texture "
            "coordinates", name, out->report.flipped,
            out->report.overlapping);
    return FACET_OK;
}
