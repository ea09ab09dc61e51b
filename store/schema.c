/*
 * schema.c: Facet's schema, declared once: its migrations (versions 1 ..
 * STORE_SCHEMA_VERSION, each the SQL that brings a file from the version
 * before) and store_schema_migrate that runs them, and the SQL helpers
 * every file of the store shares (store_fail, store_exec, ...). Opening a
 * file is store_open.c's. docs/store.md ("The result store") documents
 * every table, column and unit defined here. The build runs these
 * migrations once more (store/tool/schema_script.c) to write down each
 * version's final CREATE statements (store_schemas), which
 * store_schema_check holds a file to.
 */
#include "store_internal.h"

#include <math.h>
#include <stdio.h>
#include <string.h>
#include <time.h>

#include "core/base/text.h"

/* Version 1: the tables. Every length m, area m^2, money USD, threshold
 * mm, time UTC ISO 8601, elapsed seconds. */
static const char schema_v1[] =
    "CREATE TABLE runs ("
    " id INTEGER PRIMARY KEY,"
    " name TEXT NOT NULL DEFAULT '',"
    " status TEXT NOT NULL CHECK (status IN"
    "  ('running','done','interrupted','failed')),"
    " started TEXT NOT NULL,"
    " finished TEXT,"
    " elapsed REAL NOT NULL DEFAULT 0,"
    " surface_path TEXT NOT NULL,"
    " surface_sha256 TEXT NOT NULL,"
    " surface_area REAL, triangles INTEGER, uv_method TEXT,"
    " units TEXT NOT NULL,"
    " object TEXT,"
    " group_name TEXT,"
    " method TEXT NOT NULL,"
    " seed INTEGER NOT NULL,"
    " u_min INTEGER NOT NULL, u_max INTEGER NOT NULL,"
    " v_min INTEGER NOT NULL, v_max INTEGER NOT NULL,"
    " threshold_min_mm REAL NOT NULL, threshold_max_mm REAL NOT NULL,"
    " threshold_step_mm REAL NOT NULL,"
    " price_fp REAL NOT NULL, price_sp REAL NOT NULL,"
    " price_dp REAL NOT NULL,"
    " sp_as_fp INTEGER NOT NULL,"
    " max_panel_area_limit REAL NOT NULL,"
    " curvature_tol REAL,"
    " per_panel TEXT NOT NULL,"
    " flip_normals INTEGER NOT NULL,"
    " objectives TEXT NOT NULL,"
    " population INTEGER, generations INTEGER, evaluations INTEGER,"
    " jobs INTEGER NOT NULL,"
    " version TEXT NOT NULL,"
    " options INTEGER NOT NULL DEFAULT 0,"
    " writer_pid INTEGER, writer_host TEXT,"
    " hypervolume REAL,"
    " knee INTEGER,"
    " pareto_options INTEGER,"
    " best_cost REAL"
    ");"
    "CREATE TABLE options ("
    " run INTEGER NOT NULL REFERENCES runs(id) ON DELETE CASCADE,"
    " number INTEGER NOT NULL,"
    " generation INTEGER NOT NULL,"
    " nu INTEGER NOT NULL, nv INTEGER NOT NULL,"
    " threshold_mm REAL NOT NULL,"
    " panels INTEGER NOT NULL,"
    " fp_count INTEGER NOT NULL, sp_count INTEGER NOT NULL,"
    " dp_count INTEGER NOT NULL,"
    " fp_area REAL NOT NULL, sp_area REAL NOT NULL, dp_area REAL NOT NULL,"
    " area REAL NOT NULL,"
    " fp_cost REAL NOT NULL, sp_cost REAL NOT NULL, dp_cost REAL NOT NULL,"
    " cost REAL NOT NULL,"
    " planarity REAL NOT NULL,"
    " max_deviation REAL NOT NULL,"
    " max_panel_area REAL NOT NULL,"
    " p_dist REAL NOT NULL,"
    " feasible INTEGER NOT NULL,"
    " convex_feature_curve_count INTEGER NOT NULL,"
    " convex_feature_curve_area REAL NOT NULL,"
    " saddle_count INTEGER NOT NULL, saddle_area REAL NOT NULL,"
    " concave_feature_curve_count INTEGER NOT NULL,"
    " concave_feature_curve_area REAL NOT NULL,"
    " ruled_convex_count INTEGER NOT NULL, ruled_convex_area REAL NOT NULL,"
    " flat_count INTEGER NOT NULL, flat_area REAL NOT NULL,"
    " ruled_concave_count INTEGER NOT NULL,"
    " ruled_concave_area REAL NOT NULL,"
    " convex_round_count INTEGER NOT NULL, convex_round_area REAL NOT NULL,"
    " concave_round_count INTEGER NOT NULL,"
    " concave_round_area REAL NOT NULL,"
    " rank INTEGER,"
    " crowding REAL,"
    " knee INTEGER NOT NULL DEFAULT 0,"
    " PRIMARY KEY (run, number)"
    ") WITHOUT ROWID;"
    "CREATE TABLE panel_sets ("
    " run INTEGER NOT NULL, option INTEGER NOT NULL,"
    " nu INTEGER NOT NULL, nv INTEGER NOT NULL,"
    " umin REAL NOT NULL, vmin REAL NOT NULL,"
    " umax REAL NOT NULL, vmax REAL NOT NULL,"
    " stored TEXT NOT NULL,"
    " PRIMARY KEY (run, option),"
    " FOREIGN KEY (run, option) REFERENCES options(run, number)"
    "  ON DELETE CASCADE"
    ");"
    "CREATE TABLE panels ("
    " run INTEGER NOT NULL, option INTEGER NOT NULL,"
    " i INTEGER NOT NULL, j INTEGER NOT NULL,"
    " class TEXT NOT NULL, type TEXT NOT NULL,"
    " area REAL NOT NULL, uv_area REAL NOT NULL,"
    " deviation REAL NOT NULL,"
    " k1 REAL NOT NULL, k2 REAL NOT NULL, K REAL NOT NULL, H REAL NOT NULL,"
    " eps REAL NOT NULL, p_dist REAL NOT NULL, diameter REAL NOT NULL,"
    " trimmed INTEGER NOT NULL, corner_planarity REAL,"
    " price REAL NOT NULL, cost REAL NOT NULL,"
    " centroid_x REAL, centroid_y REAL, centroid_z REAL,"
    " normal_x REAL, normal_y REAL, normal_z REAL,"
    " c0_x REAL, c0_y REAL, c0_z REAL, c1_x REAL, c1_y REAL, c1_z REAL,"
    " c2_x REAL, c2_y REAL, c2_z REAL, c3_x REAL, c3_y REAL, c3_z REAL,"
    " PRIMARY KEY (run, option, j, i),"
    " FOREIGN KEY (run, option) REFERENCES panel_sets(run, option)"
    "  ON DELETE CASCADE"
    ") WITHOUT ROWID;";

/* Version 2: what readers query by (the TUI sorts a million options by a
 * metric without reading them all) and the two views of docs/store.md. */
static const char schema_v2[] =
    "CREATE INDEX options_by_rank ON options(run, rank, number);"
    "CREATE INDEX options_by_cost ON options(run, cost);"
    "CREATE INDEX options_by_planarity ON options(run, planarity);"
    "CREATE INDEX options_by_dp_area ON options(run, dp_area);"
    "CREATE VIEW pareto AS"
    " SELECT r.name AS run_name, r.surface_path, o.*"
    " FROM options o JOIN runs r ON r.id = o.run WHERE o.rank = 1;"
    "CREATE VIEW run_summary AS"
    " SELECT r.id, r.name, r.status, r.method, r.surface_path, r.units,"
    "  r.u_min || ':' || r.u_max AS u, r.v_min || ':' || r.v_max AS v,"
    "  r.threshold_min_mm, r.threshold_max_mm, r.seed, r.options,"
    "  r.pareto_options, r.best_cost, r.hypervolume, r.knee,"
    "  r.started, r.finished, r.elapsed,"
    "  CASE WHEN r.elapsed > 0 THEN r.options / r.elapsed END"
    "   AS options_per_second"
    " FROM runs r;";

/* Version 3: every column the options table shows can be sorted by an
 * index, so a million options re-sort without a scan. */
static const char schema_v3[] =
    "CREATE INDEX options_by_fp_area ON options(run, fp_area);"
    "CREATE INDEX options_by_sp_area ON options(run, sp_area);"
    "CREATE INDEX options_by_nu ON options(run, nu);"
    "CREATE INDEX options_by_nv ON options(run, nv);"
    "CREATE INDEX options_by_threshold ON options(run, threshold_mm);";

/* Version 4: more of a run's settings, for --resume to take them again.
 * One ALTER TABLE per column: add a column as a line of its own here. */
static const char schema_v4[] =
    "ALTER TABLE runs ADD COLUMN uv TEXT;"  /* --uv, NULL: automatic */
    /* What the designer was warned of when the run began, one per line. */
    "ALTER TABLE runs ADD COLUMN warnings TEXT NOT NULL DEFAULT '';"
    /* Which options' panels the run stores when it ends. */
    "ALTER TABLE runs ADD COLUMN store_panels TEXT NOT NULL DEFAULT 'front'"
    " CHECK (store_panels IN ('front', 'knee', 'none'));";

/* Version 5: the cost model beyond area (panels, joints, moulds) and the
 * mould families. A run's unit prices are 0 before it: the paper's model,
 * which is what those runs priced. An option's new columns are NULL for
 * options stored before it (never computed); a panel's mould family is
 * NULL for an FP panel (no mould) and for panels stored before it. */
static const char schema_v5[] =
    "ALTER TABLE runs ADD COLUMN price_panel REAL NOT NULL DEFAULT 0;"
    "ALTER TABLE runs ADD COLUMN price_joint REAL NOT NULL DEFAULT 0;"
    "ALTER TABLE runs ADD COLUMN price_sp_mould REAL NOT NULL DEFAULT 0;"
    "ALTER TABLE runs ADD COLUMN price_dp_mould REAL NOT NULL DEFAULT 0;"
    "ALTER TABLE runs ADD COLUMN mould_tol_mm REAL;"  /* NULL: threshold */
    "ALTER TABLE runs ADD COLUMN mould_mirror INTEGER NOT NULL DEFAULT 0;"
    "ALTER TABLE options ADD COLUMN joint_length REAL;"
    "ALTER TABLE options ADD COLUMN moulds INTEGER;"
    "ALTER TABLE options ADD COLUMN sp_moulds INTEGER;"
    "ALTER TABLE options ADD COLUMN dp_moulds INTEGER;"
    "ALTER TABLE options ADD COLUMN largest_family INTEGER;"
    "ALTER TABLE options ADD COLUMN single_moulds INTEGER;"
    "ALTER TABLE options ADD COLUMN area_cost REAL;"
    "ALTER TABLE options ADD COLUMN panel_cost REAL;"
    "ALTER TABLE options ADD COLUMN joint_cost REAL;"
    "ALTER TABLE options ADD COLUMN mould_cost REAL;"
    "ALTER TABLE panels ADD COLUMN mould_family INTEGER;"
    "CREATE INDEX options_by_moulds ON options(run, moulds);"
    "CREATE INDEX options_by_joint_length ON options(run, joint_length);";

/* Version 6 (shards): a run that is one shard of a search spread over
 * machines (facet optimize's shard I/N: shard_index I of shard_count N),
 * and a run merged from such shards (shard_index NULL, shard_count N,
 * shards_merged how many of the N it holds: fewer is an incomplete run).
 * NULL for every other run. */
static const char schema_v6_shards[] =
    "ALTER TABLE runs ADD COLUMN shard_index INTEGER;"
    "ALTER TABLE runs ADD COLUMN shard_count INTEGER;"
    "ALTER TABLE runs ADD COLUMN shards_merged INTEGER;";

/* Version 7: panels as built, and the gap and kink at their joints
 * (issue 16). A run's SP typing: sp_fit 1 builds a panel classed SP that
 * no cylinder or cone fits within t as DP; runs before it typed SP by
 * class alone, which 0 says. The gap and kink limits are NULL for none
 * (every run before). An option's gaps are mm and kinks degrees, NULL for
 * options stored before (never measured); a panel's worst gap (mm), the
 * side of its cell that joint is on (0 v = j, 1 u = i + 1, 2 v = j + 1,
 * 3 u = i), its worst kink (degrees), its SP fit's deviation (m, as
 * deviation) and its best cylinder's and cone's, likewise; misfit_reason
 * is NULL but for a misfit. */
static const char schema_v7[] =
    "ALTER TABLE runs ADD COLUMN sp_fit INTEGER NOT NULL DEFAULT 0;"
    "ALTER TABLE runs ADD COLUMN max_gap_mm REAL;"
    "ALTER TABLE runs ADD COLUMN max_kink_deg REAL;"
    "ALTER TABLE options ADD COLUMN max_gap REAL;"
    "ALTER TABLE options ADD COLUMN mean_gap REAL;"
    "ALTER TABLE options ADD COLUMN max_kink REAL;"
    "ALTER TABLE options ADD COLUMN mean_kink REAL;"
    "ALTER TABLE options ADD COLUMN gaps_over INTEGER;"
    "ALTER TABLE options ADD COLUMN kinks_over INTEGER;"
    "ALTER TABLE options ADD COLUMN sp_misfits INTEGER;"
    "ALTER TABLE options ADD COLUMN sp_fitted INTEGER;"
    "ALTER TABLE panels ADD COLUMN built_type TEXT;"
    "ALTER TABLE panels ADD COLUMN sp_deviation REAL;"
    "ALTER TABLE panels ADD COLUMN worst_gap REAL;"
    "ALTER TABLE panels ADD COLUMN worst_gap_side INTEGER;"
    "ALTER TABLE panels ADD COLUMN worst_kink REAL;"
    "ALTER TABLE panels ADD COLUMN best_cylinder REAL;"
    "ALTER TABLE panels ADD COLUMN best_cone REAL;"
    "ALTER TABLE panels ADD COLUMN misfit_reason TEXT;"
    "CREATE INDEX options_by_max_gap ON options(run, max_gap);"
    "CREATE INDEX options_by_max_kink ON options(run, max_kink);"
    "CREATE INDEX options_by_sp_misfits ON options(run, sp_misfits);";

/* Version 8: projects, a building of many surfaces (issue 17,
 * core/project/project.h). Every column is NULL, and the new tables hold
 * no row, for a run of a single surface (every run before).
 *
 * runs: the module range a project run searched (module.h), in m: widths
 *   module_w_min, module_w_min + module_w_step, ... up to module_w_max,
 *   heights likewise. A project run's u_min..u_max and v_min..v_max are
 *   then the width and height indices it walks (1..widths, 1..heights),
 *   its surface_path and surface_sha256 its first file's (the surfaces
 *   table has every file's).
 * options: module_w, module_h (m), the module the option was met as (the
 *   first, by index in the range, of those giving every surface the same
 *   grid), and modules, how many modules of the range give that grid
 *   vector; nu and nv are the module's width and height indices (1-based,
 *   in the run's range). Every other column holds the building's totals
 *   (project_option.h).
 * surfaces: one row per surface of a project run, in the project's
 *   order: surface (0-based), name (its o or g name, or the file's), file
 *   (absolute path), file_sha256 (hex SHA-256 of the file's bytes),
 *   triangles, area (m^2), u_length and v_length (m, the mean length of
 *   its iso-lines: project_lengths.h), uv_method (the UV it took),
 *   grid_nu and grid_nv (the grid given to this surface whatever the
 *   module, NULL for none: every option then has it).
 * option_surfaces: one row per surface per option of a project run, that
 *   surface's part of the option (project_option.h): nu, nv its grid;
 *   panels, fp_count, sp_count, dp_count; fp_area, sp_area, dp_area, area
 *   (m^2); cost and its parts area_cost, panel_cost, joint_cost,
 *   mould_cost (USD); planarity (m), max_deviation (m), max_panel_area
 *   (m^2), p_dist (m^4), joint_length (m); moulds (the mould families it
 *   starts: the first panel of the family in the building's order is its
 *   own; they add up to the option's moulds), sp_moulds, dp_moulds;
 *   moulds_used (the families its panels belong to, started here or on an
 *   earlier surface); max_gap, mean_gap (mm), max_kink, mean_kink
 *   (degrees) at its joints, joints (how many were measured: its means
 *   are over those), gaps_over, kinks_over, sp_misfits; feasible (1 when
 *   the surface on its own is). */
static const char schema_v8[] =
    "ALTER TABLE runs ADD COLUMN module_w_min REAL;"
    "ALTER TABLE runs ADD COLUMN module_w_max REAL;"
    "ALTER TABLE runs ADD COLUMN module_w_step REAL;"
    "ALTER TABLE runs ADD COLUMN module_h_min REAL;"
    "ALTER TABLE runs ADD COLUMN module_h_max REAL;"
    "ALTER TABLE runs ADD COLUMN module_h_step REAL;"
    "ALTER TABLE options ADD COLUMN module_w REAL;"
    "ALTER TABLE options ADD COLUMN module_h REAL;"
    "ALTER TABLE options ADD COLUMN modules INTEGER;"
    "CREATE TABLE surfaces ("
    " run INTEGER NOT NULL REFERENCES runs(id) ON DELETE CASCADE,"
    " surface INTEGER NOT NULL,"
    " name TEXT NOT NULL,"
    " file TEXT NOT NULL,"
    " file_sha256 TEXT NOT NULL,"
    " triangles INTEGER NOT NULL,"
    " area REAL NOT NULL,"
    " u_length REAL NOT NULL, v_length REAL NOT NULL,"
    " uv_method TEXT NOT NULL,"
    " grid_nu INTEGER, grid_nv INTEGER,"
    " PRIMARY KEY (run, surface)"
    ") WITHOUT ROWID;"
    "CREATE TABLE option_surfaces ("
    " run INTEGER NOT NULL, option INTEGER NOT NULL,"
    " surface INTEGER NOT NULL,"
    " nu INTEGER NOT NULL, nv INTEGER NOT NULL,"
    " panels INTEGER NOT NULL,"
    " fp_count INTEGER NOT NULL, sp_count INTEGER NOT NULL,"
    " dp_count INTEGER NOT NULL,"
    " fp_area REAL NOT NULL, sp_area REAL NOT NULL, dp_area REAL NOT NULL,"
    " area REAL NOT NULL,"
    " cost REAL NOT NULL, area_cost REAL NOT NULL, panel_cost REAL NOT NULL,"
    " joint_cost REAL NOT NULL, mould_cost REAL NOT NULL,"
    " planarity REAL NOT NULL, max_deviation REAL NOT NULL,"
    " max_panel_area REAL NOT NULL, p_dist REAL NOT NULL,"
    " joint_length REAL NOT NULL,"
    " moulds INTEGER NOT NULL, sp_moulds INTEGER NOT NULL,"
    " dp_moulds INTEGER NOT NULL, moulds_used INTEGER NOT NULL,"
    " max_gap REAL, mean_gap REAL, max_kink REAL, mean_kink REAL,"
    " joints INTEGER NOT NULL,"
    " gaps_over INTEGER NOT NULL, kinks_over INTEGER NOT NULL,"
    " sp_misfits INTEGER NOT NULL,"
    " feasible INTEGER NOT NULL,"
    " PRIMARY KEY (run, option, surface),"
    " FOREIGN KEY (run, option) REFERENCES options(run, number)"
    "  ON DELETE CASCADE"
    ") WITHOUT ROWID;";

/* Version 9: a run measures only what it needs (issue 27). runs.measured
 * lists what every option of the run was measured for beyond its classed
 * panels, comma-separated from fits (SP panels built on fitted cylinders
 * and cones: sp_misfits, sp_fitted), joints (max_gap .. kinks_over),
 * moulds (moulds .. single_moulds) and joint_length; '' for none of them.
 * An option's column of a measure its run did not take is NULL: not
 * measured, never 0. The run's Pareto options are measured in full. NULL
 * for every run before: all of them. */
static const char schema_v9[] =
    "ALTER TABLE runs ADD COLUMN measured TEXT;";

/* Version 10: the smallest radius an option's SP panels are bent to (m),
 * measured with the fits, for the option and for each surface of a
 * building's; NULL where not measured, where no panel is built SP, and
 * for every option stored before. */
static const char schema_v10[] =
    "ALTER TABLE options ADD COLUMN sp_min_radius REAL;"
    "ALTER TABLE option_surfaces ADD COLUMN sp_min_radius REAL;";

/* Version 11: the cylinder or cone each SP panel is built on (issue 29,
 * item 7B), as the XLSX schedule shows it: sp_surface 'cylinder' or
 * 'cone', the foot of the panel's centroid on the axis (m) and the axis
 * direction (a unit vector, from the apex towards the panel for a cone),
 * a cylinder's radius (m), a cone's apex (m) and half-angle (degrees, as
 * worst_kink); NULL for a panel not built on a fit and for every panel
 * stored before. */
static const char schema_v11[] =
    "ALTER TABLE panels ADD COLUMN sp_surface TEXT;"
    "ALTER TABLE panels ADD COLUMN sp_axis_x REAL;"
    "ALTER TABLE panels ADD COLUMN sp_axis_y REAL;"
    "ALTER TABLE panels ADD COLUMN sp_axis_z REAL;"
    "ALTER TABLE panels ADD COLUMN sp_direction_x REAL;"
    "ALTER TABLE panels ADD COLUMN sp_direction_y REAL;"
    "ALTER TABLE panels ADD COLUMN sp_direction_z REAL;"
    "ALTER TABLE panels ADD COLUMN sp_radius REAL;"
    "ALTER TABLE panels ADD COLUMN sp_apex_x REAL;"
    "ALTER TABLE panels ADD COLUMN sp_apex_y REAL;"
    "ALTER TABLE panels ADD COLUMN sp_apex_z REAL;"
    "ALTER TABLE panels ADD COLUMN sp_half_angle REAL;";

/* Version 12: slivers (issue 31, item 2). For each option and each
 * surface of a building's: the smallest panel's area (m^2) and width (m,
 * the caliper width of its outline in its plane: docs/method.md), and the
 * panels narrower than the run's width limit, runs.min_panel_width (m;
 * NULL: none). The width and the count are NULL where not measured (a
 * run without a width limit measures them for its Pareto options only),
 * and all three for every option stored before. */
static const char schema_v12[] =
    "ALTER TABLE runs ADD COLUMN min_panel_width REAL;"
    "ALTER TABLE options ADD COLUMN min_panel_area REAL;"
    "ALTER TABLE options ADD COLUMN min_panel_width REAL;"
    "ALTER TABLE options ADD COLUMN slivers INTEGER;"
    "ALTER TABLE option_surfaces ADD COLUMN min_panel_area REAL;"
    "ALTER TABLE option_surfaces ADD COLUMN min_panel_width REAL;"
    "ALTER TABLE option_surfaces ADD COLUMN slivers INTEGER;";

/* Version 13: the least radius each SP panel is bent to on its fit (m,
 * sp_fit.h's bending_radius), so that an export develops and schedules
 * the panel from what was stored instead of fitting it again; NULL for a
 * panel not built on a fit and for every panel stored before (the export
 * then fits those again). */
static const char schema_v13[] =
    "ALTER TABLE panels ADD COLUMN sp_bending_radius REAL;";

/* Version 14: planarized options (issue 33, core/planar/planar_option.h).
 * An option's kind (planarized 0: classified, the surface cut and never
 * moved; 1: its corners moved off the surface until its quads are planar)
 * and what its planarization reached: the largest and mean distance of
 * its corners from the design surface (m) and the largest planarity of
 * its quads over their longer diagonals, and the quads that missed (over
 * the planarity tolerance or with a corner beyond the budget: a limit, as
 * gaps_over), NULL for a classified option.
 * Per panel of a planarized option, the largest distance of its corners
 * from the design surface and how far they moved (m), NULL for a
 * classified option's panels. Per run, the closeness budget its
 * planarized options were held to (mm), NULL when it made none. */
static const char schema_v14[] =
    "ALTER TABLE runs ADD COLUMN planarize_closeness_mm REAL;"
    "ALTER TABLE options ADD COLUMN planarized INTEGER NOT NULL DEFAULT 0;"
    "ALTER TABLE options ADD COLUMN closeness_reached REAL;"
    "ALTER TABLE options ADD COLUMN closeness_mean REAL;"
    "ALTER TABLE options ADD COLUMN planarity_reached REAL;"
    "ALTER TABLE options ADD COLUMN planar_over INTEGER;"
    "ALTER TABLE panels ADD COLUMN corner_distance REAL;"
    "ALTER TABLE panels ADD COLUMN corner_moved REAL;";

/* Version 15: a building's seams (issue 31 item 1,
 * core/project/project_seams.h). Per run, the welding tolerance its
 * seams were found at (mm), NULL for a single surface and every run
 * before. Per option, its seams measured with its joints: how many and
 * their length (m), the largest gap (m), kink added to the design's
 * crease (rad) and crease (rad) at them, and the seam joints over the
 * gap and kink limits; NULL for a single surface, where joints were not
 * measured, and for every option stored before. */
static const char schema_v15[] =
    "ALTER TABLE runs ADD COLUMN weld_mm REAL;"
    "ALTER TABLE options ADD COLUMN seams INTEGER;"
    "ALTER TABLE options ADD COLUMN seam_length REAL;"
    "ALTER TABLE options ADD COLUMN seam_max_gap REAL;"
    "ALTER TABLE options ADD COLUMN seam_max_kink REAL;"
    "ALTER TABLE options ADD COLUMN seam_max_crease REAL;"
    "ALTER TABLE options ADD COLUMN seam_gaps_over INTEGER;"
    "ALTER TABLE options ADD COLUMN seam_kinks_over INTEGER;";

/* Version 16: one unit per family of columns, and Facet's own values kept
 * to the bit (issue 27). Core holds gaps in m and kinks in rad; users
 * query an option's max_gap, mean_gap in mm and max_kink, mean_kink in
 * degrees (schema v7), and v15 stored a building's seam_max_gap in m and
 * seam_max_kink, seam_max_crease in rad beside them. The options' and
 * option_surfaces' columns are now all in mm and degrees, the seams'
 * rescaled in place (m x 1000, rad x 180 / pi), and the same values as
 * core holds them, in m and rad, are kept beside in option_held and
 * option_surface_held (a row per option, per option's surface), which
 * Facet writes with the option and reads back: a double cannot go to mm
 * or degrees and back to the bit. An option's v15 mm and degrees give
 * its held m and rad (mm / 1000, degrees x pi / 180); a seam's its v15
 * m and rad as they were. In this migration's one transaction.
 * docs/decisions.md says why. */
static const char schema_v16[] =
    "CREATE TABLE option_held ("
    " run INTEGER NOT NULL, option INTEGER NOT NULL,"
    " max_gap REAL, mean_gap REAL, max_kink REAL, mean_kink REAL,"
    " seam_max_gap REAL, seam_max_kink REAL, seam_max_crease REAL,"
    " PRIMARY KEY (run, option),"
    " FOREIGN KEY (run, option) REFERENCES options(run, number)"
    "  ON DELETE CASCADE"
    ") WITHOUT ROWID;"
    "INSERT INTO option_held SELECT run, number, max_gap / 1000,"
    " mean_gap / 1000, max_kink * 3.141592653589793 / 180,"
    " mean_kink * 3.141592653589793 / 180,"
    " seam_max_gap, seam_max_kink, seam_max_crease FROM options;"
    "UPDATE options SET seam_max_gap = seam_max_gap * 1000,"
    " seam_max_kink = seam_max_kink * 180 / 3.141592653589793,"
    " seam_max_crease = seam_max_crease * 180 / 3.141592653589793;"
    "CREATE TABLE option_surface_held ("
    " run INTEGER NOT NULL, option INTEGER NOT NULL,"
    " surface INTEGER NOT NULL,"
    " max_gap REAL, mean_gap REAL, max_kink REAL, mean_kink REAL,"
    " PRIMARY KEY (run, option, surface),"
    " FOREIGN KEY (run, option, surface)"
    "  REFERENCES option_surfaces(run, option, surface) ON DELETE CASCADE"
    ") WITHOUT ROWID;"
    "INSERT INTO option_surface_held SELECT run, option, surface,"
    " max_gap / 1000, mean_gap / 1000,"
    " max_kink * 3.141592653589793 / 180,"
    " mean_kink * 3.141592653589793 / 180 FROM option_surfaces;";

/* A held value from its column where its held row is missing
 * (store_held_sql), by the arithmetic v16's migration filled option_held
 * with. */
const char store_held_from_mm_sql[] = "/ 1000";
const char store_held_from_deg_sql[] = "* 3.141592653589793 / 180";

static const char *const migrations[STORE_SCHEMA_VERSION] = {
    schema_v1,
    schema_v2,
    schema_v3,
    schema_v4,
    schema_v5,
    schema_v6_shards,
    schema_v7,
    schema_v8,
    schema_v9,
    schema_v10,
    schema_v11,
    schema_v12,
    schema_v13,
    schema_v14,
    schema_v15,
    schema_v16,
};

int store_fail(struct store *store, const char *doing,
               struct facet_error *err)
{
    int code = sqlite3_errcode(store->db);
    int input = code == SQLITE_CORRUPT || code == SQLITE_NOTADB ||
                code == SQLITE_BUSY || code == SQLITE_READONLY ||
                code == SQLITE_CANTOPEN || code == SQLITE_LOCKED;
    const char *hint = "";
    if (code == SQLITE_CORRUPT || code == SQLITE_NOTADB)
        hint = "; the file is damaged or not a Facet database";
    else if (code == SQLITE_BUSY || code == SQLITE_LOCKED)
        hint = "; another process holds it, try again";
    /* SQLite's message quotes the file's own text (a damaged schema's
     * SQL, a trigger's RAISE): made one line (error.h), its control
     * characters not passed on. */
    char said[400];
    text_for_terminal(sqlite3_errmsg(store->db), said, sizeof said);
    return facet_error_set(err, input ? FACET_EINPUT : FACET_EWORK,
                           "%s: %s (%s)%s", store->path, said, doing, hint);
}

int store_exec(struct store *store, const char *sql, const char *doing,
               struct facet_error *err)
{
    if (sqlite3_exec(store->db, sql, NULL, NULL, NULL) != SQLITE_OK)
        return store_fail(store, doing, err);
    return FACET_OK;
}

int store_prepare(struct store *store, const char *sql, sqlite3_stmt **out,
                  const char *doing, struct facet_error *err)
{
    if (sqlite3_prepare_v2(store->db, sql, -1, out, NULL) != SQLITE_OK) {
        *out = NULL;
        return store_fail(store, doing, err);
    }
    return FACET_OK;
}

void store_bind_or_null(sqlite3_stmt *stmt, int col, double value)
{
    if (isfinite(value))
        sqlite3_bind_double(stmt, col, value);
    else
        sqlite3_bind_null(stmt, col);
}

double store_column_or_nan(sqlite3_stmt *stmt, int col)
{
    return sqlite3_column_type(stmt, col) == SQLITE_NULL
               ? NAN : sqlite3_column_double(stmt, col);
}

void store_now(char out[32])
{
    time_t now = time(NULL);
    struct tm utc;
    gmtime_r(&now, &utc);
    strftime(out, 32, "%Y-%m-%dT%H:%M:%SZ", &utc);
}

int store_pragma_int(struct store *store, const char *sql, int *value,
                     struct facet_error *err)
{
    sqlite3_stmt *stmt;
    int rc = store_prepare(store, sql, &stmt, "reading the header", err);
    if (rc != FACET_OK)
        return rc;
    int step = sqlite3_step(stmt);
    if (step == SQLITE_ROW)
        *value = sqlite3_column_int(stmt, 0);
    sqlite3_finalize(stmt);
    if (step != SQLITE_ROW)
        return store_fail(store, "reading the header", err);
    return FACET_OK;
}

int store_schema_migrate(struct store *store, int from, int to,
                         struct facet_error *err)
{
    char sql[64], stamp[64];
    snprintf(stamp, sizeof stamp, "PRAGMA application_id = %d",
             STORE_APPLICATION_ID);
    for (int version = from + 1; version <= to; version++) {
        int rc = store_exec(store, "BEGIN IMMEDIATE", "migrating", err);
        if (rc != FACET_OK)
            return rc;
        /* Another process may have migrated the file while this one
         * waited for the write lock: look again, inside the transaction. */
        int now = 0;
        rc = store_pragma_int(store, "PRAGMA user_version", &now, err);
        if (rc == FACET_OK && now >= version) {
            rc = store_exec(store, "COMMIT", "migrating", err);
            if (rc != FACET_OK)
                return rc;
            continue;
        }
        snprintf(sql, sizeof sql, "PRAGMA user_version = %d", version);
        if (rc == FACET_OK && version == 1)
            rc = store_exec(store, stamp,
                            "creating the schema", err);
        if (rc == FACET_OK)
            rc = store_exec(store, migrations[version - 1],
                            "creating the schema", err);
        if (rc == FACET_OK)
            rc = store_exec(store, sql, "creating the schema", err);
        if (rc == FACET_OK)
            rc = store_exec(store, "COMMIT", "migrating", err);
        if (rc != FACET_OK) {
            sqlite3_exec(store->db, "ROLLBACK", NULL, NULL, NULL);
            return rc;
        }
    }
    return FACET_OK;
}
