/*
 * json.c: the JSON writer. See json.h.
 */
#include "core/out/json.h"

#include <math.h>

#include "core/base/numformat.h"
#include "core/base/text.h"

void json_init(struct json_writer *w, FILE *out)
{
    w->out = out;
    w->depth = 0;
    w->count[0] = 0;
    w->after_key = 0;
}

/* Writes the comma that separates this value from the previous one. */
static void before_value(struct json_writer *w)
{
    if (w->after_key) {
        w->after_key = 0;
        return;
    }
    if (w->count[w->depth] > 0)
        fputc(',', w->out);
    w->count[w->depth]++;
}

static void open_level(struct json_writer *w, char bracket)
{
    before_value(w);
    fputc(bracket, w->out);
    if (w->depth + 1 < JSON_MAX_DEPTH)
        w->depth++;
    w->count[w->depth] = 0;
}

static void close_level(struct json_writer *w, char bracket)
{
    fputc(bracket, w->out);
    if (w->depth > 0)
        w->depth--;
}

void json_begin_object(struct json_writer *w) { open_level(w, '{'); }
void json_end_object(struct json_writer *w) { close_level(w, '}'); }
void json_begin_array(struct json_writer *w) { open_level(w, '['); }
void json_end_array(struct json_writer *w) { close_level(w, ']'); }

/* Writes text as a JSON string. JSON must be UTF-8, and names, paths and
 * warnings come from files and stores that need not be: a byte that is not
 * part of a valid UTF-8 character becomes '?', as on a terminal
 * (text_for_terminal). Control characters (C0, DEL, C1) are kept but
 * escaped, so that no reader of the JSON is sent one raw. */
static void write_string(FILE *out, const char *text)
{
    fputc('"', out);
    for (const char *c = text; *c != '\0';) {
        size_t n = text_char_length(c);
        unsigned char first = (unsigned char)c[0];
        if (n == 0) {
            fputc('?', out);
            n = 1;
        } else if (first == '"') {
            fputs("\\\"", out);
        } else if (first == '\\') {
            fputs("\\\\", out);
        } else if (first == '\n') {
            fputs("\\n", out);
        } else if (first == '\r') {
            fputs("\\r", out);
        } else if (first == '\t') {
            fputs("\\t", out);
        } else if (text_char_is_control(c, n)) {
            /* C1 is U+0080 to U+009F, its second byte the code point */
            fprintf(out, "\\u%04x", n == 1 ? first : (unsigned char)c[1]);
        } else {
            fwrite(c, 1, n, out);
        }
        c += n;
    }
    fputc('"', out);
}

void json_key(struct json_writer *w, const char *key)
{
    before_value(w);
    write_string(w->out, key);
    fputc(':', w->out);
    w->after_key = 1;
}

void json_string(struct json_writer *w, const char *text)
{
    before_value(w);
    write_string(w->out, text);
}

void json_number(struct json_writer *w, double number)
{
    before_value(w);
    if (isfinite(number)) {
        char text[NUMBER_EXACT_SIZE];
        number_exact(text, number);
        fputs(text, w->out);
    } else {
        fputs("null", w->out);
    }
}

void json_integer(struct json_writer *w, long long number)
{
    before_value(w);
    fprintf(w->out, "%lld", number);
}

void json_bool(struct json_writer *w, int truth)
{
    before_value(w);
    fputs(truth ? "true" : "false", w->out);
}

void json_null(struct json_writer *w)
{
    before_value(w);
    fputs("null", w->out);
}

void json_finish(struct json_writer *w)
{
    fputc('\n', w->out);
}
