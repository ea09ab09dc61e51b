/*
 * option_column.c: the registry of an option's columns, and reading and
 * writing a column's value. See option_column.h, which says how to add a
 * column.
 */
#include "store/option_column.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "core/base/numformat.h"
#include "store/store.h"

/* Where a field of struct option_row is. */
#define ROW(member) offsetof(struct option_row, member)
#define TOTAL(member) offsetof(struct option_row, totals.member)

/* name, label, heading, unit, stored_unit, scale, decimals, list_decimals,
 * thousands, yes_no, example, field, offset, writer. (Sized by its rows: a
 * count in the header that differs is a compile error.) */
const struct option_column store_option_columns[] = {
    {"number", "No.", "No.", "", "", 1, 0, 0, 0, 0, "10",
     FIELD_INT64, ROW(number), WRITTEN_WITH_OPTION},
    {"generation", "generation", "gen", "", "", 1, 0, 0, 0, 0, "5",
     FIELD_INT, ROW(generation), WRITTEN_WITH_OPTION},
    {"nu", "U", "U", "", "", 1, 0, 0, 0, 0, "30",
     FIELD_INT, ROW(nu), WRITTEN_WITH_OPTION},
    {"nv", "V", "V", "", "", 1, 0, 0, 0, 0, "30",
     FIELD_INT, ROW(nv), WRITTEN_WITH_OPTION},
    {"threshold_mm", "threshold", "t", "mm", "mm", 1, 2, 2, 0, 0, "5",
     FIELD_DOUBLE, ROW(threshold_mm), WRITTEN_WITH_OPTION},
    {"panels", "panels", "panels", "", "", 1, 0, 0, 0, 0, "500",
     FIELD_SIZE, TOTAL(panels), WRITTEN_WITH_OPTION},
    {"fp_count", "FP panels", "FP n", "", "", 1, 0, 0, 0, 0, "100",
     FIELD_SIZE, TOTAL(count[TYPE_FP]), WRITTEN_WITH_OPTION},
    {"sp_count", "SP panels", "SP n", "", "", 1, 0, 0, 0, 0, "100",
     FIELD_SIZE, TOTAL(count[TYPE_SP]), WRITTEN_WITH_OPTION},
    {"dp_count", "DP panels", "DP n", "", "", 1, 0, 0, 0, 0, "100",
     FIELD_SIZE, TOTAL(count[TYPE_DP]), WRITTEN_WITH_OPTION},
    {"fp_area", "FP area", "FP area", "m^2", "m^2", 1, 2, 1, 0, 0, "100",
     FIELD_DOUBLE, TOTAL(area_of[TYPE_FP]), WRITTEN_WITH_OPTION},
    {"sp_area", "SP area", "SP area", "m^2", "m^2", 1, 2, 1, 0, 0, "100",
     FIELD_DOUBLE, TOTAL(area_of[TYPE_SP]), WRITTEN_WITH_OPTION},
    {"dp_area", "DP area", "DP area", "m^2", "m^2", 1, 2, 1, 0, 0, "900",
     FIELD_DOUBLE, TOTAL(area_of[TYPE_DP]), WRITTEN_WITH_OPTION},
    {"area", "area", "area", "m^2", "m^2", 1, 2, 1, 0, 0, "1200",
     FIELD_DOUBLE, TOTAL(area), WRITTEN_WITH_OPTION},
    {"fp_cost", "FP cost", "FP cost", "USD", "USD", 1, 0, 0, 1, 0, "5e5",
     FIELD_DOUBLE, TOTAL(cost_of[TYPE_FP]), WRITTEN_WITH_OPTION},
    {"sp_cost", "SP cost", "SP cost", "USD", "USD", 1, 0, 0, 1, 0, "5e5",
     FIELD_DOUBLE, TOTAL(cost_of[TYPE_SP]), WRITTEN_WITH_OPTION},
    {"dp_cost", "DP cost", "DP cost", "USD", "USD", 1, 0, 0, 1, 0, "5e5",
     FIELD_DOUBLE, TOTAL(cost_of[TYPE_DP]), WRITTEN_WITH_OPTION},
    {"cost", "cost", "cost", "USD", "USD", 1, 0, 0, 1, 0, "1e6",
     FIELD_DOUBLE, TOTAL(cost), WRITTEN_WITH_OPTION},
    {"planarity", "planarity", "planarity", "m", "m", 1, 4, 3, 0, 0, "0.01",
     FIELD_DOUBLE, TOTAL(planarity), WRITTEN_WITH_OPTION},
    {"max_deviation", "max deviation", "max dev", "mm", "m", 1000, 2, 2, 0, 0,
     "0.01", FIELD_DOUBLE, TOTAL(max_deviation), WRITTEN_WITH_OPTION},
    {"max_panel_area", "max panel area", "max pan",
     "m^2", "m^2", 1, 2, 2, 0, 0,
     "4", FIELD_DOUBLE, TOTAL(max_panel_area), WRITTEN_WITH_OPTION},
    {"p_dist", "P_dist", "P_dist", "m^4", "m^4", 1, 6, 4, 0, 0, "0.5",
     FIELD_DOUBLE, TOTAL(p_dist), WRITTEN_WITH_OPTION},
    {"feasible", "feasible", "ok", "", "", 1, 0, 0, 0, 1, NULL,
     FIELD_INT, TOTAL(feasible), WRITTEN_WITH_OPTION},
    /* Per class (core/panel/panel.h), in the order of enum panel_class. */
    {"convex_feature_curve_count", "convex feature curve panels",
     "convex feature curve panels", "", "",
     1, 0, 0, 0, 0, "100", FIELD_SIZE,
     TOTAL(class_count[CLASS_CONVEX_FEATURE_CURVE]), WRITTEN_WITH_OPTION},
    {"convex_feature_curve_area", "convex feature curve area",
     "convex feature curve area", "m^2", "m^2",
     1, 2, 1, 0, 0, "100", FIELD_DOUBLE,
     TOTAL(class_area[CLASS_CONVEX_FEATURE_CURVE]), WRITTEN_WITH_OPTION},
    {"saddle_count", "saddle panels", "saddle panels", "", "",
     1, 0, 0, 0, 0, "100", FIELD_SIZE,
     TOTAL(class_count[CLASS_SADDLE]), WRITTEN_WITH_OPTION},
    {"saddle_area", "saddle area", "saddle area", "m^2", "m^2",
     1, 2, 1, 0, 0, "100", FIELD_DOUBLE,
     TOTAL(class_area[CLASS_SADDLE]), WRITTEN_WITH_OPTION},
    {"concave_feature_curve_count", "concave feature curve panels",
     "concave feature curve panels", "", "",
     1, 0, 0, 0, 0, "100", FIELD_SIZE,
     TOTAL(class_count[CLASS_CONCAVE_FEATURE_CURVE]), WRITTEN_WITH_OPTION},
    {"concave_feature_curve_area", "concave feature curve area",
     "concave feature curve area", "m^2", "m^2",
     1, 2, 1, 0, 0, "100", FIELD_DOUBLE,
     TOTAL(class_area[CLASS_CONCAVE_FEATURE_CURVE]), WRITTEN_WITH_OPTION},
    {"ruled_convex_count", "ruled convex panels", "ruled convex panels",
     "", "",
     1, 0, 0, 0, 0, "100", FIELD_SIZE,
     TOTAL(class_count[CLASS_RULED_CONVEX]), WRITTEN_WITH_OPTION},
    {"ruled_convex_area", "ruled convex area", "ruled convex area",
     "m^2", "m^2",
     1, 2, 1, 0, 0, "100", FIELD_DOUBLE,
     TOTAL(class_area[CLASS_RULED_CONVEX]), WRITTEN_WITH_OPTION},
    {"flat_count", "flat panels", "flat panels", "", "",
     1, 0, 0, 0, 0, "100", FIELD_SIZE,
     TOTAL(class_count[CLASS_FLAT]), WRITTEN_WITH_OPTION},
    {"flat_area", "flat area", "flat area", "m^2", "m^2",
     1, 2, 1, 0, 0, "100", FIELD_DOUBLE,
     TOTAL(class_area[CLASS_FLAT]), WRITTEN_WITH_OPTION},
    {"ruled_concave_count", "ruled concave panels", "ruled concave panels",
     "", "",
     1, 0, 0, 0, 0, "100", FIELD_SIZE,
     TOTAL(class_count[CLASS_RULED_CONCAVE]), WRITTEN_WITH_OPTION},
    {"ruled_concave_area", "ruled concave area", "ruled concave area",
     "m^2", "m^2",
     1, 2, 1, 0, 0, "100", FIELD_DOUBLE,
     TOTAL(class_area[CLASS_RULED_CONCAVE]), WRITTEN_WITH_OPTION},
    {"convex_round_count", "convex round panels", "convex round panels",
     "", "",
     1, 0, 0, 0, 0, "100", FIELD_SIZE,
     TOTAL(class_count[CLASS_CONVEX_ROUND]), WRITTEN_WITH_OPTION},
    {"convex_round_area", "convex round area", "convex round area",
     "m^2", "m^2",
     1, 2, 1, 0, 0, "100", FIELD_DOUBLE,
     TOTAL(class_area[CLASS_CONVEX_ROUND]), WRITTEN_WITH_OPTION},
    {"concave_round_count", "concave round panels", "concave round panels",
     "", "",
     1, 0, 0, 0, 0, "100", FIELD_SIZE,
     TOTAL(class_count[CLASS_CONCAVE_ROUND]), WRITTEN_WITH_OPTION},
    {"concave_round_area", "concave round area", "concave round area",
     "m^2", "m^2",
     1, 2, 1, 0, 0, "100", FIELD_DOUBLE,
     TOTAL(class_area[CLASS_CONCAVE_ROUND]), WRITTEN_WITH_OPTION},
    /* The Pareto analysis, written when the run ends. */
    {"rank", "rank", "rank", "", "", 1, 0, 0, 0, 0, "2",
     FIELD_INT, ROW(rank), WRITTEN_BY_RANKING},
    {"crowding", "crowding", "crowd", "", "", 1, 3, 3, 0, 0, "0.5",
     FIELD_DOUBLE, ROW(crowding), WRITTEN_BY_RANKING},
    {"knee", "knee", "knee", "", "", 1, 0, 0, 0, 1, NULL,
     FIELD_INT, ROW(knee), WRITTEN_BY_RANKING},
    /* The cost model beyond area (schema v5). */
    {"joint_length", "joint length", "joints", "m", "m", 1, 1, 0, 1, 0, "2000",
     FIELD_DOUBLE, TOTAL(joint_length), WRITTEN_WITH_OPTION},
    {"moulds", "moulds", "moulds", "", "", 1, 0, 0, 0, 0, "50",
     FIELD_SIZE, TOTAL(moulds), WRITTEN_WITH_OPTION},
    {"sp_moulds", "SP moulds", "SP mld", "", "", 1, 0, 0, 0, 0, "20",
     FIELD_SIZE, TOTAL(moulds_of[TYPE_SP]), WRITTEN_WITH_OPTION},
    {"dp_moulds", "DP moulds", "DP mld", "", "", 1, 0, 0, 0, 0, "20",
     FIELD_SIZE, TOTAL(moulds_of[TYPE_DP]), WRITTEN_WITH_OPTION},
    {"largest_family", "largest mould family", "big fam", "", "", 1, 0, 0, 0, 0,
     "10", FIELD_SIZE, TOTAL(largest_family), WRITTEN_WITH_OPTION},
    {"single_moulds", "moulds of one panel", "single", "", "", 1, 0, 0, 0, 0,
     "10", FIELD_SIZE, TOTAL(singleton_families), WRITTEN_WITH_OPTION},
    {"area_cost", "area cost", "area cost", "USD", "USD", 1, 0, 0, 1, 0, "1e6",
     FIELD_DOUBLE, TOTAL(area_cost), WRITTEN_WITH_OPTION},
    {"panel_cost", "panel cost", "pan cost", "USD", "USD", 1, 0, 0, 1, 0, "1e5",
     FIELD_DOUBLE, TOTAL(panel_cost), WRITTEN_WITH_OPTION},
    {"joint_cost", "joint cost", "jnt cost", "USD", "USD", 1, 0, 0, 1, 0, "1e5",
     FIELD_DOUBLE, TOTAL(joint_cost), WRITTEN_WITH_OPTION},
    {"mould_cost", "mould cost", "mld cost", "USD", "USD", 1, 0, 0, 1, 0, "1e5",
     FIELD_DOUBLE, TOTAL(mould_cost), WRITTEN_WITH_OPTION},
    /* Panels as built and their joints (schema v7). */
    {"max_gap", "max gap", "max gap", "mm", "mm", 1, 2, 2, 0, 0, "6",
     FIELD_DOUBLE, TOTAL(max_gap_mm), WRITTEN_WITH_OPTION},
    {"mean_gap", "mean gap", "mean gap", "mm", "mm", 1, 3, 2, 0, 0, "1",
     FIELD_DOUBLE, TOTAL(mean_gap_mm), WRITTEN_WITH_OPTION},
    {"max_kink", "max kink", "max kink", "deg", "deg", 1, 2, 2, 0, 0, "1",
     FIELD_DOUBLE, TOTAL(max_kink_deg), WRITTEN_WITH_OPTION},
    {"mean_kink", "mean kink", "mean kink", "deg", "deg", 1, 3, 2, 0, 0,
     "0.5", FIELD_DOUBLE, TOTAL(mean_kink_deg), WRITTEN_WITH_OPTION},
    {"gaps_over", "gaps over limit", "gaps>", "", "", 1, 0, 0, 0, 0, "0",
     FIELD_SIZE, TOTAL(gaps_over), WRITTEN_WITH_OPTION},
    {"kinks_over", "kinks over limit", "kinks>", "", "", 1, 0, 0, 0, 0, "0",
     FIELD_SIZE, TOTAL(kinks_over), WRITTEN_WITH_OPTION},
    {"sp_misfits", "SP misfits", "misfit", "", "", 1, 0, 0, 0, 0, "10",
     FIELD_SIZE, TOTAL(sp_misfits), WRITTEN_WITH_OPTION},
    {"sp_fitted", "SP fitted", "fitted", "", "", 1, 0, 0, 0, 0, "100",
     FIELD_SIZE, TOTAL(sp_fitted), WRITTEN_WITH_OPTION},
    /* A project's module (schema v8); NULL for a single surface. */
    {"module_w", "module width", "mod w", "m", "m", 1, 2, 2, 0, 0, "1.5",
     FIELD_DOUBLE, ROW(module_w), WRITTEN_WITH_OPTION},
    {"module_h", "module height", "mod h", "m", "m", 1, 2, 2, 0, 0, "1.2",
     FIELD_DOUBLE, ROW(module_h), WRITTEN_WITH_OPTION},
    {"modules", "modules of this option", "mods", "", "", 1, 0, 0, 0, 0, "2",
     FIELD_SIZE, ROW(modules), WRITTEN_WITH_OPTION},
    /* New columns go here, before run. */
    {"run", "run", "run", "", "", 1, 0, 0, 0, 0, "1",
     FIELD_NONE, 0, WRITTEN_AS_KEY},
};

const struct option_column *store_option_column(const char *name)
{
    for (int k = 0; k < STORE_OPTION_COLUMNS; k++)
        if (strcmp(store_option_columns[k].name, name) == 0)
            return &store_option_columns[k];
    return NULL;
}

const struct option_column *store_option_column_of_project(
    const char *name)
{
    if (strcmp(name, "nu") == 0)
        return store_option_column("module_w");
    if (strcmp(name, "nv") == 0)
        return store_option_column("module_h");
    return store_option_column(name);
}

double store_option_column_value(const struct option_column *c,
                                 const struct option_row *option)
{
    const char *field = (const char *)option + c->offset;
    double value;
    switch (c->field) {
    case FIELD_INT:    value = *(const int *)(const void *)field; break;
    case FIELD_INT64:
        value = (double)*(const int64_t *)(const void *)field;
        break;
    case FIELD_SIZE:   /* NaN for TOTALS_UNKNOWN */
        value = totals_count(*(const size_t *)(const void *)field);
        break;
    case FIELD_DOUBLE: value = *(const double *)(const void *)field; break;
    default:           return NAN;
    }
    return c->yes_no ? value != 0 : value;
}

double store_option_value(const struct option_row *option,
                          const char *column)
{
    const struct option_column *c = store_option_column(column);
    return c ? store_option_column_value(c, option) : NAN;
}

void store_number_text(char *out, size_t size, double value, int decimals,
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

void store_option_text(char *out, size_t size, const struct option_column *c,
                       double value, int decimals)
{
    if (c->yes_no)
        snprintf(out, size, "%s", isnan(value) ? "-" : value != 0 ? "yes"
                                                                  : "no");
    else
        store_number_text(out, size, value * c->scale, decimals,
                          c->thousands);
}
