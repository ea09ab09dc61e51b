/*
 * main.c: the facet entry point. Finds the subcommand in the table, handles
 * --help everywhere, runs it, and turns its error into one line on stderr
 * and the exit status (0 ok, 1 failure while working, 2 bad usage or input).
 */
#include <errno.h>
#include <malloc.h>
#include <stdio.h>
#include <string.h>

#include "classify_flags.h"
#include "command.h"
#include "core/base/spelling.h"
#include "shown.h"

/* The CLI's words for the setting an error is about (core/base/error.h):
 * its flag, before the message or after it. */
static const struct {
    const char *before, *after;
} setting_words[FACET_SETTING_COUNT] = {
    [FACET_SETTING_NONE] = {"", ""},
    [FACET_SETTING_OVERWRITE] = {"", " (pass --force to overwrite it)"},
    [FACET_SETTING_OBJECT] = {"", " with --object NAME"},
    [FACET_SETTING_GROUP] = {"", " with --group NAME"},
    [FACET_SETTING_CHART] = {"", " (--object NAME or --group NAME, or "
                                 "--uv harmonic)"},
    [FACET_SETTING_UNITS] = {"", " (--units)"},
    [FACET_SETTING_SURFACE] = {"", " with --surface FILE"},
    [FACET_SETTING_STORE] = {"", "; facet optimize --db FILE makes one"},
    [FACET_SETTING_FILTER] = {"--where: ", ""},
    [FACET_SETTING_SORT] = {"--sort: ", ""},
    [FACET_SETTING_MODULE] = {"", ": give --module WMIN:WMAX x HMIN:HMAX "
                                  "(or --object NAME for one surface)"},
    [FACET_SETTING_FEWER] = {"", ", or pass --fewer to replace it"},
    [FACET_SETTING_MIGRATE] = {"", " (facet migrate FILE migrates it)"},
};

/* Prints the error in one line. Its message can quote what Facet did not
 * write (a stored path, an OBJ token, SQLite's own text, a trigger's
 * message), so all of it is cleaned (shown.h): no escape sequence reaches
 * the terminal, no newline makes a second line. */
static void print_error(const struct facet_error *err)
{
    enum facet_setting s = err->setting;
    if ((unsigned)s >= FACET_SETTING_COUNT || setting_words[s].before == NULL)
        s = FACET_SETTING_NONE;
    const char *message = err->message[0] ? err->message : "failed";
    /* Units Facet can name (surface_units_check): the flag to give, and
     * the one that reads the file as it was read. */
    if (s == FACET_SETTING_UNITS && err->value[0] != '\0') {
        struct surface_flags none = {NULL, NULL, NULL};
        struct mesh_options as_read;
        struct facet_error ignored;
        surface_flags_apply(&none, &as_read, &ignored);
        shown_line(stderr, "facet: %s: give --units %s (or --units %s to "
                   "go on as read)", message, err->value,
                   mesh_units_name(as_read.units));
        return;
    }
    shown_line(stderr, "facet: %s%s%s", setting_words[s].before, message,
               setting_words[s].after);
}

static int wants_help(int argc, char **argv)
{
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--") == 0)
            return 0;
        if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0)
            return 1;
    }
    return 0;
}

int main(int argc, char **argv)
{
    /* An optimize run frees and allocates the same large arrays (a
     * grid's lattice, its panels' geometry) for every option. glibc's
     * default gives each above its sliding mmap threshold back to the
     * kernel when freed, and trims the heap's top past 128 kB, so the
     * next option faults the same pages in again: 13 % of the paper
     * study's time was page faults. Kept in the process instead (up to
     * 32 MB an array, the most glibc allows; the heap trimmed past
     * 64 MB, so an idle workbench holds little more than it used), the
     * paper study took 9-15 % less wall time for 9 % more peak memory
     * (medians of 5 alternating runs; 1 GB or 256 MB kept gained no
     * more). */
    mallopt(M_MMAP_THRESHOLD, 32 << 20);
    mallopt(M_TRIM_THRESHOLD, 64 << 20);
    if (argc < 2) {
        command_print_overview(stderr);
        return 2;
    }
    if (strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0) {
        command_print_overview(stdout);
        return 0;
    }
    if (strcmp(argv[1], "--version") == 0) {
        printf("facet %s\n", FACET_VERSION);
        return 0;
    }
    const struct command *cmd = command_find(argv[1]);
    if (cmd == NULL) {
        const char *names[32];
        size_t n = 0;
        for (int i = 0; command_table[i] != NULL && n < 32; i++)
            names[n++] = command_table[i]->name;
        const char *near = spelling_closest(argv[1], strlen(argv[1]), names,
                                            n);
        if (near != NULL)
            shown_line(stderr, "facet: unknown command '%s' (did you mean "
                       "'facet %s'?)", argv[1], near);
        else
            shown_line(stderr, "facet: unknown command '%s' (see 'facet "
                       "--help')", argv[1]);
        return 2;
    }
    if (wants_help(argc - 1, argv + 1)) {
        command_print_usage(cmd, stdout);
        return 0;
    }

    struct facet_error err;
    facet_error_clear(&err);
    int status = cmd->run(argc - 1, argv + 1, &err);
    /* 128 + a signal (an interrupted run: 129, 130, 143) is not a
     * failure: the command said what it did. */
    if (status != 0 && status <= 128) {
        fflush(stdout);
        print_error(&err);
    }
    /* What went to stdout (a table, JSON, CSV) must have got there: a full
     * disk, /dev/full or a closed pipe is a failure, not a silent exit 0.
     * Closing flushes and reports the last write's error too. */
    errno = 0;
    int lost = ferror(stdout) != 0;
    if (fclose(stdout) != 0)
        lost = 1;
    if (lost && status == 0) {
        fprintf(stderr, "facet: writing standard output failed%s%s\n",
                errno ? ": " : "", errno ? strerror(errno) : "");
        status = 1;
    }
    return status;
}
