/*
 * cmd_example.c: `facet example NAME [-o FILE] [--res N]`, writing one of the
 * example surfaces that the README, docs/ and `make demo` use.
 */
#include <stdio.h>
#include <string.h>

#include "args.h"
#include "command.h"
#include "core/out/outfile.h"
#include "core/surface/example.h"

/* The options as given (pointing into argv), NULL or 0 when absent. */
struct example_args {
    const char *output, *res;
    int force;
};

static const struct arg_option example_options[] = {
    {"output", 'o', ARG_STRING, offsetof(struct example_args, output), "F",
     "write to F instead of standard output", NULL},
    {"res", 0, ARG_STRING, offsetof(struct example_args, res), "N",
     "N x N quads (1..4096; default about 20k vertices); skin: per face "
     "(1..1024, default 75)", NULL},
    {"force", 0, ARG_FLAG, offsetof(struct example_args, force), NULL,
     "overwrite F if it exists", NULL},
    {NULL, 0, ARG_FLAG, 0, NULL, NULL, NULL},
};

static int example_run(int argc, char **argv, struct facet_error *err)
{
    struct example_args a = {NULL, NULL, 0};
    const struct arg_table own = {example_options, &a};
    const char *name[1];
    int count;
    int rc = args_parse(argc, argv, &own, NULL, name, 1, &count, err);
    if (rc != FACET_OK)
        return rc;
    const char *output = a.output, *res_text = a.res;
    int force = a.force;
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
    .before =
        "  NAME                plane, cylinder, dome, hypar, torus, wave, "
        "roof or\n"
        "                      skin (roof: a free-form roof of about 1,240 "
        "m^2\n"
        "                      with flat, single- and double-curved "
        "regions;\n"
        "                      skin: a 180 m tower of 180 faces, one o each "
        "with\n"
        "                      its own vt, 2,025,000 triangles)\n",
    .options = example_options,
    .after = "",
    .run = example_run,
};
