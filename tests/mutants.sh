#!/usr/bin/env bash
# mutants.sh: every layer's tests can still fail. For each layer (core,
# store, study, tui, cli), one plausible defect, the kind a change could
# bring, is written into a scratch copy of the tree; the copy is rebuilt
# (from a copy of the release build, so only the changed file compiles) and
# the suites `make check-fast` picks for that file run until the first one
# fails. A mutant that no suite catches is a failure of this script: the
# tests of that layer could no longer fail on it.
#
#   tests/mutants.sh [BUILD_DIR]      (default build/release, built already)
#
# Prints one "ok - " or "not ok - " line per mutant, naming the suites that
# caught it, and exits 1 if any mutant survived.
set -uo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-build/release}
jobs=${JOBS:-$(nproc 2>/dev/null || echo 2)}
export FACET_DATA=${FACET_DATA:-$(dirname "$root")/shared/data}
if [ ! -x "$root/$build/facet" ]; then
    echo "mutants.sh: $build/facet is not built (make test-build first)" >&2
    exit 2
fi

# Each mutant: LAYER, FILE, the exact text it replaces (found once), the
# text put in its place, and what the defect means.
MUTANTS=(
"core|core/classify/classify.c|return 8 * sag / (panel->diameter * panel->diameter);|return 4 * sag / (panel->diameter * panel->diameter);|the zero-curvature tolerance halved"
"store|store/store_panel.c|\" ORDER BY j, i\"|\" ORDER BY i, j\"|an option's panels read back transposed"
"study|study/study.c|: *outcome == OPTIMIZE_DONE ? RUN_DONE|: *outcome != OPTIMIZE_DONE ? RUN_DONE|an interrupted run recorded as done"
"tui|tui/table_model.c|m->browse.keys[k].descending = keys[k].descending;|m->browse.keys[k].descending = !keys[k].descending;|every sort of the options table reversed"
"cli|cli/classify_flags.c|params->classify.max_gap = number / 1000;|params->classify.max_gap = number / 100;|--max-gap read in cm, not mm"
)

scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
survived=0
for m in "${MUTANTS[@]}"; do
    IFS='|' read -r layer file old new what <<<"$m"
    tree=$scratch/$layer
    mkdir -p "$tree/build"
    cp -a "$root/Makefile" "$root/core" "$root/store" "$root/study" "$root/tui" \
        "$root/cli" "$root/tests" "$root/examples" "$tree/" &&
        cp -a "$root/$build" "$tree/build/" || { echo "not ok - $layer: cannot copy the tree"; survived=1; continue; }
    if ! /usr/bin/python3 - "$tree/$file" "$old" "$new" <<'PY'
import sys
path, old, new = sys.argv[1:4]
text = open(path).read()
if text.count(old) != 1:
    sys.exit("mutants.sh: %s holds %d copies of the text to mutate; "
             "update the mutant" % (path, text.count(old)))
open(path, "w").write(text.replace(old, new))
PY
    then
        echo "not ok - $layer mutant ($what): its text is not in $file"
        survived=1
        continue
    fi
    if ! make -s -C "$tree" -j"$jobs" VARIANT="$(basename "$build")" \
        "$build/facet" test-build >"$tree/build.log" 2>&1; then
        echo "not ok - $layer mutant ($what): the mutated tree does not build"
        tail -n 5 "$tree/build.log" | sed 's/^/  /'
        survived=1
        continue
    fi
    start=$EPOCHREALTIME
    (cd "$tree" && tests/run.py --quiet --first-failure --shortest-first --jobs "$jobs" \
        --changed-files "$file" -- "$build") >"$tree/run.log" 2>&1
    status=$?
    seconds=$(echo "$EPOCHREALTIME - $start" | bc)
    caught=$(sed -n 's/^FAILED: //p' "$tree/run.log")
    if [ "$status" -ne 0 ] && [ -n "$caught" ]; then
        printf 'ok - %s mutant (%s, %s) caught by: %s (%.0f s)\n' \
            "$layer" "$what" "$file" "$caught" "$seconds"
    else
        echo "not ok - $layer mutant ($what, $file) survived every suite check-fast picks"
        tail -n 5 "$tree/run.log" | sed 's/^/  /'
        survived=1
    fi
    rm -rf "$tree"
done
exit $survived
