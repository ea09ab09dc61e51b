"""export_cover.py: an exported OBJ covers its surface exactly.

    export_cover.py EXPORT.obj SCHEDULE.csv SURFACE.obj

Reads both OBJ files with Debian's tinyobjloader (polygons as written) and
the schedule with the csv module, and checks, by brute force:
  - every SP or DP panel's exported faces add up to its schedule area
    (1e-9 relative, or 1e-12 of the surface for a panel so small that
    its corners' twelve written digits matter): an SP or DP panel is
    written as its surface patch;
  - the surface's area, summed here from its own polygons, equals the
    exported SP and DP faces plus the FP panels' schedule areas (1e-9
    relative). An FP panel is written on its best-fit plane (a planar
    polygon, not the patch: export_obj.h), so its exported area cannot be
    the surface's; its schedule area stands in for it, and its exported
    polygon must be within 1e-3 of that area.
A triangle missing from the export, or written twice, breaks the second
sum whichever panel it falls in. Prints the figures; exits 1 with the
reason on stderr when a check fails.

A quad is cut as Facet's triangulate.h says (along the diagonal from its one
reflex corner in its Newell plane, else a-c), since a non-planar quad's area
depends on the diagonal; larger polygons of the real files are planar
enough that a fan gives their area.
"""
import csv
import sys

import tinyobjloader


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0])


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def triangle_area(a, b, c):
    n = cross(sub(b, a), sub(c, a))
    return 0.5 * dot(n, n) ** 0.5


def fan_area(p):
    return sum(triangle_area(p[0], p[k], p[k + 1]) for k in range(1, len(p) - 1))


def newell(p):
    n = [0.0, 0.0, 0.0]
    for k in range(len(p)):
        a, b = p[k], p[(k + 1) % len(p)]
        n[0] += (a[1] - b[1]) * (a[2] + b[2])
        n[1] += (a[2] - b[2]) * (a[0] + b[0])
        n[2] += (a[0] - b[0]) * (a[1] + b[1])
    return n


def quad_area(p):
    """Two triangles as triangulate_quad cuts them."""
    n = newell(p)
    for k in range(4):
        a, b, c = p[k - 1], p[k], p[(k + 1) % 4]
        if dot(cross(sub(b, a), sub(c, b)), n) < 0:
            # Corner k is reflex: the diagonal from it.
            q = p[k:] + p[:k]
            return triangle_area(q[0], q[1], q[2]) + triangle_area(q[0], q[2], q[3])
    return triangle_area(p[0], p[1], p[2]) + triangle_area(p[0], p[2], p[3])


def polygons(path):
    """(group name, [corner positions]) for every face of path."""
    reader = tinyobjloader.ObjReader()
    config = tinyobjloader.ObjReaderConfig()
    config.triangulate = False
    if not reader.ParseFromFile(path, config):
        raise SystemExit("tinyobjloader cannot read %s: %s" % (path, reader.Error().strip()))
    v = list(reader.GetAttrib().vertices)
    out = []
    for s in reader.GetShapes():
        idx = [i.vertex_index for i in s.mesh.indices]
        at = 0
        for n in s.mesh.num_face_vertices:
            # "g panel_I_J mould_K" is one shape; its panel is the first name.
            out.append((s.name.split()[0] if s.name else "", [tuple(v[3 * idx[at + k] + c] for c in range(3))
                                 for k in range(n)]))
            at += n
    return out


def fail(msg):
    print(msg, file=sys.stderr)
    sys.exit(1)


def main():
    export, schedule, surface = sys.argv[1:4]
    rows = list(csv.DictReader(open(schedule, newline="")))
    exported = {}
    for name, p in polygons(export):
        exported[name] = exported.get(name, 0.0) + fan_area(p)
    mesh = 0.0
    for _, p in polygons(surface):
        mesh += quad_area(p) if len(p) == 4 else fan_area(p)
    # A small panel's own 1e-9 is below what twelve written digits keep of
    # its corners (export_obj.c); 1e-12 of the surface stands for that.
    floor = 1e-12 * mesh
    sp_dp = fp = 0.0
    worst = (0.0, None)
    for r in rows:
        name = "panel_%s_%s" % (r["i"], r["j"])
        want, got = float(r["area_m2"]), exported.pop(name, 0.0)
        if r["type"] == "FP":
            fp += want
            if abs(got - want) > 1e-3 * want:
                fail("FP %s: exported %.12g m^2, schedule %.12g" % (name, got, want))
            continue
        sp_dp += got
        off = abs(got - want) / max(want, 1e-300)
        if off > worst[0]:
            worst = (off, name)
        if abs(got - want) > max(1e-9 * want, floor):
            fail("%s %s: exported %.12g m^2, schedule %.12g" % (r["type"], name, got, want))
    if exported:
        fail("groups not in the schedule: %s" % sorted(exported)[:5])
    total = sp_dp + fp
    print("surface %.12g m^2, exported SP+DP %.12g + FP schedule %.12g = %.12g "
          "(%.2g relative); worst panel %.2g" % (mesh, sp_dp, fp, total,
                                                 abs(total - mesh) / mesh, worst[0]))
    if abs(total - mesh) > 1e-9 * mesh:
        fail("exported %.12g m^2, surface %.12g: %.12g m^2 %s" % (
            total, mesh, abs(total - mesh), "missing" if total < mesh else "too much"))


if __name__ == "__main__":
    main()
