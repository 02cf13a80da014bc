#include "sightline/solvers/ceres_refine_poll.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

#include "sightline/solvers/ceres_refine.h"

namespace sightline::solvers::detail {

bool BoundaryPoll::try_direction(const csp::Problem& problem,
                                 std::span<const csp::VariableId> free,
                                 std::span<const double> half_widths, std::span<const double> d,
                                 double h, const std::vector<double>& anchor, Target& target,
                                 csp::Score& score, bool& refused) {
  refused = false;
  bool changed = false;
  for (std::size_t j = 0; j < free.size(); ++j) {
    const csp::VariableId var = free[j];
    const double x = problem.domain(var).clamp(anchor[var] + h * half_widths[j] * d[j]);
    changed = changed || x != anchor[var];
    probe_[var] = x;
  }
  if (!changed) return false;
  if (!target.judge(probe_, score)) {
    refused = true;
    return false;
  }
  ++evaluations_;
  return true;
}

bool BoundaryPoll::run(const csp::Problem& problem, std::span<const csp::VariableId> free,
                       std::span<const double> half_widths, const Settings& settings,
                       Target& target, std::vector<double>& anchor, csp::Score& anchor_score) {
  const std::size_t n = free.size();
  if (n == 0) return false;
  v_.resize(n);
  g_.resize(n);
  d_.resize(n);
  last_.assign(n, 0.0);
  best_d_.resize(n);
  slope_.resize(2 * n);
  order_.resize(2 * n);
  probe_ = anchor;
  best_probe_ = anchor;
  evaluations_ = 0;
  std::mt19937_64 random(settings.seed);
  std::normal_distribution<double> normal;
  const double max_step = 4 * settings.initial_step;
  bool moved = false, have_gradient = false, gradient_stale = true, have_last = false;
  int failures = 0;
  auto spent = [&] { return evaluations_ >= settings.max_evaluations; };
  // Accepts probe_ (with `score`) as the new anchor; `d` was its direction.
  auto accept = [&](const csp::Score& score, std::span<const double> d) {
    for (const csp::VariableId var : free) anchor[var] = probe_[var];
    anchor_score = score;
    std::copy(d.begin(), d.end(), last_.begin());
    have_last = moved = gradient_stale = true;
  };
  for (double h = settings.initial_step; h >= settings.min_step;) {
    bool success = false, refused = false;
    csp::Score score;
    // 1. The last successful direction first: along a straight edge it keeps succeeding.
    if (have_last && !spent()) {
      if (try_direction(problem, free, half_widths, last_, h, anchor, target, score, refused) &&
          improves(score, anchor_score)) {
        accept(score, last_);
        success = true;
      } else {
        have_last = false;
      }
      if (refused) return moved;
    }
    if (!success && gradient_stale) {
      have_gradient = target.gradient(anchor, g_);
      if (have_gradient) {
        double norm = 0;
        for (std::size_t j = 0; j < n; ++j) {
          g_[j] *= half_widths[j];
          norm += g_[j] * g_[j];
        }
        have_gradient = norm > 0 && std::isfinite(norm);
        norm = std::sqrt(norm);
        if (have_gradient) {
          for (double& x : g_) x /= norm;
        }
      }
      gradient_stale = false;
    }
    // v uniform on the unit sphere: a normalised Gaussian vector.
    double norm = 0;
    for (double& x : v_) {
      x = normal(random);
      norm += x * x;
    }
    norm = std::sqrt(norm);
    for (double& x : v_) x = norm > 0 ? x / norm : 0.0;
    if (!(norm > 0)) v_[0] = 1;
    // 2. The +-columns of H = I - 2 v v^T, in the order of their slope along the smooth
    // part's (scaled, unit) gradient g: +-(g_c - 2 v_c g.v).
    std::iota(order_.begin(), order_.end(), 0u);
    if (have_gradient) {
      const double gv = std::inner_product(g_.begin(), g_.end(), v_.begin(), 0.0);
      for (std::size_t c = 0; c < n; ++c) {
        const double s = g_[c] - 2 * v_[c] * gv;
        slope_[2 * c] = s;
        slope_[2 * c + 1] = -s;
      }
      std::stable_sort(order_.begin(), order_.end(),
                       [&](std::uint32_t a, std::uint32_t b) { return slope_[a] < slope_[b]; });
    }
    for (std::size_t i = 0; i < order_.size() && !success; ++i) {
      if (spent()) return moved;
      const std::size_t c = order_[i] / 2;
      const double sign = (order_[i] % 2 == 0) ? 1.0 : -1.0;
      for (std::size_t j = 0; j < n; ++j) d_[j] = sign * ((j == c ? 1.0 : 0.0) - 2 * v_[j] * v_[c]);
      if (try_direction(problem, free, half_widths, d_, h, anchor, target, score, refused) &&
          improves(score, anchor_score)) {
        accept(score, d_);
        success = true;
      }
      if (refused) return moved;
    }
    // 3. The edge's tangent (see the header): in the plane of -g and w = v made orthogonal
    // to g, the directions d(t) = cos t (-g) + sin t (+-w); the smallest t > 0 that
    // improves is found by trying t = 90 (1 - 2^-k) degrees, then bisecting.
    if (!success && have_gradient && n > 1) {
      const double gv = std::inner_product(g_.begin(), g_.end(), v_.begin(), 0.0);
      double wn = 0;
      for (std::size_t j = 0; j < n; ++j) {
        v_[j] -= gv * g_[j];
        wn += v_[j] * v_[j];
      }
      wn = std::sqrt(wn);
      if (wn > 1e-6) {
        for (double& x : v_) x /= wn;
        csp::Score best_score;
        bool found = false;
        for (const double side : {1.0, -1.0}) {
          auto direction = [&](double t) {
            for (std::size_t j = 0; j < n; ++j) {
              d_[j] = -std::cos(t) * g_[j] + side * std::sin(t) * v_[j];
            }
          };
          constexpr double kQuarter = 1.5707963267948966;
          // Along d(t) the smooth part falls at rate cos t, so a step that still gains before
          // the curvature takes over is proportionally shorter: h sqrt(2) cos t (h at 45
          // degrees). One fan thus tries short steps near the tangent and long ones away
          // from it.
          auto length = [](double t) { return std::min(1.0, std::sqrt(2.0) * std::cos(t)); };
          double blocked = 0, improving = -1;
          for (int k = 1; k <= kTangentScan && improving < 0; ++k) {
            if (spent()) return moved;
            const double t = kQuarter * (1 - std::ldexp(1.0, -k));
            direction(t);
            if (try_direction(problem, free, half_widths, d_, h * length(t), anchor, target,
                              score, refused) &&
                improves(score, anchor_score)) {
              improving = t;
              if (!found || score.better_than(best_score)) {
                best_score = score;
                best_probe_ = probe_;
                best_d_ = d_;
                found = true;
              }
            } else {
              blocked = t;
            }
            if (refused) return moved;
          }
          for (int k = 0; improving >= 0 && k < kTangentBisections; ++k) {
            if (spent()) return moved;
            const double t = 0.5 * (blocked + improving);
            direction(t);
            if (try_direction(problem, free, half_widths, d_, h * length(t), anchor, target,
                              score, refused) &&
                improves(score, anchor_score)) {
              improving = t;
              if (score.better_than(best_score)) {
                best_score = score;
                best_probe_ = probe_;
                best_d_ = d_;
              }
            } else {
              blocked = t;
            }
            if (refused) return moved;
          }
        }
        if (found) {
          probe_.swap(best_probe_);
          accept(best_score, best_d_);
          success = true;
        }
      }
    }
    failures = success ? 0 : failures + 1;
    if (failures >= settings.max_failures) break;
    h = success ? std::min(2 * h, max_step) : kShrink * h;
  }
  return moved;
}

}  // namespace sightline::solvers::detail
