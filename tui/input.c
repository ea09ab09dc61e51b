/*
 * input.c: the one-line editor. See input.h.
 */
#include "input.h"

#include <curses.h>
#include <string.h>

#define CTRL(c) ((c) & 0x1f)

void tui_input_set(struct tui_input *input, const char *text)
{
    size_t n = text ? strlen(text) : 0;
    if (n >= TUI_INPUT_MAX)
        n = TUI_INPUT_MAX - 1;
    if (n > 0)
        memcpy(input->text, text, n);
    input->text[n] = '\0';
    input->length = input->cursor = n;
}

/* Removes bytes [from, to). */
static void erase_range(struct tui_input *input, size_t from, size_t to)
{
    memmove(input->text + from, input->text + to, input->length - to + 1);
    input->length -= to - from;
    input->cursor = from;
}

enum tui_input_result tui_input_key(struct tui_input *input, int key)
{
    switch (key) {
    case '\n': case '\r': case KEY_ENTER:
        return INPUT_DONE;
    case 27:
        return INPUT_CANCEL;
    case KEY_BACKSPACE: case 127: case CTRL('h'):
        if (input->cursor > 0)
            erase_range(input, input->cursor - 1, input->cursor);
        return INPUT_EDITING;
    case KEY_DC: case CTRL('d'):
        if (input->cursor < input->length)
            erase_range(input, input->cursor, input->cursor + 1);
        return INPUT_EDITING;
    case KEY_LEFT: case CTRL('b'):
        if (input->cursor > 0)
            input->cursor--;
        return INPUT_EDITING;
    case KEY_RIGHT: case CTRL('f'):
        if (input->cursor < input->length)
            input->cursor++;
        return INPUT_EDITING;
    case KEY_HOME: case CTRL('a'):
        input->cursor = 0;
        return INPUT_EDITING;
    case KEY_END: case CTRL('e'):
        input->cursor = input->length;
        return INPUT_EDITING;
    case CTRL('u'):
        erase_range(input, 0, input->cursor);
        return INPUT_EDITING;
    case CTRL('k'):
        input->text[input->cursor] = '\0';
        input->length = input->cursor;
        return INPUT_EDITING;
    case CTRL('w'): {
        size_t from = input->cursor;
        while (from > 0 && input->text[from - 1] == ' ')
            from--;
        while (from > 0 && input->text[from - 1] != ' ')
            from--;
        erase_range(input, from, input->cursor);
        return INPUT_EDITING;
    }
    default:
        break;
    }
    if (key >= 32 && key <= 255 && key != 127) {
        if (input->length + 1 >= TUI_INPUT_MAX)
            return INPUT_EDITING;
        memmove(input->text + input->cursor + 1, input->text + input->cursor,
                input->length - input->cursor + 1);
        input->text[input->cursor++] = (char)key;
        input->length++;
        return INPUT_EDITING;
    }
    return INPUT_IGNORED;
}

size_t tui_input_scroll(const struct tui_input *input, int width)
{
    if (width < 2)
        return input->cursor;
    size_t w = (size_t)width - 1;
    return input->cursor > w ? input->cursor - w : 0;
}
