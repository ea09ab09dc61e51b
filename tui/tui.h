/*
 * tui.h: `facet tui`, the terminal workbench: runs, the options table,
 * scatter, parallel coordinates, panel map, compare and New run screens
 * over a result store.
 * Every curses call of Facet is in tui/; runs are read and written only
 * through the store/ headers, and computed only through core/.
 */
#ifndef FACET_TUI_H
#define FACET_TUI_H

#include "core/base/error.h"

/* Runs the workbench until the user quits, on the result database at
 * db_path (opened, or created after a y/n when missing), with the New run
 * form open for the OBJ surface at surface_path (NULL: the Runs screen).
 * The caller says which file is which; nothing is guessed from a name.
 * Needs a terminal on stdin and stdout. The terminal is restored on every
 * return, on SIGINT and SIGTERM (which end the workbench as q does) and
 * on a crash. Returns FACET_OK, or an error (bad database, no terminal)
 * with err filled. */
int tui_run(const char *db_path, const char *surface_path,
            struct facet_error *err);

#endif
