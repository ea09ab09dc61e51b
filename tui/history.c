/*
 * history.c: a prompt's texts of a session. See history.h.
 */
#include "history.h"

#include <stdio.h>
#include <string.h>

void tui_history_add(struct tui_history *h, const char *text, int refused)
{
    h->at = h->n;
    if (text[0] == '\0')
        return;
    if (h->n > 0 && strcmp(h->text[h->n - 1], text) == 0) {
        h->refused = refused;
        return;
    }
    if (h->n == TUI_HISTORY_MAX) {
        memmove(h->text[0], h->text[1],
                (TUI_HISTORY_MAX - 1) * sizeof h->text[0]);
        h->n--;
    }
    snprintf(h->text[h->n], sizeof h->text[0], "%s", text);
    h->n++;
    h->at = h->n;
    h->refused = refused;
}

void tui_history_open(struct tui_history *h)
{
    h->at = h->n;
    h->typed[0] = '\0';
}

const char *tui_history_refused(const struct tui_history *h)
{
    return h->n > 0 && h->refused ? h->text[h->n - 1] : NULL;
}

const char *tui_history_step(struct tui_history *h, int step,
                             const char *current)
{
    int to = h->at + (step < 0 ? -1 : 1);
    if (to < 0 || to > h->n)
        return NULL;
    /* leaving what is being typed keeps it for the way back */
    if (h->at == h->n)
        snprintf(h->typed, sizeof h->typed, "%s", current);
    h->at = to;
    return to == h->n ? h->typed : h->text[to];
}
