/*
 * option_table.h: the columns of a design option in the CLI's tables
 * (`facet options`, a run's Table 2). Each is a column of the registry
 * (core/quantity/quantity.h), which gives its heading, unit and format, in
 * a width and with a rank (text_table.h) the table chooses.
 */
#ifndef FACET_OPTION_TABLE_H
#define FACET_OPTION_TABLE_H

#include <stdint.h>

#include "store/store.h"
#include "text_table.h"

struct option_table_column {
    const char *column;   /* option_quantities name; NULL for the
                             Pareto mark ("*" for rank 1) */
    int width;            /* characters, right-aligned */
    int rank;             /* higher stays longer; 0: never dropped */
};

/* The paper's Table 2: No., the Pareto mark, planarity, DP area, cost, FP
 * area, SP area, U, V, threshold, rank; the objectives and the design
 * variables stay longest, the FP and SP areas go first on a narrow
 * terminal. Both CLI tables show them. */
#define OPTION_TABLE_PAPER 11
extern const struct option_table_column option_table_paper[OPTION_TABLE_PAPER];

/* The paper's columns, then each of objectives (a run's objectives, as
 * "cost,moulds,max_gap") that is an option column the paper's table lacks,
 * in the order given, kept as long as the objectives already there: a run
 * that searched for moulds shows its moulds. Into columns (room for
 * OPTION_TABLE_MAX); returns how many. */
#define OPTION_TABLE_OBJECTIVES 8
#define OPTION_TABLE_MAX (OPTION_TABLE_PAPER + OPTION_TABLE_OBJECTIVES)
int option_table_for_objectives(const char *objectives,
                                struct option_table_column *columns);

/* For a project run's table: the module's width and height in place of
 * the grid U and V (a project's nu and nv are module indices), in
 * columns[0..n). */
void option_table_for_project(struct option_table_column *columns, int n);

/* The longest cell text, with its terminator. */
#define OPTION_TABLE_CELL 64

/* The text_table columns of columns[0..n) into heads[0..n): the
 * registry's heading and unit. */
void option_table_heads(const struct option_table_column *columns, int n,
                        struct text_column *heads);

/* The cells of option, of run, for columns[0..n): the value as the
 * registry shows it with its decimals, into text[k], and cell[k] = text[k]. */
void option_table_cells(const struct option_table_column *columns, int n,
                        int64_t run, const struct option_row *option,
                        char (*text)[OPTION_TABLE_CELL], const char **cell);

#endif
