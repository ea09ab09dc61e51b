#!/usr/bin/env bash
# bench_nsga2.sh: NSGA-II on ZDT1, Facet against Debian's python3-deap.
#
#   tests/bench/bench_nsga2.sh BUILD_DIR [RUNS]
#
# Runs BUILD_DIR/bench/bench_nsga2 and tests/bench/bench_nsga2_deap.py with
# the same problem and settings (population 100, 250 generations, 25,000
# evaluations, SBX and polynomial mutation with eta 20), RUNS seeds each
# (default 5), and prints both evaluation rates (best run), their ratio and
# both mean hypervolumes (final population, reference (1.1, 1.1)). Targets:
# Facet at least 20x DEAP's evaluations per second, and a hypervolume at
# least DEAP's. A miss is reported, and exits 1 only with BENCH_STRICT=1
# (so that make bench still runs the rest).
set -euo pipefail
build=${1:?usage: tests/bench/bench_nsga2.sh BUILD_DIR [RUNS]}
runs=${2:-5}
cd "$(dirname "$0")/../.."
[ -x "$build/bench/bench_nsga2" ] || {
    echo "bench_nsga2: no $build/bench/bench_nsga2 (run make bench)" >&2; exit 2; }
/usr/bin/python3 -c 'import deap' 2>/dev/null || {
    echo "bench_nsga2: python3-deap is missing (apt-get install -y python3-deap)" >&2
    exit 2; }

facet=$("$build/bench/bench_nsga2" "$runs" zdt1 | tail -n 1)
deap=$(/usr/bin/python3 tests/bench/bench_nsga2_deap.py "$runs" | tail -n 1)
field() { echo "$1" | sed -n "s/.*$2 \([0-9.]*\).*/\1/p"; }
facet_rate=$(field "$facet" 'evaluations\/s')
facet_hv=$(field "$facet" hypervolume)
deap_rate=$(field "$deap" 'evaluations\/s')
deap_hv=$(field "$deap" hypervolume)
ratio=$(awk -v a="$facet_rate" -v b="$deap_rate" 'BEGIN { printf "%.1f", a / b }')

echo "bench_nsga2: ZDT1, population 100 x 250 generations, $runs seeds each"
printf '  facet  %10.0f evaluations/s  hypervolume %s\n' "$facet_rate" "$facet_hv"
printf '  deap   %10.0f evaluations/s  hypervolume %s\n' "$deap_rate" "$deap_hv"
echo "  ratio ${ratio}x (target >= 20x), hypervolume facet $facet_hv vs deap $deap_hv (target >=)"

missed=0
if ! awk -v r="$ratio" 'BEGIN { exit !(r >= 20) }'; then
    echo "bench_nsga2: ratio ${ratio}x is below the 20x target"; missed=1
fi
if ! awk -v a="$facet_hv" -v b="$deap_hv" 'BEGIN { exit !(a >= b) }'; then
    echo "bench_nsga2: Facet's hypervolume $facet_hv is below DEAP's $deap_hv"; missed=1
fi
[ "$missed" = 1 ] && [ "${BENCH_STRICT:-0}" = 1 ] && exit 1
exit 0
