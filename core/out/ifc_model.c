/*
 * ifc_model.c: an option as an IFC4 STEP file. See ifc_model.h.
 */
#include "core/out/ifc_model.h"

#include <assert.h>
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "core/base/numformat.h"
#include "core/base/sha256.h"
#include "core/base/units.h"
#include "core/classify/classify.h"

/* The writer: the file, the next entity's number, the key of the ids. */
struct step {
    FILE *out;
    size_t next;
    const char *key;
};

/* Starts entity #n = and returns n. */
static size_t begin(struct step *s)
{
    size_t n = s->next++;
    fprintf(s->out, "#%zu=", n);
    return n;
}

void ifc_global_id(const unsigned char digest[16], char out[23])
{
    static const char digits[] =
        "0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz_$";
    /* 22 digits of 6 bits hold 132: the number's 128 bits, most
     * significant first, read 6 at a time from bit 131 (the top 4 zero). */
    for (int k = 0; k < 22; k++) {
        int value = 0;
        for (int b = 0; b < 6; b++) {
            int bit = 131 - (6 * k + b);  /* 127 is digest[0]'s top bit */
            int on = 0;
            if (bit <= 127) {
                int from_top = 127 - bit;
                on = (digest[from_top / 8] >> (7 - from_top % 8)) & 1;
            }
            value = value << 1 | on;
        }
        out[k] = digits[value];
    }
    out[22] = '\0';
}

/* The GlobalId of what (printf-style) in s's model, quoted, to s->out. */
static void global_id(struct step *s, const char *what, ...)
{
    char name[128], hex[65];
    va_list ap;
    va_start(ap, what);
    vsnprintf(name, sizeof name, what, ap);
    va_end(ap);
    struct sha256 h;
    sha256_init(&h);
    sha256_update(&h, s->key, strlen(s->key));
    sha256_update(&h, "\n", 1);
    sha256_update(&h, name, strlen(name));
    sha256_hex(&h, hex);
    unsigned char digest[16];
    for (int k = 0; k < 16; k++) {
        unsigned v;
        sscanf(hex + 2 * k, "%2x", &v);
        digest[k] = (unsigned char)v;
    }
    char id[23];
    ifc_global_id(digest, id);
    fprintf(s->out, "'%s'", id);
}

/* The code point of the UTF-8 sequence at *p, advancing *p past it; an
 * ill-formed byte is U+FFFD, the replacement character, and one byte. */
static uint32_t next_code_point(const unsigned char **p)
{
    const unsigned char *c = *p;
    int extra = c[0] >= 0xF0 && c[0] <= 0xF4 ? 3
              : c[0] >= 0xE0 ? 2 : c[0] >= 0xC2 && c[0] < 0xE0 ? 1 : -1;
    if (c[0] >= 0xF5)
        extra = -1;
    uint32_t cp = extra == 3 ? c[0] & 0x07u : extra == 2 ? c[0] & 0x0Fu
                : c[0] & 0x1Fu;
    for (int k = 1; extra > 0 && k <= extra; k++) {
        if ((c[k] & 0xC0) != 0x80) {
            extra = -1;
            break;
        }
        cp = cp << 6 | (c[k] & 0x3Fu);
    }
    /* Overlong forms, surrogates and beyond U+10FFFF are ill-formed. */
    if ((extra == 2 && (cp < 0x800 || (cp >= 0xD800 && cp <= 0xDFFF))) ||
        (extra == 3 && (cp < 0x10000 || cp > 0x10FFFF)))
        extra = -1;
    if (extra < 0) {
        *p = c + 1;
        return 0xFFFD;
    }
    *p = c + 1 + extra;
    return cp;
}

void ifc_write_string(FILE *out, const char *text)
{
    const unsigned char *p = (const unsigned char *)text;
    int wide = 0;  /* 2 or 4 inside \X2\ or \X4\, closed by \X0\ */
    fputc('\'', out);
    while (*p) {
        uint32_t cp = *p < 0x80 ? *p++ : next_code_point(&p);
        int need = cp >= 0x20 && cp <= 0x7E ? 0 : cp <= 0xFFFF ? 2 : 4;
        if (need != wide && wide)
            fputs("\\X0\\", out);
        if (need != wide && need)
            fprintf(out, "\\X%d\\", need);
        wide = need;
        if (need == 2)
            fprintf(out, "%04X", (unsigned)cp);
        else if (need == 4)
            fprintf(out, "%08X", (unsigned)cp);
        else if (cp == '\'')
            fputs("''", out);
        else if (cp == '\\')
            fputs("\\\\", out);
        else
            fputc((int)cp, out);
    }
    if (wide)
        fputs("\\X0\\", out);
    fputc('\'', out);
}

/* A finite value as a STEP real: the shortest text that reads back
 * (numformat.h), with the decimal point STEP requires ("1." "1.E-05"). */
static void real(FILE *out, double value)
{
    assert(isfinite(value));
    char text[NUMBER_EXACT_SIZE];
    number_exact(text, value);
    char *e = strchr(text, 'e');
    if (e != NULL)
        *e = 'E';
    if (strchr(text, '.') == NULL) {
        if (e != NULL) {
            fprintf(out, "%.*s.%s", (int)(e - text), text, e);
            return;
        }
        fprintf(out, "%s.", text);
        return;
    }
    fputs(text, out);
}

/* The fixed part of the model: units, contexts, project, site, building,
 * storey, placements. What the surfaces need of it. */
struct frame {
    size_t origin;       /* IfcAxis2Placement3D at the origin */
    size_t body;         /* the 'Body' subcontext */
    size_t storey;       /* the IfcBuildingStorey */
    size_t storey_place; /* its IfcLocalPlacement */
    size_t millimetre;   /* IfcSIUnit mm, of the deviation */
    size_t usd;          /* IfcMonetaryUnit, of the cost */
};

static void write_frame(struct step *s, const struct ifc_model *m,
                        struct frame *f)
{
    FILE *o = s->out;
    size_t metre = begin(s);
    fputs("IFCSIUNIT(*,.LENGTHUNIT.,$,.METRE.);\n", o);
    size_t square = begin(s);
    fputs("IFCSIUNIT(*,.AREAUNIT.,$,.SQUARE_METRE.);\n", o);
    size_t cubic = begin(s);
    fputs("IFCSIUNIT(*,.VOLUMEUNIT.,$,.CUBIC_METRE.);\n", o);
    size_t radian = begin(s);
    fputs("IFCSIUNIT(*,.PLANEANGLEUNIT.,$,.RADIAN.);\n", o);
    f->usd = begin(s);
    fputs("IFCMONETARYUNIT('USD');\n", o);
    f->millimetre = begin(s);
    fputs("IFCSIUNIT(*,.LENGTHUNIT.,.MILLI.,.METRE.);\n", o);
    size_t units = begin(s);
    fprintf(o, "IFCUNITASSIGNMENT((#%zu,#%zu,#%zu,#%zu,#%zu));\n", metre,
            square, cubic, radian, f->usd);
    size_t point = begin(s);
    fputs("IFCCARTESIANPOINT((0.,0.,0.));\n", o);
    f->origin = begin(s);
    fprintf(o, "IFCAXIS2PLACEMENT3D(#%zu,$,$);\n", point);
    size_t model = begin(s);
    fprintf(o, "IFCGEOMETRICREPRESENTATIONCONTEXT($,'Model',3,1.E-05,#%zu,"
            "$);\n", f->origin);
    f->body = begin(s);
    fprintf(o, "IFCGEOMETRICREPRESENTATIONSUBCONTEXT('Body','Model',*,*,*,"
            "*,#%zu,$,.MODEL_VIEW.,$);\n", model);
    size_t project = begin(s);
    fputs("IFCPROJECT(", o);
    global_id(s, "project");
    fputs(",$,", o);
    ifc_write_string(o, m->title);
    fprintf(o, ",$,$,$,$,(#%zu),#%zu);\n", model, units);
    size_t site_place = begin(s);
    fprintf(o, "IFCLOCALPLACEMENT($,#%zu);\n", f->origin);
    size_t site = begin(s);
    fputs("IFCSITE(", o);
    global_id(s, "site");
    fprintf(o, ",$,'Site',$,$,#%zu,$,$,.ELEMENT.,$,$,$,$,$);\n", site_place);
    size_t building_place = begin(s);
    fprintf(o, "IFCLOCALPLACEMENT(#%zu,#%zu);\n", site_place, f->origin);
    size_t building = begin(s);
    fputs("IFCBUILDING(", o);
    global_id(s, "building");
    fprintf(o, ",$,'Building',$,$,#%zu,$,$,.ELEMENT.,$,$,$);\n",
            building_place);
    f->storey_place = begin(s);
    fprintf(o, "IFCLOCALPLACEMENT(#%zu,#%zu);\n", building_place, f->origin);
    f->storey = begin(s);
    fputs("IFCBUILDINGSTOREY(", o);
    global_id(s, "storey");
    fprintf(o, ",$,'Facade',$,$,#%zu,$,$,.ELEMENT.,0.);\n", f->storey_place);
    const size_t whole[3] = {project, site, building};
    const size_t part[3] = {site, building, f->storey};
    for (int k = 0; k < 3; k++) {
        begin(s);
        fputs("IFCRELAGGREGATES(", o);
        global_id(s, "aggregate %d", k);
        fprintf(o, ",$,$,$,#%zu,(#%zu));\n", whole[k], part[k]);
    }
}

/* A property of a panel: its name, then the value as written. */
static size_t property_label(struct step *s, const char *name,
                             const char *type, const char *value)
{
    size_t n = begin(s);
    fprintf(s->out, "IFCPROPERTYSINGLEVALUE('%s',$,%s(", name, type);
    ifc_write_string(s->out, value);
    fputs("),$);\n", s->out);
    return n;
}

static size_t property_integer(struct step *s, const char *name, long value,
                               int known)
{
    size_t n = begin(s);
    if (known)
        fprintf(s->out, "IFCPROPERTYSINGLEVALUE('%s',$,IFCINTEGER(%ld),$);\n",
                name, value);
    else
        fprintf(s->out, "IFCPROPERTYSINGLEVALUE('%s',$,$,$);\n", name);
    return n;
}

/* A measure; unit 0: the project's. */
static size_t property_measure(struct step *s, const char *name,
                               const char *type, double value, size_t unit)
{
    size_t n = begin(s);
    fprintf(s->out, "IFCPROPERTYSINGLEVALUE('%s',$,", name);
    if (isfinite(value)) {
        fprintf(s->out, "%s(", type);
        real(s->out, value);
        fputc(')', s->out);
    } else {
        fputc('$', s->out);
    }
    if (unit)
        fprintf(s->out, ",#%zu);\n", unit);
    else
        fputs(",$);\n", s->out);
    return n;
}

#define PANEL_PROPERTIES 13

/* Panel n of surface, numbered id: its body, plate and property set.
 * Returns the plate's entity number, or 0 with err set. */
static size_t write_panel(struct step *s, const struct frame *f,
                          const struct ifc_surface *surface, size_t n,
                          size_t id, size_t wall_place,
                          struct facet_error *err)
{
    FILE *o = s->out;
    const struct panel *p = &surface->panels->panels[n];
    const struct panel_geometry *g = surface->geometry;
    size_t v0 = g->panel_vertex[n], v1 = g->panel_vertex[n + 1];
    size_t q0 = g->panel_piece[n], q1 = g->panel_piece[n + 1];
    for (size_t v = v0; v < v1; v++)
        for (int d = 0; d < 3; d++)
            if (!isfinite(g->position[3 * v + d])) {
                facet_error_set(err, FACET_EINPUT, "panel %zu (%d, %d) of "
                                "%s has a point that is not finite", id,
                                p->i, p->j, surface->name);
                return 0;
            }
    /* A body needs a triangle: a panel without one (no pieces) has none. */
    size_t triangles = 0;
    for (size_t q = q0; q < q1; q++)
        if (g->piece_start[q + 1] - g->piece_start[q] >= 3)
            triangles += g->piece_start[q + 1] - g->piece_start[q] - 2;
    size_t shape = 0;
    if (triangles > 0) {
        size_t points = begin(s);
        fputs("IFCCARTESIANPOINTLIST3D((", o);
        for (size_t v = v0; v < v1; v++) {
            fputs(v > v0 ? ",(" : "(", o);
            for (int d = 0; d < 3; d++) {
                if (d)
                    fputc(',', o);
                real(o, g->position[3 * v + d]);
            }
            fputc(')', o);
        }
        fputs("));\n", o);
        size_t faces = begin(s);
        fprintf(o, "IFCTRIANGULATEDFACESET(#%zu,$,$,(", points);
        int first = 1;
        for (size_t q = q0; q < q1; q++) {
            size_t c0 = g->piece_start[q], c1 = g->piece_start[q + 1];
            /* A convex piece as a fan from its first corner; indices
             * into the point list are 1-based. */
            for (size_t c = c0 + 1; c + 1 < c1; c++) {
                fprintf(o, "%s(%zu,%zu,%zu)", first ? "" : ",",
                        g->corner[c0] - v0 + 1, g->corner[c] - v0 + 1,
                        g->corner[c + 1] - v0 + 1);
                first = 0;
            }
        }
        fputs("),$);\n", o);
        size_t representation = begin(s);
        fprintf(o, "IFCSHAPEREPRESENTATION(#%zu,'Body','Tessellation',"
                "(#%zu));\n", f->body, faces);
        shape = begin(s);
        fprintf(o, "IFCPRODUCTDEFINITIONSHAPE($,$,(#%zu));\n",
                representation);
    }
    size_t place = begin(s);
    fprintf(o, "IFCLOCALPLACEMENT(#%zu,#%zu);\n", wall_place, f->origin);
    size_t plate = begin(s);
    fputs("IFCPLATE(", o);
    global_id(s, "panel %zu", id);
    fprintf(o, ",$,'%zu',$,$,#%zu,", id, place);
    if (shape)
        fprintf(o, "#%zu", shape);
    else
        fputc('$', o);
    fprintf(o, ",'%zu',.CURTAIN_PANEL.);\n", id);

    char text[32];
    size_t property[PANEL_PROPERTIES], k = 0;
    snprintf(text, sizeof text, "%zu", id);
    property[k++] = property_label(s, "PanelId", "IFCIDENTIFIER", text);
    property[k++] = property_label(s, "Surface", "IFCLABEL", surface->name);
    property[k++] = property_integer(s, "ColumnI", p->i, 1);
    property[k++] = property_integer(s, "RowJ", p->j, 1);
    property[k++] = property_label(s, "TypeAsClassed", "IFCLABEL",
                                   panel_type_name(p->type));
    property[k++] = property_label(s, "TypeAsBuilt", "IFCLABEL",
                                   panel_type_name(p->built));
    property[k++] = property_label(s, "Class", "IFCLABEL",
                                   panel_class_name(p->class));
    property[k++] = property_integer(s, "MouldFamily", p->mould,
                                     p->mould >= 0);
    property[k++] = property_measure(s, "Deviation", "IFCLENGTHMEASURE",
                                     units_mm(p->deviation), f->millimetre);
    property[k++] = property_measure(s, "Area", "IFCAREAMEASURE", p->area,
                                     0);
    property[k++] = property_measure(s, "Cost", "IFCMONETARYMEASURE",
                                     p->cost, f->usd);
    property[k++] = property_measure(s, "CornerDistance", "IFCLENGTHMEASURE",
        units_mm(panel_corner_distance(surface->panels, n)), f->millimetre);
    property[k++] = property_measure(s, "CornerMoved", "IFCLENGTHMEASURE",
        units_mm(panel_corner_moved(surface->panels, n)), f->millimetre);
    assert(k == PANEL_PROPERTIES);
    size_t set = begin(s);
    fputs("IFCPROPERTYSET(", o);
    global_id(s, "panel %zu properties", id);
    fputs(",$,'Facet_Panel',$,(", o);
    for (k = 0; k < PANEL_PROPERTIES; k++)
        fprintf(o, "%s#%zu", k ? "," : "", property[k]);
    fputs("));\n", o);
    begin(s);
    fputs("IFCRELDEFINESBYPROPERTIES(", o);
    global_id(s, "panel %zu defined by", id);
    fprintf(o, ",$,$,$,(#%zu),#%zu);\n", plate, set);
    return plate;
}

/* A surface's curtain wall and its panels, ids from *id on. Returns the
 * wall's entity number, or 0 with err set. */
static size_t write_surface(struct step *s, const struct frame *f,
                            const struct ifc_surface *surface, size_t k,
                            size_t *id, struct facet_error *err)
{
    FILE *o = s->out;
    const struct panelization *panels = surface->panels;
    assert(surface->geometry->npanels == panels->npanels);
    size_t place = begin(s);
    fprintf(o, "IFCLOCALPLACEMENT(#%zu,#%zu);\n", f->storey_place, f->origin);
    size_t wall = begin(s);
    fputs("IFCCURTAINWALL(", o);
    global_id(s, "surface %zu", k);
    fputs(",$,", o);
    ifc_write_string(o, surface->name);
    fprintf(o, ",$,$,#%zu,$,$,.NOTDEFINED.);\n", place);
    if (panels->npanels == 0)
        return wall;
    size_t *plate = malloc(panels->npanels * sizeof *plate);
    if (plate == NULL) {
        facet_error_set(err, FACET_EWORK, "out of memory");
        return 0;
    }
    for (size_t n = 0; n < panels->npanels; n++, (*id)++)
        if ((plate[n] = write_panel(s, f, surface, n, *id, place, err)) ==
            0) {
            free(plate);
            return 0;
        }
    begin(s);
    fputs("IFCRELAGGREGATES(", o);
    global_id(s, "surface %zu panels", k);
    fprintf(o, ",$,$,$,#%zu,(", wall);
    for (size_t n = 0; n < panels->npanels; n++)
        fprintf(o, "%s#%zu", n ? "," : "", plate[n]);
    fputs("));\n", o);
    free(plate);
    return wall;
}

int ifc_model_write(FILE *out, const struct ifc_model *m,
                    struct facet_error *err)
{
    struct step s = {out, 1, m->key};
    struct tm t;
    char stamp[32] = "1970-01-01T00:00:00";
    time_t created = m->created;
    if (gmtime_r(&created, &t) != NULL)
        strftime(stamp, sizeof stamp, "%Y-%m-%dT%H:%M:%S", &t);
    fputs("ISO-10303-21;\nHEADER;\n"
          "FILE_DESCRIPTION(('ViewDefinition [ReferenceView_V1.2]'),"
          "'2;1');\nFILE_NAME(", out);
    ifc_write_string(out, m->title);
    fprintf(out, ",'%s',('Facet'),('Facet'),", stamp);
    ifc_write_string(out, m->application);
    fputc(',', out);
    ifc_write_string(out, m->application);
    fputs(",'');\nFILE_SCHEMA(('IFC4'));\nENDSEC;\nDATA;\n", out);
    struct frame f;
    write_frame(&s, m, &f);
    size_t *wall = malloc((m->nsurfaces ? m->nsurfaces : 1) * sizeof *wall);
    if (wall == NULL)
        return facet_error_set(err, FACET_EWORK, "out of memory");
    size_t id = 1;
    for (size_t k = 0; k < m->nsurfaces; k++)
        if ((wall[k] = write_surface(&s, &f, &m->surfaces[k], k, &id,
                                     err)) == 0) {
            free(wall);
            return err->code;
        }
    if (m->nsurfaces > 0) {
        begin(&s);
        fputs("IFCRELCONTAINEDINSPATIALSTRUCTURE(", out);
        global_id(&s, "storey contains");
        fputs(",$,$,$,(", out);
        for (size_t k = 0; k < m->nsurfaces; k++)
            fprintf(out, "%s#%zu", k ? "," : "", wall[k]);
        fprintf(out, "),#%zu);\n", f.storey);
    }
    free(wall);
    fputs("ENDSEC;\nEND-ISO-10303-21;\n", out);
    if (ferror(out))
        return facet_error_set(err, FACET_EWORK, "writing the IFC model "
                               "failed");
    return FACET_OK;
}
