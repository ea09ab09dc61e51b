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
#include "core/evaluate/option.h"
#include "core/surface/param.h"

/* The flags that pick the surface of a file and its units (--units,
 * --object, --group), as given (pointing into argv), NULL when absent:
 * what every command that reads a surface takes. */
struct surface_flags {
    const char *units, *object, *group;
};

/* The table that parses them into a struct surface_flags (args.h), and
 * says them in --help. */
extern const struct arg_option surface_flags_options[];

/* Sets *mesh from the flags (metres, the whole file, when absent).
 * Returns FACET_OK or FACET_EINPUT naming a bad --units. */
int surface_flags_apply(const struct surface_flags *flags,
                        struct mesh_options *mesh, struct facet_error *err);

/* The classification flags' values as given (pointing into argv), NULL
 * (or 0) when absent, the surface's among them. */
struct classify_flags {
    struct surface_flags surface;
    const char *curvature_tol, *per_panel, *prices, *max_area, *uv;
    int flip_normals, sp_as_fp;
    const char *panel_cost, *joint_cost, *mould_cost, *mould_tol;
    int mould_mirror;
    const char *sp_fit, *max_gap, *max_kink, *min_width;
};

/* The table that parses them all into a struct classify_flags (args.h),
 * and says them in --help with the defaults option_params_defaults
 * gives. */
extern const struct arg_option classify_flags_options[];

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

#endif
