#!/usr/bin/env bash
# End-to-end: facet export (OBJ + MTL, CSV, JSON, SVG map) of a stored
# option, facet plot of runs, and their errors.
# layers: cli study store
. "$(dirname "$0")/lib.sh"
CHECK="/usr/bin/python3 $(dirname "$0")/export_check.py"
DB=$WORK/r.db

fixture roof40.obj "$WORK/roof.obj" || exit 1
"$FACET" optimize "$WORK/roof.obj" --db "$DB" --u 6:10 --v 6:10 \
    --max-panel-area 100 >/dev/null 2>&1 || exit 1
"$FACET" optimize "$WORK/roof.obj" --db "$DB" --u 5:9 --v 7:11 \
    --max-panel-area 100 >/dev/null 2>&1 || exit 1
KNEE=$(sqlite3 "$DB" 'SELECT number FROM options WHERE run=1 AND knee')
[ -n "$KNEE" ] || { echo "not ok - run 1 has a knee"; exit 1; }
GRID=$(sqlite3 "$DB" "SELECT nu || 'x' || nv FROM options WHERE run=1 AND number=$KNEE")
PANELS=$(sqlite3 "$DB" "SELECT panels FROM options WHERE run=1 AND number=$KNEE")
N1=$(sqlite3 "$DB" 'SELECT count(*) FROM options WHERE run=1')
N2=$(sqlite3 "$DB" 'SELECT count(*) FROM options WHERE run=2')

# check NAME CMD...: a python check that prints its reason on failure.
check() {
    local name=$1
    shift
    if "$@" >"$OUT" 2>"$ERR"; then STATUS=0; pass "$name"; else STATUS=$?; fail "$name"; fi
}

# count_is NAME WANT GOT
count_is() {
    if [ "$2" = "$3" ]; then pass "$1"; else echo "not ok - $1 (want $2, got $3)"; fi
}

# render NAME SVG: valid XML, renders to a PNG that is not blank.
render() {
    local name=$1 svg=$2
    run xmllint --noout "$svg"
    if [ "$STATUS" -eq 0 ]; then pass "$name: valid XML"; else fail "$name: valid XML"; fi
    run rsvg-convert -o "${svg%.svg}.png" "$svg"
    if [ "$STATUS" -eq 0 ] && [ -s "${svg%.svg}.png" ]; then
        check "$name: renders to a non-blank PNG" $CHECK png "${svg%.svg}.png"
    else
        fail "$name: renders to a non-blank PNG"
    fi
}

# --- export all four at once ------------------------------------------------
E=$WORK/e
mkdir "$E"
expect "export --obj --csv --json --svg of the knee" 0 "$FACET" export "$DB" \
    --run 1 --option "$KNEE" --obj "$E/k.obj" --csv "$E/k.csv" \
    --json "$E/k.json" --svg "$E/k.svg"
if [ -s "$E/k.obj" ] && [ -s "$E/k.mtl" ] && [ -s "$E/k.csv" ] &&
    [ -s "$E/k.json" ] && [ -s "$E/k.svg" ]; then
    pass "all five files written"
else
    fail "all five files written"
fi
if ls -A "$E" | grep -q partial; then
    echo "not ok - no .partial files left"; ls -A "$E" | sed 's/^/  /'
else
    pass "no .partial files left"
fi
count_is "obj: one g per panel" "$PANELS" "$(grep -c '^g ' "$E/k.obj")"
check "obj: tinyobjloader reads one shape per panel, FP/SP/DP materials, areas match the option" \
    $CHECK obj "$E/k.obj" "$E/k.mtl" "$DB" 1 "$KNEE"
check "obj: an object per type, full-cell FP panels as planar quads, no zero-area triangle" \
    $CHECK obj_panels "$E/k.obj" "$DB" 1 "$KNEE"

# --- CSV --------------------------------------------------------------------
check "csv: the one schedule layout, one row per panel, totals beside it = options row" \
    $CHECK csv "$E/k.csv" "$DB" 1 "$KNEE"
GRIDK=$(sqlite3 "$DB" "SELECT nu || 'x' || nv FROM options WHERE run = 1 AND number = $KNEE")
"$FACET" classify "$WORK/roof.obj" --grid "$GRIDK" --csv "$E/classify.csv" >/dev/null 2>&1
same "classify --csv and export --csv have one layout" "$(head -n 1 "$E/classify.csv")" "$(head -n 1 "$E/k.csv")"
same "classify --csv writes its totals beside the schedule" "$(head -c 30 "$E/classify-totals.csv")" "$(head -c 30 "$E/k-totals.csv")"

# --- JSON -------------------------------------------------------------------
"$FACET" classify "$WORK/roof.obj" --grid "$GRID" --json >"$WORK/classify.json" 2>/dev/null
check "json: keys of classify --json, totals = the store's" \
    $CHECK json "$E/k.json" "$WORK/classify.json" "$DB" 1 "$KNEE"

# --- SVG maps ---------------------------------------------------------------
render "svg map (uv, type)" "$E/k.svg"
count_is "svg map (uv, type): one <path class=\"panel\" per panel" "$PANELS" \
    "$(grep -c '<path class="panel ' "$E/k.svg")"
for view in uv top front side; do
    for colour in type class; do
        s=$E/map_${view}_$colour.svg
        expect "export --svg --view $view --colour $colour" 0 "$FACET" export "$DB" \
            --run 1 --option "$KNEE" --svg "$s" --view "$view" --colour "$colour"
        render "map $view/$colour" "$s"
        count_is "map $view/$colour: one panel path per panel" "$PANELS" \
            "$(grep -c '<path class="panel ' "$s")"
    done
done
expect "export --svg --triangles" 0 "$FACET" export "$DB" --run 1 \
    --option "$KNEE" --svg "$E/tri.svg" --triangles
render "map --triangles" "$E/tri.svg"
count_is "map --triangles: one panel path per panel" "$PANELS" \
    "$(grep -c '<path class="panel ' "$E/tri.svg")"
check "top and front views differ" $CHECK pngs_differ "$E/map_top_type.png" "$E/map_front_type.png"
check "type and class colourings differ" $CHECK pngs_differ "$E/map_uv_type.png" "$E/map_uv_class.png"
if grep -q 'data-class="flat" fill="\([^"]*\)"' "$E/map_uv_class.svg" &&
    [ "$(grep -o 'fill="#[0-9a-fA-F]*"' "$E/map_uv_class.svg" | sort -u | wc -l)" -ge 3 ]; then
    pass "class map uses several fills"
else
    fail "class map uses several fills"
fi

# --- plot -------------------------------------------------------------------
expect "plot --run 1" 0 "$FACET" plot "$DB" --run 1 -o "$WORK/p1.svg"
render "plot run 1" "$WORK/p1.svg"
count_is "plot run 1: one <circle per option" "$N1" "$(grep -c '<circle' "$WORK/p1.svg")"
count_is "plot run 1: one front polyline" 1 "$(grep -c '<polyline class="front"' "$WORK/p1.svg")"
if [ "$(grep -c 'class="tick" text-anchor="middle"' "$WORK/p1.svg")" -ge 2 ] &&
    [ "$(grep -c 'class="tick" text-anchor="end"' "$WORK/p1.svg")" -ge 2 ] &&
    grep -q 'class="tick"[^>]*>[-0-9.,]\+<' "$WORK/p1.svg"; then
    pass "plot: tick labels on both axes"
else
    fail "plot: tick labels on both axes"
fi
expect "plot --runs 1,2" 0 "$FACET" plot "$DB" --runs 1,2 -o "$WORK/p12.svg"
render "plot runs 1,2" "$WORK/p12.svg"
count_is "plot runs 1,2: circles = options of both runs" "$((N1 + N2))" \
    "$(grep -c '<circle' "$WORK/p12.svg")"
count_is "plot runs 1,2: one front per run" 2 "$(grep -c '<polyline class="front"' "$WORK/p12.svg")"
expect "plot --x dp_area --y fp_area --size nu" 0 "$FACET" plot "$DB" --run 1 \
    --x dp_area --y fp_area --size nu -o "$WORK/p3.svg"
render "plot dp_area/fp_area" "$WORK/p3.svg"
count_is "plot dp_area/fp_area: one <circle per option" "$N1" "$(grep -c '<circle' "$WORK/p3.svg")"
check "plots of different metrics differ" $CHECK pngs_differ "$WORK/p1.png" "$WORK/p3.png"
# issue 32 item 3: a run's name runs past the page's edge no more, and no
# axis of values that are none of them negative goes below 0
"$FACET" optimize "$WORK/roof.obj" --db "$WORK/named.db" --u 5:20 --v 5:20 \
    --max-panel-area 100 --name "paper space, the roof in the paper's grid" >/dev/null 2>&1
expect "plot of a run with a long name" 0 "$FACET" plot "$WORK/named.db" --run 1 -o "$WORK/p4.svg"
render "plot of a long name" "$WORK/p4.svg"
sed 's/width="800" height="560" viewBox="0 0 800 560"/width="1200" height="560" viewBox="0 0 1200 560"/' \
    "$WORK/p4.svg" >"$WORK/p4wide.svg"
rsvg-convert -o "$WORK/p4wide.png" "$WORK/p4wide.svg"
check "plot: the legend stays inside the 800-px page (rendered 1200 px wide, nothing right of 800)" \
    $CHECK nothing_beyond "$WORK/p4wide.png" 800
if grep -q 'class="tick"[^>]*>-' "$WORK/p4.svg" "$WORK/p1.svg" "$WORK/p3.svg"; then
    fail "plot: no negative tick on an axis of values none of which is negative"
    grep -o 'class="tick"[^>]*>-[^<]*' "$WORK/p4.svg" "$WORK/p1.svg" "$WORK/p3.svg" | head -3 | sed 's/^/  /'
else
    pass "plot: no negative tick on an axis of values none of which is negative"
fi

# --- bad input --------------------------------------------------------------
B=$WORK/bad
mkdir "$B"
# bad NAME PATTERN CMD...: one-line error, status 2, and $B stays empty.
bad() {
    local name=$1
    expect_error "$@"
    if [ -z "$(ls -A "$B")" ]; then
        pass "$name: no file created"
    else
        echo "not ok - $name: no file created"; ls -A "$B" | sed 's/^/  /'
        rm -rf "${B:?}"/*
    fi
}
bad "export: unknown run" 'run' "$FACET" export "$DB" --run 99 --option 1 \
    --svg "$B/x.svg" --csv "$B/x.csv" --obj "$B/x.obj" --json "$B/x.json"
bad "export: unknown option" 'option' "$FACET" export "$DB" --run 1 --option 999 \
    --svg "$B/x.svg" --csv "$B/x.csv" --obj "$B/x.obj" --json "$B/x.json"
bad "export: no output flag" '.' "$FACET" export "$DB" --run 1 --option "$KNEE"
bad "export: bad --view" 'view' "$FACET" export "$DB" --run 1 --option "$KNEE" \
    --svg "$B/x.svg" --view oblique
bad "export: bad --colour" 'colou?r' "$FACET" export "$DB" --run 1 --option "$KNEE" \
    --svg "$B/x.svg" --colour rainbow
bad "export: unwritable path" 'nonexistent' "$FACET" export "$DB" --run 1 \
    --option "$KNEE" --svg /nonexistent/x.svg
bad "export: unwritable path with other outputs" 'nonexistent' "$FACET" export "$DB" --run 1 \
    --option "$KNEE" --csv "$B/x.csv" --svg /nonexistent/x.svg
bad "plot: unknown run" 'run' "$FACET" plot "$DB" --run 99 -o "$B/p.svg"
bad "plot: bad --x metric" 'foo' "$FACET" plot "$DB" --run 1 --x foo -o "$B/p.svg"
bad "plot: bad --y metric" 'bar' "$FACET" plot "$DB" --run 1 --y bar -o "$B/p.svg"
bad "plot: unwritable path" 'nonexistent' "$FACET" plot "$DB" --run 1 -o /nonexistent/x.svg
bad "plot: no -o" '.' "$FACET" plot "$DB" --run 1

# A path that exists: refused without --force, replaced with it.
echo keep >"$WORK/exists.svg"
echo keep >"$WORK/exists.csv"
expect_error "export: existing file refused" 'exists|force' "$FACET" export "$DB" \
    --run 1 --option "$KNEE" --svg "$WORK/exists.svg"
if [ "$(cat "$WORK/exists.svg")" = keep ]; then pass "existing file left alone"; else fail "existing file left alone"; fi
expect_error "export: one existing file refuses all" 'exists|force' "$FACET" export "$DB" \
    --run 1 --option "$KNEE" --json "$WORK/new.json" --csv "$WORK/exists.csv"
if [ ! -e "$WORK/new.json" ] && [ "$(cat "$WORK/exists.csv")" = keep ]; then
    pass "nothing written when one output exists"
else
    fail "nothing written when one output exists"
fi
expect "export --force overwrites" 0 "$FACET" export "$DB" --run 1 --option "$KNEE" \
    --svg "$WORK/exists.svg" --force
run xmllint --noout "$WORK/exists.svg"
if [ "$STATUS" -eq 0 ]; then pass "overwritten file is the map"; else fail "overwritten file is the map"; fi
echo keep >"$WORK/exists.svg"
expect_error "plot: existing file refused" 'exists|force' "$FACET" plot "$DB" --run 1 \
    -o "$WORK/exists.svg"
if [ "$(cat "$WORK/exists.svg")" = keep ]; then pass "plot left the existing file alone"; else fail "plot left the existing file alone"; fi
expect "plot --force overwrites" 0 "$FACET" plot "$DB" --run 1 -o "$WORK/exists.svg" --force
if grep -q '<circle' "$WORK/exists.svg"; then pass "overwritten file is the plot"; else fail "overwritten file is the plot"; fi
