/*
 * text.c: clean text for terminals and stores. See text.h.
 */
#include "core/base/text.h"

#include <assert.h>
#include <string.h>

/* The length of the valid UTF-8 character at s (1 to 4), or 0 when the
 * bytes there are not one. */
static size_t utf8_length(const unsigned char *s)
{
    if (s[0] < 0x80)
        return 1;
    size_t n;
    unsigned min;
    unsigned code;
    if ((s[0] & 0xe0) == 0xc0) {
        n = 2, min = 0x80, code = s[0] & 0x1f;
    } else if ((s[0] & 0xf0) == 0xe0) {
        n = 3, min = 0x800, code = s[0] & 0x0f;
    } else if ((s[0] & 0xf8) == 0xf0) {
        n = 4, min = 0x10000, code = s[0] & 0x07;
    } else {
        return 0;
    }
    for (size_t k = 1; k < n; k++) {
        if ((s[k] & 0xc0) != 0x80)
            return 0;
        code = (code << 6) | (s[k] & 0x3f);
    }
    if (code < min || code > 0x10ffff || (code >= 0xd800 && code <= 0xdfff))
        return 0;
    return n;
}

/* Whether the character of length n at s is a control character: C0,
 * DEL, or C1 (U+0080 to U+009F, encoded C2 80 to C2 9F). */
static int is_control(const unsigned char *s, size_t n)
{
    if (n == 1)
        return s[0] < 0x20 || s[0] == 0x7f;
    return n == 2 && s[0] == 0xc2 && s[1] < 0xa0;
}

size_t text_char_length(const char *text)
{
    return utf8_length((const unsigned char *)text);
}

int text_char_is_control(const char *text, size_t n)
{
    return is_control((const unsigned char *)text, n);
}

int text_is_clean(const char *text)
{
    const unsigned char *s = (const unsigned char *)text;
    while (*s != '\0') {
        size_t n = utf8_length(s);
        if (n == 0 || is_control(s, n))
            return 0;
        s += n;
    }
    return 1;
}

void text_for_terminal(const char *text, char *out, size_t size)
{
    assert(size >= 1);
    const unsigned char *s = (const unsigned char *)text;
    size_t used = 0;
    while (*s != '\0') {
        size_t n = utf8_length(s);
        int bad = n == 0 || is_control(s, n);
        size_t take = bad ? 1 : n;
        if (used + (bad ? 1 : n) + 1 > size)
            break;  /* on a character boundary */
        if (bad) {
            out[used++] = '?';
        } else {
            memcpy(out + used, s, n);
            used += n;
        }
        s += take;
    }
    out[used] = '\0';
}

/* The units a figure is shown with, so that a row never ends between a
 * figure and its unit. */
static const char *const unit_words[] = {
    "mm", "m", "m^2", "m\xc2\xb2", "km", "%", "\xc2\xb0", "deg", "rad",
    "s", "ms", "kg", "USD", "EUR", "1/m",
};

/* 1 when the blank at text + at (at > 0) follows a digit and comes before
 * a unit word, which may end in punctuation ("mm," "mm)"). */
static int joins_unit(const char *text, size_t at)
{
    if (text[at - 1] < '0' || text[at - 1] > '9')
        return 0;
    const char *word = text + at + 1;
    size_t n = strcspn(word, " ");
    while (n > 0 && strchr(",;:.)]", word[n - 1]) != NULL)
        n--;
    for (size_t k = 0; k < sizeof unit_words / sizeof unit_words[0]; k++)
        if (strlen(unit_words[k]) == n && memcmp(word, unit_words[k], n) == 0)
            return 1;
    return 0;
}

/* The bytes of the column at s (not at its end): a character, or a byte
 * that is not one. */
static size_t column_bytes(const char *s)
{
    size_t n = utf8_length((const unsigned char *)s);
    return n > 0 ? n : 1;
}

size_t text_columns(const char *text)
{
    size_t columns = 0;
    for (size_t at = 0; text[at] != '\0'; at += column_bytes(text + at))
        columns++;
    return columns;
}

size_t text_cut(const char *text, int width)
{
    size_t at = 0;
    for (int columns = 0; text[at] != '\0' && columns < width; columns++)
        at += column_bytes(text + at);
    return at;
}

size_t text_break(const char *text, int width)
{
    assert(width >= 1);
    size_t at = 0, blank = 0, glued = 0;
    for (int columns = 0; text[at] != '\0' && columns < width; columns++) {
        at += column_bytes(text + at);
        if (text[at] == ' ') {
            if (joins_unit(text, at))
                glued = at;
            else
                blank = at;
        }
    }
    if (text[at] == '\0')
        return at;
    if (blank > 0)
        return blank;
    return glued > 0 ? glued : at;
}
