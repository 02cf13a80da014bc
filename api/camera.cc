// sightline::Camera: the public chase camera over a camera::Scene built from the game's world
// and the people's states (no scripted path, no file).
//
// The scene holds the world (sightline's own index copied from a GeometryWorld, or the game's
// World asked through SceneAtTime), one mover per person after the first (placed each frame
// as a constant-velocity forecast from what the game reports) and a one-keyframe path at the
// first person's start, which only the camera's first frame reads.
#include "sightline/camera.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "api/conversions.h"
#include "api/geometry_world.h"
#include "sightline/csp/files/yaml_spec.h"
#include "sightline/csp/input_error.h"
#include "sightline/domains/camera/control/camera_solvers.h"
#include "sightline/domains/camera/control/chase_camera.h"
#include "sightline/domains/camera/profile_file.h"
#include "sightline/version.h"

namespace sightline {

namespace {

void check_people(std::span<const PersonState> people, std::size_t expected) {
  if (people.size() != expected) {
    throw Error("camera: expected the states of " + std::to_string(expected) +
                " people (one per CameraSettings::people), got " + std::to_string(people.size()));
  }
  for (std::size_t i = 0; i < people.size(); ++i) {
    if (!finite(people[i].position) || !finite(people[i].velocity) ||
        !std::isfinite(people[i].yaw)) {
      throw Error("camera: person " + std::to_string(i) +
                  "'s state has a value that is not finite (position, velocity and yaw must be)");
    }
  }
}

camera::CharacterShape shape_of(const PersonShape& p, std::size_t i) {
  if (!finite(p.size) || !(p.size.x > 0 && p.size.y > 0 && p.size.z > 0)) {
    throw Error("camera: person " + std::to_string(i) + "'s size must be finite and > 0 on every axis");
  }
  if (!(p.look_at_height > 0 && p.look_at_height <= p.size.y)) {
    throw Error("camera: person " + std::to_string(i) +
                "'s look_at_height must be in (0, size.y]");
  }
  camera::CharacterShape s;
  s.size = to_eigen(p.size);
  s.look_at_height = p.look_at_height;
  return s;
}

camera::CameraProfile profile_of(const std::string& text) {
  try {
    if (camera::is_preset(text)) return camera::preset_profile(text);
    if (text.find(':') == std::string::npos) {
      std::string names;
      for (const std::string& n : camera_presets()) names += (names.empty() ? "" : ", ") + n;
      throw Error("camera: '" + text + "' is neither a preset (" + names +
                  ") nor a profile's YAML text");
    }
    return camera::parse_profile(csp::parse_yaml(text, "profile text"));
  } catch (const csp::InputError& e) {
    throw Error(std::string("camera: ") + e.what());
  }
}

camera::CharacterState state_of(const PersonState& p, double t) {
  camera::CharacterState s;
  s.t = t;
  s.position = to_eigen(p.position);
  s.velocity = to_eigen(p.velocity);
  s.yaw = camera::wrap_degrees(p.yaw);
  return s;
}

// The profile's ideal spot behind the person, pulled in toward the look-at point to the
// farthest point that is clear and in sight, in the world at time t (pulled_in_start).
Eigen::Vector3d start_position(const World& world, const camera::CameraProfile& profile,
                               const camera::CharacterShape& shape,
                               const camera::CharacterState& first) {
  const Eigen::Vector3d ideal = camera::ideal_camera_position(
      first, profile.height.desired, profile.distance.desired, profile.orientation.desired);
  const Eigen::Vector3d look = shape.look_at(first.position);
  const double r = profile.clearance_radius;
  return camera::pulled_in_start(look, ideal, [&](const Eigen::Vector3d& p) {
    return world.clearance(to_vec3(p), r + 1e-6, first.t) >= r &&
           world.line_of_sight(to_vec3(p), to_vec3(look), first.t);
  });
}

CutReason public_reason(camera::CutReason r) {
  switch (r) {
    case camera::CutReason::kNone: return CutReason::kNone;
    case camera::CutReason::kLeftEnclosedArea: return CutReason::kLeftEnclosedArea;
    case camera::CutReason::kBackedUpToObstacle: return CutReason::kBackedUpToObstacle;
    case camera::CutReason::kVisibilityLost: return CutReason::kVisibilityLost;
    case camera::CutReason::kStuck: return CutReason::kStuck;
    case camera::CutReason::kTooFast: return CutReason::kTooFast;
  }
  return CutReason::kNone;
}

}  // namespace

struct Camera::Impl {
  std::shared_ptr<const World> world;
  camera::Scene scene;  // holds the profile the controller reads (scene.profile())
  std::size_t people = 0;
  double t = 0;
  std::unique_ptr<camera::ChaseCamera> controller;
  CameraPose pose;

  Impl(std::shared_ptr<const World> w, camera::Scene s) : world(std::move(w)), scene(std::move(s)) {}

  void take(const camera::CameraFrame& f) {
    pose.position = to_vec3(f.position);
    pose.target = to_vec3(f.target);
    pose.up = to_vec3(f.up);
    pose.cut = f.cut;
    pose.cut_reason = public_reason(f.cut_reason);
    pose.look_at_visible = f.look_at_visible;
    pose.cost = f.score.soft;
    pose.solve_seconds = f.solve_seconds;
  }
};

namespace {

// The scene a camera films: the world's index (or the world itself), and a path of one
// keyframe where the first person starts.
camera::Scene scene_for(const std::shared_ptr<const World>& world,
                        const camera::CharacterShape& shape, const PersonState& first,
                        double t, double frame_rate) {
  camera::Trajectory path({camera::Keyframe{t, to_eigen(first.position), first.yaw}});
  if (const auto* own = dynamic_cast<const GeometryWorld*>(world.get())) {
    camera::Scene s("world", own->scene().solids(), {}, shape, std::move(path), frame_rate);
    s.share_level(own->scene());  // the index built once, in make_geometry_world
    return s;
  }
  camera::Scene s("world", {}, {}, shape, std::move(path), frame_rate);
  s.set_world(world);
  return s;
}

}  // namespace

Camera::Camera(std::shared_ptr<const World> world, const CameraSettings& settings,
               std::span<const PersonState> people, double t) {
  if (!world) throw Error("camera: no world (a null World)");
  if (settings.people.empty()) throw Error("camera: CameraSettings::people is empty: at least the followed person");
  if (!std::isfinite(t)) throw Error("camera: the start time is not finite");
  if (!(settings.frame_rate > 0) || !std::isfinite(settings.frame_rate)) {
    throw Error("camera: frame_rate must be finite and > 0");
  }
  if (settings.has_start && !finite(settings.start)) throw Error("camera: the start is not finite");
  check_people(people, settings.people.size());
  camera::CameraProfile profile = profile_of(settings.profile);
  if (profile.anticipation.lookahead == camera::Lookahead::kPath) {
    throw Error("camera: profile '" + profile.name +
                "' reads the scripted future path (anticipation.lookahead: path), which a game "
                "does not know; use lookahead: motion (the 'anticipating' preset)");
  }
  if (const std::string error = profile.validate(); !error.empty()) {
    throw Error("camera: profile '" + profile.name + "': " + error);
  }
  const camera::CharacterShape shape = shape_of(settings.people[0], 0);
  camera::Scene scene = scene_for(world, shape, people[0], t, settings.frame_rate);
  std::vector<camera::Mover> movers;
  for (std::size_t i = 1; i < people.size(); ++i) {
    const camera::CharacterShape other = shape_of(settings.people[i], i);
    movers.emplace_back("person " + std::to_string(i), other.size,
                        std::vector<camera::MoverKeyframe>{{t, to_eigen(people[i].position)}});
    movers.back().place(to_eigen(people[i].position), to_eigen(people[i].velocity), t);
  }
  scene.set_movers(std::move(movers));
  scene.set_profile(profile, "public API");  // the camera reads it there
  const camera::CharacterState first = state_of(people[0], t);
  scene.set_camera_start(settings.has_start ? to_eigen(settings.start)
                                            : start_position(*world, profile, shape, first));
  impl_ = std::make_unique<Impl>(world, std::move(scene));
  impl_->people = people.size();
  impl_->t = t;
  camera::ChaseCameraOptions options;
  options.solver = settings.solver;
  options.seed = settings.seed;
  try {
    impl_->controller = std::make_unique<camera::ChaseCamera>(impl_->scene, impl_->scene.profile(),
                                                               options);
  } catch (const Error&) {
    throw;
  } catch (const std::exception& e) {
    throw Error(std::string("camera: ") + e.what());
  }
  impl_->pose.position = to_vec3(impl_->scene.start_camera_position());
  impl_->pose.target = to_vec3(shape.look_at(first.position));
}

Camera::~Camera() = default;
Camera::Camera(Camera&&) noexcept = default;
Camera& Camera::operator=(Camera&&) noexcept = default;

const CameraPose& Camera::update(std::span<const PersonState> people, double dt) {
  return update(people, dt, impl_->t + dt);
}

const CameraPose& Camera::update(std::span<const PersonState> people, double dt, double t) {
  Impl& m = *impl_;
  if (!(dt > 0) || !std::isfinite(dt)) throw Error("camera: dt must be finite and > 0 seconds");
  if (!std::isfinite(t) || !(t > m.t)) {
    throw Error("camera: the time must be finite and later than the last update's");
  }
  check_people(people, m.people);
  for (std::size_t i = 1; i < people.size(); ++i) {
    m.scene.place_mover(i - 1, to_eigen(people[i].position), to_eigen(people[i].velocity), t);
  }
  try {
    m.take(m.controller->update(state_of(people[0], t), dt));
  } catch (const std::exception& e) {
    // The world failed part-way through the frame: start the next from the last good pose.
    m.controller->reset(to_eigen(m.pose.position));
    if (dynamic_cast<const Error*>(&e)) throw;
    throw Error(std::string("camera: ") + e.what());
  }
  m.t = t;
  return m.pose;
}

void Camera::reset(const Vec3& position) {
  if (!finite(position)) throw Error("camera: reset to a position that is not finite");
  impl_->controller->reset(to_eigen(position));
  impl_->pose.position = position;
}

const CameraPose& Camera::pose() const { return impl_->pose; }
double Camera::time() const { return impl_->t; }

const char* to_string(CutReason reason) {
  switch (reason) {
    case CutReason::kNone: return "none";
    case CutReason::kLeftEnclosedArea: return "left enclosed area";
    case CutReason::kBackedUpToObstacle: return "backed up to obstacle";
    case CutReason::kVisibilityLost: return "visibility lost";
    case CutReason::kStuck: return "stuck";
    case CutReason::kTooFast: return "too fast";
  }
  return "none";
}

std::vector<std::string> camera_presets() {
  std::vector<std::string> names;
  for (const std::string& n : camera::preset_names()) {
    if (camera::preset_profile(n).anticipation.lookahead != camera::Lookahead::kPath) {
      names.push_back(n);
    }
  }
  return names;
}

std::vector<std::string> camera_solvers() { return camera::solver_registry().names(); }

const char* version() { return SIGHTLINE_VERSION_STRING; }

}  // namespace sightline
