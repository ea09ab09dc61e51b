/*
 * store_fixture.h: the least a run needs to be stored, for tests that
 * store options of a run no study made, a file taken back to an older
 * schema, and a database file removed with its side files.
 *
 * Test support, not part of Facet: tests/ links it, the binary does not.
 */
#ifndef FACET_STORE_FIXTURE_H
#define FACET_STORE_FIXTURE_H

#include "store/store.h"

/* Fills *run with a run of x.obj (m, exhaustive, extremes, objective
 * cost, a 1 x 1 grid, one job) that store_run_create accepts. */
void store_fixture_run(struct run_info *run);

/* SQL that takes a current file back to schema version 15: the tables
 * of gaps and kinks as core holds them (schema v16, issue 27) dropped,
 * and the seams' columns in m and rad again, as v15 held them (set
 * user_version after it). */
#define STORE_FIXTURE_UNDO_V16 \
    "DROP TABLE option_surface_held;" \
    "DROP TABLE option_held;" \
    "UPDATE options SET seam_max_gap = seam_max_gap / 1000," \
    " seam_max_kink = seam_max_kink * 3.141592653589793 / 180," \
    " seam_max_crease = seam_max_crease * 3.141592653589793 / 180;"

/* SQL that takes a current file back to schema version 14: the columns
 * version 15 added (a building's seams, issue 31), dropped (set
 * user_version after it). */
#define STORE_FIXTURE_UNDO_V15 STORE_FIXTURE_UNDO_V16 \
    "ALTER TABLE runs DROP COLUMN weld_mm;" \
    "ALTER TABLE options DROP COLUMN seams;" \
    "ALTER TABLE options DROP COLUMN seam_length;" \
    "ALTER TABLE options DROP COLUMN seam_max_gap;" \
    "ALTER TABLE options DROP COLUMN seam_max_kink;" \
    "ALTER TABLE options DROP COLUMN seam_max_crease;" \
    "ALTER TABLE options DROP COLUMN seam_gaps_over;" \
    "ALTER TABLE options DROP COLUMN seam_kinks_over;"

/* SQL that takes a current file back to schema version 13: the columns
 * version 14 added (planarized options, issue 33), dropped (set
 * user_version after it). */
#define STORE_FIXTURE_UNDO_V14 STORE_FIXTURE_UNDO_V15 \
    "ALTER TABLE runs DROP COLUMN planarize_closeness_mm;" \
    "ALTER TABLE options DROP COLUMN planarized;" \
    "ALTER TABLE options DROP COLUMN closeness_reached;" \
    "ALTER TABLE options DROP COLUMN closeness_mean;" \
    "ALTER TABLE options DROP COLUMN planarity_reached;" \
    "ALTER TABLE options DROP COLUMN planar_over;" \
    "ALTER TABLE panels DROP COLUMN corner_distance;" \
    "ALTER TABLE panels DROP COLUMN corner_moved;"

/* SQL that takes a current file back to schema version 12: the column
 * version 13 added (an SP panel's bending radius), dropped (set
 * user_version after it). */
#define STORE_FIXTURE_UNDO_V13 STORE_FIXTURE_UNDO_V14 \
    "ALTER TABLE panels DROP COLUMN sp_bending_radius;"

/* SQL that takes a current file back to schema version 11: the columns
 * version 12 added (slivers: the run's width limit, the smallest panel's
 * area and width and the slivers of each option and surface), dropped
 * (set user_version after it). */
#define STORE_FIXTURE_UNDO_V12 STORE_FIXTURE_UNDO_V13 \
    "ALTER TABLE runs DROP COLUMN min_panel_width;" \
    "ALTER TABLE options DROP COLUMN min_panel_area;" \
    "ALTER TABLE options DROP COLUMN min_panel_width;" \
    "ALTER TABLE options DROP COLUMN slivers;" \
    "ALTER TABLE option_surfaces DROP COLUMN min_panel_area;" \
    "ALTER TABLE option_surfaces DROP COLUMN min_panel_width;" \
    "ALTER TABLE option_surfaces DROP COLUMN slivers;"

/* SQL that takes a current file back to schema version 10: the columns
 * version 11 added (each SP panel's fitted surface), dropped (set
 * user_version after it). */
#define STORE_FIXTURE_UNDO_V11 STORE_FIXTURE_UNDO_V12 \
    "ALTER TABLE panels DROP COLUMN sp_surface;" \
    "ALTER TABLE panels DROP COLUMN sp_axis_x;" \
    "ALTER TABLE panels DROP COLUMN sp_axis_y;" \
    "ALTER TABLE panels DROP COLUMN sp_axis_z;" \
    "ALTER TABLE panels DROP COLUMN sp_direction_x;" \
    "ALTER TABLE panels DROP COLUMN sp_direction_y;" \
    "ALTER TABLE panels DROP COLUMN sp_direction_z;" \
    "ALTER TABLE panels DROP COLUMN sp_radius;" \
    "ALTER TABLE panels DROP COLUMN sp_apex_x;" \
    "ALTER TABLE panels DROP COLUMN sp_apex_y;" \
    "ALTER TABLE panels DROP COLUMN sp_apex_z;" \
    "ALTER TABLE panels DROP COLUMN sp_half_angle;"

/* SQL that takes a current file back to schema version 9: the column
 * version 10 added (the smallest SP bending radius), dropped (set
 * user_version after it). */
#define STORE_FIXTURE_UNDO_V10 STORE_FIXTURE_UNDO_V11 \
    "ALTER TABLE options DROP COLUMN sp_min_radius;" \
    "ALTER TABLE option_surfaces DROP COLUMN sp_min_radius;"

/* SQL that takes a current file back to schema version 8: the column
 * version 9 added (what a run measured), dropped (set user_version after
 * it). */
#define STORE_FIXTURE_UNDO_V9 STORE_FIXTURE_UNDO_V10 \
    "ALTER TABLE runs DROP COLUMN measured;"

/* SQL that takes a current file back to schema version 7: the tables and
 * columns version 8 added (projects), dropped (set user_version after
 * it). */
#define STORE_FIXTURE_UNDO_V8 STORE_FIXTURE_UNDO_V9 \
    "DROP TABLE option_surfaces; DROP TABLE surfaces;" \
    "ALTER TABLE runs DROP COLUMN module_w_min;" \
    "ALTER TABLE runs DROP COLUMN module_w_max;" \
    "ALTER TABLE runs DROP COLUMN module_w_step;" \
    "ALTER TABLE runs DROP COLUMN module_h_min;" \
    "ALTER TABLE runs DROP COLUMN module_h_max;" \
    "ALTER TABLE runs DROP COLUMN module_h_step;" \
    "ALTER TABLE options DROP COLUMN module_w;" \
    "ALTER TABLE options DROP COLUMN module_h;" \
    "ALTER TABLE options DROP COLUMN modules;"

/* SQL that takes a current file back to schema version 6: the columns
 * and indexes versions 7 (panels as built, gaps and kinks) and 8 added,
 * dropped (set user_version after it). */
#define STORE_FIXTURE_UNDO_V7 STORE_FIXTURE_UNDO_V8 \
    "DROP INDEX options_by_max_gap; DROP INDEX options_by_max_kink;" \
    "DROP INDEX options_by_sp_misfits;" \
    "ALTER TABLE runs DROP COLUMN sp_fit;" \
    "ALTER TABLE runs DROP COLUMN max_gap_mm;" \
    "ALTER TABLE runs DROP COLUMN max_kink_deg;" \
    "ALTER TABLE options DROP COLUMN max_gap;" \
    "ALTER TABLE options DROP COLUMN mean_gap;" \
    "ALTER TABLE options DROP COLUMN max_kink;" \
    "ALTER TABLE options DROP COLUMN mean_kink;" \
    "ALTER TABLE options DROP COLUMN gaps_over;" \
    "ALTER TABLE options DROP COLUMN kinks_over;" \
    "ALTER TABLE options DROP COLUMN sp_misfits;" \
    "ALTER TABLE options DROP COLUMN sp_fitted;" \
    "ALTER TABLE panels DROP COLUMN built_type;" \
    "ALTER TABLE panels DROP COLUMN sp_deviation;" \
    "ALTER TABLE panels DROP COLUMN worst_gap;" \
    "ALTER TABLE panels DROP COLUMN worst_gap_side;" \
    "ALTER TABLE panels DROP COLUMN worst_kink;" \
    "ALTER TABLE panels DROP COLUMN best_cylinder;" \
    "ALTER TABLE panels DROP COLUMN best_cone;" \
    "ALTER TABLE panels DROP COLUMN misfit_reason;"

/* SQL that takes a version 6 file back to schema version 5: the columns
 * the shards' step (version 6) added, dropped (after
 * STORE_FIXTURE_UNDO_V7 for a current file). */
#define STORE_FIXTURE_UNDO_V6_SHARDS \
    "ALTER TABLE runs DROP COLUMN shard_index;" \
    "ALTER TABLE runs DROP COLUMN shard_count;" \
    "ALTER TABLE runs DROP COLUMN shards_merged;"

/* SQL that takes a current file back to schema version 4, as a Facet
 * before the cost model left it: the columns and indexes versions 5 and
 * later added, dropped (set user_version after it). */
#define STORE_FIXTURE_UNDO_V5 STORE_FIXTURE_UNDO_V7 STORE_FIXTURE_UNDO_V6_SHARDS \
    "DROP INDEX options_by_moulds; DROP INDEX options_by_joint_length;" \
    "ALTER TABLE runs DROP COLUMN price_panel;" \
    "ALTER TABLE runs DROP COLUMN price_joint;" \
    "ALTER TABLE runs DROP COLUMN price_sp_mould;" \
    "ALTER TABLE runs DROP COLUMN price_dp_mould;" \
    "ALTER TABLE runs DROP COLUMN mould_tol_mm;" \
    "ALTER TABLE runs DROP COLUMN mould_mirror;" \
    "ALTER TABLE options DROP COLUMN joint_length;" \
    "ALTER TABLE options DROP COLUMN moulds;" \
    "ALTER TABLE options DROP COLUMN sp_moulds;" \
    "ALTER TABLE options DROP COLUMN dp_moulds;" \
    "ALTER TABLE options DROP COLUMN largest_family;" \
    "ALTER TABLE options DROP COLUMN single_moulds;" \
    "ALTER TABLE options DROP COLUMN area_cost;" \
    "ALTER TABLE options DROP COLUMN panel_cost;" \
    "ALTER TABLE options DROP COLUMN joint_cost;" \
    "ALTER TABLE options DROP COLUMN mould_cost;" \
    "ALTER TABLE panels DROP COLUMN mould_family;"

/* Removes the database at path and its -wal and -shm files, where
 * there are any. */
void store_fixture_remove(const char *path);

/* The first column of the first row query gives on the database at path,
 * read by SQLite itself over a connection of its own, into *value.
 * Returns 0, or -1 when SQLite cannot open, prepare or step it. */
int store_fixture_sql_int(const char *path, const char *query,
                          int64_t *value);

#endif
