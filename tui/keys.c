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
