"""developables.py KIND OUT.obj: writes a known developable surface as an
OBJ grid with its parameters as vt, from its formula, for tests that read
back what Facet fitted or unrolled (export_xlsx.sh, export_dxf.sh).

  cylinder  radius 6 m about the axis through (1, 2, 0) along (0.2, 1,
            0.1) (normalised); 100 deg around, 8 m along; 120 x 48 quads
  cone      half-angle 30 deg, apex (-2, 1, 12), axis along (0.1, -0.2,
            -1) (normalised: opening downwards); slant 4 to 11 m, 120 deg
            around; 120 x 60 quads

The truths the tests compare with are printed, one "name value" a line:
radius, axis point and direction (cylinder); apex, axis, half-angle in
degrees (cone)."""
import math
import sys


def unit(v):
    n = math.sqrt(sum(x * x for x in v))
    return [x / n for x in v]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0]]


def frame(axis):
    pick = [1, 0, 0] if abs(axis[0]) < 0.9 else [0, 1, 0]
    e1 = unit(cross(axis, pick))
    return e1, cross(axis, e1)


kind, out = sys.argv[1], sys.argv[2]
if kind == "cylinder":
    R, base, axis = 6.0, [1.0, 2.0, 0.0], unit([0.2, 1.0, 0.1])
    nu, nv, span, length = 120, 48, math.radians(100), 8.0
    e1, e2 = frame(axis)

    def at(u, v):
        t = -span / 2 + span * u
        return [base[k] + length * v * axis[k] +
                R * (math.cos(t) * e1[k] + math.sin(t) * e2[k])
                for k in range(3)]
    print("radius %.17g" % R)
    print("axis_point %.17g %.17g %.17g" % tuple(base))
    print("axis %.17g %.17g %.17g" % tuple(axis))
elif kind == "cone":
    alpha, apex, axis = math.radians(30), [-2.0, 1.0, 12.0], \
        unit([0.1, -0.2, -1.0])
    nu, nv, span, s0, s1 = 120, 60, math.radians(120), 4.0, 11.0
    e1, e2 = frame(axis)

    def at(u, v):
        t = -span / 2 + span * u
        s = s0 + (s1 - s0) * v
        return [apex[k] + s * (math.cos(alpha) * axis[k] + math.sin(alpha) *
                               (math.cos(t) * e1[k] + math.sin(t) * e2[k]))
                for k in range(3)]
    print("apex %.17g %.17g %.17g" % tuple(apex))
    print("axis %.17g %.17g %.17g" % tuple(axis))
    print("half_angle %.17g" % 30.0)
else:
    sys.exit("developables.py: cylinder or cone")
with open(out, "w") as f:
    for j in range(nv + 1):
        for i in range(nu + 1):
            f.write("v %.17g %.17g %.17g\n" % tuple(at(i / nu, j / nv)))
    for j in range(nv + 1):
        for i in range(nu + 1):
            f.write("vt %.17g %.17g\n" % (i / nu, j / nv))
    for j in range(nv):
        for i in range(nu):
            a = j * (nu + 1) + i + 1
            b, c, d = a + 1, a + nu + 2, a + nu + 1
            f.write("f %d/%d %d/%d %d/%d %d/%d\n" % (a, a, b, b, c, c, d, d))
