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
    err->setting = FACET_SETTING_NONE;
    err->message[0] = '\0';
    err->value[0] = '\0';
}

static void set(struct facet_error *err, enum facet_setting setting,
                int code, const char *fmt, va_list ap)
{
    vsnprintf(err->message, sizeof err->message, fmt, ap);
    err->code = code;
    err->setting = setting;
    err->value[0] = '\0';
}

int facet_error_set(struct facet_error *err, int code, const char *fmt, ...)
{
    if (err != NULL) {
        va_list ap;
        va_start(ap, fmt);
        set(err, FACET_SETTING_NONE, code, fmt, ap);
        va_end(ap);
    }
    return code;
}

int facet_error_about(struct facet_error *err, enum facet_setting setting,
                      int code, const char *fmt, ...)
{
    if (err != NULL) {
        va_list ap;
        va_start(ap, fmt);
        set(err, setting, code, fmt, ap);
        va_end(ap);
    }
    return code;
}

int facet_error_about_value(struct facet_error *err,
                            enum facet_setting setting, const char *value,
                            int code, const char *fmt, ...)
{
    if (err != NULL) {
        va_list ap;
        va_start(ap, fmt);
        set(err, setting, code, fmt, ap);
        va_end(ap);
        snprintf(err->value, sizeof err->value, "%s", value);
    }
    return code;
}
