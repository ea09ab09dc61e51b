/*
 * numparse.h: reading decimal numbers out of OBJ text, the command line
 * and the TUI's forms, strictly: a number is read as written or refused,
 * never wrapped, rounded to an integer or read in another base.
 *
 * The OBJ loader spends most of its time here, so this is a small parser of
 * its own rather than strtod: it needs no NUL terminator (it stops at an end
 * pointer), never allocates, ignores the locale and is several times faster.
 * It agrees with strtod to within one unit in the last place, and exactly
 * for the short decimals that exporters write (up to 15 significant digits
 * and a decimal exponent of at most 22 in size).
 *
 * Accepted: [+-] digits [. digits] [(e|E) [+-] digits], with at least one
 * digit in the mantissa ("5.", ".5" and "5" are fine). Not accepted: nan,
 * inf, hexadecimal floats, and anything that would overflow to infinity.
 * Ranges and pairs of numbers ("1:5:0.5", "37x49") are numrange.h's.
 */
#ifndef FACET_NUMPARSE_H
#define FACET_NUMPARSE_H

#include "core/base/error.h"

enum {
    NUMPARSE_OK = 0,
    NUMPARSE_SYNTAX = 1,  /* no number starts at text */
    NUMPARSE_RANGE = 2    /* a number, but too large for a double */
};

/* Parses the number that starts at text (reading no further than end).
 * On NUMPARSE_OK stores the value in *value and the first character after
 * the number in *stop; the caller decides whether that character may follow
 * a number. On NUMPARSE_RANGE *stop is set as well and *value is untouched;
 * on NUMPARSE_SYNTAX neither is. Numbers too small for a double become
 * subnormals or signed zero, as with strtod. */
int numparse_double(const char *text, const char *end, double *value,
                    const char **stop);

/* Parses the whole number that starts at text (reading no further than
 * end): decimal digits only, with an optional leading '-' when min < 0;
 * no blanks, no '+', no hexadecimal. On NUMPARSE_OK stores it in *value
 * and the first character after it in *stop. NUMPARSE_RANGE when it is
 * outside [min, max], however many digits it has (never wrapped: 4294967297
 * is not 1); NUMPARSE_SYNTAX when no digit starts at text. */
int numparse_whole(const char *text, const char *end, long long min,
                   long long max, long long *value, const char **stop);

/* Parses all of the NUL-terminated text as a decimal number (as
 * numparse_double: no hexadecimal, nan or inf) into *value. Returns
 * NUMPARSE_OK, NUMPARSE_SYNTAX (also for anything after the number) or
 * NUMPARSE_RANGE. */
int numparse_text(const char *text, double *value);

/* Parses all of text, a value the user gave for the setting what (the
 * caller's name for it: a command-line flag, a form's label), as one
 * finite number in [min, max] into *out (numparse_text's syntax): the one
 * single-number parser of the CLI's flags and the TUI's form fields.
 * Returns FACET_OK, or FACET_EINPUT with a message that starts with what
 * ("Joint cost USD/m: 'abc' is not a number", "--joint-cost: -1 is out
 * of range (0 to 1e+09)", the text as given); a number too large for a
 * double (1e999) is out of range too. *out is untouched on an error. */
int numparse_number(const char *text, double min, double max,
                    const char *what, double *out, struct facet_error *err);

#endif
