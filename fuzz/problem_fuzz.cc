// libFuzzer target for the problem-file reader (csp/files/problem_file.h): any bytes, as the
// text of a YAML problem file, either read into a Problem or are refused with csp::InputError;
// anything else (a crash, another exception, a sanitizer report, a hang) is a bug. The entry
// point is load_problem_text, which load_problem_file calls on the file's text. A problem read
// is also scored once, on its first values, so the constraints it built are exercised.
#include <cstddef>
#include <cstdint>
#include <string>

#include "sightline/csp/files/problem_file.h"
#include "sightline/csp/input_error.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const auto loaded = sightline::csp::load_problem_text(text, "fuzz.yaml");
    const auto& problem = *loaded.problem;
    if (problem.num_variables() <= 100000) (void)problem.score(problem.default_assignment());
  } catch (const sightline::csp::InputError&) {
    // The expected answer to a bad problem file.
  }
  return 0;
}
