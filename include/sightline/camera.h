// sightline/camera.h: the chase camera for a game, driven each frame by the state of the
// people it films.
//
// A game makes one Camera per view with the world it films (sightline/world.h), the people
// in the shot (the first is the one the camera follows) and a profile, then calls update()
// once per frame with where the people are now and the time since the last frame; update
// returns where to put the camera and where to aim it, and says when the move is a cut (a
// jump the game should not interpolate, and may cover with a transition).
//
// The camera is sightline's constraint camera (docs/CAMERA.md): each frame it solves a small
// weighted CSP (height, distance, orientation, frame coherence, the character visible,
// clearance, and with the anticipating profiles the predicted positions visible) with the
// chosen solver, then moves smoothly or cuts.
//
// Threads: a Camera is used from one thread at a time; cameras of one world may run on
// different threads when the world answers concurrently. update() allocates nothing after the
// first frame (with sightline's own world; a game's world is as allocation-free as its
// queries).
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "sightline/vec3.h"
#include "sightline/world.h"

namespace sightline {

// One person's state at a frame: what a game knows.
struct PersonState {
  Vec3 position;      // centre of the feet, metres
  Vec3 velocity;      // metres per second
  double yaw = 0;     // degrees about +y; 0 faces +z, 90 faces +x
};

// One person's body: an axis-aligned box on the feet, and the point the camera aims at.
struct PersonShape {
  Vec3 size{0.6, 1.8, 0.6};     // extents along x, y, z, metres, > 0
  double look_at_height = 1.5;  // metres above the feet, in (0, size.y]
};

struct CameraSettings {
  // A preset name ("anticipating", "thesis-default", "close-follow", "high-follow"; see
  // camera_presets()) or a whole profile as YAML text (docs/CAMERA.md, "Profiles"; `base:`
  // may name a preset). Profiles that read the scripted future (lookahead: path) are refused:
  // a game's future is not known.
  std::string profile = "anticipating";
  // Any registered solver or pipeline that works on camera problems (camera_solvers()).
  std::string solver = "occlusion-octree";
  std::uint64_t seed = 1;
  // The people in the shot: the first is followed; the others block sight and the camera like
  // movers, where update() says they are. At least one.
  std::vector<PersonShape> people{PersonShape{}};
  // Where the camera starts; without it, the profile's ideal spot behind the first person.
  bool has_start = false;
  Vec3 start;
  // Frames per second the game expects; only sizes the first frame's search.
  double frame_rate = 60;
};

enum class CutReason {
  kNone, kLeftEnclosedArea, kBackedUpToObstacle, kVisibilityLost, kStuck, kTooFast
};
const char* to_string(CutReason reason);

struct CameraPose {
  Vec3 position;           // where to put the camera
  Vec3 target;             // the point to aim at (the followed person's look-at point)
  Vec3 up{0, 1, 0};
  bool cut = false;        // the camera jumped this frame
  CutReason cut_reason = CutReason::kNone;
  bool look_at_visible = true;  // by the camera's own sight-line query
  double cost = 0;         // the weighted violation of the chosen position
  double solve_seconds = 0;     // wall time of this update
};

class Camera {
 public:
  // `world` is shared: it must stay valid while the camera lives (the shared_ptr keeps it).
  // `people` are the people's states at the first frame, one per settings.people, at time t
  // (seconds, the game's clock). Throws sightline::Error on bad settings, an unknown preset or
  // solver, a profile that does not parse, NaN in the people's states or a world error.
  Camera(std::shared_ptr<const World> world, const CameraSettings& settings,
         std::span<const PersonState> people, double t = 0);
  ~Camera();
  Camera(const Camera&) = delete;
  Camera& operator=(const Camera&) = delete;
  Camera(Camera&&) noexcept;
  Camera& operator=(Camera&&) noexcept;

  // One frame: the people's states now (as many as settings.people), dt > 0 seconds since the
  // last update. Throws sightline::Error on NaN, a wrong count or dt <= 0, and passes on what
  // the world throws; the camera is unchanged then.
  const CameraPose& update(std::span<const PersonState> people, double dt);
  // The same at the game's clock `t` (seconds, > time()), for a game that keeps one: the
  // camera's clock becomes t exactly rather than the sum of the dt's, and dt stays the time
  // step its motion limits use.
  const CameraPose& update(std::span<const PersonState> people, double dt, double t);
  // Puts the camera at `position`, at rest (a respawn, a scripted cut).
  void reset(const Vec3& position);
  const CameraPose& pose() const;
  // The game's clock at the last update.
  double time() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// The names CameraSettings::profile accepts as presets, and the solvers a camera can use.
std::vector<std::string> camera_presets();
std::vector<std::string> camera_solvers();
// sightline's version, "major.minor.patch".
const char* version();

}  // namespace sightline
