/*
 * json.h: writing JSON to a stdio stream, with commas and escaping handled.
 *
 * A struct json_writer tracks nesting so that callers write keys and values
 * in order and never place a comma by hand:
 *
 *     json_begin_object(&w);
 *     json_key(&w, "area"); json_number(&w, 1240.5);
 *     json_end_object(&w);
 *
 * Numbers are written so that they read back exactly (numformat.h);
 * non-finite numbers are written as null (JSON has no NaN).
 */
#ifndef FACET_JSON_H
#define FACET_JSON_H

#include <stdio.h>

#define JSON_MAX_DEPTH 32

struct json_writer {
    FILE *out;
    int depth;
    int count[JSON_MAX_DEPTH];  /* values written at each level */
    int after_key;              /* a key was written, its value is next */
};

void json_init(struct json_writer *w, FILE *out);
void json_begin_object(struct json_writer *w);
void json_end_object(struct json_writer *w);
void json_begin_array(struct json_writer *w);
void json_end_array(struct json_writer *w);
void json_key(struct json_writer *w, const char *key);
void json_string(struct json_writer *w, const char *text);
/* The shortest decimal that reads back as number (number_exact). */
void json_number(struct json_writer *w, double number);
void json_integer(struct json_writer *w, long long number);
void json_bool(struct json_writer *w, int truth);
void json_null(struct json_writer *w);

/* Ends the document with a newline. */
void json_finish(struct json_writer *w);

#endif
