/*
 * study.h: an optimisation run from start to finish, written through the
 * store: what `facet optimize` and the TUI's New run both do.
 *
 * A study opens and prepares the surface, records the run, lets the
 * optimiser (core/search/optimize.h) evaluate the design space and commits
 * every batch as soon as it is evaluated, then ranks the options
 * (core/search/front.h), stores the panels of the Pareto options, and marks
 * the run done. When the stop hook fires it ranks what was stored and marks
 * the run interrupted; on an error, failed. Resuming reads the run back,
 * checks that the surface file is the one the run was made from, and goes
 * on: nothing stored is evaluated again, and the finished run has the
 * options an uninterrupted one would have.
 */
#ifndef FACET_STUDY_H
#define FACET_STUDY_H

#include "core/project/module.h"
#include "core/project/project_grids.h"
#include "core/surface/mesh.h"
#include "core/search/optimize.h"
#include "core/surface/surface.h"
#include "store/store.h"

struct study_hooks {
    void *context;
    /* What the study is doing now ("preparing the surface", ...). */
    void (*stage)(void *context, const char *what);
    /* Options done (stored or reused) of total, and their work
     * (optimize.h's struct optimize_progress). */
    void (*progress)(void *context, const struct optimize_progress *p);
    /* Non-zero when the user asked to stop; checked between batches, and
     * every few milliseconds while the surface is read and prepared and
     * while options are evaluated, from several threads at once
     * (core/base/stop.h): it must be cheap and thread-safe. */
    int (*should_stop)(void *context);
    /* The run's id, once it is recorded (the TUI follows it live). */
    void (*started)(void *context, int64_t run);
    /* One thing the designer must know before trusting the run's numbers
     * (a surface warning, a mesh coarser than the finest panels), as it
     * is found; the same lines are stored with the run (runs.warnings).
     * NULL: not told. */
    void (*warning)(void *context, const char *text);
    /* Something the user may like to know that does not bear on the
     * numbers (a prepared building reused from its cache, or why it was
     * prepared again), told once, not stored. NULL: not told. */
    void (*note)(void *context, const char *text);
};

/* What a new run is made of. */
struct study_request {
    const char *surface_path;
    /* A project (core/project/project.h): its files (nfiles of them, the
     * first surface_path's), searched over the panel modules of module
     * (module.h; the space's u and v study_project_space's). nfiles 0: a
     * single surface, surface_path, as it always was; a file that names
     * several objects (or groups) is then refused unless mesh selects
     * one: a project needs a module. */
    const char *const *files;
    size_t nfiles;
    struct module_range module;
    double weld;                     /* a project's welding tolerance (m,
                                        SEAM_WELD_MIN .. SEAM_WELD_MAX):
                                        its seams are found at it once
                                        prepared (project_seams.h) */
    /* Per surface of the project, by name: a grid of its own whatever
     * the module (nu 0: none); noverrides of them. */
    const char *const *override_names;
    const struct surface_grid *overrides;
    size_t noverrides;
    struct mesh_options mesh;        /* units, object, group */
    int units_named;                 /* the user named mesh.units: a single
                                        surface of no building's size is
                                        then read as asked (with its
                                        warning), not refused
                                        (surface_units_check) */
    int flip_normals;
    enum param_method uv;            /* asked for; PARAM_AUTO: the first
                                        that applies */
    struct optimize_settings settings;
    const char *name;                /* "" for none */
    enum study_keep_panels store_panels;
    int measure_all;                 /* every option measured in full, not
                                        only for what the run reads
                                        (optimize_measures_needed) */
    double planarize_closeness;      /* > 0: the front's grids planarized
                                        within this budget (m), their
                                        planarized options stored beside
                                        the classified ones (issue 33,
                                        study_planar.c); 0: none */
};

/* What a new run takes when its user does not say, the one policy of
 * `facet optimize` and the TUI's New run: the paper's design space (u
 * 20:40, v 35:50 panels, a 3 mm threshold), the method study_auto_method
 * gives for it, seed 1, 1000 random evaluations, NSGA-II with 100 x 50
 * generations, the objectives cost, planarity and dp_area, the paper's
 * classification and prices (option_params_defaults), metres, UV the
 * first that applies, every core, the front's panels stored, no name and
 * no surface. A caller that changes the space asks study_auto_method
 * again when its user left the method to it. */
void study_request_defaults(struct study_request *request);

/* What storing costs on disk, as measured (a 680,000-panel front: 303
 * bytes a panel; a million options: 350 bytes each, indexes included),
 * with a margin: what a run checks the free space against before it
 * starts, and before it stores its front's panels. */
#define STUDY_PANEL_BYTES 320
#define STUDY_OPTION_BYTES 400

/* How many Pareto options' panels a run of options options stores when it
 * ends (store_panels front): one option in STUDY_FRONT_SHARE of the run's,
 * and at least STUDY_FRONT_MIN. Storing a panel set evaluates its option
 * again and writes its panels, about three evaluations' worth as the
 * search runs them (tests/bench/bench_front.c), so the end of a large run
 * takes under a tenth of it (issue 18); a small run's front, such as the
 * paper study's 12 options, is stored whole. A larger front stores the knee,
 * then the options of the largest crowding distance (its ends first: the
 * most spread of it); the others' panels are computed, and stored, when
 * first looked at (study_option_panels: facet show, facet export, the
 * TUI's map). */
#define STUDY_FRONT_SHARE 40
#define STUDY_FRONT_MIN 16
size_t study_front_budget(int64_t options);

/* The largest space the automatic method searches exhaustively; a larger
 * one, or a continuous threshold range, goes to NSGA-II. */
#define STUDY_EXHAUSTIVE_LIMIT 100000

/* The method "auto" (or no method given) means for space: exhaustive up
 * to STUDY_EXHAUSTIVE_LIMIT points with a stepped (or single) threshold,
 * NSGA-II otherwise. The CLI and the TUI's New run both ask this. */
enum optimize_method study_auto_method(const struct design_space *space);

/* The method text names for space: "auto" is study_auto_method's, any
 * other name optimize_method_parse's (FACET_EINPUT naming the field what,
 * the caller's name for it). */
int study_method_parse(const char *text, const char *what,
                       const struct design_space *space,
                       enum optimize_method *out, struct facet_error *err);

/* Checks what request asks for before anything is opened or created: a
 * name that is clean UTF-8 text of at most 127 bytes, a sound design
 * space. FACET_EINPUT naming what is wrong. study_start checks it too. */
int study_request_check(const struct study_request *request,
                        struct facet_error *err);

/* The design space of a project searched over the modules of range: u
 * 1..widths and v 1..heights (the width and height indices,
 * project_search.h) into space's grid sides, its threshold kept.
 * FACET_EINPUT when a range holds more values than a grid side may. */
int study_project_space(const struct module_range *range,
                        struct design_space *space, struct facet_error *err);

/* Runs a new study into store. *run receives its id (0 if it failed
 * before one was recorded), *outcome DONE or INTERRUPTED. Returns
 * FACET_OK, or the first error (the run, if recorded, is then "failed").
 * A stop heard while the surface is read or prepared, before the run is
 * recorded, returns FACET_ESTOP with *run 0: nothing was stored. */
int study_start(struct store *store, const struct study_request *request,
                const struct study_hooks *hooks, int64_t *run,
                enum optimize_outcome *outcome, struct facet_error *err);

/* Goes on with run (status interrupted or failed; a running run whose
 * writer is alive is refused, a done one too). A stop heard while its
 * surface is read gives the run back interrupted: FACET_OK, *outcome
 * INTERRUPTED. */
int study_resume(struct store *store, int64_t run,
                 const struct study_hooks *hooks,
                 enum optimize_outcome *outcome, struct facet_error *err);

/* The optimiser settings, mesh options and normal flip a run was made
 * with. */
int study_settings(const struct run_info *run,
                   struct optimize_settings *settings,
                   struct mesh_options *mesh, int *flip_normals,
                   struct facet_error *err);

/* Opens and prepares the surface of run, refusing a file whose content is
 * not the one the run was made from. The surface is looked for where the
 * run recorded it, then (a relative path) against the folder of store's
 * file, then by its name in that folder; the message of a failure says how
 * to re-point the run (study_repoint_surface). The UV is the method the
 * run took (its uv_method), so a resumed run, and every option shown
 * later, follows the UV its first options did, even when an older Facet
 * chose it. Release with surface_close, also after a failure. */
int study_open_surface(const struct store *store, const struct run_info *run,
                       struct surface *surface, struct facet_error *err);

/* Records path (made absolute) as run's surface, after checking that its
 * SHA-256 is the run's: what --surface FILE does for a surface that has
 * moved. FACET_EINPUT for another file or a read-only store. */
int study_repoint_surface(struct store *store, int64_t run,
                          const char *path, struct facet_error *err);

/* The panels and totals of option number of run: read from the store when
 * stored, else evaluated on surface (opened by study_open_surface when
 * surface is NULL) and stored. *panels is caller-owned (panelization_free,
 * also after a failure). */
int study_option_panels(struct store *store, const struct run_info *run,
                        const struct surface *surface, int64_t option,
                        struct panelization *panels,
                        struct option_totals *totals,
                        struct facet_error *err);

/* Ranks every stored option of run and stores ranks, crowding, knee and
 * hypervolume. */
int study_rank(struct store *store, int64_t run, struct facet_error *err);

/* Ends run, whose options are all stored, as every run ends: ranks them
 * (study_rank), refreshes the statistics and, unless the stop hook fires
 * (*outcome then OPTIMIZE_INTERRUPTED) or surface is NULL, stores the
 * panels of the options run->store_panels names, taken from lattice
 * (optimize_lattice's for settings, or NULL) on surface. A run calls it
 * after its last batch, a merge after the union of its shards. */
int study_finish(struct store *store, const struct run_info *run,
                 const struct surface *surface,
                 const struct panel_lattice *lattice,
                 const struct optimize_settings *settings,
                 const struct study_hooks *hooks,
                 enum optimize_outcome *outcome, struct facet_error *err);

/* Writes into text (size bytes) what a designer must know when run's
 * Pareto options sit on a bound of its design space (bounds, read with
 * store_front_bounds): each such bound, how many options sit there, and
 * that widening the range there shows whether the front goes on, instead
 * of taking the bound for an optimum. Bounds of a range of one value are
 * not edges. Returns 1 when it wrote a note, 0 (text "") otherwise. */
int study_front_edge_note(const struct run_info *run,
                          const struct front_bounds *bounds, char *text,
                          size_t size);

#endif
