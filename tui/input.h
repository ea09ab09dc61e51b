/*
 * input.h: a one-line text editor (the filter line, the search line, the
 * fields of the New run form): the buffer and what keys do to it. Drawing
 * is the screen's; this file only edits, so the unit tests can drive it.
 */
#ifndef FACET_TUI_INPUT_H
#define FACET_TUI_INPUT_H

#include <stddef.h>

#define TUI_INPUT_MAX 1024

struct tui_input {
    char text[TUI_INPUT_MAX];
    size_t length;
    size_t cursor;      /* byte offset, 0..length */
};

enum tui_input_result {
    INPUT_EDITING,      /* the key edited or moved; keep going */
    INPUT_DONE,         /* Enter */
    INPUT_CANCEL,       /* Esc */
    INPUT_IGNORED       /* not an editing key (Tab, Up, Down, F-keys) */
};

/* Sets the text (truncated to fit) with the cursor at its end. */
void tui_input_set(struct tui_input *input, const char *text);

/* Applies key: printable characters insert, Backspace/Delete erase,
 * Left/Right/Home/End/Ctrl-A/Ctrl-E move, Ctrl-U clears to the start,
 * Ctrl-K to the end, Ctrl-W erases a word. */
enum tui_input_result tui_input_key(struct tui_input *input, int key);

/* The first byte of text to show so that the cursor fits in width
 * columns. */
size_t tui_input_scroll(const struct tui_input *input, int width);

#endif
