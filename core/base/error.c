/*
 * error.c: filling struct facet_error. See error.h.
 */
#include "core/base/error.h"

#include <stdarg.h>
#include <stdio.h>

/* Facet states its internal invariants as assert()s and keeps them in the
 * optimised build (a broken invariant stops the program instead of
 * printing a wrong number); the Makefile never defines NDEBUG. */
#ifdef NDEBUG
#error "build Facet without NDEBUG: its invariants are assert()s"
#endif

void facet_error_clear(struct facet_error *err)
{
    if (err == NULL)
        return;
    err->code = FACET_OK;
    err->message[0] = '\0';
}

int facet_error_set(struct facet_error *err, int code, const char *fmt, ...)
{
    if (err != NULL) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(err->message, sizeof err->message, fmt, ap);
        va_end(ap);
        err->code = code;
    }
    return code;
}
