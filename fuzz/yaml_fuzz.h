// What the YAML readers' fuzz targets share: the bytes parsed as YAML text (csp::parse_yaml)
// and handed to the reader under test, csp::InputError being the one expected answer to
// bad input; and require(), a promise whose breaking libFuzzer saves as a crash. Relative
// paths a reader meets resolve against kNoFolder, which does not exist, so a run reads no
// file.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "sightline/csp/files/yaml_spec.h"
#include "sightline/csp/input_error.h"

namespace sightline::fuzz {

inline constexpr const char* kNoFolder = "/nonexistent-sightline-fuzz";

inline void require(bool promise) {
  if (!promise) std::abort();  // libFuzzer saves the input as a crash
}

// Parses the bytes as YAML and calls read(spec); an InputError from either is the expected
// answer to bad input.
template <class Read>
int fuzz_yaml(const std::uint8_t* data, std::size_t size, Read read) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    read(csp::parse_yaml(text, "fuzz.yaml"));
  } catch (const csp::InputError&) {
  }
  return 0;
}

}  // namespace sightline::fuzz
