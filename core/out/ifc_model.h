/*
 * ifc_model.h: an option as an IFC4 model (ISO 16739-1:2018), the BIM
 * model a facade contractor opens beside the architect's, written as plain
 * STEP text (ISO 10303-21) by Facet itself.
 *
 * The model:
 *   - IfcProject (SI units: metre, square metre, cubic metre, radian; USD),
 *     IfcSite, IfcBuilding and one IfcBuildingStorey, aggregated in that
 *     order, every placement the world's;
 *   - one IfcCurtainWall per surface, contained in the storey, named as
 *     the surface;
 *   - one IfcPlate (CURTAIN_PANEL) per panel, aggregated to its surface's
 *     curtain wall (IfcRelAggregates), its Name and Tag the panel's id
 *     (1.., running on across a building's surfaces, as the CSV and XLSX
 *     schedules number them); its body an IfcTriangulatedFaceSet
 *     ('Body', 'Tessellation') of the panel's pieces (panel_geometry.h),
 *     each convex piece a fan of triangles from its first corner, in the
 *     mesh's winding, positions in metres; a panel without a triangle
 *     (no piece of three corners) has no body, not an empty face set;
 *   - per panel an IfcPropertySet 'Facet_Panel' (IfcRelDefinesByProperties)
 *     of single values: PanelId (IfcIdentifier), Surface (IfcLabel),
 *     ColumnI, RowJ (IfcInteger), TypeAsClassed, TypeAsBuilt, Class
 *     (IfcLabel: FP, SP, DP and the class names of the schedules),
 *     MouldFamily (IfcInteger, 0-based, as the schedules'; no value for a
 *     panel without one), Deviation (IfcLengthMeasure in mm), Area
 *     (IfcAreaMeasure, m^2), Cost (IfcMonetaryMeasure, USD),
 *     CornerDistance and CornerMoved (IfcLengthMeasure in mm: a planarized
 *     option's largest distance of the panel's corners from the design
 *     surface and how far they moved, panel_corner_distance and
 *     panel_corner_moved; no value for a panel whose corners were not
 *     moved, every classified option's): the values the schedules write,
 *     from the same fields. A value not known (NaN) is written as no
 *     value, never 0. A planarized option's moved panel's body is its
 *     moved quad (panel_geometry.h).
 *
 * Every GlobalId is the first 128 bits of the SHA-256 of the model's key
 * and the object's place in it ("panel 12"), in IFC's 22-character base
 * 64; the header's time stamp is the given one, never the clock: the same
 * option written twice is the same file, byte for byte. Strings are
 * escaped as ISO 10303-21 says (' doubled, \ doubled, anything outside
 * printable ASCII as \X2\...\X0\ or \X4\...\X0\ of its UTF-8); numbers are
 * the shortest text that reads back as the same double (numformat.h),
 * whatever the locale.
 */
#ifndef FACET_IFC_MODEL_H
#define FACET_IFC_MODEL_H

#include <stdio.h>
#include <time.h>

#include "core/base/error.h"
#include "core/panel/panel.h"
#include "core/panel/panel_geometry.h"

/* One surface of the option: a single surface's option has one. */
struct ifc_surface {
    const char *name;                        /* the surface's name */
    const struct panelization *panels;       /* classified, evaluated */
    const struct panel_geometry *geometry;   /* of panels */
};

struct ifc_model {
    const char *title;        /* the project's name and the file's:
                                 "Facet run 1, option 5" */
    const char *key;          /* what makes this option's GlobalIds its own
                                 (the run's start, id and option number) */
    time_t created;           /* the header's time stamp */
    const char *application;  /* "Facet 0.1.0": the header's system */
    size_t nsurfaces;
    const struct ifc_surface *surfaces;  /* nsurfaces */
};

/* Writes m to out. Returns FACET_OK, FACET_EINPUT for a panel position
 * that is not finite, or FACET_EWORK when writing failed; out then holds
 * a part of the file and the caller discards it (outfile_abort). */
int ifc_model_write(FILE *out, const struct ifc_model *m,
                    struct facet_error *err);

/* The 22-character IFC GlobalId (and its NUL) of the first 16 bytes of
 * digest, most significant first: the first character 0-3, each other
 * one of 0-9, A-Z, a-z, _ and $. */
void ifc_global_id(const unsigned char digest[16], char out[23]);

/* text as an ISO 10303-21 string, quotes included, into out. */
void ifc_write_string(FILE *out, const char *text);

#endif
