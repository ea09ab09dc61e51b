/*
 * spelling.h: "did you mean ...?" for a mistyped word.
 *
 * The filter language's column names, the subcommands and every command's
 * flags all suggest the nearest known word when an unknown one is typed,
 * by one measure: the optimal string alignment distance (insertions,
 * deletions, substitutions and swaps of neighbours), case-insensitive.
 */
#ifndef FACET_SPELLING_H
#define FACET_SPELLING_H

#include <stddef.h>

/* The candidate (lowercase words) closest to the word (length n, any
 * case): within 2 edits, and fewer edits than the word has letters, so
 * that "x" does not become "u". The first of equally close ones; NULL when
 * none is that close. */
const char *spelling_closest(const char *word, size_t n,
                             const char *const *candidates, size_t count);

#endif
