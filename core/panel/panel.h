/*
 * panel.h: dividing a surface into the panels of a UV grid, exactly.
 *
 * The grid nu x nv covers the UV bounding box; panel (i, j) is the part of
 * the surface inside UV cell (i, j), i along u, j along v. Every mesh
 * triangle is clipped to the cells it touches (in UV) and the clipped pieces
 * are mapped to 3D with the triangle's affine map, so a panel's area, its
 * best-fit plane and its deviation from that plane are exact for the mesh.
 * Cells the surface does not reach are no panels; boundary cells are
 * trimmed panels with their real area, and the panel areas add up to the
 * mesh area.
 *
 * This module measures geometry and samples curvature; naming a panel's
 * class and type and pricing it is classify.h's job.
 */
#ifndef FACET_PANEL_H
#define FACET_PANEL_H

#include <stddef.h>
#include <stdint.h>

#include "core/surface/curvature.h"
#include "core/base/error.h"
#include "core/base/stop.h"
#include "core/surface/mesh.h"
#include "core/surface/uv_index.h"

/* The paper's classes (Table 1), by the signs of K and H. */
enum panel_class {
    CLASS_CONVEX_FEATURE_CURVE,   /* K < 0, H < 0 */
    CLASS_SADDLE,                 /* K < 0, H = 0 */
    CLASS_CONCAVE_FEATURE_CURVE,  /* K < 0, H > 0 */
    CLASS_RULED_CONVEX,           /* K = 0, H < 0 */
    CLASS_FLAT,                   /* K = 0, H = 0 */
    CLASS_RULED_CONCAVE,          /* K = 0, H > 0 */
    CLASS_CONVEX_ROUND,           /* K > 0, H < 0 */
    CLASS_CONCAVE_ROUND,          /* K > 0, H > 0 */
    CLASS_COUNT
};

/* What the panel is made as: flat, single-curved or double-curved. */
enum panel_type { TYPE_FP, TYPE_SP, TYPE_DP, TYPE_COUNT };

/* How a panel's k1 and k2 come from its samples. */
enum panel_curvature_mode {
    PANEL_EXTREMES,  /* the paper's: k1 = max, k2 = min over the samples */
    PANEL_MEAN       /* eigenvalues of the area-weighted mean shape operator */
};

/* "extremes", "mean": how the store, the JSON report and the per-panel
 * setting name the modes. */
const char *panel_mode_name(enum panel_curvature_mode mode);
/* The mode named text into *out; FACET_EINPUT naming the field what (the
 * caller's name for it) and the choices. */
int panel_mode_parse(const char *text, const char *what,
                     enum panel_curvature_mode *out,
                     struct facet_error *err);

/* The cylinder or cone an SP panel is built on (sp_fit.h), as a
 * fabricator reads it: the foot of the panel's centroid on the axis and
 * the axis's direction (developable.h's developable_describe), a
 * cylinder's radius, a cone's apex and half-angle, and the least radius
 * the panel is bent to. It is the whole fit: the exports develop and
 * describe the panel from it (developable_of_sp_fit) without fitting it
 * again. */
enum panel_sp_shape { PANEL_SP_NONE, PANEL_SP_CYLINDER, PANEL_SP_CONE };

struct panel_sp_fit {
    enum panel_sp_shape shape;  /* NONE (0, as a zeroed panel): not built
                                   on a fit, every number below NaN or
                                   not read */
    double axis_point[3];       /* m */
    double direction[3];        /* unit; from the apex towards the panel
                                   for a cone */
    double radius;              /* a cylinder's (m); NaN for a cone */
    double apex[3];             /* a cone's (m); NaN for a cylinder */
    double half_angle;          /* a cone's (rad); NaN for a cylinder */
    double bending_radius;      /* the least radius of curvature over the
                                   panel's samples (m): a cylinder's
                                   radius, a cone's at its narrow end
                                   (sp_fit.h's built_panel); NaN when not
                                   known (a panel stored before schema
                                   v13) */
};

struct panel {
    int i, j;                 /* the UV cell: i along u, j along v */
    double area;              /* m^2 */
    double uv_area;           /* UV area covered (UV units^2) */
    int trimmed;              /* the surface covers only part of the cell */
    double centroid[3];       /* area centroid (m) */
    double normal[3];         /* unit normal of the area-weighted
                                 least-squares plane (the paper's Eq. 1),
                                 on the side of the surface normal */
    double deviation;         /* largest distance of the panel's surface
                                 from that plane (m) */
    double p_dist;            /* the paper's P_dist (Eq. 2) as the area
                                 integral of the squared distance to the
                                 plane (m^4) */
    double diameter;          /* the longer 3D diagonal; for a trimmed
                                 panel, the diameter of its outline (m) */
    int ncorners;             /* cell corners that lie on the surface */
    double corner[4][3];      /* corners (i,j), (i+1,j), (i+1,j+1), (i,j+1)
                                 on the surface (m); NaN where off it */
    double corner_planarity;  /* distance between the quad's two diagonals
                                 (m): 0 for a planar quad; NaN unless all
                                 four corners lie on the surface */
    /* Curvature, set by panels_build from the vertex curvature: */
    double k1, k2;            /* 1/m, k1 >= k2 */
    double k1_error[2];       /* how far below and above k1 it may lie
                                 (1/m, >= 0): k1 is known to within
                                 [k1 - k1_error[0], k1 + k1_error[1]]
                                 (panel_internal.h's
                                 panels_curvature_range: the curvature
                                 estimate's errors, curvature.h, of the
                                 vertices it is sampled from); the zero
                                 test (classify.h) reads it. 0 (exact)
                                 where not measured */
    double k2_error[2];       /* the same for k2 */
    /* Set by classify_panels: */
    double K, H;              /* Gaussian (1/m^2) and mean (1/m) curvature */
    double curvature_tol;     /* the zero tolerance eps used (1/m) */
    enum panel_class class;
    enum panel_type type;
    double price;             /* USD/m^2 of its type */
    double cost;              /* area x price (USD) */
    /* Set by option_evaluate (option.h): */
    int mould;                /* its mould family (mould.h), 0-based, or
                                 -1 for none (FP) */
    /* As built (option.h, sp_fit.h, joint.h), set by option_evaluate: */
    enum panel_type built;    /* the type it is built as: type, except DP
                                 for an SP misfit */
    int misfit;               /* 1: classed SP, but no cylinder or cone
                                 fits it within t */
    double sp_deviation;      /* largest distance of its surface from the
                                 fitted cylinder or cone (m); for a misfit
                                 the nearer of the two; NaN unless classed
                                 SP */
    double best_cylinder;     /* a misfit's best cylinder and cone (m, */
    double best_cone;         /* NaN when none fits): why it is a misfit */
    double worst_gap;         /* largest gap at its joints (m) */
    int worst_gap_side;       /* the cell side that joint is on: 0 v = j
                                 (corners 0-1), 1 u = i + 1 (1-2), 2 v =
                                 j + 1 (2-3), 3 u = i (3-0); -1 for none */
    double worst_kink;        /* largest kink at its joints (rad) */
    double width;             /* the least width of its outline in its
                                 plane (m, panel_width.h), set by
                                 option_evaluate; NaN when not measured
                                 (option.h's OPTION_MEASURE_WIDTHS) and
                                 on panels read from the store */
    struct panel_sp_fit sp_fit;  /* the surface it is built on, when SP */
};

struct panelization {
    int nu, nv;               /* grid size */
    double umin, vmin;        /* the UV box the grid covers */
    double umax, vmax;
    size_t npanels;
    struct panel *panels;     /* the cells the surface reaches, in order of
                                 j then i */
    int *cell_panel;          /* nu x nv: index into panels of cell (i, j)
                                 at [j * nu + i], or -1 when no panel */
    double threshold;         /* the flatness threshold t its panels were
                                 typed and built at (m), set by
                                 classify_types: what a misfit missed */
    /* A planarized option's panels (core/planar/planar_option.h), per
     * panel: the largest distance of its corners from the design surface
     * and the largest distance they moved (m), NaN for a panel whose
     * corners were not moved (not a full quad). NULL, both, for a
     * classified option's panels, whose corners lie on the surface. */
    double *corner_distance;
    double *corner_moved;
};

/* The largest grid side panels_build accepts. */
#define PANEL_MAX_GRID 2000

/* Divides mesh into the panels of an nu x nv grid over the UV box of index
 * by clipping every triangle to the cells it touches: the straightforward
 * computation, kept as the oracle panels_build_fast is tested against.
 *   mesh       the surface (m)
 *   index      UV lookup built over the per-corner UV the panels follow
 *              (#T x 3 x 2, mesh->uv or a computed parameterization)
 *   curvature  vertex curvature of mesh, sampled at the mesh vertices inside
 *              each cell and where the cell's border cuts mesh edges
 *   mode       how samples become the panel's k1, k2
 * Fills *out (caller-owned, released with panelization_free, also after a
 * failure). Returns FACET_OK, FACET_EINPUT for a grid side outside
 * 1..PANEL_MAX_GRID, FACET_EWORK when out of memory. */
int panels_build(const struct mesh *mesh, const struct uv_index *index,
                 const struct curvature *curvature,
                 enum panel_curvature_mode mode, int nu, int nv,
                 struct panelization *out, struct facet_error *err);

/* Panel n's corner distance and corner move (m; panelization's arrays),
 * NaN when its option was not planarized or its corners were not moved:
 * not measured, never 0. */
double panel_corner_distance(const struct panelization *panels, size_t n);
double panel_corner_moved(const struct panelization *panels, size_t n);

void panelization_free(struct panelization *panelization);

/* What does not depend on the grid, computed once per surface by
 * panel_prep_build so that every panelization of it (panels_build_fast)
 * adds a triangle that lies inside one cell in O(1) and clips only the
 * triangles that cross a cell line. */
struct panel_prep_point;     /* a point's position and curvature */
struct panel_prep_triangle;  /* a triangle's area, UV area, centroid,
                                central second moment and area-weighted
                                normal */
struct triangle_curvature_range;  /* a triangle's vertices' curvature
                                     extremes (panel_internal.h) */
struct panel_prep {
    const struct mesh *mesh;            /* borrowed, as are index and */
    const struct uv_index *index;       /* curvature: they must outlive */
    const struct curvature *curvature;  /* the prep and not change */
    size_t npoints;                     /* distinct (vertex, UV) corners */
    double *point_uv;                   /* npoints x 2 */
    struct panel_prep_point *point;     /* npoints */
    uint32_t *corner;                   /* #T x 3: the points of each
                                           triangle's corners */
    struct panel_prep_triangle *triangle;  /* #T */
    struct triangle_curvature_range *curvature_range;  /* #T, NULL when
                                                          curvature holds
                                                          no errors */
};

/* Computes the per-surface sums of mesh, whose UV lookup is index and
 * vertex curvature curvature (the arguments panels_build takes), into *out
 * (caller-owned, released with panel_prep_free, also after a failure).
 * Returns FACET_OK, FACET_EINPUT for 2^31 corners or more, FACET_EWORK when
 * out of memory. */
int panel_prep_build(const struct mesh *mesh, const struct uv_index *index,
                     const struct curvature *curvature,
                     struct panel_prep *out, struct facet_error *err);

/* For a prep whose sums were read rather than built (a prepared
 * building's cache, checked: core/project/project_cache.h) over its mesh
 * and curvature: makes what panel_prep_build derives from the curvature
 * alone and the cache does not keep, the triangles' curvature extremes.
 * Returns FACET_OK, FACET_EWORK when out of memory. */
int panel_prep_add_ranges(struct panel_prep *prep, struct facet_error *err);

void panel_prep_free(struct panel_prep *prep);

/* panels_build for prep's mesh, index and curvature: the same panels, to
 * rounding (tested against it), in a fraction of the time. Same returns. */
int panels_build_fast(const struct panel_prep *prep,
                      enum panel_curvature_mode mode, int nu, int nv,
                      struct panelization *out, struct facet_error *err);

/* panels_build_fast, asking stop (core/base/stop.h; NULL: never) between
 * its passes over the cells: FACET_ESTOP when it fires (*out then holds
 * what was built, released with panelization_free as after any failure). */
int panels_build_fast_stoppable(const struct panel_prep *prep,
                                enum panel_curvature_mode mode, int nu,
                                int nv, const struct facet_stop *stop,
                                struct panelization *out,
                                struct facet_error *err);

/* The pieces themselves, for code that needs a panel's exact geometry
 * (panel_geometry.h) rather than its measures: panels_build walks them
 * without storing them, and so does panels_walk_pieces, one at a time. */

/* A vertex of a piece: its UV and its barycentric coordinates in the
 * triangle it was cut from (which carry 3D position and curvature). */
struct panel_piece_vertex {
    double u, v;
    double b[3];
};

/* A piece has at most 3 + 4 vertices: each of the four cell sides adds
 * one. */
#define PANEL_PIECE_MAX 8

/* Receives one piece: the convex polygon piece[0..count) (count >= 3, in
 * the winding of the triangle) cut from mesh triangle triangle by grid
 * cell cell = j * nu + i. A piece may have zero area when a triangle only
 * touches a cell line. */
typedef void (*panel_piece_visitor)(void *context, size_t cell,
                                    uint32_t triangle,
                                    const struct panel_piece_vertex *piece,
                                    int count);

/* Calls visit for every piece of the nu x nv grid over the UV box of
 * index, exactly the pieces panels_build measures for the same mesh, index
 * and grid (cells in the order of triangles, then j, then i). Visits
 * nothing for a grid side below 1 or a UV box without extent. */
void panels_walk_pieces(const struct mesh *mesh,
                        const struct uv_index *index, int nu, int nv,
                        panel_piece_visitor visit, void *context);

/* The 3D position (m) of piece vertex p of mesh triangle t, by the
 * triangle's affine map. */
void panel_piece_point(const struct mesh *mesh, uint32_t t,
                       const struct panel_piece_vertex *p, double out[3]);

#endif
