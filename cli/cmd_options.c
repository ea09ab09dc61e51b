/*
 * cmd_options.c: `facet options DB`, the design options of a store,
 * filtered with the --where language (store/filter.h), sorted, as a table,
 * JSON or CSV.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "command.h"
#include "core/out/json.h"
#include "core/base/numformat.h"
#include "text_table.h"
#include "store/filter.h"
#include "store/store.h"

enum listing_format { LISTING_TABLE, LISTING_JSON, LISTING_CSV };

struct listing {
    enum listing_format format;
    struct json_writer json;
    struct text_table table;
    int64_t rows;
};

/* The human table: the objectives and the design variables stay longest,
 * the FP and SP areas go first on a narrow terminal. */
static const struct text_column option_columns[] = {
    {"run", "", 4, 0, 2, 0},
    {"No.", "", 6, 0, 0, 0},
    {"", "", 1, 0, 0, 0},
    {"planarity", "m", 11, 0, 9, 0},
    {"DP area", "m^2", 10, 0, 9, 0},
    {"total cost", "USD", 14, 0, 9, 0},
    {"FP area", "m^2", 10, 0, 3, 0},
    {"SP area", "m^2", 10, 0, 3, 0},
    {"U", "", 4, 0, 8, 0},
    {"V", "", 4, 0, 8, 0},
    {"t", "mm", 7, 0, 7, 0},
    {"rank", "", 4, 0, 5, 0},
    {"ok", "", 3, 0, 4, 0},
    {"", "", 4, 1, 6, 0},
};
enum { OPTION_COLUMNS = sizeof option_columns / sizeof option_columns[0] };

static int list_row(void *context, int64_t run, const struct option_row *o)
{
    struct listing *l = context;
    if (l->format == LISTING_TABLE) {
        char cost[64], id[24], number[24], planarity[32], dp[32], fp[32];
        char sp[32], u[16], v[16], t[32], rank[16];
        number_grouped(cost, sizeof cost, o->totals.cost, 0);
        snprintf(id, sizeof id, "%lld", (long long)run);
        snprintf(number, sizeof number, "%lld", (long long)o->number);
        snprintf(planarity, sizeof planarity, "%.4f", o->totals.planarity);
        snprintf(dp, sizeof dp, "%.2f", o->totals.area_of[TYPE_DP]);
        snprintf(fp, sizeof fp, "%.2f", o->totals.area_of[TYPE_FP]);
        snprintf(sp, sizeof sp, "%.2f", o->totals.area_of[TYPE_SP]);
        snprintf(u, sizeof u, "%d", o->nu);
        snprintf(v, sizeof v, "%d", o->nv);
        snprintf(t, sizeof t, "%.2f", o->threshold_mm);
        snprintf(rank, sizeof rank, "%d", o->rank);
        const char *cell[OPTION_COLUMNS] = {
            id, number, o->rank == 1 ? "*" : "", planarity, dp, cost, fp, sp,
            u, v, t, rank, o->totals.feasible ? "yes" : "no",
            o->knee ? "knee" : ""};
        text_table_row(stdout, &l->table, cell);
    } else if (l->format == LISTING_JSON) {
        json_begin_object(&l->json);
        json_key(&l->json, "run");
        json_integer(&l->json, run);
        for (int k = 0; store_option_columns[k] != NULL; k++) {
            const char *name = store_option_columns[k];
            if (strcmp(name, "run") == 0)
                continue;
            double value = store_option_value(o, name);
            json_key(&l->json, name);
            if (!isfinite(value))
                json_null(&l->json);  /* crowding at a front's end */
            else if (value == floor(value) && fabs(value) < 1e15)
                json_integer(&l->json, (long long)value);
            else
                json_number(&l->json, value);
        }
        json_end_object(&l->json);
    } else {
        printf("%lld", (long long)run);
        for (int k = 0; store_option_columns[k] != NULL; k++) {
            if (strcmp(store_option_columns[k], "run") == 0)
                continue;
            double value = store_option_value(o, store_option_columns[k]);
            char text[NUMBER_EXACT_SIZE] = "";
            /* Crowding at a front's end is infinite: an empty field, as
             * SQL's NULL and JSON's null say it. */
            if (isfinite(value))
                number_exact(text, value);
            printf(",%s", text);
        }
        putchar('\n');
    }
    l->rows++;
    return 0;
}

static int options_main(int argc, char **argv, struct facet_error *err)
{
    const char *run = NULL, *sort = NULL, *where = NULL, *limit = NULL;
    int pareto = 0, desc = 0, json = 0, csv = 0, wide = 0;
    const struct arg_option options[] = {
        {"run", 0, ARG_STRING, &run, NULL},
        {"pareto", 0, ARG_FLAG, NULL, &pareto},
        {"sort", 0, ARG_STRING, &sort, NULL},
        {"desc", 0, ARG_FLAG, NULL, &desc},
        {"where", 0, ARG_STRING, &where, NULL},
        {"limit", 0, ARG_STRING, &limit, NULL},
        {"json", 0, ARG_FLAG, NULL, &json},
        {"csv", 0, ARG_FLAG, NULL, &csv},
        {"wide", 0, ARG_FLAG, NULL, &wide},
        {NULL, 0, ARG_FLAG, NULL, NULL},
    };
    const char *path;
    int rc = args_parse_one(argc, argv, options, &path,
            "options: name the result database (facet options runs.db)", err);
    if (rc != FACET_OK)
        return rc;
    if (json && csv)
        return facet_error_set(err, FACET_EINPUT,
            "options: choose one of --json and --csv");
    long run_id = 0, rows = 0;
    if (run && (rc = args_int(run, 1, 1L << 62, "--run", &run_id, err)))
        return rc;
    if (limit && (rc = args_int(limit, 1, 1L << 62, "--limit", &rows, err)))
        return rc;
    if ((rc = store_options_sort_check(sort, err)))
        return rc;
    struct filter *filter = NULL;
    if (where && (rc = filter_compile(where, &filter, err)))
        return rc;
    struct store *store;
    if ((rc = store_open_read(path, &store, err)) != FACET_OK) {
        filter_free(filter);
        return rc;
    }
    struct run_info info;
    if (run_id > 0)
        rc = store_run_get(store, run_id, &info, err);

    struct listing listing;
    memset(&listing, 0, sizeof listing);
    listing.format = json ? LISTING_JSON : csv ? LISTING_CSV : LISTING_TABLE;
    if (rc == FACET_OK) {
        if (listing.format == LISTING_TABLE) {
            listing.table = (struct text_table){option_columns,
                                                OPTION_COLUMNS, {0}, 0, 0};
            text_table_fit(&listing.table, text_table_width(stdout, wide));
            text_table_head(stdout, &listing.table);
        } else if (listing.format == LISTING_JSON) {
            json_init(&listing.json, stdout);
            json_begin_array(&listing.json);
        } else {
            printf("run");
            for (int k = 0; store_option_columns[k] != NULL; k++)
                if (strcmp(store_option_columns[k], "run") != 0)
                    printf(",%s", store_option_columns[k]);
            putchar('\n');
        }
        struct option_query q = {run_id, pareto, filter, sort, desc, rows, 0};
        rc = store_options_query(store, &q, list_row, &listing, err);
        if (listing.format == LISTING_JSON) {
            json_end_array(&listing.json);
            json_finish(&listing.json);
        } else if (listing.format == LISTING_TABLE && rc == FACET_OK) {
            printf("(%lld options%s%s)\n", (long long)listing.rows,
                   filter ? " where " : "", filter ? filter_text(filter)
                                                   : "");
            text_table_foot(stdout, &listing.table);
        }
    }
    store_close(store);
    filter_free(filter);
    return rc;
}

const struct command cmd_options = {
    .name = "options",
    .usage = "DB [--run N] [--pareto] [--sort KEY[,KEY]] [--desc]\n"
             "       [--where EXPR] [--limit N] [--wide] [--json|--csv]",
    .summary = "List, filter and sort the design options of a result "
               "store.",
    .options =
        "  --run N             only run N (default every run)\n"
        "  --pareto            only Pareto-optimal options (rank 1)\n"
        "  --sort KEYS         columns to sort by, e.g. cost,dp_area\n"
        "                      (default run, number)\n"
        "  --desc              sort descending\n"
        "  --where EXPR        e.g. 'cost < 1.5e6 and dp_area <= 900 or\n"
        "                      pareto' (columns: see README)\n"
        "  --limit N           at most N options\n"
        "  --json              one JSON array, every column\n"
        "  --csv               CSV with a header row, every column\n"
        "  --wide              every column of the table, whatever the\n"
        "                      terminal's width\n"
        "examples:\n"
        "  facet options runs.db --run 1 --pareto --sort cost\n"
        "  facet options runs.db --where 'dp_area < 300 and feasible' "
        "--csv > cheap.csv\n",
    .run = options_main,
};
