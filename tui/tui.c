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
#include <strings.h>
#include <time.h>
#include <unistd.h>

#include "app.h"
#include "format.h"
#include "input.h"
#include "job.h"
#include "keys.h"

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
    while (*p && columns < width) {
        size_t n = *p < 0x80 ? 1 : *p < 0xe0 ? 2 : *p < 0xf0 ? 3 : 4;
        size_t have = strnlen((const char *)p, n);
        addnstr((const char *)p, (int)have);
        p += have;
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
}

/* The background run's line: stage, gauge, count. */
static void draw_job(struct tui_app *app, int y, int width)
{
    struct tui_job_state st;
    tui_job_state(app->job, &st);
    char text[160];
    int x = tui_putf(y, 0, width, tui_attr(ROLE_STATUS), "run %lld %s ",
                     (long long)st.run, st.stopping ? "stopping" : st.stage);
    int gauge = width - x - 34;
    if (gauge > 30)
        gauge = 30;
    if (st.total > 0 && gauge > 4) {
        int full = (int)((double)st.done / (double)st.total * gauge);
        for (int k = 0; k < gauge; k++)
            x += tui_put(y, x, 1, k < full ? tui_attr(ROLE_GAUGE)
                                            : tui_attr(ROLE_DIM),
                         k < full ? app->glyphs->gauge_full
                                  : app->glyphs->gauge_empty);
        snprintf(text, sizeof text, " %lld/%lld options (%d%%) Ctrl-X stops",
                 (long long)st.done, (long long)st.total,
                 (int)(100.0 * (double)st.done / (double)st.total));
    } else {
        snprintf(text, sizeof text, " Ctrl-X stops");
    }
    tui_put(y, x, width - x, tui_attr(ROLE_STATUS), text);
}

static void draw_status(struct tui_app *app, int y, int width)
{
    tui_fill(y, 0, width, A_NORMAL);
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
        tui_put(y, 0, width, tui_attr(app->status_error ? ROLE_ERROR
                                                          : ROLE_STATUS),
                app->status);
    else if (app->job != NULL)
        draw_job(app, y, width);
}

/* htop's bar: "F1" then the label on a coloured field of 6 columns. */
static void draw_fkeys(const struct tui_screen *s, int y, int width)
{
    tui_fill(y, 0, width, tui_attr(ROLE_FKEY_LABEL));
    int x = 0;
    for (int k = 0; k < 10 && x < width; k++) {
        const char *label = s->cls->fkeys[k];
        if (label == NULL || label[0] == '\0')
            continue;
        x += tui_putf(y, x, width - x, tui_attr(ROLE_FKEY), "F%d", k + 1);
        char field[16];
        snprintf(field, sizeof field, "%-6.6s", label);
        x += tui_put(y, x, width - x, tui_attr(ROLE_FKEY_LABEL), field);
    }
}

static const struct tui_key_help global_help[] = {
    {"?, F1", "this help (j/k scroll it, any other key closes it)"},
    {"q, Esc", "back to the previous screen (quits on the first)"},
    {"F10", "quit"},
    {"Ctrl-X", "stop the run working in the background (resumable)"},
    {"Ctrl-L", "redraw the screen"},
    {NULL, NULL},
};

static void draw_help(struct tui_app *app, int height, int width)
{
    const struct tui_screen *s = top(app);
    const struct tui_key_help *sets[2] = {s->cls->help, global_help};
    int lines = 0;
    for (int k = 0; k < 2; k++)
        for (const struct tui_key_help *h = sets[k]; h->keys; h++)
            lines++;
    lines += 1;
    int w = width - 4 < 76 ? width - 4 : 76, h = height - 2;
    int x0 = (width - w) / 2, y0 = 1;
    int visible = h - 3;
    if (app->help_top > lines - visible)
        app->help_top = lines - visible > 0 ? lines - visible : 0;
    for (int y = 0; y < h; y++)
        tui_fill(y0 + y, x0, w, tui_attr(ROLE_NORMAL));
    tui_fill(y0, x0, w, tui_attr(ROLE_TITLE));
    tui_putf(y0, x0, w, tui_attr(ROLE_TITLE),
             " Help: %s keys (j/k scroll, any other key closes)",
             s->cls->name);
    int row = 0, y = y0 + 2;
    for (int k = 0; k < 2; k++) {
        if (k == 1) {
            if (row >= app->help_top && y < y0 + h)
                tui_put(y++, x0 + 1, w - 2, tui_attr(ROLE_HEADER),
                        "Everywhere");
            row++;
        }
        for (const struct tui_key_help *e = sets[k]; e->keys; e++, row++) {
            if (row < app->help_top || y >= y0 + h)
                continue;
            tui_putf(y, x0 + 1, 16, tui_attr(ROLE_PARETO), "%s", e->keys);
            tui_put(y, x0 + 18, w - 19, A_NORMAL, e->what);
            y++;
        }
    }
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
    s->cls->draw(s, app, height - 2, width);
    if (app->help_open)
        draw_help(app, height - 2, width);
    draw_fkeys(s, height - 1, width);
    draw_status(app, height - 2, width);
    refresh();
}

/* Reports a finished background run and releases it. */
static int poll_job(struct tui_app *app)
{
    if (app->job == NULL)
        return 0;
    struct tui_job_state st;
    tui_job_state(app->job, &st);
    if (!st.finished)
        return 1;  /* the gauge moves */
    tui_job_free(app->job);
    app->job = NULL;
    if (st.rc != FACET_OK)
        tui_error(app, "run %lld failed: %s", (long long)st.run,
                  st.err.message);
    else if (st.outcome == OPTIMIZE_INTERRUPTED)
        tui_status(app, "run %lld stopped with %lld options stored; "
                   "facet optimize --db %s --resume %lld goes on",
                   (long long)st.run, (long long)st.done, app->db_path,
                   (long long)st.run);
    else if (st.warning[0] != '\0')
        tui_status(app, "run %lld done: %lld options; warning: %s",
                   (long long)st.run, (long long)st.total, st.warning);
    else
        tui_status(app, "run %lld done: %lld options", (long long)st.run,
                   (long long)st.total);
    return 1;
}

static int is_surface(const char *path)
{
    size_t n = strlen(path);
    return n > 4 && strcasecmp(path + n - 4, ".obj") == 0;
}

static void loop(struct tui_app *app)
{
    int dirty = 1;
    while (app->depth > 0 && !stop_signal) {
        if (dirty)
            draw(app);
        dirty = 0;
        int key = getch();
        if (stop_signal)
            break;
        struct tui_screen *s = top(app);
        if (key == ERR) {
            if (s->cls->tick && s->cls->tick(s, app))
                dirty = 1;
            if (poll_job(app))
                dirty = 1;
            continue;
        }
        dirty = 1;
        if (key == KEY_RESIZE)
            continue;
        if (app->help_open) {
            enum tui_action a = tui_key_action(key);
            if (a == ACTION_DOWN)
                app->help_top++;
            else if (a == ACTION_UP && app->help_top > 0)
                app->help_top--;
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
        if (r == RESULT_BACK)
            pop(app);
        else if (r == RESULT_QUIT)
            break;
    }
}

int tui_run(const char *path, struct facet_error *err)
{
    if (!isatty(STDIN_FILENO) || !isatty(STDOUT_FILENO))
        return facet_error_set(err, FACET_EINPUT,
            "tui: needs a terminal on stdin and stdout (for scripts use "
            "facet runs / facet options)");
    const char *surface = path && is_surface(path) ? path : NULL;
    struct tui_app *app = calloc(1, sizeof *app);
    if (app == NULL)
        return facet_error_set(err, FACET_EWORK, "out of memory");
    snprintf(app->db_path, sizeof app->db_path, "%s",
             path && !surface ? path : "facet.db");
    int rc = store_open(app->db_path, &app->store, err);
    if (rc != FACET_OK) {
        free(app);
        return rc;
    }
    setlocale(LC_ALL, "");
    app->utf8 = strcmp(nl_langinfo(CODESET), "UTF-8") == 0;
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
