/*
 * cmd_example.c: `facet example NAME [-o FILE] [--res N]`, writing one of the
 * example surfaces that the README and `make demo` use.
 */
#include <stdio.h>
#include <string.h>

#include "args.h"
#include "command.h"
#include "core/out/outfile.h"
#include "core/surface/example.h"

static int example_run(int argc, char **argv, struct facet_error *err)
{
    const char *output = NULL, *res_text = NULL;
    int force = 0;
    const struct arg_option options[] = {
        {"output", 'o', ARG_STRING, &output, NULL},
        {"res", 0, ARG_STRING, &res_text, NULL},
        {"force", 0, ARG_FLAG, NULL, &force},
        {NULL, 0, ARG_FLAG, NULL, NULL},
    };
    const char *name[1];
    int count;
    int rc = args_parse(argc, argv, options, name, 1, &count, err);
    if (rc != FACET_OK)
        return rc;
    if (count != 1) {
        char names[256] = "";
        for (int i = 0; example_names[i] != NULL; i++) {
            strncat(names, i ? ", " : "", sizeof names - strlen(names) - 1);
            strncat(names, example_names[i], sizeof names - strlen(names) - 1);
        }
        return facet_error_set(err, FACET_EINPUT,
                               "example: name one example (%s or skin)",
                               names);
    }
    long res = 0;
    if (res_text != NULL &&
        (rc = args_int(res_text, 1, 4096, "--res", &res, err)) != FACET_OK)
        return rc;
    if (example_describe(name[0]) == NULL && strcmp(name[0], "skin") != 0)
        return example_write(name[0], (int)res, NULL, err);

    if (output == NULL || strcmp(output, "-") == 0)
        return example_write(name[0], (int)res, stdout, err);

    /* The same writer as every export: PATH.partial renamed at the end,
     * an existing file only with --force, a link or a directory never. */
    struct outfile f;
    if ((rc = outfile_open(&f, output, force, err)) != FACET_OK)
        return rc;
    rc = example_write(name[0], (int)res, f.out, err);
    if (rc != FACET_OK) {
        outfile_abort(&f);
        return rc;
    }
    rc = outfile_commit(&f, err);
    return rc;
}

const struct command cmd_example = {
    .name = "example",
    .usage = "NAME [-o FILE] [--res N] [--force]",
    .summary = "Write an example surface (OBJ, metres, vt = surface "
               "parameters).",
    .options =
        "  NAME           plane, cylinder, dome, hypar, torus, wave, roof or\n"
        "                 skin (roof: a free-form roof of about 1,240 m^2\n"
        "                 with flat, single- and double-curved regions;\n"
        "                 skin: a 180 m tower of 180 faces, one o each with\n"
        "                 its own vt, 2,025,000 triangles)\n"
        "  -o, --output F write to F instead of standard output\n"
        "  --res N        N x N quads (1..4096; default about 20k vertices);\n"
        "                 skin: per face (1..1024, default 75)\n"
        "  --force        overwrite F if it exists\n",
    .run = example_run,
};
