#!/usr/bin/env bash
# Whole processes at 10^6 queens: `sightline nqueens 1000000 --solver sls` (model building,
# solve, check, print, exit) against the special-purpose solver's process (its benchmark
# alone), as issue 16 asks. Each round runs the two back to back pinned to one core, so the
# halves of a ratio see the same machine; CPU time (user + sys) and wall time are both given,
# as on a shared VM wall time also counts the neighbours.
#
# Usage: bench/nqueens_process_ratio.sh [ROUNDS=5] [SIGHTLINE=build/apps/sightline] [CORE=0]
#   (after building the sightline and sls_nqueens_bench targets; a second SIGHTLINE binary,
#   e.g. an older build, can be compared the same way)
set -euo pipefail
cd "$(dirname "$0")/.."
rounds=${1:-5}
sightline=${2:-build/apps/sightline}
core=${3:-0}
bench=build/bench/sls_nqueens_bench
for program in "$sightline" "$bench"; do
  [ -x "$program" ] || { echo "build $program first (docs/BENCHMARKS.md)" >&2; exit 2; }
done

measure() {  # prints "wall cpu peak_kb" of one pinned run of the given command
  { /usr/bin/time -f "%e %U %S %M" taskset -c "$core" "$@" >/dev/null; } 2>&1 | tail -1 |
    awk '{ printf "%.2f %.2f %d\n", $1, $2 + $3, $4 }'
}

echo "round generic_wall generic_cpu generic_kb special_wall special_cpu special_kb ratio_wall ratio_cpu"
for round in $(seq "$rounds"); do
  read -r gw gc gk <<<"$(measure "$sightline" nqueens 1000000 --solver sls)"
  read -r sw sc sk <<<"$(measure "$bench" --benchmark_filter='^BM_SpecialPermutationSwap/1000000')"
  awk -v r="$round" -v gw="$gw" -v gc="$gc" -v gk="$gk" -v sw="$sw" -v sc="$sc" -v sk="$sk" \
    'BEGIN { printf "%d %.2f %.2f %d %.2f %.2f %d %.2f %.2f\n", r, gw, gc, gk, sw, sc, sk, gw / sw, gc / sc }'
done
