#!/usr/bin/env bash
# Runs every test of one build: the cmocka unit tests in BUILD/tests and the
# end-to-end scripts in tests/e2e (which run BUILD/facet). Prints each
# failure's log, and ends with the line "N passed, M failed".
#
#   tests/run.sh build/release
set -uo pipefail
build=${1:?usage: tests/run.sh BUILD_DIR}
cd "$(dirname "$0")/.."
export BUILD=$build FACET=$PWD/$build/facet
export FACET_DATA=${FACET_DATA:-$PWD/../shared/data}
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=0}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
logs=$(mktemp -d)
trap 'rm -rf "$logs"' EXIT

passed=0 failed=0 skipped=0
failures=()
skips=()

for test in "$build"/tests/test_*; do
    [ -x "$test" ] || continue
    name=$(basename "$test")
    log=$logs/$name.log
    if "$test" >"$log" 2>&1; then status=0; else status=$?; fi
    ok=$(grep -ohE '\[  PASSED  \] [0-9]+' "$log" | awk '{s+=$4} END {print s+0}')
    bad=$(grep -ohE '\[  FAILED  \] [0-9]+ test' "$log" | awk '{s+=$4} END {print s+0}')
    # cmocka prints a skipped test's own line ("[  SKIPPED ] name") before
    # the summary line ("[  SKIPPED ] N test(s)"): count the summaries.
    skip=$(grep -ohE '\[  SKIPPED \] [0-9]+ test' "$log" | awk '{s+=$4} END {print s+0}')
    if [ "$status" -ne 0 ] && [ "$bad" -eq 0 ]; then bad=1; fi
    passed=$((passed + ok)); failed=$((failed + bad)); skipped=$((skipped + skip))
    printf '%-28s %4d passed %3d failed %3d skipped\n' "$name" "$ok" "$bad" "$skip"
    while IFS= read -r line; do skips+=("$name: $line"); done < <(grep -E '^skipped: ' "$log")
    [ "$bad" -eq 0 ] || failures+=("$log")
done

for script in tests/e2e/*.sh; do
    case $(basename "$script") in *lib.sh) continue ;; esac
    name=$(basename "$script" .sh)
    log=$logs/e2e_$name.log
    if bash "$script" >"$log" 2>&1; then status=0; else status=$?; fi
    ok=$(grep -c '^ok ' "$log")
    bad=$(grep -c '^not ok ' "$log")
    skip=$(grep -c '^skip ' "$log")
    if [ "$status" -ne 0 ] && [ "$bad" -eq 0 ]; then bad=1; fi
    passed=$((passed + ok)); failed=$((failed + bad)); skipped=$((skipped + skip))
    printf '%-28s %4d passed %3d failed %3d skipped\n' "e2e/$name" "$ok" "$bad" "$skip"
    while IFS= read -r line; do skips+=("e2e/$name: $line"); done < <(grep -E '^skip ' "$log")
    [ "$bad" -eq 0 ] || failures+=("$log")
done

for log in "${failures[@]+"${failures[@]}"}"; do
    echo "==== $(basename "$log")"
    tail -n 60 "$log"
done
for line in "${skips[@]+"${skips[@]}"}"; do
    echo "SKIPPED $line"
done
echo "$build: $passed passed, $failed failed, $skipped skipped (not run here, not counted as passed)"
[ "$failed" -eq 0 ] && [ "$passed" -gt 0 ]
