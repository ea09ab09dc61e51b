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
#include "core/out/option_csv.h"
#include "core/base/numformat.h"
#include "option_table.h"
#include "surface_table.h"
#include "text_table.h"
#include "store/filter.h"
#include "store/store.h"

enum listing_format { LISTING_TABLE, LISTING_JSON, LISTING_CSV };

/* The human table: the run, Table 2's columns (option_table.h), whether
 * the option is feasible, and the knee's mark. */
enum { LISTED = 1 + OPTION_TABLE_PAPER + 1 };

struct listing {
    enum listing_format format;
    struct json_writer json;
    struct option_table_column listed[LISTED];
    struct text_column heads[LISTED + 1];  /* listed, then the knee mark */
    struct text_table table;
    int64_t rows;
    /* --surfaces: a project option's rows per surface with it, the
     * surfaces of the run last met kept (names). */
    int surfaces;
    struct store *store;
    int64_t surfaces_run;
    struct surface_row *surface;
    size_t nsurfaces;
    struct facet_error err;
};

/* The rows per surface of option o of run (a project's: its module
 * known), the run's surfaces read once; *rows malloc'ed. Returns
 * non-zero with l->err set on a failure. */
static int surface_rows_of(struct listing *l, int64_t run,
                           const struct option_row *o,
                           struct option_surface_row **rows, size_t *n)
{
    *rows = NULL;
    *n = 0;
    if (isnan(o->module_w))
        return 0;
    if (l->surfaces_run != run) {
        free(l->surface);
        l->surface = NULL;
        l->nsurfaces = 0;
        l->surfaces_run = run;
        if (store_surfaces_get(l->store, run, &l->surface, &l->nsurfaces,
                               &l->err) != FACET_OK)
            return 1;
    }
    if (store_option_surfaces_get(l->store, run, o->number, rows, n,
                                  &l->err) != FACET_OK)
        return 1;
    if (*n != l->nsurfaces) {
        facet_error_set(&l->err, FACET_EINPUT,
            "run %lld option %lld: %zu surface rows for %zu surfaces",
            (long long)run, (long long)o->number, *n, l->nsurfaces);
        return 1;
    }
    return 0;
}

static int list_row(void *context, int64_t run, const struct option_row *o)
{
    struct listing *l = context;
    if (l->format == LISTING_TABLE) {
        char text[LISTED][OPTION_TABLE_CELL];
        const char *cell[LISTED + 1];
        option_table_cells(l->listed, LISTED, run, o, text, cell);
        cell[LISTED] = o->knee ? "knee" : "";
        text_table_row(stdout, &l->table, cell);
        if (l->surfaces) {
            struct option_surface_row *rows;
            size_t n;
            if (surface_rows_of(l, run, o, &rows, &n))
                return 1;
            if (n > 0) {
                surface_table_print(stdout, l->surface, rows, n);
                putchar('\n');
            }
            free(rows);
        }
    } else if (l->format == LISTING_JSON) {
        json_begin_object(&l->json);
        json_key(&l->json, "run");
        json_integer(&l->json, run);
        for (int k = 0; k < OPTION_QUANTITIES; k++) {
            const struct quantity *c = &option_quantities[k];
            if (c->writer == WRITTEN_AS_KEY)
                continue;
            double value = quantity_value(c, o);
            json_key(&l->json, c->name);
            if (!isfinite(value))
                json_null(&l->json);  /* crowding at a front's end */
            else if (c->yes_no)
                json_bool(&l->json, value != 0);  /* as classify --json */
            else if (value == floor(value) && fabs(value) < 1e15)
                json_integer(&l->json, (long long)value);
            else
                json_number(&l->json, value);
        }
        if (l->surfaces) {
            struct option_surface_row *rows;
            size_t n;
            if (surface_rows_of(l, run, o, &rows, &n))
                return 1;
            json_key(&l->json, "surfaces");
            if (n > 0)
                surface_table_json(&l->json, l->surface, rows, n);
            else
                json_null(&l->json);
            free(rows);
        }
        json_end_object(&l->json);
    } else {
        option_csv_row(stdout, run, o);
    }
    l->rows++;
    return 0;
}

/* The options as given (pointing into argv), NULL or 0 when absent. */
struct options_args {
    const char *run, *sort, *where, *limit;
    int pareto, desc, json, csv, wide, surfaces, mixed;
};

static const struct arg_option options_options[] = {
    {"run", 0, ARG_STRING, offsetof(struct options_args, run), "N",
     "only run N (default every run)", NULL},
    {"pareto", 0, ARG_FLAG, offsetof(struct options_args, pareto), NULL,
     "only Pareto-optimal options (rank 1)", NULL},
    {"sort", 0, ARG_STRING, offsetof(struct options_args, sort), "KEYS",
     "columns to sort by, e.g. cost,dp_area (default run, number); every "
     "feasible option comes first, each part sorted", NULL},
    {"desc", 0, ARG_FLAG, offsetof(struct options_args, desc), NULL,
     "sort descending (the feasible options still first)", NULL},
    {"infeasible-mixed", 0, ARG_FLAG,
     offsetof(struct options_args, mixed), NULL,
     "sort the infeasible options among the feasible ones, by the columns "
     "alone", NULL},
    {"where", 0, ARG_STRING, offsetof(struct options_args, where), "EXPR",
     "e.g. 'cost < 1.5e6 and dp_area <= 900 or pareto' (columns: see "
     "docs/store.md)", NULL},
    {"limit", 0, ARG_STRING, offsetof(struct options_args, limit), "N",
     "at most N options", NULL},
    {"surfaces", 0, ARG_FLAG, offsetof(struct options_args, surfaces), NULL,
     "a project's options with their rows per surface (table or --json: "
     "\"surfaces\")", NULL},
    {"json", 0, ARG_FLAG, offsetof(struct options_args, json), NULL,
     "one JSON array, every column", NULL},
    {"csv", 0, ARG_FLAG, offsetof(struct options_args, csv), NULL,
     "CSV with a header row, every column", NULL},
    {"wide", 0, ARG_FLAG, offsetof(struct options_args, wide), NULL,
     "every column of the table, whatever the terminal's width", NULL},
    {NULL, 0, ARG_FLAG, 0, NULL, NULL, NULL},
};

static int options_main(int argc, char **argv, struct facet_error *err)
{
    struct options_args a;
    memset(&a, 0, sizeof a);
    const struct arg_table own = {options_options, &a};
    const char *path;
    int rc = args_parse_one(argc, argv, &own, NULL, &path,
            "options: name the result database (facet options runs.db)", err);
    if (rc != FACET_OK)
        return rc;
    const char *run = a.run, *sort = a.sort, *where = a.where;
    const char *limit = a.limit;
    int pareto = a.pareto, desc = a.desc, json = a.json, csv = a.csv;
    int wide = a.wide, surfaces = a.surfaces;
    if (json && csv)
        return facet_error_set(err, FACET_EINPUT,
            "options: choose one of --json and --csv");
    if (surfaces && csv)
        return facet_error_set(err, FACET_EINPUT,
            "options --surfaces: a table or --json (a project's rows per "
            "surface are in its option_surfaces table for CSV)");
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
    listing.surfaces = surfaces;
    listing.store = store;
    if (rc == FACET_OK) {
        if (listing.format == LISTING_TABLE) {
            listing.listed[0] = (struct option_table_column){"run", 4, 2};
            memcpy(listing.listed + 1, option_table_paper,
                   sizeof option_table_paper);
            listing.listed[LISTED - 1] =
                (struct option_table_column){"feasible", 3, 4};
            if (run_id > 0 && store_run_is_project(&info))
                option_table_for_project(listing.listed, LISTED);
            option_table_heads(listing.listed, LISTED, listing.heads);
            listing.heads[LISTED] = (struct text_column){"", "", 4, 1, 6, 0};
            listing.table = (struct text_table){listing.heads, LISTED + 1,
                                                {0}, 0, 0};
            text_table_fit(&listing.table, text_table_width(stdout, wide));
            text_table_head(stdout, &listing.table);
        } else if (listing.format == LISTING_JSON) {
            json_init(&listing.json, stdout);
            json_begin_array(&listing.json);
        } else {
            option_csv_header(stdout);
        }
        struct option_query q = {run_id, pareto, filter, sort, desc, rows,
                                 0, !a.mixed};
        rc = store_options_query(store, &q, list_row, &listing, err);
        if (rc == FACET_OK && listing.err.code != FACET_OK) {
            *err = listing.err;
            rc = err->code;
        }
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
    free(listing.surface);
    store_close(store);
    filter_free(filter);
    return rc;
}

const struct command cmd_options = {
    .name = "options",
    .usage = "DB [--run N] [--pareto] [--sort KEY[,KEY]] [--desc]\n"
             "       [--infeasible-mixed] [--where EXPR] [--limit N] "
             "[--wide]\n"
             "       [--surfaces] [--json|--csv]",
    .summary = "List, filter and sort the design options of a result "
               "store.",
    .before = "",
    .options = options_options,
    .after = "examples:\n"
        "  facet options runs.db --run 1 --pareto --sort cost\n"
        "  facet options runs.db --where 'dp_area < 300 and feasible' "
        "--csv > cheap.csv\n",
    .run = options_main,
};
