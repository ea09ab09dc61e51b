/*
 * cmd_info.c: `facet info SURFACE.obj`, what a surface is before anything is
 * computed on it: counts, size, area, UV, topology and warnings.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "classify_flags.h"
#include "command.h"
#include "core/base/numformat.h"
#include "core/obj/obj.h"
#include "core/out/json.h"
#include "core/project/project.h"
#include "core/project/project_lengths.h"
#include "core/surface/surface.h"
#include "core/surface/uv_index.h"
#include "shown.h"

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
    for (size_t i = 1; i < count; i++) {
        fputs(i == 1 ? " " : ", ", stdout);
        shown_text(stdout, names[i].text);  /* the file's, not ours */
    }
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
    /* The path, names, reasons and warnings can quote the file: each line
     * that carries one is cleaned (shown.h). */
    shown_line(stdout, "%-15s %s", "surface", s->path);
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
        shown_line(stdout, "%-15s %s (%s)", "UV map",
                   param_method_name(choice->param->method),
                   choice->param->reason);
    else
        shown_line(stdout, "%-15s none: %s", "UV map", choice->why_not);
    printf("%-15s %zu\n", "components", m->ncomponents);
    printf("%-15s %zu\n", "boundary loops", m->nloops);
    print_names("objects", o->objects, o->nobjects);
    print_names("groups", o->groups, o->ngroups);
    print_names("materials", o->materials, o->nmaterials);
    for (int i = 0; i < s->nwarnings; i++)
        shown_line(stdout, "warning: %s", s->warnings[i]);
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

/* ---- a project: one line per surface ---------------------------------- */

/* What info says of one surface of a project: the UV panels would follow
 * and its lengths along it. */
struct surface_row {
    const struct project_surface *s;
    int uv_ok;
    enum param_method method;
    char reason[sizeof ((struct facet_error *)0)->message];
    double u_length, v_length;
};

static int describe_surfaces(const struct project *p, enum param_method want,
                             struct surface_row *rows,
                             struct facet_error *err)
{
    for (size_t i = 0; i < p->nsurfaces; i++) {
        struct surface_row *r = &rows[i];
        r->s = &p->surfaces[i];
        const struct surface *surface = &r->s->surface;
        struct parameterization param;
        struct facet_error why_not;
        facet_error_clear(&why_not);
        int rc = param_choose(&surface->mesh, want, surface->path, &param,
                              &why_not);
        if (rc == FACET_OK) {
            r->uv_ok = 1;
            r->method = param.method;
            snprintf(r->reason, sizeof r->reason, "%s", param.reason);
            surface_uv_lengths(&surface->mesh, param.uv, &r->u_length,
                               &r->v_length);
        } else if (rc == FACET_EINPUT && want == PARAM_AUTO) {
            snprintf(r->reason, sizeof r->reason, "%s", why_not.message);
        } else {
            *err = why_not;
            param_free(&param);
            return rc;
        }
        param_free(&param);
    }
    return FACET_OK;
}

static void print_project_human(const struct project *p,
                                const struct surface_row *rows)
{
    char area[64];
    number_grouped(area, sizeof area, p->area, 3);
    printf("%-15s %zu file%s, %zu surfaces, %zu triangles, %s m^2\n",
           "project", p->nfiles, p->nfiles == 1 ? "" : "s", p->nsurfaces,
           p->ntriangles, area);
    printf("%-20s %-20s %10s %12s %-9s %9s %9s\n", "surface", "file",
           "triangles", "area m^2", "UV", "u m", "v m");
    for (size_t i = 0; i < p->nsurfaces; i++) {
        const struct surface_row *r = &rows[i];
        const char *slash = strrchr(r->s->file, '/');
        /* the name and file are the user's: shown, not obeyed */
        shown_cell(stdout, r->s->name, 20);
        fputc(' ', stdout);
        shown_cell(stdout, slash ? slash + 1 : r->s->file, 20);
        printf(" %10zu %12.3f %-9s", r->s->surface.mesh.ntriangles,
               r->s->surface.mesh.area,
               r->uv_ok ? param_method_name(r->method) : "none");
        if (r->uv_ok)
            printf(" %9.3f %9.3f\n", r->u_length, r->v_length);
        else
            printf(" %9s %9s\n", "-", "-");
    }
    for (size_t i = 0; i < p->nsurfaces; i++) {
        const struct surface_row *r = &rows[i];
        if (!r->uv_ok)
            shown_line(stdout, "warning: %s: no UV: %s", r->s->name,
                       r->reason);
        for (int w = 0; w < r->s->surface.nwarnings; w++)
            shown_line(stdout, "warning: %s: %s", r->s->name,
                       r->s->surface.warnings[w]);
    }
}

static void print_project_json(const struct project *p,
                               const struct surface_row *rows)
{
    struct json_writer w;
    json_init(&w, stdout);
    json_begin_object(&w);
    json_key(&w, "files");
    json_begin_array(&w);
    for (size_t i = 0; i < p->nfiles; i++)
        json_string(&w, p->files[i]);
    json_end_array(&w);
    json_key(&w, "triangles");  json_integer(&w, (long long)p->ntriangles);
    json_key(&w, "area");       json_number(&w, p->area);
    json_key(&w, "surfaces");
    json_begin_array(&w);
    for (size_t i = 0; i < p->nsurfaces; i++) {
        const struct surface_row *r = &rows[i];
        const struct mesh *m = &r->s->surface.mesh;
        json_begin_object(&w);
        json_key(&w, "name");       json_string(&w, r->s->name);
        json_key(&w, "file");       json_string(&w, r->s->file);
        json_key(&w, "kind");       json_string(&w,
                                        project_key_name(r->s->key));
        json_key(&w, "triangles");  json_integer(&w, (long long)m->ntriangles);
        json_key(&w, "area");       json_number(&w, m->area);
        json_key(&w, "has_uv");     json_bool(&w, m->has_uv);
        json_key(&w, "uv_method");
        if (r->uv_ok)
            json_string(&w, param_method_name(r->method));
        else
            json_null(&w);
        json_key(&w, "uv_reason");  json_string(&w, r->reason);
        json_key(&w, "u_length");
        if (r->uv_ok)
            json_number(&w, r->u_length);
        else
            json_null(&w);
        json_key(&w, "v_length");
        if (r->uv_ok)
            json_number(&w, r->v_length);
        else
            json_null(&w);
        json_key(&w, "components"); json_integer(&w,
                                        (long long)m->ncomponents);
        json_key(&w, "warnings");
        json_begin_array(&w);
        for (int k = 0; k < r->s->surface.nwarnings; k++)
            json_string(&w, r->s->surface.warnings[k]);
        json_end_array(&w);
        json_end_object(&w);
    }
    json_end_array(&w);
    json_end_object(&w);
    json_finish(&w);
}

/* Lists a project's surfaces; takes *project over. */
static int info_project(struct project *project, enum param_method want,
                        int json, struct facet_error *err)
{
    struct surface_row *rows =
        calloc(project->nsurfaces + 1, sizeof *rows);
    int rc = rows == NULL
        ? facet_error_set(err, FACET_EWORK, "out of memory")
        : describe_surfaces(project, want, rows, err);
    if (rc == FACET_OK) {
        if (json)
            print_project_json(project, rows);
        else
            print_project_human(project, rows);
    }
    free(rows);
    project_close(project);
    return rc;
}

/* ---- one surface ---------------------------------------------------- */

static int info_surface(struct surface *surface, enum param_method want,
                        int json, struct facet_error *err)
{
    int rc = FACET_OK;
    struct uv_report uv;
    memset(&uv, 0, sizeof uv);
    if (surface->mesh.has_uv)
        rc = uv_check(surface->mesh.uv, surface->mesh.ntriangles, &uv, err);
    /* The UV a panelization would take. Without --uv, none applying is
     * part of the description; a method asked for that cannot apply is
     * the error. */
    struct parameterization param;
    struct facet_error why_not;
    memset(&param, 0, sizeof param);
    facet_error_clear(&why_not);
    struct uv_choice choice = {0, &param, ""};
    if (rc == FACET_OK) {
        int prc = param_choose(&surface->mesh, want, surface->path, &param,
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
            print_json(surface, &uv, &choice);
        else
            print_human(surface, &uv, &choice);
    }
    param_free(&param);
    return rc;
}

static int info_files(const char **paths, int npaths,
                      const struct surface_flags *which,
                      const char *uv_text, int json,
                      struct facet_error *err);

/* The options as given (pointing into argv), NULL or 0 when absent. */
struct info_args {
    const char *uv;
    int json;
};

static const struct arg_option info_options[] = {
    {"uv", 0, ARG_STRING, offsetof(struct info_args, uv),
     "vt|grid|plane|harmonic",
     "whether that UV (vt, grid, plane, harmonic) applies; default: say "
     "which is taken and why", NULL},
    {"json", 0, ARG_FLAG, offsetof(struct info_args, json), NULL,
     "one JSON object: vertices, texcoords, normals, faces (as in the "
     "file), triangles, has_uv, uv_valid, uv_method (the UV taken, or "
     "null), uv_reason, bbox [[xmin,ymin,zmin],[xmax,ymax,zmax]] (m), area "
     "(m^2), components, boundary_loops, objects, groups, materials, "
     "warnings", NULL},
    {NULL, 0, ARG_FLAG, 0, NULL, NULL, NULL},
};

static int info_run(int argc, char **argv, struct facet_error *err)
{
    struct surface_flags which = {NULL, NULL, NULL};
    struct info_args a = {NULL, 0};
    const struct arg_table own = {info_options, &a};
    const struct arg_table shared = {surface_flags_options, &which};
    const char *paths[PROJECT_FILES_MAX];
    int npaths;
    int rc = args_parse_surfaces(argc, argv, &own, &shared, paths, &npaths,
                                 err);
    if (rc == FACET_OK)
        rc = info_files(paths, npaths, &which, a.uv, a.json, err);
    return rc;
}

/* info on the files paths[0 .. npaths). */
static int info_files(const char **paths, int npaths,
                      const struct surface_flags *which,
                      const char *uv_text, int json,
                      struct facet_error *err)
{
    int rc;
    if (npaths == 0)
        return facet_error_set(err, FACET_EINPUT,
                               "info: name one OBJ file (facet info "
                               "FILE.obj) or several (a project)");
    struct mesh_options mesh_options;
    if ((rc = surface_flags_apply(which, &mesh_options, err)) != FACET_OK)
        return rc;
    enum param_method want;
    if ((rc = classify_flags_uv(uv_text, &want, err)) != FACET_OK)
        return rc;
    int selected = mesh_options.object != NULL || mesh_options.group != NULL;
    if (npaths > 1) {
        if (selected)
            return facet_error_set(err, FACET_EINPUT,
                "info: --object and --group select in one file; name one "
                "file, or none of them for a project's surfaces");
        struct project project;
        rc = project_open((const char *const *)paths, (size_t)npaths,
                          mesh_options.units,
                          &project, err);
        if (rc != FACET_OK) {
            project_close(&project);
            return rc;
        }
        return info_project(&project, want, json, err);
    }

    /* One file: a project when it names several surfaces and none is
     * selected; read once either way. */
    struct obj_file obj;
    rc = obj_load(paths[0], &obj, err);
    if (rc != FACET_OK) {
        obj_free(&obj);
        return rc;
    }
    if (!selected && project_count_named(&obj) > 1) {
        struct project project;
        rc = project_from_obj(paths[0], &obj, mesh_options.units, &project,
                              err);
        if (rc != FACET_OK) {
            project_close(&project);
            return rc;
        }
        return info_project(&project, want, json, err);
    }
    struct surface surface;
    rc = surface_from_obj(paths[0], &obj, &mesh_options, &surface, err);
    if (rc == FACET_OK)
        rc = info_surface(&surface, want, json, err);
    surface_close(&surface);
    return rc;
}

const struct command cmd_info = {
    .name = "info",
    .usage = "SURFACE.obj... [--units U] [--object NAME] [--group NAME]\n"
             "       [--uv METHOD] [--json]",
    .summary = "Describe a surface: counts, size, area, UV, topology, "
               "warnings; or list a project's surfaces.",
    .before =
        "  A file that names several objects (o), or without any several\n"
        "  groups (g), or several files, are a project: one line per\n"
        "  surface with its name, file, triangles, area (m^2), the UV its\n"
        "  panels follow (vt, grid, plane, harmonic) and its u and v\n"
        "  lengths (m): the mean length of its iso-lines v = const and\n"
        "  u = const. With --json: files, triangles, area and surfaces, each\n"
        "  with name, file, kind (object, group, file), triangles, area,\n"
        "  has_uv, uv_method, uv_reason, u_length, v_length, components,\n"
        "  warnings.\n",
    .options = info_options,
    .shared = surface_flags_options,
    .after = "",
    .run = info_run,
};
