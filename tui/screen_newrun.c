/*
 * screen_newrun.c: New run: a form for a surface (OBJ path), its units,
 * the design space (u and v ranges, flatness threshold), the method, the
 * seed, the prices of FP, SP and DP panels, SP priced as FP, the largest
 * panel, the cost model beyond area (per panel, per metre of joint, per
 * mould, the mould tolerance and whether mirror images share a mould),
 * a building's panel module and its surfaces' own grids (a project run:
 * several files, comma-separated, or one OBJ of many objects, searched
 * over modules in place of U and V, as facet optimize --module and
 * --grid) and the welding tolerance its seams are found at (--weld),
 * the objectives, and a name; Tab completes the surface's path
 * (directories and
 * OBJ files, complete.h). F5 (or Enter on the last field) starts the
 * study in a worker thread (job.h) and opens the run's options table,
 * which fills in live while the status line shows a progress gauge.
 * Under the form, before it starts: how many options the run will
 * evaluate and about how long that takes at the rate of the earlier runs
 * in the file. Ctrl-X stops the run (it stays resumable). "Like this"
 * (screen_newrun_like) fills the form from a run and one of its options,
 * with the space narrowed around the option (a building's: its files,
 * the module one step either way, its surfaces' own grids and its weld),
 * and the run's objectives. The other classification
 * settings are the paper's defaults; facet optimize takes them all.
 */
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "app.h"
#include "complete.h"
#include "format.h"
#include "input.h"
#include "job.h"
#include "keys.h"
#include "core/base/numformat.h"
#include "core/base/numparse.h"
#include "core/project/module.h"
#include "core/project/project.h"
#include "core/project/project_grids.h"
#include "core/project/seam.h"
#include "core/search/metric.h"
#include "study/study.h"
#include "study/study_estimate.h"

enum field { F_SURFACE, F_UNITS, F_U, F_V, F_THRESHOLD, F_METHOD, F_SEED,
             F_PRICES, F_SP_AS_FP, F_MAX_AREA, F_PANEL_COST, F_JOINT_COST,
             F_MOULD_COST, F_MOULD_TOL, F_MOULD_MIRROR, F_SP_FIT, F_MAX_GAP,
             F_MAX_KINK, F_WELD, F_MODULE, F_GRIDS, F_OBJECTIVES, F_NAME,
             F_COUNT };

/* At most LABEL_WIDTH - 1 columns each. */
static const char *const field_label[F_COUNT] = {
    "Surface (OBJ)", "Units", "U (panels)", "V (panels)", "Threshold (mm)",
    "Method", "Seed", "Prices FP,SP,DP", "SP priced as FP", "Max panel m^2",
    "Panel cost USD/panel", "Joint cost USD/m", "Mould cost SP,DP USD",
    "Mould tolerance (mm)", "Mirrors share moulds", "SP panels fitted",
    "Max gap (mm)", "Max kink (deg)", "Seam weld (mm)", "Module W x H (m)",
    "Surface grids",
    "Objectives", "Name"};
#define LABEL_WIDTH 22
static const char *const field_hint[F_COUNT] = {
    "path of the OBJ file; Tab completes it (directories, .obj files)",
    "m, cm, mm, in or ft; empty: m, refused if the size says otherwise",
    "A:B, panels along u", "A:B, panels along v",
    "MM, A:B or A:B:STEP", "auto, exhaustive, random or nsga2",
    "a whole number; the same seed gives the same options",
    "USD/m^2 of flat, single- and double-curved panels",
    "yes or no (the paper's MOGD prices SP area as FP)",
    "the largest panel that can be made (m^2): feasibility",
    "USD per panel, whatever its type (0: area alone, the paper's model)",
    "USD per metre of joint: panel edges once each, the outline",
    "USD per mould: a bending jig for SP, a mould for DP (e.g. 2000,15000)",
    "curved panels within it share a mould; empty: the flatness threshold",
    "yes or no: a panel and its mirror image share a mould",
    "yes: an SP panel no cylinder or cone fits within t is built DP",
    "feasible only when no joint's gap exceeds it; empty: no limit",
    "feasible only when no joint's kink exceeds it; empty: no limit",
    "a building: surfaces whose edges come this close meet at a seam, "
    "measured with the joints (needs the module); empty: 1 mm",
    "a building: panel modules WMIN:WMAX x HMIN:HMAX (m) in place of U and "
    "V; the surface: files, comma-separated, or one OBJ of many objects",
    "a building's surfaces with a grid of their own, NAME=NUxNV,... "
    "(needs the module)",
    "metrics to minimise, comma-separated, max:NAME to maximise; empty: "
    "cost,planarity,dp_area",
    "optional"};

struct newrun_screen {
    struct tui_screen base;
    struct tui_input field[F_COUNT];
    int focus;
    int top;           /* the first field shown, when they do not all fit */
    int64_t opened;    /* the run whose table was opened */
    struct tui_completion completion;  /* the last Tab's candidates */
    int listing;       /* they show under the form */
    struct study_rate rate;  /* of the earlier runs of the file (of this
                                surface when there are) */
    /* a building's files, split from the surface field, and its
     * surfaces' own grids: what build's request points into */
    char files_text[4096];
    const char *files[PROJECT_FILES_MAX];
    struct surface_grid_overrides grids;
};

static const struct tui_key_help newrun_help[] = {
    {"Tab", "on the surface: complete the path (again: list the choices);"
            " elsewhere: next field"},
    {"Down", "next field"},
    {"Shift-Tab, Up", "previous field"},
    {"Enter", "next field; on the last one, start"},
    {"F5", "start the run"},
    {"Esc", "back without starting"},
    {"(typing)", "edits the field; Ctrl-U clears it"},
    {NULL, NULL},
};

static void estimate_text(struct newrun_screen *s, char *out, size_t size);

static void newrun_draw(struct tui_screen *base, struct tui_app *app,
                        int height, int width)
{
    struct newrun_screen *s = (struct newrun_screen *)base;
    (void)height;
    tui_fill(0, 0, width, tui_attr(ROLE_TITLE));
    tui_putf(0, 0, width, tui_attr(ROLE_TITLE), " New run into %s",
             app->db_path);
    int lw = LABEL_WIDTH, fw = width - lw - 4;
    /* Under the fields: a blank, the hint and the estimate. On a screen
     * too short for them all the fields scroll, the focus in view, with
     * ^ and v in the margin where more are above or below. */
    int shown = height - 5 < 1 ? 1 : height - 5 < F_COUNT ? height - 5
                                                          : F_COUNT;
    if (s->focus < s->top)
        s->top = s->focus;
    if (s->focus >= s->top + shown)
        s->top = s->focus - shown + 1;
    if (s->top > F_COUNT - shown)
        s->top = F_COUNT - shown;
    for (int f = s->top; f < s->top + shown; f++) {
        int y = 2 + f - s->top;
        tui_putf(y, 1, lw, f == s->focus ? tui_attr(ROLE_HEADER) : A_NORMAL,
                 "%-*s", lw - 1, field_label[f]);
        attr_t attr = f == s->focus ? tui_attr(ROLE_SELECTION) : A_UNDERLINE;
        tui_fill(y, lw + 2, fw, attr);
        size_t from = f == s->focus ? tui_input_scroll(&s->field[f], fw) : 0;
        tui_put(y, lw + 2, fw, attr, s->field[f].text + from);
    }
    if (s->top > 0)
        tui_put(2, 0, 1, tui_attr(ROLE_DIM), "^");
    if (s->top + shown < F_COUNT)
        tui_put(1 + shown, 0, 1, tui_attr(ROLE_DIM), "v");
    int y = 3 + shown;
    tui_put(y, 1, width - 2, tui_attr(ROLE_DIM), field_hint[s->focus]);
    char estimate[256];
    estimate_text(s, estimate, sizeof estimate);
    tui_put(y + 1, 1, width - 2, tui_attr(ROLE_PARETO),
            app->job ? "A run is working (see the gauge below)."
                     : estimate);
    if (s->listing && s->focus == F_SURFACE) {
        const struct tui_completion *c = &s->completion;
        /* Under the estimate when three lines of choices fit there, else
         * over the fields below the surface's (they wait while a path is
         * chosen). */
        if (y + 7 > height) {
            y = 1;  /* the surface's field is on row 2 */
            for (int row = y + 2; row < height; row++)
                tui_fill(row, 0, width, A_NORMAL);
        }
        int top = y + 3, colw = 1;
        for (int k = 0; k < c->kept; k++)
            if ((int)strlen(c->name[k]) + 2 > colw)
                colw = (int)strlen(c->name[k]) + 2;
        if (colw > width - 2)
            colw = width - 2;
        int per_row = (width - 2) / colw, lines = height - top - 1;
        tui_putf(y + 2, 1, width - 2, tui_attr(ROLE_HEADER),
                 " %d choices%s", c->count,
                 c->count > c->kept ? " (the first shown)" : "");
        for (int k = 0; k < c->kept && lines > 0 &&
                        k / per_row < lines; k++)
            tui_put(top + k / per_row, 1 + (k % per_row) * colw, colw - 1,
                    c->name[k][strlen(c->name[k]) - 1] == '/'
                        ? tui_attr(ROLE_HEADER) : A_NORMAL,
                    c->name[k]);
    }
    if (app->prompt == NULL && !app->help_open && s->focus < F_COUNT) {
        size_t from = tui_input_scroll(&s->field[s->focus], fw);
        move(2 + s->focus - s->top,
             lw + 2 + (int)(s->field[s->focus].cursor - from));
        curs_set(1);
    }
}

/* Tab on the surface field: completes the path; a second Tab that adds
 * nothing lists the choices; a path that is complete goes on to the next
 * field. */
static void complete(struct newrun_screen *s, struct tui_app *app)
{
    struct tui_input *in = &s->field[F_SURFACE];
    int n = tui_complete_path(in->text, &s->completion);
    if (n == 0) {
        s->listing = 0;
        tui_error(app, "no directory or .obj file begins with '%s'",
                  in->text);
        return;
    }
    if (strcmp(s->completion.text, in->text) != 0) {
        tui_input_set(in, s->completion.text);
        s->listing = n > 1 && s->listing;
        if (n == 1 && in->text[in->length - 1] != '/')
            tui_status(app, "%s", in->text);
        return;
    }
    if (n == 1 && in->text[in->length - 1] != '/') {
        s->listing = 0;
        s->focus++;
        return;
    }
    s->listing = 1;
}

/* The form's labels in the messages of the design space's checks. */
static const struct design_space_names form_names = {
    "U (panels)", "V (panels)", "Threshold (mm)"};

/* A yes/no field f into *out: yes, y or 1; no, n, 0 or empty.
 * FACET_EINPUT names the field by its label. */
static int parse_yes_no(const struct newrun_screen *s, enum field f,
                        int *out, struct facet_error *err)
{
    const char *yes = s->field[f].text;
    if (strcmp(yes, "yes") == 0 || strcmp(yes, "y") == 0 ||
        strcmp(yes, "1") == 0)
        *out = 1;
    else if (strcmp(yes, "no") == 0 || strcmp(yes, "n") == 0 ||
             strcmp(yes, "0") == 0 || yes[0] == '\0')
        *out = 0;
    else
        return facet_error_set(err, FACET_EINPUT,
            "%s: '%s' is not yes or no", field_label[f], yes);
    return FACET_OK;
}

/* The number of field f, in [min, max], into *out (numparse_number,
 * naming the field by its label). */
static int parse_number(const struct newrun_screen *s, enum field f,
                        double min, double max, double *out,
                        struct facet_error *err)
{
    return numparse_number(s->field[f].text, min, max, field_label[f], out,
                           err);
}

/* An optional limit of field f (empty: none, 0), in [min, max] times
 * scale, into *out. */
static int parse_limit(const struct newrun_screen *s, enum field f,
                       double min, double max, double scale, double *out,
                       struct facet_error *err)
{
    *out = 0;
    if (s->field[f].text[0] == '\0')
        return FACET_OK;
    int rc = parse_number(s, f, min, max, out, err);
    *out *= scale;
    return rc;
}

/* Panels as built: the SP fit and the limits on gaps and kinks, into c. */
static int build_as_built(const struct newrun_screen *s,
                          struct classify_options *c,
                          struct facet_error *err)
{
    int fitted;
    int rc = parse_yes_no(s, F_SP_FIT, &fitted, err);
    if (rc == FACET_OK)
        rc = parse_limit(s, F_MAX_GAP, CLASSIFY_MAX_GAP_MIN_MM,
                         CLASSIFY_MAX_GAP_MAX_MM, 1e-3, &c->max_gap, err);
    if (rc == FACET_OK)
        rc = parse_limit(s, F_MAX_KINK, CLASSIFY_MAX_KINK_MIN_DEG,
                         CLASSIFY_MAX_KINK_MAX_DEG, M_PI / 180, &c->max_kink,
                         err);
    c->sp_by_class = !fitted;
    return rc;
}

/* The cost model beyond area and the mould settings, into params. */
static int build_costs(const struct newrun_screen *s,
                       struct option_params *params, struct facet_error *err)
{
    struct classify_options *c = &params->classify;
    int rc = parse_number(s, F_PANEL_COST, 0, CLASSIFY_AMOUNT_MAX,
                          &c->panel_cost, err);
    if (rc == FACET_OK)
        rc = parse_number(s, F_JOINT_COST, 0, CLASSIFY_AMOUNT_MAX,
                          &c->joint_cost, err);
    if (rc == FACET_OK)
        rc = classify_mould_costs_parse(s->field[F_MOULD_COST].text,
                                        field_label[F_MOULD_COST],
                                        c->mould_cost, err);
    if (rc != FACET_OK)
        return rc;
    /* empty: each option's flatness threshold, as the defaults have it */
    params->mould_tol_given = s->field[F_MOULD_TOL].text[0] != '\0';
    if (params->mould_tol_given) {
        double mm;
        if ((rc = parse_number(s, F_MOULD_TOL, 0, CLASSIFY_MOULD_TOL_MAX_MM,
                               &mm, err)))
            return rc;
        params->mould_tol = mm / 1000;
    }
    if ((rc = parse_yes_no(s, F_MOULD_MIRROR, &params->mould_mirror, err)))
        return rc;
    return build_as_built(s, &params->classify, err);
}

/* The surface field into r: one OBJ file, or with a module a building
 * (a project): the field's files, comma-separated (a field that names a
 * readable file is that one file, commas and all), with the surface
 * grids' overrides. */
static int surfaces(struct newrun_screen *s, struct study_request *r,
                    struct facet_error *err)
{
    const char *path = s->field[F_SURFACE].text;
    const char *module = s->field[F_MODULE].text;
    const char *grids = s->field[F_GRIDS].text;
    const char *weld = s->field[F_WELD].text;
    if (path[0] == '\0')
        return facet_error_set(err, FACET_EINPUT, "name the surface's OBJ "
                               "file");
    size_t n = 0;
    int readable = access(path, R_OK) == 0;
    if (readable || strchr(path, ',') == NULL) {
        if (!readable)
            return facet_error_set(err, FACET_EINPUT, "%s: cannot read it",
                                   path);
        snprintf(s->files_text, sizeof s->files_text, "%s", path);
        s->files[n++] = s->files_text;
    } else {
        if (strlen(path) >= sizeof s->files_text)
            return facet_error_set(err, FACET_EINPUT,
                                   "%s: too long", field_label[F_SURFACE]);
        snprintf(s->files_text, sizeof s->files_text, "%s", path);
        for (char *item = s->files_text; item != NULL;) {
            char *next = strchr(item, ',');
            if (next != NULL)
                *next++ = '\0';
            while (*item == ' ')
                item++;
            if (*item == '\0')
                return facet_error_set(err, FACET_EINPUT,
                    "%s: an empty file name between commas",
                    field_label[F_SURFACE]);
            if (n == PROJECT_FILES_MAX)
                return facet_error_set(err, FACET_EINPUT,
                    "%s: more than %d files", field_label[F_SURFACE],
                    PROJECT_FILES_MAX);
            if (access(item, R_OK) != 0)
                return facet_error_set(err, FACET_EINPUT,
                                       "%s: cannot read it", item);
            s->files[n++] = item;
            item = next;
        }
    }
    r->surface_path = s->files[0];
    if (module[0] == '\0') {
        if (n > 1)
            return facet_error_set(err, FACET_EINPUT,
                "a building of %zu files needs a panel module: give %s", n,
                field_label[F_MODULE]);
        if (grids[0] != '\0')
            return facet_error_set(err, FACET_EINPUT,
                "%s give a building's surfaces their own grid: they need %s",
                field_label[F_GRIDS], field_label[F_MODULE]);
        if (weld[0] != '\0')
            return facet_error_set(err, FACET_EINPUT,
                "%s is where a building's surfaces meet: it needs %s",
                field_label[F_WELD], field_label[F_MODULE]);
        return FACET_OK;
    }
    int rc = module_parse(module, field_label[F_MODULE], &r->module, err);
    if (rc == FACET_OK)
        rc = surface_grid_overrides_parse(grids, field_label[F_GRIDS],
                                          &s->grids, err);
    /* empty: the default tolerance, as facet optimize without --weld */
    if (rc == FACET_OK && weld[0] != '\0')
        rc = seam_weld_parse(weld, field_label[F_WELD], &r->weld, err);
    if (rc != FACET_OK)
        return rc;
    r->files = s->files;
    r->nfiles = n;
    r->override_names = (const char *const *)s->grids.name;
    r->overrides = s->grids.grid;
    r->noverrides = s->grids.n;
    return FACET_OK;
}

/* The request the form describes, over study_request_defaults;
 * FACET_EINPUT names the bad field by its label. */
static int build(struct newrun_screen *s, struct study_request *r,
                 struct facet_error *err)
{
    study_request_defaults(r);
    int rc = surfaces(s, r, err);
    if (rc != FACET_OK)
        return rc;
    r->name = s->field[F_NAME].text;
    /* Empty is the CLI without --units: metres, checked against the
     * mesh's size (a building drawn in mm is refused, not run 1000 times
     * too large). Units typed, m too, are the user's word, as --units. */
    const char *units = s->field[F_UNITS].text;
    r->units_named = units[0] != '\0';
    rc = r->units_named ? mesh_units_parse(units, field_label[F_UNITS],
                                           &r->mesh.units, err)
                        : FACET_OK;
    struct optimize_settings *o = &r->settings;
    if (rc == FACET_OK && r->nfiles > 0)
        rc = study_project_space(&r->module, &o->space, err);
    if (rc == FACET_OK && r->nfiles == 0)
        rc = design_space_parse_sides(s->field[F_U].text, field_label[F_U],
                                      &o->space.u_min, &o->space.u_max, err);
    if (rc == FACET_OK && r->nfiles == 0)
        rc = design_space_parse_sides(s->field[F_V].text, field_label[F_V],
                                      &o->space.v_min, &o->space.v_max, err);
    if (rc == FACET_OK)
        rc = design_space_parse_threshold(s->field[F_THRESHOLD].text,
                                          field_label[F_THRESHOLD],
                                          &o->space, err);
    if (rc == FACET_OK)
        rc = design_space_check(&o->space, &form_names, err);
    if (rc != FACET_OK)
        return rc;
    const char *method = s->field[F_METHOD].text;
    if ((rc = study_method_parse(method[0] ? method : "auto",
                                 field_label[F_METHOD], &o->space,
                                 &o->method, err)))
        return rc;
    if ((rc = optimize_method_check(o->method, &o->space, &form_names, err)))
        return rc;
    if (s->field[F_OBJECTIVES].text[0] != '\0' &&
        (rc = objectives_parse(s->field[F_OBJECTIVES].text,
                               field_label[F_OBJECTIVES], o->objectives,
                               &o->nobjectives, err)))
        return rc;
    const char *seed = s->field[F_SEED].text, *stop;
    long long number;
    if (numparse_whole(seed, seed + strlen(seed), 0, LLONG_MAX, &number,
                       &stop) != NUMPARSE_OK || *stop != '\0')
        return facet_error_set(err, FACET_EINPUT,
            "%s: '%s' is not a whole number from 0 to %lld",
            field_label[F_SEED], seed, LLONG_MAX);
    o->seed = (uint64_t)number;
    struct classify_options *c = &o->base.classify;
    if ((rc = classify_prices_parse(s->field[F_PRICES].text,
                                    field_label[F_PRICES], c->price, err)))
        return rc;
    if ((rc = parse_yes_no(s, F_SP_AS_FP, &c->sp_as_fp, err)) ||
        (rc = parse_number(s, F_MAX_AREA, CLASSIFY_PANEL_AREA_MIN,
                           CLASSIFY_PANEL_AREA_MAX, &c->max_panel_area,
                           err)) ||
        (rc = build_costs(s, &o->base, err)))
        return rc;
    return classify_check_options(c, err);
}

/* "336 options (exhaustive), about 0.6 s at 560/s (2 earlier runs)", or
 * why the form cannot start. */
static void estimate_text(struct newrun_screen *s, char *out, size_t size)
{
    struct study_request r;
    struct facet_error err;
    if (build(s, &r, &err) != FACET_OK) {
        snprintf(out, size, "Not ready: %.200s", err.message);
        return;
    }
    int64_t n;
    double seconds;
    study_estimate(&s->rate, &r.settings, r.nfiles > 0, &n, &seconds);
    char count[32], time[32];
    tui_fmt_number(count, sizeof count, (double)n, 0, 1);
    /* NSGA-II evaluates a point met twice once: at most so many */
    char method[32];
    snprintf(method, sizeof method, "%s%s",
             optimize_method_name(r.settings.method),
             r.settings.method == METHOD_NSGA2 ? ", at most" : "");
    if (seconds > 0) {
        tui_fmt_elapsed(time, sizeof time, seconds);
        snprintf(out, size, "F5 starts: %s options (%s), about %s at %.0f/s "
                 "(%d earlier run%s)", count, method, time,
                 (double)n / seconds, s->rate.runs,
                 s->rate.runs == 1 ? "" : "s");
    } else {
        snprintf(out, size, "F5 starts: %s options (%s); no earlier run in "
                 "this file to time them by", count, method);
    }
}

/* The rate of the file's finished runs, of this surface where there are
 * any (unknown when the file cannot list them). */
static void measure_rate(struct newrun_screen *s, struct tui_app *app,
                         const char *surface)
{
    struct facet_error err;
    if (study_rate_measure(app->store, surface, &s->rate, &err) != FACET_OK)
        memset(&s->rate, 0, sizeof s->rate);
}

static void start(struct newrun_screen *s, struct tui_app *app)
{
    if (app->job != NULL) {
        tui_error(app, "a run is already working; Ctrl-X stops it");
        return;
    }
    struct study_request request;
    struct facet_error err;
    if (build(s, &request, &err) != FACET_OK ||
        tui_job_start(app->db_path, &request, &app->job, &err) != FACET_OK) {
        tui_error(app, "new run: %s", err.message);
        return;
    }
    s->opened = 0;
    tui_status(app, "starting the run");
}

static enum tui_result newrun_key(struct tui_screen *base,
                                  struct tui_app *app, int key)
{
    struct newrun_screen *s = (struct newrun_screen *)base;
    if (key != '\t')
        s->listing = 0;
    switch (key) {
    case KEY_F(5):
        start(s, app);
        return RESULT_HANDLED;
    case '\t':
        if (s->focus == F_SURFACE) {
            complete(s, app);
            return RESULT_HANDLED;
        }
        s->focus = (s->focus + 1) % F_COUNT;
        return RESULT_HANDLED;
    case KEY_DOWN:
        s->focus = (s->focus + 1) % F_COUNT;
        return RESULT_HANDLED;
    case KEY_BTAB: case KEY_UP:
        s->focus = (s->focus + F_COUNT - 1) % F_COUNT;
        return RESULT_HANDLED;
    case 27: case KEY_F(10): case KEY_F(1):
        return RESULT_UNHANDLED;
    default:
        break;
    }
    enum tui_input_result r = tui_input_key(&s->field[s->focus], key);
    if (r == INPUT_DONE) {
        if (s->focus == F_COUNT - 1)
            start(s, app);
        else
            s->focus++;
    }
    return RESULT_HANDLED;
}

/* Opens the run's table once the study has recorded it. */
static int newrun_tick(struct tui_screen *base, struct tui_app *app)
{
    struct newrun_screen *s = (struct newrun_screen *)base;
    if (app->job == NULL || s->opened)
        return 0;
    struct tui_job_state st;
    tui_job_state(app->job, &st);
    if (st.run <= 0)
        return 0;
    /* the run may not show through this connection yet: try again at the
     * next tick */
    struct tui_screen *table = screen_options_new(app, st.run);
    if (table == NULL)
        return 0;
    app->status[0] = '\0';
    s->opened = st.run;
    tui_push(app, table);
    return 1;
}

static void newrun_destroy(struct tui_screen *base)
{
    curs_set(0);
    free(base);
}

static const struct tui_screen_class newrun_class = {
    "New run", newrun_help,
    {"Help", NULL, NULL, NULL, "Start", NULL, NULL, NULL, NULL, "Quit"},
    newrun_draw, newrun_key, newrun_tick, newrun_destroy,
};

/* field f shows value so that it reads back as the same double. */
static void set_number(struct newrun_screen *s, enum field f, double value)
{
    char text[NUMBER_EXACT_SIZE];
    number_exact(text, value);
    tui_input_set(&s->field[f], text);
}

/* An optional limit's field: empty for NaN (none). */
static void set_limit(struct newrun_screen *s, enum field f, double value)
{
    if (isnan(value))
        tui_input_set(&s->field[f], "");
    else
        set_number(s, f, value);
}

/* The fields of the prices, the size limit, the cost model and panels as
 * built from params, the defaults' or a run's, with the mould tolerance
 * and the limits on gaps and kinks in the run's own units from limits
 * (NaN: none, an empty field; the tolerance's none is each option's
 * flatness threshold), so that they read back as the run's numbers. */
static void set_classification(struct newrun_screen *s,
                               const struct option_params *params,
                               const struct run_info *limits)
{
    double mould_tol_mm = limits->mould_tol_mm;
    const struct classify_options *c = &params->classify;
    char text[3 * NUMBER_EXACT_SIZE + 2], n[TYPE_COUNT][NUMBER_EXACT_SIZE];
    for (int t = 0; t < TYPE_COUNT; t++)
        number_exact(n[t], c->price[t]);
    snprintf(text, sizeof text, "%s,%s,%s", n[TYPE_FP], n[TYPE_SP],
             n[TYPE_DP]);
    tui_input_set(&s->field[F_PRICES], text);
    tui_input_set(&s->field[F_SP_AS_FP], c->sp_as_fp ? "yes" : "no");
    set_number(s, F_MAX_AREA, c->max_panel_area);
    set_number(s, F_PANEL_COST, c->panel_cost);
    set_number(s, F_JOINT_COST, c->joint_cost);
    number_exact(n[TYPE_SP], c->mould_cost[TYPE_SP]);
    number_exact(n[TYPE_DP], c->mould_cost[TYPE_DP]);
    snprintf(text, sizeof text, "%s,%s", n[TYPE_SP], n[TYPE_DP]);
    tui_input_set(&s->field[F_MOULD_COST], text);
    if (!isnan(mould_tol_mm))
        set_number(s, F_MOULD_TOL, mould_tol_mm);
    else
        tui_input_set(&s->field[F_MOULD_TOL], "");
    tui_input_set(&s->field[F_MOULD_MIRROR],
                  params->mould_mirror ? "yes" : "no");
    tui_input_set(&s->field[F_SP_FIT], c->sp_by_class ? "no" : "yes");
    set_limit(s, F_MAX_GAP, limits->max_gap_mm);
    set_limit(s, F_MAX_KINK, limits->max_kink_deg);
}

struct tui_screen *screen_newrun_new(struct tui_app *app,
                                     const char *surface_path)
{
    struct newrun_screen *s = calloc(1, sizeof *s);
    if (s == NULL) {
        tui_error(app, "out of memory");
        return NULL;
    }
    s->base.cls = &newrun_class;
    /* the form opens on the defaults `facet optimize` takes too */
    struct study_request r;
    study_request_defaults(&r);
    const struct design_space *d = &r.settings.space;
    char u[32], v[32], t[32], seed[32];
    snprintf(u, sizeof u, "%d:%d", d->u_min, d->u_max);
    snprintf(v, sizeof v, "%d:%d", d->v_min, d->v_max);
    snprintf(t, sizeof t, "%g", d->t_min_mm);
    snprintf(seed, sizeof seed, "%llu", (unsigned long long)r.settings.seed);
    const char *const defaults[F_COUNT] = {
        [F_SURFACE] = "", [F_UNITS] = "",
        [F_U] = u, [F_V] = v, [F_THRESHOLD] = t, [F_METHOD] = "auto",
        [F_SEED] = seed, [F_NAME] = r.name};
    for (int f = 0; f < F_COUNT; f++)
        if (defaults[f] != NULL)
            tui_input_set(&s->field[f], defaults[f]);
    /* the defaults in a run's units: none of the limits given */
    struct run_info none;
    memset(&none, 0, sizeof none);
    none.mould_tol_mm = r.settings.base.mould_tol_given
                            ? r.settings.base.mould_tol * 1000 : NAN;
    none.max_gap_mm = none.max_kink_deg = NAN;
    set_classification(s, &r.settings.base, &none);
    measure_rate(s, app, surface_path);
    if (surface_path) {
        tui_input_set(&s->field[F_SURFACE], surface_path);
        s->focus = F_UNITS;
        if (access(surface_path, R_OK) != 0)
            tui_error(app, "%s: cannot read it", surface_path);
    }
    return &s->base;
}

/* A module value as the form shows it: to the nanometre, as module_parse
 * rounds it, so that 1.5 - 0.1 reads 1.4. */
static void module_text(char *out, size_t size, double m)
{
    snprintf(out, size, "%.12g", round(m * 1e9) / 1e9);
}

/* One module side narrowed around value: one step of the run either way
 * (the run's own step; the least module below), as "LO:HI:STEP". */
static void module_side(char *out, size_t size, double value, double step)
{
    char lo[40], hi[40], by[40];
    if (!(step >= MODULE_MIN))
        step = MODULE_DEFAULT_STEP;
    module_text(lo, sizeof lo, value - step >= MODULE_MIN ? value - step
                                                          : value);
    module_text(hi, sizeof hi, value + step);
    module_text(by, sizeof by, step);
    snprintf(out, size, "%s:%s:%s", lo, hi, by);
}

/* The building fields of the form from a project run and one of its
 * options: its files in surface order (each once, comma-separated), the
 * module one step either way, the surfaces' own grids and the welding
 * tolerance the run had. FACET_EINPUT when the form cannot hold them (a
 * file name with a comma among several, or too long a list). */
static int like_building(struct newrun_screen *s, struct tui_app *app,
                         const struct run_info *run,
                         const struct option_row *option,
                         struct facet_error *err)
{
    struct surface_row *rows = NULL;
    size_t n = 0;
    int rc = store_surfaces_get(app->store, run->id, &rows, &n, err);
    if (rc != FACET_OK)
        return rc;
    char files[TUI_INPUT_MAX] = "", grids[TUI_INPUT_MAX] = "";
    size_t nfiles = 0, used = 0, gused = 0;
    const char *comma = NULL;   /* a file name with a comma, in rows */
    for (size_t k = 0; k < n && rc == FACET_OK; k++) {
        int seen = 0;
        for (size_t j = 0; j < k && !seen; j++)
            seen = strcmp(rows[j].file, rows[k].file) == 0;
        if (!seen) {
            if (strchr(rows[k].file, ',') != NULL)
                comma = rows[k].file;
            int w = snprintf(files + used, sizeof files - used, "%s%s",
                             nfiles ? "," : "", rows[k].file);
            if (w < 0 || (size_t)w >= sizeof files - used)
                rc = facet_error_set(err, FACET_EINPUT,
                    "its files do not fit the %s field",
                    field_label[F_SURFACE]);
            else
                used += (size_t)w;
            nfiles++;
        }
        if (rc == FACET_OK && rows[k].grid_nu > 0) {
            if (strchr(rows[k].name, ',') != NULL)
                rc = facet_error_set(err, FACET_EINPUT,
                    "surface '%s' has its own grid and a comma in its name",
                    rows[k].name);
            int w = snprintf(grids + gused, sizeof grids - gused,
                             "%s%s=%dx%d", gused ? "," : "", rows[k].name,
                             rows[k].grid_nu, rows[k].grid_nv);
            if (rc == FACET_OK && (w < 0 || (size_t)w >= sizeof grids - gused))
                rc = facet_error_set(err, FACET_EINPUT,
                    "the surfaces' own grids do not fit the %s field",
                    field_label[F_GRIDS]);
            else if (rc == FACET_OK)
                gused += (size_t)w;
        }
    }
    /* one file is itself, commas and all (surfaces, above); among several
     * its commas would split it */
    if (rc == FACET_OK && comma != NULL && nfiles > 1)
        rc = facet_error_set(err, FACET_EINPUT,
                             "%s: a comma in a file name of several", comma);
    free(rows);
    if (rc == FACET_OK && nfiles == 0)
        rc = facet_error_set(err, FACET_EINPUT, "run %lld has no surfaces",
                             (long long)run->id);
    if (rc != FACET_OK)
        return rc;
    char width[128], height[128], module[260];
    module_side(width, sizeof width, option->module_w, run->module_w_step);
    module_side(height, sizeof height, option->module_h, run->module_h_step);
    snprintf(module, sizeof module, "%sx%s", width, height);
    tui_input_set(&s->field[F_SURFACE], files);
    tui_input_set(&s->field[F_MODULE], module);
    tui_input_set(&s->field[F_GRIDS], grids);
    set_limit(s, F_WELD, run->weld_mm);
    return FACET_OK;
}

struct tui_screen *screen_newrun_like(struct tui_app *app,
                                      const struct run_info *run,
                                      const struct option_row *option)
{
    struct tui_screen *base = screen_newrun_new(app, run->surface_path);
    if (base == NULL)
        return NULL;
    struct newrun_screen *s = (struct newrun_screen *)base;
    char text[128];
    tui_input_set(&s->field[F_UNITS],
                  store_run_setting_text(run, RUN_SETTING_UNITS));
    /* the grid two panels either way, never below one panel (a
     * building's option is a module, its nu and nv the module's indices:
     * like_building below) */
    if (!store_run_is_project(run)) {
        int u0 = option->nu - 2 > 1 ? option->nu - 2 : 1;
        int v0 = option->nv - 2 > 1 ? option->nv - 2 : 1;
        snprintf(text, sizeof text, "%d:%d", u0, option->nu + 2);
        tui_input_set(&s->field[F_U], text);
        snprintf(text, sizeof text, "%d:%d", v0, option->nv + 2);
        tui_input_set(&s->field[F_V], text);
    }
    /* the threshold one step of the run either way (0.5 mm when it had
     * none), in quarter steps */
    double t = option->threshold_mm;
    double step = run->threshold_step_mm > 0 ? run->threshold_step_mm : 0.5;
    double lo = t - step > 0 ? t - step : 0;
    snprintf(text, sizeof text, "%g:%g:%g", lo, t + step, step / 4);
    tui_input_set(&s->field[F_THRESHOLD], text);
    tui_input_set(&s->field[F_METHOD], "auto");
    snprintf(text, sizeof text, "%llu", (unsigned long long)run->seed);
    tui_input_set(&s->field[F_SEED], text);
    /* the run's classification and cost model as study_settings reads
     * them back, the mould tolerance in the run's own millimetres */
    struct optimize_settings settings;
    struct mesh_options mesh;
    int flip;
    struct facet_error err;
    int rc = study_settings(run, &settings, &mesh, &flip, &err);
    if (rc == FACET_OK)
        set_classification(s, &settings.base, run);
    /* the objectives the run ranked its options by */
    tui_input_set(&s->field[F_OBJECTIVES], run->objectives);
    if (store_run_is_project(run)) {
        struct facet_error building;
        if (like_building(s, app, run, option, &building) != FACET_OK) {
            tui_error(app, "like No. %lld: %s", (long long)option->number,
                      building.message);
            return base;
        }
        s->focus = F_MODULE;
    }
    snprintf(text, sizeof text, "like No. %lld of run %lld",
             (long long)option->number, (long long)run->id);
    tui_input_set(&s->field[F_NAME], text);
    if (!store_run_is_project(run))
        s->focus = F_U;
    if (rc != FACET_OK)
        tui_error(app, "like No. %lld: %s; prices and costs are the "
                  "defaults'", (long long)option->number, err.message);
    else
        tui_status(app, "like No. %lld: %s and t narrowed around it; F5 "
                   "starts", (long long)option->number,
                   store_run_is_project(run) ? "the module" : "U, V");
    return base;
}
