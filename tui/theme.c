/*
 * theme.c: the role table and glyph sets. See theme.h.
 */
#include "theme.h"

#include <ctype.h>
#include <string.h>

struct role_style {
    short fg, bg;       /* colours, -1 = terminal default */
    attr_t colour;      /* extra attributes with colours */
    attr_t mono;        /* attributes without colours */
};

static const struct role_style styles[ROLE_COUNT] = {
    [ROLE_NORMAL] = {-1, -1, 0, 0},
    [ROLE_TITLE] = {COLOR_BLACK, COLOR_CYAN, 0, A_REVERSE},
    [ROLE_HEADER] = {COLOR_BLACK, COLOR_GREEN, 0, A_UNDERLINE | A_BOLD},
    [ROLE_SORTED] = {COLOR_BLACK, COLOR_CYAN, A_BOLD, A_REVERSE | A_BOLD},
    [ROLE_COLUMN] = {COLOR_WHITE, COLOR_BLUE, A_BOLD, A_REVERSE},
    [ROLE_SELECTION] = {COLOR_BLACK, COLOR_CYAN, 0, A_REVERSE},
    [ROLE_STATUS] = {COLOR_CYAN, -1, 0, 0},
    [ROLE_ERROR] = {COLOR_WHITE, COLOR_RED, A_BOLD, A_BOLD | A_REVERSE},
    [ROLE_FKEY] = {-1, -1, 0, 0},
    [ROLE_FKEY_LABEL] = {COLOR_BLACK, COLOR_CYAN, 0, A_REVERSE},
    [ROLE_FP] = {COLOR_BLACK, COLOR_GREEN, 0, 0},
    [ROLE_SP] = {COLOR_BLACK, COLOR_YELLOW, 0, A_UNDERLINE},
    [ROLE_DP] = {COLOR_WHITE, COLOR_RED, A_BOLD, A_BOLD},
    [ROLE_PARETO] = {COLOR_YELLOW, -1, A_BOLD, A_BOLD},
    [ROLE_KNEE] = {COLOR_MAGENTA, -1, A_BOLD, A_BOLD | A_UNDERLINE},
    [ROLE_MARKED] = {COLOR_GREEN, -1, A_BOLD, A_BOLD},
    [ROLE_DIM] = {COLOR_BLUE, -1, 0, A_DIM},
    [ROLE_CLASS0 + 0] = {COLOR_WHITE, COLOR_MAGENTA, 0, 0},
    [ROLE_CLASS0 + 1] = {COLOR_BLACK, COLOR_CYAN, 0, 0},
    [ROLE_CLASS0 + 2] = {COLOR_WHITE, COLOR_BLUE, 0, 0},
    [ROLE_CLASS0 + 3] = {COLOR_BLACK, COLOR_YELLOW, 0, 0},
    [ROLE_CLASS0 + 4] = {COLOR_BLACK, COLOR_GREEN, 0, 0},
    [ROLE_CLASS0 + 5] = {COLOR_BLACK, COLOR_WHITE, 0, 0},
    [ROLE_CLASS0 + 6] = {COLOR_WHITE, COLOR_RED, 0, 0},
    [ROLE_CLASS0 + 7] = {COLOR_RED, COLOR_WHITE, 0, 0},
    [ROLE_GAUGE] = {COLOR_BLACK, COLOR_GREEN, 0, A_REVERSE},
    /* better and worse in blue and yellow, which readers who cannot tell
     * red from green tell apart; the glyphs say it without colour */
    [ROLE_BETTER] = {COLOR_CYAN, -1, A_BOLD, A_BOLD},
    [ROLE_WORSE] = {COLOR_YELLOW, -1, 0, A_UNDERLINE},
    /* a sequential scale, dark blue to yellow as viridis runs */
    [ROLE_SCALE0 + 0] = {COLOR_BLUE, -1, A_BOLD, A_DIM},
    [ROLE_SCALE0 + 1] = {COLOR_CYAN, -1, 0, A_NORMAL},
    [ROLE_SCALE0 + 2] = {COLOR_GREEN, -1, A_BOLD, A_NORMAL},
    [ROLE_SCALE0 + 3] = {COLOR_YELLOW, -1, A_BOLD, A_BOLD},
    [ROLE_INFEASIBLE] = {-1, -1, A_DIM, A_DIM},
};

static attr_t attrs[ROLE_COUNT];

int tui_theme_init(int colour)
{
    int use = colour && has_colors();
    if (use && start_color() == OK) {
        use_default_colors();
        for (int r = 0; r < ROLE_COUNT; r++) {
            init_pair((short)(r + 1), styles[r].fg, styles[r].bg);
            attrs[r] = COLOR_PAIR(r + 1) | styles[r].colour;
        }
        attrs[ROLE_NORMAL] = A_NORMAL;
        return 1;
    }
    for (int r = 0; r < ROLE_COUNT; r++)
        attrs[r] = styles[r].mono;
    return 0;
}

attr_t tui_attr(enum tui_role role)
{
    return role >= 0 && role < ROLE_COUNT ? attrs[role] : A_NORMAL;
}

enum tui_role tui_type_role(int type)
{
    return type == 0 ? ROLE_FP : type == 1 ? ROLE_SP : ROLE_DP;
}

static const struct tui_glyphs utf8_glyphs = {
    "\u25c6", "\u2605", "\u2713", "\u25b2", "\u25bc",
    {"\u00b7", "\u2022", "\u25cf"}, "\u2500", "\u2500", "\u2502", "\u2514",
    "\u2588", "\u2591", "\u00b7", "\u2713", "\u2717", "\u2717",
};

static const struct tui_glyphs ascii_glyphs = {
    "*", "K", "+", "^", "v", {".", "o", "O"}, "-", "-", "|", "+", "#", ".",
    " ", "v", "x", "x",
};

int tui_terminal_utf8(const char *codeset, const char *term)
{
    if (codeset == NULL || strcmp(codeset, "UTF-8") != 0)
        return 0;
    if (term == NULL)
        return 1;
    if (strcmp(term, "dumb") == 0 || strncmp(term, "ansi", 4) == 0)
        return 0;
    /* vt52, vt100, vt102, vt220, vt320, vt420, vt520 and their -am,
     * -nam variants; not vte or vt-utf8 */
    return !(term[0] == 'v' && term[1] == 't' && isdigit((unsigned char)term[2]));
}

const struct tui_glyphs *tui_glyphs_for(int utf8)
{
    return utf8 ? &utf8_glyphs : &ascii_glyphs;
}
