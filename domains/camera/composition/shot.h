// Shot: what the image must show (FORMATS.md "Shots"), as read from a scene's `shot:` block:
// the lens (field of view and roll, each fixed or a range the camera may choose in), the
// image's aspect, where the camera may stand (region, clearance) and the properties of the
// image (framing, screen position, projected size, vantage angles, visibility, distance,
// order on screen), each with a wanted range, a softness, and a weight or hard.
//
// The properties' kinds, with their fields, defaults and measures, are registered in
// ShotPropertyKinds (property_kinds.h); reading checks each against its kind.
#pragma once

#include <Eigen/Core>
#include <limits>
#include <string>
#include <vector>

#include "sightline/csp/spec.h"
#include "sightline/domains/camera/geometry/aabb.h"

namespace sightline::camera {

// A closed interval of wanted values; either end may be infinite.
struct ValueRange {
  double lo = 0, hi = 0;
  bool fixed() const { return lo == hi; }
};

// One property of a shot (one row of FORMATS.md's table).
struct ShotProperty {
  std::string kind;                  // a registered property kind: "framed", "size", ...
  std::vector<std::string> targets;  // one person (target:), or two for `order` (targets:)
  ValueRange range;                  // wanted values of the measure
  double softness = 1;               // the gap at which the satisfaction reaches 0, > 0
  double weight = 1;                 // of a soft property, > 0
  bool hard = false;                 // the pose must score 1
  // Kind-specific fields (meaningful for the kinds that read them).
  Eigen::Vector4d rect{0, 0, 1, 1};  // framed: [x0, y0, x1, y1] in screen units
  Eigen::Vector2d at{0.5, 0.5};      // screen_position: the wanted screen point
  std::string measure;               // size: height | width | area; order: the axis
  csp::SourceLocation where;         // the property's entry, for messages
  // "size of alice", "order of alice, bob": for tables and messages.
  std::string describe() const;
};

struct Shot {
  std::string name;        // a named shot's (the scene's shots:), empty for the shot: block
  ValueRange fov{50, 50};  // vertical field of view, degrees, in (0, 180)
  double aspect = 16.0 / 9.0;
  ValueRange roll{0, 0};   // degrees
  Aabb region;             // where the camera may stand
  double clearance = 0.2;  // metres kept from solid geometry and from every person's box
  std::vector<ShotProperty> properties;
  csp::SourceLocation where;
  // Everyone the properties name, in first-mention order (each once).
  std::vector<std::string> targets() const;
};

// One entry of a scene's script (FORMATS.md "Script and named shots"): a line of dialogue
// (speaker, to) or an action (action), over the half-open interval [t0, t1).
struct ScriptEntry {
  double t0 = 0, t1 = 0;
  std::string speaker, to;  // a line: who speaks, to whom
  std::string action;       // an action: who acts
  csp::SourceLocation where;
};

// Reads a scene's `script:`: people must be known, t0 < t1, entries in time order, and one
// person's lines may not overlap each other.
std::vector<ScriptEntry> read_script(const csp::Spec& spec, const std::vector<std::string>& people);

// Reads a `shot:` block (`named`: an entry of `shots:`, which needs a name). `people` are the names a target may take (the actors and, when the
// scene has one, "character"); an unknown name, a range with lo > hi, NaN, a region of zero
// volume, an aspect <= 0, an unknown kind or field get a csp::InputError at their line.
Shot read_shot(const csp::Spec& spec, const std::vector<std::string>& people, bool named = false);

}  // namespace sightline::camera
