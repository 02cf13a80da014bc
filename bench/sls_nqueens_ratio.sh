#!/usr/bin/env bash
# The generic sls against the special-purpose N-queens solver, as a ratio per size.
#
# Why a script: on a shared VM one run of sls_nqueens_bench can put the two solvers' times
# 30% apart or together depending on what the neighbours do at that moment. Here each round
# runs, for each size, the generic benchmark and the special one back to back (each the
# median of 5 repetitions, CPU time, pinned to one core), so the two halves of a ratio see
# the same machine; the ratio is reported per round, with its median over the rounds.
#
# Usage: bench/sls_nqueens_ratio.sh [ROUNDS=5] [CORE=0]   (after building sls_nqueens_bench)
set -euo pipefail
cd "$(dirname "$0")/.."
rounds=${1:-5}
core=${2:-0}
bench=build/bench/sls_nqueens_bench
[ -x "$bench" ] || { echo "build $bench first (docs/BENCHMARKS.md)" >&2; exit 2; }

median_ms() {  # median CPU time, in ms, of benchmark $1 at size $2
  taskset -c "$core" "$bench" --benchmark_filter="^BM_$1/$2(/|\$)" --benchmark_repetitions=5 \
    --benchmark_report_aggregates_only=true --benchmark_format=csv 2>/dev/null |
    awk -F, '$1 ~ /_median"$/ { print $4 }'
}

for round in $(seq "$rounds"); do
  for n in 1000 10000 100000 1000000; do
    echo "$n $(median_ms GenericSls "$n") $(median_ms SpecialPermutationSwap "$n")"
  done
done | awk '
  function median(list, count,   sorted, i, j, t) {
    for (i = 1; i <= count; ++i) sorted[i] = list[i]
    for (i = 1; i <= count; ++i) for (j = i + 1; j <= count; ++j)
      if (sorted[j] < sorted[i]) { t = sorted[i]; sorted[i] = sorted[j]; sorted[j] = t }
    return count % 2 ? sorted[(count + 1) / 2] : (sorted[count / 2] + sorted[count / 2 + 1]) / 2
  }
  { k = ++rounds_of[$1]; generic[$1, k] = $2; special[$1, k] = $3; ratio[$1, k] = $2 / $3 }
  END {
    printf "%9s %12s %12s %7s  %s\n", "n", "generic ms", "special ms", "ratio", "ratio per round"
    split("1000 10000 100000 1000000", sizes, " ")
    for (s = 1; s <= 4; ++s) {
      n = sizes[s]; count = rounds_of[n]; line = ""
      for (k = 1; k <= count; ++k) {
        g[k] = generic[n, k]; p[k] = special[n, k]; r[k] = ratio[n, k]
        line = line sprintf(" %.2f", r[k])
      }
      printf "%9d %12.4g %12.4g %6.2fx %s\n", n, median(g, count), median(p, count),
             median(r, count), line
    }
  }'
