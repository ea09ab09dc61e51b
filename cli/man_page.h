/*
 * man_page.h: facet(1), the manual page, as roff for the man macros.
 *
 * The page is made from what --help prints: the command table
 * (command.h), each command's usage, summary and notes, and a tagged
 * paragraph per entry of the option tables it parses with (args.h), with
 * the same help text and defaults. So the page and --help cannot drift:
 * one table, two formats. `facet help --man` prints it; `make install`
 * installs it as man1/facet.1. One page holds every command, each under
 * its own heading.
 */
#ifndef FACET_MAN_PAGE_H
#define FACET_MAN_PAGE_H

#include <stdio.h>

/* Writes the whole page to out. Plain ASCII roff: every '-' written as
 * \- (so that flags copy as typed), every '\' as \e, and no text line
 * that starts with a control character. */
void man_page_write(FILE *out);

#endif
