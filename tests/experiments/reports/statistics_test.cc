// Statistics for suites against answers worked out by hand (in the comments), closed forms
// (chi-square with 2 degrees of freedom has survival exp(-x/2)) and brute force written here
// (the Wilcoxon null distribution by enumerating every sign pattern).
#include "sightline/experiments/reports/statistics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <vector>

namespace sightline::experiments {
namespace {

using Values = std::vector<double>;
const double kInfinity = std::numeric_limits<double>::infinity();

TEST(Statistics, MedianOfAnOddSampleIsTheMiddleValue) {
  EXPECT_DOUBLE_EQ(median(Values{3.0, 1.0, 2.0}), 2.0);
  EXPECT_DOUBLE_EQ(median(Values{7.0}), 7.0);
}

TEST(Statistics, MedianOfAnEvenSampleAveragesTheTwoMiddleValues) {
  // sorted 1 2 3 4 -> (2 + 3) / 2
  EXPECT_DOUBLE_EQ(median(Values{4.0, 1.0, 3.0, 2.0}), 2.5);
  // sorted 1 1 5 10 -> (1 + 5) / 2
  EXPECT_DOUBLE_EQ(median(Values{10.0, 1.0, 5.0, 1.0}), 3.0);
}

TEST(Statistics, MeanIsTheArithmeticMean) {
  EXPECT_DOUBLE_EQ(mean(Values{1.0, 2.0, 3.0, 10.0}), 4.0);
}

TEST(Statistics, EmptyOrNanSamplesAreRefused) {
  EXPECT_THROW(median(Values{}), std::invalid_argument);
  EXPECT_THROW(mean(Values{}), std::invalid_argument);
  EXPECT_THROW(median(Values{1.0, std::nan("")}), std::invalid_argument);
  EXPECT_THROW(average_ranks(Values{}), std::invalid_argument);
}

TEST(Statistics, TiedValuesShareTheAverageOfTheirPositions) {
  // sorted: 1 (position 1), 2 (position 2), 3 and 3 (positions 3 and 4 -> 3.5 each);
  // ranks are reported in input order.
  EXPECT_EQ(average_ranks(Values{3.0, 1.0, 3.0, 2.0}), (Values{3.5, 1.0, 3.5, 2.0}));
  // three-way tie in positions 2..4 -> 3 each; smallest first
  EXPECT_EQ(average_ranks(Values{0.5, 2.0, 2.0, 2.0, 9.0}), (Values{1.0, 3.0, 3.0, 3.0, 5.0}));
  EXPECT_EQ(average_ranks(Values{5.0, 5.0}), (Values{1.5, 1.5}));
  EXPECT_EQ(average_ranks(Values{2.0, 1.0}), (Values{2.0, 1.0}));
}

// Four blocks, three solvers, no ties. Ranks per block: [1 2 3] [1 3 2] [1 2 3] [2 1 3];
// rank sums R = 5 8 11; average ranks 1.25 2 2.75.
// Q = 12 / (n k (k+1)) sum R^2 - 3 n (k+1) = 12/48 * (25 + 64 + 121) - 48 = 52.5 - 48 = 4.5;
// with k - 1 = 2 degrees of freedom p = exp(-4.5 / 2) = exp(-2.25).
TEST(Statistics, FriedmanAverageRanksAndStatisticOnASmallTable) {
  const std::vector<Values> table = {
      {10.0, 20.0, 30.0}, {1.0, 9.0, 5.0}, {0.1, 0.2, 0.3}, {7.0, 6.0, 8.0}};
  const FriedmanResult result = friedman_test(table);
  EXPECT_EQ(result.blocks, 4);
  EXPECT_EQ(result.solvers, 3);
  ASSERT_EQ(result.average_ranks.size(), 3u);
  EXPECT_DOUBLE_EQ(result.average_ranks[0], 1.25);
  EXPECT_DOUBLE_EQ(result.average_ranks[1], 2.0);
  EXPECT_DOUBLE_EQ(result.average_ranks[2], 2.75);
  EXPECT_NEAR(result.chi_square, 4.5, 1e-12);
  EXPECT_NEAR(result.p_value, std::exp(-2.25), 1e-12);
}

// The same table with a fifth block [1 1 2] -> ranks [1.5 1.5 3]. R = 6.5 9.5 14, n = 5.
// sum r^2 = 4 * 14 + (2.25 + 2.25 + 9) = 69.5; n k (k+1)^2 / 4 = 60 -> denominator 9.5.
// n (k+1) / 2 = 10: (6.5-10)^2 + (9.5-10)^2 + (14-10)^2 = 12.25 + 0.25 + 16 = 28.5.
// Q = (k-1) 28.5 / 9.5 = 6; p = exp(-3).
TEST(Statistics, FriedmanCorrectsForTiesWithinABlock) {
  const std::vector<Values> table = {
      {10.0, 20.0, 30.0}, {1.0, 9.0, 5.0}, {0.1, 0.2, 0.3}, {7.0, 6.0, 8.0}, {4.0, 4.0, 8.0}};
  const FriedmanResult result = friedman_test(table);
  EXPECT_DOUBLE_EQ(result.average_ranks[0], 6.5 / 5.0);
  EXPECT_DOUBLE_EQ(result.average_ranks[1], 9.5 / 5.0);
  EXPECT_DOUBLE_EQ(result.average_ranks[2], 14.0 / 5.0);
  EXPECT_NEAR(result.chi_square, 6.0, 1e-12);
  EXPECT_NEAR(result.p_value, std::exp(-3.0), 1e-12);
}

TEST(Statistics, FriedmanOnAllTiedBlocksFindsNoDifference) {
  const FriedmanResult result = friedman_test({{1.0, 1.0}, {2.0, 2.0}});
  EXPECT_EQ(result.average_ranks, (Values{1.5, 1.5}));
  EXPECT_EQ(result.chi_square, 0.0);
  EXPECT_EQ(result.p_value, 1.0);
}

TEST(Statistics, FriedmanRefusesRaggedOrTooSmallTables) {
  EXPECT_THROW(friedman_test({{1.0, 2.0}}), std::invalid_argument);
  EXPECT_THROW(friedman_test({{1.0}, {2.0}}), std::invalid_argument);
  EXPECT_THROW(friedman_test({{1.0, 2.0}, {1.0, 2.0, 3.0}}), std::invalid_argument);
}

// Textbook: five positive differences 1..5 -> W+ = 15, W- = 0; only one of the 2^5 sign
// patterns reaches 15, so the two-sided exact p = 2/32 = 0.0625.
TEST(Statistics, WilcoxonExactOnFiveAllPositiveDifferences) {
  const WilcoxonResult result =
      wilcoxon_signed_rank(Values{2.0, 4.0, 6.0, 8.0, 10.0}, Values{1.0, 2.0, 3.0, 4.0, 5.0});
  EXPECT_EQ(result.n, 5);
  EXPECT_DOUBLE_EQ(result.w_plus, 15.0);
  EXPECT_DOUBLE_EQ(result.w_minus, 0.0);
  EXPECT_TRUE(result.exact);
  EXPECT_DOUBLE_EQ(result.p_value, 0.0625);
}

// Differences -1 2 3 4 5 6 and one zero (dropped): n = 6, W- = 1, W+ = 20.
// P(W+ >= 20) = P(W- <= 1) = #{subsets of 1..6 summing to <= 1} / 64 = 2/64 -> p = 4/64.
TEST(Statistics, WilcoxonDropsZeroDifferences) {
  const WilcoxonResult result = wilcoxon_signed_rank(Values{0.0, 2.0, 3.0, 4.0, 5.0, 6.0, 9.0},
                                                     Values{1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 9.0});
  EXPECT_EQ(result.n, 6);
  EXPECT_DOUBLE_EQ(result.w_plus, 20.0);
  EXPECT_DOUBLE_EQ(result.w_minus, 1.0);
  EXPECT_DOUBLE_EQ(result.p_value, 4.0 / 64.0);
}

// Differences 1 -1 2 3: |d| ranks 1.5 1.5 3 4; W+ = 1.5 + 3 + 4 = 8.5, W- = 1.5.
// Sign patterns with W+ >= 8.5: {1.5, 3, 4} twice (either 1.5) and all four (10) -> 3 of 16;
// W+ <= 8.5: all but the full set -> 15 of 16. p = 2 * 3/16 = 0.375.
TEST(Statistics, WilcoxonExactCountsTiedRanks) {
  const WilcoxonResult result =
      wilcoxon_signed_rank(Values{1.0, 0.0, 2.0, 3.0}, Values{0.0, 1.0, 0.0, 0.0});
  EXPECT_DOUBLE_EQ(result.w_plus, 8.5);
  EXPECT_DOUBLE_EQ(result.w_minus, 1.5);
  EXPECT_DOUBLE_EQ(result.p_value, 0.375);
}

// Brute force: enumerate all 2^n sign patterns over the observed average ranks.
double brute_force_wilcoxon_p(const Values& a, const Values& b) {
  Values magnitudes;
  Values signs;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i] != b[i]) {
      magnitudes.push_back(std::abs(a[i] - b[i]));
      signs.push_back(a[i] > b[i] ? 1.0 : 0.0);
    }
  const std::size_t n = magnitudes.size();
  Values ranks(n);
  for (std::size_t i = 0; i < n; ++i) {  // rank = 1 + #smaller + (#equal others) / 2
    double smaller = 0, equal = 0;
    for (std::size_t j = 0; j < n; ++j) {
      if (magnitudes[j] < magnitudes[i]) ++smaller;
      if (j != i && magnitudes[j] == magnitudes[i]) ++equal;
    }
    ranks[i] = 1.0 + smaller + equal / 2.0;
  }
  double observed = 0;
  for (std::size_t i = 0; i < n; ++i) observed += signs[i] * ranks[i];
  double low = 0, high = 0;
  for (unsigned mask = 0; mask < (1u << n); ++mask) {
    double w = 0;
    for (std::size_t i = 0; i < n; ++i)
      if (mask & (1u << i)) w += ranks[i];
    if (w <= observed + 1e-9) ++low;
    if (w >= observed - 1e-9) ++high;
  }
  return std::min(1.0, 2.0 * std::min(low, high) / static_cast<double>(1u << n));
}

TEST(Statistics, WilcoxonExactMatchesEnumerationOfEverySignPattern) {
  std::mt19937 generator(14);
  std::uniform_int_distribution<int> value(0, 6);  // small range: many ties and zeros
  for (int trial = 0; trial < 200; ++trial) {
    const int n = 1 + trial % 12;
    Values a, b;
    for (int i = 0; i < n; ++i) {
      a.push_back(value(generator));
      b.push_back(value(generator));
    }
    const WilcoxonResult result = wilcoxon_signed_rank(a, b);
    EXPECT_NEAR(result.p_value, brute_force_wilcoxon_p(a, b), 1e-12) << "trial " << trial;
    EXPECT_DOUBLE_EQ(result.w_plus + result.w_minus, result.n * (result.n + 1) / 2.0);
  }
}

// n = 30, differences 1..30 with the first ten negative: W- = 55, W+ = 465 - 55 = 410.
// Mean n(n+1)/4 = 232.5, variance n(n+1)(2n+1)/24 = 2363.75, z = 177.5 / sqrt(2363.75).
TEST(Statistics, WilcoxonAboveTwentyFiveUsesTheNormalApproximation) {
  Values a, b(30, 0.0);
  for (int i = 1; i <= 30; ++i) a.push_back(i <= 10 ? -i : i);
  const WilcoxonResult result = wilcoxon_signed_rank(a, b);
  EXPECT_FALSE(result.exact);
  EXPECT_DOUBLE_EQ(result.w_plus, 410.0);
  const double z = 177.5 / std::sqrt(2363.75);
  EXPECT_NEAR(result.p_value, std::erfc(z / std::sqrt(2.0)), 1e-12);
}

// n = 26, every |d| = 1 (one tie group of 26, ranks 13.5), 20 positive: W+ = 270.
// Variance 26*27*53/24 - (26^3 - 26)/48 = 1550.25 - 365.625 = 1184.625; mean 175.5.
TEST(Statistics, WilcoxonNormalApproximationCorrectsForTies) {
  Values a, b(26, 0.0);
  for (int i = 0; i < 26; ++i) a.push_back(i < 20 ? 1.0 : -1.0);
  const WilcoxonResult result = wilcoxon_signed_rank(a, b);
  EXPECT_DOUBLE_EQ(result.w_plus, 270.0);
  const double z = (270.0 - 175.5) / std::sqrt(1184.625);
  EXPECT_NEAR(result.p_value, std::erfc(z / std::sqrt(2.0)), 1e-12);
}

TEST(Statistics, WilcoxonWithoutNonZeroDifferencesFindsNothing) {
  const WilcoxonResult result = wilcoxon_signed_rank(Values{1.0, 2.0}, Values{1.0, 2.0});
  EXPECT_EQ(result.n, 0);
  EXPECT_EQ(result.p_value, 1.0);
  EXPECT_THROW(wilcoxon_signed_rank(Values{1.0}, Values{1.0, 2.0}), std::invalid_argument);
}

// A large normal sample: the interval contains the true mean, and its width is close to the
// normal theory's 2 * 1.96 * sd / sqrt(n).
TEST(Statistics, BootstrapMeanIntervalMatchesNormalTheoryOnALargeSample) {
  std::mt19937_64 generator(2026);
  std::normal_distribution<double> normal(5.0, 2.0);
  Values sample(5000);
  for (double& x : sample) x = normal(generator);
  const double m = mean(sample);
  double squares = 0;
  for (double x : sample) squares += (x - m) * (x - m);
  const double sd = std::sqrt(squares / (sample.size() - 1.0));
  const double theory = 2.0 * 1.96 * sd / std::sqrt(static_cast<double>(sample.size()));

  const ConfidenceInterval ci = bootstrap_mean_ci(sample);
  EXPECT_LT(ci.low, 5.0);
  EXPECT_GT(ci.high, 5.0);
  EXPECT_LT(ci.low, m);
  EXPECT_GT(ci.high, m);
  EXPECT_NEAR(ci.high - ci.low, theory, 0.2 * theory);

  // The median of a normal sample has standard error ~ 1.2533 sd / sqrt(n).
  const ConfidenceInterval median_ci = bootstrap_median_ci(sample);
  EXPECT_LT(median_ci.low, 5.0);
  EXPECT_GT(median_ci.high, 5.0);
  EXPECT_NEAR(median_ci.high - median_ci.low, 1.2533 * theory, 0.3 * 1.2533 * theory);
}

// 1..100 in order (a resampler that favours some positions would show): mean 50.5, sd
// sqrt((100^2 - 1) / 12) = 28.87 (population) -> normal-theory width 2 * 1.96 * 2.887 = 11.3.
TEST(Statistics, BootstrapDrawsFromTheWholeSample) {
  Values sample;
  for (int i = 1; i <= 100; ++i) sample.push_back(i);
  const ConfidenceInterval ci = bootstrap_mean_ci(sample);
  EXPECT_LT(ci.low, 50.5);
  EXPECT_GT(ci.high, 50.5);
  EXPECT_NEAR(0.5 * (ci.low + ci.high), 50.5, 1.5);
  EXPECT_NEAR(ci.high - ci.low, 11.3, 0.2 * 11.3);
}

TEST(Statistics, BootstrapIsReproducibleForTheSameSeedAndDependsOnIt) {
  // Values with no common denominator, so resample means rarely coincide between seeds.
  const Values sample = {3.01, 9.3, 1.0, 4.007, 7.21, 2.0003, 8.9};
  const ConfidenceInterval first = bootstrap_mean_ci(sample);
  const ConfidenceInterval again = bootstrap_mean_ci(sample);
  EXPECT_EQ(first.low, again.low);
  EXPECT_EQ(first.high, again.high);
  BootstrapOptions other;
  other.seed = 99;
  const ConfidenceInterval reseeded = bootstrap_mean_ci(sample, other);
  EXPECT_TRUE(reseeded.low != first.low || reseeded.high != first.high);
  // Resample means lie within the sample's range.
  EXPECT_GE(first.low, 1.0);
  EXPECT_LE(first.high, 9.3);
  EXPECT_LT(first.low, first.high);
}

TEST(Statistics, BootstrapOfOneValueIsThatValue) {
  const ConfidenceInterval ci = bootstrap_median_ci(Values{4.25});
  EXPECT_EQ(ci.low, 4.25);
  EXPECT_EQ(ci.high, 4.25);
  BootstrapOptions bad;
  bad.resamples = 0;
  EXPECT_THROW(bootstrap_mean_ci(Values{1.0, 2.0}, bad), std::invalid_argument);
}

// Limit 10 s: solved 1 s, solved 3 s, unsolved (2 s), solved but 12 s (over the limit).
// PAR-2 = (1 + 3 + 20 + 20) / 4 = 11.
TEST(Statistics, Par2CountsUnsolvedAndLateRunsAsTwiceTheLimit) {
  const std::vector<TimedRun> runs = {{true, 1.0}, {true, 3.0}, {false, 2.0}, {true, 12.0}};
  EXPECT_DOUBLE_EQ(par2_score(runs, 10.0), 11.0);
  EXPECT_DOUBLE_EQ(par2_score(std::vector<TimedRun>{{true, 10.0}}, 10.0), 10.0);
  EXPECT_THROW(par2_score(runs, 0.0), std::invalid_argument);
}

TEST(Statistics, CactusCurveListsSolvedRunsInOrderOfTime) {
  const std::vector<TimedRun> runs = {
      {true, 5.0}, {true, 1.0}, {false, 0.5}, {true, 12.0}, {true, 3.0}};
  const std::vector<CactusPoint> curve = cactus_curve(runs, 10.0);
  ASSERT_EQ(curve.size(), 3u);  // 12 s is over the limit, 0.5 s unsolved
  EXPECT_EQ(curve[0].runs_solved, 1);
  EXPECT_DOUBLE_EQ(curve[0].seconds, 1.0);
  EXPECT_EQ(curve[1].runs_solved, 2);
  EXPECT_DOUBLE_EQ(curve[1].seconds, 3.0);
  EXPECT_EQ(curve[2].runs_solved, 3);
  EXPECT_DOUBLE_EQ(curve[2].seconds, 5.0);
  EXPECT_EQ(cactus_curve(runs, kInfinity).size(), 4u);
}

// Instances x solvers A, B:
//   I1: A 1 s, B 2 s        -> ratios 1, 2
//   I2: A 4 s, B 2 s        -> ratios 2, 1
//   I3: A unsolved, B 3 s   -> inf, 1
//   I4: both unsolved       -> inf, inf
// rho(1) = A 1/4, B 2/4; rho(2) = A 2/4, B 3/4; rho(1e9) = A 2/4, B 3/4; rho(1.5) = 1/4, 2/4.
TEST(Statistics, PerformanceProfileCountsInstancesWithinAFactorOfTheBest) {
  const std::vector<std::vector<TimedRun>> table = {{{true, 1.0}, {true, 2.0}},
                                                    {{true, 4.0}, {true, 2.0}},
                                                    {{false, 1.0}, {true, 3.0}},
                                                    {{false, 1.0}, {false, 1.0}}};
  const auto ratios = performance_ratios(table);
  ASSERT_EQ(ratios.size(), 4u);
  EXPECT_EQ(ratios[0], (Values{1.0, 2.0}));
  EXPECT_EQ(ratios[1], (Values{2.0, 1.0}));
  EXPECT_EQ(ratios[2], (Values{kInfinity, 1.0}));
  EXPECT_EQ(ratios[3], (Values{kInfinity, kInfinity}));
  EXPECT_EQ(performance_profile_at(ratios, 1.0), (Values{0.25, 0.5}));
  EXPECT_EQ(performance_profile_at(ratios, 1.5), (Values{0.25, 0.5}));
  EXPECT_EQ(performance_profile_at(ratios, 2.0), (Values{0.5, 0.75}));
  EXPECT_EQ(performance_profile_at(ratios, 1e9), (Values{0.5, 0.75}));
}

TEST(Statistics, PerformanceRatiosFloorZeroTimes) {
  const auto ratios = performance_ratios({{{true, 0.0}, {true, 0.5}}}, 0.25);
  EXPECT_EQ(ratios[0], (Values{1.0, 2.0}));  // 0 counts as 0.25 s
}

}  // namespace
}  // namespace sightline::experiments
