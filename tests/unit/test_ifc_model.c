/*
 * test_ifc_model.c: the IFC model's STEP text against what ISO 10303-21
 * and IFC say, worked by hand: GlobalIds decoded back digit by digit,
 * strings escaped, reals with their decimal point, a one-panel model's
 * entities; and the same model written twice is the same bytes.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <stdio.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/out/ifc_model.h"

/* GlobalIds: 22 digits of base 64 that read back as the 128 bits. */
static void test_global_id_reads_back(void **state)
{
    (void)state;
    static const char digits[] =
        "0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz_$";
    unsigned char zero[16] = {0}, ones[16], one[16] = {0}, sixty_four[16] =
        {0};
    memset(ones, 0xFF, sizeof ones);
    one[15] = 1;
    sixty_four[15] = 64;
    char id[23];
    ifc_global_id(zero, id);
    assert_string_equal(id, "0000000000000000000000");
    ifc_global_id(ones, id);
    assert_string_equal(id, "3$$$$$$$$$$$$$$$$$$$$$");
    ifc_global_id(one, id);
    assert_string_equal(id, "0000000000000000000001");
    ifc_global_id(sixty_four, id);
    assert_string_equal(id, "0000000000000000000010");
    /* Random digests decoded back: the number times 64 plus each digit,
     * kept as 16 bytes, is the digest. */
    unsigned seed = 12345;
    for (int trial = 0; trial < 1000; trial++) {
        unsigned char digest[16], back[16] = {0};
        for (int k = 0; k < 16; k++) {
            seed = seed * 1103515245u + 12345u;
            digest[k] = (unsigned char)(seed >> 16);
        }
        ifc_global_id(digest, id);
        assert_int_equal(strlen(id), 22);
        assert_true(id[0] >= '0' && id[0] <= '3');
        for (int k = 0; k < 22; k++) {
            const char *at = strchr(digits, id[k]);
            assert_non_null(at);
            unsigned carry = (unsigned)(at - digits);
            for (int b = 15; b >= 0; b--) {
                unsigned v = back[b] * 64u + carry;
                back[b] = (unsigned char)(v & 0xFF);
                carry = v >> 8;
            }
        }
        assert_memory_equal(back, digest, 16);
    }
}

static char *string_of(const char *text)
{
    char *buffer = NULL;
    size_t size = 0;
    FILE *out = open_memstream(&buffer, &size);
    assert_non_null(out);
    ifc_write_string(out, text);
    fclose(out);
    return buffer;
}

static void escaped_as(const char *text, const char *want)
{
    char *got = string_of(text);
    assert_string_equal(got, want);
    free(got);
}

/* ISO 10303-21 7.3.3: ' doubled, \ doubled, the rest printable ASCII;
 * other characters as \X2\ (UCS-2, 4 hex digits each) or \X4\ (8 each),
 * closed by \X0\. */
static void test_string_escapes(void **state)
{
    (void)state;
    escaped_as("roof", "'roof'");
    escaped_as("d'été", "'d''\\X2\\00E9\\X0\\t\\X2\\00E9\\X0\\'");
    escaped_as("a\\b", "'a\\\\b'");
    escaped_as("\xC3\xA7\xE2\x82\xAC", "'\\X2\\00E720AC\\X0\\'");
    escaped_as("x\xF0\x9F\x98\x80y", "'x\\X4\\0001F600\\X0\\y'");
    escaped_as("\t", "'\\X2\\0009\\X0\\'");
    /* Not UTF-8: each such byte the replacement character. */
    escaped_as("a\xFF" "b", "'a\\X2\\FFFD\\X0\\b'");
    escaped_as("\xC3", "'\\X2\\FFFD\\X0\\'");
    escaped_as("", "''");
}

/* A square panel, 2 m x 0.1 m at z = 1e-5, as two pieces: one triangle
 * and one quadrilateral (a fan of two). */
struct one_panel {
    struct panel panel;
    struct panelization panels;
    double position[5 * 3];
    size_t panel_vertex[2], panel_piece[2], piece_start[3], corner[7];
    struct panel_geometry geometry;
    struct ifc_surface surface;
};

static void one_panel(struct one_panel *o)
{
    memset(o, 0, sizeof *o);
    static const double position[5 * 3] = {
        0, 0, 1e-5,  2, 0, 1e-5,  2, 0.1, 1e-5,  0, 0.1, 1e-5,  1, 0, 1e-5};
    memcpy(o->position, position, sizeof position);
    o->panel.i = 3;
    o->panel.j = 4;
    o->panel.class = CLASS_FLAT;
    o->panel.type = TYPE_SP;
    o->panel.built = TYPE_DP;
    o->panel.mould = -1;
    o->panel.deviation = 0.0025;
    o->panel.area = 0.2;
    o->panel.cost = 1234.5;
    o->panels.npanels = 1;
    o->panels.panels = &o->panel;
    o->panel_vertex[1] = 5;
    o->panel_piece[1] = 2;
    /* piece 0: 0 4 3; piece 1: 4 1 2 3 */
    static const size_t corner[7] = {0, 4, 3, 4, 1, 2, 3};
    memcpy(o->corner, corner, sizeof corner);
    o->piece_start[1] = 3;
    o->piece_start[2] = 7;
    o->geometry = (struct panel_geometry){
        .npanels = 1, .nvertices = 5, .position = o->position,
        .panel_vertex = o->panel_vertex, .npieces = 2,
        .panel_piece = o->panel_piece, .piece_start = o->piece_start,
        .corner = o->corner};
    o->surface = (struct ifc_surface){"roof", &o->panels, &o->geometry};
}

static char *model_of(const struct ifc_surface *surface, const char *key)
{
    char *buffer = NULL;
    size_t size = 0;
    FILE *out = open_memstream(&buffer, &size);
    assert_non_null(out);
    struct ifc_model m = {"Facet run 1, option 2", key, 86400 + 3661,
                          "Facet test", 1, surface};
    struct facet_error err;
    assert_int_equal(ifc_model_write(out, &m, &err), FACET_OK);
    fclose(out);
    return buffer;
}

static void test_one_panel_model(void **state)
{
    (void)state;
    struct one_panel o;
    one_panel(&o);
    char *text = model_of(&o.surface, "key");
    assert_non_null(strstr(text, "ISO-10303-21;\nHEADER;\n"));
    assert_non_null(strstr(text, "FILE_NAME('Facet run 1, option 2',"
                                 "'1970-01-02T01:01:01',"));
    assert_non_null(strstr(text, "FILE_SCHEMA(('IFC4'));"));
    /* Reals as STEP writes them: a point always, exponents as E. */
    assert_non_null(strstr(text, "IFCCARTESIANPOINTLIST3D(((0.,0.,1.E-05),"
                                 "(2.,0.,1.E-05),(2.,0.1,1.E-05),"
                                 "(0.,0.1,1.E-05),(1.,0.,1.E-05)));"));
    /* The triangle, then the quadrilateral as a fan from its first
     * corner; 1-based. */
    assert_non_null(strstr(text, "IFCTRIANGULATEDFACESET(#"));
    assert_non_null(strstr(text, ",$,$,((1,5,4),(5,2,3),(5,3,4)),$);"));
    assert_non_null(strstr(text, "IFCSHAPEREPRESENTATION(#"));
    assert_non_null(strstr(text, ",'Body','Tessellation',(#"));
    assert_non_null(strstr(text, ",$,'1',$,$,#"));
    assert_non_null(strstr(text, ",'1',.CURTAIN_PANEL.);"));
    assert_non_null(strstr(text, "IFCPROPERTYSINGLEVALUE('TypeAsClassed',$,"
                                 "IFCLABEL('SP'),$);"));
    assert_non_null(strstr(text, "IFCPROPERTYSINGLEVALUE('TypeAsBuilt',$,"
                                 "IFCLABEL('DP'),$);"));
    assert_non_null(strstr(text, "IFCPROPERTYSINGLEVALUE('Class',$,"
                                 "IFCLABEL('flat'),$);"));
    assert_non_null(strstr(text, "IFCPROPERTYSINGLEVALUE('ColumnI',$,"
                                 "IFCINTEGER(3),$);"));
    /* No mould: no value. */
    assert_non_null(strstr(text, "IFCPROPERTYSINGLEVALUE('MouldFamily',$,$,"
                                 "$);"));
    assert_non_null(strstr(text, "IFCPROPERTYSINGLEVALUE('Deviation',$,"
                                 "IFCLENGTHMEASURE(2.5),#"));
    assert_non_null(strstr(text, "IFCPROPERTYSINGLEVALUE('Area',$,"
                                 "IFCAREAMEASURE(0.2),$);"));
    assert_non_null(strstr(text, "IFCPROPERTYSINGLEVALUE('Cost',$,"
                                 "IFCMONETARYMEASURE(1234.5),#"));
    assert_non_null(strstr(text, "IFCPROPERTYSET("));
    assert_non_null(strstr(text, "'Facet_Panel'"));
    assert_non_null(strstr(text, "ENDSEC;\nEND-ISO-10303-21;\n"));

    /* The same model twice: the same bytes; another key: other ids. */
    char *again = model_of(&o.surface, "key");
    assert_string_equal(text, again);
    char *other = model_of(&o.surface, "another key");
    assert_string_not_equal(text, other);
    assert_int_equal(strlen(text), strlen(other));
    free(text);
    free(again);
    free(other);
}

/* A panel without a triangle: a plate with no body, never an empty face
 * set (IFC's CoordIndex holds one triangle at least). */
static void test_panel_without_pieces(void **state)
{
    (void)state;
    struct one_panel o;
    one_panel(&o);
    o.panel_piece[1] = 0;
    o.geometry.npieces = 0;
    char *text = model_of(&o.surface, "key");
    assert_null(strstr(text, "IFCTRIANGULATEDFACESET"));
    assert_null(strstr(text, "IFCSHAPEREPRESENTATION"));
    assert_non_null(strstr(text, ",$,'1',.CURTAIN_PANEL.);"));
    free(text);
    /* Nor one whose only piece is a segment (two corners): no triangle. */
    one_panel(&o);
    o.panel_piece[1] = 1;
    o.piece_start[1] = 2;
    o.geometry.npieces = 1;
    text = model_of(&o.surface, "key");
    assert_null(strstr(text, "IFCTRIANGULATEDFACESET"));
    assert_non_null(strstr(text, ",$,'1',.CURTAIN_PANEL.);"));
    free(text);
}

/* A panel whose point is not finite is refused, not written as "nan". */
static void test_not_finite_refused(void **state)
{
    (void)state;
    struct one_panel o;
    one_panel(&o);
    o.position[4] = NAN;
    char *buffer = NULL;
    size_t size = 0;
    FILE *out = open_memstream(&buffer, &size);
    struct ifc_model m = {"t", "k", 0, "Facet test", 1, &o.surface};
    struct facet_error err;
    assert_int_equal(ifc_model_write(out, &m, &err), FACET_EINPUT);
    assert_non_null(strstr(err.message, "not finite"));
    fclose(out);
    free(buffer);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_global_id_reads_back),
        cmocka_unit_test(test_string_escapes),
        cmocka_unit_test(test_one_panel_model),
        cmocka_unit_test(test_panel_without_pieces),
        cmocka_unit_test(test_not_finite_refused),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
