/*
 * shown.c: text Facet did not write, shown and never obeyed. See shown.h.
 */
#include "shown.h"

#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#include "core/base/text.h"

void shown_text(FILE *out, const char *text)
{
    while (*text != '\0') {
        size_t n = text_char_length(text);
        if (n == 0 || text_char_is_control(text, n)) {
            fputc('?', out);
            text++;  /* one '?' a byte, as text_for_terminal */
            continue;
        }
        fwrite(text, 1, n, out);
        text += n;
    }
}

void shown_cell(FILE *out, const char *text, int width)
{
    shown_text(out, text);
    for (int k = (int)strlen(text); k < width; k++)
        fputc(' ', out);
}

void shown_line(FILE *out, const char *format, ...)
{
    va_list args;
    va_start(args, format);
    char small[1024];
    int length = vsnprintf(small, sizeof small, format, args);
    va_end(args);
    char *line = small;
    /* A line longer than small: formatted again into memory of its size,
     * so no name is cut; without the memory, what fitted is shown. */
    if (length >= (int)sizeof small) {
        char *big = malloc((size_t)length + 1);
        if (big != NULL) {
            va_start(args, format);
            vsnprintf(big, (size_t)length + 1, format, args);
            va_end(args);
            line = big;
        }
    }
    if (length >= 0)
        shown_text(out, line);
    fputc('\n', out);
    if (line != small)
        free(line);
}
