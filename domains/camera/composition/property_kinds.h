// ShotPropertyKinds: the registry of shot properties (FORMATS.md "Shots"), as the csp and
// camera constraint kinds are registered: a kind is its name, its own fields, its default
// range and softness, and its measure; a new one is one file and one add() call.
//
// Built in: framed, screen_position, size, angle_horizontal, angle_vertical, visible,
// distance, order, each measured exactly as FORMATS.md defines it (measure()), and scored by
// satisfaction(): 1 inside the wanted range, falling linearly to 0 at `softness` outside it
// (modulo 360 for angle_horizontal).
#pragma once

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "sightline/csp/spec.h"
#include "sightline/domains/camera/composition/camera_pose.h"
#include "sightline/domains/camera/composition/shot.h"
#include "sightline/domains/camera/composition/shot_world.h"

namespace sightline::camera {

// What a measure reads: the view of the pose, the world at the shot's time, and the
// property's targets as indices into world.people().
struct MeasureContext {
  const View& view;
  const ShotWorld& world;
  const int* targets;  // property.targets.size() of them
};

struct ShotPropertyKind {
  std::string name;
  std::string description;  // one line: the measured value
  int target_count = 1;     // 1: `target:`; 2: `targets: [A, B]`
  std::vector<std::string> fields;  // its own, besides kind, target(s), range, softness, weight, hard
  std::optional<ValueRange> default_range;  // nullopt: `range:` is required
  bool circular = false;  // ranges and gaps taken modulo 360 (degrees)
  // The measure reads the view's position only, not its aim, fov or roll (visible,
  // distance, the vantage angles): a search that turns the view without moving it need not
  // measure it again.
  bool position_only = false;
  // Reads the kind's own fields into the property and returns its default softness
  // (which may depend on them: size's area, order's depth). Fails at the field's line.
  std::function<double(ShotProperty& property, const csp::Spec& entry)> read;
  // The measured value; +inf where FORMATS.md says infinite, NaN where it says "scores 0".
  std::function<double(const ShotProperty& property, const MeasureContext& context)> measure;
};

class ShotPropertyKinds {
 public:
  static ShotPropertyKinds& global();  // with the built-in kinds
  void add(ShotPropertyKind kind);     // std::invalid_argument for an empty or taken name
  const ShotPropertyKind* find(const std::string& name) const;
  std::vector<std::string> names() const;

 private:
  std::map<std::string, ShotPropertyKind> kinds_;
};

// The satisfaction of a measured value q: 1 in [lo, hi], else max(0, 1 - gap / softness);
// 0 for NaN. `circular`: degrees modulo 360, [lo, hi] the arc from lo up to hi (through 180
// when hi < lo), the gap the shorter way round to the nearer end.
double satisfaction(double q, const ValueRange& range, double softness, bool circular);

}  // namespace sightline::camera
