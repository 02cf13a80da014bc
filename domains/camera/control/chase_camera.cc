#include "sightline/domains/camera/control/chase_camera.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "sightline/domains/camera/control/camera_solvers.h"

namespace sightline::camera {

std::string ChaseCameraOptions::validate() const {
  auto positive = [](double v) { return std::isfinite(v) && v > 0; };
  if (!positive(max_speed)) return "max_speed must be > 0 (m/s)";
  if (!positive(max_acceleration)) return "max_acceleration must be > 0 (m/s^2)";
  if (!positive(escape_speed)) return "escape_speed must be > 0 (m/s)";
  if (!positive(response_time)) return "response_time must be > 0 (s)";
  if (!(target_smoothing >= 0) || !std::isfinite(target_smoothing)) {
    return "target_smoothing must be >= 0 (s)";
  }
  if (target_smoothing_stages < 1 || target_smoothing_stages > kMaxSmoothingStages) {
    return "target_smoothing_stages must be 1 to " + std::to_string(kMaxSmoothingStages) +
           ", got " + std::to_string(target_smoothing_stages);
  }
  if (!(min_shot_seconds >= 0) || !std::isfinite(min_shot_seconds)) {
    return "min_shot_seconds must be >= 0 (s)";
  }
  if (!positive(stuck_seconds)) return "stuck_seconds must be > 0 (s)";
  if (!(backing_speed >= 0) || !std::isfinite(backing_speed)) return "backing_speed must be >= 0";
  return "";
}

ChaseCamera::ChaseCamera(const Scene& scene, const CameraProfile& profile,
                         ChaseCameraOptions options)
    : scene_(&scene), options_(std::move(options)), problem_(scene, profile) {
  if (std::string why = options_.validate(); !why.empty()) {
    throw std::invalid_argument("chase camera: " + why);
  }
  solver_ = solver_registry().create(options_.solver, options_.solver_options);
  if (std::string why = solver_->unsuitable_reason(problem_.problem()); !why.empty()) {
    throw std::invalid_argument("solver '" + options_.solver + "' cannot drive the camera: " + why);
  }
  context_.want_breakdown = false;
  // The escape's pricing: constraints that ask the geometry last (see smooth_escape).
  const CameraProblem::ConstraintIds& ids = problem_.ids();
  for (csp::ConstraintId id = 0; id < problem_.problem().num_constraints(); ++id) {
    if (id == ids.look_at || id == ids.clearance) continue;  // 0 for every usable move
    const bool sighted = id == ids.visible_fraction || id == ids.future_visible;
    (sighted ? sighted_ids_ : cheap_ids_).push_back(id);
  }
  if (profile.anticipation.plan_seconds > 0) {
    std::vector<csp::ConstraintId> framing;
    for (csp::ConstraintId id : cheap_ids_) {
      if (id != ids.frame_coherence) framing.push_back(id);
    }
    planner_.emplace(problem_, std::move(framing), options_.max_speed,
                     options_.max_acceleration, profile.anticipation.plan_seconds,
                     profile.anticipation.max_jerk);
  }
  reset(scene.start_camera_position());
}

ChaseCamera::~ChaseCamera() = default;

void ChaseCamera::reset(const Eigen::Vector3d& position) {
  position_ = position;
  velocity_.setZero();
  acceleration_.setZero();
  followed_velocity_.setZero();
  last_followed_ = position;
  if (planner_) planner_->reset();
  set_filtered_target(position);
  since_cut_ = 1e9;
  stuck_for_ = 0;
  cuts_made_ = 0;
  frame_.position = position;
}

bool ChaseCamera::clear(const Eigen::Vector3d& p) const {
  const double r = problem_.profile().clearance_radius;
  return !problem_.scene_at_time().closer_than(p, r, r + 1e-6);  // clearance >= r
}

bool ChaseCamera::sees(const Eigen::Vector3d& p, const Eigen::Vector3d& look) const {
  return problem_.scene_at_time().line_of_sight(p, look);
}

Eigen::Vector3d ChaseCamera::solve_from_here() {
  context_.seed = options_.seed + frames_;
  const double start[3] = {position_.x(), position_.y(), position_.z()};
  solver_->solve_into(problem_.problem(), start, context_, result_);
  return {result_.best[0], result_.best[1], result_.best[2]};
}

Eigen::Vector3d ChaseCamera::solve_for_new_shot(const CharacterState& character, double dt,
                                                const Eigen::Vector3d& look) {
  // A new shot is searched around the profile's ideal position (or, when that is unusable,
  // around the look-at point), as if the camera were already there: frame coherence must not
  // pull a cut back toward the old shot.
  Eigen::Vector3d centre = problem_.ideal_position();
  if (!usable(centre, look)) centre = look;
  problem_.set_frame(character, centre, dt);
  const EffectiveProfile& e = problem_.effective();
  problem_.set_search_box(centre, std::max(problem_.profile().search_half_size,
                                           0.5 * std::hypot(e.desired_distance, e.desired_height)));
  context_.seed = options_.seed + frames_;
  const double start[3] = {centre.x(), centre.y(), centre.z()};
  solver_->solve_into(problem_.problem(), start, context_, result_);
  const Eigen::Vector3d found(result_.best[0], result_.best[1], result_.best[2]);
  // Back to this frame's real parameters (last camera = where the camera is).
  problem_.set_frame(character, position_, dt);
  return found;
}

Eigen::Vector3d ChaseCamera::smooth_step(const Eigen::Vector3d& target, double dt,
                                         Eigen::Vector3d* velocity) const {
  // A critically damped spring (omega = 2 / response_time), with bounded acceleration and
  // speed, integrated semi-implicitly:
  //   a = omega^2 (target - p) - 2 omega v,  |a| <= max_acceleration
  //   v' = v + a dt,  |v'| <= max_speed,      p' = p + v' dt
  // Velocity stays continuous, so the camera eases in and out instead of jerking.
  const double omega = 2.0 / options_.response_time;
  Eigen::Vector3d a = omega * omega * (target - position_) - 2 * omega * velocity_;
  if (a.norm() > options_.max_acceleration) a *= options_.max_acceleration / a.norm();
  Eigen::Vector3d v = velocity_ + a * dt;
  if (v.norm() > options_.max_speed) v *= options_.max_speed / v.norm();
  *velocity = v;
  return position_ + v * dt;
}

void ChaseCamera::cut_to(const Eigen::Vector3d& p, CutReason reason) {
  position_ = p;
  velocity_.setZero();
  acceleration_.setZero();
  followed_velocity_.setZero();
  last_followed_ = p;
  if (planner_) planner_->reset();
  set_filtered_target(p);
  since_cut_ = 0;
  stuck_for_ = 0;
  frame_.cut = true;
  frame_.cut_reason = reason;
  note_cut(now_);
}

bool ChaseCamera::backed_up(const CharacterState& character, const Eigen::Vector3d& look) const {
  // Backing up: moving against the facing. Into an obstruction: the spot right behind the
  // character where the profile wants the camera cannot hold it (blocked or in a wall).
  if (character.velocity.dot(character.facing()) > -options_.backing_speed) return false;
  const Eigen::Vector3d ideal = problem_.ideal_position();
  return !usable(ideal, look);
}

int ChaseCamera::hidden_ahead(const Eigen::Vector3d& p, bool* by_mover) const {
  const MotionPrediction& prediction = problem_.prediction();
  int hidden = 0;
  for (int k = 0; k < prediction.size(); ++k) {
    const SceneAtTime& g = prediction.geometry(k);
    const Eigen::Vector3d& l = prediction.sample(k).look_at;
    if (g.line_of_sight(p, l)) continue;
    ++hidden;
    if (by_mover && g.mover_blocks(p, l)) *by_mover = true;
  }
  return hidden;
}

bool ChaseCamera::shut_out(const Eigen::Vector3d& p, bool by_mover_only) const {
  bool by_mover = false;
  const int hidden = hidden_ahead(p, by_mover_only ? &by_mover : nullptr);
  return 2 * hidden > problem_.prediction().size() && (by_mover || !by_mover_only);
}

std::optional<Eigen::Vector3d> ChaseCamera::smooth_escape(const Eigen::Vector3d& look,
                                                           const Eigen::Vector3d& step,
                                                           double dt) const {
  const Eigen::Vector3d up = Eigen::Vector3d::UnitY();
  Eigen::Vector3d toward = look - position_;
  toward.y() = 0;
  if (toward.norm() < 1e-9) toward = Eigen::Vector3d::UnitX();
  toward.normalize();
  const Eigen::Vector3d side(toward.z(), 0, -toward.x());  // horizontal, across the view
  const Eigen::Vector3d directions[] = {
      up, -up, toward, -toward, side, -side, (up + toward).normalized(),
      (up + side).normalized(), (up - side).normalized(), (toward + side).normalized(),
      (toward - side).normalized()};
  // Each move is priced at this frame's soft cost (a usable move breaks no hard constraint)
  // plus kVelocityChangeCost per m/s of change in the camera's velocity, so among usable
  // moves the one closest to the spring's step (the smoothest) wins unless another is
  // clearly better placed. Staying is priced the same way when it is usable, and a move
  // must beat it. The constraints without sight lines are summed first, so most moves are
  // dropped before any query. After an escape the low-passed target is kept: the spring
  // goes on toward the solver's target (restarting it from the camera's position raised
  // jerk p99 on most thesis scenes: grand-tour 2,721 m/s^3 against 581). The moves reach
  // escape_speed x dt; only when none of them is usable (nor staying), max_speed x dt.
  constexpr double kVelocityChangeCost = 0.1;
  double escape_step = std::min(options_.max_speed, options_.escape_speed) * dt;
  double reach = escape_step * (1 + 1e-9);
  const csp::Problem& problem = problem_.problem();
  auto soft_cost = [&](const std::vector<csp::ConstraintId>& ids, const double* values) {
    double sum = 0;
    for (csp::ConstraintId id : ids) {
      const csp::Constraint& c = problem.constraint(id);
      if (!c.is_hard()) sum += c.weight() * c.violation(std::span<const double>(values, 3));
    }
    return sum;
  };
  std::optional<Eigen::Vector3d> best;
  double best_cost = std::numeric_limits<double>::infinity();
  auto consider = [&](const Eigen::Vector3d& next, bool staying) {
    if ((next - position_).norm() > reach) return;
    const double values[3] = {next.x(), next.y(), next.z()};
    double cost = soft_cost(cheap_ids_, values) +
                  kVelocityChangeCost * ((next - position_) / dt - velocity_).norm();
    if (cost >= best_cost) return;
    if (!usable(next, look) || (!staying && !sees(position_, next))) return;
    cost += soft_cost(sighted_ids_, values);
    if (cost < best_cost) {
      best_cost = cost;
      best = staying ? std::nullopt : std::optional<Eigen::Vector3d>(next);
    }
  };
  consider(position_, true);
  auto around = [&] {
    for (const Eigen::Vector3d& centre : {step, position_}) {
      for (double length : {0.125, 0.25, 0.5, 1.0}) {
        for (const Eigen::Vector3d& d : directions) {
          consider(centre + length * escape_step * d, false);
        }
      }
    }
  };
  around();
  for (double fraction : {0.75, 0.5, 0.25}) {
    consider(position_ + fraction * (step - position_), false);
  }
  if (!std::isfinite(best_cost) && escape_step < max_step(dt)) {
    // Nothing usable within escape_speed, staying included: the same moves up to max_speed
    // rather than a forced cut (escapes this long everywhere made jerk p99 on the level
    // walks and families worse than the thesis camera's on 7 walks instead of 4; none at
    // all cut 7 more times on the level walks).
    escape_step = max_step(dt);
    reach = escape_step * (1 + 1e-9);
    around();
  }
  return best;
}

double ChaseCamera::shot_cost(const Eigen::Vector3d& p) const {
  // A cut pays no frame coherence: the shot is priced on framing and sight alone.
  const csp::Problem& problem = problem_.problem();
  const double values[3] = {p.x(), p.y(), p.z()};
  double sum = 0;
  for (const auto* ids : {&cheap_ids_, &sighted_ids_}) {
    for (csp::ConstraintId id : *ids) {
      if (id == problem_.ids().frame_coherence) continue;
      const csp::Constraint& c = problem.constraint(id);
      if (!c.is_hard()) sum += c.weight() * c.violation(std::span<const double>(values, 3));
    }
  }
  return sum;
}

std::optional<Eigen::Vector3d> ChaseCamera::close_in(const Eigen::Vector3d& look,
                                                      bool ahead) const {
  // Rings around the look-at point, nearest first, from behind the character (toward the
  // camera) round to the front, at and above the look-at height: the first usable one.
  Eigen::Vector3d back = position_ - look;
  back.y() = 0;
  if (back.norm() < 1e-9) back = Eigen::Vector3d::UnitZ();
  back.normalize();
  const Eigen::Vector3d side(back.z(), 0, -back.x());
  for (double distance : {1.0, 1.5, 2.0, 3.0}) {
    for (double rise : {0.5, 1.0, 0.0, 2.0}) {
      for (int k = 0; k < 8; ++k) {
        const double a = (k % 2 == 0 ? 1 : -1) * ((k + 1) / 2) * 0.25 * 3.14159265358979;
        const Eigen::Vector3d dir = std::cos(a) * back + std::sin(a) * side;
        const Eigen::Vector3d p = look + distance * dir + Eigen::Vector3d(0, rise, 0);
        if (usable(p, look) && !(ahead && shut_out(p, false))) return p;
      }
    }
  }
  return std::nullopt;
}

// One frame, as its steps: re-parameterise the problem (which also predicts the character's
// motion), take a discretionary cut if one is due, otherwise solve for a target and move
// toward it (planned, stepped, escaping or staying) or cut, then flag any long move as a cut
// and record the frame.
const CameraFrame& ChaseCamera::update(const CharacterState& character, double dt) {
  const auto started = std::chrono::steady_clock::now();
  if (!(dt > 0) || !std::isfinite(dt)) throw std::invalid_argument("update needs dt > 0");
  frame_.cut = false;
  frame_.cut_reason = CutReason::kNone;
  since_cut_ += dt;
  now_ = character.t;

  const AreaTransition transition = problem_.set_frame(character, position_, dt);
  const Eigen::Vector3d look = scene_->character().look_at(character.position);
  const FrameContext frame{character, dt, look,
                           since_cut_ >= options_.min_shot_seconds && frames_ > 0};
  Eigen::Vector3d target;
  if (const std::optional<CutReason> reason = discretionary_cut(frame, transition)) {
    target = solve_for_new_shot(character, dt, look);
    cut_to(target, *reason);
  } else {
    target = solve_target(frame);
    move_or_cut(frame, target);
  }
  // A move longer than smooth motion allows is a cut, and flagged as one.
  if (!frame_.cut && (position_ - frame_.position).norm() > max_step(dt) * (1 + 1e-9)) {
    cut_to(position_, CutReason::kVisibilityLost);
  }
  record_frame(look, target, started);
  return frame_;
}

// Discretionary cuts (thesis table 9): leaving an enclosed area for the outside, and backing
// up into an obstruction (once per episode); each only if the profile's cut policy allows it
// and the shot is old enough.
std::optional<CutReason> ChaseCamera::discretionary_cut(const FrameContext& frame,
                                                        const AreaTransition& transition) {
  const CutPolicy& policy = problem_.profile().cuts;
  bool left_enclosed = false;
  if (policy.leave_enclosed && transition.left &&
      scene_->areas()[*transition.left].kind == AreaKind::kEnclosed) {
    const auto& now = problem_.effective().area;
    left_enclosed = !now || scene_->areas()[*now].kind != AreaKind::kEnclosed;
  }
  const bool backing = policy.backing_up && backed_up(frame.character, frame.look);
  const bool backing_started = backing && !was_backed_up_;
  was_backed_up_ = backing;
  if (!frame.may_cut || !(left_enclosed || backing_started)) return std::nullopt;
  return left_enclosed ? CutReason::kLeftEnclosedArea : CutReason::kBackedUpToObstacle;
}

// The solver's target near the camera; when it is unusable, the solver asked once more
// around the ideal position. (Bourne's octree ignores visibility and may still fail; that
// is the point.)
Eigen::Vector3d ChaseCamera::solve_target(const FrameContext& frame) {
  Eigen::Vector3d target = solve_from_here();
  if (options_.visibility_guard && !usable(target, frame.look)) {
    const Eigen::Vector3d other = solve_for_new_shot(frame.character, frame.dt, frame.look);
    if (usable(other, frame.look)) target = other;
  }
  return target;
}

// The solver's target moves a little every frame; the spring follows a low-passed copy,
// and the planner also its velocity, low-passed alike.
const Eigen::Vector3d& ChaseCamera::low_pass(const Eigen::Vector3d& target, double dt) {
  const double keep =
      options_.target_smoothing > 0 ? std::exp(-dt / options_.target_smoothing) : 0.0;
  const auto stages = static_cast<std::size_t>(options_.target_smoothing_stages);
  for (std::size_t i = 0; i < stages; ++i) {
    const Eigen::Vector3d& input = i == 0 ? target : filtered_target_[i - 1];
    filtered_target_[i] = keep * filtered_target_[i] + (1 - keep) * input;
  }
  const Eigen::Vector3d& followed = filtered_target_[stages - 1];
  followed_velocity_ = keep * followed_velocity_ + (1 - keep) * (followed - last_followed_) / dt;
  last_followed_ = followed;
  return followed;
}

// The planner's first frame toward the followed target, taken when it has one.
bool ChaseCamera::follow_plan(const Eigen::Vector3d& followed, const Eigen::Vector3d& look,
                              double dt) {
  const HorizonPlanner::State now{position_, velocity_, acceleration_};
  const auto planned = planner_->plan(now, followed, followed_velocity_, look, dt);
  if (!planned) return false;
  position_ = planned->position;
  velocity_ = planned->velocity;
  acceleration_ = planned->acceleration;
  return true;
}

// cuts.cut_ahead: no planned trajectory keeps the look-at point in sight this frame, and a
// mover will hide it from where the camera is for most of the horizon (a door shutting, a
// bus, not a passer-by). Escapes (velocity jumps, each buying a frame) would only delay the
// forced cut: it comes now, to a shot that keeps the predicted points. Sets `target` to
// that shot and returns true, or returns false when the rule does not apply or no such shot
// exists (then the frame goes on as without the option).
bool ChaseCamera::cut_ahead_shot(const FrameContext& frame, Eigen::Vector3d& target) {
  if (problem_.prediction().size() == 0 || planner_->regains_sight() || !shut_out(position_, true)) {
    return false;
  }
  std::optional<Eigen::Vector3d> shot;
  if (usable(target, frame.look) && !shut_out(target, false)) shot = target;
  if (!shot) {
    const Eigen::Vector3d other = solve_for_new_shot(frame.character, frame.dt, frame.look);
    if (usable(other, frame.look) && !shut_out(other, false)) shot = other;
  }
  if (!shot) shot = close_in(frame.look, true);
  if (!shot) return false;
  target = *shot;
  return true;
}

// The spring's step, or a half or a quarter of it (not with smooth_escape, whose moves
// include the shorter steps), if it keeps the look-at point visible and crosses nothing.
bool ChaseCamera::take_step(const Eigen::Vector3d& step, const Eigen::Vector3d& velocity,
                            const Eigen::Vector3d& look, bool escapes) {
  const bool guard = options_.visibility_guard;
  for (double fraction : {1.0, 0.5, 0.25}) {
    if (escapes && fraction < 1) break;
    const Eigen::Vector3d next = position_ + fraction * (step - position_);
    if (!guard || (usable(next, look) && sees(position_, next))) {
      velocity_ = fraction * velocity;
      position_ = next;
      return true;
    }
  }
  return false;
}

// Smooth motion if a planned or stepped move keeps the character visible and crosses no
// geometry; else an escape move; else stay (cutting when stuck too long), or cut when
// staying loses sight too.
void ChaseCamera::move_or_cut(const FrameContext& frame, Eigen::Vector3d& target) {
  const CutPolicy& policy = problem_.profile().cuts;
  const Eigen::Vector3d& look = frame.look;
  const double dt = frame.dt;
  const Eigen::Vector3d& followed = low_pass(target, dt);
  const Eigen::Vector3d last_velocity = velocity_;
  Eigen::Vector3d velocity;
  const Eigen::Vector3d step = smooth_step(followed, dt, &velocity);
  const bool guard = options_.visibility_guard;
  const bool escapes = guard && policy.smooth_escape;
  const bool planned_move = guard && planner_ && follow_plan(followed, look, dt);
  bool moved = planned_move;
  const bool cut_ahead = guard && planner_ && !moved && escapes && policy.cut_ahead &&
                         cut_ahead_shot(frame, target);
  if (!moved && !cut_ahead) moved = take_step(step, velocity, look, escapes);
  const std::optional<Eigen::Vector3d> escape =
      !moved && escapes && !cut_ahead ? smooth_escape(look, step, dt) : std::nullopt;
  if (planned_move) {
    check_left_behind(frame, target);
  } else if (moved) {
    stuck_for_ = 0;
  } else if (cut_ahead) {
    cut_to(target, CutReason::kVisibilityLost);
  } else if (escape) {
    velocity_ = (*escape - position_) / dt;
    position_ = *escape;
    stuck_for_ = 0;
  } else if (usable(position_, look)) {
    stay(frame, target);
  } else {
    forced_cut(frame, escapes, target);
  }
  // A frame without a plan restarts the left-behind measure; the planner starts from the
  // acceleration the camera really had (spring, escape, stop).
  if (!planned_move) last_off_ideal_ = std::numeric_limits<double>::infinity();
  if (planner_ && !frame_.cut && !planned_move) {
    acceleration_ = (velocity_ - last_velocity) / dt;
    const double a = acceleration_.norm();
    if (a > options_.max_acceleration) acceleration_ *= options_.max_acceleration / a;
  }
}

// After a planned move. A planned move always exists while some trajectory is usable, so
// "blocked" is not what strands this camera: being left behind is. It makes no progress
// while it is farther from the ideal position than the solver can see (the search cube's
// half-size) and not getting nearer; past the patience below, if the policy allows, it cuts
// to a new shot searched around the ideal position. Only when the ideal position itself is
// usable: with the ideal inside a wall (the character backed up to it) the camera is where
// it can be, not left behind.
void ChaseCamera::check_left_behind(const FrameContext& frame, Eigen::Vector3d& target) {
  const Eigen::Vector3d ideal = problem_.ideal_position();
  const double off = (position_ - ideal).norm();
  const bool progress = off <= problem_.profile().search_half_size || off < last_off_ideal_ ||
                        !usable(ideal, frame.look);
  last_off_ideal_ = off;
  stuck_for_ = progress ? 0 : stuck_for_ + frame.dt;
  // Left behind for longer than the plan looks ahead: no plan will bring it back.
  const double patience =
      std::max(options_.stuck_seconds, problem_.profile().anticipation.horizon);
  if (problem_.profile().cuts.stuck && stuck_for_ >= patience && frame.may_cut &&
      stuck_cut_allowed(frame.character.t)) {
    const Eigen::Vector3d shot = solve_for_new_shot(frame.character, frame.dt, frame.look);
    if (usable(shot, frame.look) && (shot - position_).norm() > max_step(frame.dt)) {
      target = shot;
      cut_to(shot, CutReason::kStuck);
    }
  }
}

// cuts.stuck_per_minute: fewer cuts (of any reason) than the limit in the last 60 s.
bool ChaseCamera::stuck_cut_allowed(double t) const {
  const int limit = problem_.profile().cuts.stuck_per_minute;
  if (limit <= 0) return true;
  const std::size_t kept = std::min<std::size_t>(cuts_made_, cut_times_.size());
  int recent = 0;
  for (std::size_t i = 0; i < kept; ++i) recent += t - cut_times_[i] < 60.0 ? 1 : 0;
  return recent < limit;
}

void ChaseCamera::note_cut(double t) {
  cut_times_[cuts_made_ % cut_times_.size()] = t;
  ++cuts_made_;
}

// Blocked but still seeing the character: stay, and cut to the target when stuck for
// stuck_seconds (if the policy allows and the shot is old enough).
void ChaseCamera::stay(const FrameContext& frame, const Eigen::Vector3d& target) {
  velocity_.setZero();
  set_filtered_target(position_);
  stuck_for_ += frame.dt;
  if (problem_.profile().cuts.stuck && stuck_for_ >= options_.stuck_seconds && frame.may_cut &&
      stuck_cut_allowed(frame.character.t) && usable(target, frame.look) &&
      (target - position_).norm() > max_step(frame.dt)) {
    cut_to(target, CutReason::kStuck);
  }
}

// No smooth move keeps the character visible: cut, whatever the shot's age. The escape
// profiles also search a new shot around the ideal position, as the stuck cut does, and cut
// to the better framed of the two (framing and sight, no frame coherence: see shot_cost):
// the solver's target near the old camera, left behind, is a jump of a metre or two that
// the next frames lose again (a character running round corners faster than the camera can
// follow: a cut every frame or two). When neither is usable (a vehicle right between camera
// and character), they look close in.
void ChaseCamera::forced_cut(const FrameContext& frame, bool escapes, Eigen::Vector3d& target) {
  const Eigen::Vector3d& look = frame.look;
  if (escapes) {
    const Eigen::Vector3d shot = solve_for_new_shot(frame.character, frame.dt, look);
    if (usable(shot, look) && (!usable(target, look) || shot_cost(shot) < shot_cost(target))) {
      target = shot;
    } else if (!usable(target, look)) {
      if (const auto close = close_in(look)) target = *close;
    }
  }
  cut_to(target, CutReason::kVisibilityLost);
}

void ChaseCamera::record_frame(const Eigen::Vector3d& look, const Eigen::Vector3d& target,
                               std::chrono::steady_clock::time_point started) {
  ++frames_;
  frame_.position = position_;
  frame_.target = look;
  frame_.solver_target = target;
  const double values[3] = {position_.x(), position_.y(), position_.z()};
  frame_.score = problem_.problem().score(values);
  frame_.look_at_visible = sees(position_, look);
  frame_.effective = problem_.effective();
  frame_.solve_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
}

}  // namespace sightline::camera
