/*
 * cmd_info.c: `facet info SURFACE.obj`, what a surface is before anything is
 * computed on it: counts, size, area, UV, topology and warnings.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "args.h"
#include "classify_flags.h"
#include "command.h"
#include "core/out/json.h"
#include "core/surface/surface.h"
#include "core/surface/uv_index.h"

static const char *uv_verdict(const struct mesh *mesh,
                              const struct uv_report *uv)
{
    if (!mesh->has_uv)
        return "absent";
    if (uv->flipped || uv->overlapping || uv->degenerate)
        return "invalid";
    return "valid";
}

static void print_names(const char *label, const struct obj_name *names,
                        size_t count)
{
    printf("%-15s", label);
    if (count <= 1) {
        printf(" -\n");
        return;
    }
    for (size_t i = 1; i < count; i++)
        printf("%s%s", i == 1 ? " " : ", ", names[i].text);
    printf("\n");
}

/* The UV panels would follow: the parameterization taken and why, or
 * why none applies. */
struct uv_choice {
    int ok;
    const struct parameterization *param;
    const char *why_not;       /* the error's message when !ok */
};

static void print_human(const struct surface *s, const struct uv_report *uv,
                        const struct uv_choice *choice)
{
    const struct mesh *m = &s->mesh;
    const struct obj_file *o = &s->obj;
    printf("%-15s %s\n", "surface", s->path);
    printf("%-15s %s\n", "units", mesh_units_name(s->units));
    printf("%-15s %zu in file, %zu welded\n", "vertices", o->nvertices,
           m->nvertices);
    printf("%-15s %zu\n", "texcoords", o->ntexcoords);
    printf("%-15s %zu\n", "normals", o->nnormals);
    printf("%-15s %zu\n", "faces", o->nfaces);
    printf("%-15s %zu\n", "triangles", m->ntriangles);
    printf("%-15s %.3f .. %.3f x %.3f .. %.3f x %.3f .. %.3f m\n", "bbox",
           m->bbox_min[0], m->bbox_max[0], m->bbox_min[1], m->bbox_max[1],
           m->bbox_min[2], m->bbox_max[2]);
    printf("%-15s %.3f x %.3f x %.3f m\n", "size",
           m->bbox_max[0] - m->bbox_min[0], m->bbox_max[1] - m->bbox_min[1],
           m->bbox_max[2] - m->bbox_min[2]);
    printf("%-15s %.3f m^2\n", "area", m->area);
    printf("%-15s %s", "UV", uv_verdict(m, uv));
    if (m->has_uv)
        printf(" (u %.4g .. %.4g, v %.4g .. %.4g; %zu flipped, "
               "%zu overlapping pairs, %zu degenerate)",
               uv->umin, uv->umax, uv->vmin, uv->vmax, uv->flipped,
               uv->overlapping, uv->degenerate);
    printf("\n");
    if (choice->ok)
        printf("%-15s %s (%s)\n", "UV map",
               param_method_name(choice->param->method),
               choice->param->reason);
    else
        printf("%-15s none: %s\n", "UV map", choice->why_not);
    printf("%-15s %zu\n", "components", m->ncomponents);
    printf("%-15s %zu\n", "boundary loops", m->nloops);
    print_names("objects", o->objects, o->nobjects);
    print_names("groups", o->groups, o->ngroups);
    print_names("materials", o->materials, o->nmaterials);
    for (int i = 0; i < s->nwarnings; i++)
        printf("warning: %s\n", s->warnings[i]);
}

static void json_names(struct json_writer *w, const char *key,
                       const struct obj_name *names, size_t count)
{
    json_key(w, key);
    json_begin_array(w);
    for (size_t i = 1; i < count; i++)
        json_string(w, names[i].text);
    json_end_array(w);
}

static void print_json(const struct surface *s, const struct uv_report *uv,
                       const struct uv_choice *choice)
{
    const struct mesh *m = &s->mesh;
    const struct obj_file *o = &s->obj;
    struct json_writer w;
    json_init(&w, stdout);
    json_begin_object(&w);
    json_key(&w, "file");            json_string(&w, s->path);
    json_key(&w, "units");           json_string(&w, mesh_units_name(s->units));
    json_key(&w, "vertices");        json_integer(&w, (long long)o->nvertices);
    json_key(&w, "texcoords");       json_integer(&w, (long long)o->ntexcoords);
    json_key(&w, "normals");         json_integer(&w, (long long)o->nnormals);
    json_key(&w, "faces");           json_integer(&w, (long long)o->nfaces);
    json_key(&w, "triangles");       json_integer(&w, (long long)m->ntriangles);
    json_key(&w, "welded_vertices"); json_integer(&w, (long long)m->nvertices);
    json_key(&w, "has_uv");          json_bool(&w, m->has_uv);
    json_key(&w, "uv_valid");
    json_bool(&w, strcmp(uv_verdict(m, uv), "valid") == 0);
    json_key(&w, "uv");
    json_begin_object(&w);
    json_key(&w, "flipped");         json_integer(&w, (long long)uv->flipped);
    json_key(&w, "overlapping");     json_integer(&w, (long long)uv->overlapping);
    json_key(&w, "degenerate");      json_integer(&w, (long long)uv->degenerate);
    json_end_object(&w);
    json_key(&w, "uv_method");
    if (choice->ok)
        json_string(&w, param_method_name(choice->param->method));
    else
        json_null(&w);
    json_key(&w, "uv_reason");
    json_string(&w, choice->ok ? choice->param->reason : choice->why_not);
    json_key(&w, "bbox");
    json_begin_array(&w);
    json_begin_array(&w);
    for (int k = 0; k < 3; k++)
        json_number(&w, m->bbox_min[k]);
    json_end_array(&w);
    json_begin_array(&w);
    for (int k = 0; k < 3; k++)
        json_number(&w, m->bbox_max[k]);
    json_end_array(&w);
    json_end_array(&w);
    json_key(&w, "area");            json_number(&w, m->area);
    json_key(&w, "components");      json_integer(&w, (long long)m->ncomponents);
    json_key(&w, "boundary_loops");  json_integer(&w, (long long)m->nloops);
    json_key(&w, "nonmanifold_edges");
    json_integer(&w, (long long)m->nonmanifold_edges);
    json_names(&w, "objects", o->objects, o->nobjects);
    json_names(&w, "groups", o->groups, o->ngroups);
    json_names(&w, "materials", o->materials, o->nmaterials);
    json_names(&w, "mtllibs", o->mtllibs, o->nmtllibs);
    json_key(&w, "warnings");
    json_begin_array(&w);
    for (int i = 0; i < s->nwarnings; i++)
        json_string(&w, s->warnings[i]);
    json_end_array(&w);
    json_end_object(&w);
    json_finish(&w);
}

static int info_run(int argc, char **argv, struct facet_error *err)
{
    struct surface_flags which;
    surface_flags_init(&which);
    const char *uv_text = NULL;
    int json = 0;
    const struct arg_option options[] = {
        {"json", 0, ARG_FLAG, NULL, &json},
        {"uv", 0, ARG_STRING, &uv_text, NULL},
        {NULL, 0, ARG_FLAG, NULL, NULL},
    };
    const char *path;
    int rc = args_parse_one(argc, argv, options, which.table, &path,
            "info: name one OBJ file (facet info FILE.obj)", err);
    if (rc != FACET_OK)
        return rc;
    struct mesh_options mesh_options;
    if ((rc = surface_flags_apply(&which, &mesh_options, err)) != FACET_OK)
        return rc;
    enum param_method want;
    if ((rc = classify_flags_uv(uv_text, &want, err)) != FACET_OK)
        return rc;

    struct surface surface;
    rc = surface_open(path, &mesh_options, &surface, err);
    struct uv_report uv;
    memset(&uv, 0, sizeof uv);
    if (rc == FACET_OK && surface.mesh.has_uv)
        rc = uv_check(surface.mesh.uv, surface.mesh.ntriangles, &uv, err);
    /* The UV a panelization would take. Without --uv, none applying is
     * part of the description; a method asked for that cannot apply is
     * the error. */
    struct parameterization param;
    struct facet_error why_not;
    memset(&param, 0, sizeof param);
    facet_error_clear(&why_not);
    struct uv_choice choice = {0, &param, ""};
    if (rc == FACET_OK) {
        int prc = param_choose(&surface.mesh, want, surface.path, &param,
                               &why_not);
        if (prc == FACET_OK)
            choice.ok = 1;
        else if (prc == FACET_EINPUT && want == PARAM_AUTO)
            choice.why_not = why_not.message;
        else {
            *err = why_not;
            rc = prc;
        }
    }
    if (rc == FACET_OK) {
        if (json)
            print_json(&surface, &uv, &choice);
        else
            print_human(&surface, &uv, &choice);
    }
    param_free(&param);
    surface_close(&surface);
    return rc;
}

const struct command cmd_info = {
    .name = "info",
    .usage = "SURFACE.obj [--units U] [--object NAME] [--group NAME] "
             "[--uv METHOD] [--json]",
    .summary = "Describe a surface: counts, size, area, UV, topology, "
               "warnings.",
    .options =
        "  --units U      what one OBJ unit is: m (default), cm, mm, in, ft\n"
        "  --object NAME  only the faces of object NAME (o statement)\n"
        "  --group NAME   only the faces of group NAME (g statement)\n"
        "  --uv METHOD    whether that UV (vt, grid, plane, harmonic)\n"
        "                 applies; default: say which is taken and why\n"
        "  --json         one JSON object: vertices, texcoords, normals,\n"
        "                 faces (as in the file), triangles, has_uv, uv_valid,\n"
        "                 uv_method (the UV taken, or null), uv_reason,\n"
        "                 bbox [[xmin,ymin,zmin],[xmax,ymax,zmax]] (m),\n"
        "                 area (m^2), components, boundary_loops, objects,\n"
        "                 groups, materials, warnings\n",
    .run = info_run,
};
