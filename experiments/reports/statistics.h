// Statistics for experiment suites (issue 14): what researchers publish about repeated runs.
//
// Pure, deterministic functions without I/O, so the suite summary, the report and the tests
// all compute the same numbers from the same data:
//  - median and mean of repetitions over seeds, with a percentile-bootstrap 95% confidence
//    interval (a fixed seeded std::mt19937_64, so the same data always gives the same
//    interval);
//  - average ranks with ties per block (scene or instance), Friedman's average ranks across
//    blocks with the Friedman chi-square statistic and its p-value;
//  - the Wilcoxon signed-rank test between two named solvers' paired results;
//  - for toy and WCSP suites: PAR-2 scores, cactus curves and Dolan-More performance
//    profiles.
// Distributions (chi-square, normal) come from Boost.Math, not from hand-written code.
// Bad arguments (empty samples, NaN, ragged tables) throw std::invalid_argument naming what
// was expected: these are programming or data errors of the caller, never guessed around.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace sightline::experiments {

// The middle value of the sorted sample; the mean of the two middle values for an even size.
double median(std::span<const double> values);
// The arithmetic mean.
double mean(std::span<const double> values);

struct BootstrapOptions {
  int resamples = 2000;                      // B, the number of resamples drawn with replacement
  std::uint64_t seed = 0x5167'4c69'6e65ULL;  // fixed, so an interval is reproducible
  double level = 0.95;                       // two-sided coverage in (0, 1)
};

struct ConfidenceInterval {
  double low = 0.0;
  double high = 0.0;
};

// Percentile bootstrap: draw B resamples of size n with replacement (indices from a
// std::mt19937_64 seeded with options.seed, one generator per call), compute the statistic of
// each, and take the (1-level)/2 and (1+level)/2 quantiles of the B values (linear
// interpolation between order statistics, "type 7"). A sample of one value gives [v, v].
ConfidenceInterval bootstrap_mean_ci(std::span<const double> values,
                                     const BootstrapOptions& options = {});
ConfidenceInterval bootstrap_median_ci(std::span<const double> values,
                                       const BootstrapOptions& options = {});

// Ranks 1..n of the values, smallest first (lower is better: cost, time); tied values share
// the average of the positions they occupy, so [3, 1, 3, 2] ranks as [3.5, 1, 3.5, 2]
// (ranks in input order).
std::vector<double> average_ranks(std::span<const double> values);

struct FriedmanResult {
  std::vector<double> average_ranks;  // per solver, over blocks (1 = best)
  double chi_square = 0.0;            // Friedman's statistic, tie-corrected
  double p_value = 1.0;               // upper tail of chi-square with k-1 degrees of freedom
  int blocks = 0;                     // n, scenes or instances
  int solvers = 0;                    // k
};

// table[block][solver], lower is better; at least 2 blocks and 2 solvers, all rows the same
// length. Ranks are taken within each block (ties averaged). With rank sums R_j,
//   Q = (k-1) * sum_j (R_j - n(k+1)/2)^2 / (sum_ij r_ij^2 - n k (k+1)^2 / 4),
// which without ties equals the textbook 12/(n k (k+1)) sum_j R_j^2 - 3 n (k+1). When every
// block is all ties the denominator is 0: Q = 0, p = 1 (no evidence of any difference).
FriedmanResult friedman_test(const std::vector<std::vector<double>>& table);

struct WilcoxonResult {
  int n = 0;             // pairs with a non-zero difference
  double w_plus = 0.0;   // sum of ranks of |d| where a > b
  double w_minus = 0.0;  // sum of ranks of |d| where a < b
  double p_value = 1.0;  // two-sided
  bool exact = false;    // true: exact null distribution; false: normal approximation
};

// Paired samples a[i], b[i] (same length). Differences d = a - b; zero differences are
// dropped; |d| are ranked with ties averaged. For n <= 25 the p-value is exact: the null
// distribution of W+ given these (possibly tied) ranks, counted over all 2^n sign patterns
// by dynamic programming on doubled ranks; p = min(1, 2 min(P(W+ <= w), P(W+ >= w))).
// Above, the normal approximation with mean n(n+1)/4 and variance
// n(n+1)(2n+1)/24 - sum_t (t^3 - t)/48 over tie groups, without continuity correction.
// n = 0 gives p = 1.
WilcoxonResult wilcoxon_signed_rank(std::span<const double> a, std::span<const double> b);

// One run of a solver on an instance for the time-based scores.
struct TimedRun {
  bool solved = false;   // reached the answer (optimum proven, or the target) in time
  double seconds = 0.0;  // wall time of the run
};

// PAR-2: the mean over runs of the time, where a run unsolved or over time_limit counts
// 2 * time_limit. time_limit > 0; at least one run.
double par2_score(std::span<const TimedRun> runs, double time_limit);

struct CactusPoint {
  int runs_solved = 0;   // x: how many runs are solved ...
  double seconds = 0.0;  // y: ... within this time each
};

// The solved runs within time_limit (pass infinity for none), sorted by time: point i is
// (i + 1, i-th smallest time). Unsolved runs do not appear.
std::vector<CactusPoint> cactus_curve(std::span<const TimedRun> runs, double time_limit);

// Dolan-More performance ratios: table[instance][solver]. On each instance the ratio of a
// solver is its time over the best solved time on that instance; unsolved runs, and every run
// on an instance nobody solved, have an infinite ratio. Times below min_seconds count as
// min_seconds, so a 0 s best time does not make every other ratio infinite.
std::vector<std::vector<double>> performance_ratios(const std::vector<std::vector<TimedRun>>& table,
                                                    double min_seconds = 1e-6);

// rho_s(tau): per solver, the fraction of instances whose ratio is <= tau.
std::vector<double> performance_profile_at(const std::vector<std::vector<double>>& ratios,
                                           double tau);

}  // namespace sightline::experiments
