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

#endif
