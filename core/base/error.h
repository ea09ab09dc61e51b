/*
 * error.h: the one error convention of Facet.
 *
 * A function that can fail returns int: 0 on success, otherwise one of the
 * FACET_E* codes below, and fills a caller-owned struct facet_error with a
 * one-line message naming the file, line or value at fault. Nothing below
 * cli/ prints or exits; the CLI prints err.message and exits with err.code.
 */
#ifndef FACET_ERROR_H
#define FACET_ERROR_H

enum {
    FACET_OK = 0,
    FACET_EWORK = 1,  /* failure while working: out of memory, I/O error */
    FACET_EINPUT = 2  /* bad usage or bad input: the user can fix it */
};

struct facet_error {
    int code;           /* FACET_OK or FACET_E* */
    char message[512];  /* one line, no trailing newline */
};

/* Clears err to FACET_OK with an empty message. err may be NULL. */
void facet_error_clear(struct facet_error *err);

/* Sets err (if not NULL) to code and a printf-formatted message, and returns
 * code so that callers can write `return facet_error_set(err, ...)`. */
int facet_error_set(struct facet_error *err, int code, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

#endif
