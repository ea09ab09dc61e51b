/*
 * keys.h: what a key means to every screen (navigation, help, back,
 * quit), so that vi keys, arrows and function keys agree everywhere, and
 * key names for the help screen. Screens look at their own keys first and
 * ask tui_key_action for the rest.
 */
#ifndef FACET_TUI_KEYS_H
#define FACET_TUI_KEYS_H

enum tui_action {
    ACTION_NONE,
    ACTION_UP,         /* k, Up */
    ACTION_DOWN,       /* j, Down */
    ACTION_LEFT,       /* h, Left */
    ACTION_RIGHT,      /* l, Right */
    ACTION_PAGE_UP,    /* PgUp, Ctrl-B, Ctrl-U */
    ACTION_PAGE_DOWN,  /* PgDn, Ctrl-F, Ctrl-D */
    ACTION_TOP,        /* g, Home */
    ACTION_BOTTOM,     /* G, End */
    ACTION_SEARCH,     /* / */
    ACTION_NEXT,       /* n */
    ACTION_PREVIOUS,   /* N */
    ACTION_OPEN,       /* Enter */
    ACTION_BACK,       /* q, Esc */
    ACTION_QUIT,       /* F10 */
    ACTION_HELP,       /* ?, F1 */
    ACTION_REDRAW      /* Ctrl-L */
};

/* The action of curses key code key (getch's value), ACTION_NONE for a
 * key that has none. */
enum tui_action tui_key_action(int key);

/* What an Esc from getch begins. Under a TERM that does not match the
 * terminal, curses does not know a key's sequence and hands it over byte
 * by byte, Esc first: acting on those bytes made F5 go back and F10 quit.
 * next(context) gives the next byte already sent (or -1 when none follows
 * within the escape delay). Returns the key a common xterm/VT sequence
 * stands for (KEY_F(n), arrows, Home/End, PgUp/PgDn, Insert/Delete, with
 * any modifier dropped), TUI_KEY_NONE for any other sequence (read to its
 * end and ignored: mouse reports, Alt-keys, unknown CSI/SS3), or 27 for an
 * Esc on its own. *pushback is a key read past the Esc that is not part of
 * it (a second Esc), for the caller to handle next, or -1. */
#define TUI_KEY_NONE (-2)
int tui_key_escape(int (*next)(void *context), void *context,
                   int *pushback);

/* The name of a key for the help screen and messages: "F5", "Enter",
 * "Up", "Space", "Ctrl-L", or the character itself. */
const char *tui_key_name(int key, char buffer[16]);

#endif
