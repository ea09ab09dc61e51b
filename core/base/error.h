/*
 * error.h: the one error convention of Facet.
 *
 * A function that can fail returns int: 0 on success, otherwise one of the
 * FACET_E* codes below, and fills a caller-owned struct facet_error with a
 * one-line message naming the file, line or value at fault. Nothing below
 * cli/ prints or exits; the CLI prints err.message and exits with err.code.
 *
 * The user's words stay with the front-end. Below cli/ no message names a
 * command-line flag ("--threshold"), for the same message reaches a user
 * of the TUI's forms, who has fields and keys instead. Two rules keep it so:
 *
 *   - A parser or check of something the user typed takes the field's
 *     name from its caller, as `what` (e.g. mesh_units_parse(text,
 *     "--units", ...) in the CLI, "Units" in the New-run form), and
 *     starts its message with it.
 *   - A message that tells the user to change a setting they did not type
 *     here (overwrite the output, pick one object of the file, say the
 *     file's units, give a moved surface's place) or that is about a
 *     setting whose text it quotes (a filter, a sort) names the thing in
 *     words, and sets err->setting (facet_error_about) to that setting.
 *     Each front-end words it: the CLI (cli/main.c) adds its flag, e.g.
 *     " (pass --force to overwrite it)" or "--where: " before a filter's
 *     message; the TUI its field or nothing.
 *
 * A warning (surface.h) is text kept with the run and shown by every
 * front-end, so it names a setting in words only ("set its units to mm").
 * tests/e2e/layers.sh fails on a "--flag" word in a string below cli/.
 */
#ifndef FACET_ERROR_H
#define FACET_ERROR_H

enum {
    FACET_OK = 0,
    FACET_EWORK = 1,  /* failure while working: out of memory, I/O error */
    FACET_EINPUT = 2, /* bad usage or bad input: the user can fix it */
    FACET_ESTOP = 3   /* stopped at the caller's request (stop.h): not a
                         failure; the front-end says what was stopped and
                         exits as for the signal that asked */
};

/* The setting a message is about, or whose change puts the error right;
 * the front-end names it in its own words. */
enum facet_setting {
    FACET_SETTING_NONE = 0,
    FACET_SETTING_OVERWRITE,  /* fix: replace the output file that exists */
    FACET_SETTING_OBJECT,     /* fix: read one object of the file */
    FACET_SETTING_GROUP,      /* fix: read one group of the file */
    FACET_SETTING_CHART,      /* fix: one object or group of the file, or
                                 a harmonic UV */
    FACET_SETTING_UNITS,      /* fix: the file's units */
    FACET_SETTING_SURFACE,    /* fix: the moved surface's new place */
    FACET_SETTING_STORE,      /* fix: a run that creates the result store */
    FACET_SETTING_FILTER,     /* about: the filter expression */
    FACET_SETTING_SORT,       /* about: the sort columns */
    FACET_SETTING_MODULE,     /* fix: a panel module for a project, or one
                                 object or group of the file */
    FACET_SETTING_FEWER,      /* fix: let a merge replace a merged run with
                                 one of fewer shards */
    FACET_SETTING_MIGRATE,    /* fix: bring an older Facet's database to
                                 this Facet's schema, as a writer */
    FACET_SETTING_COUNT
};

struct facet_error {
    int code;                   /* FACET_OK or FACET_E* */
    enum facet_setting setting; /* FACET_SETTING_NONE unless the message
                                   is about a setting (see above) */
    char message[1024];         /* one line, no trailing newline */
    char value[16];             /* the value the setting should take, when
                                   the message knows it ("mm"), else "" */
};

/* Clears err to FACET_OK with an empty message. err may be NULL. */
void facet_error_clear(struct facet_error *err);

/* Sets err (if not NULL) to code and a printf-formatted message, with no
 * setting, and returns code so that callers can write `return
 * facet_error_set(err, ...)`. */
int facet_error_set(struct facet_error *err, int code, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

/* facet_error_set, the message being about setting (see above). */
int facet_error_about(struct facet_error *err, enum facet_setting setting,
                      int code, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));

/* facet_error_about, with the value the setting should take (at most 15
 * bytes), for the front-end to name with its flag. */
int facet_error_about_value(struct facet_error *err,
                            enum facet_setting setting, const char *value,
                            int code, const char *fmt, ...)
    __attribute__((format(printf, 5, 6)));

#endif
