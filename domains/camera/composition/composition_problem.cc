#include "sightline/domains/camera/composition/composition_problem.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "sightline/csp/input_error.h"
#include "sightline/csp/json_text.h"
#include "sightline/domains/camera/trajectory.h"

namespace sightline::camera {
namespace {

constexpr double kDegrees = 180.0 / 3.14159265358979323846;
constexpr double kClearanceProbe = 10;  // metres: how far evaluate() looks for the nearest solid

// The fewest samples k whose fraction k / 27, as the `visible` measure computes it, reaches
// the property's lo when its range reaches 1 (then seeing k makes it score 1); 0 otherwise.
int visible_at_once(const ShotPropertyKind& kind, const ShotProperty& property) {
  const ValueRange& range = property.range;
  if (kind.name != "visible" || range.hi < 1 || !(range.lo > 0) || range.lo > 1) return 0;
  int k = 1;
  while (static_cast<double>(k) / kPersonSamples < range.lo) ++k;
  return k;
}

// A property's score at a view in `world`; a `visible` one with `at_once` > 0 stops casting
// sight lines once that many samples are seen (the same score, fewer rays).
double property_score(const ShotPropertyKind& kind, const ShotProperty& property, int at_once,
                      const View& view, const ShotWorld& world, const int* targets) {
  if (at_once > 0) {
    const int clear = world.count_clear(view.position(), targets[0], at_once);
    if (clear == at_once) return 1.0;
    return satisfaction(static_cast<double>(clear) / kPersonSamples, property.range, property.softness,
                        kind.circular);
  }
  return satisfaction(kind.measure(property, MeasureContext{view, world, targets}), property.range,
                      property.softness, kind.circular);
}

}  // namespace

CompositionProblem::CompositionProblem(const Scene& scene, const Shot& shot, double t,
                                       Foresight foresight)
    : shot_(&shot),
      world_(std::make_unique<ShotWorld>(scene, t)),
      foresight_(std::move(foresight)),
      problem_(std::make_unique<csp::Problem>("shot: " + scene.name())) {
  csp::Problem& p = *problem_;
  const Aabb& r = shot.region;
  p.add_variable("cam_x", csp::Domain::real_interval(r.min.x(), r.max.x()));
  p.add_variable("cam_y", csp::Domain::real_interval(r.min.y(), r.max.y()));
  p.add_variable("cam_z", csp::Domain::real_interval(r.min.z(), r.max.z()));
  p.add_variable("yaw", csp::Domain::real_interval(-180, 180));
  p.add_variable("pitch", csp::Domain::real_interval(-89, 89));
  p.add_variable("fov", csp::Domain::real_interval(shot.fov.lo, shot.fov.hi));
  p.add_variable("roll", csp::Domain::real_interval(shot.roll.lo, shot.roll.hi));
  targets_.reserve(shot.properties.size());
  for (const ShotProperty& property : shot.properties) {
    std::vector<int> ids;
    for (const std::string& name : property.targets) {
      const std::optional<int> id = world_->find(name);
      if (!id) {
        throw csp::InputError(property.where, "the shot's " + property.kind +
                                                  " property names '" + name +
                                                  "', who is not in the scene");
      }
      ids.push_back(*id);
    }
    targets_.push_back(std::move(ids));
  }
  for (std::size_t i = 0; i < shot.properties.size(); ++i) {
    const ShotProperty& p = shot.properties[i];
    if ((p.kind == "framed" || p.kind == "visible") && p.range.hi <= 0) continue;  // kept out
    for (int t : targets_[i]) {
      if (std::find(wanted_.begin(), wanted_.end(), t) == wanted_.end()) wanted_.push_back(t);
    }
  }
  if (wanted_.empty()) wanted_.push_back(targets_[0][0]);
  for (std::size_t i = 0; i < shot.properties.size(); ++i) {
    const ShotPropertyKind* kind = ShotPropertyKinds::global().find(shot.properties[i].kind);
    if (!kind) {
      throw csp::InputError(shot.properties[i].where,
                            "unknown shot property kind '" + shot.properties[i].kind + "'");
    }
    auto c = std::make_unique<ShotPropertyConstraint>(*this, i, *kind);
    c->set_label(shot.properties[i].describe());
    p.add_constraint(std::move(c));
  }
  auto clearance = std::make_unique<ShotClearanceConstraint>(*this);
  clearance->set_label("clearance");
  p.add_constraint(std::move(clearance));
  for (std::size_t h = 0; h < foresight_.horizons.size(); ++h) {
    if (!(foresight_.horizons[h] >= 0) || !(foresight_.weight > 0)) {
      throw std::invalid_argument("foresight horizons must be >= 0 and its weight > 0");
    }
    futures_.push_back(std::make_unique<ShotWorld>(scene, t));
    shifts_.push_back(Eigen::Vector3d::Zero());
    for (std::size_t i = 0; i < shot.properties.size(); ++i) {
      const ShotProperty& property = shot.properties[i];
      if ((property.kind != "framed" && property.kind != "visible") || property.range.hi <= 0) continue;
      auto c = std::make_unique<ShotForesightConstraint>(
          *this, i, *ShotPropertyKinds::global().find(property.kind), h);
      c->set_label(property.describe() + " in " + csp::json_number(foresight_.horizons[h]) + " s");
      p.add_constraint(std::move(c));
    }
  }
  set_time(t);
}

void CompositionProblem::set_time(double t, double lead) {
  world_->set_time(t, lead);
  for (std::size_t h = 0; h < futures_.size(); ++h) {
    futures_[h]->set_time(t, lead + foresight_.horizons[h]);
    Eigen::Vector3d shift = Eigen::Vector3d::Zero();
    for (int w : wanted_) {
      const auto i = static_cast<std::size_t>(w);
      shift += futures_[h]->people()[i].aim - world_->people()[i].aim;
    }
    shifts_[h] = shift / static_cast<double>(wanted_.size());
  }
}

CameraPose CompositionProblem::pose(std::span<const double> v) const {
  CameraPose pose;
  pose.position = Eigen::Vector3d(v[kX], v[kY], v[kZ]);
  pose.look_at = pose.position + direction_from_yaw_pitch(v[kYaw], v[kPitch]);
  pose.fov = v[kFov];
  pose.roll = v[kRoll];
  pose.aspect = shot_->aspect;
  return pose;
}

csp::Assignment CompositionProblem::assignment(const CameraPose& pose) const {
  const std::array<double, 7> a = pose_values(pose);
  return csp::Assignment(a.begin(), a.end());
}

std::array<double, 7> CompositionProblem::pose_values(const CameraPose& pose) const {
  const Eigen::Vector3d d = (pose.look_at - pose.position).normalized();
  std::array<double, 7> a{pose.position.x(), pose.position.y(), pose.position.z(),
                          std::atan2(d.x(), d.z()) * kDegrees,
                          std::asin(std::clamp(d.y(), -1.0, 1.0)) * kDegrees, pose.fov, pose.roll};
  for (csp::VariableId v = 0; v < 7; ++v) a[v] = problem_->domain(v).clamp(a[v]);
  return a;
}

ShotEvaluation CompositionProblem::evaluate(const CameraPose& pose) const {
  ShotEvaluation e;
  evaluate_into(pose, e);
  return e;
}

void CompositionProblem::evaluate_into(const CameraPose& pose, ShotEvaluation& e) const {
  const std::size_t n = shot_->properties.size();
  e.valid_pose = e.feasible = false;
  e.satisfaction = e.cost = e.clearance = 0;
  e.measures.assign(n, std::numeric_limits<double>::quiet_NaN());
  e.scores.assign(n, 0.0);
  e.why_infeasible.clear();
  const std::optional<View> view = View::of(pose);
  if (!view) {
    e.why_infeasible = "the pose has no view (its direction is vertical, or its lens is invalid)";
    return;
  }
  e.valid_pose = true;
  double weights = 0, weighted = 0;
  const ShotProperty* first_hard = nullptr;
  double first_hard_score = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const ShotProperty& property = shot_->properties[i];
    const ShotPropertyKind& kind = *ShotPropertyKinds::global().find(property.kind);
    const MeasureContext context{*view, *world_, targets_[i].data()};
    e.measures[i] = kind.measure(property, context);
    e.scores[i] = satisfaction(e.measures[i], property.range, property.softness, kind.circular);
    if (property.hard) {
      if (e.scores[i] < 1 && !first_hard) {
        first_hard = &property;
        first_hard_score = e.scores[i];
      }
    } else {
      weights += property.weight;
      weighted += property.weight * e.scores[i];
      e.cost += property.weight * (1 - e.scores[i]);
    }
  }
  e.satisfaction = weights > 0 ? weighted / weights : 1.0;
  e.clearance = world_->clearance(pose.position, kClearanceProbe);
  const Aabb& r = shot_->region;
  const auto in = [](double v, const ValueRange& range) { return v >= range.lo && v <= range.hi; };
  if (!r.contains(pose.position)) {
    e.why_infeasible = "the camera is outside the shot's region";
  } else if (e.clearance < shot_->clearance) {
    e.why_infeasible = "the camera is " + std::to_string(std::max(0.0, e.clearance)) +
                       " m from solid geometry or a person, nearer than the clearance";
  } else if (!in(pose.fov, shot_->fov)) {
    e.why_infeasible = "the field of view is outside the shot's";
  } else if (!in(pose.roll, shot_->roll)) {
    e.why_infeasible = "the roll is outside the shot's";
  } else if (std::abs(pose.aspect - shot_->aspect) > 1e-9) {
    e.why_infeasible = "the aspect is not the shot's";
  } else if (first_hard) {
    e.why_infeasible = "the hard property " + first_hard->describe() + " (line " +
                       std::to_string(first_hard->where.line) + ") scores " +
                       std::to_string(first_hard_score);
  }
  e.feasible = e.why_infeasible.empty();
}

const CompositionProblem* composition_of(const csp::Problem& problem) {
  for (csp::ConstraintId id = 0; id < problem.num_constraints(); ++id) {
    if (const auto* c = dynamic_cast<const ShotPropertyConstraint*>(&problem.constraint(id))) {
      return &c->owner();
    }
  }
  return nullptr;
}

void fill_frame(const CompositionProblem& problem, const CameraPose& pose, bool feasible,
                const Eigen::Vector3d& aimed_for, CameraFrame& frame) {
  frame.position = pose.position;
  frame.target = pose.look_at;
  frame.solver_target = aimed_for;
  frame.score = problem.problem().score(problem.pose_values(pose));
  frame.look_at_visible = feasible;
  frame.fov = pose.fov;
  frame.roll = pose.roll;
}

double arc_middle(const ValueRange& range) {
  const double hi = range.hi < range.lo ? range.hi + 360 : range.hi;
  return (range.lo + hi) / 2;
}

double signed_degrees(double a) { return wrap_degrees(a + 180.0) - 180.0; }

ShotPropertyConstraint::ShotPropertyConstraint(const CompositionProblem& owner, std::size_t index,
                                               const ShotPropertyKind& kind)
    : Constraint({0, 1, 2, 3, 4, 5, 6}, owner.shot().properties[index].weight,
                 owner.shot().properties[index].hard),
      owner_(&owner),
      property_(&owner.shot().properties[index]),
      kind_(&kind),
      targets_(owner.targets()[index].data()),
      kind_name_("shot." + kind.name) {
  visible_at_once_ = visible_at_once(kind, *property_);
}


double ShotPropertyConstraint::score(const View& view) const {
  return property_score(*kind_, *property_, visible_at_once_, view, owner_->world(), targets_);
}

double ShotPropertyConstraint::violation(std::span<const double> values) const {
  const std::optional<View> view = View::of(owner_->pose(values));
  return view ? 1 - score(*view) : 1.0;
}

ShotForesightConstraint::ShotForesightConstraint(const CompositionProblem& owner,
                                                 std::size_t index, const ShotPropertyKind& kind,
                                                 std::size_t horizon)
    : Constraint({0, 1, 2, 3, 4, 5, 6},
                 owner.shot().properties[index].weight * owner.foresight().weight, false),
      owner_(&owner),
      property_(&owner.shot().properties[index]),
      kind_(&kind),
      targets_(owner.targets()[index].data()),
      horizon_(horizon),
      visible_at_once_(visible_at_once(kind, *property_)) {}

double ShotForesightConstraint::violation(std::span<const double> values) const {
  CameraPose pose = owner_->pose(values);
  const Eigen::Vector3d& shift = owner_->future_shift(horizon_);
  pose.position += shift;
  pose.look_at += shift;
  const std::optional<View> view = View::of(pose);
  if (!view) return 1.0;
  return 1 - property_score(*kind_, *property_, visible_at_once_, *view, owner_->future(horizon_), targets_);
}

ShotClearanceConstraint::ShotClearanceConstraint(const CompositionProblem& owner)
    : Constraint({0, 1, 2}, 1, true), owner_(&owner) {}

double ShotClearanceConstraint::violation(std::span<const double> values) const {
  const double r = owner_->shot().clearance;
  const Eigen::Vector3d p(values[0], values[1], values[2]);
  return std::max(0.0, r - owner_->world().clearance(p, r + 1));
}

}  // namespace sightline::camera
