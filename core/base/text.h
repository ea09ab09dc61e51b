/*
 * text.h: text from users and files, made safe to show and to store.
 *
 * Run names, surface paths and OBJ names come from outside. Printed raw,
 * an escape sequence in one can retitle the terminal or forge a table
 * line; cut at a byte count, a name can end inside a UTF-8 character and
 * make the JSON that carries it invalid.
 */
#ifndef FACET_TEXT_H
#define FACET_TEXT_H

#include <stddef.h>

/* 1 when text is valid UTF-8 (no overlong forms, no surrogates) without
 * control characters (C0, DEL, C1), else 0. */
int text_is_clean(const char *text);

/* Copies text into out (size bytes, at least 1) for a terminal: control
 * characters and bytes that are not valid UTF-8 become '?', and the copy
 * is cut on a character boundary. */
void text_for_terminal(const char *text, char *out, size_t size);

/* The bytes (1 to 4) of the valid UTF-8 character text starts with, or 0
 * when they are not one; text is not empty. With text_char_is_control,
 * for writers that clean as they go (JSON keeps a control character,
 * escaped, where a terminal gets '?'). */
size_t text_char_length(const char *text);

/* 1 when the character of n bytes at text (text_char_length) is a control
 * character: C0, DEL or C1. */
int text_char_is_control(const char *text, size_t n);

/* The display columns of text: a character is one column whatever its
 * bytes, and a byte that is not UTF-8 one too, as a terminal shows it
 * ('?'). */
size_t text_columns(const char *text);

/* The bytes of text's first width display columns (text_columns' count;
 * all of text when it is narrower, 0 when width is 0 or less): a cut on a
 * character's boundary. */
size_t text_cut(const char *text, int width);

/* The bytes of text's next row of at most width display columns (width at
 * least 1), for a wrapper that prints them, skips the blanks after them and
 * asks again. A character is one column whatever its bytes, and a byte
 * that is not UTF-8 one column too, as a terminal shows it ('?'). The row
 * is all of text when it fits; else it ends at the last blank within
 * width + 1 columns, but not at the blank between a number and its unit
 * ("4.00 mm", "1,240 m^2") while another blank will do, so that a unit
 * stays with its figure; else (one word wider than the row) the word is
 * cut after width columns, on a character's boundary. Never 0 for a text
 * that is not empty. */
size_t text_break(const char *text, int width);

#endif
