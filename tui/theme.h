/*
 * theme.h: the workbench's one table of semantic colours (selection,
 * header, FP, SP, DP, Pareto, ...) with a monochrome fallback, and its
 * glyphs with an ASCII fallback for terminals whose locale is not UTF-8.
 * Screens name a role, never a colour.
 */
#ifndef FACET_TUI_THEME_H
#define FACET_TUI_THEME_H

#include <curses.h>

enum tui_role {
    ROLE_NORMAL,
    ROLE_TITLE,        /* the top line */
    ROLE_HEADER,       /* table headers */
    ROLE_SORTED,       /* the header of a sort column */
    ROLE_COLUMN,       /* the header under the column cursor */
    ROLE_SELECTION,    /* the selected row or point */
    ROLE_STATUS,       /* an information message */
    ROLE_ERROR,        /* an error message */
    ROLE_FKEY,         /* "F5" in the function-key bar */
    ROLE_FKEY_LABEL,   /* "Scatter" in the function-key bar */
    ROLE_FP, ROLE_SP, ROLE_DP,
    ROLE_PARETO,       /* Pareto-optimal options and the front */
    ROLE_KNEE,
    ROLE_MARKED,       /* options marked for comparison */
    ROLE_DIM,          /* axes, grid, hidden things */
    ROLE_CLASS0,       /* the 8 panel classes, ROLE_CLASS0 + class */
    ROLE_GAUGE = ROLE_CLASS0 + 8,
    ROLE_BETTER,       /* a difference for the better (Compare) */
    ROLE_WORSE,        /* ... for the worse */
    ROLE_SCALE0,       /* 4 levels of a colour scale, low to high */
    ROLE_INFEASIBLE = ROLE_SCALE0 + 4,  /* an infeasible option's row:
                                           dim, with or without colours */
    ROLE_COUNT
};

/* Sets the roles up for this terminal: colours when colour is non-zero
 * and the terminal has them (has_colors), attributes only otherwise.
 * Call after initscr/newterm. Returns whether colours are in use. */
int tui_theme_init(int colour);

/* The attribute to draw role with. */
attr_t tui_attr(enum tui_role role);

/* The role of a panel type (0 FP, 1 SP, 2 DP). */
enum tui_role tui_type_role(int type);

/* The glyphs, as UTF-8 or ASCII strings of one column each. */
struct tui_glyphs {
    const char *pareto;     /* a Pareto-optimal option */
    const char *knee;
    const char *mark;       /* marked for comparison */
    const char *up, *down;  /* sort direction */
    const char *point[3];   /* scatter points, small to large */
    const char *front;      /* the scatter's front line */
    const char *hline, *vline, *corner;
    const char *gauge_full, *gauge_empty;
    const char *empty;      /* a grid cell with no panel */
    const char *better, *worse;  /* a difference's direction (Compare) */
    const char *infeasible; /* an infeasible option (its row is dim too,
                               which some terminals do not show) */
};

/* The glyphs for a UTF-8 locale (utf8 non-zero) or plain ASCII. */
const struct tui_glyphs *tui_glyphs_for(int utf8);

/* Whether the terminal draws UTF-8: the locale's codeset (nl_langinfo)
 * is UTF-8 and term (TERM, NULL when unset) is not a terminal that
 * predates it (dumb, ansi, the DEC VT family: vt52, vt100, vt220 ...),
 * which would show each glyph's bytes as two or three wrong characters
 * whatever the locale says. */
int tui_terminal_utf8(const char *codeset, const char *term);

#endif
