/*
 * option_column.h: the columns of a design option, in one registry.
 *
 * Every column of the options table (docs/store.md, the result store) is
 * one row of store_option_columns, and everything that names, reads or
 * shows an option's column takes it from there: the store's INSERT and
 * SELECT lists (store_option.c), the words --where and --sort accept
 * (filter.c), the workbench's options table, detail pane and plots
 * (tui/format.c), the CLI's tables, --json and --csv (cli/cmd_options.c,
 * cli/run_table.c).
 *
 * Adding a column to an option:
 *   1. the field, in struct option_totals (core/classify/classify.h) or
 *      struct option_row (store/store.h);
 *   2. one row of store_option_columns (option_column.c), after knee and
 *      before run: the table's order, as ALTER TABLE appends;
 *   3. the schema migration that adds it (store/schema.c) and its line in
 *      the options table of docs/store.md;
 *   4. its field in by_hand of tests/unit/test_option_column.c, the
 *      test's own reading of a row.
 * test_option_column fails until the registry and the table agree
 * (pragma_table_info), and checks that --where and --sort take the new
 * column. Nothing else needs to learn its name: it is stored, read back,
 * filtered, sorted and written to --json and --csv; to show it in a table
 * add its name to that table's list (tui/format.c, cli/option_table.c,
 * cli/cmd_options.c).
 *
 * No SQL and no curses here: store/ holds the registry because its SQL
 * uses the names; tui/ and cli/ read it.
 */
#ifndef FACET_OPTION_COLUMN_H
#define FACET_OPTION_COLUMN_H

#include <stddef.h>

struct option_row;  /* store.h */

/* How an option_row holds a column's value. */
enum option_field {
    FIELD_INT,       /* int */
    FIELD_INT64,     /* int64_t */
    FIELD_SIZE,      /* size_t */
    FIELD_DOUBLE,    /* double */
    FIELD_NONE       /* not in the row: run (the query's caller has it) */
};

/* Who writes a column to the table. */
enum option_writer {
    WRITTEN_WITH_OPTION,  /* store_options_put, from the row */
    WRITTEN_BY_RANKING,   /* store_options_set_pareto (NULL until then) */
    WRITTEN_AS_KEY        /* the run the option belongs to */
};

struct option_column {
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
};

/* Every column of the options table, in its order (pragma_table_info) but
 * run last. */
#define STORE_OPTION_COLUMNS 63
extern const struct option_column store_option_columns[STORE_OPTION_COLUMNS];

/* The column named name (exactly, lowercase), or NULL. */
const struct option_column *store_option_column(const char *name);

/* What a project's option shows in place of the column named name: its
 * nu and nv index the run's module range, a count of nothing on the
 * building, so module_w stands for nu and module_h for nv; any other
 * column is itself (NULL for no column). The CLI's tables and the TUI's
 * both ask it. */
const struct option_column *store_option_column_of_project(
    const char *name);

/* c's value in option, as stored (a deviation in m), yes/no as 0 or 1;
 * NaN for a value not known (NULL in the file: a column added after the
 * option was stored; a count then reads as TOTALS_UNKNOWN, classify.h),
 * and for run, which the row does not hold. */
double store_option_column_value(const struct option_column *c,
                                 const struct option_row *option);

/* The value of the column named column of option (store_option_column_value),
 * NaN for a name it does not know. */
double store_option_value(const struct option_row *option,
                          const char *column);

/* value with decimals places and, when thousands, 1,000 separators
 * ("1,551,317.25"); "-" for NaN, "inf"/"-inf" for infinities. */
void store_number_text(char *out, size_t size, double value, int decimals,
                       int thousands);

/* value (as stored) as c shows it with decimals places: times c->scale,
 * in c->unit, with c's separators; yes/no as "yes", "no" ("-" for NaN).
 * Not padded. */
void store_option_text(char *out, size_t size, const struct option_column *c,
                       double value, int decimals);

#endif
