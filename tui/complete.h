/*
 * complete.h: Tab completion of a file path (the New run form's surface
 * field): the directory named so far is listed, and the entries that
 * begin with the rest are the candidates: directories (with a '/') and
 * OBJ files (.obj, any case), hidden ones only when the rest begins with
 * a dot. No curses here.
 */
#ifndef FACET_TUI_COMPLETE_H
#define FACET_TUI_COMPLETE_H

#include <stddef.h>

#define TUI_COMPLETE_MAX 64     /* candidates kept (sorted) */
#define TUI_COMPLETE_NAME 256

struct tui_completion {
    char text[1024];            /* the path completed as far as it goes */
    int count;                  /* candidates in all */
    int kept;                   /* of them in name[] (<= TUI_COMPLETE_MAX) */
    char name[TUI_COMPLETE_MAX][TUI_COMPLETE_NAME];  /* sorted, dirs end
                                                        with '/' */
};

/* Completes path (which may be out->text): out->text is path extended by what every candidate
 * shares (the whole name, and '/' for a directory, when there is one
 * candidate), out->count and out->name the candidates. An unreadable
 * directory has none. Returns out->count. */
int tui_complete_path(const char *path, struct tui_completion *out);

#endif
