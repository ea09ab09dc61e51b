/*
 * tui.c: the workbench's frame: the terminal set up and always restored,
 * the screen stack, the main loop (keys, resize, ticks for live runs),
 * the status line, the htop-like function-key bar, the help overlay and
 * the global keys (F1/? help, q/Esc back, F10 quit, Ctrl-X stop the
 * background run). The screens are in screen_*.c.
 */
#include "tui.h"

#include <ctype.h>
#include <langinfo.h>
#include <locale.h>
#include <signal.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "app.h"
#include "core/base/text.h"
#include "format.h"
#include "input.h"
#include "job.h"
#include "keys.h"
#include "layout.h"
#include "terminal_key.h"
#include "project_load.h"
#include "store/snapshot.h"

#define CTRL(c) ((c) & 0x1f)

/* --- the terminal, restored whatever happens --- */

static volatile sig_atomic_t stop_signal;
static volatile sig_atomic_t curses_active;
static struct sigaction old_actions[6];
static const int stop_signals[2] = {SIGINT, SIGTERM};
static const int crash_signals[4] = {SIGSEGV, SIGBUS, SIGFPE, SIGABRT};

static void on_stop(int signal_number)
{
    stop_signal = signal_number;
}

/* A crash: give the terminal back, then die of the same signal. */
static void on_crash(int signal_number)
{
    if (curses_active) {
        curses_active = 0;
        endwin();
    }
    signal(signal_number, SIG_DFL);
    raise(signal_number);
}

static void signals_install(void)
{
    struct sigaction action;
    memset(&action, 0, sizeof action);
    sigemptyset(&action.sa_mask);
    action.sa_handler = on_stop;
    for (int k = 0; k < 2; k++)
        sigaction(stop_signals[k], &action, &old_actions[k]);
    action.sa_handler = on_crash;
    action.sa_flags = (int)SA_RESETHAND;
    for (int k = 0; k < 4; k++)
        sigaction(crash_signals[k], &action, &old_actions[2 + k]);
}

static void signals_restore(void)
{
    for (int k = 0; k < 2; k++)
        sigaction(stop_signals[k], &old_actions[k], NULL);
    for (int k = 0; k < 4; k++)
        sigaction(crash_signals[k], &old_actions[2 + k], NULL);
}

/* --- helpers for screens --- */

void tui_push(struct tui_app *app, struct tui_screen *screen)
{
    if (screen == NULL)
        return;
    if (app->depth == TUI_STACK_MAX) {
        screen->cls->destroy(screen);
        tui_error(app, "too many screens open; press q to go back");
        return;
    }
    app->stack[app->depth++] = screen;
}

void tui_status(struct tui_app *app, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(app->status, sizeof app->status, fmt, ap);
    va_end(ap);
    app->status_error = 0;
}

void tui_error(struct tui_app *app, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(app->status, sizeof app->status, fmt, ap);
    va_end(ap);
    app->status_error = 1;
}

void tui_prompt(struct tui_app *app, const char *label,
                const struct tui_input *input)
{
    app->prompt = input ? label : NULL;
    app->input = input;
}

void tui_filter_open(struct tui_app *app, struct tui_input *input,
                     const struct table_model *model)
{
    const char *refused = tui_history_refused(&app->filters);
    tui_input_set(input, refused ? refused
                         : model->filter ? filter_text(model->filter) : "");
    tui_history_open(&app->filters);
    tui_prompt(app, "Filter:", input);
}

int tui_filter_history_key(struct tui_app *app, struct tui_input *input,
                           int key)
{
    if (key != KEY_UP && key != KEY_DOWN)
        return 0;
    const char *text = tui_history_step(&app->filters,
                                        key == KEY_UP ? -1 : 1, input->text);
    if (text != NULL)
        tui_input_set(input, text);
    return 1;
}

enum tui_input_result tui_prompt_key(struct tui_app *app,
                                     struct tui_input *input, int *open,
                                     int key)
{
    enum tui_input_result r = tui_input_key(input, key);
    if (r != INPUT_DONE && r != INPUT_CANCEL)
        return INPUT_EDITING;
    *open = 0;
    tui_prompt(app, NULL, NULL);
    return r;
}

static const char *next_row(const char *text, size_t n)
{
    text += n;
    while (*text == ' ')
        text++;
    return text;
}

int tui_wrapped_rows(const char *text, int width)
{
    int rows = 0;
    while (*text && width > 0) {
        text = next_row(text, text_break(text, width));
        rows++;
    }
    return rows;
}

int tui_put_wrapped(int y, int x, int width, int rows, attr_t attr,
                    const char *text)
{
    int r = 0;
    for (; r < rows && *text && width > 0; r++) {
        size_t n = text_break(text, width);
        tui_putf(y + r, x, width, attr, "%.*s", (int)n, text);
        text = next_row(text, n);
    }
    return r;
}

int tui_put(int y, int x, int width, attr_t attr, const char *text)
{
    if (width <= 0 || y < 0 || y >= LINES || x >= COLS)
        return 0;
    if (x + width > COLS)
        width = COLS - x;
    attr_t old_attr;
    short old_pair;
    attr_get(&old_attr, &old_pair, NULL);
    attrset(attr);
    move(y, x);
    int columns = 0;
    const unsigned char *p = (const unsigned char *)text;
    /* Names, paths and warnings came from files and stores: a control
     * character or a byte that is not UTF-8 is shown as '?', as the CLI
     * shows it (text_for_terminal), never handed to curses. */
    while (*p && columns < width) {
        size_t n = text_char_length((const char *)p);
        if (n == 0 || text_char_is_control((const char *)p, n)) {
            addch('?');
            n = 1;
        } else {
            addnstr((const char *)p, (int)n);
        }
        p += n;
        columns++;
    }
    attr_set(old_attr, old_pair, NULL);
    return columns;
}

int tui_putf(int y, int x, int width, attr_t attr, const char *fmt, ...)
{
    char text[1024];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(text, sizeof text, fmt, ap);
    va_end(ap);
    return tui_put(y, x, width, attr, text);
}

double tui_seconds_since(const struct timespec *t)
{
    struct timespec now;
    clock_gettime(CLOCK_MONOTONIC, &now);
    return (double)(now.tv_sec - t->tv_sec) +
           (double)(now.tv_nsec - t->tv_nsec) * 1e-9;
}

void tui_fill(int y, int x, int width, attr_t attr)
{
    if (width <= 0 || y < 0 || y >= LINES)
        return;
    if (x + width > COLS)
        width = COLS - x;
    attr_t old_attr;
    short old_pair;
    attr_get(&old_attr, &old_pair, NULL);
    attrset(attr);
    mvhline(y, x, ' ', width);
    attr_set(old_attr, old_pair, NULL);
}

/* --- the frame --- */

static struct tui_screen *top(struct tui_app *app)
{
    return app->depth > 0 ? app->stack[app->depth - 1] : NULL;
}

static void pop(struct tui_app *app)
{
    if (app->depth == 0)
        return;
    struct tui_screen *s = app->stack[--app->depth];
    s->cls->destroy(s);
    tui_prompt(app, NULL, NULL);
    /* Back at the first screen: no run is browsed, its project goes. */
    if (app->depth <= 1 && app->project != NULL) {
        tui_project_load_free(app->project);
        app->project = NULL;
        app->project_run = 0;
    }
}

/* The background run's line: stage, gauge, count. */
static void draw_job(struct tui_app *app, int y, int width)
{
    struct tui_job_state st;
    tui_job_state(app->job, &st);
    char text[160];
    int x = tui_putf(y, 0, width, tui_attr(ROLE_STATUS), "run %lld %s ",
                     (long long)st.run, st.stopping ? "stopping" : st.stage);
    int gauge = width - x - 46;
    if (gauge > 30)
        gauge = 30;
    /* the sampled numbers, not the live ones: the table of the run shows
     * the same moment */
    st.done = app->job_done;
    st.total = app->job_total;
    if (st.total > 0 && gauge > 4) {
        int full = (int)((double)st.done / (double)st.total * gauge);
        for (int k = 0; k < gauge; k++)
            x += tui_put(y, x, 1, k < full ? tui_attr(ROLE_GAUGE)
                                            : tui_attr(ROLE_DIM),
                         k < full ? app->glyphs->gauge_full
                                  : app->glyphs->gauge_empty);
        char stored[32];
        tui_fmt_number(stored, sizeof stored, (double)app->job_stored, 0, 1);
        snprintf(text, sizeof text, " %d%% %s options stored  Ctrl-X stops",
                 (int)(100.0 * (double)st.done / (double)st.total), stored);
    } else {
        snprintf(text, sizeof text, " Ctrl-X stops");
    }
    tui_put(y, x, width - x, tui_attr(ROLE_STATUS), text);
}

static void draw_status(struct tui_app *app, int y, int rows, int width)
{
    for (int r = 0; r < rows; r++)
        tui_fill(y + r, 0, width, A_NORMAL);
    if (app->prompt != NULL) {
        int x = tui_put(y, 0, width, tui_attr(ROLE_HEADER), app->prompt);
        x += tui_put(y, x, 1, A_NORMAL, " ");
        size_t from = tui_input_scroll(app->input, width - x);
        tui_put(y, x, width - x, A_NORMAL, app->input->text + from);
        move(y, x + (int)(app->input->cursor - from));
        curs_set(1);
        return;
    }
    curs_set(0);
    if (app->status[0])
        tui_put_wrapped(y, 0, width, rows,
                        tui_attr(app->status_error ? ROLE_ERROR
                                                   : ROLE_STATUS),
                        app->status);
    else if (app->job != NULL)
        draw_job(app, y, width);
}

/* htop's bar: "F1" then the label on a coloured field, a blank after
 * each so that the labels never run together (layout.h). */
static void draw_fkeys(struct tui_app *app, const struct tui_screen *s,
                       int y, int width)
{
    tui_fill(y, 0, width, A_NORMAL);
    tui_fkey_layout(s->cls->fkeys, width, app->fkey_x, app->fkey_width);
    for (int k = 0; k < 10; k++) {
        int x = app->fkey_x[k];
        if (x < 0 || x >= width)
            continue;
        x += tui_putf(y, x, width - x, tui_attr(ROLE_FKEY), "F%d", k + 1);
        tui_fill(y, x, app->fkey_width[k], tui_attr(ROLE_FKEY_LABEL));
        tui_put(y, x, app->fkey_width[k], tui_attr(ROLE_FKEY_LABEL),
                s->cls->fkeys[k]);
    }
}

static const struct tui_key_help global_help[] = {
    {"?, F1", "this help (j/k, PgUp/PgDn scroll it, any other key closes)"},
    {"q, Esc", "back to the previous screen (on the first: asks, then "
               "quits)"},
    {"F10", "quit (asks only while a run is working)"},
    {"Ctrl-X", "stop the run working in the background (resumable)"},
    {"Ctrl-L", "redraw the screen"},
    {"mouse click", "select (twice: open); a header: sort; the bar: its key"},
    {"mouse wheel", "scroll"},
    {NULL, NULL},
};

/* The help's lines: the screen's keys, a heading, the global keys; a
 * description wider than what_width goes on under its keys, cut at
 * blanks, so that nothing is cut at the screen's edge. */
struct help_line {
    const char *keys;  /* NULL: a heading (text); "": a continuation */
    char text[128];
};

static int help_add(struct help_line *out, int n, int max, const char *keys,
                    const char *what, int what_width)
{
    if (what_width < 20)
        what_width = 20;
    if (what_width > 127)
        what_width = 127;
    const char *p = what;
    int first = 1;
    while (n < max) {
        int len = (int)strlen(p), cut = len;
        if (tui_text_width(p) > what_width) {
            /* the last blank within what_width code points */
            int columns = 0, k = 0;
            cut = 0;
            for (; p[k] && columns < what_width; k++) {
                if (((unsigned char)p[k] & 0xc0) != 0x80)
                    columns++;
                if (p[k] == ' ')
                    cut = k;
            }
            if (cut == 0)
                cut = k;
        }
        out[n].keys = first ? keys : "";
        snprintf(out[n].text, sizeof out[n].text, "%.*s", cut, p);
        n++;
        first = 0;
        p += cut;
        while (*p == ' ')
            p++;
        if (*p == '\0')
            break;
    }
    return n;
}

static int help_lines(const struct tui_screen *s, struct help_line *out,
                      int max, int what_width)
{
    int n = 0;
    for (const struct tui_key_help *h = s->cls->help; h->keys && n < max;
         h++)
        n = help_add(out, n, max, h->keys, h->what, what_width);
    if (n < max) {
        out[n].keys = NULL;
        snprintf(out[n].text, sizeof out[n].text, "Everywhere");
        n++;
    }
    for (const struct tui_key_help *h = global_help; h->keys && n < max;
         h++)
        n = help_add(out, n, max, h->keys, h->what, what_width);
    return n;
}

/* The help over the whole screen above the status line, in two columns
 * when it is wide and the keys do not fit one; scrolls by lines, and
 * says which lines show. */
static void draw_help(struct tui_app *app, int height, int width)
{
    const struct tui_screen *s = top(app);
    struct help_line lines[128];
    /* two columns need 2 x 78 + 3: the width of one decides the wrap */
    int two = width >= 2 * 78 + 3;
    int cw = two ? (width - 1) / 2 : width;
    int n = help_lines(s, lines, 128, cw - 19);
    struct tui_help_page page;
    tui_help_layout(n, height, width, 78, app->help_top, &page);
    if (page.columns == 1 && two) {
        /* one column after all: wrapped for the whole width */
        cw = width;
        n = help_lines(s, lines, 128, cw - 19);
        tui_help_layout(n, height, width, 78, app->help_top, &page);
    }
    app->help_top = page.top;
    for (int y = 0; y < height; y++)
        tui_fill(y, 0, width, tui_attr(ROLE_NORMAL));
    tui_fill(0, 0, width, tui_attr(ROLE_TITLE));
    tui_putf(0, 0, width, tui_attr(ROLE_TITLE), " Help: %s keys",
             s->cls->name);
    int shown = page.per_page * page.columns;
    int last = page.top + shown < n ? page.top + shown : n;
    char where[96];
    snprintf(where, sizeof where, "lines %d-%d of %d%s ", page.top + 1, last,
             n, n > shown ? ", j/k scroll" : "");
    int ww = tui_text_width(where);
    if (ww < width - 20)
        tui_put(0, width - ww, ww, tui_attr(ROLE_TITLE), where);
    for (int k = page.top; k < last; k++) {
        int col = (k - page.top) / page.per_page;
        int y = 2 + (k - page.top) % page.per_page;
        int x0 = col * (cw + 1);
        if (lines[k].keys == NULL) {
            tui_put(y, x0 + 1, cw - 2, tui_attr(ROLE_HEADER), lines[k].text);
            continue;
        }
        tui_put(y, x0 + 1, 16, tui_attr(ROLE_PARETO), lines[k].keys);
        tui_put(y, x0 + 18, cw - 19, A_NORMAL, lines[k].text);
    }
    tui_put(height - 1, 1, width - 2, tui_attr(ROLE_DIM),
            n > shown ? "j/k or PgUp/PgDn scroll; any other key closes"
                      : "any key closes");
}

static void draw(struct tui_app *app)
{
    int height = LINES, width = COLS;
    erase();
    struct tui_screen *s = top(app);
    if (height < 6 || width < 30) {
        tui_put(0, 0, width, A_NORMAL, "terminal too small");
        refresh();
        return;
    }
    /* A message wider than the screen takes rows from the screen until
     * the next key, so that its end is read, not cut: up to a quarter of
     * them (a front on three bounds of its space takes four at 80
     * columns). */
    int status_rows = 1;
    if (app->prompt == NULL && app->status[0]) {
        int most = height / 4 > 1 ? height / 4 : 1;
        status_rows = tui_wrapped_rows(app->status, width);
        status_rows = status_rows < 1 ? 1
                      : status_rows > most ? most : status_rows;
    }
    s->cls->draw(s, app, height - 1 - status_rows, width);
    if (app->help_open)
        draw_help(app, height - 1 - status_rows, width);
    draw_fkeys(app, s, height - 1, width);
    draw_status(app, height - 1 - status_rows, status_rows, width);
    refresh();
}

/* Samples the background run once a second, before the screens' ticks:
 * its progress, and its options stored as of a snapshot of the database
 * that stays open through the ticks (end_sample), so that the gauge and
 * the run's table (title, count, rows) are read at one moment. */
static int sample_job(struct tui_app *app)
{
    if (app->job == NULL)
        return 0;
    if (app->job_samples > 0 && tui_seconds_since(&app->job_sampled) < 1.0)
        return 0;
    struct tui_job_state st;
    tui_job_state(app->job, &st);
    clock_gettime(CLOCK_MONOTONIC, &app->job_sampled);
    app->job_run = st.run;
    app->job_done = st.done;
    app->job_total = st.total;
    app->job_samples++;
    app->job_sampling = 1;
    struct facet_error ignored;  /* without a snapshot the reads go on */
    store_snapshot_begin(app->store, &app->job_snapshot, &ignored);
    struct run_info info;
    if (st.run > 0 &&
        store_run_get(app->store, st.run, &info, &ignored) == FACET_OK)
        app->job_stored = info.options;
    return 1;  /* the gauge moves */
}

static void end_sample(struct tui_app *app)
{
    store_snapshot_end(app->store, app->job_snapshot);
    app->job_snapshot = 0;
    app->job_sampling = 0;
}

/* Reports a finished background run and releases it, after the screens'
 * ticks (the New run form opens the run's table from the job). */
static int poll_job(struct tui_app *app)
{
    if (app->job == NULL)
        return 0;
    struct tui_job_state st;
    tui_job_state(app->job, &st);
    if (!st.finished)
        return 0;
    app->job_samples = 0;
    tui_job_free(app->job);
    app->job = NULL;
    app->runs_finished++;  /* every screen of it refreshes */
    if (st.rc == FACET_ESTOP)
        tui_status(app, "stopped while reading the surface: no run was "
                   "recorded");
    else if (st.rc != FACET_OK && st.err.setting == FACET_SETTING_UNITS &&
             st.err.value[0] != '\0')
        /* Units Facet can name (surface_units_check): the form's field to
         * type them in, and how to insist on metres. */
        tui_error(app, "new run refused: %s: type %s in New run's Units "
                  "(or m to go on in metres)", st.err.message,
                  st.err.value);
    else if (st.rc != FACET_OK && st.run <= 0)
        tui_error(app, "new run refused: %s", st.err.message);
    else if (st.rc != FACET_OK)
        tui_error(app, "run %lld failed: %s", (long long)st.run,
                  st.err.message);
    else if (st.outcome == OPTIMIZE_INTERRUPTED)
        tui_status(app, "run %lld stopped with %lld options stored; R on "
                   "the Runs screen goes on with it", (long long)st.run,
                   (long long)st.done);
    else if (st.warning[0] != '\0')
        tui_status(app, "run %lld done: %lld options; warning: %s",
                   (long long)st.run, (long long)st.total, st.warning);
    else
        tui_status(app, "run %lld done: %lld options", (long long)st.run,
                   (long long)st.total);
    return 1;
}

/* The next byte of an escape sequence, if one was sent with it. */
static int next_byte(void *context)
{
    (void)context;
    timeout(30);
    int c = getch();
    timeout(250);
    /* the mouse where the terminal reports it: presses (no click
     * resolution, which would delay them) and the wheel */
    mouseinterval(0);
    mousemask(BUTTON1_PRESSED | BUTTON4_PRESSED | BUTTON5_PRESSED, NULL);
    return c == ERR ? -1 : c;
}

/* A key from getch with unknown escape sequences read whole and ignored
 * (keys.h); ERR when none came. */
static int read_key(void)
{
    int key = getch();
    if (key != 27)
        return key;
    int pushback;
    key = tui_key_escape(next_byte, NULL, &pushback);
    if (pushback >= 0)
        ungetch(pushback);
    return key;
}

/* Turns the KEY_MOUSE curses has into app->mouse; returns 0 for an event
 * Facet does not use (a release, another button). */
static int read_mouse(struct tui_app *app)
{
    MEVENT event;
    if (getmouse(&event) != OK)
        return 0;
    static const double double_click = 0.4;
    struct tui_mouse *m = &app->mouse;
    if (event.bstate & BUTTON4_PRESSED) {
        m->kind = MOUSE_WHEEL_UP;
    } else if (event.bstate & BUTTON5_PRESSED) {
        m->kind = MOUSE_WHEEL_DOWN;
    } else if (event.bstate & (BUTTON1_PRESSED | BUTTON1_CLICKED)) {
        int again = m->kind == MOUSE_CLICK && m->y == event.y &&
                    m->x == event.x && m->clicks == 1 &&
                    tui_seconds_since(&m->at) < double_click;
        clock_gettime(CLOCK_MONOTONIC, &m->at);
        m->kind = MOUSE_CLICK;
        m->clicks = again ? 2 : 1;
    } else {
        return 0;
    }
    m->y = event.y;
    m->x = event.x;
    return 1;
}

/* Asks before quitting: always on the first screen's q/Esc, on F10 only
 * while a run works (which quitting stops, resumably). */
static int job_working(struct tui_app *app)
{
    if (app->job == NULL)
        return 0;
    struct tui_job_state st;
    tui_job_state(app->job, &st);
    return !st.finished;
}

static void ask_quit(struct tui_app *app)
{
    app->confirm_quit = 1;
    if (job_working(app))
        tui_error(app, "A run is working: quit and stop it (it stays "
                  "resumable)? (y/n)");
    else
        tui_error(app, "Quit Facet? (y/n)");
}

static void loop(struct tui_app *app)
{
    int dirty = 1;
    while (app->depth > 0 && !stop_signal) {
        if (dirty)
            draw(app);
        dirty = 0;
        /* Work left by a tick goes on at once; otherwise a quarter of a
         * second between ticks (live runs refresh once a second). */
        timeout(app->tick_soon ? 0 : 250);
        app->tick_soon = 0;
        int key = read_key();
        if (stop_signal)
            break;
        struct tui_screen *s = top(app);
        if (key == ERR) {
            if (sample_job(app))
                dirty = 1;
            if (s->cls->tick && s->cls->tick(s, app))
                dirty = 1;
            end_sample(app);
            if (poll_job(app))
                dirty = 1;
            continue;
        }
        if (key == TUI_KEY_NONE)
            continue;  /* a sequence Facet does not know: nothing */
        dirty = 1;
        if (key == KEY_RESIZE)
            continue;
        if (key == KEY_MOUSE) {
            if (!read_mouse(app))
                continue;
            if (app->mouse.kind == MOUSE_CLICK && app->mouse.y == LINES - 1 &&
                !app->help_open && app->prompt == NULL) {
                int f = tui_fkey_at(app->fkey_x, app->fkey_width,
                                    app->mouse.x);
                if (f == 0)
                    continue;
                key = KEY_F(f);  /* a click on the bar presses the key */
            }
        }
        if (app->confirm_quit) {
            app->confirm_quit = 0;
            app->status[0] = '\0';
            app->status_error = 0;
            if (key == 'y' || key == 'Y')
                break;
            tui_status(app, "not quitting");
            continue;
        }
        if (app->help_open) {
            enum tui_action a = tui_key_action(key);
            if (key == KEY_MOUSE)
                a = app->mouse.kind == MOUSE_WHEEL_UP ? ACTION_UP
                    : app->mouse.kind == MOUSE_WHEEL_DOWN ? ACTION_DOWN
                                                          : ACTION_NONE;
            if (a == ACTION_DOWN)
                app->help_top++;
            else if (a == ACTION_UP && app->help_top > 0)
                app->help_top--;
            else if (a == ACTION_PAGE_DOWN)
                app->help_top += LINES / 2;
            else if (a == ACTION_PAGE_UP)
                app->help_top = app->help_top > LINES / 2
                                    ? app->help_top - LINES / 2 : 0;
            else
                app->help_open = 0;
            continue;
        }
        if (app->prompt == NULL) {
            app->status[0] = '\0';
            app->status_error = 0;
        }
        if (key == CTRL('x') && app->job != NULL) {
            tui_job_stop(app->job);
            tui_status(app, "stopping the run after its current batch");
            continue;
        }
        enum tui_result r = s->cls->key(s, app, key);
        if (r == RESULT_UNHANDLED && key == KEY_MOUSE &&
            app->mouse.kind != MOUSE_CLICK) {
            /* a wheel the screen does not take: three lines as keys */
            int arrow = app->mouse.kind == MOUSE_WHEEL_UP ? KEY_UP
                                                          : KEY_DOWN;
            for (int k = 0; k < 3; k++)
                s->cls->key(s, app, arrow);
            r = RESULT_HANDLED;
        }
        if (r == RESULT_UNHANDLED && app->prompt == NULL) {
            switch (tui_key_action(key)) {
            case ACTION_HELP:
                app->help_open = 1;
                app->help_top = 0;
                break;
            case ACTION_BACK:
                r = RESULT_BACK;
                break;
            case ACTION_QUIT:
                r = RESULT_QUIT;
                break;
            case ACTION_REDRAW:
                clearok(curscr, TRUE);
                break;
            default:
                break;
            }
        }
        if (r == RESULT_BACK && app->depth == 1)
            ask_quit(app);
        else if (r == RESULT_BACK)
            pop(app);
        else if (r == RESULT_QUIT && job_working(app))
            ask_quit(app);
        else if (r == RESULT_QUIT)
            break;
    }
}

/* facet tui on a file that does not exist: asks on the terminal, before
 * curses starts, whether to create it (a typo must not leave a database
 * behind). Returns 1 to go on. */
static int may_create(const char *path)
{
    struct stat st;
    if (stat(path, &st) == 0)
        return 1;
    printf("%s does not exist. Create a new result database there? (y/n) ",
           path);
    fflush(stdout);
    /* one key answers, as (y/n) says */
    int answer = terminal_read_key(STDIN_FILENO);
    if (answer != '\n')
        putchar('\n');
    return answer == 'y' || answer == 'Y';
}

int tui_run(const char *db_path, const char *surface,
            struct facet_error *err)
{
    if (!isatty(STDIN_FILENO) || !isatty(STDOUT_FILENO))
        return facet_error_set(err, FACET_EINPUT,
            "tui: needs a terminal on stdin and stdout (for scripts use "
            "facet runs / facet options)");
    struct tui_app *app = calloc(1, sizeof *app);
    if (app == NULL)
        return facet_error_set(err, FACET_EWORK, "out of memory");
    if (strlen(db_path) >= sizeof app->db_path) {
        free(app);
        return facet_error_set(err, FACET_EINPUT, "%.200s...: path too long",
                               db_path);
    }
    snprintf(app->db_path, sizeof app->db_path, "%s", db_path);
    if (!may_create(app->db_path)) {
        printf("nothing created\n");
        free(app);
        return FACET_OK;
    }
    /* Opened to look: an older file is not migrated behind the user's
     * back (store_open_current says how). */
    int rc = store_open_current(app->db_path, &app->store, err);
    if (rc != FACET_OK) {
        free(app);
        return rc;
    }
    setlocale(LC_ALL, "");
    app->utf8 = tui_terminal_utf8(nl_langinfo(CODESET), getenv("TERM"));
    app->glyphs = tui_glyphs_for(app->utf8);
    tui_columns_default(&app->columns);
    stop_signal = 0;
    signals_install();
    SCREEN *screen = newterm(NULL, stdout, stdin);
    if (screen == NULL) {
        signals_restore();
        store_close(app->store);
        free(app);
        return facet_error_set(err, FACET_EINPUT,
            "tui: cannot drive terminal type '%s'",
            getenv("TERM") ? getenv("TERM") : "(TERM unset)");
    }
    curses_active = 1;
    cbreak();
    noecho();
    nonl();
    keypad(stdscr, TRUE);
    set_escdelay(25);
    curs_set(0);
    timeout(250);
    /* the mouse where the terminal reports it: presses (no click
     * resolution, which would delay them) and the wheel */
    mouseinterval(0);
    mousemask(BUTTON1_PRESSED | BUTTON4_PRESSED | BUTTON5_PRESSED, NULL);
    app->colour = tui_theme_init(getenv("NO_COLOR") == NULL);

    tui_push(app, screen_runs_new(app));
    if (surface != NULL)
        tui_push(app, screen_newrun_new(app, surface));
    if (app->depth > 0)
        loop(app);

    while (app->depth > 0)
        pop(app);
    if (app->job != NULL) {
        /* leaving with a run at work: stop it, which keeps it resumable */
        tui_job_free(app->job);
        app->job = NULL;
    }
    curses_active = 0;
    endwin();
    delscreen(screen);
    signals_restore();
    store_close(app->store);
    free(app);
    return FACET_OK;
}
