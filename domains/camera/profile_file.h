// Reading camera profiles from YAML, and the named presets shipped with the project.
//
// A profile file (or an inline `profile:` mapping in a scene) looks like
//
//   name: close-follow
//   description: low and near, for tight spaces
//   base: thesis-default            # optional: start from a preset (default: thesis-default)
//   height:      {desired: 1.8, weight: 1.0}     # metres above the feet
//   distance:    {desired: 2.5, weight: 1.5}     # horizontal metres
//   orientation: {desired: 0, weight: 0.03}      # degrees, 0 = right behind
//   frame_coherence: {weight: 0.003}             # per metre/second of camera speed
//   occlusion: {look_at_hard: true, look_at_weight: 1, visible_fraction_weight: 2}
//   clearance: {radius: 0.2, hard: true, weight: 1}
//   search: {half_size: 2.0}
//   areas:                          # an entry replaces the base's entry for that kind
//     enclosed: {ceiling_margin: 0.4, distance_fraction: 0.35}
//     semi-enclosed: {distance_fraction: 0.5}
//   extras:                         # any registered constraint kind over cam_x, cam_y, cam_z
//     - {kind: expression, scope: [cam_y], formula: "char_y + 1.2 - cam_y", hard: true}
//
// Every field is optional and overrides the base; within height/distance/orientation a
// missing desired or weight keeps the base's. Unknown fields, non-finite numbers and values
// out of range are InputErrors naming the file, line and the expected value.
#pragma once

#include <string>
#include <vector>

#include "sightline/csp/spec.h"
#include "sightline/domains/camera/profile.h"

namespace sightline::camera {

// Reads a profile from a Spec (a YAML mapping). `fallback_name` names it when it has no
// `name` field.
CameraProfile parse_profile(const csp::Spec& spec, const std::string& fallback_name = "inline");
// Reads a profile file.
CameraProfile read_profile_file(const std::string& path);

// Names of the shipped presets (thesis-default, close-follow, high-follow, ...), sorted.
std::vector<std::string> preset_names();
bool is_preset(const std::string& name);
// The project's default camera, its best: what a scene without `camera.profile`, `follow`
// without --profile and the preset name "default" get. The thesis' reactive camera stays
// as the preset `thesis-default` (also named `thesis`) so the reproduction keeps its figures.
inline constexpr const char* kDefaultPreset = "anticipating";
// A preset's own name for a name a user may write ("default", "thesis").
std::string canonical_preset(const std::string& name);

// A preset by name ("default" is kDefaultPreset, "thesis" is thesis-default). Throws
// InputError at `where` for an unknown name, listing the presets.
CameraProfile preset_profile(const std::string& name, const csp::SourceLocation& where = {});

// What a scene's `camera.profile` or the command line's --profile may say: a preset name, a
// path to a profile file (.yaml/.yml, relative paths resolved against `base_dir`), or an
// inline mapping. Sets `source` to "preset NAME", "file PATH" or "inline".
CameraProfile resolve_profile(const csp::Spec& value, const std::string& base_dir,
                              std::string& source);

}  // namespace sightline::camera
