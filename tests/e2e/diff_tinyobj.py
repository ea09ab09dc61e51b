"""diff_tinyobj.py: compares what Facet's loader reads with Debian's
tinyobjloader (python3-tinyobjloader, double precision) for one OBJ file.

    diff_tinyobj.py OBJDUMP FILE

Runs OBJDUMP FILE (tests/tools/objdump.c) and tinyobjloader (triangulate
on), then compares vertex, texcoord, normal and triangle counts and every
coordinate. tinyobjloader's own number parser is not always correctly
rounded, so coordinates must agree to 1e-12 relative (or 1e-300 absolute).
Prints "ok - NAME" or "not ok - NAME" and mismatches; exits 0 if they agree.
"""
import os
import subprocess
import sys

import tinyobjloader

TOLERANCE = 1e-12


def facet_read(objdump, path):
    out = subprocess.run([objdump, path], capture_output=True, text=True)
    if out.returncode != 0:
        raise RuntimeError(out.stderr.strip())
    counts, arrays = {}, {"v": [], "vt": [], "vn": []}
    for line in out.stdout.splitlines():
        word, _, rest = line.partition(" ")
        if word in arrays:
            arrays[word].extend(float(x) for x in rest.split())
        elif word != "t":
            counts[word] = int(rest)
    return counts, arrays


def tiny_read(path):
    reader = tinyobjloader.ObjReader()
    config = tinyobjloader.ObjReaderConfig()
    config.triangulate = True
    if not reader.ParseFromFile(path, config):
        raise RuntimeError(reader.Error().strip())
    attrib = reader.GetAttrib()
    ntriangles = sum(len(s.mesh.indices) // 3 for s in reader.GetShapes())
    counts = {"vertices": len(attrib.vertices) // 3,
              "texcoords": len(attrib.texcoords) // 2,
              "normals": len(attrib.normals) // 3,
              "triangles": ntriangles}
    arrays = {"v": list(attrib.vertices), "vt": list(attrib.texcoords),
              "vn": list(attrib.normals)}
    return counts, arrays


def compare(objdump, path):
    problems = []
    try:
        fc, fa = facet_read(objdump, path)
    except RuntimeError as e:
        return ["objdump failed: %s" % e]
    try:
        tc, ta = tiny_read(path)
    except RuntimeError as e:
        return ["tinyobjloader failed: %s" % e]
    for key in ("vertices", "texcoords", "normals", "triangles"):
        if fc.get(key) != tc[key]:
            problems.append("%s: facet %s, tinyobjloader %s"
                            % (key, fc.get(key), tc[key]))
    for key in ("v", "vt", "vn"):
        a, b = fa[key], ta[key]
        if len(a) != len(b):
            continue  # already reported as a count
        bad = [i for i, (x, y) in enumerate(zip(a, b))
               if abs(x - y) > max(TOLERANCE * max(abs(x), abs(y)), 1e-300)]
        for i in bad[:5]:
            problems.append("%s number %d: facet %.17g, tinyobjloader %.17g"
                            % (key, i, a[i], b[i]))
        if len(bad) > 5:
            problems.append("%s: %d more differences" % (key, len(bad) - 5))
    return problems


def main():
    if len(sys.argv) != 3:
        sys.stderr.write("usage: diff_tinyobj.py OBJDUMP FILE\n")
        return 2
    objdump, path = sys.argv[1], sys.argv[2]
    problems = compare(objdump, path)
    name = os.path.basename(path)
    print(("not ok - " if problems else "ok - ") + "tinyobjloader agrees: "
          + name)
    for p in problems:
        print("  " + p)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
