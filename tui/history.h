/*
 * history.h: the texts entered at a prompt during a session (the filter
 * line), newest last, that Up and Down bring back as a shell does: Up
 * goes to older texts, Down to newer ones, and past the newest to what
 * was being typed before Up. A text refused when entered (a mistyped
 * filter) is what the prompt opens on next, so that it can be mended
 * rather than typed again. No curses here: the unit tests drive it.
 */
#ifndef FACET_TUI_HISTORY_H
#define FACET_TUI_HISTORY_H

#include "input.h"

#define TUI_HISTORY_MAX 32

struct tui_history {
    char text[TUI_HISTORY_MAX][TUI_INPUT_MAX];  /* oldest first */
    int n;                        /* texts held */
    int at;                       /* the text Up/Down shows: n is the one
                                     being typed */
    char typed[TUI_INPUT_MAX];    /* what was being typed before Up */
    int refused;                  /* text[n - 1] was refused */
};

/* Records text as entered (refused: it was not taken), unless it is empty
 * or the newest text again (then only refused is updated); the oldest
 * goes when the history is full. Browsing starts again from the end. */
void tui_history_add(struct tui_history *h, const char *text, int refused);

/* The prompt opens: browsing starts from what is being typed. */
void tui_history_open(struct tui_history *h);

/* The newest text when it was refused, else NULL: what the prompt
 * opens on. */
const char *tui_history_refused(const struct tui_history *h);

/* Up (step -1, older) or Down (step 1, newer) from where browsing is,
 * current being the prompt's text now: the text to show instead, or NULL
 * when there is none further that way (the prompt keeps its text). */
const char *tui_history_step(struct tui_history *h, int step,
                             const char *current);

#endif
