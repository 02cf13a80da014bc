// libFuzzer target for the .cfn reader (csp/files/cfn_reader.h): any bytes either read into
// a Problem or are refused with csp::InputError; anything else (a crash, another exception,
// a sanitizer report) is a bug. A problem read is also scored once, on its first values.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "sightline/csp/files/cfn_reader.h"
#include "sightline/csp/input_error.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const auto problem = sightline::csp::parse_cfn(text, "fuzz.cfn");
    if (problem->num_variables() <= 100000) (void)problem->score(problem->default_assignment());
  } catch (const sightline::csp::InputError&) {
  }
  return 0;
}
