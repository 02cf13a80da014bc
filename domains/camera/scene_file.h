// Reading scene files (YAML, the format of FORMATS.md and docs/CAMERA.md) into Scenes.
//
// Every problem is an InputError naming the file, the line and what was expected: unknown
// fields, missing required ones, non-finite numbers, boxes with min >= max on some axis,
// keyframe times that do not increase, a frame rate <= 0, an unknown profile; movers with a
// size not > 0 on every axis, an empty path, or keyframe times that do not increase strictly
// (naming both keyframes' lines). Movers are never checked against the character. A trajectory
// that puts the character's body inside a solid box is rejected naming the keyframe (or the
// two keyframes around the first bad frame, when the body passes through a box between them);
// touching a box, as standing on a floor or leaning on a wall, is fine. A camera start inside
// a solid box is rejected too, and the profile's extras are built once so that a bad extra is
// reported when the scene is read, not on the first frame.
#pragma once

#include <string>

#include "sightline/csp/spec.h"
#include "sightline/domains/camera/scene.h"

namespace sightline::camera {

// Reads and validates a scene file.
Scene read_scene_file(const std::string& path);
// Same from a Spec; relative profile file names are resolved against `base_dir`.
Scene parse_scene(const csp::Spec& spec, const std::string& base_dir = "");

// Scenes may not simulate more frames than this (a frame rate typo such as 6000000 would
// otherwise allocate traces of billions of rows).
constexpr double kMaxSceneFrames = 1e7;

}  // namespace sightline::camera
