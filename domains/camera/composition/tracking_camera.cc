#include "sightline/domains/camera/composition/tracking_camera.h"

#include <algorithm>
#include <array>
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

// The shot the poses are solved for: each soft `visible` property of someone wanted asks
// at least `share` of the samples (within its range), so that the pose aimed for keeps
// people in view with room to spare while pillars and passers-by come near and while the
// camera lags behind it; what a pose keeps or loses is still judged by the shot itself.
// Working to the shot's own ranges, the aimed-for pose sat where the last sample it needed
// was just visible or just framed, and lost someone at the next small change.
Shot asking_more_visible(const Shot& shot, double share) {
  Shot out = shot;
  for (ShotProperty& p : out.properties) {
    if (p.kind == "visible" && !p.hard && p.range.hi > 0) {
      p.range.lo = std::max(p.range.lo, std::min(p.range.hi, share));
    }
  }
  return out;
}

// The shot the camera's view is turned to from where it stands: `framed` of each person
// wanted made hard, so that the view gives up no one for a better size, angle or screen
// point (from a position the aimed-for pose is not at, those trade against each other;
// whether someone is seen is fixed by the position).
Shot framing_first(const Shot& shot) {
  Shot out = shot;
  for (ShotProperty& p : out.properties) {
    if (p.kind == "framed" && p.range.hi > 0) p.hard = true;
  }
  return out;
}

// The names of the people `problem` wants in the image.
std::vector<std::string> wanted_names(const CompositionProblem& problem) {
  std::vector<std::string> out;
  for (int w : problem.wanted()) out.push_back(problem.world().people()[static_cast<std::size_t>(w)].name);
  return out;
}

}  // namespace

TrackingCamera::TrackingCamera(const Scene& scene, TrackingOptions options)
    : scene_(&scene),
      options_(std::move(options)),
      verdict_(scene, shot_of(scene), scene.trajectory().start_time()),
      shot_(working_shot(shot_of(scene), wanted_names(verdict_))),
      aimed_shot_(asking_more_visible(shot_, options_.visible_aim)),
      turn_shot_(framing_first(aimed_shot_)),
      problem_(scene, shot_, scene.trajectory().start_time()),
      refine_(scene, aimed_shot_, scene.trajectory().start_time()),
      ahead_(scene, aimed_shot_, scene.trajectory().start_time(), options_.foresight),
      turn_(scene, turn_shot_, scene.trajectory().start_time()),
      sweep_terms_(ahead_.problem().num_constraints()) {
  solvers::SolverRegistry& registry = solvers::SolverRegistry::global();
  register_composition_solvers(registry);
  global_ = registry.create(options_.solver);
  if (std::string why = global_->unsuitable_reason(problem_.problem()); !why.empty()) {
    throw std::invalid_argument("solver '" + options_.solver + "' cannot film this shot: " + why);
  }
  local_ = registry.create("shot-search", {{"global", "false"}});
  turner_ = registry.create("shot-search", {{"global", "false"}, {"hold_position", "true"}});
  // The sweep's share of a frame is in people looked at: fewer candidates with more people.
  sweep_count_ = static_cast<std::size_t>(std::max<std::int64_t>(
      4, options_.sweep_people_per_frame / static_cast<std::int64_t>(problem_.wanted().size())));
  local_context_.limits.max_evaluations = static_cast<std::uint64_t>(std::max<std::int64_t>(
      30, options_.frame_people_evaluations / static_cast<std::int64_t>(problem_.wanted().size())));
  local_context_.want_breakdown = false;
  local_context_.anytime = false;
  local_context_.seed = options_.seed;
  turn_context_ = local_context_;
  turn_context_.limits.max_evaluations = static_cast<std::uint64_t>(options_.turn_evaluations);
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

Eigen::Vector3d TrackingCamera::wanted_centre() const {
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (int w : ahead_.wanted()) c += ahead_.world().people()[static_cast<std::size_t>(w)].aim;
  return c / static_cast<double>(ahead_.wanted().size());
}

void TrackingCamera::sweep_pose(std::size_t i, const Eigen::Vector3d& centre, CameraPose& out) const {
  // 16 bearings x 3 elevations x 3 distances (the aim's, 0.7 and 1.4 times) round the
  // people, then 48 Halton points of the region; each looking at the people's centre with
  // the aim's lens.
  const CameraPose aim = problem_.pose(aim_);
  const double d0 = std::max(1.0, (aim.position - centre).norm());
  const Aabb& region = shot_.region;
  Eigen::Vector3d p;
  if (i < 144) {
    static constexpr double kElevations[3] = {10, 30, 55}, kScales[3] = {0.7, 1.0, 1.4};
    const double bearing = (i % 16) * 22.5 * M_PI / 180, elevation = kElevations[(i / 16) % 3] * M_PI / 180;
    const double d = d0 * kScales[i / 48];
    p = centre + d * Eigen::Vector3d(std::cos(elevation) * std::sin(bearing), std::sin(elevation),
                                     std::cos(elevation) * std::cos(bearing));
  } else {
    auto halton = [](std::size_t k, std::size_t b) {
      double f = 1, r = 0;
      for (; k > 0; k /= b) {
        f /= static_cast<double>(b);
        r += f * static_cast<double>(k % b);
      }
      return r;
    };
    const std::size_t k = i - 143;
    p = region.min + Eigen::Vector3d(halton(k, 2), halton(k, 3), halton(k, 5)).cwiseProduct(region.max - region.min);
  }
  out.position = p.cwiseMax(region.min).cwiseMin(region.max);
  out.look_at = centre;
  out.fov = aim.fov;
  out.roll = aim.roll;
  out.aspect = aim.aspect;
}

void TrackingCamera::sweep_slice(std::size_t count) {
  constexpr std::size_t kCandidates = 144 + 48;  // sweep_pose's
  const Eigen::Vector3d centre = wanted_centre();
  CameraPose candidate;
  for (std::size_t n = 0; n < count; ++n, ++sweep_cursor_) {
    if (sweep_cursor_ == kCandidates) {  // a sweep done: its best is ready
      sweep_cursor_ = 0;
      ready_ = has_best_;
      ready_offset_ = best_offset_;
      has_best_ = false;
    }
    sweep_pose(sweep_cursor_, centre, candidate);
    // A candidate that cannot beat this sweep's best skips its sight lines.
    bool complete = true;
    const auto values = ahead_.pose_values(candidate);
    const csp::Score score = has_best_ ? ahead_.problem().score_below(values, best_score_, complete, sweep_terms_)
                                       : ahead_.problem().score(values);
    if (complete && (!has_best_ || score.better_than(best_score_))) {
      has_best_ = true;
      best_score_ = score;
      best_offset_ = candidate.position - centre;
    }
  }
}

bool TrackingCamera::take_sweep_best() {
  if (!ready_) return false;
  const Eigen::Vector3d centre = wanted_centre();
  CameraPose candidate = problem_.pose(aim_);
  candidate.position = (centre + ready_offset_).cwiseMax(shot_.region.min).cwiseMin(shot_.region.max);
  candidate.look_at = centre;
  const auto values = ahead_.pose_values(candidate);
  const csp::Score there = ahead_.problem().score(values);
  if (!there.better_than(ahead_.problem().score(aim_))) return false;
  std::copy(values.begin(), values.end(), aim_.begin());
  return true;
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
  // Never into the shot's clearance: the step, else half of it, else none (the smoothed path
  // cuts corners the aimed-for poses keep clear of), unless each of them is inside it
  // (verdict_ is at the frame's time: update() sets it first).
  const double clearance = shot_.clearance;
  for (double scale : {1.0, 0.5, 0.0}) {
    if (verdict_.world().clearance(pose_.position + scale * step, clearance) >= clearance) {
      step *= scale;
      break;
    }
  }
  const Eigen::Vector3d new_position = pose_.position + step;
  const Eigen::Vector3d old_dir = (pose_.look_at - pose_.position).normalized();
  // On a long move (the camera held back by max_speed, the low-passed aim metres ahead), the
  // view is not the aim's: from where the camera is, that looks the way it will look from
  // there, and the people leave the image on the way. The look first turns from the aim's
  // direction toward the point the aim's view centres at the people's depth; from that, the
  // aim, lens and roll are refined with the camera held where it is, for the shot with each
  // wanted person's `framed` made hard (turn_shot_), where they will be when the look has
  // turned (one smoothing stage on). Near the aim (the camera's usual lag), the aim's view:
  // refining it there too put an over-the-shoulder shot's partner on the edge of the image,
  // the refined view's optimum, and the look's lag took them off it (tracking-shot-15: 79%
  // of frames shown instead of 100%).
  Eigen::Vector3d wanted_dir = filtered_.look_at;
  double wanted_fov = filtered_.fov, wanted_roll = filtered_.roll;
  const double behind = (new_position - filtered_.position).norm();
  if (behind > kNearAim) {
    const double depth = std::max(1.0, (wanted_centre() - filtered_.position).dot(filtered_.look_at));
    const Eigen::Vector3d to = filtered_.position + depth * filtered_.look_at - new_position;
    const double w = std::min(1.0, (behind - kNearAim) / kTurnAcross);
    if (to.norm() > 1e-6) wanted_dir = ((1 - w) * filtered_.look_at + w * to.normalized()).normalized();
    if (options_.turn_evaluations > 0) {
      turn_.set_time(t_, options_.smoothing);
      CameraPose here = filtered_;
      here.position = new_position;
      here.look_at = new_position + wanted_dir;
      turner_->solve_into(turn_.problem(), turn_.pose_values(here), turn_context_, turned_);
      const CameraPose turned = turn_.pose(turned_.best);
      wanted_dir = (turned.look_at - turned.position).normalized();
      wanted_fov = turned.fov;
      wanted_roll = turned.roll;
    }
  }
  const Eigen::Vector3d dir = (old_dir + k * (wanted_dir - old_dir)).normalized();
  pose_.position = new_position;
  pose_.look_at = new_position + dir;
  pose_.fov += k * (wanted_fov - pose_.fov);
  pose_.roll += k * (wanted_roll - pose_.roll);
}

void TrackingCamera::jump_to_aim() {
  pose_ = problem_.pose(aim_);
  filtered_ = pose_;
  filtered_.look_at = (pose_.look_at - pose_.position).normalized();  // a direction here
}

const CameraFrame& TrackingCamera::update(const CharacterState& character, double dt) {
  const auto began = std::chrono::steady_clock::now();
  t_ = character.t;
  verdict_.set_time(t_);  // the people now: the verdict and move_toward's clearance
  frame_.cut = false;
  frame_.cut_reason = CutReason::kNone;
  if (!started_) {
    // The first frame: a global solve from nowhere, and the camera starts there.
    problem_.set_time(t_);
    refine_.set_time(t_);
    ahead_.set_time(t_);
    aim_ = problem_.assignment(pose_);
    solve_globally(options_.resolve_evaluations * 5);
    jump_to_aim();
    if (options_.turn_evaluations > 0) {
      // The view turned from where the camera is runs only on long moves: once now, so that
      // its search's storage is made before the frames that must allocate nothing.
      turn_.set_time(t_);
      turner_->solve_into(turn_.problem(), aim_, turn_context_, turned_);
    }
    started_ = true;
    last_cut_t_ = t_;  // the film starts a shot: no cut within its minimum length either
  } else {
    // The pose to aim for is solved where the people will be when the camera gets there
    // (the two stages lag about 2 x smoothing), forecast from their velocities; a slice of
    // the background sweep is scored there too.
    problem_.set_time(t_, options_.lead_seconds);
    refine_.set_time(t_, options_.lead_seconds);
    ahead_.set_time(t_, options_.lead_seconds);
    sweep_slice(sweep_count_);
    local_->solve_into(refine_.problem(), aim_, local_context_, result_);
    aim_ = result_.best;
    problem_.evaluate_into(problem_.pose(aim_), aimed_);
    // When the aimed-for pose breaks a rule: a global solve. When it loses someone or falls
    // well below the last global pose: the last sweep's best if it does better with
    // foresight, else a global solve if one is due (they are rationed: one at hand at the
    // start, then resolves_per_second).
    resolves_ = std::min(1.0, resolves_ + options_.resolves_per_second * dt);
    const bool loses = loses_someone(aimed_);
    const bool dropped = aimed_.satisfaction < aim_satisfaction_ - options_.resolve_drop;
    if (!aimed_.feasible) {
      solve_globally(options_.resolve_evaluations);
    } else if ((loses || dropped) && take_sweep_best()) {
      problem_.evaluate_into(problem_.pose(aim_), aimed_);
      aim_satisfaction_ = aimed_.satisfaction;
    } else if (((loses && !global_loses_) || dropped) && resolves_ >= 1) {
      resolves_ -= 1;
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
        // The cut goes to the last sweep's best instead when it does better with foresight
        // (the aimed-for pose is refined frame by frame for the present alone) and keeps
        // everyone now: no second cut can come within the shot's minimum length.
        std::array<double, 7> kept;
        std::copy(aim_.begin(), aim_.end(), kept.begin());
        if (take_sweep_best()) {
          problem_.evaluate_into(problem_.pose(aim_), aimed_);
          if (aimed_.feasible && !loses_someone(aimed_)) {
            aim_satisfaction_ = aimed_.satisfaction;
          } else {
            std::copy(kept.begin(), kept.end(), aim_.begin());
            problem_.evaluate_into(problem_.pose(aim_), aimed_);  // aimed_ is the aim's again
          }
        }
        jump_to_aim();
        frame_.cut = true;
        frame_.cut_reason = CutReason::kVisibilityLost;
        last_cut_t_ = t_;
      }
    }
  }
  // FORMATS.md's verdict on the pose, for the frame and evaluation().
  verdict_.evaluate_into(pose_, evaluation_);
  fill_frame(problem_, pose_, evaluation_.feasible, problem_.pose(aim_).position, frame_);
  frame_.solve_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
  return frame_;
}

}  // namespace sightline::camera
