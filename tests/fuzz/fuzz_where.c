/*
 * fuzz_where.c: the --where language on any text. What compiles must
 * select the same options through SQLite (its SQL and its scan form) as
 * through Facet's own evaluator, on a fixed table of pseudo-random
 * options (filter_oracle.h); what does not compile is one line.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fuzz.h"
#include "tests/support/filter_oracle.h"

enum { ROWS = 300 };

/* The table every input is filtered against, made on the first input:
 * fuzz targets keep state only to save rebuilding it. */
static struct oracle_row table_rows[ROWS];
static sqlite3 *table;

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (table == NULL) {
        struct rng rng;
        rng_seed(&rng, 11);
        oracle_random_rows(&rng, table_rows, ROWS);
        table = oracle_database(table_rows, ROWS);
        if (table == NULL)
            abort();
    }
    char *text = malloc(size + 1);
    if (text == NULL)
        return 0;
    memcpy(text, data, size);
    text[size] = '\0';
    struct filter *f = NULL;
    struct facet_error err;
    if (filter_compile(text, &f, &err) == FACET_OK) {
        char why[2048];
        if (oracle_compare(table, table_rows, ROWS, f, why, sizeof why) < 0) {
            fprintf(stderr, "fuzz_where: %s\n", why);
            abort();
        }
        /* The text shown back is the same filter. */
        struct filter *again = NULL;
        if (filter_compile(filter_text(f), &again, &err) != FACET_OK) {
            fprintf(stderr, "fuzz_where: its text does not compile: %s\n",
                    err.message);
            abort();
        }
        int first = oracle_compare(table, table_rows, ROWS, f, why,
                                   sizeof why);
        int second = oracle_compare(table, table_rows, ROWS, again, why,
                                    sizeof why);
        if (first < 0 || second != first)
            abort();
        filter_free(again);
    } else if (err.message[0] == '\0' || strchr(err.message, '\n')) {
        abort();
    }
    filter_free(f);
    free(text);
    return 0;
}
