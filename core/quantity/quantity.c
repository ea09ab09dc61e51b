/*
 * quantity.c: the quantities of an option, and reading and writing a
 * quantity's value. See quantity.h, which says how to add one.
 */
#include "core/quantity/quantity.h"

#include <assert.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "core/base/numformat.h"
#include "core/base/units.h"
#include "core/evaluate/option.h"

/* Where a field of struct option_row is. */
#define ROW(member) offsetof(struct option_row, member)
#define TOTAL(member) offsetof(struct option_row, totals.member)

/* name, label, heading, unit, stored_unit, scale, decimals, list_decimals,
 * thousands, yes_no, example, field, offset, writer, combine, measure,
 * objective, per_surface, stored. (Sized by its rows: a
 * count in the header that differs is a compile error.) */
const struct quantity option_quantities[] = {
    {"number", "No.", "No.", "", "", 1, 0, 0, 0, 0, "10",
     FIELD_INT64, ROW(number), WRITTEN_WITH_OPTION,
     COMBINE_NONE, 0, 0, 0, STORED_AS_HELD},
    {"generation", "generation", "gen", "", "", 1, 0, 0, 0, 0, "5",
     FIELD_INT, ROW(generation), WRITTEN_WITH_OPTION,
     COMBINE_NONE, 0, 0, 0, STORED_AS_HELD},
    {"nu", "U", "U", "", "", 1, 0, 0, 0, 0, "30",
     FIELD_INT, ROW(nu), WRITTEN_WITH_OPTION,
     COMBINE_NONE, 0, 0, 0, STORED_AS_HELD},
    {"nv", "V", "V", "", "", 1, 0, 0, 0, 0, "30",
     FIELD_INT, ROW(nv), WRITTEN_WITH_OPTION,
     COMBINE_NONE, 0, 0, 0, STORED_AS_HELD},
    {"threshold_mm", "threshold", "t", "mm", "mm", 1, 2, 2, 0, 0, "5",
     FIELD_DOUBLE, ROW(threshold_mm), WRITTEN_WITH_OPTION,
     COMBINE_NONE, 0, 0, 0, STORED_AS_HELD},
    {"panels", "panels", "panels", "", "", 1, 0, 0, 1, 0, "500",
     FIELD_SIZE, TOTAL(panels), WRITTEN_WITH_OPTION,
     COMBINE_SUM, 0, 1, 1, STORED_AS_HELD},
    {"fp_count", "FP panels", "FP n", "", "", 1, 0, 0, 1, 0, "100",
     FIELD_SIZE, TOTAL(count[TYPE_FP]), WRITTEN_WITH_OPTION,
     COMBINE_SUM, 0, 1, 1, STORED_AS_HELD},
    {"sp_count", "SP panels", "SP n", "", "", 1, 0, 0, 1, 0, "100",
     FIELD_SIZE, TOTAL(count[TYPE_SP]), WRITTEN_WITH_OPTION,
     COMBINE_SUM, 0, 1, 1, STORED_AS_HELD},
    {"dp_count", "DP panels", "DP n", "", "", 1, 0, 0, 1, 0, "100",
     FIELD_SIZE, TOTAL(count[TYPE_DP]), WRITTEN_WITH_OPTION,
     COMBINE_SUM, 0, 1, 1, STORED_AS_HELD},
    {"fp_area", "FP area", "FP area", "m^2", "m^2", 1, 2, 1, 1, 0, "100",
     FIELD_DOUBLE, TOTAL(area_of[TYPE_FP]), WRITTEN_WITH_OPTION,
     COMBINE_EXACT_SUM, 0, 1, 1, STORED_AS_HELD},
    {"sp_area", "SP area", "SP area", "m^2", "m^2", 1, 2, 1, 1, 0, "100",
     FIELD_DOUBLE, TOTAL(area_of[TYPE_SP]), WRITTEN_WITH_OPTION,
     COMBINE_EXACT_SUM, 0, 1, 1, STORED_AS_HELD},
    {"dp_area", "DP area", "DP area", "m^2", "m^2", 1, 2, 1, 1, 0, "900",
     FIELD_DOUBLE, TOTAL(area_of[TYPE_DP]), WRITTEN_WITH_OPTION,
     COMBINE_EXACT_SUM, 0, 1, 1, STORED_AS_HELD},
    {"area", "area", "area", "m^2", "m^2", 1, 2, 1, 1, 0, "1200",
     FIELD_DOUBLE, TOTAL(area), WRITTEN_WITH_OPTION,
     COMBINE_EXACT_SUM, 0, 0, 1, STORED_AS_HELD},
    {"fp_cost", "FP cost", "FP cost", "USD", "USD", 1, 0, 0, 1, 0, "5e5",
     FIELD_DOUBLE, TOTAL(cost_of[TYPE_FP]), WRITTEN_WITH_OPTION,
     COMBINE_RECOMPUTED, 0, 0, 0, STORED_AS_HELD},
    {"sp_cost", "SP cost", "SP cost", "USD", "USD", 1, 0, 0, 1, 0, "5e5",
     FIELD_DOUBLE, TOTAL(cost_of[TYPE_SP]), WRITTEN_WITH_OPTION,
     COMBINE_RECOMPUTED, 0, 0, 0, STORED_AS_HELD},
    {"dp_cost", "DP cost", "DP cost", "USD", "USD", 1, 0, 0, 1, 0, "5e5",
     FIELD_DOUBLE, TOTAL(cost_of[TYPE_DP]), WRITTEN_WITH_OPTION,
     COMBINE_RECOMPUTED, 0, 0, 0, STORED_AS_HELD},
    {"cost", "cost", "cost", "USD", "USD", 1, 0, 0, 1, 0, "1e6",
     FIELD_DOUBLE, TOTAL(cost), WRITTEN_WITH_OPTION,
     COMBINE_RECOMPUTED, 0, 1, 1, STORED_AS_HELD},
    {"planarity", "planarity", "planarity", "m", "m", 1, 4, 3, 0, 0, "0.01",
     FIELD_DOUBLE, TOTAL(planarity), WRITTEN_WITH_OPTION,
     COMBINE_EXACT_SUM, 0, 1, 1, STORED_AS_HELD},
    {"max_deviation", "max deviation", "max dev", "mm", "m", 1000, 2, 2, 0, 0,
     "0.01", FIELD_DOUBLE, TOTAL(max_deviation), WRITTEN_WITH_OPTION,
     COMBINE_MAX, 0, 1, 1, STORED_AS_HELD},
    {"max_panel_area", "max panel area", "max pan",
     "m^2", "m^2", 1, 2, 2, 0, 0,
     "4", FIELD_DOUBLE, TOTAL(max_panel_area), WRITTEN_WITH_OPTION,
     COMBINE_MAX, 0, 1, 1, STORED_AS_HELD},
    {"p_dist", "P_dist", "P_dist", "m^4", "m^4", 1, 6, 4, 0, 0, "0.5",
     FIELD_DOUBLE, TOTAL(p_dist), WRITTEN_WITH_OPTION,
     COMBINE_EXACT_SUM, 0, 1, 1, STORED_AS_HELD},
    {"feasible", "feasible", "ok", "", "", 1, 0, 0, 0, 1, NULL,
     FIELD_INT, TOTAL(feasible), WRITTEN_WITH_OPTION,
     COMBINE_RECOMPUTED, 0, 0, 1, STORED_AS_HELD},
    /* Per class (core/panel/panel.h), in the order of enum panel_class. */
    {"convex_feature_curve_count", "convex feature curve panels",
     "convex feature curve panels", "", "",
     1, 0, 0, 1, 0, "100", FIELD_SIZE,
     TOTAL(class_count[CLASS_CONVEX_FEATURE_CURVE]), WRITTEN_WITH_OPTION,
     COMBINE_SUM, 0, 0, 0, STORED_AS_HELD},
    {"convex_feature_curve_area", "convex feature curve area",
     "convex feature curve area", "m^2", "m^2",
     1, 2, 1, 1, 0, "100", FIELD_DOUBLE,
     TOTAL(class_area[CLASS_CONVEX_FEATURE_CURVE]), WRITTEN_WITH_OPTION,
     COMBINE_EXACT_SUM, 0, 0, 0, STORED_AS_HELD},
    {"saddle_count", "saddle panels", "saddle panels", "", "",
     1, 0, 0, 1, 0, "100", FIELD_SIZE,
     TOTAL(class_count[CLASS_SADDLE]), WRITTEN_WITH_OPTION,
     COMBINE_SUM, 0, 0, 0, STORED_AS_HELD},
    {"saddle_area", "saddle area", "saddle area", "m^2", "m^2",
     1, 2, 1, 1, 0, "100", FIELD_DOUBLE,
     TOTAL(class_area[CLASS_SADDLE]), WRITTEN_WITH_OPTION,
     COMBINE_EXACT_SUM, 0, 0, 0, STORED_AS_HELD},
    {"concave_feature_curve_count", "concave feature curve panels",
     "concave feature curve panels", "", "",
     1, 0, 0, 1, 0, "100", FIELD_SIZE,
     TOTAL(class_count[CLASS_CONCAVE_FEATURE_CURVE]), WRITTEN_WITH_OPTION,
     COMBINE_SUM, 0, 0, 0, STORED_AS_HELD},
    {"concave_feature_curve_area", "concave feature curve area",
     "concave feature curve area", "m^2", "m^2",
     1, 2, 1, 1, 0, "100", FIELD_DOUBLE,
     TOTAL(class_area[CLASS_CONCAVE_FEATURE_CURVE]), WRITTEN_WITH_OPTION,
     COMBINE_EXACT_SUM, 0, 0, 0, STORED_AS_HELD},
    {"ruled_convex_count", "ruled convex panels", "ruled convex panels",
     "", "",
     1, 0, 0, 1, 0, "100", FIELD_SIZE,
     TOTAL(class_count[CLASS_RULED_CONVEX]), WRITTEN_WITH_OPTION,
     COMBINE_SUM, 0, 0, 0, STORED_AS_HELD},
    {"ruled_convex_area", "ruled convex area", "ruled convex area",
     "m^2", "m^2",
     1, 2, 1, 1, 0, "100", FIELD_DOUBLE,
     TOTAL(class_area[CLASS_RULED_CONVEX]), WRITTEN_WITH_OPTION,
     COMBINE_EXACT_SUM, 0, 0, 0, STORED_AS_HELD},
    {"flat_count", "flat panels", "flat panels", "", "",
     1, 0, 0, 1, 0, "100", FIELD_SIZE,
     TOTAL(class_count[CLASS_FLAT]), WRITTEN_WITH_OPTION,
     COMBINE_SUM, 0, 0, 0, STORED_AS_HELD},
    {"flat_area", "flat area", "flat area", "m^2", "m^2",
     1, 2, 1, 1, 0, "100", FIELD_DOUBLE,
     TOTAL(class_area[CLASS_FLAT]), WRITTEN_WITH_OPTION,
     COMBINE_EXACT_SUM, 0, 0, 0, STORED_AS_HELD},
    {"ruled_concave_count", "ruled concave panels", "ruled concave panels",
     "", "",
     1, 0, 0, 1, 0, "100", FIELD_SIZE,
     TOTAL(class_count[CLASS_RULED_CONCAVE]), WRITTEN_WITH_OPTION,
     COMBINE_SUM, 0, 0, 0, STORED_AS_HELD},
    {"ruled_concave_area", "ruled concave area", "ruled concave area",
     "m^2", "m^2",
     1, 2, 1, 1, 0, "100", FIELD_DOUBLE,
     TOTAL(class_area[CLASS_RULED_CONCAVE]), WRITTEN_WITH_OPTION,
     COMBINE_EXACT_SUM, 0, 0, 0, STORED_AS_HELD},
    {"convex_round_count", "convex round panels", "convex round panels",
     "", "",
     1, 0, 0, 1, 0, "100", FIELD_SIZE,
     TOTAL(class_count[CLASS_CONVEX_ROUND]), WRITTEN_WITH_OPTION,
     COMBINE_SUM, 0, 0, 0, STORED_AS_HELD},
    {"convex_round_area", "convex round area", "convex round area",
     "m^2", "m^2",
     1, 2, 1, 1, 0, "100", FIELD_DOUBLE,
     TOTAL(class_area[CLASS_CONVEX_ROUND]), WRITTEN_WITH_OPTION,
     COMBINE_EXACT_SUM, 0, 0, 0, STORED_AS_HELD},
    {"concave_round_count", "concave round panels", "concave round panels",
     "", "",
     1, 0, 0, 1, 0, "100", FIELD_SIZE,
     TOTAL(class_count[CLASS_CONCAVE_ROUND]), WRITTEN_WITH_OPTION,
     COMBINE_SUM, 0, 0, 0, STORED_AS_HELD},
    {"concave_round_area", "concave round area", "concave round area",
     "m^2", "m^2",
     1, 2, 1, 1, 0, "100", FIELD_DOUBLE,
     TOTAL(class_area[CLASS_CONCAVE_ROUND]), WRITTEN_WITH_OPTION,
     COMBINE_EXACT_SUM, 0, 0, 0, STORED_AS_HELD},
    /* The Pareto analysis, written when the run ends. */
    {"rank", "rank", "rank", "", "", 1, 0, 0, 0, 0, "2",
     FIELD_INT, ROW(rank), WRITTEN_BY_RANKING,
     COMBINE_NONE, 0, 0, 0, STORED_AS_HELD},
    {"crowding", "crowding", "crowd", "", "", 1, 3, 3, 0, 0, "0.5",
     FIELD_DOUBLE, ROW(crowding), WRITTEN_BY_RANKING,
     COMBINE_NONE, 0, 0, 0, STORED_AS_HELD},
    {"knee", "knee", "knee", "", "", 1, 0, 0, 0, 1, NULL,
     FIELD_INT, ROW(knee), WRITTEN_BY_RANKING,
     COMBINE_NONE, 0, 0, 0, STORED_AS_HELD},
    /* The cost model beyond area (schema v5). */
    {"joint_length", "joint length", "joints", "m", "m", 1, 1, 0, 1, 0, "2000",
     FIELD_DOUBLE, TOTAL(joint_length), WRITTEN_WITH_OPTION,
     COMBINE_EXACT_SUM, OPTION_MEASURE_JOINT_LENGTH, 1, 1, STORED_AS_HELD},
    {"moulds", "moulds", "moulds", "", "", 1, 0, 0, 0, 0, "50",
     FIELD_SIZE, TOTAL(moulds), WRITTEN_WITH_OPTION,
     COMBINE_RECOMPUTED, OPTION_MEASURE_MOULDS, 1, 1, STORED_AS_HELD},
    {"sp_moulds", "SP moulds", "SP mld", "", "", 1, 0, 0, 0, 0, "20",
     FIELD_SIZE, TOTAL(moulds_of[TYPE_SP]), WRITTEN_WITH_OPTION,
     COMBINE_RECOMPUTED, OPTION_MEASURE_MOULDS, 1, 1, STORED_AS_HELD},
    {"dp_moulds", "DP moulds", "DP mld", "", "", 1, 0, 0, 0, 0, "20",
     FIELD_SIZE, TOTAL(moulds_of[TYPE_DP]), WRITTEN_WITH_OPTION,
     COMBINE_RECOMPUTED, OPTION_MEASURE_MOULDS, 1, 1, STORED_AS_HELD},
    {"largest_family", "largest mould family", "big fam", "", "", 1, 0, 0, 0, 0,
     "10", FIELD_SIZE, TOTAL(largest_family), WRITTEN_WITH_OPTION,
     COMBINE_RECOMPUTED, OPTION_MEASURE_MOULDS, 0, 0, STORED_AS_HELD},
    {"single_moulds", "moulds of one panel", "single", "", "", 1, 0, 0, 0, 0,
     "10", FIELD_SIZE, TOTAL(singleton_families), WRITTEN_WITH_OPTION,
     COMBINE_RECOMPUTED, OPTION_MEASURE_MOULDS, 0, 0, STORED_AS_HELD},
    {"area_cost", "area cost", "area cost", "USD", "USD", 1, 0, 0, 1, 0, "1e6",
     FIELD_DOUBLE, TOTAL(area_cost), WRITTEN_WITH_OPTION,
     COMBINE_RECOMPUTED, 0, 0, 1, STORED_AS_HELD},
    {"panel_cost", "panel cost", "pan cost", "USD", "USD", 1, 0, 0, 1, 0, "1e5",
     FIELD_DOUBLE, TOTAL(panel_cost), WRITTEN_WITH_OPTION,
     COMBINE_RECOMPUTED, 0, 0, 1, STORED_AS_HELD},
    {"joint_cost", "joint cost", "jnt cost", "USD", "USD", 1, 0, 0, 1, 0, "1e5",
     FIELD_DOUBLE, TOTAL(joint_cost), WRITTEN_WITH_OPTION,
     COMBINE_RECOMPUTED, 0, 0, 1, STORED_AS_HELD},
    {"mould_cost", "mould cost", "mld cost", "USD", "USD", 1, 0, 0, 1, 0, "1e5",
     FIELD_DOUBLE, TOTAL(mould_cost), WRITTEN_WITH_OPTION,
     COMBINE_RECOMPUTED, 0, 0, 1, STORED_AS_HELD},
    /* Panels as built and their joints (schema v7). */
    {"max_gap", "max gap", "max gap", "mm", "mm", 1, 2, 2, 0, 0, "6",
     FIELD_DOUBLE, TOTAL(max_gap), WRITTEN_WITH_OPTION,
     COMBINE_MAX, OPTION_MEASURE_JOINTS, 1, 1, STORED_MM},
    {"mean_gap", "mean gap", "mean gap", "mm", "mm", 1, 3, 2, 0, 0, "1",
     FIELD_DOUBLE, TOTAL(mean_gap), WRITTEN_WITH_OPTION,
     COMBINE_JOINT_MEAN, OPTION_MEASURE_JOINTS, 0, 1, STORED_MM},
    {"max_kink", "max kink", "max kink", "deg", "deg", 1, 2, 2, 0, 0, "1",
     FIELD_DOUBLE, TOTAL(max_kink), WRITTEN_WITH_OPTION,
     COMBINE_MAX, OPTION_MEASURE_JOINTS, 1, 1, STORED_DEG},
    {"mean_kink", "mean kink", "mean kink", "deg", "deg", 1, 3, 2, 0, 0,
     "0.5", FIELD_DOUBLE, TOTAL(mean_kink), WRITTEN_WITH_OPTION,
     COMBINE_JOINT_MEAN, OPTION_MEASURE_JOINTS, 0, 1, STORED_DEG},
    {"gaps_over", "gaps over limit", "gaps>", "", "", 1, 0, 0, 0, 0, "0",
     FIELD_SIZE, TOTAL(gaps_over), WRITTEN_WITH_OPTION,
     COMBINE_SUM, OPTION_MEASURE_JOINTS, 0, 1, STORED_AS_HELD},
    {"kinks_over", "kinks over limit", "kinks>", "", "", 1, 0, 0, 0, 0, "0",
     FIELD_SIZE, TOTAL(kinks_over), WRITTEN_WITH_OPTION,
     COMBINE_SUM, OPTION_MEASURE_JOINTS, 0, 1, STORED_AS_HELD},
    {"sp_misfits", "SP misfits", "misfit", "", "", 1, 0, 0, 0, 0, "10",
     FIELD_SIZE, TOTAL(sp_misfits), WRITTEN_WITH_OPTION,
     COMBINE_SUM, OPTION_MEASURE_FITS, 1, 1, STORED_AS_HELD},
    {"sp_fitted", "SP fitted", "fitted", "", "", 1, 0, 0, 0, 0, "100",
     FIELD_SIZE, TOTAL(sp_fitted), WRITTEN_WITH_OPTION,
     COMBINE_SUM, OPTION_MEASURE_FITS, 0, 0, STORED_AS_HELD},
    /* A project's module (schema v8); NULL for a single surface. */
    {"module_w", "module width", "mod w", "m", "m", 1, 2, 2, 0, 0, "1.5",
     FIELD_DOUBLE, ROW(module_w), WRITTEN_WITH_OPTION,
     COMBINE_NONE, 0, 0, 0, STORED_AS_HELD},
    {"module_h", "module height", "mod h", "m", "m", 1, 2, 2, 0, 0, "1.2",
     FIELD_DOUBLE, ROW(module_h), WRITTEN_WITH_OPTION,
     COMBINE_NONE, 0, 0, 0, STORED_AS_HELD},
    {"modules", "modules of this option", "mods", "", "", 1, 0, 0, 0, 0, "2",
     FIELD_SIZE, ROW(modules), WRITTEN_WITH_OPTION,
     COMBINE_NONE, 0, 0, 0, STORED_AS_HELD},
    {"sp_min_radius", "smallest SP bending radius", "min R", "m", "m", 1, 2,
     1, 0, 0, "5", FIELD_DOUBLE, TOTAL(sp_min_radius), WRITTEN_WITH_OPTION,
     COMBINE_MIN, OPTION_MEASURE_FITS, 1, 1, STORED_AS_HELD},
    /* Slivers (schema v12): the smallest panel by area (classifying
     * measures it) and by width (panel_width.h, shown in mm), and the
     * panels narrower than the run's width limit. */
    {"min_panel_area", "smallest panel area", "min pan", "m^2", "m^2", 1, 3,
     2, 0, 0, "0.5", FIELD_DOUBLE, TOTAL(min_panel_area), WRITTEN_WITH_OPTION,
     COMBINE_MIN, 0, 1, 1, STORED_AS_HELD},
    {"min_panel_width", "smallest panel width", "min w", "mm", "m", 1000, 0,
     0, 0, 0, "0.3", FIELD_DOUBLE, TOTAL(min_panel_width),
     WRITTEN_WITH_OPTION, COMBINE_MIN, OPTION_MEASURE_WIDTHS, 1, 1,
     STORED_AS_HELD},
    {"slivers", "slivers (panels under the width limit)", "slivers", "", "",
     1, 0, 0, 0, 0, "0", FIELD_SIZE, TOTAL(slivers), WRITTEN_WITH_OPTION,
     COMBINE_SUM, OPTION_MEASURE_WIDTHS, 1, 1, STORED_AS_HELD},
    /* The kind of option and what a planarization reached (schema v14,
     * core/planar/planar_option.h): NULL for a classified option. */
    {"planarized", "planarized (corners moved)", "plnz", "", "", 1, 0, 0, 0,
     1, NULL, FIELD_INT, TOTAL(planarized), WRITTEN_WITH_OPTION,
     COMBINE_RECOMPUTED, 0, 0, 0, STORED_AS_HELD},
    {"closeness_reached", "closeness reached (largest corner move off the "
     "surface)", "close", "mm", "m", 1000, 2, 1, 0, 0, "5",
     FIELD_DOUBLE, TOTAL(closeness_reached), WRITTEN_WITH_OPTION,
     COMBINE_RECOMPUTED, 0, 0, 0, STORED_AS_HELD},
    {"closeness_mean", "mean corner distance off the surface", "close avg",
     "mm", "m", 1000, 3, 1, 0, 0, "1", FIELD_DOUBLE, TOTAL(closeness_mean),
     WRITTEN_WITH_OPTION, COMBINE_RECOMPUTED, 0, 0, 0, STORED_AS_HELD},
    {"planarity_reached", "planarity reached (diagonals' distance over the "
     "longer diagonal)", "planar", "%", "", 100, 4, 3, 0, 0, "0.001",
     FIELD_DOUBLE, TOTAL(planarity_reached), WRITTEN_WITH_OPTION,
     COMBINE_RECOMPUTED, 0, 0, 0, STORED_AS_HELD},
    {"planar_over", "quads not planar or beyond the closeness budget",
     "plan>", "", "", 1, 0, 0, 0, 0, "0", FIELD_SIZE, TOTAL(planar_over),
     WRITTEN_WITH_OPTION, COMBINE_RECOMPUTED, 0, 0, 0, STORED_AS_HELD},
    /* A building's seams (schema v15, core/project/project_seams.h),
     * measured with the joints; NULL for a single surface. Its kink is
     * what the panels add to the design's crease, the crease the
     * design's own angle between the surfaces. Gaps in mm and angles in
     * degrees as the option's own (schema v16). */
    {"seams", "seams between surfaces", "seams", "", "", 1, 0, 0, 0, 0, "4",
     FIELD_SIZE, TOTAL(seams), WRITTEN_WITH_OPTION,
     COMBINE_RECOMPUTED, OPTION_MEASURE_JOINTS, 0, 0, STORED_AS_HELD},
    {"seam_length", "seam length", "seam len", "m", "m", 1, 1, 0, 1, 0, "100",
     FIELD_DOUBLE, TOTAL(seam_length), WRITTEN_WITH_OPTION,
     COMBINE_RECOMPUTED, OPTION_MEASURE_JOINTS, 0, 0, STORED_AS_HELD},
    {"seam_max_gap", "max gap at a seam", "seam gap", "mm", "mm", 1, 2, 2,
     0, 0, "6", FIELD_DOUBLE, TOTAL(seam_max_gap), WRITTEN_WITH_OPTION,
     COMBINE_RECOMPUTED, OPTION_MEASURE_JOINTS, 0, 0, STORED_MM},
    {"seam_max_kink", "max kink added at a seam", "seam kink", "deg", "deg",
     1, 2, 2, 0, 0, "1", FIELD_DOUBLE, TOTAL(seam_max_kink),
     WRITTEN_WITH_OPTION, COMBINE_RECOMPUTED, OPTION_MEASURE_JOINTS, 0, 0,
     STORED_DEG},
    {"seam_max_crease", "max crease (the design's angle at a seam)",
     "crease", "deg", "deg", 1, 1, 1, 0, 0, "90", FIELD_DOUBLE,
     TOTAL(seam_max_crease), WRITTEN_WITH_OPTION,
     COMBINE_RECOMPUTED, OPTION_MEASURE_JOINTS, 0, 0, STORED_DEG},
    {"seam_gaps_over", "seam gaps over limit", "seam gaps>", "", "", 1, 0, 0,
     0, 0, "0", FIELD_SIZE, TOTAL(seam_gaps_over), WRITTEN_WITH_OPTION,
     COMBINE_RECOMPUTED, OPTION_MEASURE_JOINTS, 0, 0, STORED_AS_HELD},
    {"seam_kinks_over", "seam kinks over limit", "seam kinks>", "", "", 1, 0,
     0, 0, 0, "0", FIELD_SIZE, TOTAL(seam_kinks_over), WRITTEN_WITH_OPTION,
     COMBINE_RECOMPUTED, OPTION_MEASURE_JOINTS, 0, 0, STORED_AS_HELD},
    /* New columns go here, before run. */
    {"run", "run", "run", "", "", 1, 0, 0, 0, 0, "1",
     FIELD_NONE, 0, WRITTEN_AS_KEY,
     COMBINE_NONE, 0, 0, 0, STORED_AS_HELD},
};

const struct quantity *quantity_named(const char *name)
{
    for (int k = 0; k < OPTION_QUANTITIES; k++)
        if (strcmp(option_quantities[k].name, name) == 0)
            return &option_quantities[k];
    return NULL;
}

const struct quantity *quantity_of_project(
    const char *name)
{
    if (strcmp(name, "nu") == 0)
        return quantity_named("module_w");
    if (strcmp(name, "nv") == 0)
        return quantity_named("module_h");
    return quantity_named(name);
}

/* The number at field, a field of q's type; NaN for a count not known
 * (TOTALS_UNKNOWN) and for a quantity no row field holds. */
static double field_number(const struct quantity *q, const void *field)
{
    switch (q->field) {
    case FIELD_INT:    return *(const int *)field;
    case FIELD_INT64:  return (double)*(const int64_t *)field;
    case FIELD_SIZE:   return totals_count(*(const size_t *)field);
    case FIELD_DOUBLE: return *(const double *)field;
    default:           return NAN;
    }
}

double quantity_stored_of_held(const struct quantity *q, double held)
{
    switch (q->stored) {
    case STORED_MM:  return units_mm(held);
    case STORED_DEG: return units_deg(held);
    default:         return held;
    }
}


double quantity_value(const struct quantity *c,
                                 const struct option_row *option)
{
    if (c->field == FIELD_NONE)
        return NAN;
    double value = field_number(c, (const char *)option + c->offset);
    if (c->field == FIELD_DOUBLE)
        value = quantity_stored_of_held(c, value);
    return c->yes_no ? value != 0 : value;
}

const void *quantity_field(const struct quantity *q,
                           const struct option_totals *totals)
{
    assert(quantity_in_totals(q));
    /* The offset is the row's; the totals sit at their own offset in it. */
    return (const char *)totals +
           (q->offset - offsetof(struct option_row, totals));
}

void *quantity_field_to_set(const struct quantity *q,
                            struct option_totals *totals)
{
    return (void *)quantity_field(q, totals);
}

double quantity_of_totals(const struct quantity *q,
                          const struct option_totals *totals)
{
    double value = field_number(q, quantity_field(q, totals));
    return q->field == FIELD_DOUBLE ? quantity_stored_of_held(q, value)
                                    : value;
}

int quantity_in_totals(const struct quantity *q)
{
    size_t first = offsetof(struct option_row, totals);
    return q->field != FIELD_NONE && q->offset >= first &&
           q->offset < first + sizeof(struct option_totals);
}

int quantity_none(const struct quantity *q, const struct option_totals *totals)
{
    return quantity_in_totals(q) && q->measure != 0 &&
           (q->measure & ~option_totals_measures(totals)) == 0 &&
           isnan(quantity_of_totals(q, totals));
}

void quantity_totals_forget(struct option_totals *totals, unsigned measures)
{
    for (int k = 0; k < OPTION_QUANTITIES; k++) {
        const struct quantity *q = &option_quantities[k];
        if (!quantity_in_totals(q) || !(q->measure & measures))
            continue;
        void *field = quantity_field_to_set(q, totals);
        if (q->field == FIELD_SIZE)
            *(size_t *)field = TOTALS_UNKNOWN;
        else if (q->field == FIELD_DOUBLE)
            *(double *)field = NAN;
    }
}

void quantity_totals_copy(struct option_totals *to,
                          const struct option_totals *from,
                          unsigned measures)
{
    for (int k = 0; k < OPTION_QUANTITIES; k++) {
        const struct quantity *q = &option_quantities[k];
        if (!quantity_in_totals(q) || !(q->measure & measures))
            continue;
        size_t size = q->field == FIELD_SIZE ? sizeof(size_t)
                                             : sizeof(double);
        assert(q->field == FIELD_SIZE || q->field == FIELD_DOUBLE);
        memcpy(quantity_field_to_set(q, to), quantity_field(q, from), size);
    }
}

double option_quantity_value(const struct option_row *option,
                          const char *column)
{
    const struct quantity *c = quantity_named(column);
    return c ? quantity_value(c, option) : NAN;
}

void quantity_csv_name(const struct quantity *q, char *out, size_t size)
{
    /* the unit as a word of a name: "m^2" is "m2", "USD" "usd" */
    char unit[16];
    size_t n = 0;
    for (const char *c = q->stored_unit; *c != '\0' && n + 1 < sizeof unit;
         c++)
        if (*c != '^')
            unit[n++] = (char)(*c >= 'A' && *c <= 'Z' ? *c - 'A' + 'a' : *c);
    unit[n] = '\0';
    size_t name = strlen(q->name);
    if (n == 0 || (name > n + 1 && q->name[name - n - 1] == '_' &&
                   strcmp(q->name + name - n, unit) == 0))
        snprintf(out, size, "%s", q->name);
    else
        snprintf(out, size, "%s_%s", q->name, unit);
}

void quantity_number_text(char *out, size_t size, double value, int decimals,
                       int thousands)
{
    if (size == 0)
        return;
    if (thousands && !(fabs(value) >= 1e18)) {
        number_grouped(out, size, value, decimals);
        return;
    }
    if (isnan(value))
        snprintf(out, size, "-");
    else if (isinf(value))
        snprintf(out, size, value > 0 ? "inf" : "-inf");
    else
        snprintf(out, size, "%.*f", decimals, value);
}

void quantity_text(char *out, size_t size, const struct quantity *c,
                       double value, int decimals)
{
    if (c->yes_no)
        snprintf(out, size, "%s", isnan(value) ? "-" : value != 0 ? "yes"
                                                                  : "no");
    else
        quantity_number_text(out, size, value * c->scale, decimals,
                          c->thousands);
}
