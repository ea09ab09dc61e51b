/*
 * spelling.c: the nearest known word. See spelling.h.
 */
#include "core/base/spelling.h"

#include <string.h>

static char lower(char c)
{
    return c >= 'A' && c <= 'Z' ? (char)(c - 'A' + 'a') : c;
}

/* Optimal string alignment distance of a (length n, any case) to the
 * lowercase word b, or 3 when it is surely more than 2 (all callers want). */
static int distance(const char *a, size_t n, const char *b)
{
    size_t m = strlen(b);
    if (n > m + 2 || m > n + 2 || m > 30)
        return 3;
    int d[33][33];
    for (size_t i = 0; i <= n; i++)
        d[i][0] = (int)i;
    for (size_t j = 0; j <= m; j++)
        d[0][j] = (int)j;
    for (size_t i = 1; i <= n; i++)
        for (size_t j = 1; j <= m; j++) {
            int cost = lower(a[i - 1]) != b[j - 1];
            int best = d[i - 1][j - 1] + cost;
            if (d[i - 1][j] + 1 < best)
                best = d[i - 1][j] + 1;
            if (d[i][j - 1] + 1 < best)
                best = d[i][j - 1] + 1;
            if (i > 1 && j > 1 && lower(a[i - 1]) == b[j - 2] &&
                lower(a[i - 2]) == b[j - 1] && d[i - 2][j - 2] + 1 < best)
                best = d[i - 2][j - 2] + 1;
            d[i][j] = best;
        }
    return d[n][m];
}

const char *spelling_closest(const char *word, size_t n,
                             const char *const *candidates, size_t count)
{
    const char *best = NULL;
    int best_distance = 3;
    for (size_t k = 0; k < count; k++) {
        int d = distance(word, n, candidates[k]);
        if (d < best_distance && (size_t)d < n) {
            best = candidates[k];
            best_distance = d;
        }
    }
    return best;
}
