/*
 * option_table.c: an option's cells in the CLI's tables. See
 * option_table.h.
 */
#include "option_table.h"

#include <assert.h>
#include <stdio.h>
#include <string.h>

const struct option_table_column option_table_paper[] = {
    {"number", 6, 0},
    {NULL, 1, 0},
    {"planarity", 11, 9},
    {"dp_area", 10, 9},
    {"cost", 14, 9},
    {"fp_area", 10, 3},
    {"sp_area", 10, 3},
    {"nu", 4, 8},
    {"nv", 4, 8},
    {"threshold_mm", 7, 7},
    {"rank", 4, 5},
};

int option_table_for_objectives(const char *objectives,
                                struct option_table_column *columns)
{
    int n = OPTION_TABLE_PAPER;
    memcpy(columns, option_table_paper, sizeof option_table_paper);
    const char *p = objectives;
    while (p != NULL && *p != '\0' && n < OPTION_TABLE_MAX) {
        size_t len = strcspn(p, ",");
        char name[64];
        snprintf(name, sizeof name, "%.*s", (int)len, p);
        const struct quantity *c = quantity_named(name);
        int listed = c == NULL;
        for (int k = 0; k < n && !listed; k++)
            listed = columns[k].column != NULL &&
                     strcmp(columns[k].column, c->name) == 0;
        if (!listed)
            columns[n++] = (struct option_table_column){c->name, 10, 9};
        p += len;
        if (*p == ',')
            p++;
    }
    return n;
}

void option_table_for_project(struct option_table_column *columns, int n)
{
    for (int k = 0; k < n; k++) {
        if (columns[k].column == NULL)
            continue;
        const struct quantity *shown =
            quantity_of_project(columns[k].column);
        if (shown != NULL && strcmp(shown->name, columns[k].column) != 0)
            columns[k] = (struct option_table_column){shown->name, 6,
                                                      columns[k].rank};
    }
}

void option_table_heads(const struct option_table_column *columns, int n,
                        struct text_column *heads)
{
    for (int k = 0; k < n; k++) {
        const struct quantity *c =
            columns[k].column ? quantity_named(columns[k].column)
                              : NULL;
        assert(columns[k].column == NULL || c != NULL);
        heads[k] = (struct text_column){c ? c->heading : "",
                                        c ? c->unit : "", columns[k].width,
                                        0, columns[k].rank, 0};
    }
}

void option_table_cells(const struct option_table_column *columns, int n,
                        int64_t run, const struct option_row *option,
                        char (*text)[OPTION_TABLE_CELL], const char **cell)
{
    for (int k = 0; k < n; k++) {
        cell[k] = text[k];
        if (columns[k].column == NULL) {
            snprintf(text[k], OPTION_TABLE_CELL, "%s",
                     option->rank == 1 ? "*" : "");
            continue;
        }
        const struct quantity *c = quantity_named(columns[k].column);
        double value = c->writer == WRITTEN_AS_KEY
                           ? (double)run : quantity_value(c, option);
        quantity_text(text[k], OPTION_TABLE_CELL, c, value, c->decimals);
    }
}
