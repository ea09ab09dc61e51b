/*
 * quantity.h: every quantity of a design option, declared once.
 *
 * One row of option_quantities per number an option has: its design
 * point (grid, threshold), its totals (areas, counts, costs, deviation,
 * gaps and kinks, moulds), its Pareto ranking and a building's module.
 * Each row says, for that number:
 *   - its name: the column of the store's options table, and the word of
 *     --where, --sort, --objectives, --json and --csv;
 *   - its words and units as a facade engineer reads them (label,
 *     heading, unit), the scale from the value as held to the value as
 *     shown (a deviation held in m, shown in mm), its decimals;
 *   - where it is held (offset in struct option_row, option_row.h);
 *   - how a building's value combines its surfaces' (combine);
 *   - the stage of the evaluation that measures it (measure: option.h's
 *     option_measure bits; 0 for what classifying the panels gives), so a
 *     run that does not need the stage leaves it NULL, "not measured";
 *   - whether it can be an objective (objective), and whether a
 *     building's option keeps it for each of its surfaces (per_surface).
 * Everything that names, reads, combines or shows an option's number takes
 * it from here: the store's INSERT and SELECT lists and its migrations'
 * check (store/), --where and --sort (store/filter.c), the objectives
 * (core/search/metric.c), a building's totals
 * (core/project/project_option.c), the workbench's tables, detail pane,
 * pickers and plots (tui/), the CLI's tables, --json and --csv (cli/).
 *
 * Adding a quantity to an option:
 *   1. its field, in struct option_totals (core/classify/classify.h) and
 *      its computation in the stage that measures it;
 *   2. one row of option_quantities (quantity.c), after modules and before
 *      run: the table's order, as ALTER TABLE appends;
 *   3. the schema migration that adds its column (store/schema.c) to
 *      options, and to option_surfaces when per_surface, and its line in
 *      the options table of docs/store.md.
 * test_option_column fails until the rows and the store's table agree
 * (pragma_table_info), reads every row back through SQLite, and checks
 * that --where and --sort take the new row; test_project_option checks a
 * building's totals against its own sums of the surfaces'.
 *
 * No SQL and no curses here: pure data and the formatting of a value.
 */
#ifndef FACET_OPTION_COLUMN_H
#define FACET_OPTION_COLUMN_H

#include <stddef.h>

#include "core/quantity/option_row.h"

/* How an option_row holds a column's value. */
enum option_field {
    FIELD_INT,       /* int */
    FIELD_INT64,     /* int64_t */
    FIELD_SIZE,      /* size_t */
    FIELD_DOUBLE,    /* double */
    FIELD_NONE       /* not in the row: run (the query's caller has it) */
};

/* How a building's value of a quantity follows from its surfaces'. */
enum quantity_combine {
    COMBINE_SUM,          /* a count: the surfaces' counts added */
    COMBINE_EXACT_SUM,    /* a length, area or sum of deviations: added in
                             exact arithmetic (core/base/exact_sum.h), so
                             the order of the surfaces cannot show */
    COMBINE_MAX,          /* the largest of the surfaces' */
    COMBINE_MIN,          /* the least of the surfaces' that are known
                             (NaN: none has one) */
    COMBINE_JOINT_MEAN,   /* a mean over joints: the surfaces' means, each
                             weighted by its share of the joints */
    COMBINE_RECOMPUTED,   /* priced, counted over the building's mould
                             families, or judged again on the building's
                             totals: not from the surfaces' values */
    COMBINE_NONE          /* the option's own: its design point, number,
                             ranking, module */
};

/* How the store keeps a quantity that core holds in SI (metres,
 * radians) but users query in mm or degrees (docs/store.md, schema v16).
 * Its column of the options table (and of option_surfaces) holds it in
 * mm or degrees, by units.h's functions, so that it has the bits it had
 * when core held the value so; the value as core holds it is kept beside,
 * in option_held (option_surface_held), which Facet reads back: a length
 * or angle cannot go through mm or degrees and back to the bit (x * 1000
 * / 1000 is not always x). */
enum quantity_stored {
    STORED_AS_HELD = 0,   /* the column holds the value as core does */
    STORED_MM,            /* held in m, the column in mm */
    STORED_DEG            /* held in rad, the column in degrees */
};

/* Who writes a column to the table. */
enum option_writer {
    WRITTEN_WITH_OPTION,  /* store_options_put, from the row */
    WRITTEN_BY_RANKING,   /* store_options_set_pareto (NULL until then) */
    WRITTEN_AS_KEY        /* the run the option belongs to */
};

struct quantity {
    const char *name;      /* the column of the options table, and the word
                              of --where, --sort, --json and --csv */
    const char *label;     /* what a facade engineer reads beside a value:
                              "max deviation" */
    const char *heading;   /* the same in a narrow table's header: "max dev" */
    const char *unit;      /* of the value as shown ("mm"), "" for none */
    const char *stored_unit; /* of the value as stored and plotted ("m"),
                              "" for none: unit when scale is 1 */
    double scale;          /* shown = stored x scale: a deviation is stored
                              in m and shown in mm (1000), as the threshold
                              it is held to; 1 otherwise */
    int decimals;          /* shown on its own, and in the CLI's tables */
    int list_decimals;     /* in the workbench's options list, where twelve
                              columns share 80 characters */
    int thousands;         /* 1,000 separators */
    int yes_no;            /* 0 or 1, shown "no"/"yes"; stands alone in a
                              --where ("feasible and knee") */
    const char *example;   /* a number to compare it with, for a --where
                              message ("cost < 1e6"); NULL when yes_no */
    enum option_field field;
    size_t offset;         /* of the field in struct option_row */
    enum option_writer writer;
    enum quantity_combine combine;
    unsigned measure;      /* option.h's option_measure bits of the stage
                              that measures it; 0: classifying does, and
                              for a price (what a price needs measured is
                              option_measures_needed's) */
    int objective;         /* can be minimised or maximised (metric.h) */
    int per_surface;       /* a building's option keeps it for each
                              surface too (the store's option_surfaces) */
    enum quantity_stored stored; /* a gap or angle held in SI, its
                              column in stored_unit (quantity_stored) */
};

/* Every column of the options table, in its order (pragma_table_info) but
 * run last. */
#define OPTION_QUANTITIES 79
extern const struct quantity option_quantities[OPTION_QUANTITIES];

/* The column named name (exactly, lowercase), or NULL. */
const struct quantity *quantity_named(const char *name);

/* What a project's option shows in place of the column named name: its
 * nu and nv index the run's module range, a count of nothing on the
 * building, so module_w stands for nu and module_h for nv; any other
 * column is itself (NULL for no column). The CLI's tables and the TUI's
 * both ask it. */
const struct quantity *quantity_of_project(
    const char *name);

/* held (a double of q's field, in SI) in q's stored unit: what its
 * column holds (quantity_stored). NaN stays NaN. */
double quantity_stored_of_held(const struct quantity *q, double held);

/* c's value in option, as stored (a deviation in m, a gap in mm: held in
 * SI and turned into the column's unit, quantity_stored), yes/no as 0 or 1;
 * NaN for a value not known (NULL in the file: a column added after the
 * option was stored; a count then reads as TOTALS_UNKNOWN, classify.h),
 * and for run, which the row does not hold. */
double quantity_value(const struct quantity *c,
                                 const struct option_row *option);

/* Whether q is one of an option's totals (struct option_totals), the
 * numbers an evaluation gives, rather than its design point, number,
 * ranking or module. */
int quantity_in_totals(const struct quantity *q);

/* Where totals hold q (q must be in them: quantity_in_totals): an int,
 * size_t or double as q->field says. quantity_field_to_set is the same
 * place, to write. */
const void *quantity_field(const struct quantity *q,
                           const struct option_totals *totals);
void *quantity_field_to_set(const struct quantity *q,
                            struct option_totals *totals);

/* q's value in totals (q must be in them: quantity_in_totals), as
 * quantity_value reads it from a row: in the stored unit. */
double quantity_of_totals(const struct quantity *q,
                          const struct option_totals *totals);

/* Whether q has no value in totals although the stage that measures it
 * ran: an option with no panel built SP has no smallest bending radius,
 * one of a single panel no joint. What a view shows as "none", where a
 * value a stage did not measure (option.h's option_totals_measures) is
 * "not measured". 0 for a value that is there. */
int quantity_none(const struct quantity *q,
                  const struct option_totals *totals);

/* Sets every quantity of totals that a stage of measures (option.h's
 * option_measure bits) measures to "not measured": NaN, or
 * TOTALS_UNKNOWN for a count. What a run that leaves those stages out
 * stores (NULL). */
void quantity_totals_forget(struct option_totals *totals, unsigned measures);

/* Copies from from into to every quantity a stage of measures measures. */
void quantity_totals_copy(struct option_totals *to,
                          const struct option_totals *from,
                          unsigned measures);

/* The value of the column named column of option (quantity_value),
 * NaN for a name it does not know. */
double option_quantity_value(const struct option_row *option,
                          const char *column);

/* q's name in a CSV header: its name and the unit it is written in (as
 * stored), the panel schedule's convention: "cost_usd", "fp_area_m2",
 * "max_deviation_m", "p_dist_m4", "max_gap_mm", "max_kink_deg"; a name
 * that already ends with its unit ("threshold_mm") and a quantity of no
 * unit ("panels", "crowding") as it is. What `facet options --csv`, the
 * workbench's marked CSV and an export's totals CSV name their columns;
 * --where, --sort and --json take the name alone (docs/manual.md). */
void quantity_csv_name(const struct quantity *q, char *out, size_t size);

/* value with decimals places and, when thousands, 1,000 separators
 * ("1,551,317.25"); "-" for NaN, "inf"/"-inf" for infinities. */
void quantity_number_text(char *out, size_t size, double value, int decimals,
                       int thousands);

/* value (as stored) as c shows it with decimals places: times c->scale,
 * in c->unit, with c's separators; yes/no as "yes", "no" ("-" for NaN).
 * Not padded. */
void quantity_text(char *out, size_t size, const struct quantity *c,
                       double value, int decimals);

#endif
