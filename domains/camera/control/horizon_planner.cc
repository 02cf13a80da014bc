#include "sightline/domains/camera/control/horizon_planner.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <span>

namespace sightline::camera {

namespace {

// The minimum-jerk quintic from (p0, v0, a0) to (p1, v1, 0) in T seconds, per axis; after T
// it goes on at v1 (the goal keeps moving).
struct Quintic {
  std::array<Eigen::Vector3d, 6> c;
  Eigen::Vector3d end, end_velocity;
  double duration = 1;

  Quintic(const HorizonPlanner::State& s, const Eigen::Vector3d& p1, const Eigen::Vector3d& v1,
          double T)
      : end(p1), end_velocity(v1), duration(T) {
    const Eigen::Vector3d h = p1 - s.position;
    const double T2 = T * T, T3 = T2 * T;
    c[0] = s.position;
    c[1] = s.velocity;
    c[2] = 0.5 * s.acceleration;
    c[3] = (20 * h - (8 * v1 + 12 * s.velocity) * T - 3 * s.acceleration * T2) / (2 * T3);
    c[4] = (-30 * h + (14 * v1 + 16 * s.velocity) * T + 3 * s.acceleration * T2) / (2 * T3 * T);
    c[5] = (12 * h - 6 * (v1 + s.velocity) * T - s.acceleration * T2) / (2 * T3 * T2);
  }
  Eigen::Vector3d position(double t) const {
    if (t >= duration) return end + (t - duration) * end_velocity;
    return c[0] + t * (c[1] + t * (c[2] + t * (c[3] + t * (c[4] + t * c[5]))));
  }
  Eigen::Vector3d velocity(double t) const {
    if (t >= duration) return end_velocity;
    return c[1] + t * (2 * c[2] + t * (3 * c[3] + t * (4 * c[4] + t * 5 * c[5])));
  }
  Eigen::Vector3d acceleration(double t) const {
    if (t >= duration) return Eigen::Vector3d::Zero();
    return 2 * c[2] + t * (6 * c[3] + t * (12 * c[4] + t * 20 * c[5]));
  }
};

// Room for the camera's sphere of radius r at p (clearance >= r), by the query that answers
// just that.
bool has_room(const SceneAtTime& geometry, const Eigen::Vector3d& p, double r) {
  return !geometry.closer_than(p, r, r + 1e-6);
}

// A first frame that grazes a wall (inside clearance by at most kMaxSlide) slides along it:
// pushed out along the wall's normal (the clearance's gradient, by central differences),
// its velocity into the wall removed. A few millimetres of push cost far less jerk than any
// other way out once momentum has brought the camera there. False when it cannot.
bool slide_out(const SceneAtTime& geometry, double radius, Eigen::Vector3d* p,
               Eigen::Vector3d* velocity) {
  constexpr double kMaxSlide = 0.02, kStep = 0.01, kMargin = 1e-4;
  const double probe = radius + kStep + kMaxSlide;
  const double c = geometry.clearance(*p, probe);
  if (c >= radius) return true;
  if (c < radius - kMaxSlide) return false;
  Eigen::Vector3d normal;
  for (int i = 0; i < 3; ++i) {
    Eigen::Vector3d e = Eigen::Vector3d::Zero();
    e[i] = kStep;
    normal[i] = geometry.clearance(*p + e, probe) - geometry.clearance(*p - e, probe);
  }
  if (normal.norm() < 1e-12) return false;
  normal.normalize();
  const Eigen::Vector3d pushed = *p + (radius - c + kMargin) * normal;
  if (geometry.clearance(pushed, probe) < radius) return false;
  *p = pushed;
  const double into = velocity->dot(normal);
  if (into < 0) *velocity -= into * normal;
  return true;
}

}  // namespace

HorizonPlanner::HorizonPlanner(const CameraProblem& problem,
                               std::vector<csp::ConstraintId> framing_ids, double max_speed,
                               double max_acceleration, double plan_seconds, double max_jerk)
    : problem_(&problem),
      framing_ids_(std::move(framing_ids)),
      max_speed_(max_speed),
      max_acceleration_(max_acceleration),
      plan_seconds_(plan_seconds),
      max_jerk_(max_jerk) {}

void HorizonPlanner::record_trail(const Eigen::Vector3d& look) {
  if (trail_size_ == 0 || (look - trail_point(1)).norm() >= kTrailSpacing) {
    trail_[static_cast<std::size_t>(trail_next_)] = look;
    trail_next_ = (trail_next_ + 1) % kTrailPoints;
    trail_size_ = std::min(trail_size_ + 1, kTrailPoints);
  }
}

std::optional<Eigen::Vector3d> HorizonPlanner::at_shot_height(const Eigen::Vector3d& p,
                                                              double rise) const {
  const SceneAtTime& geometry = problem_->scene_at_time();
  const Eigen::Vector3d raised = p + Eigen::Vector3d(0, rise, 0);
  if (!has_room(geometry, raised, problem_->profile().clearance_radius) ||
      !geometry.line_of_sight(raised, p)) {
    return std::nullopt;
  }
  return raised;
}

std::optional<Eigen::Vector3d> HorizonPlanner::chase_on_trail(
    const Eigen::Vector3d& look, const Eigen::Vector3d& ideal,
    Eigen::Vector3d& chase_velocity) const {
  const double distance = problem_->effective().desired_distance;
  Eigen::Vector3d newer = look;
  double walked = 0;
  for (int k = 1; k <= trail_size_; ++k) {
    const Eigen::Vector3d& older = trail_point(k);
    const double leg = (newer - older).norm();
    if (walked + leg >= distance && leg > 1e-9) {
      const Eigen::Vector3d along = (newer - older) / leg;
      const Eigen::Vector3d p = newer - (distance - walked) * along;
      Eigen::Vector3d speed = problem_->character().velocity;
      speed.y() = 0;
      chase_velocity = along * speed.norm();
      return at_shot_height(p, ideal.y() - look.y()).value_or(p);
    }
    walked += leg;
    newer = older;
  }
  return std::nullopt;
}

std::optional<Eigen::Vector3d> HorizonPlanner::follow_trail(const State& now,
                                                            const Eigen::Vector3d& look,
                                                            const Eigen::Vector3d& target_velocity,
                                                            Eigen::Vector3d& trail_velocity) {
  const SceneAtTime& geometry_now = problem_->scene_at_time();
  // Only when the straight way to the ideal position (the profile's shot, where the
  // camera should end up; the solver's target is searched near the camera and may be on
  // the camera's side of a wall) is blocked: the newest trail point the camera sees
  // directly, with room for it there.
  const Eigen::Vector3d ideal = problem_->ideal_position();
  const double radius = problem_->profile().clearance_radius;
  // Left behind: farther from the ideal shot than the solver searches, the straight way
  // there blocked, the shot itself open and in her sight (so her path leads there: a shot
  // beyond the wall she backed up to is not reached along it), and (to start following)
  // no nearer than last frame; then it follows until it sees its way to the shot or is
  // near it.
  const double off = (now.position - ideal).norm();
  const bool cut_off = off > problem_->profile().search_half_size &&
                       has_room(geometry_now, ideal, radius) &&
                       !geometry_now.line_of_sight(now.position, ideal) &&
                       geometry_now.line_of_sight(look, ideal);
  following_trail_ = cut_off && (following_trail_ || off >= last_off_ideal_);
  last_off_ideal_ = off;
  if (!following_trail_) return std::nullopt;
  for (int k = 1; k <= trail_size_; ++k) {
    const Eigen::Vector3d& p = trail_point(k);
    // At the shot's height above her path where there is room (no ceiling in the way),
    // else at her look-at height, where her body was.
    const std::optional<Eigen::Vector3d> raised = at_shot_height(p, ideal.y() - look.y());
    const bool high = raised && geometry_now.line_of_sight(now.position, *raised);
    if (high || (geometry_now.line_of_sight(now.position, p) &&
                 has_room(geometry_now, p, radius))) {
      const Eigen::Vector3d waypoint = high ? *raised : p;
      // Moving on along her path at the target's speed: the way she went from there.
      const Eigen::Vector3d& next = trail_point(std::max(1, k - 1));
      const Eigen::Vector3d along = next - p;
      trail_velocity = along.norm() > 1e-9
                           ? Eigen::Vector3d(along.normalized() * target_velocity.norm())
                           : Eigen::Vector3d::Zero();
      return waypoint;
    }
  }
  return std::nullopt;
}

std::optional<HorizonPlanner::State> HorizonPlanner::plan(const State& now,
                                                          const Eigen::Vector3d& target,
                                                          const Eigen::Vector3d& target_velocity,
                                                          const Eigen::Vector3d& look,
                                                          double dt) {
  // The view's frame at the target: toward the look-at point (horizontal), across, up.
  const Eigen::Vector3d up = Eigen::Vector3d::UnitY();
  Eigen::Vector3d toward = look - target;
  toward.y() = 0;
  const double reach_in = toward.norm();
  toward = reach_in > 1e-9 ? Eigen::Vector3d(toward / reach_in) : Eigen::Vector3d::UnitX();
  const Eigen::Vector3d side(toward.z(), 0, -toward.x());

  // The trail's waypoint, when the camera is left behind (follow_trail).
  record_trail(look);
  Eigen::Vector3d trail_velocity = Eigen::Vector3d::Zero();
  const std::optional<Eigen::Vector3d> waypoint =
      follow_trail(now, look, target_velocity, trail_velocity);
  const Eigen::Vector3d ideal = problem_->ideal_position();
  Eigen::Vector3d chase_velocity = Eigen::Vector3d::Zero();
  // The chase on her trail, while she runs (see the header comment).
  const std::optional<Eigen::Vector3d> chase =
      problem_->character().velocity.norm() > kRunningSpeed
          ? chase_on_trail(look, ideal, chase_velocity)
          : std::nullopt;

  // Offsets from the target (index kStop: the smooth stop, goal computed below; kTrail:
  // the trail's waypoint; kChase: the chase on her trail; kIdeal: the ideal shot).
  constexpr int kStop = kCandidates - 1, kTrail = kCandidates - 2, kChase = kCandidates - 3,
                kIdeal = kCandidates - 4;
  // The ideal shot, moving as it has been moving (its velocity low-passed, at most
  // max_speed), offered while it has room and sees her look-at point.
  if (has_ideal_ && dt > 0) {
    const double w = std::min(1.0, dt / kIdealSmoothing);
    ideal_velocity_ += w * ((ideal - last_ideal_) / dt - ideal_velocity_);
    if (ideal_velocity_.norm() > max_speed_) ideal_velocity_ *= max_speed_ / ideal_velocity_.norm();
  }
  last_ideal_ = ideal;
  has_ideal_ = true;
  const bool ideal_open = has_room(problem_->scene_at_time(), ideal,
                                   problem_->profile().clearance_radius) &&
                          problem_->scene_at_time().line_of_sight(ideal, look);
  std::array<Eigen::Vector3d, kCandidates> offsets = {
      Eigen::Vector3d::Zero(),
      previous_offset_,
      up,
      2 * up,
      0.35 * reach_in * toward,
      0.65 * reach_in * toward + 0.5 * up,
      1.5 * side,
      -1.5 * side,
      up + 1.5 * side,
      up - 1.5 * side,
      Eigen::Vector3d(ideal - target),
      chase ? Eigen::Vector3d(*chase - target) : Eigen::Vector3d::Zero(),
      waypoint ? Eigen::Vector3d(*waypoint - target) : Eigen::Vector3d::Zero(),
      Eigen::Vector3d::Zero()};

  // The ideal shot of a character who turns as she walks (a curve, a lap round a pillar):
  // where the shot will be `ahead` seconds on if she keeps her pace and her turn rate (the
  // forecast's: her velocity turned with her facing, as MotionPrediction turns it), the shot
  // turned with her. Carried on along its present velocity instead, the shot of a
  // character circling a pillar runs off along the tangent, outside her circle, and the
  // camera lagged a quarter lap behind her until a stuck cut (seeds 201-220 of the orbit
  // family: 14 cuts in 210 s).
  const CharacterState& her = problem_->character();
  Eigen::Vector3d pace = her.velocity;
  pace.y() = 0;
  const double turn_rate = problem_->prediction().turn_rate();  // degrees per second
  const bool turning = problem_->prediction().size() > 0 && pace.norm() > kTurningPace &&
                       std::abs(turn_rate) > kTurningRate;
  const EffectiveProfile& shot = problem_->effective();
  auto ideal_turning = [&](double ahead) -> Eigen::Vector3d {
    const double w = turn_rate * M_PI / 180.0;  // rad/s, not 0 (turning)
    const double a = std::clamp(w * ahead, -M_PI, M_PI);
    // Her velocity turned by w t integrates to `along` it and `across` it, across being the
    // velocity turned a quarter turn the way yaw turns (turned() in motion_prediction.cc).
    const double along = std::sin(a) / w, across = (1 - std::cos(a)) / w;
    const Eigen::Vector3d side(pace.z(), 0, -pace.x());
    CharacterState then = her;
    then.position = her.position + along * pace + across * side;
    then.yaw = her.yaw + a * 180.0 / M_PI;
    return ideal_camera_position(then, shot.desired_height, shot.desired_distance,
                                 shot.desired_orientation);
  };
  // Where candidate i's goal is `ahead` seconds from now (the target keeps moving), and
  // how fast it moves then; the smooth stop comes to rest ahead of the camera.
  auto goal_of = [&](int i, double ahead) -> Eigen::Vector3d {
    if (i == kStop) return now.position + 0.5 * plan_seconds_ * now.velocity;
    if (i == kTrail) return *waypoint + ahead * trail_velocity;  // on along her path
    if (i == kChase) return *chase + ahead * chase_velocity;
    if (i == kIdeal) return turning ? ideal_turning(ahead) : ideal + ahead * ideal_velocity_;
    return target + offsets[static_cast<std::size_t>(i)] + ahead * target_velocity;
  };
  auto velocity_of = [&](int i, double at) -> Eigen::Vector3d {
    if (i == kTrail) return trail_velocity;
    if (i == kChase) return chase_velocity;
    if (i == kIdeal) {
      if (!turning) return ideal_velocity_;
      constexpr double e = 1e-3;  // s: the shot's velocity by central differences
      return Eigen::Vector3d((ideal_turning(at + e) - ideal_turning(at - e)) / (2 * e));
    }
    return i == kStop ? Eigen::Vector3d::Zero() : target_velocity;
  };
  const csp::Problem& problem = problem_->problem();
  const SceneAtTime& geometry_now = problem_->scene_at_time();
  const MotionPrediction& prediction = problem_->prediction();
  const double radius = problem_->profile().clearance_radius;
  const double sight_weight =
      prediction.size() > 0 ? problem_->profile().anticipation.weight / prediction.total_weight()
                            : 0.0;
  const double reach = max_speed_ * dt * (1 + 1e-9);

  // Terms without queries, for every candidate.
  std::array<double, kCandidates> cheap{};
  std::array<int, kCandidates> order{};
  std::array<double, kCandidates> durations{};
  // Candidate i's trajectory, once its duration is set: from the camera's state to its goal
  // there, arriving at the goal's velocity.
  auto trajectory = [&](int i) {
    const double at = durations[static_cast<std::size_t>(i)];
    return Quintic(now, goal_of(i, at), velocity_of(i, at), at);
  };
  for (int i = 0; i < kCandidates; ++i) {
    order[static_cast<std::size_t>(i)] = i;
    const auto u = static_cast<std::size_t>(i);
    // A duplicate of the target (previous choice was the target itself) is skipped.
    if ((i == 1 && previous_offset_.squaredNorm() < 1e-12) || (i == kTrail && !waypoint) ||
        (i == kChase && !chase) || (i == kIdeal && !ideal_open)) {
      cheap[u] = std::numeric_limits<double>::infinity();
      continue;
    }
    const Eigen::Vector3d goal = goal_of(i, plan_seconds_);
    // Long enough that a minimum-jerk move this long keeps under the speed and acceleration
    // bounds (its peaks are 1.875 d / T and 5.77 d / T^2), with 10% to spare.
    const double d = (goal - now.position).norm();
    durations[u] = std::max({plan_seconds_, 1.875 * d / (0.9 * max_speed_),
                             std::sqrt(5.77 * d / (0.9 * max_acceleration_))});
    const Quintic q = trajectory(i);
    const double jerk = (q.acceleration(dt) - now.acceleration).norm() / dt;
    // Framing is priced where the goal is now, against this frame's character; the trail's
    // where it leads, the ideal shot behind her (its waypoint is a way, not a shot).
    const Eigen::Vector3d here = i == kTrail ? ideal : goal_of(i, 0);
    const double values[3] = {here.x(), here.y(), here.z()};
    double framing = 0;
    for (csp::ConstraintId id : framing_ids_) {
      const csp::Constraint& c = problem.constraint(id);
      if (!c.is_hard()) framing += c.weight() * c.violation(std::span<const double>(values, 3));
    }
    const Eigen::Vector3d offset =
        i == kStop || i == kTrail ? Eigen::Vector3d(here - target) : offsets[u];
    cheap[u] = framing + kJerkPrice * jerk + kSwitchPrice * (offset - previous_offset_).norm();
  }
  // Ties (a duplicate of the previous choice, mirror offsets) go to the lower index, so the
  // choice never depends on how the sort orders equal keys.
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    const double ca = cheap[static_cast<std::size_t>(a)], cb = cheap[static_cast<std::size_t>(b)];
    return ca < cb || (ca == cb && a < b);
  });

  double best_cost = std::numeric_limits<double>::infinity();
  std::optional<State> best;
  bool at_stake = false;  // the chosen plan loses a predicted point or meets geometry
  for (int i : order) {
    const auto u = static_cast<std::size_t>(i);
    if (!(cheap[u] < best_cost)) break;  // sorted: nothing after can win either
    const Quintic q = trajectory(i);
    // The first frame must be a smooth, usable move.
    Eigen::Vector3d first = q.position(dt);
    Eigen::Vector3d first_velocity = q.velocity(dt);
    if ((first - now.position).norm() > reach) continue;
    if (!slide_out(geometry_now, radius, &first, &first_velocity) ||
        (first - now.position).norm() > reach) continue;
    if (!geometry_now.line_of_sight(first, look)) continue;
    if (!geometry_now.line_of_sight(now.position, first)) continue;
    // Sight and room along the rest, at the prediction's times, cheapest-first cut-off.
    double cost = cheap[u];
    // Room over the next few frames, where the camera's momentum decides: a trajectory
    // that runs into a wall there leaves next frame's plans no usable first frame.
    // And sight there, of the look-at point on its way to the first predicted one (a
    // sight line the character's next steps will cut is lost before any frame can react).
    //
    // Priced in two passes, to the same cost: first every sight line (rays) with the
    // clearance checks not yet known (counted clear), a lower bound of the cost (sums of
    // non-negative terms in floating point are monotone), so a trajectory that loses on its
    // sight lines alone never asks clearance (a point query and, on a level, the map's solid
    // volume: about three rays' time); then, for one that may still win, the cost summed in
    // the order the checks come along the trajectory, clearance asked where the path is
    // clear and only while the sum is below the best's.
    constexpr int kNear = 3;
    constexpr int kNearFrames[kNear] = {2, 4, 8};
    std::array<Eigen::Vector3d, kNear> near_x;
    std::array<bool, kNear> near_path{}, near_soon{}, near_has_soon{};
    const int samples = prediction.size();
    std::array<Eigen::Vector3d, Anticipation::kMaxSamples> xs;
    std::array<bool, Anticipation::kMaxSamples> sees{}, path_clear{};
    int known = 0;  // checks (near frames, then samples) whose sight lines are known
    double at_least = cost;
    for (; known < kNear + samples && at_least < best_cost; ++known) {
      if (known < kNear) {
        const auto j = static_cast<std::size_t>(known);
        const double t = kNearFrames[j] * dt;
        near_x[j] = q.position(t);
        near_path[j] = geometry_now.line_of_sight(known == 0 ? first : near_x[j - 1], near_x[j]);
        if (!near_path[j]) at_least += kBlockedPrice;
        near_has_soon[j] = prediction.size() > 0 && t < prediction.sample(0).ahead;
        if (near_has_soon[j]) {
          const double w = t / prediction.sample(0).ahead;
          const Eigen::Vector3d soon = (1 - w) * look + w * prediction.sample(0).look_at;
          near_soon[j] = geometry_now.line_of_sight(near_x[j], soon);
          if (!near_soon[j]) at_least += kBlockedPrice;
        }
        continue;
      }
      const int sample = known - kNear;
      const auto k = static_cast<std::size_t>(sample);
      const MotionPrediction::Sample& s = prediction.sample(sample);
      const SceneAtTime& g = prediction.geometry(sample);
      xs[k] = q.position(std::max(s.ahead, dt));
      sees[k] = g.line_of_sight(xs[k], s.look_at);
      path_clear[k] = g.line_of_sight(sample == 0 ? near_x[kNear - 1] : xs[k - 1], xs[k]);
      double hidden = sees[k] ? 0.0 : 1.0;
      if (!path_clear[k]) {
        hidden += 1;
        at_least += kBlockedPrice * s.weight;
      }
      at_least += sight_weight * s.weight * hidden;
    }
    if (known < kNear + samples || !(at_least < best_cost)) {
      cost = at_least;  // lost: a lower bound of its cost already reaches the best's
    } else {
      for (int j = 0; j < kNear && cost < best_cost; ++j) {
        const auto v = static_cast<std::size_t>(j);
        if (!near_path[v] || !has_room(geometry_now, near_x[v], radius)) {
          cost += kBlockedPrice;
        }
        if (near_has_soon[v] && !near_soon[v]) cost += kBlockedPrice;
      }
      for (int k = 0; k < samples && cost < best_cost; ++k) {
        const auto v = static_cast<std::size_t>(k);
        const MotionPrediction::Sample& s = prediction.sample(k);
        double hidden = sees[v] ? 0.0 : 1.0;
        if (!path_clear[v] || !has_room(prediction.geometry(k), xs[v], radius)) {
          hidden += 1;
          cost += kBlockedPrice * s.weight;  // geometry is no guess: priced like the near frames
        }
        cost += sight_weight * s.weight * hidden;
      }
    }
    if (cost < best_cost) {
      best_cost = cost;
      best = State{first, first_velocity, q.acceleration(dt)};
      last_choice_ = i;
      at_stake = cost > cheap[u];
    }
  }
  if (best && max_jerk_ > 0 && !at_stake) {
    // The plan's first frame with its change of acceleration bounded by max_jerk x dt
    // (constant jerk over the frame), when nothing is at stake (the chosen plan keeps every
    // predicted point in sight and meets no geometry) and that frame is usable too:
    // re-planning every frame, a new cheapest candidate (the stop instead of the target,
    // say) would otherwise switch the acceleration at once, and the bound spreads the
    // switch over a few frames. With sight or room at stake the plan is followed as it is
    // (bounded there too, the camera lagged into more forced cuts and escapes: 27 -> 35
    // cuts on the level walks, oa_thor-walk3 jerk p99 99 -> 2,070 m/s^3).
    Eigen::Vector3d change = best->acceleration - now.acceleration;
    const double limit = max_jerk_ * dt;
    if (change.norm() > limit) {
      change *= limit / change.norm();
      const Eigen::Vector3d a1 = now.acceleration + change;
      State bounded{now.position + dt * now.velocity + dt * dt * (now.acceleration / 3 + a1 / 6),
                    now.velocity + 0.5 * dt * (now.acceleration + a1), a1};
      if ((bounded.position - now.position).norm() <= reach &&
          slide_out(geometry_now, radius, &bounded.position, &bounded.velocity) &&
          (bounded.position - now.position).norm() <= reach &&
          geometry_now.line_of_sight(bounded.position, look) &&
          geometry_now.line_of_sight(now.position, bounded.position)) {
        best = bounded;
      }
    }
  }
  if (!best) {
    // No usable first frame. Would any candidate, its first frame aside, see the first
    // predicted look-at point from where it is then (clear of geometry)? The controller's
    // cuts.cut_ahead asks (regains_sight()).
    regains_sight_ = prediction.size() == 0;
    for (int i = 0; i < kCandidates && !regains_sight_; ++i) {
      const auto u = static_cast<std::size_t>(i);
      if (!std::isfinite(cheap[u])) continue;
      const MotionPrediction::Sample& first = prediction.sample(0);
      const SceneAtTime& g = prediction.geometry(0);
      const Quintic q = trajectory(i);
      const Eigen::Vector3d x = q.position(std::max(first.ahead, dt));
      regains_sight_ = has_room(g, x, radius) && g.line_of_sight(x, first.look_at);
    }
  }
  if (best) {
    if (last_choice_ == kStop) {
      // Kept as where the stop was heading, so leaving it is priced like any switch.
      previous_offset_ = goal_of(kStop, 0) - target;
    } else {
      previous_offset_ = offsets[static_cast<std::size_t>(last_choice_)];
    }
  }
  return best;
}

}  // namespace sightline::camera
