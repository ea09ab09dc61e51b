#!/usr/bin/env bash
# End-to-end: projects of many surfaces. The example skin and small files
# through `facet info`, checked against a Python reading of the files and
# Debian's tinyobjloader (project_check.py), and the project's errors.
# layers: core cli
. "$(dirname "$0")/lib.sh"
CHECK=$(dirname "$0")/project_check.py

# The skin at the default resolution: at least 100 faces, 2M triangles.
expect "example skin writes" 0 "$FACET" example skin -o "$WORK/skin.obj"
objects=$(grep -c '^o ' "$WORK/skin.obj")
faces=$(grep -c '^f ' "$WORK/skin.obj")
if [ "$objects" -ge 100 ] && [ "$faces" -ge 2000000 ]; then
    pass "skin: $objects objects, $faces triangles"
else
    echo "not ok - skin: $objects objects, $faces triangles (want >= 100, >= 2M)"
fi
faces_with_vt=$(grep -c '^f [0-9]*/[0-9]* [0-9]*/[0-9]* [0-9]*/[0-9]*$' "$WORK/skin.obj")
same "every skin face has its vt" "$faces_with_vt" "$faces"
run "$FACET" info "$WORK/skin.obj" --json
json_check "info lists the skin's 180 surfaces, every one on its vt" \
    'len(j["surfaces"])==180 and all(s["uv_method"]=="vt" for s in j["surfaces"]) and j["triangles"]=='"$faces"
rm -f "$WORK/skin.obj"

# A small skin, against the independent readings.
"$FACET" example skin --res 5 -o "$WORK/s5.obj" || exit 1
run "$FACET" info "$WORK/s5.obj" --json
/usr/bin/python3 "$CHECK" "$OUT" "$WORK/s5.obj" || echo "not ok - project_check.py on the small skin (status $?)"
json_check "a podium's flat face is 12 m x 20 m along u and v" \
    '[(round(s["u_length"],9), round(s["v_length"],9), round(s["area"],9)) for s in j["surfaces"] if s["name"]=="skin_r00_c00"]==[(12.0,20.0,240.0)]'
run "$FACET" info "$WORK/s5.obj"
stdout_has "human info: the project line" '^project +1 file, 180 surfaces, 9000 triangles'
stdout_has "human info: one row per surface" '^skin_r08_c19 +s5\.obj +50 +[0-9.]+ vt +[0-9.]+ +[0-9.]+$'

# Several files: groups, a file without names, a quad and a pentagon.
printf 'v 0 0 0\nv 2 0 0\nv 2 1 0\nv 0 1 0\ng east_a\nf 1 2 3 4\ng east_b\nf 4 3 1\n' >"$WORK/east.obj"
printf 'v 0 0 0\nv 1 0 0\nv 1.5 1 0.5\nv 0.5 2 1\nv -0.5 1 0\nf 1 2 3 4 5\n' >"$WORK/roof.obj"
run "$FACET" info "$WORK/east.obj" "$WORK/roof.obj" --json
/usr/bin/python3 "$CHECK" "$OUT" "$WORK/east.obj" "$WORK/roof.obj" || echo "not ok - project_check.py on several files (status $?)"
json_check "a file without names is one surface named after it" \
    '[s["kind"] for s in j["surfaces"]]==["group","group","file"] and j["surfaces"][2]["name"]=="roof"'

# Two objects in one file: a project of two.
printf 'o left\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\no right\nv 5 0 0\nv 6 0 0\nv 5 1 0\nf 4 5 6\n' >"$WORK/two.obj"
run "$FACET" info "$WORK/two.obj" --json
json_check "two objects: two surfaces" '[s["name"] for s in j["surfaces"]]==["left","right"]'
run "$FACET" info "$WORK/two.obj" --object right --json
json_check "--object still describes one surface" 'j["triangles"]==1 and j["components"]==1'

# Errors: one line naming the file, the line and the surface.
printf 'o a\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nf 1/1 2/2 3/3\no b\nf 1 2 3\n' >"$WORK/novt.obj"
expect_error "a face without vt names file, line and object" \
    "novt\.obj:10: object 'b': a face without vt" "$FACET" info "$WORK/novt.obj"
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\no a\nf 1 2 3\no b\nf 1 2 3\no a\nf 1 2 3\n' >"$WORK/again.obj"
expect_error "a name used twice names both lines" \
    "again\.obj:9: object 'a' again.*line 5" "$FACET" info "$WORK/again.obj"
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\ng none\ng one\nf 1 2 3\ng two\nf 1 2 3\n' >"$WORK/empty.obj"
expect_error "an empty group names its line" \
    "empty\.obj:4: group 'none' has no faces" "$FACET" info "$WORK/empty.obj"
cp "$WORK/two.obj" "$WORK/other.obj"
expect_error "a name in two files names both" \
    "other\.obj:5: object 'left' is also in .*two\.obj \(line 5\)" \
    "$FACET" info "$WORK/two.obj" "$WORK/other.obj"
expect_error "--object with several files" "select in one file" \
    "$FACET" info "$WORK/two.obj" "$WORK/east.obj" --object left
