/*
 * option_csv.c: options as CSV. See option_csv.h.
 */
#include "core/out/option_csv.h"

#include <math.h>

#include "core/base/numformat.h"
#include "core/quantity/quantity.h"

void option_csv_header(FILE *out)
{
    fputs("run", out);
    for (int k = 0; k < OPTION_QUANTITIES; k++)
        if (option_quantities[k].writer != WRITTEN_AS_KEY) {
            char name[64];
            quantity_csv_name(&option_quantities[k], name, sizeof name);
            fprintf(out, ",%s", name);
        }
    fputc('\n', out);
}

void option_csv_row(FILE *out, int64_t run, const struct option_row *o)
{
    fprintf(out, "%lld", (long long)run);
    for (int k = 0; k < OPTION_QUANTITIES; k++) {
        const struct quantity *c = &option_quantities[k];
        if (c->writer == WRITTEN_AS_KEY)
            continue;
        double value = quantity_value(c, o);
        char text[NUMBER_EXACT_SIZE] = "";
        if (isfinite(value))
            number_exact(text, value);
        fprintf(out, ",%s", text);
    }
    fputc('\n', out);
}
