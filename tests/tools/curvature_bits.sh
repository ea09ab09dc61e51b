#!/usr/bin/env bash
# curvature_bits.sh: whether two builds of the curvature estimator give the
# same bits for every vertex (k1, k2, both directions, the normal and the
# surface normal), on the bundled examples at several sizes (coarse ones
# take the boundary, thin-strip and Newton paths), flipped and not, on one
# thread and on two, and on every OBJ of the real-data folder.
#
#   tests/tools/curvature_bits.sh OLD_DUMP NEW_DUMP FACET [DATA_DIR]
#
# OLD_DUMP and NEW_DUMP are curvature_dump binaries (tests/tools) of the
# two builds, say one of main's and one of a branch's; FACET writes the
# examples. DATA_DIR defaults to ../shared/data; its files are skipped,
# and said so, when it is not there. Prints one line per surface and a
# closing "N passed, N failed"; exits 1 when any differ.
set -u
old=$1 new=$2 facet=$3 data=${4:-../shared/data}
work=$(mktemp -d /tmp/curvature_bits.XXXXXX)
trap 'rm -rf "$work"' EXIT
passed=0 failed=0

compare() {  # name file [dump args...]
    local name=$1 file=$2
    shift 2
    if ! "$old" "$file" "$@" > "$work/old" 2> "$work/old.err" ||
       ! "$new" "$file" "$@" > "$work/new" 2> "$work/new.err"; then
        if cmp -s "$work/old.err" "$work/new.err"; then
            echo "same error: $name $* ($(cat "$work/new.err"))"
            passed=$((passed + 1))
        else
            echo "DIFFERENT errors: $name $*"
            failed=$((failed + 1))
        fi
        return
    fi
    local n
    n=$(head -1 "$work/new")
    if cmp -s "$work/old" "$work/new"; then
        echo "same bits: $name $* ($n)"
        passed=$((passed + 1))
    else
        echo "DIFFERENT: $name $* ($n, $(diff "$work/old" "$work/new" |
              grep -c '^>') lines differ)"
        failed=$((failed + 1))
    fi
}

for example in plane cylinder dome hypar torus wave roof; do
    for res in 2 3 4 6 8 10 20 0; do
        file="$work/$example-$res.obj"
        if [ "$res" = 0 ]; then
            "$facet" example "$example" -o "$file" || exit 2
        else
            "$facet" example "$example" --res "$res" -o "$file" || exit 2
        fi
        compare "$example res ${res/#0/default}" "$file"
        compare "$example res ${res/#0/default}" "$file" --flip-normals
        rm -f "$file"
    done
done
file="$work/skin.obj"
"$facet" example skin --res 8 -o "$file" || exit 2
compare "skin res 8" "$file"
rm -f "$file"
"$facet" example roof --res 224 -o "$file" || exit 2
compare "roof res 224" "$file" --jobs 1
compare "roof res 224" "$file" --jobs 2
rm -f "$file"

if [ -d "$data" ]; then
    for file in "$data"/*.obj; do
        compare "$(basename "$file")" "$file" --jobs 1
        compare "$(basename "$file")" "$file" --flip-normals
    done
else
    echo "real data: skipped, $data is not there"
fi
echo "$passed passed, $failed failed"
[ "$failed" = 0 ]
