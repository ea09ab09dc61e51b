/*
 * project_locate.c: finding a statement's line. See project_locate.h.
 */
#include "core/project/project_locate.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int blank(char c)
{
    return c == ' ' || c == '\t' || c == '\r' || c == '\n';
}

/* Reads path statement by statement; calls match(statement, data) with
 * the statement's text (continuations joined by a space, ends trimmed)
 * and returns the line where the first match starts, or 0. */
static size_t find(const char *path,
                   int (*match)(const char *statement, void *data),
                   void *data)
{
    FILE *in = fopen(path, "r");
    if (in == NULL)
        return 0;
    char *line = NULL, *joined = NULL;
    size_t size = 0, joined_size = 0, joined_length = 0;
    size_t number = 0, start = 0, found = 0;
    ssize_t got;
    while (found == 0 && (got = getline(&line, &size, in)) >= 0) {
        number++;
        if (joined_length == 0)
            start = number;
        size_t n = (size_t)got;
        while (n > 0 && (line[n - 1] == '\n' || line[n - 1] == '\r'))
            n--;
        int continued = n > 0 && line[n - 1] == '\\';
        if (continued)
            line[n - 1] = ' ';
        if (joined_length + n + 1 > joined_size) {
            size_t want = 2 * (joined_length + n + 1);
            char *grown = realloc(joined, want);
            if (grown == NULL)
                break;
            joined = grown;
            joined_size = want;
        }
        memcpy(joined + joined_length, line, n);
        joined_length += n;
        joined[joined_length] = '\0';
        if (continued)
            continue;
        char *text = joined;
        while (*text != '\0' && blank(*text))
            text++;
        size_t length = strlen(text);
        while (length > 0 && blank(text[length - 1]))
            text[--length] = '\0';
        if (match(text, data))
            found = start;
        joined_length = 0;
    }
    free(line);
    free(joined);
    fclose(in);
    return found;
}

struct face_count {
    size_t wanted, seen;
};

static int match_face(const char *statement, void *data)
{
    struct face_count *count = data;
    if (statement[0] != 'f' || !blank(statement[1]))
        return 0;
    return count->seen++ == count->wanted;
}

size_t locate_face(const char *path, size_t face)
{
    struct face_count count = {face, 0};
    return find(path, match_face, &count);
}

struct name_wanted {
    const char *keyword, *name;
};

static int match_name(const char *statement, void *data)
{
    const struct name_wanted *want = data;
    size_t k = strlen(want->keyword);
    if (strncmp(statement, want->keyword, k) != 0 || !blank(statement[k]))
        return 0;
    statement += k;
    while (blank(*statement))
        statement++;
    return strcmp(statement, want->name) == 0;
}

size_t locate_name(const char *path, const char *keyword, const char *name)
{
    struct name_wanted want = {keyword, name};
    return find(path, match_name, &want);
}
