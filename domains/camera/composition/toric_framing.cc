#include "sightline/domains/camera/composition/toric_framing.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <vector>

#include "sightline/domains/camera/composition/composition_problem.h"

namespace sightline::camera {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDegrees = 180.0 / kPi;

struct Subjects {
  Eigen::Vector3d a, b;   // aim points
  Eigen::Vector2d sa, sb;  // wanted screen points
};

// The first two screen_position properties of different targets.
std::optional<Subjects> subjects_of(const CompositionProblem& owner) {
  const Shot& shot = owner.shot();
  int first = -1;
  for (std::size_t i = 0; i < shot.properties.size(); ++i) {
    if (shot.properties[i].kind != "screen_position") continue;
    if (first < 0) {
      first = static_cast<int>(i);
      continue;
    }
    const auto f = static_cast<std::size_t>(first);
    if (owner.targets()[i][0] == owner.targets()[f][0]) continue;
    const auto& people = owner.world().people();
    Subjects s{people[static_cast<std::size_t>(owner.targets()[f][0])].aim,
               people[static_cast<std::size_t>(owner.targets()[i][0])].aim, shot.properties[f].at,
               shot.properties[i].at};
    if ((s.a - s.b).norm() < 1e-6 || (s.sa - s.sb).norm() < 1e-9) return std::nullopt;
    return s;
  }
  return std::nullopt;
}

// The camera-frame direction (right, up, forward) of a screen point.
Eigen::Vector3d camera_ray(const Eigen::Vector2d& s, double tan_half, double aspect) {
  return Eigen::Vector3d((2 * s.x() - 1) * tan_half * aspect, (2 * s.y() - 1) * tan_half, 1)
      .normalized();
}

struct Oriented {
  Eigen::Vector3d forward;
  double roll = 0;  // degrees
  bool valid = false;
};

// The orientation at p that maps the camera rays c1, c2 onto the directions to a and b
// (their angles agree by construction). The camera frame (right, up, forward) is
// left-handed in the world (right = forward x up), hence the sign of the third axis.
Oriented orient(const Eigen::Vector3d& p, const Subjects& s, const Eigen::Vector3d& c1,
                const Eigen::Vector3d& c2) {
  Oriented o;
  const Eigen::Vector3d w1 = (s.a - p).normalized(), w2 = (s.b - p).normalized();
  const Eigen::Vector3d e2 = (c2 - c2.dot(c1) * c1).normalized();
  const Eigen::Vector3d g2 = (w2 - w2.dot(w1) * w1).normalized();
  Eigen::Matrix3d e, g;
  e << c1, e2, c1.cross(e2);
  g << w1, g2, -w1.cross(g2);
  const Eigen::Matrix3d m = g * e.transpose();
  const Eigen::Vector3d right = m.col(0), forward = m.col(2);
  const Eigen::Vector3d side = forward.cross(Eigen::Vector3d::UnitY());
  if (!(side.norm() > 1e-9) || !forward.allFinite()) return o;
  const Eigen::Vector3d r0 = side.normalized(), u0 = r0.cross(forward);
  o.forward = forward;
  o.roll = std::atan2(right.dot(u0), right.dot(r0)) * kDegrees;
  o.valid = true;
  return o;
}

}  // namespace

const solvers::OptionSchema<ToricFraming::Options>& ToricFraming::Options::schema() {
  static const solvers::OptionSchema<Options> schema = [] {
    solvers::OptionSchema<Options> s;
    s.integer("beta_steps", &Options::beta_steps, "samples of the angle at the first subject (>= 2)", 2);
    s.integer("phi_steps", &Options::phi_steps, "samples of the turn about the subjects' axis (>= 8)", 8);
    return s;
  }();
  return schema;
}

std::string ToricFraming::Options::validate() const { return ""; }

std::string ToricFraming::unsuitable_reason(const csp::Problem& problem) const {
  const CompositionProblem* owner = composition_of(problem);
  if (!owner) return "needs a composition problem (a scene's shot: block)";
  if (!subjects_of(*owner)) {
    return "needs screen_position properties of two different targets at different points";
  }
  return "";
}

void ToricFraming::solve_into(const csp::Problem& problem, std::span<const double> start,
                              const solvers::SolveContext& context, solvers::SolverResult& result) {
  if (std::string why = unsuitable_reason(problem); !why.empty()) {
    throw std::invalid_argument(name_ + ": " + why);
  }
  const CompositionProblem& owner = *composition_of(problem);
  const Subjects s = *subjects_of(owner);
  const Shot& shot = owner.shot();
  solvers::Budget budget(context.limits, 16);
  std::uint64_t evaluations = 0, iterations = 0;

  const double length = (s.b - s.a).norm();
  const Eigen::Vector3d axis = (s.b - s.a) / length;
  const Eigen::Vector3d e1 = axis.unitOrthogonal(), e2 = axis.cross(e1);
  bool found = false;
  csp::Score best;
  csp::Assignment candidate(7);
  result.best.assign(start.begin(), start.end());
  if (result.best.size() != 7) result.best = owner.assignment(CameraPose{});

  auto consider = [&](const Eigen::Vector3d& p, const Oriented& o, double fov, double roll) {
    if (!shot.region.contains(p)) return;
    candidate[0] = p.x();
    candidate[1] = p.y();
    candidate[2] = p.z();
    candidate[3] = std::atan2(o.forward.x(), o.forward.z()) * kDegrees;
    candidate[4] = std::asin(std::clamp(o.forward.y(), -1.0, 1.0)) * kDegrees;
    if (std::abs(candidate[4]) > 89) return;
    candidate[5] = fov;
    candidate[6] = roll;
    const csp::Score score = problem.score(candidate);
    ++evaluations;
    if (!found || score.better_than(best)) {
      found = true;
      best = score;
      result.best = candidate;
      budget.note_best(evaluations);
    }
  };

  std::vector<double> fovs{(shot.fov.lo + shot.fov.hi) / 2};
  if (!shot.fov.fixed()) fovs = {(shot.fov.lo + shot.fov.hi) / 2, shot.fov.lo, shot.fov.hi};
  const double wanted_roll = std::clamp(0.0, shot.roll.lo, shot.roll.hi);
  const auto beta_steps = static_cast<int>(options_.beta_steps);
  const auto phi_steps = static_cast<int>(options_.phi_steps);
  std::vector<double> roll_at(static_cast<std::size_t>(phi_steps) + 1);
  std::vector<bool> valid_at(static_cast<std::size_t>(phi_steps) + 1);
  for (double fov : fovs) {
    const double tan_half = std::tan(fov / kDegrees / 2);
    const Eigen::Vector3d c1 = camera_ray(s.sa, tan_half, shot.aspect);
    const Eigen::Vector3d c2 = camera_ray(s.sb, tan_half, shot.aspect);
    const double theta = std::acos(std::clamp(c1.dot(c2), -1.0, 1.0));
    if (!(theta > 1e-9)) continue;
    // The samples of beta, i = 1..beta_steps, visited coarse to fine (i - 1 is the
    // bit-reversed n, those past beta_steps skipped): a solve its time limit cuts short
    // has sampled the whole range evenly, not only the angles nearest the axis.
    int bits = 0;
    while ((1 << bits) < beta_steps) ++bits;
    for (int n = 0; n < (1 << bits) && !budget.exhausted(evaluations, iterations); ++n) {
      int reversed = 0;
      for (int b = 0; b < bits; ++b) reversed |= ((n >> b) & 1) << (bits - 1 - b);
      if (reversed >= beta_steps) continue;
      const int i = reversed + 1;
      ++iterations;
      const double beta = (kPi - theta) * i / (beta_steps + 1);
      const double reach = length * std::sin(theta + beta) / std::sin(theta);
      auto place = [&](double phi) {
        return Eigen::Vector3d(s.a + reach * (std::cos(beta) * axis +
                                              std::sin(beta) * (std::cos(phi) * e1 + std::sin(phi) * e2)));
      };
      for (int j = 0; j <= phi_steps; ++j) {
        const Oriented o = orient(place(2 * kPi * j / phi_steps), s, c1, c2);
        valid_at[static_cast<std::size_t>(j)] = o.valid;
        roll_at[static_cast<std::size_t>(j)] = o.roll;
        if (o.valid && !shot.roll.fixed() && o.roll >= shot.roll.lo && o.roll <= shot.roll.hi) {
          consider(place(2 * kPi * j / phi_steps), o, fov, o.roll);
        }
      }
      // Where roll(phi) crosses the wanted roll: the root, bracketed, by the Illinois
      // variant of regula falsi (superlinear; plain bisection took 60 orientations a root,
      // most of a short solve), so the subjects land on their points with that roll.
      for (int j = 0; j < phi_steps; ++j) {
        const auto k = static_cast<std::size_t>(j);
        if (!valid_at[k] || !valid_at[k + 1]) continue;
        double lo = 2 * kPi * j / phi_steps, hi = 2 * kPi * (j + 1) / phi_steps;
        double g_lo = signed_degrees(roll_at[k] - wanted_roll);
        double g_hi = signed_degrees(roll_at[k + 1] - wanted_roll);
        if ((g_lo > 0) == (g_hi > 0) || std::abs(g_lo) > 90 || std::abs(g_hi) > 90) continue;
        double phi = (lo + hi) / 2;
        // The end the last step kept (-1: lo, +1: hi); one kept twice running has its value
        // halved (Illinois), so the estimate stops creeping up from one side.
        int kept_side = 0;
        for (int step = 0; step < 60 && hi - lo > 1e-13; ++step) {
          phi = std::clamp(hi - g_hi * (hi - lo) / (g_hi - g_lo), lo, hi);
          const Oriented o = orient(place(phi), s, c1, c2);
          if (!o.valid) break;
          const double g = signed_degrees(o.roll - wanted_roll);
          if (std::abs(g) < 1e-11) break;
          if ((g > 0) == (g_lo > 0)) {
            lo = phi;
            g_lo = g;
            if (kept_side == 1) g_hi /= 2;
            kept_side = 1;
          } else {
            hi = phi;
            g_hi = g;
            if (kept_side == -1) g_lo /= 2;
            kept_side = -1;
          }
        }
        const Oriented o = orient(place(phi), s, c1, c2);
        if (o.valid) consider(place(phi), o, fov, wanted_roll);
      }
    }
  }
  result.evaluations = evaluations;
  result.iterations = iterations;
  result.stop = budget.exhausted(evaluations, iterations) ? budget.reason()
                                                          : solvers::StopReason::kCompleted;
  result.message = found ? "" : "no pose on the two subjects' torus lies in the region with the shot's roll";
  solvers::finish_result(problem, context, budget, result);
}

}  // namespace sightline::camera
