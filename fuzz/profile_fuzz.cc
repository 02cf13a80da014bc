// libFuzzer target for camera profiles (domains/camera/profile_file.h) and their canonical
// text (profile_text.h): any bytes, as YAML, either resolve to a CameraProfile or are refused
// with csp::InputError; anything else (a crash, another exception, a sanitizer report, a hang)
// is a bug. The YAML goes to resolve_profile, what a scene's `camera.profile` and the command
// line's --profile go through: a mapping is a profile (as in a profile file), a name is a
// preset. Relative profile-file paths resolve against a folder that does not exist, so the
// run reads no file. A profile read is valid (CameraProfile::validate) and is written once
// as its canonical text, which suite run ids hash.
#include <string>

#include "sightline/domains/camera/profile_file.h"
#include "sightline/domains/camera/profile_text.h"
#include "yaml_fuzz.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace sightline;
  return fuzz::fuzz_yaml(data, size, [](const csp::Spec& spec) {
    std::string source;
    const camera::CameraProfile profile = camera::resolve_profile(spec, fuzz::kNoFolder, source);
    fuzz::require(profile.validate().empty());
    fuzz::require(!camera::profile_text(profile).empty());
  });
}
