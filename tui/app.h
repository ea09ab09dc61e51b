/*
 * app.h: what the workbench's screens share (internal to tui/): the open
 * store, the screen stack, the status line, the glyphs, the background
 * run; the screen interface; and the drawing helpers every screen uses.
 *
 * A screen is a small struct whose first member is struct tui_screen; its
 * class names it, lists its keys for the help screen and its function-key
 * labels, draws it, and handles a key by returning what happened. A screen
 * never reaches into another: it pushes a new one or returns RESULT_BACK.
 */
#ifndef FACET_TUI_APP_H
#define FACET_TUI_APP_H

#include <curses.h>
#include <stdint.h>
#include <time.h>

#include "columns.h"
#include "history.h"
#include "input.h"
#include "store/store.h"
#include "table_model.h"
#include "theme.h"

struct tui_app;
struct tui_screen;

enum tui_result {
    RESULT_UNHANDLED,  /* not this screen's key: the global keys apply
                          (a mouse wheel left unhandled scrolls as Up and
                          Down do) */
    RESULT_HANDLED,    /* done; redraw */
    RESULT_BACK,       /* close this screen */
    RESULT_QUIT        /* leave the workbench */
};

struct tui_key_help {
    const char *keys;  /* "s, F6" */
    const char *what;  /* "sort by the column under the cursor" */
};

struct tui_screen_class {
    const char *name;                  /* "Options", for the help title */
    const struct tui_key_help *help;   /* ends with {NULL, NULL} */
    const char *fkeys[10];             /* labels of F1..F10 (<= 6 chars) */
    /* Draws into rows [0, height) of the terminal, width columns. */
    void (*draw)(struct tui_screen *s, struct tui_app *app, int height,
                 int width);
    enum tui_result (*key)(struct tui_screen *s, struct tui_app *app,
                           int key);
    /* About four times a second while no key comes, or at once when the
     * last tick set app->tick_soon; returns non-zero to be redrawn (live
     * runs). May be NULL. */
    int (*tick)(struct tui_screen *s, struct tui_app *app);
    void (*destroy)(struct tui_screen *s);
};

struct tui_screen {
    const struct tui_screen_class *cls;
};

#define TUI_STACK_MAX 12

/* The mouse event a screen gets with KEY_MOUSE (tui_app.mouse), where the
 * terminal reports one: a press of the first button (clicks 2: the
 * second on the same cell within 0.4 s), or the wheel one step. */
enum tui_mouse_kind { MOUSE_CLICK, MOUSE_WHEEL_UP, MOUSE_WHEEL_DOWN };
struct tui_mouse {
    enum tui_mouse_kind kind;
    int y, x;              /* screen cell */
    int clicks;            /* 1, or 2 for a double click */
    struct timespec at;    /* when the last click came */
};

struct tui_job;  /* a New run working in a thread (job.h) */
struct tui_project_load;  /* a project prepared in a thread
                             (project_load.h) */

struct tui_app {
    struct store *store;
    char db_path[1024];
    struct tui_screen *stack[TUI_STACK_MAX];
    int depth;
    char status[512];
    int status_error;             /* the message is an error */
    const char *prompt;           /* a screen's input line label, or NULL */
    const struct tui_input *input;/* ... and its text */
    int utf8, colour;
    const struct tui_glyphs *glyphs;
    int help_open, help_top;
    int tick_soon;                /* a tick left work for the next (each
                                     does a share small enough for keys to
                                     be answered between them): the next
                                     comes as soon as no key waits */
    struct tui_job *job;          /* NULL when no run works */
    struct tui_column_set columns;/* the options table's, for the session */
    struct tui_history filters;   /* the filter line's texts (the table's
                                     and the scatter's), for the session */
    int confirm_quit;             /* "Quit? (y/n)" is asked */
    struct tui_mouse mouse;       /* the event of the last KEY_MOUSE */
    int fkey_x[10], fkey_width[10];  /* the bar as drawn (clicks on it) */
    /* Bumped when a background run ends: screens showing runs refresh
     * (header, counts and ranks) when it moves. */
    int64_t runs_finished;
    /* The background run as last sampled (once a second): the gauge
     * draws it, and the options table of that run refreshes when
     * job_samples moves, so the two show one moment. */
    int64_t job_run, job_done, job_total, job_samples;
    int64_t job_stored;           /* its options stored, at the sample */
    int job_sampling;             /* a sample was taken this round: the
                                     ticks read the run in its snapshot */
    int job_snapshot;             /* the sample's read transaction is open
                                     (store/snapshot.h) until the ticks
                                     have read the run too */
    struct timespec job_sampled;
    /* The project of the run whose project options' maps are browsed
     * (project_run), prepared once for all of them; NULL when none. It
     * goes when a map of another run's project needs the room, and when
     * the stack is back at its first screen. */
    struct tui_project_load *project;
    int64_t project_run;
};

/* Pushes screen (NULL: nothing, the constructor reported its error). */
void tui_push(struct tui_app *app, struct tui_screen *screen);

/* Sets the status line (cleared at the next key). */
void tui_status(struct tui_app *app, const char *fmt, ...)
    __attribute__((format(printf, 2, 3)));
void tui_error(struct tui_app *app, const char *fmt, ...)
    __attribute__((format(printf, 2, 3)));

/* Shows label and input in the status row (input NULL: no prompt). */
void tui_prompt(struct tui_app *app, const char *label,
                const struct tui_input *input);

/* Opens the filter prompt on input for model: on the text last entered
 * when it was refused (a mistyped filter, to be mended), else on model's
 * filter; Up and Down then browse app->filters (tui_filter_history_key).
 * The options table's and the scatter's '/'. */
void tui_filter_open(struct tui_app *app, struct tui_input *input,
                     const struct table_model *model);

/* Up or Down while a filter prompt is open: input takes the older or the
 * newer text of app->filters. Returns 1 when key was one of them (handled
 * here), 0 otherwise. */
int tui_filter_history_key(struct tui_app *app, struct tui_input *input,
                           int key);

/* Feeds key to input, the open prompt's text: on Enter or Esc the prompt
 * closes (tui_prompt(app, NULL, NULL)) and *open becomes 0. Returns
 * INPUT_DONE (Enter), INPUT_CANCEL (Esc) or INPUT_EDITING (anything
 * else: the prompt stays open). */
enum tui_input_result tui_prompt_key(struct tui_app *app,
                                     struct tui_input *input, int *open,
                                     int key);

/* Text at (y, x) in at most width columns (UTF-8 aware: one column per
 * code point), with attr; returns the columns written. */
int tui_put(int y, int x, int width, attr_t attr, const char *text);
/* text from (y, x) over at most rows rows of width columns, broken at
 * blanks (a word wider than a row is cut there); returns the rows it
 * took. tui_wrapped_rows: the rows it would take, with no row limit. */
int tui_put_wrapped(int y, int x, int width, int rows, attr_t attr,
                    const char *text);
int tui_wrapped_rows(const char *text, int width);
/* Same, formatted. */
int tui_putf(int y, int x, int width, attr_t attr, const char *fmt, ...)
    __attribute__((format(printf, 5, 6)));
/* Seconds from *t to now on CLOCK_MONOTONIC (the screens' refresh
 * clocks). */
double tui_seconds_since(const struct timespec *t);

/* width blanks with attr at (y, x). */
void tui_fill(int y, int x, int width, attr_t attr);

/* Screens (one file each). Constructors report failures on the status
 * line and return NULL. */
struct tui_screen *screen_runs_new(struct tui_app *app);
struct tui_screen *screen_options_new(struct tui_app *app, int64_t run);
struct tui_screen *screen_map_new(struct tui_app *app, int64_t run,
                                  int64_t option);
/* The map of option of a project run opened at its surface (0-based; a
 * single surface's option ignores it). */
struct tui_screen *screen_map_at(struct tui_app *app, int64_t run,
                                 int64_t option, int surface);
/* The surfaces of option of a project run, a row each (option_surfaces):
 * grid, panels, FP/SP/DP, cost, moulds, largest deviation, gap, kink. */
struct tui_screen *screen_surfaces_new(struct tui_app *app, int64_t run,
                                       int64_t option);
struct tui_screen *screen_scatter_new(struct tui_app *app,
                                      struct table_model *model);
/* Parallel coordinates over model (the options table's, borrowed): its
 * brushes set model's filter. */
struct tui_screen *screen_parallel_new(struct tui_app *app,
                                       struct table_model *model);
struct tui_screen *screen_compare_new(struct tui_app *app, int64_t run,
                                      const int64_t *options, int n);
struct tui_screen *screen_newrun_new(struct tui_app *app,
                                     const char *surface_path);
/* New run "like this": the form filled in from run's settings with a
 * design space narrowed around option (U and V +-2, or a building's
 * module +- one step of the run's; the threshold +- one step, or +-0.5
 * mm, in quarter steps), with the run's objectives and, for a building,
 * its files, surfaces' own grids and welding tolerance. */
struct tui_screen *screen_newrun_like(struct tui_app *app,
                                      const struct run_info *run,
                                      const struct option_row *option);
/* Statistics of model's options (borrowed: its filter applies), opened
 * at section (0 the columns, 5 the generations; screen_stats.c). */
struct tui_screen *screen_stats_new(struct tui_app *app,
                                    struct table_model *model, int section);

#endif
