"""The header a CSV of options gives a column of the store's options
table: the column and the unit its value is written in, as the panel
schedule names its columns (docs/manual.md, "facet options"). Written
here from the documented units of docs/store.md, not from Facet's code,
for the tests that read `facet options --csv` and the workbench's marked
CSV by name.
"""

# Each column that has a unit, as its value is stored and written.
UNITS = {
    "fp_area": "m2", "sp_area": "m2", "dp_area": "m2", "area": "m2",
    "fp_cost": "usd", "sp_cost": "usd", "dp_cost": "usd", "cost": "usd",
    "planarity": "m", "max_deviation": "m", "max_panel_area": "m2",
    "p_dist": "m4", "joint_length": "m", "area_cost": "usd",
    "panel_cost": "usd", "joint_cost": "usd", "mould_cost": "usd",
    "max_gap": "mm", "mean_gap": "mm", "max_kink": "deg", "mean_kink": "deg",
    "module_w": "m", "module_h": "m", "sp_min_radius": "m",
    "min_panel_area": "m2", "min_panel_width": "m",
    "closeness_reached": "m", "closeness_mean": "m",
    "seam_length": "m", "seam_max_gap": "mm", "seam_max_kink": "deg",
    "seam_max_crease": "deg",  # schema v16: as max_gap and max_kink
}
for _class in ("convex_feature_curve", "saddle", "concave_feature_curve",
               "ruled_convex", "flat", "ruled_concave", "convex_round",
               "concave_round"):
    UNITS[_class + "_area"] = "m2"


def csv_name(column):
    """The CSV header of the store's column."""
    return column + "_" + UNITS[column] if column in UNITS else column


def column_of(header):
    """The store's column a CSV header names."""
    for column, unit in UNITS.items():
        if header == column + "_" + unit:
            return column
    return header
