/*
 * numrange.h: the two syntaxes in which a designer writes a design space,
 * on the command line and in the TUI's New-run form alike, one parser
 * each, which every caller uses:
 *
 *   a range  A, A:B or A:B:STEP  "20:40" (panels along u), "1:5:0.5" (a
 *                                threshold), each side of a module range
 *   a pair   LEFT x RIGHT        a grid "37x49" (numrange_grid), a module
 *                                range "1.2:2.0 x 1.0:1.6" (module.h)
 *
 * Numbers are read as numparse.h reads them: as written, never wrapped or
 * rounded. A whole number is digits only (no sign, no blank, no 0x:
 * 4294967297 is out of range, not 1); a decimal is [+-]digits[.digits]
 * [e[+-]digits], never nan, inf or hexadecimal. A range has no blanks. A
 * pair has exactly one x (or X); blanks (spaces, tabs) may stand around
 * it and at either end, and neither side may be empty.
 *
 * A range's limits are its caller's (struct numrange_spec): every A and B
 * within [least, most], A <= B ("A" alone is A:A), a step above 0, at
 * least step_least and at most most, and at most values_max values, the
 * values being A, A + STEP, ... up to B, B included when it falls on a
 * step to within slack of a step (numrange_count). A range written
 * without a step takes step_default (0: a continuous range, which has no
 * count). A -0 is read as 0.
 *
 * Every message is one line that starts with what, the caller's name for
 * the setting ("--u" on the command line, "U (panels)" in the form), and
 * quotes the text as typed:
 *
 *   --u: '2x3' is not N or a range A:B of whole numbers
 *   --threshold: 'a' is not a number, A:B or A:B:STEP
 *   --u: '0:5' is out of range (1 to 2000)
 *   --module width: '0:1' is out of range (at least 0.001)
 *   --threshold: 5:1 runs backwards
 *   --threshold: the step of '1:5:0' must be above 0
 *   --module width: the step of '1:2:1e-12' must be at least 0.001
 *   --threshold: '0:1e6:1e-300' is 1e+306 steps (at most 1000000: take a
 *       larger step, or a continuous range A:B)
 *   --grid: '37by49' is not NUxNV (e.g. 37x49)
 *   --grid: '0x5' is out of range (each side 1 to 2000)
 *
 * A number too large for a double (1e999, 99999999999999999999) is out of
 * range, as a value beyond most is.
 */
#ifndef FACET_NUMRANGE_H
#define FACET_NUMRANGE_H

#include "core/base/error.h"

/* What a caller's range may hold. */
struct numrange_spec {
    int whole;           /* whole numbers (least >= 0), else decimals */
    double least, most;  /* A and B within; most DBL_MAX: no upper limit */
    int stepped;         /* 1: a third part, STEP, may be given */
    double step_least;   /* a step given is above 0 and at least this */
    double step_default; /* the step of a range without one; 0: none */
    double slack;        /* of a step, forgiven when counting values */
    double values_max;   /* the most values a stepped range has; 0: any */
};

/* A range as read: min <= max, and step (0: continuous). */
struct numrange {
    double min, max, step;
};

/* Parses all of [text, end) as a range of spec into *out, untouched on
 * an error. Returns FACET_OK, or FACET_EINPUT with one of the messages
 * above, naming the setting what. */
int numrange_parse(const char *text, const char *end,
                   const struct numrange_spec *spec, const char *what,
                   struct numrange *out, struct facet_error *err);

/* How many values min, min + step, ... up to max holds: floor((max -
 * min) / step + slack) + 1, as a double, so that a count too large for
 * any integer is still compared rightly; 1 when step is not above 0 or
 * max is not above min. The one count of every stepped range, so that
 * its check and its walk never disagree. */
double numrange_count(double min, double max, double step, double slack);

/* The sides of a pair: [left, left_end) and [right, right_end), blanks
 * trimmed. */
struct numrange_pair {
    const char *left, *left_end, *right, *right_end;
};

/* Splits [text, end) at its one x or X into *out. Returns 0, or -1 (the
 * caller words the message, naming its own syntax) when there is no x,
 * more than one, or a side is empty. */
int numrange_pair_split(const char *text, const char *end,
                        struct numrange_pair *out);

/* Parses text, a grid NUxNV (a pair of whole numbers, each 1 to max),
 * into *nu and *nv, untouched on an error. Returns FACET_OK, or
 * FACET_EINPUT with a message that names what, as above. */
int numrange_grid(const char *text, int max, const char *what, int *nu,
                  int *nv, struct facet_error *err);

#endif
