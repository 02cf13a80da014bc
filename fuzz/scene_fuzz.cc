// libFuzzer target for the scene reader (domains/camera/scene_file.h): any bytes, as the text
// of a scene file, either read into a Scene or are refused with csp::InputError; anything else
// (a crash, another exception, a sanitizer report, a hang) is a bug. The text goes through
// the same two steps as read_scene_file: csp::parse_yaml, then parse_scene.
//
// Two things are kept off the file system so that a run is fast and depends on the input
// alone: relative paths (a `level:` file, a profile file) resolve against a folder that does
// not exist, and `load_level` is fuzz/level_stub.cc's, which reads no file (see there).
#include "sightline/domains/camera/scene_file.h"
#include "yaml_fuzz.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace sightline;
  return fuzz::fuzz_yaml(data, size, [](const csp::Spec& spec) {
    const camera::Scene scene = camera::parse_scene(spec, fuzz::kNoFolder);
    // What a read scene promises the runs: a bounded number of frames, the first at the
    // first keyframe.
    fuzz::require(scene.frame_count() >= 1 &&
                  static_cast<double>(scene.frame_count()) <= camera::kMaxSceneFrames + 1);
  });
}
