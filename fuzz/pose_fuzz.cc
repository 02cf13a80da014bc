// libFuzzer target for the pose file reader (domains/camera/composition/pose_reading.h): any
// bytes either read into a CameraPose or are refused with csp::InputError; anything else (a
// crash, another exception, a sanitizer report) is a bug. A pose read keeps the reader's
// promises: every number finite, fov in (0, 180), aspect > 0, and a view exists.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "sightline/csp/input_error.h"
#include "sightline/domains/camera/composition/pose_reading.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const sightline::camera::CameraPose pose = sightline::camera::parse_pose_json(text, "fuzz.json");
    const bool finite = pose.position.allFinite() && pose.look_at.allFinite() &&
                        std::isfinite(pose.roll);
    if (!finite || !(pose.fov > 0 && pose.fov < 180) || !(pose.aspect > 0) ||
        !sightline::camera::View::of(pose)) {
      std::abort();
    }
  } catch (const sightline::csp::InputError&) {
  }
  return 0;
}
