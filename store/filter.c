/*
 * filter.c: the --where expression language (filter.h, filter_sql.h).
 *
 * Text is lexed into tokens, parsed by recursive descent into a small tree
 * held in one array, and that tree is written back three ways: the text
 * Facet shows (filter_text), the SQL fragment the store runs (filter_sql, in store_browse.c and store_option.c),
 * and an in-memory evaluator (filter_match) that follows SQL's three-valued
 * logic so that both always select the same options. The columns a filter
 * may name, which of them are yes/no and a number to compare each with are
 * the registry's (core/quantity/quantity.h). This file runs no SQL.
 *
 * Hostile text is bounded before any work: at most FILTER_MAX_LENGTH bytes,
 * at most FILTER_MAX_DEPTH nested '(' and 'not' (recursion depth), and
 * and/or chains are n-ary nodes, so no chain makes the tree deep.
 */
#include "store/filter.h"
#include "store/filter_sql.h"
#include "store/store_internal.h"
#include "store/store.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/base/numformat.h"
#include "core/base/numparse.h"
#include "core/base/spelling.h"

enum { COLUMN_COUNT = OPTION_QUANTITIES };

/* Other names a user may type for a column. */
static const struct {
    const char *name;
    const char *column;
} aliases[] = {
    {"u", "nu"},
    {"v", "nv"},
    {"threshold", "threshold_mm"},
};

#define ALIAS_COUNT (sizeof aliases / sizeof *aliases)

/* The words of the language that are not columns: pareto (resolve) and
 * the joiners lex reads. */
static const char *const keywords[] = {"pareto", "and", "or", "not"};
#define KEYWORD_COUNT (sizeof keywords / sizeof *keywords)
#define COLUMN_PARETO (-2)  /* the name pareto: rank = 1, not a column */
#define COLUMN_UNKNOWN (-1)
#define SHOWN_MAX 32        /* bytes of a user's word quoted in a message */

enum op { OP_LT, OP_LE, OP_GT, OP_GE, OP_EQ, OP_NE };

static const char *const op_text[] = {"<", "<=", ">", ">=", "=", "!="};

/* a OP b is b FLIPPED(OP) a: NUMBER OP COLUMN becomes COLUMN OP' NUMBER. */
static const enum op op_flipped[] = {OP_GT, OP_GE, OP_LT, OP_LE, OP_EQ,
                                     OP_NE};

enum token_kind {
    TOK_END,
    TOK_NAME,
    TOK_NUMBER,
    TOK_OP,
    TOK_LPAREN,
    TOK_RPAREN,
    TOK_AND,
    TOK_OR,
    TOK_NOT
};

struct token {
    enum token_kind kind;
    size_t at;       /* byte offset in the text */
    size_t length;   /* bytes */
    enum op op;      /* TOK_OP */
    double number;   /* TOK_NUMBER */
};

enum node_kind {
    NODE_COMPARE,    /* column op params[param] */
    NODE_YES_NO,     /* column != 0 */
    NODE_PARETO,     /* rank = 1 */
    NODE_NOT,
    NODE_AND,
    NODE_OR
};

struct node {
    enum node_kind kind;
    enum op op;      /* NODE_COMPARE */
    int column;      /* index into option_quantities */
    size_t param;    /* NODE_COMPARE: index into filter->params */
    int child;       /* NOT, AND, OR: first operand */
    int next;        /* the next operand of the parent, -1 after the last */
};

struct filter {
    struct node *nodes;
    int root;        /* -1 for the empty filter, which matches everything */
    double *params;  /* the user's numbers, in the order written */
    size_t nparams;
    char *text;      /* filter_text */
};

struct parser {
    const char *text;
    size_t length;
    struct token *tokens;
    size_t ntokens;
    size_t pos;      /* the next token */
    struct filter *filter;
    int nnodes;
    int depth;       /* '(' and 'not' open */
    struct facet_error *err;
};

/* ---- characters and messages --------------------------------------------- */

/* ASCII only, whatever the locale: the language is ASCII. */
static int is_space(char c)
{
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' ||
           c == '\f';
}

static int is_digit(char c)
{
    return c >= '0' && c <= '9';
}

static int is_name_start(char c)
{
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
}

static int is_name_char(char c)
{
    return is_name_start(c) || is_digit(c);
}

static char lower(char c)
{
    return c >= 'A' && c <= 'Z' ? (char)(c - 'A' + 'a') : c;
}

/* Whether the length bytes at s spell word (lowercase) in any case. */
static int word_is(const char *s, size_t length, const char *word)
{
    size_t i = 0;
    for (; i < length && word[i] != '\0'; i++)
        if (lower(s[i]) != word[i])
            return 0;
    return i == length && word[i] == '\0';
}

/* The 1-based character position of byte offset at: UTF-8 continuation
 * bytes do not start a character, so a caret under a terminal line lands
 * where the user sees the mistake. */
static size_t column_of(const char *text, size_t at)
{
    size_t column = 1;
    for (size_t i = 0; i < at; i++)
        column += ((unsigned char)text[i] & 0xC0) != 0x80;
    return column;
}

/* Sets p->err to "column N: WHAT" about the filter, N the column of byte
 * offset at. Returns FACET_EINPUT. */
static int fail_at(struct parser *p, size_t at, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

static int fail_at(struct parser *p, size_t at, const char *fmt, ...)
{
    char what[sizeof p->err->message];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(what, sizeof what, fmt, ap);
    va_end(ap);
    return facet_error_about(p->err, FACET_SETTING_FILTER, FACET_EINPUT,
                             "column %zu: %s", column_of(p->text, at), what);
}

/* The token as the user wrote it, cut to SHOWN_MAX bytes, for quoting in
 * a message. Only ever holds ASCII: names, numbers and operators are. */
static const char *shown(const struct parser *p, const struct token *t,
                         char buf[SHOWN_MAX + 4])
{
    if (t->kind == TOK_END)
        return "the end";
    size_t n = t->length;
    if (n > SHOWN_MAX) {
        memcpy(buf, p->text + t->at, SHOWN_MAX - 3);
        memcpy(buf + SHOWN_MAX - 3, "...", 4);
    } else {
        memcpy(buf, p->text + t->at, n);
        buf[n] = '\0';
    }
    return buf;
}

/* ---- lexing -------------------------------------------------------------- */

/* Whether a NaN or infinity is spelled at s (length n). */
static int is_not_finite_word(const char *s, size_t n)
{
    return word_is(s, n, "nan") || word_is(s, n, "inf") ||
           word_is(s, n, "infinity");
}

/* The length of the well-formed, printable UTF-8 character of two to four
 * bytes at s, or 0 (then the message shows the byte in hex, keeping control
 * characters and broken sequences out of a one-line message). */
static size_t utf8_length(const char *s)
{
    const unsigned char *u = (const unsigned char *)s;
    size_t n = u[0] >= 0xC2 && u[0] <= 0xDF   ? 2
               : u[0] >= 0xE0 && u[0] <= 0xEF ? 3
               : u[0] >= 0xF0 && u[0] <= 0xF4 ? 4
                                              : 0;
    for (size_t k = 1; k < n; k++)
        if ((u[k] & 0xC0) != 0x80)
            return 0;
    if (n == 2 && u[0] == 0xC2 && u[1] < 0xA0)
        return 0;  /* C1 controls */
    if (n == 3 && ((u[0] == 0xE0 && u[1] < 0xA0) ||
                   (u[0] == 0xED && u[1] >= 0xA0)))
        return 0;  /* overlong, surrogates */
    if (n == 4 && ((u[0] == 0xF0 && u[1] < 0x90) ||
                   (u[0] == 0xF4 && u[1] >= 0x90)))
        return 0;  /* overlong, beyond U+10FFFF */
    return n;
}

/* Reads the number that starts at byte i into t: [+-] decimal [exponent]
 * or [+-] decimal k/K/M. Whatever name character or '.' follows makes it
 * malformed, so "1e6and" and "1.2.3" are mistakes rather than two tokens.
 */
static int lex_number(struct parser *p, size_t i, struct token *t)
{
    const char *s = p->text;
    const char *stop = s + i;
    double value = 0;
    int rc = numparse_double(s + i, s + p->length, &value, &stop);
    size_t j = (size_t)(stop - s);
    t->kind = TOK_NUMBER;  /* for shown() in the messages below */
    if (rc == NUMPARSE_SYNTAX)
        j = i + 1;
    int has_exponent = memchr(s + i, 'e', j - i) != NULL ||
                       memchr(s + i, 'E', j - i) != NULL;
    int scale = 0;  /* decimal exponent of a k or M suffix */
    if (rc != NUMPARSE_SYNTAX && j < p->length &&
        (s[j] == 'k' || s[j] == 'K' || s[j] == 'M') &&
        !(is_name_char(s[j + 1]) || s[j + 1] == '.')) {
        scale = s[j] == 'M' ? 6 : 3;
        j++;
    }
    if (rc == NUMPARSE_SYNTAX || is_name_char(s[j]) || s[j] == '.') {
        size_t k = j;
        while (is_name_char(s[k]) || s[k] == '.')
            k++;
        t->length = k - i;
        char buf[SHOWN_MAX + 4];
        if (s[j] == 'm' && k == j + 1)
            return fail_at(p, j, "'m' after a number is ambiguous; write k "
                                 "(thousand) or M (million)");
        return fail_at(p, i, "malformed number '%s'", shown(p, t, buf));
    }
    t->length = j - i;
    char buf[SHOWN_MAX + 4];
    if (rc == NUMPARSE_RANGE)
        return fail_at(p, i, "number '%s' is out of range",
                       shown(p, t, buf));
    if (scale != 0) {
        if (has_exponent)
            return fail_at(p, i, "number '%s' has both an exponent and a "
                                 "k/M suffix; write one",
                           shown(p, t, buf));
        /* Shifting the decimal exponent of the written digits, rather than
         * multiplying, keeps 1.1k exactly the double of 1100. */
        size_t n = j - 1 - i;
        char *scaled = malloc(n + 3);
        if (scaled == NULL)
            return facet_error_about(p->err, FACET_SETTING_FILTER,
                                     FACET_EWORK, "out of memory");
        memcpy(scaled, s + i, n);
        scaled[n] = 'e';
        scaled[n + 1] = (char)('0' + scale);
        scaled[n + 2] = '\0';
        rc = numparse_double(scaled, scaled + n + 2, &value, &stop);
        free(scaled);
        if (rc != NUMPARSE_OK)
            return fail_at(p, i, "number '%s' is out of range",
                           shown(p, t, buf));
    }
    if (!isfinite(value))
        return fail_at(p, i, "number '%s' is out of range",
                       shown(p, t, buf));
    t->kind = TOK_NUMBER;
    t->number = value;
    return FACET_OK;
}

/* Splits p->text into p->tokens, the last one TOK_END at the end of the
 * text. p->tokens has room for one token per byte plus the end. */
static int lex(struct parser *p)
{
    const char *s = p->text;
    size_t i = 0;
    p->ntokens = 0;
    for (;;) {
        while (i < p->length && is_space(s[i]))
            i++;
        struct token *t = &p->tokens[p->ntokens++];
        t->kind = TOK_END;
        t->at = i;
        t->length = 0;
        t->op = OP_EQ;
        t->number = 0;
        if (i == p->length)
            return FACET_OK;
        char c = s[i], d = s[i + 1];  /* s[p->length] is the NUL */
        t->length = 1;
        switch (c) {
        case '(':
            t->kind = TOK_LPAREN;
            break;
        case ')':
            t->kind = TOK_RPAREN;
            break;
        case '<':
            t->kind = TOK_OP;
            t->op = d == '=' ? OP_LE : d == '>' ? OP_NE : OP_LT;
            t->length = d == '=' || d == '>' ? 2 : 1;
            break;
        case '>':
            t->kind = TOK_OP;
            t->op = d == '=' ? OP_GE : OP_GT;
            t->length = d == '=' ? 2 : 1;
            break;
        case '=':
            t->kind = TOK_OP;
            t->op = OP_EQ;
            t->length = d == '=' ? 2 : 1;
            break;
        case '!':
            if (d == '=') {
                t->kind = TOK_OP;
                t->op = OP_NE;
                t->length = 2;
            } else {
                t->kind = TOK_NOT;
            }
            break;
        case '&':
        case '|':
            if (d != c)
                return fail_at(p, i, "'%c' is not an operator; write %s "
                                     "(or %c%c)",
                               c, c == '&' ? "and" : "or", c, c);
            t->kind = c == '&' ? TOK_AND : TOK_OR;
            t->length = 2;
            break;
        default:
            if (is_name_start(c)) {
                size_t j = i;
                while (is_name_char(s[j]))
                    j++;
                t->length = j - i;
                t->kind = word_is(s + i, t->length, "and")   ? TOK_AND
                          : word_is(s + i, t->length, "or")  ? TOK_OR
                          : word_is(s + i, t->length, "not") ? TOK_NOT
                                                              : TOK_NAME;
            } else if (is_digit(c) || (c == '.' && is_digit(d)) ||
                       ((c == '+' || c == '-') &&
                        (is_digit(d) || (d == '.' && is_digit(s[i + 2]))))) {
                int rc = lex_number(p, i, t);
                if (rc != FACET_OK)
                    return rc;
            } else if ((c == '+' || c == '-') && is_name_start(d)) {
                size_t j = i + 1;
                while (is_name_char(s[j]))
                    j++;
                if (is_not_finite_word(s + i + 1, j - i - 1))
                    return fail_at(p, i, "NaN and infinity are not allowed; "
                                         "write a finite number");
                return fail_at(p, i, "unexpected '%c'", c);
            } else if (c >= 0x21 && c <= 0x7E) {
                return fail_at(p, i, "unexpected '%c'", c);
            } else {
                size_t n = utf8_length(s + i);
                if (n > 0)
                    return fail_at(p, i, "unexpected character '%.*s'",
                                   (int)n, s + i);
                return fail_at(p, i, "unexpected byte 0x%02X",
                               (unsigned)(unsigned char)c);
            }
        }
        i += t->length;
    }
}

/* ---- parsing ------------------------------------------------------------- */

static const struct token *peek(const struct parser *p)
{
    return &p->tokens[p->pos];
}

/* Consumes and returns the next token; TOK_END stays put. */
static const struct token *advance(struct parser *p)
{
    const struct token *t = &p->tokens[p->pos];
    if (t->kind != TOK_END)
        p->pos++;
    return t;
}

/* Every node takes at least one token no other node takes (a comparison
 * its operator, a yes/no its name, a not its not, an and/or chain its
 * first and/or), so ntokens nodes are always room enough. */
static int new_node(struct parser *p, enum node_kind kind)
{
    int k = p->nnodes++;
    struct node *n = &p->filter->nodes[k];
    n->kind = kind;
    n->op = OP_EQ;
    n->column = COLUMN_UNKNOWN;
    n->param = 0;
    n->child = -1;
    n->next = -1;
    return k;
}

static int column_index(const char *name)
{
    for (int k = 0; k < COLUMN_COUNT; k++)
        if (strcmp(option_quantities[k].name, name) == 0)
            return k;
    return COLUMN_UNKNOWN;
}

/* The column a name token means (any case, aliases resolved),
 * COLUMN_PARETO, or COLUMN_UNKNOWN. */
static int resolve(const struct parser *p, const struct token *t)
{
    const char *s = p->text + t->at;
    for (int k = 0; k < COLUMN_COUNT; k++)
        if (word_is(s, t->length, option_quantities[k].name))
            return k;
    for (size_t k = 0; k < ALIAS_COUNT; k++)
        if (word_is(s, t->length, aliases[k].name))
            return column_index(aliases[k].column);
    if (word_is(s, t->length, "pareto"))
        return COLUMN_PARETO;
    return COLUMN_UNKNOWN;
}

/* The part of name after its first '_' ("count" of "fp_count"), or NULL
 * when it has none. */
static const char *name_suffix(const char *name)
{
    const char *under = strchr(name, '_');
    return under != NULL && under != name && under[1] != '\0' ? under + 1
                                                               : NULL;
}

/* Writes names[k] to list as the columns' list shows it: the names that
 * end alike after their first '_' as one family, "{fp,sp,dp}_count", at
 * the family's first member, nothing at the others; a name alone as
 * itself. Returns the bytes written. */
static size_t list_name(char *list, size_t size, size_t used,
                        const char *const *names, size_t n, size_t k)
{
    const char *sep = used == 0 ? "" : ", ";
    const char *suffix = name_suffix(names[k]);
    size_t members = 0;
    for (size_t e = 0; suffix != NULL && e < n; e++) {
        const char *other = name_suffix(names[e]);
        if (other == NULL || strcmp(other, suffix) != 0)
            continue;
        if (e < k)
            return 0;
        members++;
    }
    if (members < 2)
        return (size_t)snprintf(list + used, size - used, "%s%s", sep,
                                names[k]);
    char family[128] = "";
    for (size_t e = k; e < n; e++) {
        const char *other = name_suffix(names[e]);
        if (other != NULL && strcmp(other, suffix) == 0)
            snprintf(family + strlen(family), sizeof family - strlen(family),
                     "%s%.*s", family[0] ? "," : "",
                     (int)(other - 1 - names[e]), names[e]);
    }
    return (size_t)snprintf(list + used, size - used, "%s{%s}_%s", sep,
                            family, suffix);
}

void filter_column_hint(const char *word, size_t n, int in_filter,
                        char *out, size_t size)
{
    const char *names[COLUMN_COUNT + ALIAS_COUNT + 1];
    size_t count = 0;
    for (int k = 0; k < COLUMN_COUNT; k++)
        names[count++] = option_quantities[k].name;
    if (in_filter) {
        for (size_t k = 0; k < ALIAS_COUNT; k++)
            names[count++] = aliases[k].name;
        names[count++] = "pareto";
    }
    const char *near = spelling_closest(word, n, names, count);
    if (near != NULL) {
        snprintf(out, size, "did you mean %s?", near);
        return;
    }
    /* The per-class columns are named by their pattern, so the list fits
     * one line. */
    const char *listed[COLUMN_COUNT + ALIAS_COUNT + 1];
    size_t nlisted = 0;
    for (size_t k = 0; k < count; k++) {
        size_t len = strlen(names[k]);
        int per_class = 0;
        for (int c = 0; c < CLASS_COUNT && !per_class; c++) {
            const char *class = panel_class_name((enum panel_class)c);
            per_class = strncmp(names[k], class, strlen(class)) == 0 &&
                        len > strlen(class) && names[k][strlen(class)] == '_';
        }
        if (!per_class)
            listed[nlisted++] = names[k];
    }
    char list[900];
    size_t used = 0;
    for (size_t k = 0; k < nlisted && used < sizeof list; k++)
        used += list_name(list, sizeof list, used, listed, nlisted, k);
    snprintf(out, size, "columns: %s, CLASS_{count,area}", list);
}

/* The message for a name that is no column, with the nearest name or, when
 * nothing is near, the list of them. */
static int fail_unknown_name(struct parser *p, const struct token *t)
{
    char buf[SHOWN_MAX + 4];
    const char *s = p->text + t->at;
    if (is_not_finite_word(s, t->length))
        return fail_at(p, t->at, "NaN and infinity are not allowed; write a "
                                 "finite number");
    char hint[960];
    filter_column_hint(s, t->length, 1, hint, sizeof hint);
    return fail_at(p, t->at, "unknown column '%s' (%s)", shown(p, t, buf),
                   hint);
}

/* A complete condition was followed by t, which cannot follow one here. */
static int fail_after_condition(struct parser *p, const struct token *t)
{
    char buf[SHOWN_MAX + 4];
    if (t->kind == TOK_RPAREN)
        return fail_at(p, t->at, "unexpected ')'");
    if (t->kind == TOK_OP)
        return fail_at(p, t->at, "unexpected '%s'; compare one column with "
                                 "one number at a time, e.g. cost > 5 and "
                                 "cost < 10",
                       op_text[t->op]);
    if (t->kind == TOK_NAME) {
        static const char *const joins[] = {"and", "or"};
        const char *near = spelling_closest(p->text + t->at, t->length, joins, 2);
        if (near != NULL)
            return fail_at(p, t->at, "unexpected '%s' (did you mean %s?)",
                           shown(p, t, buf), near);
    }
    return fail_at(p, t->at, "unexpected '%s'; join conditions with and / or",
                   shown(p, t, buf));
}

static int parse_or(struct parser *p, int *out);

/* A number of the text becomes the next parameter. */
static size_t add_param(struct parser *p, double value)
{
    p->filter->params[p->filter->nparams] = value;
    return p->filter->nparams++;
}

/* term: '(' or-expression ')' | NAME [OP NUMBER] | NUMBER OP NAME. */
static int parse_term(struct parser *p, int *out)
{
    char buf[SHOWN_MAX + 4], buf2[SHOWN_MAX + 4];
    const struct token *t = peek(p);
    struct node *nodes = p->filter->nodes;

    if (t->kind == TOK_LPAREN) {
        if (p->depth >= FILTER_MAX_DEPTH)
            return fail_at(p, t->at, "nested too deeply (more than %d "
                                     "parentheses and nots)",
                           FILTER_MAX_DEPTH);
        advance(p);
        p->depth++;
        int rc = parse_or(p, out);
        if (rc != FACET_OK)
            return rc;
        const struct token *close = peek(p);
        if (close->kind == TOK_END)
            return fail_at(p, close->at, "missing ')' for the '(' at column "
                                         "%zu",
                           column_of(p->text, t->at));
        if (close->kind != TOK_RPAREN)
            return fail_after_condition(p, close);
        advance(p);
        p->depth--;
        return FACET_OK;
    }

    if (t->kind == TOK_NAME) {
        int column = resolve(p, t);
        if (column == COLUMN_UNKNOWN)
            return fail_unknown_name(p, t);
        advance(p);
        const struct token *op = peek(p);
        if (op->kind == TOK_OP) {
            if (column == COLUMN_PARETO)
                return fail_at(p, t->at, "'%s' is yes/no and cannot be "
                                         "compared; write pareto, or compare "
                                         "rank, e.g. rank <= 2",
                               shown(p, t, buf));
            advance(p);
            const struct token *number = peek(p);
            if (number->kind != TOK_NUMBER) {
                if (number->kind == TOK_NAME &&
                    is_not_finite_word(p->text + number->at, number->length))
                    return fail_at(p, number->at, "NaN and infinity are not "
                                                  "allowed; write a finite "
                                                  "number");
                return fail_at(p, number->at, "expected a number after '%s'",
                               shown(p, op, buf));
            }
            advance(p);
            int k = new_node(p, NODE_COMPARE);
            nodes[k].column = column;
            nodes[k].op = op->op;
            nodes[k].param = add_param(p, number->number);
            *out = k;
            return FACET_OK;
        }
        int ends = op->kind == TOK_END || op->kind == TOK_AND ||
                   op->kind == TOK_OR || op->kind == TOK_RPAREN;
        int yes_no = column == COLUMN_PARETO ||
                     option_quantities[column].yes_no;
        if (!yes_no && ends)
            return fail_at(p, t->at, "'%s' is not a yes/no column; compare "
                                     "it, e.g. %s < %s",
                           shown(p, t, buf),
                           option_quantities[column].name,
                           option_quantities[column].example);
        if (!yes_no)
            return fail_at(p, op->at, "expected a comparison (<, <=, >, >=, "
                                      "=, !=) after '%s'",
                           shown(p, t, buf));
        int k = new_node(p, column == COLUMN_PARETO ? NODE_PARETO
                                                    : NODE_YES_NO);
        nodes[k].column = column;
        *out = k;
        return FACET_OK;
    }

    if (t->kind == TOK_NUMBER) {
        advance(p);
        const struct token *op = peek(p);
        if (op->kind != TOK_OP)
            return fail_at(p, op->at, "expected a comparison (<, <=, >, >=, "
                                      "=, !=) after '%s'",
                           shown(p, t, buf));
        advance(p);
        const struct token *name = peek(p);
        if (name->kind != TOK_NAME)
            return fail_at(p, name->at, "expected a column after '%s'",
                           shown(p, op, buf));
        int column = resolve(p, name);
        if (column == COLUMN_UNKNOWN)
            return fail_unknown_name(p, name);
        if (column == COLUMN_PARETO)
            return fail_at(p, name->at, "'%s' is yes/no and cannot be "
                                        "compared; write pareto, or compare "
                                        "rank, e.g. rank <= 2",
                           shown(p, name, buf));
        advance(p);
        int k = new_node(p, NODE_COMPARE);
        nodes[k].column = column;
        nodes[k].op = op_flipped[op->op];
        nodes[k].param = add_param(p, t->number);
        *out = k;
        return FACET_OK;
    }

    if (t->kind == TOK_RPAREN && p->pos == 0)
        return fail_at(p, t->at, "unexpected ')'");
    if (p->pos == 0)
        return fail_at(p, t->at, "unexpected '%s'; a condition starts with a "
                                 "column, a number, not or '('",
                       shown(p, t, buf));
    return fail_at(p, t->at, "expected a condition after '%s'%s%s%s",
                   shown(p, &p->tokens[p->pos - 1], buf),
                   t->kind == TOK_END ? "" : ", not '",
                   t->kind == TOK_END ? "" : shown(p, t, buf2),
                   t->kind == TOK_END ? "" : "'");
}

/* not-term: ('not' | '!')* term */
static int parse_not(struct parser *p, int *out)
{
    const struct token *t = peek(p);
    if (t->kind != TOK_NOT)
        return parse_term(p, out);
    if (p->depth >= FILTER_MAX_DEPTH)
        return fail_at(p, t->at, "nested too deeply (more than %d "
                                 "parentheses and nots)",
                       FILTER_MAX_DEPTH);
    advance(p);
    p->depth++;
    int child;
    int rc = parse_not(p, &child);
    if (rc != FACET_OK)
        return rc;
    p->depth--;
    int k = new_node(p, NODE_NOT);
    p->filter->nodes[k].child = child;
    *out = k;
    return FACET_OK;
}

/* A chain of operands joined by joiner, as one n-ary node (or the operand
 * alone when there is no joiner). */
static int parse_chain(struct parser *p, enum token_kind joiner,
                       enum node_kind kind,
                       int (*operand)(struct parser *, int *), int *out)
{
    int first;
    int rc = operand(p, &first);
    if (rc != FACET_OK)
        return rc;
    if (peek(p)->kind != joiner) {
        *out = first;
        return FACET_OK;
    }
    int k = new_node(p, kind);
    struct node *nodes = p->filter->nodes;
    nodes[k].child = first;
    int tail = first;
    while (peek(p)->kind == joiner) {
        advance(p);
        int next;
        rc = operand(p, &next);
        if (rc != FACET_OK)
            return rc;
        nodes[tail].next = next;
        tail = next;
    }
    *out = k;
    return FACET_OK;
}

static int parse_and(struct parser *p, int *out)
{
    return parse_chain(p, TOK_AND, NODE_AND, parse_not, out);
}

static int parse_or(struct parser *p, int *out)
{
    return parse_chain(p, TOK_OR, NODE_OR, parse_and, out);
}

/* ---- writing ------------------------------------------------------------- */

struct buffer {
    char *data;
    size_t length, capacity;
    int failed;      /* out of memory: data is gone */
};

static void put(struct buffer *b, const char *s)
{
    size_t n = strlen(s);
    if (b->failed)
        return;
    if (b->length + n + 1 > b->capacity) {
        size_t capacity = b->capacity == 0 ? 64 : b->capacity;
        while (b->length + n + 1 > capacity)
            capacity *= 2;
        char *data = realloc(b->data, capacity);
        if (data == NULL) {
            free(b->data);
            b->data = NULL;
            b->failed = 1;
            return;
        }
        b->data = data;
        b->capacity = capacity;
    }
    memcpy(b->data + b->length, s, n + 1);
    b->length += n;
}

static int is_compound(const struct node *n)
{
    return n->kind == NODE_NOT || n->kind == NODE_AND || n->kind == NODE_OR;
}

/* filter_text of node k; operand: 1 when it is an operand of and/or, 2
 * of not. All but a bare yes/no name are parenthesised, but for a not
 * under a not ("not not knee"), so that a chain of nots reads back no
 * deeper than it was written (text_depth counts the parentheses). */
static int text_parens(const struct node *n, int operand)
{
    if (operand == 2 && n->kind == NODE_NOT)
        return 0;
    return operand && n->kind != NODE_YES_NO && n->kind != NODE_PARETO;
}

static void write_text(const struct filter *f, int k, int operand,
                       struct buffer *b)
{
    const struct node *n = &f->nodes[k];
    int parens = text_parens(n, operand);
    char number[NUMBER_EXACT_SIZE];
    if (parens)
        put(b, "(");
    switch (n->kind) {
    case NODE_COMPARE:
        number_exact(number, f->params[n->param]);
        put(b, option_quantities[n->column].name);
        put(b, " ");
        put(b, op_text[n->op]);
        put(b, " ");
        put(b, number);
        break;
    case NODE_YES_NO:
        put(b, option_quantities[n->column].name);
        break;
    case NODE_PARETO:
        put(b, "pareto");
        break;
    case NODE_NOT:
        put(b, "not ");
        write_text(f, n->child, 2, b);
        break;
    case NODE_AND:
    case NODE_OR:
        for (int c = n->child; c >= 0; c = f->nodes[c].next) {
            if (c != n->child)
                put(b, n->kind == NODE_AND ? " and " : " or ");
            write_text(f, c, 1, b);
        }
        break;
    }
    if (parens)
        put(b, ")");
}

/* How deep write_text's text of node k nests '(' and 'not' (operand as
 * there): what the parser counts against FILTER_MAX_DEPTH. */
static int text_depth(const struct filter *f, int k, int operand)
{
    const struct node *n = &f->nodes[k];
    int own = text_parens(n, operand);
    int deepest = 0;
    if (n->kind == NODE_NOT)
        deepest = 1 + text_depth(f, n->child, 2);
    else if (n->kind == NODE_AND || n->kind == NODE_OR)
        for (int c = n->child; c >= 0; c = f->nodes[c].next) {
            int d = text_depth(f, c, 1);
            if (d > deepest)
                deepest = d;
        }
    return own + deepest;
}

/* The SQL of node k. Comparisons bind tighter than NOT, AND and OR in
 * SQL, so only compound operands need parentheses. With scan, columns are
 * written +"column", which no index serves. */
static void write_sql(const struct filter *f, int k, int first_param,
                      int scan, struct buffer *b)
{
    const char *plus = scan ? "+" : "";
    const struct node *n = &f->nodes[k];
    const char *column = n->column >= 0 ? option_quantities[n->column].name
                                        : NULL;
    char text[192];
    switch (n->kind) {
    case NODE_COMPARE:
        /* crowding is stored NULL at a front's ends, where it is
         * infinite, and rank NULL until the run is ranked: compare them
         * as the values an option's row holds (filter_match's). */
        if (strcmp(column, "crowding") == 0 || strcmp(column, "rank") == 0)
            snprintf(text, sizeof text, "%s %s ?%lld",
                     strcmp(column, "rank") == 0 ? store_rank_sql
                                                 : store_crowding_sql,
                     op_text[n->op],
                     (long long)first_param + (long long)n->param);
        else
            snprintf(text, sizeof text, "%s\"%s\" %s ?%lld", plus, column,
                     op_text[n->op],
                     (long long)first_param + (long long)n->param);
        put(b, text);
        break;
    case NODE_YES_NO:
        snprintf(text, sizeof text, "%s\"%s\" != 0", plus, column);
        put(b, text);
        break;
    case NODE_PARETO:
        /* Never NULL (an unranked option is not Pareto, and "not pareto"
         * takes it), and still the rank index's. */
        snprintf(text, sizeof text,
                 "(%s\"rank\" IS NOT NULL AND %s\"rank\" = 1)", plus, plus);
        put(b, text);
        break;
    case NODE_NOT:
        put(b, "NOT (");
        write_sql(f, n->child, first_param, scan, b);
        put(b, ")");
        break;
    case NODE_AND:
    case NODE_OR:
        for (int c = n->child; c >= 0; c = f->nodes[c].next) {
            int parens = is_compound(&f->nodes[c]);
            if (c != n->child)
                put(b, n->kind == NODE_AND ? " AND " : " OR ");
            if (parens)
                put(b, "(");
            write_sql(f, c, first_param, scan, b);
            if (parens)
                put(b, ")");
        }
        break;
    }
}

/* ---- the public functions ------------------------------------------------ */

int filter_compile(const char *text, struct filter **out,
                   struct facet_error *err)
{
    *out = NULL;
    if (text == NULL)
        text = "";
    size_t length = strnlen(text, (size_t)FILTER_MAX_LENGTH + 1);
    if (length > FILTER_MAX_LENGTH)
        return facet_error_about(err, FACET_SETTING_FILTER, FACET_EINPUT,
                                 "column %zu: the expression is longer "
                                 "than %d bytes",
                               column_of(text, FILTER_MAX_LENGTH),
                               FILTER_MAX_LENGTH);

    int rc = FACET_EWORK;
    struct buffer b = {0};
    struct filter *f = calloc(1, sizeof *f);
    struct parser p = {.text = text, .length = length, .filter = f,
                       .err = err};
    p.tokens = malloc((length + 1) * sizeof *p.tokens);
    if (f == NULL || p.tokens == NULL)
        goto out_of_memory;
    f->root = -1;
    rc = lex(&p);
    if (rc != FACET_OK)
        goto fail;
    f->nodes = malloc(p.ntokens * sizeof *f->nodes);
    f->params = malloc(p.ntokens * sizeof *f->params);
    if (f->nodes == NULL || f->params == NULL)
        goto out_of_memory;

    if (p.ntokens > 1) {
        rc = parse_or(&p, &f->root);
        if (rc != FACET_OK)
            goto fail;
        if (peek(&p)->kind != TOK_END) {
            rc = fail_after_condition(&p, peek(&p));
            goto fail;
        }
        /* Its text is compiled again (shown, copied, brushed): it must
         * nest within the limit too, with the parentheses write_text
         * puts around every operand. */
        if (text_depth(f, f->root, 0) > FILTER_MAX_DEPTH) {
            rc = facet_error_about(err, FACET_SETTING_FILTER, FACET_EINPUT,
                "nested too deeply (more than %d parentheses and "
                "nots as Facet writes the expression back)",
                FILTER_MAX_DEPTH);
            goto fail;
        }
        write_text(f, f->root, 0, &b);
    } else {
        put(&b, "");
    }
    if (b.failed)
        goto out_of_memory;
    /* Its text is compiled again: it must fit the length limit too
     * ("!" is written back as "not "). */
    if (b.length > FILTER_MAX_LENGTH) {
        free(b.data);
        rc = facet_error_about(err, FACET_SETTING_FILTER, FACET_EINPUT,
            "the expression is longer than %d bytes as Facet "
            "writes it back (%zu)", FILTER_MAX_LENGTH, b.length);
        goto fail;
    }
    f->text = b.data;
    free(p.tokens);
    facet_error_clear(err);
    *out = f;
    return FACET_OK;

out_of_memory:
    rc = facet_error_about(err, FACET_SETTING_FILTER, FACET_EWORK,
                           "out of memory");
fail:
    free(p.tokens);
    filter_free(f);
    return rc;
}

void filter_free(struct filter *filter)
{
    if (filter == NULL)
        return;
    free(filter->nodes);
    free(filter->params);
    free(filter->text);
    free(filter);
}

const char *filter_text(const struct filter *filter)
{
    return filter == NULL || filter->text == NULL ? "" : filter->text;
}

static char *sql_of(const struct filter *filter, int first_param, int scan)
{
    struct buffer b = {0};
    if (filter == NULL || filter->root < 0)
        put(&b, "1");
    else
        write_sql(filter, filter->root, first_param, scan, &b);
    return b.data;
}

char *filter_sql(const struct filter *filter, int first_param)
{
    return sql_of(filter, first_param, 0);
}

char *filter_sql_scan(const struct filter *filter, int first_param)
{
    return sql_of(filter, first_param, 1);
}

size_t filter_param_count(const struct filter *filter)
{
    return filter == NULL ? 0 : filter->nparams;
}

double filter_param(const struct filter *filter, size_t k)
{
    return filter->params[k];
}

/* SQL's three truth values: a comparison with NULL (a NaN here) is
 * unknown, and unknown spreads through not, and, or as SQL spreads it. */
enum truth { TRUTH_NO, TRUTH_YES, TRUTH_UNKNOWN };

struct match {
    const struct filter *filter;
    double (*value)(void *context, const char *column);
    void *context;
};

static enum truth compare(enum op op, double a, double b)
{
    if (isnan(a))
        return TRUTH_UNKNOWN;
    switch (op) {
    case OP_LT:
        return a < b;
    case OP_LE:
        return a <= b;
    case OP_GT:
        return a > b;
    case OP_GE:
        return a >= b;
    case OP_EQ:
        return a == b;
    case OP_NE:
        return a != b;
    }
    return TRUTH_NO;
}

static enum truth evaluate(const struct match *m, int k)
{
    const struct node *n = &m->filter->nodes[k];
    const char *column = n->column >= 0 ? option_quantities[n->column].name
                                        : NULL;
    switch (n->kind) {
    case NODE_COMPARE:
        return compare(n->op, m->value(m->context, column),
                       m->filter->params[n->param]);
    case NODE_YES_NO:
        return compare(OP_NE, m->value(m->context, column), 0);
    case NODE_PARETO:
        return compare(OP_EQ, m->value(m->context, "rank"), 1);
    case NODE_NOT: {
        enum truth t = evaluate(m, n->child);
        return t == TRUTH_UNKNOWN ? t : t == TRUTH_YES ? TRUTH_NO : TRUTH_YES;
    }
    case NODE_AND:
    case NODE_OR: {
        /* and: any no decides; or: any yes decides; else unknown wins. */
        enum truth decisive = n->kind == NODE_AND ? TRUTH_NO : TRUTH_YES;
        enum truth result = n->kind == NODE_AND ? TRUTH_YES : TRUTH_NO;
        for (int c = n->child; c >= 0; c = m->filter->nodes[c].next) {
            enum truth t = evaluate(m, c);
            if (t == decisive)
                return t;
            if (t == TRUTH_UNKNOWN)
                result = TRUTH_UNKNOWN;
        }
        return result;
    }
    }
    return TRUTH_NO;
}

int filter_match(const struct filter *filter,
                 double (*value)(void *context, const char *column),
                 void *context)
{
    if (filter == NULL || filter->root < 0)
        return 1;
    struct match m = {filter, value, context};
    return evaluate(&m, filter->root) == TRUTH_YES;
}

const char *filter_word(size_t k)
{
    if (k < ALIAS_COUNT)
        return aliases[k].name;
    k -= ALIAS_COUNT;
    return k < KEYWORD_COUNT ? keywords[k] : NULL;
}
