// Reading a pose file (FORMATS.md "Shots": {"position": [x, y, z], "look_at": [x, y, z],
// "roll": r, "fov": f, "aspect": a}, more fields allowed), such as `compose` writes or any
// other tool: so that a pose found elsewhere can be judged by this project's measures
// (`sightline compose SCENE --evaluate POSE.json`).
//
// All five fields are required; position and look_at are 3 finite numbers, roll a finite
// number of degrees, fov in (0, 180) degrees, aspect > 0, and the pose must make a view
// (the look-at point away from the position, the view not straight up or down: View::of).
// Refused, with an InputError naming the file, line and column: text that is not JSON
// (the position nlohmann's parser gives), a document that is not an object, a key given
// twice, a missing or malformed field (at its key's line). Other fields are ignored.
//
// For the tools only (it links a JSON parser): the runtime camera reads no files.
#pragma once

#include <string>
#include <string_view>

#include "sightline/domains/camera/composition/camera_pose.h"

namespace sightline::camera {

CameraPose parse_pose_json(std::string_view text, const std::string& origin);
CameraPose read_pose_file(const std::string& path);

}  // namespace sightline::camera
