/*
 * columns.c: the column chooser's model. See columns.h.
 */
#include "columns.h"

#include "format.h"

void tui_columns_default(struct tui_column_set *set)
{
    set->n = tui_option_column_count < TUI_COLUMNS_MAX
                 ? tui_option_column_count : TUI_COLUMNS_MAX;
    for (int k = 0; k < set->n; k++) {
        set->order[k] = k;
        set->shown[k] = k < tui_option_column_default_count;
    }
}

int tui_columns_visible(const struct tui_column_set *set, int *out)
{
    int n = 0;
    for (int k = 0; k < set->n; k++)
        if (set->shown[k])
            out[n++] = set->order[k];
    return n;
}

int tui_columns_toggle(struct tui_column_set *set, int position)
{
    if (position < 0 || position >= set->n)
        return -1;
    if (set->shown[position]) {
        int shown = 0;
        for (int k = 0; k < set->n; k++)
            shown += set->shown[k] != 0;
        if (shown <= 1)
            return -1;
    }
    set->shown[position] = !set->shown[position];
    return 0;
}

int tui_columns_move(struct tui_column_set *set, int position, int delta)
{
    if (position < 0 || position >= set->n)
        return position;
    int to = position + delta;
    if (to < 0)
        to = 0;
    if (to >= set->n)
        to = set->n - 1;
    int order = set->order[position];
    unsigned char shown = set->shown[position];
    int step = to > position ? 1 : -1;
    for (int k = position; k != to; k += step) {
        set->order[k] = set->order[k + step];
        set->shown[k] = set->shown[k + step];
    }
    set->order[to] = order;
    set->shown[to] = shown;
    return to;
}

int tui_columns_width(const struct tui_column_set *set)
{
    int width = 0;
    for (int k = 0; k < set->n; k++)
        if (set->shown[k])
            width += tui_option_columns[set->order[k]].width + 1;
    return width > 0 ? width - 1 : 0;
}
