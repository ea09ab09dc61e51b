/*
 * seam_shapes.h: the buildings whose seams are known by construction, as
 * formulas for surface_fixture_formula (surface_fixture.h), shared by the
 * tests of the seams (test_seam) and of the map's seam marks
 * (test_tui_map_seams). Metres; s and t run from 0 to 1.
 */
#ifndef FACET_TEST_SEAM_SHAPES_H
#define FACET_TEST_SEAM_SHAPES_H

/* A plane strip 2 m x 1 m in z = 0, x from 0 to 2 (seam_plane_a, no
 * shape); or its continuation past the hinge x = 2 (seam_plane_b, shape
 * a struct hinge), bent up by angle (rad), `width` m wide, moved `apart`
 * m along x; `reversed` winds it the other way (t runs backwards). */
struct hinge {
    double angle, width, apart;
    int reversed;
};

void seam_plane_a(const void *shape, double s, double t, double p[3]);
void seam_plane_b(const void *shape, double s, double t, double p[3]);

/* Half of a cylinder of radius 3 m and height 4 m, from the angle `from`
 * (rad) round by pi: two halves from 0 and pi meet along two rulings. */
struct half {
    double from;
};

void seam_half_cylinder(const void *shape, double s, double t, double p[3]);

#endif
