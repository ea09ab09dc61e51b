/*
 * store.h: the SQLite result store. Every SQL string of Facet is in store/.
 *
 * One file holds any number of runs. A run records what produced it; every
 * design option it evaluated is a row with its variables and metrics; the
 * panels of the options a designer looks at (every Pareto option, and any
 * other on demand) are stored too. The schema is versioned (application_id,
 * user_version), in WAL mode with foreign keys on and a busy timeout, so a
 * reader (the TUI, sqlite3) and the writer coexist. docs/store.md documents
 * every table and column.
 *
 * Ownership: store_open returns a handle the caller releases with
 * store_close. Arrays a store_* function returns are malloc'ed and owned by
 * the caller (free(), or the named _free function).
 */
#ifndef FACET_STORE_H
#define FACET_STORE_H

#include <stddef.h>
#include <stdint.h>

#include "core/classify/classify.h"
#include "core/quantity/option_row.h"
#include "core/base/error.h"
#include "core/panel/panel.h"
#include "core/search/optimize.h"
#include "core/surface/mesh.h"
#include "core/surface/param.h"
#include "core/quantity/quantity.h"

struct store;  /* an open database */

/* How a run stands: being written, finished, stopped (resumable) or
 * failed (resumable). Kept as text in runs.status, whose CHECK lists the
 * names run_status_name gives; the text is read and written only here, at
 * the SQL boundary, and compared nowhere else. */
enum run_status { RUN_RUNNING, RUN_DONE, RUN_INTERRUPTED, RUN_FAILED };

/* "running", "done", "interrupted", "failed". */
const char *run_status_name(enum run_status status);
/* The status named text into *out: 0, or -1 when text names none. */
int run_status_parse(const char *text, enum run_status *out);

/* Whose panels a run stores at the end; the others are computed when
 * shown or exported. Here, not in study/, because the store records it. */
enum study_keep_panels {
    KEEP_FRONT,  /* every Pareto option's */
    KEEP_KNEE,   /* the knee's alone */
    KEEP_NONE
};

/* "front", "knee", "none", as runs.store_panels keeps them. */
const char *study_keep_panels_name(enum study_keep_panels keep);
/* The choice named text into *out; FACET_EINPUT naming the field what
 * (the caller's name for it) and the choices. */
int study_keep_panels_parse(const char *text, const char *what,
                            enum study_keep_panels *out,
                            struct facet_error *err);

/* The settings runs keeps by name (its columns units, method, per_panel,
 * uv_method, uv, store_panels). The names are turned into the enums of
 * struct run_info here, in the store, and nowhere else. A column whose
 * text names nothing this Facet knows (a newer Facet's name, or one
 * written by hand) is not guessed: run_info.unknown keeps its text. */
enum run_setting {
    RUN_SETTING_UNITS, RUN_SETTING_METHOD, RUN_SETTING_PER_PANEL,
    RUN_SETTING_UV_METHOD, RUN_SETTING_UV, RUN_SETTING_STORE_PANELS,
    RUN_SETTINGS
};

/* What produced a run, and how it went. Text fields are NUL-terminated. */
struct run_info {
    int64_t id;
    char name[128];
    char surface_path[1024];
    char surface_sha256[65];   /* hex digest of the OBJ file's bytes */
    double surface_area;       /* m^2 of the selected part */
    int64_t triangles;         /* after triangulation */
    enum param_method uv_method; /* taken; PARAM_AUTO for a run of a
                                  Facet that did not record it */
    enum param_method uv;      /* asked for; PARAM_AUTO for automatic */
    enum study_keep_panels store_panels; /* whose panels it stores at the
                                  end */
    /* Per enum run_setting: the column's text when it names nothing this
     * Facet knows (the field then holds its first value, which must not
     * be used: store_run_setting_check), "" when it was read. */
    char unknown[RUN_SETTINGS][32];
    char warnings[1400];       /* what the run warned of when it began
                                  (the surface's warnings and a mesh coarser
                                  than the space's finest panels), one per
                                  line; "" for none */
    enum mesh_units units;     /* what one OBJ unit is */
    enum optimize_method method;
    uint64_t seed;
    int u_min, u_max;          /* design space: grid sides */
    int v_min, v_max;
    double threshold_min_mm;   /* flatness threshold range (mm) */
    double threshold_max_mm;
    double threshold_step_mm;  /* 0 for a continuous range (nsga2, random) */
    double price[TYPE_COUNT];  /* USD/m^2 of FP, SP, DP */
    int sp_as_fp;
    double max_panel_area;     /* m^2 */
    double curvature_tol;      /* 1/m; 0 for 8 t / d^2 */
    enum panel_curvature_mode per_panel;
    int flip_normals;
    char object[128];          /* --object, or "" */
    char group[128];           /* --group, or "" */
    char objectives[128];      /* e.g. "cost,planarity,dp_area" */
    int population;            /* nsga2 */
    int generations;           /* nsga2 */
    int64_t evaluations;       /* random: --evals */
    int jobs;
    char version[16];          /* Facet's version */
    enum run_status status;
    char started[32];          /* UTC, ISO 8601 */
    char finished[32];         /* "" while running */
    int64_t options;           /* options evaluated and stored */
    double elapsed;            /* seconds of work */
    int64_t writer_pid;        /* process writing it, while running */
    char writer_host[64];
    double hypervolume;        /* of the Pareto front, normalised; NaN if
                                  not computed */
    int64_t knee;              /* option number of the knee, or 0 */
    int64_t pareto_options;    /* options of rank 1 */
    double best_cost;          /* lowest cost of a feasible option (USD) */
    /* The cost model beyond area (classify.h), 0 for the paper's: */
    double panel_cost;         /* USD per panel */
    double joint_cost;         /* USD per metre of joint */
    double mould_cost[TYPE_COUNT];  /* USD per mould of SP, DP; FP 0 */
    double mould_tol_mm;       /* mould tolerance (mm); NaN: each option's
                                  flatness threshold */
    int mould_mirror;          /* mirror images share a mould */
    /* Panels as built (option.h; schema v7): */
    int sp_fit;                /* 1: an SP panel no cylinder or cone fits
                                  is built DP; 0: SP by class alone (the
                                  paper's typing, and every run before) */
    double max_gap_mm;         /* gap limit on feasibility (mm); NaN: none */
    double max_kink_deg;       /* kink limit (degrees); NaN: none */
    double min_panel_width;    /* width limit on every panel (m,
                                  panel_width.h; schema v12); NaN: none */
    double planarize_closeness_mm;  /* the closeness budget its planarized
                                  options were held to (mm, schema v14,
                                  core/planar/planar_option.h); NaN: the
                                  run made none */
    double weld_mm;            /* the welding tolerance a building's seams
                                  were found at (mm, schema v15,
                                  core/project/seam.h); NaN: a single
                                  surface, or a run before seams */
    /* What every option of the run was measured for beyond its classed
     * panels (option.h's option_measure bits; schema v9): what its
     * objectives, limits and prices read, or all of them. Its Pareto
     * options are measured in full. OPTION_MEASURE_ALL for every run
     * before. */
    unsigned measured;
    /* Spread over machines (core/search/shard.h): a shard is shard_index
     * of shard_count; a merge of shards has shard_index 0, shard_count N
     * and shards_merged of them (incomplete when fewer than N); every
     * other run 0, 0, 0. */
    int shard_index, shard_count, shards_merged;
    /* A project run (schema v8): the module range it searched (m;
     * module.h); NaN for a run of a single surface. Its u and v ranges
     * are then the width and height indices it walks. */
    double module_w_min, module_w_max, module_w_step;
    double module_h_min, module_h_max, module_h_step;
};

/* Whether run is a project's (a building of surfaces). */
int store_run_is_project(const struct run_info *run);

/* Whether run is a merge that lacks some of its shards. */
int store_run_incomplete(const struct run_info *run);

/* What a listing shows for run's status, into text (size bytes, 16 are
 * enough): "incomplete" for a merge that lacks shards (its status says it
 * finished, not that it is whole), the status and "I/N" for a shard
 * ("done 2/4"), else run_status_name. Returns text. */
const char *store_run_status_text(const struct run_info *run, char *text,
                                  size_t size);

/* What a listing shows for the welding tolerance a building's run found
 * its seams at, into text (size bytes): its mm ("%g"), or "-" where it
 * has none (a single surface, or a building before schema v15), never 0.
 * Returns text. */
const char *store_run_weld_text(const struct run_info *run, char *text,
                                size_t size);

/* FACET_OK when run's setting was read from the file; FACET_EINPUT when
 * its column names nothing this Facet knows, with a one-line message
 * naming the run, the column and the value. A run is neither resumed nor
 * evaluated with a setting guessed in its place. */
int store_run_setting_check(const struct run_info *run,
                            enum run_setting setting,
                            struct facet_error *err);

/* How run's setting reads in a listing: its name as the column holds it
 * ("" for an automatic UV), or the column's own text when that names
 * nothing this Facet knows (a listing still shows every run). */
const char *store_run_setting_text(const struct run_info *run,
                                   enum run_setting setting);

/* Every open below treats the file as anyone's: SQLite is set up so that
 * no SQL of the file's own runs (no trigger fires, no view is read, the
 * schema may call innocuous functions only), and a file whose schema is
 * not Facet's own of its version (a trigger, a view Facet did not make,
 * a view where Facet keeps a table, a column changed, added or missing)
 * is FACET_EINPUT naming the file and the first difference, before
 * anything is read or written (store_schema_check). */

/* Opens or creates the database at path, for writing. A new file gets the
 * current schema; an older Facet schema is migrated; a file of another
 * application, a newer schema, or a corrupt file is FACET_EINPUT with a
 * message naming the file and what is wrong. Runs left "running" by a
 * writer that is gone (same host, process not alive) are marked
 * "interrupted". For the commands that write runs (optimize, merge). */
int store_open(const char *path, struct store **out, struct facet_error *err);

/* store_open, but a file of an older schema is refused as
 * store_open_read refuses it, not migrated: for the workbench, opened to
 * look before anything is written (a new file is still created). */
int store_open_current(const char *path, struct store **out,
                       struct facet_error *err);

/* Brings the existing database at path to the current schema, as a
 * writer, and closes it: *from gets the version it had (the current one:
 * nothing was done). FACET_EINPUT when there is no such file, it may not
 * be written, or it is not Facet's. The only way, with store_open, that
 * an existing file's schema changes. */
int store_migrate(const char *path, int *from, struct facet_error *err);

/* Opens the database at path for reading only, for the commands that only
 * read (runs, options, plot): a missing path is FACET_EINPUT ("no such
 * database") and nothing is created; the file is opened read-only, as
 * immutable media when its folder is read-only (no -shm can be made
 * there). A file of an older schema is FACET_EINPUT about
 * FACET_SETTING_MIGRATE, and left as it is: reading never migrates. A run
 * left "running" by a writer that is gone reads as "interrupted" (nothing
 * is written). */
int store_open_read(const char *path, struct store **out,
                    struct facet_error *err);

/* Opens an existing database (FACET_EINPUT when there is none) for
 * writing when it may be written, else as store_open_read: for commands
 * that store what they compute only if they can (show, export). A file of
 * an older schema is refused as store_open_read refuses it. */
int store_open_existing(const char *path, struct store **out,
                        struct facet_error *err);

/* The schema version this Facet reads and writes (PRAGMA user_version). */
int store_schema_version(void);

/* 1 when store was opened read-only: nothing can be stored. */
int store_read_only(const struct store *store);

/* The file's path, as given to the open call. */
const char *store_path(const struct store *store);

void store_close(struct store *store);

/* Refreshes the statistics SQLite plans queries with (a bounded ANALYZE,
 * 0.07 s on a million options), so that a filter on nu
 * or nv reads its index instead of the whole run. A writer calls it when a
 * run ends. */
int store_analyze(struct store *store, struct facet_error *err);

/* Reads every page of the file (PRAGMA quick_check): FACET_EINPUT naming
 * the file when it is damaged. A writer calls it before adding to a file,
 * so that nothing is written into a database that is already broken; it
 * takes time in proportion to the file's size (0.9 s for a million
 * options). */
int store_check(struct store *store, struct facet_error *err);

/* Makes a writer's file hold everything itself, for a file about to take
 * another's place: every page of the WAL moved into it (a checkpoint that
 * must complete, the WAL then empty), then read whole (store_check).
 * FACET_EWORK naming the file when the checkpoint cannot finish (a full
 * disk), FACET_EINPUT when the file reads as damaged; either way its WAL
 * still holds what the file lacks and must not be deleted. */
int store_seal(struct store *store, struct facet_error *err);

/* --- runs --- */

/* Inserts run (id, started, status RUN_RUNNING, writer pid/host are set here
 * and written back into *run). */
int store_run_create(struct store *store, struct run_info *run,
                     struct facet_error *err);
/* Fills *run for id; FACET_EINPUT when there is no such run. */
int store_run_get(struct store *store, int64_t id, struct run_info *run,
                  struct facet_error *err);
/* Every run, by id; *runs is malloc'ed (free()). */
int store_run_list(struct store *store, struct run_info **runs,
                   size_t *count, struct facet_error *err);
/* Takes run id over for --resume, in one write transaction with the
 * checks: FACET_EINPUT when it is done, or running with its writer alive
 * (named: pid, host); otherwise its status becomes RUN_RUNNING with this
 * process as its writer, and *run holds it as it was read. */
int store_run_claim(struct store *store, int64_t id, struct run_info *run,
                    struct facet_error *err);

/* Fills *run with a run of the file other than except (0: any) that a
 * Facet still there is writing (status running, its writer alive on this
 * host, or on another host, where it cannot be told), and sets *live;
 * *live 0 when there is none. Whoever would replace the file (facet merge)
 * asks first: the writer would go on into the file replaced, and its work
 * be lost; a run that dropped the indexes asks before building them. */
int store_run_live_writer(struct store *store, int64_t except,
                          struct run_info *run, int *live,
                          struct facet_error *err);

/* Records path as run id's surface (study_repoint_surface checks it). */
int store_run_set_surface(struct store *store, int64_t id, const char *path,
                          struct facet_error *err);

/* Sets status (and finished when not RUN_RUNNING), elapsed and the
 * options count. Taking a run over to resume it: RUN_RUNNING with this
 * process as its writer. */
int store_run_set_status(struct store *store, int64_t id,
                         enum run_status status,
                         double elapsed, struct facet_error *err);
/* --- shards and merges (store_shard.c) --- */

/* Writes run's shard_index, shard_count and shards_merged (0 is NULL in
 * the file) and its warnings: what a merge records of its shards. */
int store_run_set_shard(struct store *store, const struct run_info *run,
                        struct facet_error *err);

/* Checks that the shard run (read from store) holds what a shard made by
 * Facet holds, before a merge takes its options: its index within its
 * count, as many options as its run recorded, and every value of every
 * option of the type and range its column takes (a number where a number
 * goes, finite, counts and areas not negative, a grid within the grid's
 * bounds). FACET_EINPUT naming the file, the shard and the first option
 * and column that do not add up; a value a reader would take as 0 or a
 * NOT NULL insert would drop is never merged. */
int store_shard_check(struct store *store, const struct run_info *run,
                      struct facet_error *err);

/* Deletes every option of run (and their panels), keeping the run: a
 * merge made again refills the run it made before. */
int store_run_clear_options(struct store *store, int64_t run,
                            struct facet_error *err);

/* Writes a copy of the whole database to path, a file that must not
 * exist or be empty (SQLite's VACUUM INTO): a consistent snapshot, WAL
 * included, that a merge adds to before it takes the original's place. */
int store_copy(struct store *store, const char *path,
               struct facet_error *err);

/* Deletes a run with its options and panels. */
int store_run_delete(struct store *store, int64_t id,
                     struct facet_error *err);

/* --- options --- */

/* Stores n options of run in one transaction (committed on return), and
 * updates the run's options count. An option whose number is already
 * stored is left as it is. */
int store_options_put(struct store *store, int64_t run,
                      const struct option_row *rows, size_t n,
                      struct facet_error *err);
/* Writes the values of rows[0..n), options of run already stored, over
 * theirs, in one transaction: for options measured in full after the run
 * measured them for what it reads (its Pareto options; option.h). Their
 * rank, crowding and knee stay. */
int store_options_measured(struct store *store, int64_t run,
                           const struct option_row *rows, size_t n,
                           struct facet_error *err);
/* Every option of run, by number; *rows malloc'ed (free()). */
int store_options_get(struct store *store, int64_t run,
                      struct option_row **rows, size_t *n,
                      struct facet_error *err);
/* How many of a run's Pareto options sit on each bound of its design
 * space, in the order of enum front_bound. */
enum front_bound { BOUND_U_MIN, BOUND_U_MAX, BOUND_V_MIN, BOUND_V_MAX,
                   BOUND_T_MIN, BOUND_T_MAX, FRONT_BOUNDS };
struct front_bounds {
    int64_t pareto;              /* options of rank 1 */
    int64_t at[FRONT_BOUNDS];
};
int store_front_bounds(struct store *store, int64_t run,
                       struct front_bounds *out, struct facet_error *err);

/* Option number of run into *row; FACET_EINPUT when there is none. */
int store_option_get(struct store *store, int64_t run, int64_t number,
                     struct option_row *row, struct facet_error *err);
/* Writes Pareto rank, crowding and the knee flag of every option given
 * (numbers[k] gets rank[k], crowding[k]), and the run's hypervolume,
 * knee, pareto_options, best_cost and options (its count of stored
 * options), in one transaction. */
int store_options_set_pareto(struct store *store, int64_t run,
                             const int64_t *numbers, const int *rank,
                             const double *crowding, size_t n, int64_t knee,
                             double hypervolume, struct facet_error *err);

/* --- a run of many options (store_index.c) --- */

/* Runs expected to store at least this many options store them with the
 * indexes by metric dropped (store_indexes_defer). */
#define STORE_BULK_ROWS 50000

/* Before a run stores about rows options: when they are many
 * (STORE_BULK_ROWS or more) and at least as many as the file holds
 * already, drops the options table's indexes by metric (all but the one
 * by rank), so that an option is written once, not into thirteen B-trees
 * at random places (a million options: 5,000 a second with them). Sets
 * *deferred when it did; the writer must then call store_indexes_build
 * when the run ends, however it ends. Queries give the same rows
 * meanwhile, reading the table instead of an index (a reader sorting a
 * million options of a live run by cost reads them all). */
int store_indexes_defer(struct store *store, int64_t rows, int *deferred,
                        struct facet_error *err);

/* Builds the indexes by metric that are missing, each from the whole
 * table in one transaction of its own (about a second a million options
 * each), unless a run other than writing_run (0: none) is being written
 * by a live writer, which builds them when it ends. *built (may be NULL)
 * is set when any was built: statistics are then due (store_analyze).
 * store_open calls it, so a file whose writer was killed while they were
 * dropped gets them back when its run is marked interrupted. */
int store_indexes_build(struct store *store, int64_t writing_run,
                        int *built, struct facet_error *err);

/* The name of index k of those by metric, k from 0; NULL past the last
 * (for tests that check the file against the list). */
const char *store_metric_index_name(size_t k);

/* --- projects (store_project.c) --- */

/* A surface of a project run (the surfaces table). */
struct surface_row {
    char name[256];
    char file[1024];           /* absolute path */
    char file_sha256[65];
    int64_t triangles;
    double area;               /* m^2 */
    double u_length, v_length; /* m */
    enum param_method uv_method;
    int grid_nu, grid_nv;      /* its own grid whatever the module; 0 for
                                  none */
};

/* One surface's part of an option of a project run (option_surfaces). */
struct option_surface_row {
    int nu, nv;
    struct option_totals totals;  /* that surface's (project_option.h) */
    int64_t moulds_used;          /* families its panels belong to */
    int64_t joints;               /* joints measured on it */
};

/* Stores rows[0..n) as run's surfaces 0..n-1, in one transaction. */
int store_surfaces_put(struct store *store, int64_t run,
                       const struct surface_row *rows, size_t n,
                       struct facet_error *err);
/* run's surfaces in order into *rows (malloc'ed, free()); *n 0 for a run
 * of a single surface. */
int store_surfaces_get(struct store *store, int64_t run,
                       struct surface_row **rows, size_t *n,
                       struct facet_error *err);

/* store_options_put for a project run: with each option rows[k], its
 * nsurfaces surface rows surfaces[k * nsurfaces .. (k + 1) * nsurfaces),
 * all in the one transaction, so that an option is never stored without
 * them. An option already stored is left as it is, its surface rows too. */
int store_project_options_put(struct store *store, int64_t run,
                              const struct option_row *rows, size_t n,
                              const struct option_surface_row *surfaces,
                              size_t nsurfaces, struct facet_error *err);

/* The surface rows of option number of run, in surface order, into
 * *rows (malloc'ed, free()); *n 0 when it has none (a single surface's
 * option). */
int store_option_surfaces_get(struct store *store, int64_t run,
                              int64_t number,
                              struct option_surface_row **rows, size_t *n,
                              struct facet_error *err);

/* --- panels --- */

/* Stores the panels of option number of run (replacing any stored). */
int store_panels_put(struct store *store, int64_t run, int64_t option,
                     const struct panelization *panels,
                     struct facet_error *err);
/* store_panels_put, asking stop (core/base/stop.h) every few thousand
 * panels: when it asks, nothing of the option's panels is stored (the
 * transaction is rolled back; any set stored before stays) and it
 * returns FACET_ESTOP. */
int store_panels_put_stoppable(struct store *store, int64_t run,
                               int64_t option,
                               const struct panelization *panels,
                               const struct facet_stop *stop,
                               struct facet_error *err);
/* Sets *stored to 1 when panels of that option are stored, 0 when not.
 * Returns FACET_OK, or FACET_EINPUT (a damaged or busy file) or FACET_EWORK
 * with err naming the file and what SQLite refused (*stored is then 0). */
int store_panels_exist(struct store *store, int64_t run, int64_t option,
                       int *stored, struct facet_error *err);
/* Reads the stored panels back into *panels (nu, nv, cell_panel and the
 * panel fields the panels table holds); release with panelization_free. */
int store_panels_get(struct store *store, int64_t run, int64_t option,
                     struct panelization *panels, struct facet_error *err);

/* --- queries (facet options, the TUI) --- */

/* A compiled --where expression: see filter.h. */
struct filter;

struct option_query {
    int64_t run;               /* 0 = every run */
    int pareto_only;           /* rank 1 only */
    const struct filter *where;/* NULL = no filter */
    const char *sort;          /* "cost,dp_area" (column names), NULL =
                                  number */
    int descending;
    int64_t limit;             /* 0 = no limit */
    int64_t offset;
    int feasible_first;        /* sorted (sort given): every feasible
                                  option before every other one (infeasible,
                                  or not measured yet), each part in the
                                  order of the columns, whatever their
                                  direction; 0: feasibility is no key */
};

/* Calls row(context, run, option) for each option that matches q, in
 * order; stops early when row returns non-zero. Sorted by columns (after
 * feasibility, with feasible_first), values
 * of a column equal but for rounding tie (core/search/ties.h, the column's
 * tolerance over q's run, or over every run) and fall to the next column,
 * then to run and number; limit and offset count in that order. (SQL
 * orders by the exact values; each tie class of the first column is
 * gathered from that order and ordered in C, so memory grows with the
 * largest class, not with the rows.) Unknown sort columns are
 * FACET_EINPUT naming the column and listing the valid ones. */
int store_options_query(struct store *store, const struct option_query *q,
                        int (*row)(void *context, int64_t run,
                                   const struct option_row *option),
                        void *context, struct facet_error *err);

/* The options that match q, in order, into *rows (malloc'ed, free()),
 * *n of them. */
int store_options_query_rows(struct store *store,
                             const struct option_query *q,
                             struct option_row **rows, size_t *n,
                             struct facet_error *err);

/* Checks a sort list ("cost,dp_area") as store_options_query would, so a
 * caller can refuse it before printing anything. */
int store_options_sort_check(const char *sort, struct facet_error *err);

/* The columns of an option (their names, what a sort or filter may name,
 * how each is shown, and store_option_value) are the registry of
 * core/quantity/quantity.h, which this header includes. */

/* --- browsing one run (the TUI): keyset pages, counts, ranges ---
 * These serve a table that shows a page of a million options at a time:
 * no call reads more rows than it returns, except counts and ranges, which
 * scan the run's rows once (SQLite's count(*) and min/max, no rows built). */

/* One sort key: a column of option_quantities (not run), ascending
 * unless descending. */
struct browse_key {
    const char *column;
    int descending;
};

#define BROWSE_MAX_KEYS 3

/* What a browse sees: one run's options, filtered, in the order of keys
 * (after feasibility, with feasible_first) then number ascending (so
 * every option has one place). */
struct option_browse {
    int64_t run;               /* > 0 */
    int pareto_only;           /* rank 1 only */
    const struct filter *where;/* NULL = every option */
    struct browse_key keys[BROWSE_MAX_KEYS];
    int nkeys;                 /* 0 = by number */
    int filter_first;          /* the filter passes few options: find them
                                  by the filter's own index (or a scan) and
                                  sort them, instead of walking the order's
                                  index past rows that fail it;
                                  BROWSE_SCAN: read every row of the run
                                  by number, filter and sort them (what a
                                  page falls back to, store_browse_page) */
    int feasible_first;        /* with keys: every feasible option before
                                  every other one (infeasible, or not
                                  measured yet), each part in the order of
                                  keys; a page is read part by part, each
                                  by the index of its first key */
    int feasible_part;         /* 0: every option; 1: the feasible ones
                                  only; -1: the others. How the store
                                  reads one part of a feasible_first
                                  browse; a caller may ask for one too */
};

#define BROWSE_SCAN 2


/* Calls row(context, option) for up to limit options of b that come after
 * *after in b's order (after NULL: from the first), or, backward, for
 * those before *after (after NULL: from the last) nearest first, so the
 * caller receives them in reverse order. Stops early when row returns
 * non-zero. Unknown columns are FACET_EINPUT naming the column. A filter
 * that fails the rows of a long stretch of the order is not walked for
 * more than 20 ms: the page is then read by a scan of the run (0.3 s a
 * million options, instead of seconds of lookups). */
int store_browse_page(struct store *store, const struct option_browse *b,
                      const struct option_row *after, int backward,
                      int64_t limit,
                      int (*row)(void *context,
                                 const struct option_row *option),
                      void *context, struct facet_error *err);

/* The options of b in its order from position offset (0-based), for a
 * jump far from what the caller holds. */
int store_browse_offset(struct store *store, const struct option_browse *b,
                        int64_t offset, int64_t limit,
                        int (*row)(void *context,
                                   const struct option_row *option),
                        void *context, struct facet_error *err);

/* How many options b sees into *count. */
int store_browse_count(struct store *store, const struct option_browse *b,
                       int64_t *count, struct facet_error *err);

/* How many options of b come after *after in b's order (after NULL:
 * every option; backward: before *after), counting no further than cap,
 * into *count: a count of cap means "cap or more". It reads at most the
 * cap matching rows (and the rows that fail the filter among them), so
 * it is the cheap count a table shows first ("10,000+"). */
int store_browse_count_capped(struct store *store,
                              const struct option_browse *b,
                              const struct option_row *after, int backward,
                              int64_t cap, int64_t *count,
                              struct facet_error *err);

/* The last options of a browse's order, gathered by the steps of a count
 * (store_browse_count_step): their numbers, the last first, n of them. */
#define BROWSE_TAIL 200
struct browse_tail {
    int64_t numbers[BROWSE_TAIL];
    int n;
};

/* One slice of an exact count in steps: looks at the next at most rows
 * options of b's run by number after number *from (0: from the first),
 * adds those b sees to *count and sets *from to the last number looked
 * at; *done is set when no option is left after it. The cost of a step
 * is bounded by rows, so a caller can count a million options between
 * keystrokes. With tail (NULL: none; n 0 before the first step) the step
 * also keeps the last BROWSE_TAIL options of b's order seen so far, so
 * that when the count is done, so is the table's last page (a filter's
 * last page otherwise reads the whole run: store_browse_page). */
int store_browse_count_step(struct store *store,
                            const struct option_browse *b, int64_t rows,
                            int64_t *from, int64_t *count, int *done,
                            struct browse_tail *tail,
                            struct facet_error *err);

/* How many options of b come before *option in b's order (its 0-based
 * position when b sees it) into *position. */
int store_browse_position(struct store *store,
                          const struct option_browse *b,
                          const struct option_row *option,
                          int64_t *position, struct facet_error *err);

/* The least and greatest value of column over the options b sees; both
 * NaN when it sees none. */
int store_browse_range(struct store *store, const struct option_browse *b,
                       const char *column, double *min, double *max,
                       struct facet_error *err);

/* A sample of b for a plot: every option when stride <= 1, else the
 * options whose number is a multiple of stride and every option of rank
 * 1, by number; at most limit (0 = no limit). */
int store_browse_sample(struct store *store, const struct option_browse *b,
                        int64_t stride, int64_t limit,
                        int (*row)(void *context,
                                   const struct option_row *option),
                        void *context, struct facet_error *err);

/* Statistics of one column over the options a browse sees. */
struct column_stats {
    int64_t count;               /* options with a value (NULLs left out) */
    double min, median, max, mean;  /* NaN when count is 0; the median of
                                       an even count is the mean of the two
                                       middle values */
};

/* The count, min, max and mean of columns[0..n) (names of
 * option_quantities other than run) over the options b sees into
 * out[0..n), in one aggregate query over b's rows (one read of the run);
 * the medians are left NaN for store_browse_median. Unknown columns are
 * FACET_EINPUT. */
int store_browse_stats(struct store *store, const struct option_browse *b,
                       const char *const *columns, int n,
                       struct column_stats *out, struct facet_error *err);

/* The median of column over the options b sees, count of which have a
 * value (store_browse_stats), into *median: the middle value, or the mean
 * of the two middle ones. Without a filter a column with an index is read
 * from the middle of its index (0.03 s on a million options); otherwise
 * b's rows are read once and sorted (0.7 s for 420,000 of a million). */
int store_browse_median(struct store *store, const struct option_browse *b,
                        const char *column, int64_t count, double *median,
                        struct facet_error *err);

/* The runs a browse reads whole for their medians at once
 * (store_browse_medians): up to this many options, 8 bytes a value. */
#define STORE_MEDIANS_AT_ONCE 200000

/* The medians of columns[0..n) over the options b sees into out[k].median
 * (out from store_browse_stats: its counts say how many values each has),
 * as store_browse_median gives each, to the bit: b's rows are read once,
 * every column's values kept and sorted in memory (a run of 10,000
 * options: one read instead of a sort by SQLite per column). For runs of
 * at most STORE_MEDIANS_AT_ONCE options; FACET_EINPUT for an unknown
 * column, FACET_EWORK when out of memory. */
int store_browse_medians(struct store *store, const struct option_browse *b,
                         const char *const *columns, int n,
                         struct column_stats *out, struct facet_error *err);

/* The options of b that share one value of a column (a frequency table's
 * row). */
struct option_group {
    double value;                /* the column's value; binned: the bin's
                                    lower end */
    int64_t options;             /* options in the group */
    int64_t pareto;              /* of them, of rank 1 */
    int64_t feasible;            /* of them, feasible */
    double min_cost;             /* USD; NaN when the group has none */
    double min_planarity;        /* m */
    double min_dp_area;          /* m^2 */
};

/* The options b sees grouped by column's value (bin > 0: by
 * floor(value / bin) x bin), by value ascending, NULLs left out, into
 * *groups (malloc'ed, free()), *n of them. b's rows are read once in
 * the table's order and sorted by the group (0.8 s for a million
 * options; walking the column's index would look each row up). */
int store_browse_groups(struct store *store, const struct option_browse *b,
                        const char *column, double bin,
                        struct option_group **groups, size_t *n,
                        struct facet_error *err);

/* Per panel class, over the options b sees: how many options have a
 * panel of it, and its panels and m^2 summed over them all. */
struct class_frequency {
    int64_t options;
    int64_t panels;
    double area;
};

int store_browse_classes(struct store *store, const struct option_browse *b,
                         struct class_frequency out[CLASS_COUNT],
                         struct facet_error *err);

/* --- the extent of a column over a run (store_column_range.c) --- */

/* The least and greatest value of column (a name of option_quantities
 * other than run) over every option of run, NULLs left out, each read
 * from one end of the column's index where it has one; both NaN when the
 * run has none. Unknown columns are FACET_EINPUT. */
int store_run_column_range(struct store *store, int64_t run,
                           const char *column, double *min, double *max,
                           struct facet_error *err);

#endif
