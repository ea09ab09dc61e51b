/*
 * keys.c: the key map every screen shares. See keys.h.
 */
#include "keys.h"

#include <curses.h>
#include <stdio.h>

#define CTRL(c) ((c) & 0x1f)

enum tui_action tui_key_action(int key)
{
    switch (key) {
    case 'k': case KEY_UP: return ACTION_UP;
    case 'j': case KEY_DOWN: return ACTION_DOWN;
    case 'h': case KEY_LEFT: return ACTION_LEFT;
    case 'l': case KEY_RIGHT: return ACTION_RIGHT;
    case KEY_PPAGE: case CTRL('b'): case CTRL('u'): return ACTION_PAGE_UP;
    case KEY_NPAGE: case CTRL('f'): case CTRL('d'): return ACTION_PAGE_DOWN;
    case 'g': case KEY_HOME: return ACTION_TOP;
    case 'G': case KEY_END: return ACTION_BOTTOM;
    case '/': return ACTION_SEARCH;
    case 'n': return ACTION_NEXT;
    case 'N': return ACTION_PREVIOUS;
    case '\n': case '\r': case KEY_ENTER: return ACTION_OPEN;
    case 'q': case 27: return ACTION_BACK;
    case KEY_F(10): return ACTION_QUIT;
    case '?': case KEY_F(1): return ACTION_HELP;
    case CTRL('l'): return ACTION_REDRAW;
    default: return ACTION_NONE;
    }
}

/* The key of "CSI n ~". */
static int tilde_key(int n)
{
    switch (n) {
    case 1: case 7: return KEY_HOME;
    case 2: return KEY_IC;
    case 3: return KEY_DC;
    case 4: case 8: return KEY_END;
    case 5: return KEY_PPAGE;
    case 6: return KEY_NPAGE;
    case 11: case 12: case 13: case 14: case 15: return KEY_F(n - 10);
    case 17: case 18: case 19: case 20: case 21: return KEY_F(n - 11);
    case 23: case 24: return KEY_F(n - 12);
    default: return TUI_KEY_NONE;
    }
}

/* The key of a final byte (CSI or SS3 A-D, H, F, P-S). */
static int final_key(int c)
{
    switch (c) {
    case 'A': return KEY_UP;
    case 'B': return KEY_DOWN;
    case 'C': return KEY_RIGHT;
    case 'D': return KEY_LEFT;
    case 'H': return KEY_HOME;
    case 'F': return KEY_END;
    case 'P': case 'Q': case 'R': case 'S': return KEY_F(c - 'P' + 1);
    default: return TUI_KEY_NONE;
    }
}

int tui_key_escape(int (*next)(void *context), void *context,
                   int *pushback)
{
    *pushback = -1;
    int c = next(context);
    if (c < 0)
        return 27;
    if (c == 27) {
        *pushback = 27;  /* Esc, Esc: two backs */
        return 27;
    }
    if (c == 'O') {      /* SS3: one more byte */
        int f = next(context);
        return f < 0 ? TUI_KEY_NONE : final_key(f);
    }
    if (c != '[')
        return TUI_KEY_NONE;  /* Alt-key: not a key of Facet */
    /* CSI: parameter bytes 0x30-0x3f, intermediates 0x20-0x2f, one final
     * byte 0x40-0x7e; the first parameter is read as a number. */
    int first = next(context), n = 0, params = 0, number = 1;
    if (first == '[') {   /* the Linux console's F1-F5: CSI [ A..E */
        int f = next(context);
        return f >= 'A' && f <= 'E' ? KEY_F(f - 'A' + 1) : TUI_KEY_NONE;
    }
    if (first == 'M') {   /* an X10 mouse report: three bytes follow */
        for (int k = 0; k < 3; k++)
            next(context);
        return TUI_KEY_NONE;
    }
    for (int k = 0, b = first; k < 64; k++, b = next(context)) {
        if (b < 0)
            return TUI_KEY_NONE;
        if (b >= 0x30 && b <= 0x3f) {
            params++;
            if (b >= '0' && b <= '9' && number)
                n = n * 10 + (b - '0');
            else
                number = 0;  /* ';' ends the first parameter, '<' etc. */
            continue;
        }
        if (b >= 0x20 && b <= 0x2f)
            continue;
        if (b < 0x40 || b > 0x7e)
            return TUI_KEY_NONE;
        if (b == '~')
            return params ? tilde_key(n) : TUI_KEY_NONE;
        return final_key(b);
    }
    return TUI_KEY_NONE;
}

const char *tui_key_name(int key, char buffer[16])
{
    static const struct { int key; const char *name; } names[] = {
        {KEY_UP, "Up"}, {KEY_DOWN, "Down"}, {KEY_LEFT, "Left"},
        {KEY_RIGHT, "Right"}, {KEY_PPAGE, "PgUp"}, {KEY_NPAGE, "PgDn"},
        {KEY_HOME, "Home"}, {KEY_END, "End"}, {'\n', "Enter"},
        {KEY_ENTER, "Enter"}, {27, "Esc"}, {' ', "Space"},
        {KEY_BACKSPACE, "Backspace"}, {127, "Backspace"}, {'\t', "Tab"},
        {KEY_DC, "Delete"},
    };
    for (size_t k = 0; k < sizeof names / sizeof names[0]; k++)
        if (names[k].key == key)
            return names[k].name;
    if (key >= KEY_F(1) && key <= KEY_F(12))
        snprintf(buffer, 16, "F%d", key - KEY_F(0));
    else if (key > 0 && key < 32)
        snprintf(buffer, 16, "Ctrl-%c", key + 'A' - 1);
    else if (key > 32 && key < 127)
        snprintf(buffer, 16, "%c", key);
    else
        snprintf(buffer, 16, "key %d", key);
    return buffer;
}
