/*
 * units.h: the one place a length or an angle changes unit.
 *
 * Facet computes in SI: lengths in metres, angles in radians. A designer
 * writes and reads a threshold, a gap and a tolerance in millimetres and a
 * kink in degrees, and the store shows those columns in the units users
 * already query (docs/store.md; the store writes an option's gaps and
 * kinks in mm and degrees with these functions, keeping the m and rad
 * beside, store/schema.c v16). Every crossing between the two goes
 * through these functions, so that no number is converted by hand in two
 * places, and a check (tests/e2e/units.sh) fails on a conversion written
 * out anywhere else below the display layer (tui/, cli/), and on one in
 * core/ outside a message and core/out/.
 *
 * Each is the plain expression it names, so a value converted here has
 * the bits it had when the expression was written at its call site.
 */
#ifndef FACET_UNITS_H
#define FACET_UNITS_H

#include <math.h>

/* The length of a millimetre, in metres: an OBJ written in millimetres
 * is scaled by it as it is read. */
#define UNITS_METRES_PER_MM 0.001

/* metres as millimetres. */
static inline double units_mm(double metres)
{
    return metres * 1000;
}

/* metres as kilometres: how a surface read in the wrong units is said. */
static inline double units_km(double metres)
{
    return metres / 1000;
}

/* millimetres as metres. */
static inline double units_m_of_mm(double millimetres)
{
    return millimetres / 1000;
}

/* radians as degrees. */
static inline double units_deg(double radians)
{
    return radians * 180 / M_PI;
}

/* degrees as radians. */
static inline double units_rad_of_deg(double degrees)
{
    return degrees * M_PI / 180;
}

#endif
