// Random numbers for the stochastic solvers: one seeded engine, and the few draws they need.
//
// std::mt19937_64 seeded from SolveContext::seed makes every run reproducible. Indices use
// Lemire's multiply-shift (one 64x64->128-bit product, no division, no loop), which matters
// when 1,000,000-queens draws tens of millions of them; its bias is below 2^-40 for the
// ranges used here. Gaussians come from std::normal_distribution (deterministic for a given
// standard library).
#pragma once

#include <cstdint>
#include <random>

namespace sightline::solvers::detail {

class Random {
 public:
  explicit Random(std::uint64_t seed) : engine_(seed) {}

  // Uniform in [0, n), n >= 1.
  std::size_t index(std::size_t n) { return scale(bits(), n); }
  // The same in two steps, for callers that draw ahead of use: 64 random bits now, and
  // scale(bits, n), uniform in [0, n), when n is known.
  std::uint64_t bits() { return engine_(); }
  static std::size_t scale(std::uint64_t bits, std::size_t n) {
    __extension__ using Wide = unsigned __int128;
    return static_cast<std::size_t>((static_cast<Wide>(bits) * n) >> 64);
  }
  // Uniform in [0, 1).
  double uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }
  // True with probability p.
  bool chance(double p) { return p > 0 && uniform() < p; }
  // Standard normal.
  double gaussian() { return normal_(engine_); }
  std::mt19937_64& engine() { return engine_; }

 private:
  std::mt19937_64 engine_;
  std::normal_distribution<double> normal_{0.0, 1.0};
};

}  // namespace sightline::solvers::detail
