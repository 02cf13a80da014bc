// N-queens at 10^3 .. 10^6: the generic `sls` solver (through the registry, on the problem
// built from three all_different constraints) against a special-purpose solver written
// here for nothing but N-queens, in the style of Sosic & Gu's QS4 ("Efficient local search
// with conflict minimization: a case study of the n-queens problem", IEEE TKDE 1994):
// a random permutation, a greedy placement of queens one by one by swaps with the not yet
// placed ones, then swaps with random partners for queens still in conflict, with the
// diagonal counts kept in two flat arrays. The generic solver's target is to stay within
// 3x of it at 10^6. Both results are checked by counting attacking pairs from the rows.
// Results and the exact command: docs/BENCHMARKS.md.
#include <benchmark/benchmark.h>

#include <cstdint>
#include <random>
#include <stdexcept>
#include <vector>

#include "sightline/domains/nqueens/nqueens.h"
#include "sightline/solvers/registry.h"

namespace {

using sightline::nqueens::attacking_pairs;

// The special-purpose solver: rows q[i], diagonal counts up[q + i] and down[q - i + n - 1].
// The measure is the number of queens that share a diagonal with an earlier one,
// sum over diagonals of max(0, count - 1), as the generic solver's `var` measure.
class PermutationSwapQueens {
 public:
  explicit PermutationSwapQueens(std::size_t n, std::uint64_t seed)
      : n_(n), q_(n), up_(2 * n, 0), down_(2 * n, 0), random_(seed) {}

  // Returns the number of swaps tried.
  std::uint64_t solve() {
    for (std::size_t i = 0; i < n_; ++i) q_[i] = static_cast<std::int32_t>(i);
    for (std::size_t i = n_ - 1; i > 0; --i) std::swap(q_[i], q_[index(i + 1)]);
    std::uint64_t tries = 0;
    // Greedy placement: queen j takes a random not-yet-placed row that no placed queen
    // attacks, within 3.08 n attempts overall (Sosic & Gu's constant).
    std::size_t placed = 0;
    const auto attempts = static_cast<std::uint64_t>(3.08 * static_cast<double>(n_));
    for (std::uint64_t a = 0; a < attempts && placed < n_; ++a) {
      const std::size_t m = placed + index(n_ - placed);
      std::swap(q_[placed], q_[m]);
      ++tries;
      if (up_[up_key(placed)] == 0 && down_[down_key(placed)] == 0) {
        add(placed);
        ++placed;
      } else {
        std::swap(q_[placed], q_[m]);
      }
    }
    for (std::size_t i = placed; i < n_; ++i) add(i);
    // Final phase: queens in conflict swap with random partners while that lowers the total.
    std::vector<std::size_t> suspects;
    for (std::size_t i = placed; i < n_; ++i) suspects.push_back(i);
    while (total_ > 0) {
      if (suspects.empty()) {
        for (std::size_t i = 0; i < n_; ++i) {
          if (in_conflict(i)) suspects.push_back(i);
        }
      }
      const std::size_t pick = index(suspects.size());
      const std::size_t i = suspects[pick];
      if (!in_conflict(i)) {
        suspects[pick] = suspects.back();
        suspects.pop_back();
        continue;
      }
      const std::size_t k = index(n_);
      if (k == i) continue;
      ++tries;
      const std::int64_t before = total_;
      remove(i);
      remove(k);
      std::swap(q_[i], q_[k]);
      add(i);
      add(k);
      if (total_ < before) {
        if (in_conflict(k)) suspects.push_back(k);
        continue;
      }
      remove(i);
      remove(k);
      std::swap(q_[i], q_[k]);
      add(i);
      add(k);
    }
    return tries;
  }

  std::vector<double> rows() const { return std::vector<double>(q_.begin(), q_.end()); }

 private:
  std::size_t up_key(std::size_t i) const { return static_cast<std::size_t>(q_[i]) + i; }
  std::size_t down_key(std::size_t i) const { return static_cast<std::size_t>(q_[i]) + n_ - 1 - i; }
  bool in_conflict(std::size_t i) const { return up_[up_key(i)] > 1 || down_[down_key(i)] > 1; }
  void add(std::size_t i) {
    if (up_[up_key(i)]++ > 0) ++total_;
    if (down_[down_key(i)]++ > 0) ++total_;
  }
  void remove(std::size_t i) {
    if (--up_[up_key(i)] > 0) --total_;
    if (--down_[down_key(i)] > 0) --total_;
  }
  std::size_t index(std::size_t n) {
    __extension__ using Wide = unsigned __int128;
    return static_cast<std::size_t>((static_cast<Wide>(random_()) * n) >> 64);
  }

  std::size_t n_;
  std::vector<std::int32_t> q_, up_, down_;
  std::int64_t total_ = 0;
  std::mt19937_64 random_;
};

void BM_GenericSls(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  const auto problem = sightline::nqueens::build_nqueens(n);
  auto sls = sightline::solvers::SolverRegistry::global().create("sls");
  const auto start = problem->default_assignment();
  sightline::solvers::SolveContext context;
  context.want_breakdown = false;
  sightline::solvers::SolverResult result;
  for (auto _ : state) {
    sls->solve_into(*problem, start, context, result);
    benchmark::DoNotOptimize(result.best.data());
  }
  if (attacking_pairs(result.best) != 0) state.SkipWithError("sls left queens attacking");
  state.counters["evaluations"] = static_cast<double>(result.evaluations);
  state.counters["iterations"] = static_cast<double>(result.iterations);
}

void BM_SpecialPermutationSwap(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  std::uint64_t tries = 0;
  std::vector<double> rows;
  for (auto _ : state) {
    PermutationSwapQueens solver(n, 1);
    tries = solver.solve();
    rows = solver.rows();
    benchmark::DoNotOptimize(rows.data());
  }
  if (attacking_pairs(rows) != 0) state.SkipWithError("special solver left queens attacking");
  state.counters["swaps_tried"] = static_cast<double>(tries);
}

BENCHMARK(BM_GenericSls)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_GenericSls)->Arg(100000)->Arg(1000000)->Iterations(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SpecialPermutationSwap)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SpecialPermutationSwap)
    ->Arg(100000)
    ->Arg(1000000)
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
