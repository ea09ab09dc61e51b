/*
 * classify_flags.h: the options that fix how a surface is read and its
 * panels classified and priced (units, part, curvature tolerance, per-panel
 * mode, normals, prices, size limit). `facet classify` takes them for one
 * option, `facet optimize` for every option of a run; one parser serves
 * both so that the two never disagree on a flag.
 */
#ifndef FACET_CLASSIFY_FLAGS_H
#define FACET_CLASSIFY_FLAGS_H

#include "args.h"
#include "core/surface/mesh.h"
#include "core/classify/option.h"
#include "core/surface/param.h"

/* The flags' values as given (pointing into argv), NULL when absent, and
 * the table that parses them (args_parse_shared), pointing at them. */
struct classify_flags {
    const char *units, *curvature_tol, *per_panel, *prices, *max_area;
    const char *object, *group, *uv;
    int flip_normals, sp_as_fp;
    struct arg_option table[11];  /* the ten flags, then the end */
};

/* Clears flags and fills flags->table, pointing at flags itself (which
 * must not move before the parse). */
void classify_flags_init(struct classify_flags *flags);

/* Sets params (all but grid and threshold, which it leaves at the
 * defaults' values), mesh and the UV method asked for (PARAM_AUTO when
 * --uv is absent) from the flags, starting from the paper's defaults.
 * Returns FACET_OK or FACET_EINPUT naming the bad flag. */
int classify_flags_apply(const struct classify_flags *flags,
                         struct option_params *params,
                         struct mesh_options *mesh, enum param_method *uv,
                         struct facet_error *err);

/* Parses the text of --uv into *uv. */
int classify_flags_uv(const char *text, enum param_method *uv,
                      struct facet_error *err);

/* The usage lines of the flags, for a command's --help. */
extern const char classify_flags_usage[];

#endif
