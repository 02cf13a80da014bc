#include "sightline/experiments/reports/statistics.h"

#include <algorithm>
#include <boost/math/distributions/chi_squared.hpp>
#include <boost/math/distributions/normal.hpp>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>
#include <stdexcept>
#include <string>

namespace sightline::experiments {
namespace {

void require_sample(std::span<const double> values, const char* what) {
  if (values.empty())
    throw std::invalid_argument(std::string(what) + ": expected at least one value");
  for (double v : values)
    if (std::isnan(v)) throw std::invalid_argument(std::string(what) + ": expected no NaN values");
}

double median_of_sorted(const std::vector<double>& sorted) {
  const std::size_t n = sorted.size();
  return n % 2 == 1 ? sorted[n / 2] : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]);
}

// Linear interpolation between order statistics (Hyndman-Fan type 7, R's default).
double quantile_of_sorted(const std::vector<double>& sorted, double p) {
  const double h = (static_cast<double>(sorted.size()) - 1.0) * p;
  const auto lo = static_cast<std::size_t>(std::floor(h));
  const std::size_t hi = std::min(lo + 1, sorted.size() - 1);
  return sorted[lo] + (h - static_cast<double>(lo)) * (sorted[hi] - sorted[lo]);
}

template <typename Statistic>
ConfidenceInterval bootstrap_ci(std::span<const double> values, const BootstrapOptions& options,
                                Statistic statistic, const char* what) {
  require_sample(values, what);
  if (options.resamples < 1)
    throw std::invalid_argument(std::string(what) + ": expected resamples >= 1");
  if (!(options.level > 0.0 && options.level < 1.0))
    throw std::invalid_argument(std::string(what) + ": expected level in (0, 1)");
  std::mt19937_64 generator(options.seed);
  std::uniform_int_distribution<std::size_t> pick(0, values.size() - 1);
  std::vector<double> resample(values.size());
  std::vector<double> statistics;
  statistics.reserve(static_cast<std::size_t>(options.resamples));
  for (int b = 0; b < options.resamples; ++b) {
    for (double& x : resample) x = values[pick(generator)];
    statistics.push_back(statistic(resample));
  }
  std::sort(statistics.begin(), statistics.end());
  const double tail = (1.0 - options.level) / 2.0;
  return {quantile_of_sorted(statistics, tail), quantile_of_sorted(statistics, 1.0 - tail)};
}

}  // namespace

double median(std::span<const double> values) {
  require_sample(values, "median");
  std::vector<double> sorted(values.begin(), values.end());
  std::sort(sorted.begin(), sorted.end());
  return median_of_sorted(sorted);
}

double mean(std::span<const double> values) {
  require_sample(values, "mean");
  return std::accumulate(values.begin(), values.end(), 0.0) / static_cast<double>(values.size());
}

ConfidenceInterval bootstrap_mean_ci(std::span<const double> values,
                                     const BootstrapOptions& options) {
  return bootstrap_ci(
      values, options,
      [](const std::vector<double>& s) {
        return std::accumulate(s.begin(), s.end(), 0.0) / static_cast<double>(s.size());
      },
      "bootstrap_mean_ci");
}

ConfidenceInterval bootstrap_median_ci(std::span<const double> values,
                                       const BootstrapOptions& options) {
  return bootstrap_ci(
      values, options,
      [](std::vector<double>& s) {
        std::sort(s.begin(), s.end());  // the resample is redrawn next round: sorting is free
        return median_of_sorted(s);
      },
      "bootstrap_median_ci");
}

std::vector<double> average_ranks(std::span<const double> values) {
  require_sample(values, "average_ranks");
  std::vector<std::size_t> order(values.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t i, std::size_t j) { return values[i] < values[j]; });
  std::vector<double> ranks(values.size());
  for (std::size_t start = 0; start < order.size();) {
    std::size_t end = start + 1;
    while (end < order.size() && values[order[end]] == values[order[start]]) ++end;
    // Positions start+1 .. end (1-based) share their average.
    const double shared = 0.5 * (static_cast<double>(start + 1) + static_cast<double>(end));
    for (std::size_t p = start; p < end; ++p) ranks[order[p]] = shared;
    start = end;
  }
  return ranks;
}

FriedmanResult friedman_test(const std::vector<std::vector<double>>& table) {
  if (table.size() < 2) throw std::invalid_argument("friedman_test: expected at least 2 blocks");
  const std::size_t k = table.front().size();
  if (k < 2) throw std::invalid_argument("friedman_test: expected at least 2 solvers");
  const double n = static_cast<double>(table.size());
  const double kd = static_cast<double>(k);
  std::vector<double> rank_sums(k, 0.0);
  double sum_squared_ranks = 0.0;
  for (const auto& row : table) {
    if (row.size() != k)
      throw std::invalid_argument(
          "friedman_test: expected every block to have the same number of solvers");
    const std::vector<double> ranks = average_ranks(row);
    for (std::size_t j = 0; j < k; ++j) {
      rank_sums[j] += ranks[j];
      sum_squared_ranks += ranks[j] * ranks[j];
    }
  }
  FriedmanResult result;
  result.blocks = static_cast<int>(table.size());
  result.solvers = static_cast<int>(k);
  for (double r : rank_sums) result.average_ranks.push_back(r / n);
  double spread = 0.0;
  for (double r : rank_sums) spread += (r - n * (kd + 1.0) / 2.0) * (r - n * (kd + 1.0) / 2.0);
  const double denominator = sum_squared_ranks - n * kd * (kd + 1.0) * (kd + 1.0) / 4.0;
  if (denominator <= 1e-12) return result;  // every block all ties: Q = 0, p = 1
  result.chi_square = (kd - 1.0) * spread / denominator;
  const boost::math::chi_squared distribution(kd - 1.0);
  result.p_value = boost::math::cdf(boost::math::complement(distribution, result.chi_square));
  return result;
}

WilcoxonResult wilcoxon_signed_rank(std::span<const double> a, std::span<const double> b) {
  if (a.size() != b.size())
    throw std::invalid_argument("wilcoxon_signed_rank: expected paired samples of the same length");
  std::vector<double> magnitudes;
  std::vector<bool> positive;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const double d = a[i] - b[i];
    if (std::isnan(d)) throw std::invalid_argument("wilcoxon_signed_rank: expected no NaN values");
    if (d == 0.0) continue;
    magnitudes.push_back(std::abs(d));
    positive.push_back(d > 0.0);
  }
  WilcoxonResult result;
  result.n = static_cast<int>(magnitudes.size());
  if (magnitudes.empty()) return result;
  const std::vector<double> ranks = average_ranks(magnitudes);
  for (std::size_t i = 0; i < ranks.size(); ++i)
    (positive[i] ? result.w_plus : result.w_minus) += ranks[i];

  if (result.n <= 25) {
    // Average ranks are multiples of 1/2, so doubled ranks are integers; count the sign
    // patterns reaching each doubled W+ (2^25 fits a double exactly).
    std::vector<int> doubled;
    int total = 0;
    for (double r : ranks) {
      doubled.push_back(static_cast<int>(std::lround(2.0 * r)));
      total += doubled.back();
    }
    std::vector<double> ways(static_cast<std::size_t>(total) + 1, 0.0);
    ways[0] = 1.0;
    int reach = 0;
    for (int r : doubled) {
      for (int s = reach; s >= 0; --s)
        ways[static_cast<std::size_t>(s + r)] += ways[static_cast<std::size_t>(s)];
      reach += r;
    }
    const int observed = static_cast<int>(std::lround(2.0 * result.w_plus));
    const double patterns = std::ldexp(1.0, result.n);
    double at_most = 0.0, at_least = 0.0;
    for (int s = 0; s <= total; ++s) {
      if (s <= observed) at_most += ways[static_cast<std::size_t>(s)];
      if (s >= observed) at_least += ways[static_cast<std::size_t>(s)];
    }
    result.p_value = std::min(1.0, 2.0 * std::min(at_most, at_least) / patterns);
    result.exact = true;
    return result;
  }

  const double n = static_cast<double>(result.n);
  double tie_term = 0.0;
  std::vector<double> sorted = ranks;
  std::sort(sorted.begin(), sorted.end());
  for (std::size_t start = 0; start < sorted.size();) {
    std::size_t end = start;
    while (end < sorted.size() && sorted[end] == sorted[start]) ++end;
    const double t = static_cast<double>(end - start);
    tie_term += t * t * t - t;
    start = end;
  }
  const double variance = n * (n + 1.0) * (2.0 * n + 1.0) / 24.0 - tie_term / 48.0;
  if (variance <= 0.0) return result;
  const double z = (result.w_plus - n * (n + 1.0) / 4.0) / std::sqrt(variance);
  const boost::math::normal standard;
  result.p_value =
      std::min(1.0, 2.0 * boost::math::cdf(boost::math::complement(standard, std::abs(z))));
  return result;
}

namespace {
bool solved_within(const TimedRun& run, double time_limit) {
  return run.solved && run.seconds <= time_limit;
}
}  // namespace

double par2_score(std::span<const TimedRun> runs, double time_limit) {
  if (runs.empty()) throw std::invalid_argument("par2_score: expected at least one run");
  if (!(time_limit > 0.0)) throw std::invalid_argument("par2_score: expected a time limit > 0");
  double total = 0.0;
  for (const TimedRun& run : runs)
    total += solved_within(run, time_limit) ? run.seconds : 2.0 * time_limit;
  return total / static_cast<double>(runs.size());
}

std::vector<CactusPoint> cactus_curve(std::span<const TimedRun> runs, double time_limit) {
  std::vector<double> times;
  for (const TimedRun& run : runs)
    if (solved_within(run, time_limit)) times.push_back(run.seconds);
  std::sort(times.begin(), times.end());
  std::vector<CactusPoint> curve;
  for (std::size_t i = 0; i < times.size(); ++i)
    curve.push_back({static_cast<int>(i + 1), times[i]});
  return curve;
}

std::vector<std::vector<double>> performance_ratios(const std::vector<std::vector<TimedRun>>& table,
                                                    double min_seconds) {
  if (!(min_seconds > 0.0))
    throw std::invalid_argument("performance_ratios: expected min_seconds > 0");
  const double infinite = std::numeric_limits<double>::infinity();
  std::vector<std::vector<double>> ratios;
  const std::size_t k = table.empty() ? 0 : table.front().size();
  for (const auto& row : table) {
    if (row.size() != k)
      throw std::invalid_argument(
          "performance_ratios: expected every instance to have the same number of solvers");
    double best = infinite;
    for (const TimedRun& run : row)
      if (run.solved) best = std::min(best, std::max(run.seconds, min_seconds));
    std::vector<double>& out = ratios.emplace_back();
    for (const TimedRun& run : row)
      out.push_back(run.solved ? std::max(run.seconds, min_seconds) / best : infinite);
  }
  return ratios;
}

std::vector<double> performance_profile_at(const std::vector<std::vector<double>>& ratios,
                                           double tau) {
  if (ratios.empty())
    throw std::invalid_argument("performance_profile_at: expected at least one instance");
  const std::size_t k = ratios.front().size();
  std::vector<double> fraction(k, 0.0);
  for (const auto& row : ratios) {
    if (row.size() != k)
      throw std::invalid_argument(
          "performance_profile_at: expected every instance to have the same number of solvers");
    for (std::size_t s = 0; s < k; ++s)
      if (row[s] <= tau) fraction[s] += 1.0;
  }
  for (double& f : fraction) f /= static_cast<double>(ratios.size());
  return fraction;
}

}  // namespace sightline::experiments
