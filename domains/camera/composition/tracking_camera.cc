#include "sightline/domains/camera/composition/tracking_camera.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "sightline/domains/camera/composition/composition_solvers.h"
#include "sightline/solvers/registry.h"

namespace sightline::camera {
namespace {

const Shot& shot_of(const Scene& scene) {
  if (!scene.shot()) throw std::invalid_argument("a tracking shot needs a scene with a shot: block");
  return *scene.shot();
}

// The shot the camera works to: the scene's, plus a `visible` property asking half the
// samples of each person the shot wants in the image and names in no visible property (a
// person framed but hidden behind another is not in the shot, whatever the framing says).
Shot working_shot(const Shot& shot, const std::vector<std::string>& wanted) {
  Shot out = shot;
  for (const std::string& name : wanted) {
    const bool asked = std::any_of(shot.properties.begin(), shot.properties.end(), [&](const ShotProperty& p) {
      return p.kind == "visible" && p.targets.front() == name;
    });
    if (asked) continue;
    ShotProperty visible;
    visible.kind = "visible";
    visible.targets = {name};
    visible.range = {0.5, 1};
    visible.softness = 1;
    visible.where = shot.where;
    out.properties.push_back(std::move(visible));
  }
  return out;
}

std::vector<std::string> wanted_names(const Scene& scene) {
  const CompositionProblem problem(scene, shot_of(scene), scene.trajectory().start_time());
  std::vector<std::string> out;
  for (int w : problem.wanted()) out.push_back(problem.world().people()[static_cast<std::size_t>(w)].name);
  return out;
}

}  // namespace

TrackingCamera::TrackingCamera(const Scene& scene, TrackingOptions options)
    : scene_(&scene),
      options_(std::move(options)),
      shot_(working_shot(shot_of(scene), wanted_names(scene))),
      problem_(scene, shot_, scene.trajectory().start_time()),
      ahead_(scene, shot_, scene.trajectory().start_time(), options_.foresight),
      verdict_(scene, shot_of(scene), scene.trajectory().start_time()) {
  solvers::SolverRegistry& registry = solvers::SolverRegistry::global();
  register_composition_solvers(registry);
  global_ = registry.create(options_.solver);
  if (std::string why = global_->unsuitable_reason(problem_.problem()); !why.empty()) {
    throw std::invalid_argument("solver '" + options_.solver + "' cannot film this shot: " + why);
  }
  local_ = registry.create("shot-search", {{"global", "false"}});
  local_context_.limits.max_evaluations = options_.frame_evaluations;
  local_context_.want_breakdown = false;
  local_context_.anytime = false;
  local_context_.seed = options_.seed;
  global_context_.limits.max_evaluations = options_.resolve_evaluations;
  global_context_.want_breakdown = false;
  global_context_.seed = options_.seed;
  frame_.cut = false;
}

void TrackingCamera::reset(const Eigen::Vector3d& position) {
  started_ = false;
  pose_.position = position;
}

void TrackingCamera::solve_globally(std::uint64_t evaluations) {
  global_context_.limits.max_evaluations = evaluations;
  global_->solve_into(ahead_.problem(), aim_, global_context_, result_);
  aim_ = result_.best;
  problem_.evaluate_into(problem_.pose(aim_), aimed_);
  aim_satisfaction_ = aimed_.satisfaction;
  global_loses_ = loses_someone(aimed_);
}

bool TrackingCamera::loses_someone(const ShotEvaluation& e) const {
  for (std::size_t i = 0; i < e.scores.size(); ++i) {
    const ShotProperty& p = problem_.shot().properties[i];
    if ((p.kind == "visible" || p.kind == "framed") && p.range.hi > 0 && e.scores[i] < 1) return true;
  }
  return false;
}

void TrackingCamera::move_toward(double dt) {
  // Two first-order stages: the aimed-for pose is low-passed (the local solve's answer moves
  // in small discrete steps from frame to frame), and the camera follows that, so neither
  // the steps nor the spring's own corners reach the camera's acceleration.
  const CameraPose aim = problem_.pose(aim_);
  const double k = 1 - std::exp(-dt / options_.smoothing);
  const Eigen::Vector3d aim_dir = (aim.look_at - aim.position).normalized();
  filtered_.position += k * (aim.position - filtered_.position);
  filtered_.look_at = (filtered_.look_at + k * (aim_dir - filtered_.look_at)).normalized();
  filtered_.fov += k * (aim.fov - filtered_.fov);
  filtered_.roll += k * (aim.roll - filtered_.roll);
  Eigen::Vector3d step = k * (filtered_.position - pose_.position);
  const double limit = 0.98 * max_step(dt);
  if (step.norm() > limit) step *= limit / step.norm();
  const Eigen::Vector3d new_position = pose_.position + step;
  const Eigen::Vector3d old_dir = (pose_.look_at - pose_.position).normalized();
  const Eigen::Vector3d dir = (old_dir + k * (filtered_.look_at - old_dir)).normalized();
  pose_.position = new_position;
  pose_.look_at = new_position + dir;
  pose_.fov += k * (filtered_.fov - pose_.fov);
  pose_.roll += k * (filtered_.roll - pose_.roll);
}

void TrackingCamera::jump_to_aim() {
  pose_ = problem_.pose(aim_);
  filtered_ = pose_;
  filtered_.look_at = (pose_.look_at - pose_.position).normalized();  // a direction here
}

const CameraFrame& TrackingCamera::update(const CharacterState& character, double dt) {
  const auto began = std::chrono::steady_clock::now();
  t_ = character.t;
  frame_.cut = false;
  frame_.cut_reason = CutReason::kNone;
  if (!started_) {
    // The first frame: a global solve from nowhere, and the camera starts there.
    problem_.set_time(t_);
    ahead_.set_time(t_);
    aim_ = problem_.assignment(pose_);
    solve_globally(options_.resolve_evaluations * 5);
    jump_to_aim();
    started_ = true;
    last_cut_t_ = t_;  // the film starts a shot: no cut within its minimum length either
  } else {
    // The pose to aim for is solved where the people will be when the camera gets there
    // (the two stages lag about 2 x smoothing), forecast from their velocities.
    problem_.set_time(t_, options_.lead_seconds);
    ahead_.set_time(t_, options_.lead_seconds);
    local_->solve_into(problem_.problem(), aim_, local_context_, result_);
    aim_ = result_.best;
    problem_.evaluate_into(problem_.pose(aim_), aimed_);
    // A global solve when the aimed-for pose breaks a rule, loses someone the last global
    // solve's pose kept, or has fallen well below it.
    if (!aimed_.feasible || (loses_someone(aimed_) && !global_loses_) ||
        aimed_.satisfaction < aim_satisfaction_ - options_.resolve_drop) {
      solve_globally(options_.resolve_evaluations);
    } else {
      aim_satisfaction_ = std::max(aim_satisfaction_ * 0.98, aimed_.satisfaction);
    }
    move_toward(dt);
    // Cut when the camera's pose has lost the shot (a rule broken, or someone it wants
    // framed and visible lost) while the aimed-for pose keeps it and is out of smooth
    // reach; never within the minimum shot length.
    problem_.set_time(t_);
    problem_.evaluate_into(pose_, here_);
    const CameraPose aim = problem_.pose(aim_);
    if ((!here_.feasible || loses_someone(here_)) &&
        (aim.position - pose_.position).norm() > max_step(dt) &&
        t_ - last_cut_t_ >= options_.min_shot_seconds) {
      problem_.evaluate_into(aim, aimed_);
      if (aimed_.feasible && !loses_someone(aimed_)) {
        jump_to_aim();
        frame_.cut = true;
        frame_.cut_reason = CutReason::kVisibilityLost;
        last_cut_t_ = t_;
      }
    }
  }
  // FORMATS.md's verdict on the pose, for the frame and evaluation().
  verdict_.set_time(t_);
  verdict_.evaluate_into(pose_, evaluation_);
  fill_frame(problem_, pose_, evaluation_.feasible, problem_.pose(aim_).position, frame_);
  frame_.solve_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
  return frame_;
}

}  // namespace sightline::camera
