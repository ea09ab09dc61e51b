/*
 * shown.h: printing text Facet did not write (names, paths, warnings,
 * stored text, SQLite's messages) so that it is shown, never obeyed.
 *
 * An OBJ name, a stored warning or a trigger's message can carry an
 * escape sequence (retitle the terminal, clear it) or a newline (forge a
 * line of output). Every such text reaches a terminal through here or
 * through text_for_terminal (core/base/text.h): control characters and
 * bytes that are not UTF-8 become '?'.
 */
#ifndef FACET_SHOWN_H
#define FACET_SHOWN_H

#include <stdio.h>

/* Writes text cleaned as text_for_terminal cleans it, whatever its
 * length. Cleaning keeps the byte count, so "%-20s" widths still hold. */
void shown_text(FILE *out, const char *text);

/* Writes text cleaned, then blanks to width bytes (left-aligned). */
void shown_cell(FILE *out, const char *text, int width);

/* Formats one line (printf), cleans all of it and ends it with a newline:
 * a newline inside the line becomes '?'. */
void shown_line(FILE *out, const char *format, ...)
    __attribute__((format(printf, 2, 3)));

#endif
